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
mod digits;
mod entry;

use self::cache::Cache;
use self::entry::Layout;
use super::{Dims, SEED_PAD, WordSampler};
use crate::hash::hash_words;
use crate::net::Net;
use crate::{Error, RandomizeStrategy, reversed_to_f32, to_f32};

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
    /// The last pixel started (`x << 32 | y`, both masked to the square)
    /// and its Morton code.
    last_pixel: Option<(u64, u64)>,
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
        Self::with_net(spp, resolution, strategy, seed, Net::SOBOL)
    }

    /// [`ZSobolSampler::new`] reading dimensions 0-1 of `net` in place of
    /// Sobol's (the same sampler for [`Net::SOBOL`]).
    ///
    /// ```
    /// use lowdisc::RandomizeStrategy;
    /// use lowdisc::net::{DigitalNet, Net};
    /// use lowdisc::pixel::{WordSampler, ZSobolSampler};
    ///
    /// let text = "d s a m_i\n2 1 0 1\n";
    /// let net = DigitalNet::from_joe_kuo("two.txt", text)?.into_net();
    /// let mut a = ZSobolSampler::with_net(16, [4, 4], RandomizeStrategy::FastOwen, 7, net)?;
    /// let mut b = ZSobolSampler::new(16, [4, 4], RandomizeStrategy::FastOwen, 7)?;
    /// a.start_pixel_sample([1, 2], 5, 0);
    /// b.start_pixel_sample([1, 2], 5, 0);
    /// assert_eq!(a.get_2d_words(), b.get_2d_words());
    /// # Ok::<(), lowdisc::Error>(())
    /// ```
    pub fn with_net(
        spp: u32,
        resolution: [u32; 2],
        strategy: RandomizeStrategy,
        seed: u64,
        net: Net,
    ) -> Result<Self, Error> {
        super::check_spp(spp)?;
        net.require(2, "a Z-order sampler")?;
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
            net,
        };
        Ok(ZSobolSampler {
            spp,
            log2_spp,
            log2_res,
            base4_digits: layout.base4_digits,
            strategy,
            seed,
            morton: 0,
            last_pixel: None,
            dimension: 0,
            cache: Cache::new(layout),
        })
    }

    /// The scrambled words of Sobol dimensions `0..N` (`N` = 1 or 2) for
    /// dimension key `key`: the cached path, else the definition.
    #[inline(always)]
    fn words<const N: usize>(&mut self, key: u64) -> [u32; N] {
        match self.cache.fast(slot(key)) {
            Some(hashes) => hashes.map(u32::reverse_bits),
            None => match self.slow(key) {
                Slow::Hashes(hashes) => hashes.map(u32::reverse_bits),
                Slow::Words(words) => words,
            },
        }
    }

    /// [`ZSobolSampler::words`] as floats in `[0, 1)` (as [`to_f32`]).
    #[inline(always)]
    fn values<const N: usize>(&mut self, key: u64) -> [f32; N] {
        match self.cache.fast(slot(key)) {
            Some(hashes) => hashes.map(reversed_to_f32),
            None => match self.slow(key) {
                Slow::Hashes(hashes) => hashes.map(reversed_to_f32),
                Slow::Words(words) => words.map(to_f32),
            },
        }
    }

    /// [`ZSobolSampler::words`] off the cache's fast path: the fast path's
    /// hashes once the key's slot is refreshed for the pixel, if the
    /// layout has that path, else the words from the cache's general path
    /// or from the definition.
    #[inline(never)]
    fn slow<const N: usize>(&mut self, key: u64) -> Slow<N> {
        if self.cache.refresh_fast_path(key)
            && let Some(hashes) = self.cache.fast(slot(key))
        {
            return Slow::Hashes(hashes);
        }
        Slow::Words(match self.cache.words_general(key, self.morton) {
            Some(words) => words,
            None => self.direct_words(key),
        })
    }

    /// The scrambled words of Sobol dimensions `0..N` for `key`, computed
    /// from the definition ([`ZSobolSampler::sample_index`]).
    #[cold]
    #[inline(never)]
    fn direct_words<const N: usize>(&self, key: u64) -> [u32; N] {
        let index = self.sample_index(key);
        let seed = self.randomizer_seed(key, index >> 32);
        core::array::from_fn(|d| {
            let word = self.cache.net().sample(index as u32, d as u32);
            self.strategy.apply(word, seed, d as u32)
        })
    }

    /// The randomization strategy given at construction.
    pub fn strategy(&self) -> RandomizeStrategy {
        self.strategy
    }

    /// The generator matrices given at construction.
    pub fn net(&self) -> Net {
        self.cache.net()
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
        let [x, y] = pixel.map(|c| u64::from(c & mask));
        let masked = (x << 32) | y;
        let code = match self.last_pixel {
            Some((last, code)) if last == masked => code,
            _ => {
                let code = morton2(x as u32, y as u32);
                self.last_pixel = Some((masked, code));
                code
            }
        };
        let sample = if sample_index < self.spp {
            sample_index
        } else {
            sample_index % self.spp
        };
        self.morton = (code << self.log2_spp) | u64::from(sample);
        self.cache.start(self.morton);
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

    #[inline(always)]
    fn get_1d_value(&mut self) -> f32 {
        let key = super::next_key(&mut self.dimension, 1);
        let [value] = self.values(key);
        value
    }

    #[inline(always)]
    fn get_2d_values(&mut self) -> [f32; 2] {
        let key = super::next_key(&mut self.dimension, 2);
        self.values(key)
    }

    #[inline(always)]
    fn get_pixel_2d_values(&mut self) -> [f32; 2] {
        self.values(PIXEL_KEY)
    }

    /// The values from the cache's fast path in one go when every key has
    /// it (one counter update, range check and sample state read), else
    /// one call per value.
    #[inline(always)]
    fn get_values<const N: usize>(&mut self, dims: [Dims; N]) -> [[f32; 2]; N]
    where
        Self: Sized,
    {
        let first = self.dimension;
        let mut offsets = [0; N];
        let mut count = 0u32;
        for (offset, d) in offsets.iter_mut().zip(dims) {
            *offset = count as usize;
            count += d.count();
        }
        if let Some(hashes) = self.cache.fast_many(slot(u64::from(first)), offsets, dims) {
            self.dimension = first.wrapping_add(count);
            let mut values = [[0.0; 2]; N];
            for ((value, hash), d) in values.iter_mut().zip(hashes).zip(dims) {
                value[0] = reversed_to_f32(hash[0]);
                if d == Dims::Two {
                    value[1] = reversed_to_f32(hash[1]);
                }
            }
            return values;
        }
        super::values_in_order(self, dims)
    }
}

/// What [`ZSobolSampler::slow`] found.
enum Slow<const N: usize> {
    /// Hashes of the cache's fast path (the words bit-reversed).
    Hashes([u32; N]),
    /// The words.
    Words([u32; N]),
}

/// The cache slot of dimension key `key` (`1 + key`; 0 for the pixel key;
/// slots past the cache's end are not cached).
#[inline(always)]
fn slot(key: u64) -> usize {
    if key == PIXEL_KEY {
        0
    } else {
        usize::try_from(key).map_or(usize::MAX, |k| k.saturating_add(1))
    }
}

mod split_index;
pub(crate) use split_index::KeyIndex;

#[cfg(test)]
mod tests;
