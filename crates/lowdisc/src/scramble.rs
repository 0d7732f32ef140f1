//! Randomizations of digit words, after pbrt-v4's `RandomizeStrategy`: a
//! small seedless enum, [`RandomizeStrategy`], handed to the sequence
//! routines together with a seed.
//!
//! Each strategy maps a 32-bit digit word (bit 31 = first digit) to another,
//! with a seed that is first combined with the dimension, so every dimension
//! gets its own independent scramble:
//! * [`RandomizeStrategy::None`] is the identity.
//! * [`RandomizeStrategy::Xor`] is a random digital shift (XOR with a
//!   per-dimension word).
//! * [`RandomizeStrategy::Owen`] is exact nested uniform scrambling: digit `b`
//!   is flipped by a random bit drawn from a hash of the seed and digits `0..b`.
//! * [`RandomizeStrategy::Lms`] is Matoušek's linear matrix scrambling with a
//!   digital shift ([`lms`]): a random unit lower-triangular matrix times the
//!   word, XOR a random word.
//! * [`RandomizeStrategy::FastOwen`] is a Laine-Karras-style hash on bit-reversed
//!   words (Burley 2020, "Practical Hash-based Owen Scrambling", with the
//!   improved hash of N. Vegdahl 2021, "Building a Better LK Hash"): a
//!   nested scramble, though not an exactly uniform one. The hash multiplies
//!   by `(key >> 16) | 1`, so a key with small upper bits would get a tiny
//!   multiplier (39 for Sobol dimension 8 of `sobol-fast-owen` seed 0, 19
//!   for a key of `zsobol` seed 1); the strategy therefore hands every
//!   per-dimension seed to the hash through [`fast_owen_key`], which
//!   rehashes a seed whose multiplier has a run of more than 5 zero bits.
//!
//! All five keep a digital net a digital net: the first `2^m` Sobol points
//! of dimensions 0 and 1 remain a (0,m,2)-net (tested in `sobol::tests`).

mod cache;
pub mod lms;
pub mod owen_tree;
#[cfg(all(feature = "std", target_arch = "x86_64", lowdisc_avx512))]
mod owen_tree_avx512;
mod owen_tree_points;

pub use cache::{PreparedKey, ScrambleCache};
pub use lms::{LmsKey, lms_scramble};
pub use owen_tree::OwenTreeKey;
pub use owen_tree_points::OwenTreePoints;

use crate::hash::{hash2, mix64};

/// The initial and per-round constant of [`crate::hash::hash_words`], which
/// [`dimension_seeds_4`] and the Owen scramble unroll (tests check they agree).
const HASH_INIT: u64 = 0x9e37_79b9_7f4a_7c15;

/// How digit words are randomized: the strategy alone, without a seed (as
/// pbrt-v4's `RandomizeStrategy`). The seed is passed once to whatever holds
/// the strategy (a sampler, [`ScrambleCache`]) or to each call of
/// [`RandomizeStrategy::apply`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum RandomizeStrategy {
    /// The sequence as defined (deterministic; the seed is not used).
    #[default]
    None,
    /// Random digital shift (XOR scrambling).
    Xor,
    /// Exact Owen (nested uniform) scrambling. 32 hashes per value.
    Owen,
    /// Fast hash-based Owen scrambling (Laine-Karras / Burley / Vegdahl).
    FastOwen,
    /// Matoušek's linear matrix scrambling plus a digital shift (LMS + shift).
    Lms,
}

impl RandomizeStrategy {
    /// Every strategy, the identity first.
    pub const ALL: [RandomizeStrategy; 5] = [
        RandomizeStrategy::None,
        RandomizeStrategy::Xor,
        RandomizeStrategy::Owen,
        RandomizeStrategy::FastOwen,
        RandomizeStrategy::Lms,
    ];

    /// Randomizes digit word `word` of dimension `dim` under `seed` (the
    /// seed is combined with the dimension by [`dimension_seed`]).
    #[inline]
    pub fn apply(self, word: u32, seed: u64, dim: u32) -> u32 {
        match self {
            RandomizeStrategy::None => word,
            _ => self.apply_dimension_seed(word, dimension_seed(seed, dim)),
        }
    }

    /// The scramble of [`RandomizeStrategy::apply`] with the per-dimension
    /// seed already derived: `self.apply(word, seed, dim)` equals
    /// `self.apply_dimension_seed(word, dimension_seed(seed, dim))`. Lets
    /// callers that scramble many words of one dimension hash the seed once.
    #[inline(always)]
    pub fn apply_dimension_seed(self, word: u32, dimension_seed: u32) -> u32 {
        match self {
            RandomizeStrategy::None => word,
            RandomizeStrategy::Xor => word ^ dimension_seed,
            RandomizeStrategy::Owen => owen_scramble(word, dimension_seed),
            RandomizeStrategy::FastOwen => fast_owen_scramble(word, fast_owen_key(dimension_seed)),
            RandomizeStrategy::Lms => lms_scramble(word, dimension_seed),
        }
    }

    /// The scramble key of a per-dimension seed, for
    /// [`RandomizeStrategy::apply_key_reversed`]: [`fast_owen_key`] of it
    /// for [`RandomizeStrategy::FastOwen`], the seed itself otherwise. A
    /// caller that scrambles many words of one dimension derives it once.
    #[inline]
    pub fn scramble_key(self, dimension_seed: u32) -> u32 {
        match self {
            RandomizeStrategy::FastOwen => fast_owen_key(dimension_seed),
            _ => dimension_seed,
        }
    }

    /// [`RandomizeStrategy::apply_dimension_seed`] of
    /// `reversed.reverse_bits()`, given `key = self.scramble_key(dimension_seed)`:
    /// the fast Owen scramble works on bit-reversed words, so a caller that
    /// keeps its words reversed saves a reversal.
    #[inline(always)]
    pub fn apply_key_reversed(self, reversed: u32, key: u32) -> u32 {
        match self {
            RandomizeStrategy::FastOwen => fast_owen_scramble_reversed(reversed, key),
            r => r.apply_dimension_seed(reversed.reverse_bits(), key),
        }
    }

    /// Randomizes the digit words of dimensions `dim..dim + 4` at once: lane
    /// `k` equals `self.apply(words[k], seed, dim + k)`. The hashing of the
    /// seed is shared between the lanes and the fast Owen scramble runs on
    /// all four lanes together (written for the compiler's vectoriser).
    #[inline(always)]
    pub fn apply_4(self, words: [u32; 4], seed: u64, dim: u32) -> [u32; 4] {
        match self {
            RandomizeStrategy::None => words,
            RandomizeStrategy::Xor => {
                let seeds = dimension_seeds_4(seed, dim);
                core::array::from_fn(|k| words[k] ^ seeds[k])
            }
            RandomizeStrategy::Owen => {
                let seeds = dimension_seeds_4(seed, dim);
                core::array::from_fn(|k| owen_scramble(words[k], seeds[k]))
            }
            RandomizeStrategy::FastOwen => {
                fast_owen_scramble_4(words, dimension_seeds_4(seed, dim).map(fast_owen_key))
            }
            RandomizeStrategy::Lms => {
                let seeds = dimension_seeds_4(seed, dim);
                core::array::from_fn(|k| lms_scramble(words[k], seeds[k]))
            }
        }
    }

    /// A short name: `none`, `xor`, `owen`, `fast-owen` or `lms`.
    pub fn name(self) -> &'static str {
        match self {
            RandomizeStrategy::None => "none",
            RandomizeStrategy::Xor => "xor",
            RandomizeStrategy::Owen => "owen",
            RandomizeStrategy::FastOwen => "fast-owen",
            RandomizeStrategy::Lms => "lms",
        }
    }

    /// The prepared key of a per-dimension seed, for the strategies whose
    /// per-seed setup costs more than a scramble (Owen, LMS); `None` for the
    /// others, which use the seed as it is.
    pub fn prepare(self, dimension_seed: u32) -> Option<PreparedKey> {
        match self {
            RandomizeStrategy::Owen => Some(PreparedKey::Owen(OwenKey::new(dimension_seed))),
            RandomizeStrategy::Lms => Some(PreparedKey::Lms(LmsKey::new(dimension_seed))),
            _ => None,
        }
    }

    /// Whether [`RandomizeStrategy::prepare`] gives a key.
    pub fn prepares(self) -> bool {
        matches!(self, RandomizeStrategy::Owen | RandomizeStrategy::Lms)
    }
}

/// The 32-bit seed of one dimension, derived from a user seed.
#[inline]
pub fn dimension_seed(seed: u64, dim: u32) -> u32 {
    (hash2(seed, u64::from(dim)) >> 32) as u32
}

/// The seeds of dimensions `dim..dim + 4`: lane `k` equals
/// `dimension_seed(seed, dim + k)` (wrapping past `u32::MAX`).
///
/// The first round of `hash2`, which depends on `seed` only, is computed once.
#[inline]
pub fn dimension_seeds_4(seed: u64, dim: u32) -> [u32; 4] {
    let shared = seed_round(seed);
    core::array::from_fn(|k| {
        let d = dim.wrapping_add(k as u32);
        (finish_round(shared, u64::from(d)) >> 32) as u32
    })
}

/// The first round of `hash2(seed, _)` (see [`crate::hash::hash_words`]).
#[inline]
fn seed_round(seed: u64) -> u64 {
    mix64(HASH_INIT ^ 2 ^ seed).wrapping_add(HASH_INIT)
}

/// The second round and finaliser of `hash2(seed, word)`, from
/// [`seed_round`]`(seed)`.
#[inline]
fn finish_round(shared: u64, word: u64) -> u64 {
    mix64(mix64(shared ^ word).wrapping_add(HASH_INIT))
}

/// Exact Owen scrambling of a 32-bit digit word.
///
/// Digit `b` (bit `31 - b`) is XORed with one bit of `hash(seed, b, digits 0..b)`,
/// so the flip of each digit depends on all digits before it, as nested uniform
/// scrambling requires. The last digit's flip is not truncated: all 32 digits
/// are scrambled.
// Not inlined: 32 rounds of hashing dwarf a call, and inlining it would keep
// the cheap strategies' `match` arms from being inlined.
#[inline(never)]
pub fn owen_scramble(word: u32, seed: u32) -> u32 {
    // hash3(seed, b, prefix): the round that absorbs `seed` is shared by
    // all 32 digits (see [`OwenKey`] for the round of `b` too).
    let shared = owen_seed_round(seed);
    let mut out = word;
    for b in 0..32u32 {
        let round = mix64(shared ^ u64::from(b)).wrapping_add(HASH_INIT);
        out ^= owen_flip(round, word, b) << (31 - b);
    }
    out
}

/// The first round of `hash3(seed, _, _)` (see [`crate::hash::hash_words`]).
#[inline(always)]
fn owen_seed_round(seed: u32) -> u64 {
    mix64(HASH_INIT ^ 3 ^ u64::from(seed)).wrapping_add(HASH_INIT)
}

/// The flip of digit `b` of `word`: the top bit of `hash3(seed, b, prefix)`
/// finished from its first two rounds `round`.
#[inline(always)]
fn owen_flip(round: u64, word: u32, b: u32) -> u32 {
    // Digits 0..b of the input (the prefix), aligned at the bottom.
    let prefix = if b == 0 { 0 } else { word >> (32 - b) };
    (mix64(mix64(round ^ u64::from(prefix)).wrapping_add(HASH_INIT)) >> 63) as u32
}

/// [`owen_scramble`] with one seed's hashing done in advance: the first two
/// rounds of `hash3(seed, b, _)` for the 32 digits `b`, so a scramble costs
/// two bit mixes per digit instead of three. For callers that scramble
/// several words with one seed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OwenKey {
    rounds: [u64; 32],
}

impl OwenKey {
    /// The key of `seed` (a per-dimension seed, as [`owen_scramble`] takes).
    pub fn new(seed: u32) -> Self {
        let shared = owen_seed_round(seed);
        OwenKey {
            rounds: core::array::from_fn(|b| mix64(shared ^ b as u64).wrapping_add(HASH_INIT)),
        }
    }

    /// Equals `owen_scramble(word, seed)` for the seed of [`OwenKey::new`].
    #[inline]
    pub fn scramble(&self, word: u32) -> u32 {
        let mut out = word;
        for (b, &round) in (0..32u32).zip(&self.rounds) {
            out ^= owen_flip(round, word, b) << (31 - b);
        }
        out
    }
}

/// The longest run of zero bits [`fast_owen_key`] allows in the 16-bit
/// multiplier `(key >> 16) | 1` (leading zeros count as a run).
const MAX_ZERO_RUN: u32 = 5;

/// Whether the 16-bit multiplier `m` has a run of more than
/// [`MAX_ZERO_RUN`] zero bits.
#[inline(always)]
fn has_long_zero_run(m: u32) -> bool {
    let mut run = !m & 0xffff;
    for _ in 0..MAX_ZERO_RUN {
        run &= run >> 1;
    }
    run != 0
}

/// The key [`RandomizeStrategy::FastOwen`] gives [`fast_owen_scramble`] for
/// a per-dimension seed: the seed itself when its multiplier
/// `(seed >> 16) | 1` has no run of more than 5 zero bits, otherwise the
/// first rehash of it that has none (after 8 rehashes, which a random seed
/// needs with probability below 1e-8, the upper half is ORed with
/// `0x5555`, whose runs are single zeros).
///
/// On the reversed word the multiply carries bit `i` into bit `i + k` for
/// every set bit `k` of the multiplier; a run of zeros from bit `a` to `b`
/// leaves the digits `a..=b` places below a digit out of its scramble but
/// for carries. A seed with small upper bits is the extreme case: seed 0 of
/// `sobol-fast-owen` gave Sobol dimension 8 the multiplier 39, zeros from
/// bit 6 up. About 9 % of uniformly random seeds are rehashed.
#[inline]
pub fn fast_owen_key(dimension_seed: u32) -> u32 {
    let mut key = dimension_seed;
    for _ in 0..8 {
        if !has_long_zero_run((key >> 16) | 1) {
            return key;
        }
        key = (mix64(u64::from(key) ^ FAST_OWEN_REHASH) >> 32) as u32;
    }
    key | 0x5555_0000
}

/// Salt of [`fast_owen_key`]'s rehash.
const FAST_OWEN_REHASH: u64 = 0x6c6b_5f72_6568_6173;

/// Fast hash-based Owen scrambling (Laine-Karras style permutation of a
/// bit-reversed word: the hash of N. Vegdahl, "Building a Better LK Hash",
/// 2021, also used by the `sobol_burley` crate and Blender Cycles), keyed by
/// `seed` as it is (bit for bit `sobol_burley::parts::owen_scramble_rev` of
/// the reversed word); [`RandomizeStrategy::FastOwen`] keys it with
/// [`fast_owen_key`].
///
/// On the reversed word, a bit only influences higher bits, i.e. in the
/// original word each digit's flip depends only on earlier digits, which is
/// the structure of a nested scramble.
#[inline]
pub fn fast_owen_scramble(word: u32, seed: u32) -> u32 {
    fast_owen_scramble_reversed(word.reverse_bits(), seed)
}

/// [`fast_owen_scramble`] of `reversed.reverse_bits()`.
#[inline(always)]
pub(crate) fn fast_owen_scramble_reversed(reversed: u32, seed: u32) -> u32 {
    fast_owen_hash(reversed, seed, fast_owen_multiplier(seed)).reverse_bits()
}

/// The multiplier the fast Owen hash derives from its seed (see
/// [`fast_owen_hash`]); a caller that keeps a seed keeps this too.
#[inline(always)]
pub(crate) fn fast_owen_multiplier(seed: u32) -> u32 {
    (seed >> 16) | 1
}

/// The hash of [`fast_owen_scramble_reversed`] before its final reversal,
/// with the seed's `multiplier` ([`fast_owen_multiplier`]) given:
/// `fast_owen_scramble_reversed(r, seed)` equals
/// `fast_owen_hash(r, seed, fast_owen_multiplier(seed)).reverse_bits()`.
#[inline(always)]
pub(crate) fn fast_owen_hash(reversed: u32, seed: u32, multiplier: u32) -> u32 {
    let mut x = reversed;
    x ^= x.wrapping_mul(0x3d20_adea);
    x = x.wrapping_add(seed);
    x = x.wrapping_mul(multiplier);
    x ^= x.wrapping_mul(0x0552_6c56);
    x ^= x.wrapping_mul(0x53a2_2864);
    x
}

/// [`fast_owen_scramble`] on four words with four seeds: lane `k` equals
/// `fast_owen_scramble(words[k], seeds[k])`. Each step is a loop over the
/// lanes, which the compiler turns into SIMD code.
#[inline]
pub fn fast_owen_scramble_4(words: [u32; 4], seeds: [u32; 4]) -> [u32; 4] {
    let mut x = words;
    for v in &mut x {
        *v = v.reverse_bits();
    }
    for v in &mut x {
        *v ^= v.wrapping_mul(0x3d20_adea);
    }
    for (v, &s) in x.iter_mut().zip(&seeds) {
        *v = v.wrapping_add(s);
    }
    for (v, &s) in x.iter_mut().zip(&seeds) {
        *v = v.wrapping_mul((s >> 16) | 1);
    }
    for v in &mut x {
        *v ^= v.wrapping_mul(0x0552_6c56);
    }
    for v in &mut x {
        *v ^= v.wrapping_mul(0x53a2_2864);
    }
    for v in &mut x {
        *v = v.reverse_bits();
    }
    x
}

/// A seed from a user seed and a salt naming its use, so independent uses of
/// one user seed do not share random choices.
#[inline]
pub fn derive_seed(seed: u64, salt: u64) -> u64 {
    mix64(seed ^ mix64(salt.wrapping_add(0x6a09_e667_f3bc_c909)))
}

#[cfg(test)]
mod tests;
