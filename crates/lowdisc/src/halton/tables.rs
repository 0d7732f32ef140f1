//! Digit-permutation tables of the `PermuteDigits` Halton randomization.
//!
//! Dimension `d` (base `b`, `K = scrambled_digits(b)` positions) owns `K`
//! uniformly random permutations of `0..b`, stored position-major in one
//! `u16` slice of `K * b` entries (`b <= 8161` fits `u16`). They are drawn by
//! Fisher-Yates shuffles from one PCG32 stream seeded by `hash(seed, d)`, so
//! each dimension's tables can be built alone, in any order.
//!
//! All tables for all 1,024 dimensions would take about 45 MB, so they are
//! built lazily: with the `std` feature each dimension's slot is a
//! `OnceLock` filled on first use and shared (`Arc`) between clones of the
//! sequence; without `std` the tables of a dimension are rebuilt for every
//! sample (same values, slowly).

use alloc::vec::Vec;

use super::primes::{NUM_DIMENSIONS, PRIMES, scrambled_digits};
use crate::hash::{bounded, hash2};
use crate::pcg::Pcg32;

/// Builds the `K * b` permutation entries of dimension `dim`.
pub(super) fn build(seed: u64, dim: u32) -> Vec<u16> {
    let base = PRIMES[dim as usize] as usize;
    let positions = scrambled_digits(base as u32) as usize;
    let mut rng = Pcg32::new(hash2(seed, u64::from(dim)), u64::from(dim));
    let mut table = Vec::with_capacity(positions * base);
    for _ in 0..positions {
        let start = table.len();
        table.extend(0..base as u16);
        let perm = &mut table[start..];
        for i in (1..base).rev() {
            let bits = (u64::from(rng.next_u32()) << 32) | u64::from(rng.next_u32());
            let j = bounded(bits, i as u64 + 1) as usize;
            perm.swap(i, j);
        }
    }
    table
}

/// Lazily built permutation tables for every dimension (or none, for the
/// randomizations that do not use them).
#[derive(Clone)]
pub(super) struct PermutationTables {
    #[cfg(feature = "std")]
    slots: alloc::sync::Arc<[std::sync::OnceLock<Vec<u16>>]>,
}

impl PermutationTables {
    /// Empty slots for all dimensions if `used`, else no slots at all.
    pub(super) fn new(used: bool) -> Self {
        #[cfg(feature = "std")]
        {
            let count = if used { NUM_DIMENSIONS as usize } else { 0 };
            let slots: Vec<std::sync::OnceLock<Vec<u16>>> =
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
    pub(super) fn with_dimension<R>(&self, seed: u64, dim: u32, f: impl FnOnce(&[u16]) -> R) -> R {
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
            let table = build(9, dim);
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
        let table = build(1, 4); // base 11
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
        assert!(tables.with_dimension(5, 3, |t| t == &direct[..]));
        assert!(copy.with_dimension(5, 3, |t| t == &direct[..]));
    }
}
