//! Randomizations of digit words, in the spirit of pbrt-v4's
//! `RandomizeStrategy`: one small enum handed to the sequence routines.
//!
//! Each strategy maps a 32-bit digit word (bit 31 = first digit) to another,
//! with a seed that is first combined with the dimension, so every dimension
//! gets its own independent scramble:
//! * [`Randomize::None`]: identity.
//! * [`Randomize::Xor`]: random digital shift (XOR with a per-dimension word).
//! * [`Randomize::Owen`]: exact nested uniform scrambling: digit `b` is flipped
//!   by a random bit drawn from a hash of the seed and digits `0..b`.
//! * [`Randomize::FastOwen`]: the Laine-Karras hash on bit-reversed words
//!   with the constants of Burley (2020), "Practical Hash-based Owen
//!   Scrambling"; an Owen scramble in distribution-like behaviour, not
//!   an exactly uniform one.
//!
//! All four keep a digital net a digital net: the first `2^m` Sobol points
//! of dimensions 0 and 1 remain a (0,m,2)-net (tested in `sobol::tests`).

use crate::hash::{hash2, hash3, mix64};

/// How digit words are randomized.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Randomize {
    /// The sequence as defined (deterministic).
    #[default]
    None,
    /// Random digital shift (XOR scrambling), seeded.
    Xor {
        /// Seed; combined with the dimension.
        seed: u64,
    },
    /// Exact Owen (nested uniform) scrambling, seeded. 32 hashes per value.
    Owen {
        /// Seed; combined with the dimension.
        seed: u64,
    },
    /// Fast hash-based Owen scrambling (Laine-Karras / Burley), seeded.
    FastOwen {
        /// Seed; combined with the dimension.
        seed: u64,
    },
}

impl Randomize {
    /// Randomizes digit word `word` of dimension `dim`.
    #[inline]
    pub fn apply(self, word: u32, dim: u32) -> u32 {
        match self {
            Randomize::None => word,
            Randomize::Xor { seed } => word ^ dimension_seed(seed, dim),
            Randomize::Owen { seed } => owen_scramble(word, dimension_seed(seed, dim)),
            Randomize::FastOwen { seed } => fast_owen_scramble(word, dimension_seed(seed, dim)),
        }
    }

    /// A short name: `none`, `xor`, `owen` or `fast-owen`.
    pub fn name(self) -> &'static str {
        match self {
            Randomize::None => "none",
            Randomize::Xor { .. } => "xor",
            Randomize::Owen { .. } => "owen",
            Randomize::FastOwen { .. } => "fast-owen",
        }
    }
}

/// The 32-bit seed of one dimension, derived from a user seed.
#[inline]
pub fn dimension_seed(seed: u64, dim: u32) -> u32 {
    (hash2(seed, u64::from(dim)) >> 32) as u32
}

/// Exact Owen scrambling of a 32-bit digit word.
///
/// Digit `b` (bit `31 - b`) is XORed with one bit of `hash(seed, b, digits 0..b)`,
/// so the flip of each digit depends on all digits before it, as nested uniform
/// scrambling requires. The last digit's flip is not truncated: all 32 digits
/// are scrambled.
#[inline]
pub fn owen_scramble(word: u32, seed: u32) -> u32 {
    let mut out = word;
    for b in 0..32u32 {
        // Digits 0..b of the input (the prefix), aligned at the bottom.
        let prefix = if b == 0 { 0 } else { word >> (32 - b) };
        let flip = hash3(u64::from(seed), u64::from(b), u64::from(prefix)) >> 63;
        out ^= (flip as u32) << (31 - b);
    }
    out
}

/// Fast hash-based Owen scrambling (Laine-Karras style permutation of a
/// bit-reversed word, with Burley's 2020 constants).
///
/// On the reversed word, a bit only influences higher bits, i.e. in the
/// original word each digit's flip depends only on earlier digits, which is
/// the structure of a nested scramble.
#[inline]
pub fn fast_owen_scramble(word: u32, seed: u32) -> u32 {
    let mut x = word.reverse_bits();
    x ^= x.wrapping_mul(0x3d20_adea);
    x = x.wrapping_add(seed);
    x = x.wrapping_mul((seed >> 16) | 1);
    x ^= x.wrapping_mul(0x0552_6c56);
    x ^= x.wrapping_mul(0x53a2_2864);
    x.reverse_bits()
}

/// A seed from a user seed and a salt naming its use, so independent uses of
/// one user seed do not share random choices.
#[inline]
pub fn derive_seed(seed: u64, salt: u64) -> u64 {
    mix64(seed ^ mix64(salt.wrapping_add(0x6a09_e667_f3bc_c909)))
}
