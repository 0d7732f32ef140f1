//! Padded per-pixel Sobol, after pbrt-v4's `PaddedSobolSampler`.
//!
//! For every (pixel, sampler dimension) a hash `h` of the seed, the
//! randomization's own seed, the pixel and the dimension is computed. The
//! sample index `s` is mapped through a seeded bijection of `[0, spp)`
//! ([`permutation_element`]), so the dimensions of one pixel are paired in
//! independent random orders ("padding"). A 1-D value is Sobol dimension 0
//! at the permuted index, a 2-D value Sobol dimensions 0-1, each scrambled
//! with the given [`Randomize`] seeded from `h` (Owen by default in the
//! catalog). The in-pixel offset uses a reserved dimension key and does not
//! move the dimension counter.
//!
//! Any `spp >= 1` works. For a power of two `2^m` the `spp` samples of one
//! pixel are the first `2^m` Sobol points, so their 2-D values form a
//! (0,m,2)-net (kept by XOR, Owen and fast Owen). For other counts they are
//! the first `spp` points of the (0,2)-sequence: well spread, but not a
//! complete net. Sample indices `>= spp` are reduced modulo `spp`.

use super::PixelSampler;
use crate::hash::{hash_words, mix64};
use crate::sobol::sample;
use crate::{Error, Randomize, to_f32};

/// Dimension key of the in-pixel offset (above every `u32` dimension).
const PIXEL_KEY: u64 = 1 << 32;

/// A seeded bijection of `m`-bit integers: an odd multiply-add modulo `2^m`
/// followed by a nested bit scramble (each bit flipped by a hash of the bits
/// above it).
fn scramble_bits(x: u64, m: u32, h: u64) -> u64 {
    let mask = if m >= 64 { u64::MAX } else { (1u64 << m) - 1 };
    let mut x = x.wrapping_mul(h | 1).wrapping_add(h >> 17) & mask;
    let key = mix64(h ^ 0x5bd1_e995_1234_5678);
    for b in (0..m).rev() {
        let higher = x >> b >> 1;
        let flip = mix64(key ^ higher.wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ u64::from(b)) >> 63;
        x ^= flip << b;
    }
    x
}

/// Element `i` of a seeded random permutation of `[0, n)` (`i` is reduced
/// modulo `n`; `n = 0` gives 0). A bijection of `ceil(log2 n)`-bit integers
/// is applied by cycle-walking until the result falls below `n`, which is a
/// bijection of `[0, n)` for every `n`.
pub fn permutation_element(i: u32, n: u32, seed: u64) -> u32 {
    if n <= 1 {
        return 0;
    }
    let m = super::ceil_log2(u64::from(n));
    let mut x = u64::from(i % n);
    loop {
        x = scramble_bits(x, m, seed);
        if x < u64::from(n) {
            return x as u32;
        }
    }
}

/// pbrt-v4-style padded Sobol sampler; see the module documentation.
#[derive(Debug, Clone)]
pub struct PaddedSobolSampler {
    spp: u32,
    randomize: Randomize,
    seed: u64,
    pixel: [u32; 2],
    sample_index: u32,
    dimension: u32,
}

impl PaddedSobolSampler {
    /// A sampler with `spp` samples per pixel (any `spp >= 1`). The seed
    /// inside `randomize` is combined with `seed`.
    pub fn new(spp: u32, randomize: Randomize, seed: u64) -> Result<Self, Error> {
        super::check_spp(spp)?;
        Ok(PaddedSobolSampler {
            spp,
            randomize,
            seed,
            pixel: [0, 0],
            sample_index: 0,
            dimension: 0,
        })
    }

    /// The randomization given at construction.
    pub fn randomize(&self) -> Randomize {
        self.randomize
    }

    /// The hash of the current pixel and a dimension key.
    fn hash(&self, key: u64) -> u64 {
        let seed = super::randomize_seed(self.randomize);
        hash_words(&[
            self.seed,
            seed,
            u64::from(self.pixel[0]),
            u64::from(self.pixel[1]),
            key,
        ])
    }

    /// The Sobol index (after permutation) used for dimension key `key`.
    pub fn permuted_index(&self, key: u64) -> u32 {
        permutation_element(self.sample_index, self.spp, mix64(self.hash(key)))
    }

    /// Sobol dimensions 0-1 at the permuted index for `key`, scrambled.
    fn words_2d(&self, key: u64) -> [u32; 2] {
        let h = self.hash(key);
        let index = permutation_element(self.sample_index, self.spp, mix64(h));
        let r = super::reseed(self.randomize, h);
        [r.apply(sample(index, 0), 0), r.apply(sample(index, 1), 1)]
    }

    /// The next 1-D value as a digit word.
    pub fn get_1d_word(&mut self) -> u32 {
        let key = u64::from(self.dimension);
        self.dimension = self.dimension.wrapping_add(1);
        let h = self.hash(key);
        let index = permutation_element(self.sample_index, self.spp, mix64(h));
        super::reseed(self.randomize, h).apply(sample(index, 0), 0)
    }

    /// The next 2-D value as digit words.
    pub fn get_2d_words(&mut self) -> [u32; 2] {
        let key = u64::from(self.dimension);
        self.dimension = self.dimension.wrapping_add(2);
        self.words_2d(key)
    }

    /// The in-pixel offset as digit words.
    pub fn get_pixel_2d_words(&mut self) -> [u32; 2] {
        self.words_2d(PIXEL_KEY)
    }
}

impl PixelSampler for PaddedSobolSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
        self.pixel = pixel;
        self.sample_index = sample_index % self.spp;
        self.dimension = dimension;
    }

    fn get_1d(&mut self) -> f32 {
        to_f32(self.get_1d_word())
    }

    fn get_2d(&mut self) -> [f32; 2] {
        self.get_2d_words().map(to_f32)
    }

    fn get_pixel_2d(&mut self) -> [f32; 2] {
        self.get_pixel_2d_words().map(to_f32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn permutation_element_is_a_bijection_for_every_size() {
        for n in [1u32, 2, 3, 5, 7, 8, 16, 17, 100, 255, 256, 1000] {
            for seed in [0u64, 1, 0xdead_beef] {
                let mut seen = alloc::vec![false; n as usize];
                for i in 0..n {
                    let p = permutation_element(i, n, seed);
                    assert!(p < n && !seen[p as usize], "n {n} seed {seed} i {i}");
                    seen[p as usize] = true;
                }
            }
        }
    }

    #[test]
    fn permutations_depend_on_the_seed() {
        let a: alloc::vec::Vec<u32> = (0..64).map(|i| permutation_element(i, 64, 1)).collect();
        let b: alloc::vec::Vec<u32> = (0..64).map(|i| permutation_element(i, 64, 2)).collect();
        assert_ne!(a, b);
        let identity: alloc::vec::Vec<u32> = (0..64).collect();
        assert_ne!(a, identity);
    }
}
