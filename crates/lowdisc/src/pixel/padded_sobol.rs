//! Padded per-pixel Sobol, after pbrt-v4's `PaddedSobolSampler`.
//!
//! For every (pixel, sampler dimension) a hash `h` of the seed, the pixel
//! and the dimension is computed. The
//! sample index `s` is mapped through a seeded bijection of `[0, spp)`
//! ([`permutation_element`]), so the dimensions of one pixel are paired in
//! independent random orders ("padding"). A 1-D value is Sobol dimension 0
//! at the permuted index, a 2-D value Sobol dimensions 0-1, each scrambled
//! with the given [`RandomizeStrategy`] seeded from `h` (Owen in the
//! catalog's `padded-sobol`, LMS + shift in `padded-sobol-lms`). The in-pixel offset uses a reserved dimension key and does not
//! move the dimension counter.
//!
//! Any `spp >= 1` works. For a power of two `2^m` the `spp` samples of one
//! pixel are the first `2^m` Sobol points, so their 2-D values form a
//! (0,m,2)-net (kept by every strategy). For other counts they are
//! the first `spp` points of the (0,2)-sequence: well spread, but not a
//! complete net. Sample indices `>= spp` are reduced modulo `spp`.
//!
//! ## Speed
//! Everything but the sample index's permutation and the scramble of the
//! word depends on the pixel and the dimension key only, so for keys below
//! `CACHED_KEYS` (and the pixel key) it is kept per key while the pixel
//! stays the same (a renderer visits a pixel's samples one after another):
//! the hash, the permutation's key, the per-dimension scramble seeds and,
//! for Owen and LMS scrambling, their [`PreparedKey`]s. The seed, which
//! starts every hash, is absorbed once per pixel. The values are those of
//! the definition ([`PaddedSobolSampler::permuted_index`] and the plain
//! scramble; tests check both paths agree).

use alloc::vec::Vec;

use super::{SEED_PAD, WordSampler};
use crate::hash::{WordHasher, hash_words, mix64};
use crate::net::Net;
use crate::scramble::{PreparedKey, dimension_seed};
use crate::{Error, RandomizeStrategy};

/// Dimension key of the in-pixel offset (above every `u32` dimension).
const PIXEL_KEY: u64 = 1 << 32;
/// Dimension keys below this are cached (slot `1 + key`; slot 0 is the
/// pixel key).
const CACHED_KEYS: u64 = 1024;

/// A seeded bijection of `m`-bit integers: an odd multiply-add modulo `2^m`
/// followed by a nested bit scramble (each bit flipped by a hash of the bits
/// above it). The seed's own hashing is done by [`Permutation::new`].
#[derive(Debug, Clone, Copy)]
struct Permutation {
    /// The size `n` of the permuted range.
    n: u32,
    /// `ceil(log2 n)`.
    m: u32,
    /// The seed `h`.
    h: u64,
    /// The key of the bit flips.
    key: u64,
}

impl Permutation {
    /// The permutation of `[0, n)` seeded by `h`.
    #[inline]
    fn new(n: u32, h: u64) -> Self {
        Permutation {
            n,
            m: super::ceil_log2(u64::from(n)),
            h,
            key: mix64(h ^ 0x5bd1_e995_1234_5678),
        }
    }

    /// One pass of the `m`-bit bijection.
    #[inline]
    fn scramble_bits(&self, x: u64) -> u64 {
        let (m, h) = (self.m, self.h);
        let mask = if m >= 64 { u64::MAX } else { (1u64 << m) - 1 };
        let mut x = x.wrapping_mul(h | 1).wrapping_add(h >> 17) & mask;
        for b in (0..m).rev() {
            let higher = x >> b >> 1;
            let flip =
                mix64(self.key ^ higher.wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ u64::from(b)) >> 63;
            x ^= flip << b;
        }
        x
    }

    /// Element `i` (reduced modulo `n`), by cycle-walking.
    #[inline]
    fn element(&self, i: u32) -> u32 {
        let n = self.n;
        if n <= 1 {
            return 0;
        }
        let mut x = u64::from(i % n);
        loop {
            x = self.scramble_bits(x);
            if x < u64::from(n) {
                return x as u32;
            }
        }
    }
}

/// Element `i` of a seeded random permutation of `[0, n)` (`i` is reduced
/// modulo `n`; `n = 0` gives 0). A bijection of `ceil(log2 n)`-bit integers
/// is applied by cycle-walking until the result falls below `n`, which is a
/// bijection of `[0, n)` for every `n`.
pub fn permutation_element(i: u32, n: u32, seed: u64) -> u32 {
    Permutation::new(n, seed).element(i)
}

/// What one dimension key needs for the current pixel.
#[derive(Debug, Clone)]
struct Entry {
    /// Whether the fields below are for `pixel`.
    valid: bool,
    /// The pixel they are for.
    pixel: [u32; 2],
    /// The sample-index permutation.
    permutation: Permutation,
    /// Scramble seeds of Sobol dimensions 0 and 1.
    seeds: [u32; 2],
}

/// Per-key caches (see the module documentation).
#[derive(Debug, Clone, Default)]
struct Cache {
    /// The pixel `prefix` is for, if any.
    pixel: Option<[u32; 2]>,
    /// The hash of every key after the seed and the pixel's coordinates.
    prefix: Option<WordHasher>,
    entries: Vec<Entry>,
    /// Prepared keys of Sobol dimensions 0 and 1, per slot (Owen and LMS
    /// only).
    prepared: Vec<[PreparedKey; 2]>,
}

/// pbrt-v4-style padded Sobol sampler; see the module documentation.
#[derive(Debug, Clone)]
pub struct PaddedSobolSampler {
    spp: u32,
    strategy: RandomizeStrategy,
    seed: u64,
    /// The generator matrices (dimensions 0-1 are read).
    net: Net,
    pixel: [u32; 2],
    sample_index: u32,
    dimension: u32,
    /// Hashes reused between values (never changes a value).
    cache: Cache,
}

impl PaddedSobolSampler {
    /// A sampler with `spp` samples per pixel (any `spp >= 1`), scrambled
    /// by `strategy` under `seed`.
    pub fn new(spp: u32, strategy: RandomizeStrategy, seed: u64) -> Result<Self, Error> {
        Self::with_net(spp, strategy, seed, Net::SOBOL)
    }

    /// [`PaddedSobolSampler::new`] reading dimensions 0-1 of `net` in
    /// place of Sobol's (the same sampler for [`Net::SOBOL`]).
    pub fn with_net(
        spp: u32,
        strategy: RandomizeStrategy,
        seed: u64,
        net: Net,
    ) -> Result<Self, Error> {
        super::check_spp(spp)?;
        net.require(2, "a padded sampler")?;
        Ok(PaddedSobolSampler {
            spp,
            strategy,
            seed,
            net,
            pixel: [0, 0],
            sample_index: 0,
            dimension: 0,
            cache: Cache::default(),
        })
    }

    /// The randomization strategy given at construction.
    pub fn strategy(&self) -> RandomizeStrategy {
        self.strategy
    }

    /// The hash of the current pixel and a dimension key.
    fn hash(&self, key: u64) -> u64 {
        hash_words(&[
            self.seed,
            SEED_PAD,
            u64::from(self.pixel[0]),
            u64::from(self.pixel[1]),
            key,
        ])
    }

    /// The Sobol index (after permutation) used for dimension key `key`.
    pub fn permuted_index(&self, key: u64) -> u32 {
        permutation_element(self.sample_index, self.spp, mix64(self.hash(key)))
    }

    /// Sobol dimensions `0..N` (`N` = 1 or 2) at the permuted index for
    /// `key`, scrambled: the definition.
    fn direct_words<const N: usize>(&self, key: u64) -> [u32; N] {
        let h = self.hash(key);
        let index = permutation_element(self.sample_index, self.spp, mix64(h));
        core::array::from_fn(|d| {
            let word = self.net.sample(index, d as u32);
            self.strategy.apply(word, h, d as u32)
        })
    }

    /// As [`PaddedSobolSampler::direct_words`], through the caches.
    #[inline]
    fn words<const N: usize>(&mut self, key: u64) -> [u32; N] {
        let slot = match key {
            PIXEL_KEY => 0,
            k if k < CACHED_KEYS => k as usize + 1,
            _ => return self.direct_words(key),
        };
        let valid = self
            .cache
            .entries
            .get(slot)
            .is_some_and(|e| e.valid && e.pixel == self.pixel);
        if !valid {
            self.refresh(slot, key);
        }
        let entry = &self.cache.entries[slot];
        let index = entry.permutation.element(self.sample_index);
        core::array::from_fn(|d| {
            let word = self.net.sample(index, d as u32);
            match self.cache.prepared.get(slot) {
                Some(keys) => keys[d].scramble(word),
                None => self.strategy.apply_dimension_seed(word, entry.seeds[d]),
            }
        })
    }

    /// Computes the entry of `slot` (dimension key `key`) for the pixel.
    #[cold]
    fn refresh(&mut self, slot: usize, key: u64) {
        let cache = &mut self.cache;
        if cache.pixel != Some(self.pixel) {
            let [x, y] = self.pixel.map(u64::from);
            let seeded = WordHasher::new(5).push(self.seed).push(SEED_PAD);
            cache.prefix = Some(seeded.push(x).push(y));
            cache.pixel = Some(self.pixel);
        }
        let prefix = cache.prefix.unwrap_or(WordHasher::new(5));
        let h = prefix.push(key).finish();
        let seeds = [dimension_seed(h, 0), dimension_seed(h, 1)];
        let entry = Entry {
            valid: true,
            pixel: self.pixel,
            permutation: Permutation::new(self.spp, mix64(h)),
            seeds,
        };
        let prepare = |s| self.strategy.prepare(s);
        let keys = match seeds.map(prepare) {
            [Some(a), Some(b)] => Some([a, b]),
            _ => None,
        };
        while cache.entries.len() <= slot {
            // Placeholders, invalid until their own key is asked for.
            cache.entries.push(Entry {
                valid: false,
                ..entry.clone()
            });
            cache.prepared.extend(keys.clone());
        }
        cache.entries[slot] = entry;
        if let Some(keys) = keys {
            cache.prepared[slot] = keys;
        }
    }
}

impl WordSampler for PaddedSobolSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
        self.pixel = pixel;
        self.sample_index = sample_index % self.spp;
        self.dimension = dimension;
    }

    fn get_1d_word(&mut self) -> u32 {
        let key = super::next_key(&mut self.dimension, 1);
        let [word] = self.words(key);
        word
    }

    fn get_2d_words(&mut self) -> [u32; 2] {
        let key = super::next_key(&mut self.dimension, 2);
        self.words(key)
    }

    fn get_pixel_2d_words(&mut self) -> [u32; 2] {
        self.words(PIXEL_KEY)
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
    fn the_cached_path_equals_the_definition() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        for spp in [1u32, 3, 16, 100] {
            for r in RandomizeStrategy::ALL {
                let mut s = PaddedSobolSampler::new(spp, r, 11).unwrap();
                for visit in 0..60u32 {
                    state = mix64(state.wrapping_add(u64::from(visit)));
                    let pixel = [(state % 3) as u32, u32::MAX - ((state >> 8) % 2) as u32];
                    let start = if visit % 3 == 0 {
                        1020
                    } else {
                        (state >> 50) as u32 % 4
                    };
                    for k in 0..(1 + (state >> 40) as u32 % 4) {
                        s.start_pixel_sample(pixel, (state >> 20) as u32 + k, start);
                        assert_eq!(s.get_pixel_2d_words(), s.direct_words::<2>(PIXEL_KEY));
                        for _ in 0..4 {
                            let want1 = s.direct_words::<1>(u64::from(s.dimension));
                            assert_eq!([s.get_1d_word()], want1, "{spp} {r:?}");
                            let want2 = s.direct_words::<2>(u64::from(s.dimension));
                            assert_eq!(s.get_2d_words(), want2, "{spp} {r:?}");
                        }
                    }
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
