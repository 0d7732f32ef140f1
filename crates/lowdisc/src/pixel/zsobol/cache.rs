//! The fast path of [`super::ZSobolSampler`]: the same values as
//! [`super::ZSobolSampler::sample_index`] and its randomizer, with the
//! hashing that does not change from value to value done once.
//!
//! * **Per dimension key** (the same for every pixel): the hash of the seed
//!   and the key, the level hash of every base-4 digit and the key of the
//!   odd low bit's flip.
//! * **Per dimension key and pixel** (the *pixel part*, `digits.rs`): the
//!   digits at or above the sample bits (shift `>= m`) depend only on the
//!   pixel's Morton code, so their permuted value, its Sobol words (the
//!   Sobol point is linear over GF(2) in the index bits, so the words of
//!   `upper | lower` are the XOR of the words of both parts) and the
//!   randomizer seeds (which depend on the index bits above 31, all among
//!   these digits as `m <= 32`) are kept until the pixel changes; only the
//!   pixel digits at or below the highest one that changed are permuted
//!   again. The permutations of the four highest sample digits are chosen
//!   by hashes of the pixel digits and at most three sample digits, so the
//!   1 + 4 + 16 + 64 of them are applied once, level by level, into a table
//!   of the permuted value of those digits for each of their (at most 256)
//!   values; the scramble key of each randomizer seed is kept too.
//! * **Per sample** ([`Cache::start`]): the pixel's code and the value of
//!   the tabled sample digits.
//! * **Per value**: one lookup in that table, the sample digits below those
//!   four (one bit mix each; none for `m <= 9`), the odd low bit's flip, a
//!   table lookup of the Sobol words of the low bits and the scramble.
//!   With no sample digits below the table's (`m` even, at most 8: `spp`
//!   1, 4, 16, 64 or 256) and the fast Owen scramble, that path
//!   ([`Cache::fast`]) is a tag compare, two lookups and the hash, without
//!   a call, so it inlines into the caller, and hands back the hash before
//!   its final bit reversal (a float is then read from the reversed word,
//!   [`crate::reversed_to_f32`]); refreshes, hashed digits and the other
//!   scrambles are out of line ([`Cache::words_general`]).
//!
//! Keys `0..CACHED_KEYS` and the pixel key are cached; any other key takes
//! the direct path.

use alloc::boxed::Box;
use alloc::vec::Vec;

use super::digits::{PixelSteps, below_top, first_step, refresh};
use super::entry::{Entry, Layout, NO_TAG, TOP_LEN, top_digits};
use super::{LOW_BIT_SALT, PIXEL_KEY};
use crate::RandomizeStrategy;
use crate::hash::{hash_words, mix64};
use crate::net::Net;
use crate::pixel::Dims;
use crate::pixel::SEED_PAD;
use crate::scramble::fast_owen_hash;

/// Dimension keys below this are cached (slot `1 + key`; slot 0 is the
/// pixel key).
const CACHED_KEYS: u64 = 1024;
/// Sample bits up to which the Sobol words of the low index bits are tabled.
const LOWER_TABLE_BITS: u32 = 10;
/// Entries of [`Cache::lower_words`].
const LOWER_LEN: usize = 1 << LOWER_TABLE_BITS;
/// [`Cache::tag`] when the layout has no fast path (no entry has this tag).
const NO_FAST_PATH: u64 = u64::MAX - 1;

/// Per-key hashes and per-pixel parts; see the module documentation.
#[derive(Debug, Clone)]
pub(super) struct Cache {
    layout: Layout,
    /// Index bits below the top sample digits ([`Entry::top`]).
    below: u32,
    /// Mask of the top sample digits' value (after shifting by `below`).
    top_mask: u64,
    /// Whether [`Cache::fast`] may serve values: no sample bits below the
    /// top digits (`m` even, at most 8), the fast Owen scramble and fewer
    /// than 32 pixel digits (so no code equals a tag with a meaning).
    short: bool,
    /// The current sample's tag: its pixel's Morton code if `short`, else
    /// [`NO_FAST_PATH`].
    tag: u64,
    /// The value of the current sample's tabled sample digits.
    top_index: u8,
    entries: Vec<Entry>,
    /// `levels[slot * base4_digits + i]`: the first step
    /// (`digits::first_step`) of the level hash of digit `i`.
    levels: Vec<u64>,
    /// The first steps of the last refreshed pixel's hash inputs.
    steps: PixelSteps,
    /// Sobol dimensions 0-1 of every `m`-bit index for `m` up to
    /// [`LOWER_TABLE_BITS`] (dimension 0 in the low half), bit-reversed:
    /// the words are kept reversed because the fast Owen scramble starts by
    /// reversing them (reversal commutes with XOR).
    lower_words: Box<[u64; LOWER_LEN]>,
    /// `digit_words[i][d]`: the same words of pixel digit `i` of value `d`
    /// (zero where the digit lies above index bit 31).
    digit_words: Vec<[u64; 4]>,
}

impl Cache {
    /// An empty cache for `layout`; tables the low-bit words when `m` is small.
    pub(super) fn new(layout: Layout) -> Self {
        let m = layout.log2_spp;
        let mut lower_words = Box::new([0; LOWER_LEN]);
        if m <= LOWER_TABLE_BITS {
            for (i, w) in lower_words.iter_mut().take(1 << m).enumerate() {
                *w = packed_reversed_words(layout.net, i as u32);
            }
        }
        let digit_words = (0..layout.pixel_digits())
            .map(|i| {
                let shift = m + 2 * i;
                core::array::from_fn(|d| match shift {
                    0..32 => packed_reversed_words(layout.net, (d as u32) << shift),
                    _ => 0,
                })
            })
            .collect();
        let t = top_digits(m);
        let below = m - 2 * t;
        Cache {
            layout,
            below,
            top_mask: (1 << (2 * t)) - 1,
            short: below == 0
                && m <= LOWER_TABLE_BITS
                && layout.strategy == RandomizeStrategy::FastOwen
                && layout.pixel_digits() < 32,
            tag: NO_FAST_PATH,
            top_index: 0,
            entries: Vec::new(),
            levels: Vec::new(),
            steps: PixelSteps::new(0, layout.pixel_digits()),
            lower_words,
            digit_words,
        }
    }

    /// The generator matrices.
    pub(super) fn net(&self) -> Net {
        self.layout.net
    }

    /// Starts the sample at Morton index `morton`.
    #[inline(always)]
    pub(super) fn start(&mut self, morton: u64) {
        self.tag = if self.short {
            morton >> self.layout.log2_spp
        } else {
            NO_FAST_PATH
        };
        self.top_index = (morton & self.top_mask) as u8;
    }

    /// The `N` (1 or 2) hashes of Sobol dimensions `0..N` of slot `slot`
    /// at the started sample, before their final bit reversal (the word is
    /// `hash.reverse_bits()`), if the fast path has them: the slot's pixel
    /// part is for this pixel and the layout is `short`.
    #[inline(always)]
    pub(super) fn fast<const N: usize>(&self, slot: usize) -> Option<[u32; N]> {
        let entry = self.entries.get(slot)?;
        if entry.tag != self.tag {
            return None;
        }
        let lower = entry.top[usize::from(self.top_index)];
        let words = entry.upper_words ^ self.lower_words[usize::from(lower)];
        Some(core::array::from_fn(|d| {
            let word = (words >> (32 * d)) as u32;
            fast_owen_hash(word, entry.keys[d], entry.multipliers[d])
        }))
    }

    /// [`Cache::fast`] of the slots `first + offsets[k]` (increasing
    /// offsets), of `dims[k]` Sobol dimensions each (lane 1 is 0 for one),
    /// if the fast path has them all.
    #[inline(always)]
    pub(super) fn fast_many<const N: usize>(
        &self,
        first: usize,
        offsets: [usize; N],
        dims: [Dims; N],
    ) -> Option<[[u32; 2]; N]> {
        let last = first.checked_add(*offsets.last()?)?;
        let entries = self.entries.get(first..=last)?;
        // Plain loops: the array helpers' closures do not always inline.
        let mut tagged = true;
        for &o in &offsets {
            tagged &= entries[o].tag == self.tag;
        }
        if !tagged {
            return None;
        }
        let top_index = usize::from(self.top_index);
        let mut hashes = [[0; 2]; N];
        for ((hash, &o), n) in hashes.iter_mut().zip(&offsets).zip(dims) {
            let entry = &entries[o];
            let lower = entry.top[top_index];
            let words = entry.upper_words ^ self.lower_words[usize::from(lower)];
            for (d, h) in hash.iter_mut().enumerate().take(n.count() as usize) {
                let word = (words >> (32 * d)) as u32;
                *h = fast_owen_hash(word, entry.keys[d], entry.multipliers[d]);
            }
        }
        Some(hashes)
    }

    /// Readies the slot of dimension key `key` for [`Cache::fast`] at the
    /// started sample (refreshing its pixel part); false if the layout has
    /// no fast path or `key` is not cached.
    #[inline(always)]
    pub(super) fn refresh_fast_path(&mut self, key: u64) -> bool {
        let Some(slot) = cached_slot(key) else {
            return false;
        };
        if self.short {
            self.refresh(slot, key, self.tag);
        }
        self.short
    }

    /// The `N` (1 or 2) scrambled words of Sobol dimensions `0..N` for
    /// dimension key `key` at Morton index `morton`, or `None` if `key` is
    /// not cached: refreshes the key's slot for the pixel if needed, hashes
    /// the sample digits below the top ones and applies any strategy.
    #[inline(never)]
    pub(super) fn words_general<const N: usize>(
        &mut self,
        key: u64,
        morton: u64,
    ) -> Option<[u32; N]> {
        let slot = cached_slot(key)?;
        let m = self.layout.log2_spp;
        let code = morton >> m;
        match self.entries.get(slot) {
            Some(entry) if entry.valid && entry.code == code => {}
            _ => self.refresh(slot, key, code),
        }
        let entry = &self.entries[slot];
        let below = self.below;
        let top = (morton >> below) & self.top_mask;
        let mut lower = u64::from(entry.top[top as usize & (TOP_LEN - 1)]) << below;
        if below != 0 {
            let digits = self.layout.base4_digits as usize;
            let levels = &self.levels[slot * digits..(slot + 1) * digits];
            lower |= below_top(levels, entry.low_key, m, morton);
        }
        let lower_words = if m <= LOWER_TABLE_BITS {
            self.lower_words[lower as usize & (LOWER_LEN - 1)]
        } else {
            packed_reversed_words(self.layout.net, lower as u32)
        };
        let entry = &self.entries[slot];
        let words = entry.upper_words ^ lower_words;
        Some(core::array::from_fn(|d| {
            let reversed = (words >> (32 * d)) as u32;
            self.layout
                .strategy
                .apply_key_reversed(reversed, entry.keys[d])
        }))
    }

    /// Recomputes the pixel part of slot `slot` (adding the slots up to it
    /// first) for the pixel with Morton code `code`.
    #[inline(always)]
    fn refresh(&mut self, slot: usize, key: u64, code: u64) {
        if slot >= self.entries.len() {
            self.grow(slot);
        }
        if self.steps.code != code {
            self.steps = PixelSteps::new(code, self.layout.pixel_digits());
        }
        let digits = self.layout.base4_digits as usize;
        let levels = &self.levels[slot * digits..(slot + 1) * digits];
        let entry = &mut self.entries[slot];
        refresh(
            entry,
            levels,
            &self.layout,
            &self.digit_words,
            key,
            &self.steps,
        );
        entry.tag = if self.short { code } else { NO_TAG };
    }

    /// Adds the entries of every slot up to `slot`.
    #[cold]
    fn grow(&mut self, slot: usize) {
        let layout = self.layout;
        for s in self.entries.len()..=slot {
            let key = if s == 0 { PIXEL_KEY } else { s as u64 - 1 };
            let dim_seed = hash_words(&[layout.seed, SEED_PAD, key]);
            self.levels.extend(
                (0..u64::from(layout.base4_digits)).map(|i| first_step(level(dim_seed, i))),
            );
            self.entries.push(Entry {
                tag: NO_TAG,
                upper_words: 0,
                keys: [0; 2],
                multipliers: [0; 2],
                top: [0; TOP_LEN],
                valid: false,
                code: 0,
                upper: 0,
                pixel_permutations: [0; 32],
                pixel_digits: [0; 32],
                seeded: false,
                high: 0,
                low_key: mix64(dim_seed ^ LOW_BIT_SALT),
            });
        }
    }
}

/// The slot of dimension key `key` if it is cached (slot 0 is the pixel
/// key's).
fn cached_slot(key: u64) -> Option<usize> {
    match key {
        PIXEL_KEY => Some(0),
        0..CACHED_KEYS => Some(key as usize + 1),
        _ => None,
    }
}

/// Dimensions 0 (low half) and 1 (high half) of `index` in `net`,
/// bit-reversed.
fn packed_reversed_words(net: Net, index: u32) -> u64 {
    let [a, b] = [net.sample(index, 0), net.sample(index, 1)].map(u32::reverse_bits);
    u64::from(a) | (u64::from(b) << 32)
}

/// The level hash of digit `i` for a dimension seed (as `sample_index`).
#[inline]
pub(super) fn level(dim_seed: u64, i: u64) -> u64 {
    mix64(dim_seed ^ i.wrapping_mul(0x9e37_79b9_7f4a_7c15))
}
