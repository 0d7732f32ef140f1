//! The digit permutation of Song & Ro (2019), "A Method for Better Quality
//! with Improved Sample Sequence in 3D Rendering".
//!
//! ## How the printed code is read
//! The paper's `SobolSampleFloat(a, dimension)` walks the generator-matrix
//! columns `i = 0, 1, ...` of the dimension while the index `a` has bits
//! left (`a >>= 1` each step). At every column visited it draws one uniform
//! float `r` from a single static RNG, whether or not bit `i` of `a` is set.
//! If `r >= threshold` the column's entry is *bit-flipped*, else it is used
//! unchanged; entries whose index bit is set are XORed into the result.
//! The printed code's defects are resolved as follows:
//! * `perm[0]=1; perm[0]=0;` is read as `perm[0]=1; perm[1]=0;` (the flip
//!   permutation; the other branch is the identity).
//! * `b` is initialised to 0.
//! * `c` is unsigned, so the loop over the entry's bits terminates.
//! * `perm[c - (c>>1)*2]` is `perm[c & 1]`: every bit of the entry from bit 0
//!   up to and including its highest set bit is mapped through `perm`; bits
//!   above it stay 0. The flip of entry `c` is therefore
//!   `c ^ (2^(msb(c)+1) - 1)`: its highest set bit is cleared and every bit
//!   below it is complemented. Column `i` of a Sobol matrix has its *lowest*
//!   set bit on the diagonal (digit `i`, bit `31 - i`), so a flipped column
//!   loses its diagonal digit and gains a 1 in every later digit: the matrix
//!   stops being upper triangular and is no longer guaranteed non-singular,
//!   which is why the permutation can break stratification (see the README
//!   for measurements).
//! * An entry of 0 (which never occurs in a Sobol matrix) stays 0.
//! * `threshold` is a parameter in `[0, 1]`: the probability that a column is
//!   left unflipped (`threshold = 1`: plain Sobol; `0`: every column flipped).
//!
//! ## Variants
//! * [`PaperLiteral`]: one sequential stream, one draw per column visited, as
//!   printed: a value depends on every call made before it. The stream is
//!   PCG32 as in pbrt-v3 (`Pcg32::default()` is pbrt-v3's static `RNG`).
//! * [`paper_reproducible`]: the draw for column `i` of index `a` in dimension
//!   `d` is derived from `hash(seed, a, d, i)`, so any value can be recomputed
//!   alone and in any order, with the same flip probability per column.

use crate::Error;
use crate::hash::{hash4, unit_f64};
use crate::pcg::Pcg32;
use crate::sobol::matrix;

/// Checks that a threshold lies in `[0, 1]` (NaN is rejected).
pub fn check_threshold(threshold: f64) -> Result<f64, Error> {
    if (0.0..=1.0).contains(&threshold) {
        Ok(threshold)
    } else {
        Err(Error::ThresholdOutOfRange(threshold))
    }
}

/// The paper's flip of one matrix entry: every bit from bit 0 up to the
/// highest set bit complemented (so the highest set bit becomes 0).
#[inline]
pub fn flip_entry(entry: u32) -> u32 {
    if entry == 0 {
        return 0;
    }
    let width = 32 - entry.leading_zeros();
    let mask = if width == 32 {
        u32::MAX
    } else {
        (1u32 << width) - 1
    };
    entry ^ mask
}

/// Walks the columns of `dim` as the printed code does, asking `flip(i)` for
/// every column visited (in order `i = 0, 1, ...` up to the highest set bit of
/// `index`) whether to flip it.
#[inline]
fn permuted_sample(index: u32, dim: u32, mut flip: impl FnMut(u32) -> bool) -> u32 {
    let columns = matrix(dim);
    let mut word = 0;
    let mut rest = index;
    let mut i = 0u32;
    while rest != 0 {
        let flipped = flip(i);
        if rest & 1 == 1 {
            let entry = columns[i as usize];
            word ^= if flipped { flip_entry(entry) } else { entry };
        }
        rest >>= 1;
        i += 1;
    }
    word
}

/// The literal variant: one shared sequential stream, as printed.
#[derive(Debug, Clone)]
pub struct PaperLiteral {
    rng: Pcg32,
    threshold: f32,
}

impl PaperLiteral {
    /// A literal permuted-Sobol generator. `seed = None` replays pbrt-v3's
    /// default-constructed static `RNG`; `Some(s)` uses PCG32 stream `s`.
    pub fn new(threshold: f64, seed: Option<u64>) -> Result<Self, Error> {
        let threshold = check_threshold(threshold)? as f32;
        let rng = match seed {
            None => Pcg32::default(),
            Some(s) => Pcg32::new(crate::hash::mix64(s), s),
        };
        Ok(PaperLiteral { rng, threshold })
    }

    /// The threshold in use.
    pub fn threshold(&self) -> f32 {
        self.threshold
    }

    /// The next value: the digit word of point `index` in dimension `dim`,
    /// advancing the shared stream by one draw per column visited.
    ///
    /// # Panics
    /// If `dim >= sobol::NUM_DIMENSIONS`.
    pub fn sample(&mut self, index: u32, dim: u32) -> u32 {
        let threshold = self.threshold;
        let rng = &mut self.rng;
        permuted_sample(index, dim, |_| rng.next_f32() >= threshold)
    }
}

/// The reproducible variant: the digit word of point `index` in dimension
/// `dim`, each column's flip drawn from `hash(seed, index, dim, column)`.
/// A column is flipped with probability `1 - threshold`.
///
/// # Panics
/// If `dim >= sobol::NUM_DIMENSIONS`.
#[inline]
pub fn paper_reproducible(index: u32, dim: u32, threshold: f64, seed: u64) -> u32 {
    permuted_sample(index, dim, |i| {
        unit_f64(hash4(seed, u64::from(index), u64::from(dim), u64::from(i))) >= threshold
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sobol::sample;

    #[test]
    fn flip_entry_complements_up_to_the_highest_bit() {
        assert_eq!(flip_entry(0x8000_0000), 0x7fff_ffff);
        assert_eq!(flip_entry(0b1011), 0b0100);
        assert_eq!(flip_entry(1), 0);
        assert_eq!(flip_entry(0), 0);
        assert_eq!(flip_entry(u32::MAX), 0);
    }

    #[test]
    fn threshold_one_is_plain_sobol() {
        let mut literal = PaperLiteral::new(1.0, None).unwrap();
        for dim in [0u32, 1, 5, 1000, 21_200] {
            for index in [0u32, 1, 2, 3, 77, 1 << 20, u32::MAX] {
                assert_eq!(literal.sample(index, dim), sample(index, dim));
                assert_eq!(paper_reproducible(index, dim, 1.0, 9), sample(index, dim));
            }
        }
    }

    #[test]
    fn threshold_zero_flips_every_column() {
        let mut literal = PaperLiteral::new(0.0, Some(3)).unwrap();
        // Index 1 uses column 0 only: dimension 0's column 0 is 0x8000_0000.
        assert_eq!(literal.sample(1, 0), 0x7fff_ffff);
        assert_eq!(paper_reproducible(1, 0, 0.0, 3), 0x7fff_ffff);
        // Index 3 = columns 0 and 1 of dimension 0: 0x7fffffff ^ 0x3fffffff.
        assert_eq!(paper_reproducible(3, 0, 0.0, 3), 0x4000_0000);
    }

    #[test]
    fn literal_draws_one_number_per_column_visited() {
        // Index 0b100 visits three columns even though one bit is set.
        let mut literal = PaperLiteral::new(0.5, None).unwrap();
        let mut rng = Pcg32::default();
        literal.sample(0b100, 7);
        for _ in 0..3 {
            rng.next_f32();
        }
        assert_eq!(literal.rng, rng);
        // Index 0 visits none.
        literal.sample(0, 7);
        assert_eq!(literal.rng, rng);
    }

    #[test]
    fn thresholds_outside_the_unit_interval_are_rejected() {
        assert!(PaperLiteral::new(1.5, None).is_err());
        assert!(PaperLiteral::new(-0.1, None).is_err());
        assert!(PaperLiteral::new(f64::NAN, None).is_err());
        assert!(check_threshold(0.0).is_ok() && check_threshold(1.0).is_ok());
    }
}
