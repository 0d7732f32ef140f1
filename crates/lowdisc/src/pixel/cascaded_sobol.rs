//! Cascaded Sobol' sampling (`cascaded-sobol`), after Paulin, Coeurjolly,
//! Iehl, Bonneel, Keller and Ostromoukhov, "Cascaded Sobol' Sampling", ACM
//! TOG 40(6), SIGGRAPH Asia 2021: a per-pixel point set in which *every
//! consecutive pair of dimensions* is a (0,m,2)-net and every dimension is
//! stratified, implemented here from the paper's published description.
//!
//! ## The cascade
//! A pixel's `2^m` samples (`m = ceil(log2 spp)`) walk a chain of
//! *positions* `c = 0, 1, 2, ...`; each position holds one value per
//! sample, computed from an `m`-bit *index*:
//!
//! * position 0 (the start of a chain) takes the sample's index and gives
//!   its van der Corput value (the index bit-reversed);
//! * position `c + 1` takes as its index the leading `m` binary digits of
//!   the *scrambled* value at position `c`, read as an integer with the
//!   first digit as its lowest bit (the radical inverse), and gives Sobol
//!   dimension 1 of that index (the Pascal matrix);
//! * every value is then scrambled ([`RandomizeStrategy`], fast Owen in the
//!   catalog) under a seed of the sampler seed, the pixel and the position,
//!   over all 32 digits: the leading `m` digits are permuted as a tree, the
//!   digits below them ("the finer levels") are randomized.
//!
//! Why the pairs are nets: the index at position `c + 1` runs through all
//! of `0..2^m` exactly once over the pixel (induction: Sobol's matrices are
//! upper triangular, so an `m`-bit index gives a value with `m` digits, a
//! bijection; a nested scramble permutes the leading `m` digits as a
//! bijection). So positions `c` and `c + 1` are, digit for digit up to the
//! scramble of position `c + 1`, the pairs (van der Corput, Sobol
//! dimension 1) of the `2^m` indices: the first `2^m` points of Sobol's 2-D
//! (0,2)-sequence, a (0,m,2)-net, and a nested scramble keeps it one. The
//! chain drops Sobol's sequence property (the samples are a point set of
//! `2^m`), as the paper says.
//!
//! ## Generator matrices
//! The paper pairs van der Corput with one optimized 1-D Sobol' generator
//! per dimension. Of Joe and Kuo's matrices only dimension 1 (the Pascal
//! matrix) forms a (0,2)-sequence with van der Corput beyond `m = 4`
//! (checked over dimensions 1-59: the others fail at `m = 2` to `5`), and
//! the optimized tables are not reproduced here, so every position after a
//! chain's start uses the Pascal matrix. Under Owen scrambling that loses
//! nothing in distribution for the consecutive pairs (a nested uniform
//! scramble absorbs any left lower-triangular factor of a generator); the
//! non-consecutive pairs are those of independent scrambles.
//!
//! ## Dimensions
//! The in-pixel offset is positions 0-1 and sampler dimension `d` is
//! position `d + 2`, in the order the path tracer consumes them: film x,
//! film y, lens (2), then per vertex light choice, light position (2),
//! BSDF lobe, BSDF direction (2), Russian roulette. Every 2-D value is a
//! consecutive pair, and so is every neighbour in that order (film y with
//! the lens, the light choice with the light position...).
//!
//! ## Limits
//! * A chain restarts every [`CHAIN_LENGTH`] positions (its first position
//!   is the sample's van der Corput value again, under its own scramble),
//!   so a value started cold at dimension `d` costs at most that many
//!   steps; the pair across a restart is not a net.
//! * `spp` not a power of two: the first `spp` indices of `0..2^m`; the
//!   offset is a prefix of Sobol's (0,2)-sequence, later pairs are distinct
//!   boxes of the `2^m`-point net. Sample indices `>= spp` are reduced
//!   modulo `spp`.
//! * Values depend only on (pixel, sample, dimension), but reaching
//!   dimension `d` computes the chain up to it: the renderer's in-order
//!   calls take one step per value.
//! * Pixels are scrambled independently: the error is white noise between
//!   pixels (no Z-order); `spp` is at most `2^31`.

use super::WordSampler;
use crate::hash::hash_words;
use crate::scramble::dimension_seed;
use crate::sobol::sample;
use crate::{Error, RandomizeStrategy};

/// Positions per chain before it restarts from the sample index.
pub const CHAIN_LENGTH: u64 = 256;
/// Positions whose scramble keys are kept while the pixel stays the same.
const KEYED_POSITIONS: usize = 64;

/// The unscrambled word at chain position `position` for index `index`:
/// van der Corput at a chain's start, Sobol dimension 1 after.
#[inline]
pub fn cascade_word(position: u64, index: u32) -> u32 {
    if position % CHAIN_LENGTH == 0 {
        index.reverse_bits()
    } else {
        sample(index, 1)
    }
}

/// The index of the position after one whose scrambled word is `word`: its
/// leading `bits` digits, first digit lowest.
#[inline]
pub fn next_index(word: u32, bits: u32) -> u32 {
    word.reverse_bits() & low_mask(bits)
}

/// `2^bits - 1` (`bits <= 32`).
#[inline]
fn low_mask(bits: u32) -> u32 {
    ((1u64 << bits) - 1) as u32
}

/// Cascaded Sobol' pixel sampler; see the module documentation.
#[derive(Debug, Clone)]
pub struct CascadedSobolSampler {
    spp: u32,
    /// `m`: index bits.
    bits: u32,
    strategy: RandomizeStrategy,
    seed: u64,
    /// The current pixel and its scramble seed.
    pixel: Option<[u32; 2]>,
    pixel_seed: u64,
    /// Scramble keys of positions `0..KEYED_POSITIONS` in this pixel
    /// (bit `c` of `known` set when `keys[c]` is computed): the samples of
    /// a pixel share them, and a renderer visits them one after another.
    keys: [u32; KEYED_POSITIONS],
    known: u64,
    /// The current sample's index in its pixel.
    sample: u32,
    /// The next chain position to compute and its index.
    position: u64,
    index: u32,
    /// The scrambled offset (positions 0-1).
    offset: [u32; 2],
    /// The next sampler dimension.
    dimension: u32,
}

impl CascadedSobolSampler {
    /// A sampler for `spp` samples per pixel (`1..=2^31`), scrambled by
    /// `strategy` under `seed`.
    pub fn new(spp: u32, strategy: RandomizeStrategy, seed: u64) -> Result<Self, Error> {
        super::check_spp(spp)?;
        if spp > 1 << 31 {
            return Err(Error::InvalidSampleCount {
                count: u64::from(spp),
                reason: "cascaded Sobol' takes at most 2^31 samples per pixel",
            });
        }
        Ok(CascadedSobolSampler {
            spp,
            bits: super::ceil_log2(u64::from(spp)),
            strategy,
            seed,
            pixel: None,
            pixel_seed: 0,
            keys: [0; KEYED_POSITIONS],
            known: 0,
            sample: 0,
            position: 0,
            index: 0,
            offset: [0; 2],
            dimension: 0,
        })
    }

    /// The scrambled word at chain position `position` of the current
    /// sample, stepping the chain from where it is (or from the start of
    /// `position`'s chain if it is behind).
    fn word_at(&mut self, position: u64) -> u32 {
        let start = position - position % CHAIN_LENGTH;
        if self.position > position || self.position < start {
            self.position = start;
        }
        loop {
            let c = self.position;
            if c % CHAIN_LENGTH == 0 {
                self.index = self.sample;
            }
            let word = cascade_word(c, self.index);
            let key = self.scramble_key(c);
            let scrambled = self.strategy.apply_key_reversed(word.reverse_bits(), key);
            self.index = next_index(scrambled, self.bits);
            self.position = c + 1;
            if c == position {
                return scrambled;
            }
        }
    }
}

impl CascadedSobolSampler {
    /// The scramble key of position `c` in the current pixel:
    /// `strategy.scramble_key(dimension_seed(pixel_seed, c))`, kept for
    /// the first positions.
    #[inline]
    fn scramble_key(&mut self, c: u64) -> u32 {
        let compute = |s: &Self| (s.strategy).scramble_key(dimension_seed(s.pixel_seed, c as u32));
        let Some(slot) = usize::try_from(c).ok().filter(|&c| c < KEYED_POSITIONS) else {
            return compute(self);
        };
        if self.known & (1 << slot) == 0 {
            self.keys[slot] = compute(self);
            self.known |= 1 << slot;
        }
        self.keys[slot]
    }
}

impl WordSampler for CascadedSobolSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
        if self.pixel != Some(pixel) {
            let [x, y] = pixel.map(u64::from);
            self.pixel_seed = hash_words(&[self.seed, x, y]);
            self.pixel = Some(pixel);
            self.known = 0;
        }
        self.sample = sample_index % self.spp;
        self.position = 0;
        self.offset = [self.word_at(0), self.word_at(1)];
        self.dimension = dimension;
    }

    fn get_1d_word(&mut self) -> u32 {
        let d = super::next_key(&mut self.dimension, 1);
        self.word_at(d + 2)
    }

    fn get_2d_words(&mut self) -> [u32; 2] {
        let d = super::next_key(&mut self.dimension, 2);
        let first = self.word_at(d + 2);
        // The counter wraps like the other samplers' (`d + 1` past u32::MAX
        // is dimension 0).
        [
            first,
            self.word_at(u64::from((d as u32).wrapping_add(1)) + 2),
        ]
    }

    fn get_pixel_2d_words(&mut self) -> [u32; 2] {
        self.offset
    }
}

#[cfg(test)]
#[path = "cascaded_sobol_tests.rs"]
mod tests;
