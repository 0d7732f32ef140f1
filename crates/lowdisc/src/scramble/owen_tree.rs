//! Owen (nested uniform) scrambling at a few hashes per value: the flips of
//! the scramble tree are drawn subtree by subtree, 63 nodes per 64-bit hash.
//!
//! [`super::owen_scramble`] draws every node's flip from its own hash, 32
//! hashes per digit word. [`OwenTreeKey`] is the same kind of scramble (every
//! output digit is its input digit XOR a random bit of its own tree node,
//! which depends only on the digits before it) with the randomness laid out
//! so that one hash serves a whole subtree:
//!
//! * The binary tree of digit prefixes is cut into layers of
//!   [`SUBTREE_DEPTH`] = 6 levels: layer `t` holds the digits `6t .. 6t + 5`.
//!   A layer-`t` subtree is rooted at a prefix `r` of the first `6t` digits
//!   and has 63 nodes.
//! * The subtree of root `r` in layer `t` of dimension `dim` draws the 64-bit
//!   word `mix64(K_t + r * GAMMA)`: value `r` of a SplitMix64 stream, with
//!   `K_t = hash3(derive_seed(seed, SALT), dim, t)` and `GAMMA` SplitMix64's
//!   increment.
//! * The node at local depth `i` (digit `6t + i`) whose `i` local digits
//!   before it read `q` flips its digit by bit `2^i - 1 + q` of that word
//!   (bits 0, 1-2, 3-6, 7-14, 15-30, 31-62 for depths 0..5; bit 63 unused).
//!
//! Distinct nodes therefore use distinct bits of distinct hash inputs, so
//! under the usual assumption that the hash behaves as a random function
//! every node's flip is an independent fair bit: the scramble is exact in
//! distribution. The flips of the first [`TABLE_DIGITS`] = 12 digits (two
//! layers, 65 subtrees) are kept in a table of 4096 entries, so a digit word
//! costs one table load and one hash per further layer: three hashes for
//! 30 digits, four for 32, instead of 32.
//!
//! The values differ from [`super::owen_scramble`]'s (the renderer's
//! `sobol-owen` sampler); the distribution of the scrambled point set is the
//! same.

use alloc::vec::Vec;

use crate::hash::{hash3, mix64};

use super::derive_seed;

/// Levels of the tree whose flips one 64-bit hash holds (`2^6 - 1 = 63` nodes).
pub const SUBTREE_DEPTH: u32 = 6;
/// Leading digits whose flips are kept in the key's table.
pub const TABLE_DIGITS: u32 = 12;
/// Layers of [`SUBTREE_DEPTH`] levels that cover the 32 digits.
pub(super) const LAYERS_TOTAL: usize = 32_usize.div_ceil(SUBTREE_DEPTH as usize);
/// SplitMix64's increment (the golden ratio times `2^64`, odd).
pub(super) const GAMMA: u64 = 0x9e37_79b9_7f4a_7c15;
/// Dimensions per vector of the AVX-512 kernel: the key arrays of
/// [`super::OwenTreePoints`] are padded to a multiple of it.
pub(super) const LANES: usize = 8;
/// Salt of the seed (so this scramble's randomness is not another's).
const SALT: u64 = 0x6f77_656e_5f74_7265;

/// `PATH3[(bits & 127) << 3 | q]`: the flips of depths 0-2 (at bits 5-3)
/// on the path whose first three local digits read `q`, from the node bits
/// 0-6 of a subtree (depth 0: bit 0; depth 1: bits 1-2; depth 2: bits 3-6).
const PATH3: [u8; 1024] = {
    let mut table = [0u8; 1024];
    let mut k = 0;
    while k < 1024 {
        let (bits, q) = (k >> 3, k & 7);
        let f0 = bits & 1;
        let f1 = (bits >> (1 + (q >> 2))) & 1;
        let f2 = (bits >> (3 + (q >> 1))) & 1;
        table[k] = (f0 << 5 | f1 << 4 | f2 << 3) as u8;
        k += 1;
    }
    table
};

/// The flips of the 6 nodes on the path of local digits `local` (6 digits,
/// the first at bit 5) through the subtree whose node bits are `bits`, as a
/// 6-digit XOR mask (the first digit's flip at bit 5). The node of depth
/// `i` is bit `2^i - 1` plus the `i` local digits before it.
#[inline(always)]
fn path_flips(bits: u64, local: u32) -> u32 {
    let top = u32::from(PATH3[((bits as usize & 127) << 3) | (local >> 3) as usize]);
    let f3 = ((bits >> (7 + (local >> 3))) & 1) as u32;
    let f4 = ((bits >> (15 + (local >> 2))) & 1) as u32;
    let f5 = ((bits >> (31 + (local >> 1))) & 1) as u32;
    top | f3 << 2 | f4 << 1 | f5
}

/// One dimension's Owen scramble under one seed (see the module docs for the
/// randomness each node gets).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OwenTreeKey {
    /// `K_t` of each layer.
    layer_keys: [u64; LAYERS_TOTAL],
    /// Digits whose flips are in `top` (6 or 12).
    table_digits: u32,
    /// XOR masks of the first `table_digits` digits, by those digits.
    top: Vec<u16>,
}

impl OwenTreeKey {
    /// The scramble of dimension `dim` under `seed`, with the flips of the
    /// first [`TABLE_DIGITS`] digits in a table (4096 entries, 8 KiB).
    pub fn new(seed: u64, dim: u32) -> Self {
        Self::with_table(seed, dim, TABLE_DIGITS)
    }

    /// The same scramble with a table of the first `table_digits` digits'
    /// flips: 6 (64 entries, one hash more per value) or 12 (4096 entries);
    /// other values are rounded to these. The values do not depend on it.
    pub fn with_table(seed: u64, dim: u32, table_digits: u32) -> Self {
        let mut key = OwenTreeKey {
            layer_keys: layer_keys(seed, dim),
            table_digits: if table_digits > SUBTREE_DEPTH {
                TABLE_DIGITS
            } else {
                SUBTREE_DEPTH
            },
            top: Vec::new(),
        };
        let root = key.subtree_bits(0, 0);
        let width = 1u32 << SUBTREE_DEPTH;
        let top: Vec<u16> = if key.table_digits == SUBTREE_DEPTH {
            (0..width)
                .map(|first| path_flips(root, first) as u16)
                .collect()
        } else {
            (0..width)
                .flat_map(|first| {
                    let high = path_flips(root, first) << SUBTREE_DEPTH;
                    let bits = key.subtree_bits(1, first);
                    (0..width).map(move |next| (high | path_flips(bits, next)) as u16)
                })
                .collect()
        };
        key.top = top;
        key
    }

    /// The 63 node bits of the subtree of layer `layer` rooted at `root`.
    #[inline(always)]
    fn subtree_bits(&self, layer: usize, root: u32) -> u64 {
        mix64(self.layer_keys[layer].wrapping_add(u64::from(root).wrapping_mul(GAMMA)))
    }

    /// The scrambled word: all 32 digits.
    #[inline]
    pub fn scramble(&self, word: u32) -> u32 {
        self.scramble_digits(word, 32)
    }

    /// The first `digits` digits of [`OwenTreeKey::scramble`]`(word)` (the
    /// others 0), for `digits` in `1..=32`; deeper layers are not hashed.
    #[inline(always)]
    pub fn scramble_digits(&self, word: u32, digits: u32) -> u32 {
        match layers_of(digits) {
            0..=2 => self.scramble_layers::<2>(word, digits),
            3 => self.scramble_layers::<3>(word, digits),
            4 => self.scramble_layers::<4>(word, digits),
            5 => self.scramble_layers::<5>(word, digits),
            _ => self.scramble_layers::<6>(word, digits),
        }
    }

    /// [`OwenTreeKey::scramble_digits`] with the number of layers to hash
    /// known at compile time, for callers that scramble many words with one
    /// `digits` (which must be at most `6 * LAYERS`; `LAYERS` from
    /// [`layers_of`]`(digits)`, or 2 for fewer digits, hashes no more than
    /// needed).
    #[inline(always)]
    pub fn scramble_layers<const LAYERS: usize>(&self, word: u32, digits: u32) -> u32 {
        let flips = if self.table_digits == TABLE_DIGITS {
            self.flips::<2, LAYERS>(word)
        } else {
            self.flips::<1, LAYERS>(word)
        };
        (word ^ flips) & (u32::MAX << (32 - digits.clamp(1, 32)))
    }

    /// The flips of the digits of layers `0..LAYERS` of `word`, layers
    /// `0..FIRST` from the table (which must hold `6 * FIRST` digits).
    #[inline(always)]
    fn flips<const FIRST: usize, const LAYERS: usize>(&self, word: u32) -> u32 {
        let table = SUBTREE_DEPTH * FIRST as u32;
        let mut flips = u32::from(self.top[(word >> (32 - table)) as usize]) << (32 - table);
        for t in FIRST..LAYERS.min(LAYERS_TOTAL) {
            let above = SUBTREE_DEPTH * t as u32;
            let bits = self.subtree_bits(t, word >> (32 - above));
            // The layer's digits end at digit above + 5; the last layer has
            // only 2 digits (30 and 31), shifted up to the path's top.
            flips |= match (32 - above).checked_sub(SUBTREE_DEPTH) {
                Some(shift) => path_flips(bits, (word >> shift) & 63) << shift,
                None => {
                    let pad = above + SUBTREE_DEPTH - 32;
                    path_flips(bits, (word << pad) & 63) >> pad
                }
            };
        }
        flips
    }
}

/// `K_t` of the layers `t` of dimension `dim` under `seed`.
pub(super) fn layer_keys(seed: u64, dim: u32) -> [u64; LAYERS_TOTAL] {
    let salted = derive_seed(seed, SALT);
    core::array::from_fn(|t| hash3(salted, u64::from(dim), t as u64))
}

/// The layers that hold the first `digits` digits, `ceil(digits / 6)`.
#[inline(always)]
pub fn layers_of(digits: u32) -> u32 {
    digits.clamp(1, 32).div_ceil(SUBTREE_DEPTH)
}

#[cfg(test)]
#[path = "owen_tree_tests.rs"]
mod tests;
