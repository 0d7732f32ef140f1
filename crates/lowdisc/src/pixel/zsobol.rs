//! Z-order blue-noise Sobol (Ahmed & Wonka 2020, "Screen-Space Blue-Noise
//! Diffusion of Monte Carlo Sampling Error via Hierarchical Ordering of
//! Pixels"), after pbrt-v4's `ZSobolSampler`.
//!
//! The image is covered by a square of `R = 2^k` pixels per side. Sample `s`
//! of pixel `p` has the *Morton index* `morton(p) << m | s` (`m` sample bits).
//! Its base-4 digits, from the most significant down, are each mapped through
//! one of the 24 permutations of `{0, 1, 2, 3}`, chosen by a hash of the
//! sampler dimension, the digit's level and all higher digits; when `m` is
//! odd the lowest bit is a single binary digit, flipped by a hash of the
//! digits above it. The result is a bijection of the index space that maps
//! the block of every pixel to an aligned block of `2^m` indices, so the
//! `2^m` samples of a pixel are an aligned block of the Sobol sequence (a
//! (0,m,2)-net in dimensions 0-1), while neighbouring pixels receive
//! different, hierarchically decorrelated blocks (the blue-noise error
//! distribution).
//!
//! ## Dimensions (as pbrt-v4)
//! Every 1-D value is Sobol dimension 0 and every 2-D value Sobol dimensions
//! 0-1 at the permuted index of that sampler dimension; the sampler
//! dimensions differ by their index permutation and by their randomization
//! seed (a hash of the seed and the dimension, the same for all pixels;
//! fast Owen in the catalog). The in-pixel offset uses a reserved
//! dimension key and does not move the counter.
//!
//! ## Limits
//! * `spp` not a power of two: the index layout uses `m = ceil(log2 spp)`
//!   sample bits and the pixel uses the first `spp` of its `2^m` slots (after
//!   permutation, a subset of the net). Sample indices `>= spp` are reduced
//!   modulo `spp`; pixels outside the square wrap modulo `R`.
//! * The index `2k + m` bits must fit in 64 bits. The Sobol tables have 32
//!   columns, so index bits above 31 do not enter the Sobol point; they are
//!   hashed into the randomization seed instead (pixels that share the low
//!   32 bits get independent scrambles of the same block). Without a
//!   randomization that would repeat samples, so `RandomizeStrategy::None` requires
//!   `2k + m <= 32`.
//!
//! ## Speed
//! The values are computed as the definition above says by
//! [`ZSobolSampler::sample_index`], but the sampler's own calls take a
//! cached path (`cache.rs`) that hashes per dimension key once and per
//! pixel and key once, leaving a table lookup of the four highest sample
//! digits' permutation, a bit mix per lower sample digit (none for
//! `spp <= 256`) and one scramble per value. Tests check both paths give
//! the same bits.

mod cache;

use self::cache::{Cache, Layout};
use super::{SEED_PAD, WordSampler};
use crate::hash::hash_words;
use crate::sobol::sample;
use crate::{Error, RandomizeStrategy};

/// All 24 permutations of `{0, 1, 2, 3}` in lexicographic order.
const fn base4_permutations() -> [[u8; 4]; 24] {
    let mut out = [[0u8; 4]; 24];
    let mut n = 0;
    let mut a = 0u8;
    while a < 4 {
        let mut b = 0u8;
        while b < 4 {
            let mut c = 0u8;
            while c < 4 {
                if a != b && a != c && b != c {
                    out[n] = [a, b, c, 6 - a - b - c];
                    n += 1;
                }
                c += 1;
            }
            b += 1;
        }
        a += 1;
    }
    out
}

/// The table of the 24 base-4 digit permutations.
pub const BASE4_PERMUTATIONS: [[u8; 4]; 24] = base4_permutations();

/// Dimension key of the in-pixel offset (above every `u32` dimension).
const PIXEL_KEY: u64 = 1 << 32;
/// Salt of the odd final bit's flip.
const LOW_BIT_SALT: u64 = 0x6c6f_775f_6269_7421;

/// Interleaves the bits of `x` (even positions) and `y` (odd positions).
fn morton2(x: u32, y: u32) -> u64 {
    fn spread(v: u32) -> u64 {
        let mut v = u64::from(v);
        v = (v | (v << 16)) & 0x0000_ffff_0000_ffff;
        v = (v | (v << 8)) & 0x00ff_00ff_00ff_00ff;
        v = (v | (v << 4)) & 0x0f0f_0f0f_0f0f_0f0f;
        v = (v | (v << 2)) & 0x3333_3333_3333_3333;
        (v | (v << 1)) & 0x5555_5555_5555_5555
    }
    spread(x) | (spread(y) << 1)
}

/// pbrt-v4-style Z-order Sobol sampler; see the module documentation.
#[derive(Debug, Clone)]
pub struct ZSobolSampler {
    spp: u32,
    /// `m`: sample bits in the index layout.
    log2_spp: u32,
    /// `k`: the square covering the image is `2^k` wide.
    log2_res: u32,
    /// Base-4 digits above the odd low bit (if any).
    base4_digits: u32,
    strategy: RandomizeStrategy,
    seed: u64,
    morton: u64,
    dimension: u32,
    /// Hashes reused between values (never changes a value).
    cache: Cache,
}

impl ZSobolSampler {
    /// A sampler for `spp` samples per pixel of a `resolution` image,
    /// scrambled by `strategy` under `seed`.
    pub fn new(
        spp: u32,
        resolution: [u32; 2],
        strategy: RandomizeStrategy,
        seed: u64,
    ) -> Result<Self, Error> {
        super::check_spp(spp)?;
        let [w, h] = super::check_resolution(resolution)?;
        let log2_spp = super::ceil_log2(u64::from(spp));
        let log2_res = super::ceil_log2(u64::from(w.max(h)));
        let bits = 2 * log2_res + log2_spp;
        if bits > 64 {
            return Err(Error::InvalidSampleCount {
                count: u64::from(spp),
                reason: "the Z-order index (2 log2 R + log2 spp bits) exceeds 64 bits",
            });
        }
        if bits > 32 && strategy == RandomizeStrategy::None {
            return Err(Error::InvalidSampleCount {
                count: u64::from(spp),
                reason: "unscrambled Z-order Sobol needs 2 log2 R + log2 spp <= 32 index bits",
            });
        }
        let layout = Layout {
            seed,
            strategy,
            log2_spp,
            base4_digits: log2_res + log2_spp.div_ceil(2),
        };
        Ok(ZSobolSampler {
            spp,
            log2_spp,
            log2_res,
            base4_digits: layout.base4_digits,
            strategy,
            seed,
            morton: 0,
            dimension: 0,
            cache: Cache::new(layout),
        })
    }

    /// The scrambled words of Sobol dimensions `0..N` (`N` = 1 or 2) for
    /// dimension key `key`: the cached path, else the definition.
    #[inline(always)]
    fn words<const N: usize>(&mut self, key: u64) -> [u32; N] {
        match self.cache.words(key, self.morton) {
            Some(words) => words,
            None => self.direct_words(key),
        }
    }

    /// The scrambled words of Sobol dimensions `0..N` for `key`, computed
    /// from the definition ([`ZSobolSampler::sample_index`]).
    #[cold]
    #[inline(never)]
    fn direct_words<const N: usize>(&self, key: u64) -> [u32; N] {
        let index = self.sample_index(key);
        let seed = self.randomizer_seed(key, index >> 32);
        core::array::from_fn(|d| {
            let word = sample(index as u32, d as u32);
            self.strategy.apply(word, seed, d as u32)
        })
    }

    /// The randomization strategy given at construction.
    pub fn strategy(&self) -> RandomizeStrategy {
        self.strategy
    }

    /// The Morton index of the current pixel sample (before permutation).
    pub fn morton_index(&self) -> u64 {
        self.morton
    }

    /// The permuted 64-bit sequence index of the current pixel sample for
    /// sampler dimension key `key`.
    pub fn sample_index(&self, key: u64) -> u64 {
        self.sample_index_with(&mut self.key_index(key))
    }

    /// The randomization seed of dimension key `key` (and high index bits
    /// `high`).
    fn randomizer_seed(&self, key: u64, high: u64) -> u64 {
        hash_words(&[self.seed, SEED_PAD, key, high])
    }
}

impl WordSampler for ZSobolSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    #[inline]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
        let mask = ((1u64 << self.log2_res) - 1) as u32;
        let code = morton2(pixel[0] & mask, pixel[1] & mask);
        self.morton = (code << self.log2_spp) | u64::from(sample_index % self.spp);
        self.dimension = dimension;
    }

    #[inline]
    fn get_1d_word(&mut self) -> u32 {
        let key = super::next_key(&mut self.dimension, 1);
        let [word] = self.words(key);
        word
    }

    #[inline]
    fn get_2d_words(&mut self) -> [u32; 2] {
        let key = super::next_key(&mut self.dimension, 2);
        self.words(key)
    }

    #[inline]
    fn get_pixel_2d_words(&mut self) -> [u32; 2] {
        self.words(PIXEL_KEY)
    }
}

mod split_index;
pub(crate) use split_index::KeyIndex;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hash::mix64;

    #[test]
    fn the_table_holds_all_24_distinct_permutations() {
        for (i, p) in BASE4_PERMUTATIONS.iter().enumerate() {
            let mut sorted = *p;
            sorted.sort_unstable();
            assert_eq!(sorted, [0, 1, 2, 3]);
            assert!(BASE4_PERMUTATIONS[..i].iter().all(|q| q != p));
        }
        assert_eq!(BASE4_PERMUTATIONS[0], [0, 1, 2, 3]);
        assert_eq!(BASE4_PERMUTATIONS[23], [3, 2, 1, 0]);
    }

    #[test]
    fn morton_interleaves_x_low() {
        assert_eq!(morton2(1, 0), 1);
        assert_eq!(morton2(0, 1), 2);
        assert_eq!(morton2(3, 5), 0b10_01_11);
        assert_eq!(morton2(u32::MAX, u32::MAX), u64::MAX);
    }

    #[test]
    fn the_cached_path_equals_the_definition() {
        // (spp, resolution): even and odd m, spp not a power of two, more
        // than 32 index bits (high bits in the seed), m above the table.
        let configs = [
            (16u32, [640u32, 360u32]),
            (1, [7, 5]),
            (2, [3, 3]),
            (5, [33, 17]),
            (8, [1 << 15, 3]),
            (3, [1 << 16, 1 << 16]),
            (1 << 12, [64, 64]),
            (2048, [1, 1]),
        ];
        let mut state = 0x2545_f491_4f6c_dd1du64;
        for (spp, res) in configs {
            for r in RandomizeStrategy::ALL {
                let Ok(mut s) = ZSobolSampler::new(spp, res, r, 11) else {
                    assert!(r == RandomizeStrategy::None);
                    continue;
                };
                for visit in 0..120u32 {
                    state = mix64(state.wrapping_add(u64::from(visit)));
                    // Runs of samples of one pixel, and jumps between pixels.
                    let pixel = [
                        (state as u32) % (res[0] + 3),
                        ((state >> 20) as u32) % res[1],
                    ];
                    let start = if visit % 3 == 0 {
                        1020
                    } else {
                        (state >> 50) as u32 % 4
                    };
                    for k in 0..(1 + (state >> 40) as u32 % 4) {
                        s.start_pixel_sample(pixel, (state >> 8) as u32 % spp + k, start);
                        assert_eq!(s.get_pixel_2d_words(), s.direct_words::<2>(PIXEL_KEY));
                        for _ in 0..4 {
                            let key = u64::from(s.dimension);
                            let want1 = s.direct_words::<1>(key);
                            assert_eq!([s.get_1d_word()], want1, "{spp} {res:?} {r:?}");
                            let key = u64::from(s.dimension);
                            let want2 = s.direct_words::<2>(key);
                            assert_eq!(s.get_2d_words(), want2, "{spp} {res:?} {r:?}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn the_index_map_is_a_bijection_preserving_pixel_blocks() {
        for spp in [1u32, 2, 4, 8, 32] {
            let mut s = ZSobolSampler::new(spp, [8, 8], RandomizeStrategy::None, 3).unwrap();
            let m = s.log2_spp;
            let total = 64usize << m;
            let mut seen = alloc::vec![false; total];
            for y in 0..8 {
                for x in 0..8 {
                    let mut block = None;
                    for k in 0..spp {
                        s.start_pixel_sample([x, y], k, 0);
                        let i = s.sample_index(5);
                        assert!(!seen[i as usize]);
                        seen[i as usize] = true;
                        let b = i >> m;
                        assert!(block.is_none_or(|c| c == b), "pixel block split");
                        block = Some(b);
                    }
                }
            }
            assert!(seen.iter().all(|&v| v));
        }
    }
}
