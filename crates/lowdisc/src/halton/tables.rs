//! Digit-permutation tables of the `PermuteDigits` Halton randomization.
//!
//! Dimension `d` (base `b`, `K = scrambled_digits(b)` positions) owns `K`
//! uniformly random permutations of `0..b`, stored position-major in one
//! `u16` slice of `K * b` entries (every base is below `2^16`), with the values
//! of their scrambled zero tails (`K + 1` words). They are drawn by
//! Fisher-Yates shuffles from one PCG32 stream seeded by `hash(seed, d)`, so
//! each dimension's tables can be built alone, in any order.
//!
//! All tables would take about 45 MB for the first 1,024 dimensions and
//! gigabytes for all 6,542, so they are
//! built lazily: with the `std` feature each dimension's slot is a
//! `OnceLock` filled on first use and shared (`Arc`) between clones of the
//! sequence; without `std` the tables of a dimension are rebuilt for every
//! sample (same values, slowly).

use alloc::vec::Vec;

use super::digits::BASES;
use super::primes::{NUM_DIMENSIONS, PRIMES, scrambled_digits};
use crate::hash::{bounded, hash2};
use crate::pcg::Pcg32;

/// The permutations of one dimension and the values of their zero tails.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct DimensionTables {
    /// `perms[i * b + a]`: the image of digit `a` at position `i < K`.
    pub perms: Vec<u16>,
    /// `tails[m] = floor(2^64 * sum_{m <= i < K} pi_i(0) b^-(i - m + 1))`,
    /// `m = 0..=K`: the scrambled zero digits past an index's `m` digits,
    /// as the Horner state a value's `m` leading digits continue from.
    pub tails: Vec<u64>,
}

/// Builds the `K * b` permutation entries of dimension `dim` and their tails.
pub(super) fn build(seed: u64, dim: u32) -> DimensionTables {
    let base = PRIMES[dim as usize] as usize;
    let positions = scrambled_digits(base as u32) as usize;
    let mut rng = Pcg32::new(hash2(seed, u64::from(dim)), u64::from(dim));
    let mut perms = Vec::with_capacity(positions * base);
    for _ in 0..positions {
        let start = perms.len();
        perms.extend(0..base as u16);
        let perm = &mut perms[start..];
        for i in (1..base).rev() {
            let bits = (u64::from(rng.next_u32()) << 32) | u64::from(rng.next_u32());
            let j = bounded(bits, i as u64 + 1) as usize;
            perm.swap(i, j);
        }
    }
    let zero_images: Vec<u32> = (0..positions).map(|i| u32::from(perms[i * base])).collect();
    let digits = &BASES[dim as usize];
    let tails = (0..=positions)
        .map(|m| digits.fixed64(&zero_images[m..]))
        .collect();
    DimensionTables { perms, tails }
}

/// Lazily built permutation tables for every dimension (or none, for the
/// randomizations that do not use them).
#[derive(Clone)]
pub(super) struct PermutationTables {
    #[cfg(feature = "std")]
    slots: alloc::sync::Arc<[std::sync::OnceLock<DimensionTables>]>,
}

impl PermutationTables {
    /// Empty slots for all dimensions if `used`, else no slots at all.
    pub(super) fn new(used: bool) -> Self {
        #[cfg(feature = "std")]
        {
            let count = if used { NUM_DIMENSIONS as usize } else { 0 };
            let slots: Vec<std::sync::OnceLock<DimensionTables>> =
                (0..count).map(|_| std::sync::OnceLock::new()).collect();
            PermutationTables {
                slots: slots.into(),
            }
        }
        #[cfg(not(feature = "std"))]
        {
            let _ = (used, NUM_DIMENSIONS);
            PermutationTables {}
        }
    }

    /// Runs `f` on the tables of dimension `dim`, building them if needed.
    /// `seed` must be the same on every call for one `PermutationTables`.
    pub(super) fn with_dimension<R>(
        &self,
        seed: u64,
        dim: u32,
        f: impl FnOnce(&DimensionTables) -> R,
    ) -> R {
        #[cfg(feature = "std")]
        {
            f(self.slots[dim as usize].get_or_init(|| build(seed, dim)))
        }
        #[cfg(not(feature = "std"))]
        {
            f(&build(seed, dim))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_position_holds_a_permutation() {
        for dim in [0u32, 1, 2, 17, 500, NUM_DIMENSIONS - 1] {
            let base = PRIMES[dim as usize] as usize;
            let table = build(9, dim).perms;
            assert_eq!(table.len(), base * scrambled_digits(base as u32) as usize);
            for perm in table.chunks(base) {
                let mut seen = alloc::vec![false; base];
                for &v in perm {
                    assert!(!seen[v as usize], "dimension {dim}: repeated {v}");
                    seen[v as usize] = true;
                }
            }
        }
    }

    #[test]
    fn positions_and_seeds_get_different_permutations() {
        let table = build(1, 4).perms; // base 11
        let base = 11;
        assert_ne!(table[..base], table[base..2 * base]);
        assert_ne!(build(1, 4), build(2, 4));
        assert_eq!(build(1, 4), build(1, 4));
    }

    #[test]
    fn lazy_tables_equal_direct_builds_and_are_shared_by_clones() {
        let tables = PermutationTables::new(true);
        let copy = tables.clone();
        let direct = build(5, 3);
        assert!(tables.with_dimension(5, 3, |t| t == &direct));
        assert!(copy.with_dimension(5, 3, |t| t == &direct));
    }
}
