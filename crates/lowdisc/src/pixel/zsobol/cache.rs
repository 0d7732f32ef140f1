//! The fast path of [`super::ZSobolSampler`]: the same values as
//! [`super::ZSobolSampler::sample_index`] and its randomizer, with the
//! hashing that does not change from value to value done once.
//!
//! * **Per dimension key** (the same for every pixel): the hash of the seed
//!   and the key, the level hash of every base-4 digit and the key of the
//!   odd low bit's flip.
//! * **Per dimension key and pixel**: the digits at or above the sample bits
//!   (shift `>= m`) depend only on the pixel's Morton code, so their
//!   permuted value, its Sobol words (the Sobol point is linear over GF(2)
//!   in the index bits, so the words of `upper | lower` are the XOR of the
//!   words of both parts) and the randomizer seeds (which depend on the
//!   index bits above 31, all among these digits as `m <= 32`) are kept
//!   until the pixel changes. A renderer visits the samples of a pixel one
//!   after another, so this is computed once per pixel and key.
//!   The permutations of the four highest sample digits are chosen by
//!   hashes of the pixel digits and at most three sample digits, so the
//!   1 + 4 + 16 + 64 of them are applied once, level by level, into a table
//!   of the permuted value of those digits for each of their (at most 256)
//!   values; the scramble key of each randomizer seed is kept too.
//! * **Per value**: one lookup in that table, the sample digits below those
//!   four (one bit mix each; none for `m <= 9`), the odd low bit's flip, a
//!   table lookup of the Sobol words of the low bits and the scramble.
//!   With no sample digits below the table's (`m` even, at most 8: `spp`
//!   1, 4, 16, 64 or 256) and the fast Owen scramble, that path makes no
//!   call, so it inlines into the caller; refreshes, hashed digits and the
//!   other scrambles are out of line.
//!
//! Keys `0..CACHED_KEYS` and the pixel key are cached; any other key takes
//! the direct path.

use alloc::vec::Vec;

use super::{BASE4_PERMUTATIONS, LOW_BIT_SALT, PIXEL_KEY};
use crate::RandomizeStrategy;
use crate::hash::{bounded, hash_words, mix64};
use crate::pixel::SEED_PAD;
use crate::scramble::{dimension_seed, fast_owen_scramble_reversed};
use crate::sobol::sample;

/// Dimension keys below this are cached (slot `1 + key`; slot 0 is the
/// pixel key).
const CACHED_KEYS: u64 = 1024;
/// Sample bits up to which the Sobol words of the low index bits are tabled.
const LOWER_TABLE_BITS: u32 = 10;

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
}

/// What is known about one dimension key.
#[derive(Debug, Clone)]
struct Entry {
    /// Key of the odd low bit's flip.
    low_key: u64,
    /// Whether the pixel part below is computed (for `code`).
    valid: bool,
    /// Morton code of the pixel the pixel part is for.
    code: u64,
    /// Sobol dimensions 0-1 of the low 32 bits of the permuted pixel
    /// digits, bit-reversed (see `Cache::lower_words`).
    upper_words: [u32; 2],
    /// The permuted value of the [`TOP_DIGITS`] (or fewer, see
    /// [`top_digits`]) highest sample digits, indexed by their value.
    top: [u8; TOP_LEN],
    /// Whether `keys` is computed (for `high`).
    seeded: bool,
    /// Index bits above 31 the keys are for.
    high: u64,
    /// Scramble keys ([`RandomizeStrategy::scramble_key`]) of the
    /// per-dimension seeds of Sobol dimensions 0 and 1.
    keys: [u32; 2],
}

/// The caches of one sampler (see the module documentation).
#[derive(Debug, Clone)]
pub(super) struct Cache {
    layout: Layout,
    /// Index bits below the top sample digits ([`Entry::top`]).
    below: u32,
    /// Mask of the top sample digits' value (after shifting by `below`).
    top_mask: u64,
    /// Whether [`Cache::words`] may take its shortest path: no sample bits
    /// below the top digits (`m` even, at most 8), the low-bit words
    /// tabled and the fast Owen scramble.
    short: bool,
    entries: Vec<Entry>,
    /// `levels[slot * base4_digits + i]`: the level hash of digit `i`.
    levels: Vec<u64>,
    /// Sobol dimensions 0-1 of every `m`-bit index (empty for large `m`),
    /// bit-reversed: the words are kept reversed because the fast Owen
    /// scramble starts by reversing them (reversal commutes with XOR).
    lower_words: Vec<[u32; 2]>,
}

impl Cache {
    /// An empty cache for `layout`; tables the low-bit words when `m` is small.
    pub(super) fn new(layout: Layout) -> Self {
        let lower_words = if layout.log2_spp <= LOWER_TABLE_BITS {
            (0..1u32 << layout.log2_spp).map(reversed_words).collect()
        } else {
            Vec::new()
        };
        let t = top_digits(layout.log2_spp);
        let below = layout.log2_spp - 2 * t;
        Cache {
            layout,
            below,
            top_mask: (1 << (2 * t)) - 1,
            short: below == 0
                && !lower_words.is_empty()
                && layout.strategy == RandomizeStrategy::FastOwen,
            entries: Vec::new(),
            levels: Vec::new(),
            lower_words,
        }
    }

    /// The `N` (1 or 2) scrambled words of Sobol dimensions `0..N` for
    /// dimension key `key` at Morton index `morton`, or `None` if `key` is
    /// not cached.
    #[inline(always)]
    pub(super) fn words<const N: usize>(&mut self, key: u64, morton: u64) -> Option<[u32; N]> {
        let slot = if key == PIXEL_KEY {
            0
        } else if key < CACHED_KEYS {
            key as usize + 1
        } else {
            return None;
        };
        let code = morton >> self.layout.log2_spp;
        if self.short
            && let Some(entry) = self.entries.get(slot)
            && entry.valid
            && entry.code == code
        {
            // A lookup and the scramble, without a call (the common case).
            let lower = entry.top[(morton & self.top_mask) as usize & (TOP_LEN - 1)];
            let lower_words = self.lower_words[usize::from(lower)];
            return Some(core::array::from_fn(|d| {
                fast_owen_scramble_reversed(entry.upper_words[d] ^ lower_words[d], entry.keys[d])
            }));
        }
        Some(self.words_general(slot, key, morton))
    }

    /// [`Cache::words`] of a cached `slot` in general: refreshes the slot
    /// for the pixel if needed, hashes the sample digits below the top
    /// ones and applies any strategy.
    #[inline(never)]
    fn words_general<const N: usize>(&mut self, slot: usize, key: u64, morton: u64) -> [u32; N] {
        let code = morton >> self.layout.log2_spp;
        match self.entries.get(slot) {
            Some(entry) if entry.valid && entry.code == code => {}
            _ => self.refresh(slot, key, code),
        }
        let entry = &self.entries[slot];
        let below = self.below;
        let top = (morton >> below) & self.top_mask;
        let mut lower = u64::from(entry.top[top as usize & (TOP_LEN - 1)]) << below;
        if below != 0 {
            lower |= self.below_top(slot, morton);
        }
        let lower_words = match self.lower_words.get(lower as usize) {
            Some(&w) => w,
            None => reversed_words(lower as u32),
        };
        let entry = &self.entries[slot];
        core::array::from_fn(|d| {
            let reversed = entry.upper_words[d] ^ lower_words[d];
            self.layout
                .strategy
                .apply_key_reversed(reversed, entry.keys[d])
        })
    }

    /// The permuted index bits below the top sample digits of slot `slot`:
    /// the sample digits under them (one bit mix each) and the odd low bit.
    #[inline(never)]
    fn below_top(&self, slot: usize, morton: u64) -> u64 {
        let m = self.layout.log2_spp;
        let odd = m & 1;
        let digits = self.layout.base4_digits as usize;
        let levels = &self.levels[slot * digits..(slot + 1) * digits];
        let entry = &self.entries[slot];
        let mut lower = 0;
        // The digits below the top ones (index `i` at shift `2i - odd`).
        let rest = m / 2 - top_digits(m) + odd;
        for (i, &level) in (odd..rest).zip(&levels[odd as usize..]) {
            lower |= permuted_digit(level, morton, 2 * i - odd);
        }
        if odd == 1 {
            let flip = mix64(entry.low_key ^ (morton >> 1)) >> 63;
            lower |= (morton & 1) ^ flip;
        }
        lower
    }

    /// Recomputes the pixel part of slot `slot` (adding the slots up to it
    /// first) for the pixel with Morton code `code`.
    #[inline(never)]
    fn refresh(&mut self, slot: usize, key: u64, code: u64) {
        if slot >= self.entries.len() {
            self.grow(slot);
        }
        let digits = self.layout.base4_digits as usize;
        let levels = &self.levels[slot * digits..(slot + 1) * digits];
        refresh(&mut self.entries[slot], levels, &self.layout, key, code);
    }

    /// Adds the entries of every slot up to `slot`.
    #[cold]
    fn grow(&mut self, slot: usize) {
        let layout = self.layout;
        for s in self.entries.len()..=slot {
            let key = if s == 0 { PIXEL_KEY } else { s as u64 - 1 };
            let dim_seed = hash_words(&[layout.seed, SEED_PAD, key]);
            self.levels
                .extend((0..u64::from(layout.base4_digits)).map(|i| level(dim_seed, i)));
            self.entries.push(Entry {
                low_key: mix64(dim_seed ^ LOW_BIT_SALT),
                valid: false,
                code: 0,
                upper_words: [0; 2],
                top: [0; TOP_LEN],
                seeded: false,
                high: 0,
                keys: [0; 2],
            });
        }
    }
}

/// Sobol dimensions 0-1 of `index`, bit-reversed.
#[inline]
fn reversed_words(index: u32) -> [u32; 2] {
    [sample(index, 0), sample(index, 1)].map(u32::reverse_bits)
}

/// The level hash of digit `i` for a dimension seed (as `sample_index`).
#[inline]
pub(super) fn level(dim_seed: u64, i: u64) -> u64 {
    mix64(dim_seed ^ i.wrapping_mul(0x9e37_79b9_7f4a_7c15))
}

/// [`BASE4_PERMUTATIONS`] packed two bits per image: permutation `p` maps
/// digit `d` to `(PACKED_PERMUTATIONS[p] >> 2d) & 3`.
const PACKED_PERMUTATIONS: [u8; 24] = {
    let mut out = [0u8; 24];
    let mut p = 0;
    while p < 24 {
        let q = BASE4_PERMUTATIONS[p];
        out[p] = q[0] | (q[1] << 2) | (q[2] << 4) | (q[3] << 6);
        p += 1;
    }
    out
};

/// [`BASE4_PERMUTATIONS`] as four bytes, image of digit `d` in byte `d`
/// (little-endian): a digit's permuted images appended to a prefix `q`
/// are `SPREAD_PERMUTATIONS[p] | q * 0x0101_0101`.
const SPREAD_PERMUTATIONS: [u32; 24] = {
    let mut out = [0u32; 24];
    let mut p = 0;
    while p < 24 {
        let q = BASE4_PERMUTATIONS[p];
        out[p] = u32::from_le_bytes(q);
        p += 1;
    }
    out
};

/// The index (into [`BASE4_PERMUTATIONS`]) of the permutation chosen for a
/// digit with level hash `level` and higher digits `higher`.
#[inline(always)]
fn permutation_index(level: u64, higher: u64) -> usize {
    bounded(mix64(level ^ higher), 24) as usize
}

/// The packed permutation chosen for a digit with level hash `level` and
/// higher digits `higher`.
#[inline(always)]
fn packed_permutation(level: u64, higher: u64) -> u8 {
    PACKED_PERMUTATIONS[permutation_index(level, higher)]
}

/// Applies a packed permutation to the digit of `morton` at `shift`.
#[inline(always)]
fn apply_packed(packed: u8, morton: u64, shift: u32) -> u64 {
    let digit = (morton >> shift) & 3;
    u64::from((packed >> (2 * digit)) & 3) << shift
}

/// The permuted base-4 digit `i` (at `shift`) of `morton`.
#[inline(always)]
fn permuted_digit(level: u64, morton: u64, shift: u32) -> u64 {
    let higher = morton.checked_shr(shift + 2).unwrap_or(0);
    apply_packed(packed_permutation(level, higher), morton, shift)
}

/// Recomputes the pixel part of `entry` for the pixel with Morton code `code`.
fn refresh(entry: &mut Entry, levels: &[u64], layout: &Layout, key: u64, code: u64) {
    let m = layout.log2_spp;
    let odd = m & 1;
    // `code << m` fits: the index has at most 64 bits.
    let morton = code << m;
    let mut upper = 0u64;
    for (i, &level) in (m.div_ceil(2)..).zip(&levels[m.div_ceil(2) as usize..]) {
        upper |= permuted_digit(level, morton, 2 * i - odd);
    }
    entry.upper_words = reversed_words(upper as u32);
    // The highest sample digits, level by level: the `j`-th from the top
    // is digit `top - 1 - j`; its permutation is chosen by the pixel code
    // and the `j` digits above it (value `v`). Each pass extends the
    // permuted prefixes of `j` digits (`entry.top[v]`) by one digit, in
    // place from the end (entry `4v + d` is written after `v` is read).
    let top = m.div_ceil(2) as usize;
    entry.top[0] = 0;
    for j in 0..top_digits(m) {
        let level = levels[top - 1 - j as usize];
        for v in (0..1usize << (2 * j)).rev() {
            let p = permutation_index(level, (code << (2 * j)) | v as u64);
            let prefixed = SPREAD_PERMUTATIONS[p] | (u32::from(entry.top[v] << 2) * 0x0101_0101);
            entry.top[4 * v..4 * v + 4].copy_from_slice(&prefixed.to_le_bytes());
        }
    }
    let high = upper >> 32;
    if !entry.seeded || entry.high != high {
        let h = hash_words(&[layout.seed, SEED_PAD, key, high]);
        entry.keys = [0, 1].map(|d| layout.strategy.scramble_key(dimension_seed(h, d)));
        entry.high = high;
        entry.seeded = true;
    }
    entry.code = code;
    entry.valid = true;
}

/// Sample digits (at most) that [`Entry::top`] permutes by lookup.
const TOP_DIGITS: u32 = 4;
/// Entries of [`Entry::top`]: `4^TOP_DIGITS`.
const TOP_LEN: usize = 1 << (2 * TOP_DIGITS);

/// Sample digits in [`Entry::top`] for `m` sample bits.
#[inline(always)]
fn top_digits(m: u32) -> u32 {
    (m / 2).min(TOP_DIGITS)
}
