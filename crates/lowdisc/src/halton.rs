//! The Halton sequence (6,542 dimensions: every prime base below `2^16`), unscrambled, with random
//! digit permutations, or Owen-scrambled.
//!
//! Dimension `d` is the radical inverse in base `b = PRIMES[d]` (dimension 0 is
//! base 2, the van der Corput sequence): the base-`b` digits `a_0, a_1, ...` of
//! the index (least significant first) are mirrored about the point,
//! `x = a_0/b + a_1/b^2 + ...`.
//!
//! ## Randomizations ([`HaltonRandomize`])
//! * `None`: the definition. Values are exact rationals `R / b^m`.
//! * `PermuteDigits`: as pbrt-v4's `DigitPermutation`: digit position `i` of
//!   dimension `d` gets its own uniformly random permutation `pi_{d,i}` of
//!   `0..b` (Fisher-Yates from a PCG32 stream seeded by the seed and `d`), and
//!   the value is `sum_i pi_{d,i}(a_i) b^-(i+1)`.
//! * `Owen`: Owen's nested uniform scrambling in base `b`: the permutation
//!   applied to digit `i` is keyed by a hash chain over the seed, `d` and the
//!   index digits `a_0..a_{i-1}` before it, so points that share a prefix
//!   share the permutation and all others get independent ones, and each
//!   permutation is uniform over all `b!` permutations of `0..b`. The image
//!   of a digit `a` is read from a Fisher-Yates shuffle keyed by the node
//!   (step `t` swaps position `t` with `t + bounded(hash, b - t)`) by tracing
//!   position `a` back through steps `a, a-1, .., 0`: `a + 1` hashes, no
//!   table. Each draw is uniform up to the `b / 2^64` bias of a 64-bit
//!   multiply-shift.
//! * `NestedAffine`: the same nesting and key chain, but each permutation is
//!   the affine map `a -> (m a + c) mod b` with `m` uniform in `1..b` and `c`
//!   uniform in `0..b` (`b` is prime, so these are bijections): one hash per
//!   digit. The family is sharply 2-transitive (one digit maps to a uniform
//!   digit, two distinct digits to a uniform pair of distinct digits), which
//!   gives Owen's variance, but it maps arithmetic progressions of digits to
//!   arithmetic progressions, so its point sets are not Owen's in
//!   distribution beyond pairs. For bases 2 and 3 the affine maps are the
//!   whole symmetric group, and `Owen` uses them there too: in dimensions 0
//!   and 1 the two variants give the same values.
//!
//! ## The infinite tail of zero digits
//! An index has finitely many nonzero digits, but its radical inverse has
//! infinitely many digit positions, all zero past the last nonzero digit.
//! A scramble maps those zeros to `pi_i(0)`, which is generally not zero, so
//! the scrambled value has an infinite random tail (pbrt-v3 summed it as a
//! geometric series for its single per-dimension permutation; pbrt-v4 keeps
//! scrambling digit positions, zeros included, until they fall below float
//! precision). Here both randomizations scramble exactly
//! [`scrambled_digits`]`(b) = K` positions, the smallest `K` with
//! `b^K >= 2^64`, zeros included (every `u64` index has at most `K` digits),
//! and drop the rest: the value is the scrambled expansion truncated after `K`
//! digits, which is below the infinite one by less than `b^-K <= 2^-64`.
//!
//! ## Output forms
//! [`Halton::sample_fixed64`] is `floor(x * 2^64)` of that `K`-digit value,
//! computed exactly in integers; [`Halton::sample_word`] its top 32 bits
//! (`floor(x * 2^32)`, the crate's digit word); [`Halton::sample`] the `f64`
//! nearest to the 64-bit value (absolute error below `2^-63`), clamped below 1.
//!
//! Cost: the digits are handled in 32-bit chunks (two 64-bit divisions per
//! chunk, multiply-shift divisions by the base), so `None` and
//! `PermuteDigits` cost a few tens of nanoseconds; `NestedAffine` adds one
//! 64-bit hash per scrambled digit (64 in base 2, 41 in base 3, 5 in base
//! 8161) and `Owen` `a + 2` hashes per digit `a` (zero digits, the tail,
//! cost 2; on average about `b / 2` per nonzero digit).
//!
//! Permutation tables are built lazily, one dimension at a time on first use,
//! and shared between clones (with the `std` feature; without it they are
//! rebuilt on every call, which gives the same values, slowly).

mod digits;
mod primes;
mod tables;
#[cfg(test)]
mod tests;

pub use primes::{NUM_DIMENSIONS, PRIMES, prime, scrambled_digits};

use crate::Error;
use crate::hash::{bounded, hash2, mix64};
use crate::scramble::derive_seed;
use digits::{BASES, Base, MAX_DIGITS};

/// The largest `f64` below 1.
const ONE_MINUS_EPSILON_F64: f64 = 1.0 - f64::EPSILON / 2.0;

/// How the Halton sequence is randomized (see the module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum HaltonRandomize {
    /// The sequence as defined.
    #[default]
    None,
    /// Random digit permutations, one per dimension and digit position.
    PermuteDigits,
    /// Owen's nested uniform scrambling in base `b`.
    Owen,
    /// Nested scrambling by random affine digit maps (not Owen's law
    /// beyond pairs of points; see the module documentation).
    NestedAffine,
}

impl HaltonRandomize {
    /// All randomizations, in declaration order.
    pub const ALL: [HaltonRandomize; 4] = [
        HaltonRandomize::None,
        HaltonRandomize::PermuteDigits,
        HaltonRandomize::Owen,
        HaltonRandomize::NestedAffine,
    ];

    /// The randomization called `name` (as [`HaltonRandomize::name`] gives
    /// it), or `None`.
    pub fn from_name(name: &str) -> Option<HaltonRandomize> {
        Self::ALL.into_iter().find(|r| r.name() == name)
    }

    /// A short name: `none`, `permute`, `owen` or `nested-affine`.
    pub fn name(self) -> &'static str {
        match self {
            HaltonRandomize::None => "none",
            HaltonRandomize::PermuteDigits => "permute",
            HaltonRandomize::Owen => "owen",
            HaltonRandomize::NestedAffine => "nested-affine",
        }
    }
}

/// A (possibly randomized) Halton sequence with random access by index and
/// dimension.
#[derive(Clone)]
pub struct Halton {
    randomize: HaltonRandomize,
    seed: u64,
    /// `derive_seed(seed, SALT_PERMUTE)` or `derive_seed(seed, SALT_OWEN)`
    /// as the randomization needs (hashed once, not per value).
    derived_seed: u64,
    tables: tables::PermutationTables,
}

impl core::fmt::Debug for Halton {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Halton")
            .field("randomize", &self.randomize)
            .field("seed", &self.seed)
            .finish_non_exhaustive()
    }
}

impl Halton {
    /// A Halton sequence with the given randomization. `seed` is ignored by
    /// [`HaltonRandomize::None`]. Does not build any permutation table yet.
    pub fn new(randomize: HaltonRandomize, seed: u64) -> Halton {
        let tables = tables::PermutationTables::new(randomize == HaltonRandomize::PermuteDigits);
        let derived_seed = match randomize {
            HaltonRandomize::None => 0,
            HaltonRandomize::PermuteDigits => derive_seed(seed, SALT_PERMUTE),
            HaltonRandomize::Owen | HaltonRandomize::NestedAffine => derive_seed(seed, SALT_OWEN),
        };
        Halton {
            randomize,
            seed,
            derived_seed,
            tables,
        }
    }

    /// The randomization.
    pub fn randomize(&self) -> HaltonRandomize {
        self.randomize
    }

    /// The seed.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// `Ok` if `dim` is a dimension of the sequence (`dim < NUM_DIMENSIONS`).
    pub fn check_dimension(dim: u32) -> Result<(), Error> {
        if dim < NUM_DIMENSIONS {
            Ok(())
        } else {
            Err(Error::DimensionOutOfRange {
                dimension: u64::from(dim),
                available: u64::from(NUM_DIMENSIONS),
            })
        }
    }

    /// Point `index` of dimension `dim` in `[0, 1)`.
    ///
    /// # Panics
    /// If `dim >= NUM_DIMENSIONS`; use [`Halton::try_sample`] or
    /// [`Halton::check_dimension`] to validate first.
    #[inline]
    pub fn sample(&self, index: u64, dim: u32) -> f64 {
        fixed64_to_f64(self.sample_fixed64(index, dim))
    }

    /// [`Halton::sample`], or an error for a dimension out of range.
    pub fn try_sample(&self, index: u64, dim: u32) -> Result<f64, Error> {
        Self::check_dimension(dim)?;
        Ok(self.sample(index, dim))
    }

    /// The 32-bit digit word `floor(x * 2^32)` of point `index`, dimension `dim`.
    ///
    /// # Panics
    /// If `dim >= NUM_DIMENSIONS`.
    #[inline]
    pub fn sample_word(&self, index: u64, dim: u32) -> u32 {
        (self.sample_fixed64(index, dim) >> 32) as u32
    }

    /// [`Halton::sample_word`], or an error for a dimension out of range.
    pub fn try_sample_word(&self, index: u64, dim: u32) -> Result<u32, Error> {
        Self::check_dimension(dim)?;
        Ok(self.sample_word(index, dim))
    }

    /// The first key of dimension `dim`'s nested scramble chain.
    #[inline]
    fn dim_key(&self, dim: u32) -> u64 {
        hash2(self.derived_seed, u64::from(dim))
    }

    /// `floor(x * 2^64)` for point `index` of dimension `dim`, exact.
    ///
    /// # Panics
    /// If `dim >= NUM_DIMENSIONS`.
    pub fn sample_fixed64(&self, index: u64, dim: u32) -> u64 {
        let base = &BASES[dim as usize];
        match self.randomize {
            HaltonRandomize::None => unscrambled(index, base),
            HaltonRandomize::PermuteDigits => {
                let seed = self.derived_seed;
                self.tables
                    .with_dimension(seed, dim, |tables| permuted(index, base, tables))
            }
            HaltonRandomize::Owen => nested(index, base, self.dim_key(dim), uniform_image),
            HaltonRandomize::NestedAffine => nested(index, base, self.dim_key(dim), affine_image),
        }
    }
}

/// Salt separating the digit-permutation seeds from other uses of a seed.
const SALT_PERMUTE: u64 = 0x4841_4c54_4f4e_5050; // "HALTONPP"
/// Salt separating the Owen-scramble seeds from other uses of a seed.
const SALT_OWEN: u64 = 0x4841_4c54_4f4e_4f57; // "HALTONOW"

/// The index residue whose radical inverse starts with given digits:
/// `digits` read as a `ndigits`-digit base-`base` integer (first digit after
/// the point most significant) is mirrored back, so that for every index `i`
/// with `i mod base^ndigits` equal to the result, `floor(x_i * base^ndigits)`
/// equals `digits`. Digits of `digits` beyond `ndigits` are ignored. A base
/// below 2 has no digits: the result is 0.
pub fn inverse_radical_inverse(digits: u64, base: u32, ndigits: u32) -> u64 {
    if base < 2 {
        return 0;
    }
    let b = u64::from(base);
    let (mut rest, mut index) = (digits, 0u64);
    for _ in 0..ndigits {
        index = index.wrapping_mul(b).wrapping_add(rest % b);
        rest /= b;
    }
    index
}

/// The unscrambled radical inverse, `floor(x * 2^64)`.
fn unscrambled(index: u64, base: &Base) -> u64 {
    if base.b == 2 {
        return index.reverse_bits();
    }
    let mut digits = [0u32; MAX_DIGITS];
    let n = base.digits(index, &mut digits);
    base.fixed64(&digits[..n])
}

/// Digits of `index` scrambled by the per-position permutation tables of
/// its dimension, over all `base.scrambled` positions: the index's own `n`
/// digits are mapped through the tables and continued by the precomputed
/// tail of scrambled zeros after position `n`.
fn permuted(index: u64, base: &Base, tables: &tables::DimensionTables) -> u64 {
    if base.b == 2 {
        // Position i flips bit 63 - i of the mirrored index or keeps it; the
        // all-zero tail from position 0 is exactly the mask of flips.
        return index.reverse_bits() ^ tables.tails[0];
    }
    let b = base.b as usize;
    let mut digits = [0u32; MAX_DIGITS];
    let n = base.digits(index, &mut digits);
    for (i, d) in digits[..n].iter_mut().enumerate() {
        *d = u32::from(tables.perms[i * b + *d as usize]);
    }
    base.fixed64_with_tail(&digits[..n], tables.tails[n])
}

/// Advances the Owen key chain past digit `digit`.
#[inline]
fn next_key(key: u64, digit: u32) -> u64 {
    mix64(key ^ u64::from(digit + 1).wrapping_mul(0x9e37_79b9_7f4a_7c15))
}

/// Digits of `index` scrambled by nested permutations (see the module
/// documentation). `key` is the per-dimension seed; it is extended by a hash
/// chain over the digits, so the key of position `i` depends on the seed and
/// on exactly the digits `a_0..a_{i-1}`. `image(key, base, digit)` is the
/// image of `digit` under the permutation of the node with that key.
#[inline]
fn nested(index: u64, base: &Base, mut key: u64, image: fn(u64, &Base, u32) -> u32) -> u64 {
    if base.b == 2 {
        // The only nontrivial permutation of {0, 1} is the flip; both
        // variants flip digit i when the node key's top bit is set.
        let mut out = 0u64;
        for i in 0..64 {
            let digit = ((index >> i) & 1) as u32;
            out |= u64::from(digit ^ (key >> 63) as u32) << (63 - i);
            key = next_key(key, digit);
        }
        return out;
    }
    let mut digits = [0u32; MAX_DIGITS];
    base.digits(index, &mut digits);
    let k = base.scrambled as usize;
    for d in digits[..k].iter_mut() {
        let digit = *d;
        *d = image(key, base, digit);
        key = next_key(key, digit);
    }
    base.fixed64(&digits[..k])
}

/// The image of `digit` under the affine map `a -> (m a + c) mod b` of the
/// node `key`: the pair `(m - 1, c)` is `floor(key * b (b - 1) / 2^64)` split
/// as `(q, r)` by `b`.
#[inline]
fn affine_image(key: u64, base: &Base, digit: u32) -> u32 {
    let b = base.b;
    let pick = ((u128::from(key) * u128::from(b * (b - 1))) >> 64) as u32;
    let q = base.div(pick);
    let (mult, add) = (1 + q, pick - q * b);
    base.rem(mult * digit + add)
}

/// Salt of the shuffle keys, separating them from the chain's next keys.
const SALT_SHUFFLE: u64 = 0x5348_5546_464c_4521; // "SHUFFLE!"

/// The image of `digit` under the uniformly random permutation of the node
/// `key`: the Fisher-Yates shuffle whose step `t` swaps positions `t` and
/// `j_t = t + bounded(h_t, b - t)` leaves at position `digit` the value
/// found by tracing that position back through steps `digit, .., 0` (later
/// steps never touch it). Bases 2 and 3 use the affine maps, which are all
/// of their permutations, each equally likely.
#[inline]
fn uniform_image(key: u64, base: &Base, digit: u32) -> u32 {
    let b = base.b;
    if b <= 3 {
        return affine_image(key, base, digit);
    }
    let shuffle = mix64(key ^ SALT_SHUFFLE);
    let mut pos = digit;
    for t in (0..=digit).rev() {
        let h = mix64(shuffle.wrapping_add(u64::from(t + 1).wrapping_mul(0x9e37_79b9_7f4a_7c15)));
        let j = t + bounded(h, u64::from(b - t)) as u32;
        if pos == t {
            pos = j;
        } else if pos == j {
            pos = t;
        }
    }
    pos
}

/// A 64-bit fixed-point fraction to the nearest `f64`, kept below 1.
#[inline]
fn fixed64_to_f64(fixed: u64) -> f64 {
    (fixed as f64 * (1.0 / 18_446_744_073_709_551_616.0)).min(ONE_MINUS_EPSILON_F64)
}
