//! The per-pixel samplers of Burley 2020, "Practical Hash-based Owen
//! Scrambling" (JCGT 9(4)): Owen-scrambled Sobol with a shuffled index and
//! padding by groups of four dimensions, with Vegdahl's hash
//! (`sobol-burley`) or the original Laine-Karras hash (`laine-karras`), and
//! per-pixel Sobol with a random digital shift (`sobol-pixel-xor`).
//!
//! ## Shuffled, scrambled, padded ([`BurleySampler`])
//! Every pixel gets a 32-bit seed (a hash of the sampler seed and the
//! pixel). The in-pixel offset and the sampler dimensions are laid out as
//! *virtual dimensions* `v`: the offset is `v = 0, 1`, sampler dimension `d`
//! is `v = d + 2`. Virtual dimension `v` is lane `v % 4` of group `v / 4`;
//! group `g` has its own seed (a hash of the pixel seed and `g`), and its
//! value for sample `i` is [`burley_word`]: the index is shuffled by a
//! nested (Owen) scramble of its bits keyed by the group seed, then Sobol
//! dimension `lane` at the shuffled index is Owen-scrambled with a key of
//! the group seed and the lane. Groups therefore use Sobol dimensions 0-3
//! only, in independent random orders (the padding), and within a group the
//! four lanes stay jointly stratified: the offset with sampler dimensions
//! 0-1 (the lens, in this project's renderer) in group 0. A 2-D value whose
//! two dimensions straddle groups (`v % 4 == 3`) takes one lane from each.
//!
//! The function [`burley_word`] is Burley's `sobol_burley::sample` (crate
//! 0.5: the same seed hashing, the same constants, indices below 2^16) on
//! digit words, with one change: a fast-Owen key whose multiplier has a long
//! zero run is rehashed first ([`fast_owen_key`]); with strong keys the two
//! agree bit for bit (tested). The `laine-karras` variant replaces the
//! Vegdahl hash by Laine and Karras's 2011 hash (constants as printed in
//! Burley 2020, Listing 1) in both the shuffle and the scramble.
//!
//! Any `spp` in `1..=65536` works: the shuffle maps the first `2^m` indices
//! onto an aligned block of `2^m` (a (0,m,2)-net in lanes 0-1 for
//! `spp = 2^m`); other counts use the first `spp` points of the shuffled
//! block. Sample indices `>= spp` are reduced modulo `spp`.
//!
//! ## Per-pixel Sobol + digital shift ([`PixelXorSampler`])
//! Sample `i` of every pixel is Sobol point `i` (virtual dimension `v` is
//! Sobol dimension `v`, wrapping past the table's end to dimension 2), XORed
//! with a per-pixel, per-dimension random word: the pixels share one
//! sequence, each under its own digital shift. Any `spp >= 1`; indices
//! `>= spp` continue the sequence.

use super::WordSampler;
use crate::hash::{hash_words, mix64};
use crate::scramble::{fast_owen_key, fast_owen_scramble_reversed};
use crate::sobol::{NUM_DIMENSIONS, sample};
use crate::{Error, RandomizeStrategy};

/// Burley's 32-bit seed hash (`sobol_burley::parts::hash`: Wellons's
/// "lowbias32" after an XOR so that zero does not map to zero).
#[inline]
pub fn seed_hash(mut n: u32) -> u32 {
    n ^= 0xe6fe_3beb;
    n ^= n >> 16;
    n = n.wrapping_mul(0x7feb_352d);
    n ^= n >> 15;
    n = n.wrapping_mul(0x846c_a68b);
    n ^ (n >> 16)
}

/// Laine & Karras's 2011 nested permutation of a bit-reversed word (the
/// seed enters by one addition only), returned un-reversed.
#[inline]
pub fn laine_karras_scramble_reversed(reversed: u32, seed: u32) -> u32 {
    let mut x = reversed.wrapping_add(seed);
    x ^= x.wrapping_mul(0x6c50_b47c);
    x ^= x.wrapping_mul(0xb82f_1e52);
    x ^= x.wrapping_mul(0xc7af_e638);
    x ^= x.wrapping_mul(0x8d22_f6e6);
    x.reverse_bits()
}

/// The nested hash a [`BurleySampler`] uses for its shuffle and scramble.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NestedHash {
    /// Vegdahl 2021 (as `sobol_burley`), keys through [`fast_owen_key`].
    Vegdahl,
    /// Laine & Karras 2011.
    LaineKarras,
}

impl NestedHash {
    /// The nested scramble of digit word `word` under `key`.
    #[inline]
    fn scramble(self, word: u32, key: u32) -> u32 {
        match self {
            NestedHash::Vegdahl => fast_owen_scramble_reversed(word.reverse_bits(), key),
            NestedHash::LaineKarras => laine_karras_scramble_reversed(word.reverse_bits(), key),
        }
    }

    /// The key the hash is given for a hashed seed.
    #[inline]
    fn key(self, hashed: u32) -> u32 {
        match self {
            NestedHash::Vegdahl => fast_owen_key(hashed),
            NestedHash::LaineKarras => hashed,
        }
    }
}

/// Per-lane constants of Burley's scramble seeds (`sobol_burley` 0.5).
const LANE_SALTS: [u32; 4] = [0x912f_69ba, 0x174f_18ab, 0x691e_72ca, 0xb40c_c1b8];

/// Sobol dimension `dim` of sample `index` (`< 2^16`) under 32-bit `seed`, as `sobol_burley::sample(index, dim,
/// seed)` but as a 32-bit digit word and with strong keys (see the module
/// documentation); `hash` picks the nested hash.
#[inline]
pub fn burley_word(index: u32, dim: u32, seed: u32, hash: NestedHash) -> u32 {
    let shuffle_key = hash.key(seed_hash(seed ^ 0x79c6_8e4a));
    let shuffled = hash.scramble(index, shuffle_key) & 0xffff;
    let lane_seed = (dim >> 2) ^ seed.wrapping_mul(0x9c8f_2d3b) ^ LANE_SALTS[dim as usize & 3];
    hash.scramble(sample(shuffled, dim), hash.key(seed_hash(lane_seed)))
}

/// The samplers of this module: a value per virtual dimension `v` (the
/// in-pixel offset at `v = 0, 1`, sampler dimension `d` at `v = d + 2`).
trait VirtualDimensions {
    /// The dimension counter.
    fn counter(&mut self) -> &mut u32;
    /// Virtual dimension `v` at the current sample.
    fn word(&self, v: u32) -> u32;
}

/// The next 1-D value of a [`VirtualDimensions`] sampler.
fn virtual_1d(s: &mut impl VirtualDimensions) -> u32 {
    let d = super::next_key(s.counter(), 1) as u32;
    s.word(d.wrapping_add(2))
}

/// The next 2-D value of a [`VirtualDimensions`] sampler.
fn virtual_2d(s: &mut impl VirtualDimensions) -> [u32; 2] {
    let v = (super::next_key(s.counter(), 2) as u32).wrapping_add(2);
    [s.word(v), s.word(v.wrapping_add(1))]
}

/// Burley's shuffled, Owen-scrambled, 4-D padded per-pixel Sobol; see the
/// module documentation.
#[derive(Debug, Clone)]
pub struct BurleySampler {
    spp: u32,
    seed: u64,
    hash: NestedHash,
    pixel_seed: u32,
    index: u32,
    dimension: u32,
}

impl BurleySampler {
    /// A sampler with `spp` samples per pixel (`1..=65536`).
    pub fn new(spp: u32, hash: NestedHash, seed: u64) -> Result<Self, Error> {
        super::check_spp(spp)?;
        if spp > 1 << 16 {
            return Err(Error::InvalidSampleCount {
                count: u64::from(spp),
                reason: "Burley's shuffled Sobol addresses at most 65536 samples per pixel",
            });
        }
        Ok(BurleySampler {
            spp,
            seed,
            hash,
            pixel_seed: 0,
            index: 0,
            dimension: 0,
        })
    }

    /// The seed of group `g` of the current pixel.
    #[inline]
    fn group_seed(&self, g: u32) -> u32 {
        (mix64((u64::from(self.pixel_seed) << 32) ^ u64::from(g)) >> 32) as u32
    }
}

impl VirtualDimensions for BurleySampler {
    fn counter(&mut self) -> &mut u32 {
        &mut self.dimension
    }

    #[inline]
    fn word(&self, v: u32) -> u32 {
        burley_word(self.index, v & 3, self.group_seed(v >> 2), self.hash)
    }
}

impl WordSampler for BurleySampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
        let [x, y] = pixel.map(u64::from);
        self.pixel_seed = (hash_words(&[self.seed, x, y]) >> 32) as u32;
        self.index = sample_index % self.spp;
        self.dimension = dimension;
    }

    fn get_1d_word(&mut self) -> u32 {
        virtual_1d(self)
    }

    fn get_2d_words(&mut self) -> [u32; 2] {
        virtual_2d(self)
    }

    fn get_pixel_2d_words(&mut self) -> [u32; 2] {
        [self.word(0), self.word(1)]
    }
}

/// Per-pixel Sobol with a random digital shift; see the module
/// documentation.
#[derive(Debug, Clone)]
pub struct PixelXorSampler {
    spp: u32,
    seed: u64,
    pixel_seed: u64,
    index: u32,
    dimension: u32,
}

impl PixelXorSampler {
    /// A sampler with `spp >= 1` samples per pixel.
    pub fn new(spp: u32, seed: u64) -> Result<Self, Error> {
        super::check_spp(spp)?;
        Ok(PixelXorSampler {
            spp,
            seed,
            pixel_seed: 0,
            index: 0,
            dimension: 0,
        })
    }
}

impl VirtualDimensions for PixelXorSampler {
    fn counter(&mut self) -> &mut u32 {
        &mut self.dimension
    }

    #[inline]
    fn word(&self, v: u32) -> u32 {
        let dim = if v < 2 {
            v
        } else {
            2 + (v - 2) % (NUM_DIMENSIONS as u32 - 2)
        };
        RandomizeStrategy::Xor.apply(sample(self.index, dim), self.pixel_seed, dim)
    }
}

impl WordSampler for PixelXorSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
        let [x, y] = pixel.map(u64::from);
        self.pixel_seed = hash_words(&[self.seed, x, y]);
        self.index = sample_index;
        self.dimension = dimension;
    }

    fn get_1d_word(&mut self) -> u32 {
        virtual_1d(self)
    }

    fn get_2d_words(&mut self) -> [u32; 2] {
        virtual_2d(self)
    }

    fn get_pixel_2d_words(&mut self) -> [u32; 2] {
        [self.word(0), self.word(1)]
    }
}
