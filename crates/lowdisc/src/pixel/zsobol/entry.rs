//! The data of the cached path (`cache.rs`): the sampler's [`Layout`] and
//! what is known about one dimension key ([`Entry`]), with the size of the
//! table of the highest sample digits. The digit permutations
//! (`digits.rs`) fill entries and the cache reads them.

use crate::RandomizeStrategy;
use crate::net::Net;

/// [`Entry::tag`] of an entry the fast path must not use.
pub(super) const NO_TAG: u64 = u64::MAX;

/// The sampler constants the fast path needs.
#[derive(Debug, Clone, Copy)]
pub(super) struct Layout {
    /// The sampler seed.
    pub seed: u64,
    /// The randomization strategy (seeded from `seed`).
    pub strategy: RandomizeStrategy,
    /// `m`: sample bits of the index.
    pub log2_spp: u32,
    /// Base-4 digits of the index (above the odd low bit, if any).
    pub base4_digits: u32,
    /// The generator matrices (dimensions 0-1 are read).
    pub net: Net,
}

impl Layout {
    /// The base-4 digits of the pixel's Morton code (`log2 R`).
    pub fn pixel_digits(&self) -> u32 {
        self.base4_digits - self.log2_spp.div_ceil(2)
    }
}

/// What is known about one dimension key.
#[derive(Debug, Clone)]
pub(super) struct Entry {
    /// The Morton code the pixel part is for while the cache's fast path
    /// (`Cache::fast`) may use the entry, else [`NO_TAG`].
    pub tag: u64,
    /// Sobol dimensions 0 (low half) and 1 (high half) of the low 32 bits
    /// of the permuted pixel digits, bit-reversed (as
    /// `Cache::lower_words`).
    pub upper_words: u64,
    /// Scramble keys ([`RandomizeStrategy::scramble_key`]) of the
    /// per-dimension seeds of Sobol dimensions 0 and 1.
    pub keys: [u32; 2],
    /// The fast Owen hash's multipliers of `keys`.
    pub multipliers: [u32; 2],
    /// The permuted value of the [`TOP_DIGITS`] (or fewer, see
    /// [`top_digits`]) highest sample digits, indexed by their value.
    pub top: [u8; TOP_LEN],
    /// Whether the pixel part is computed (for `code`).
    pub valid: bool,
    /// Morton code of the pixel the pixel part is for.
    pub code: u64,
    /// The permuted pixel digits, in place (index bits `>= m`).
    pub upper: u64,
    /// The permutation of every pixel digit `i` (its index into
    /// [`super::BASE4_PERMUTATIONS`]), for `code`.
    pub pixel_permutations: [u8; 32],
    /// Every permuted pixel digit (`upper`, digit by digit).
    pub pixel_digits: [u8; 32],
    /// Whether `keys` is computed (for `high`).
    pub seeded: bool,
    /// Index bits above 31 the keys are for.
    pub high: u64,
    /// Key of the odd low bit's flip.
    pub low_key: u64,
}

/// Sample digits (at most) that [`Entry::top`] permutes by lookup.
const TOP_DIGITS: u32 = 4;
/// Entries of [`Entry::top`]: `4^TOP_DIGITS`.
pub(super) const TOP_LEN: usize = 1 << (2 * TOP_DIGITS);

/// Sample digits in [`Entry::top`] for `m` sample bits.
#[inline(always)]
pub(super) fn top_digits(m: u32) -> u32 {
    (m / 2).min(TOP_DIGITS)
}
