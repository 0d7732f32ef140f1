//! The Sobol sequence with Joe & Kuo's 2008 direction numbers
//! (`new-joe-kuo-6.21201`: 21,201 dimensions, 32 output digits, indices
//! `0..2^32`).
//!
//! [`sample`] is random access in Sobol's natural order: the 32-bit digit word
//! of point `index` in dimension `dim` is the XOR of the generator-matrix
//! columns `c` for which bit `c` of `index` is set. Dimension 0 is the van der
//! Corput sequence and point 0 is all zeros. [`sample_randomized`] applies a
//! [`Randomize`] strategy. [`GrayCodeBatch`] emits the points in Gray-code
//! order (the order of Joe & Kuo's reference generator and of
//! `scipy.stats.qmc.Sobol`) at one XOR per value.

mod gray;
mod matrices;

pub use gray::{GrayCodeBatch, gray_code};
pub use matrices::{NUM_DIMENSIONS, matrix};

use crate::Randomize;

/// The unscrambled 32-bit digit word of point `index` in dimension `dim`
/// (natural order).
///
/// # Panics
/// If `dim >= NUM_DIMENSIONS`.
#[inline]
pub fn sample(index: u32, dim: u32) -> u32 {
    multiply(matrix(dim), index)
}

/// Multiplies a generator matrix (32 columns, MSB-first digit words) by the
/// binary digits of `index`, over GF(2).
#[inline]
pub fn multiply(columns: &[u32; 32], index: u32) -> u32 {
    let mut word = 0;
    let mut rest = index;
    while rest != 0 {
        word ^= columns[rest.trailing_zeros() as usize];
        rest &= rest - 1;
    }
    word
}

/// Point `index` of dimension `dim` in `[0, 1)` as `f32` (unscrambled).
///
/// # Panics
/// If `dim >= NUM_DIMENSIONS`.
#[inline]
pub fn sample_f32(index: u32, dim: u32) -> f32 {
    crate::to_f32(sample(index, dim))
}

/// The digit word of point `index` in dimension `dim`, randomized.
///
/// The randomization is seeded per dimension (see [`Randomize::apply`]), so
/// dimensions are scrambled independently. The paper's permutation is not a
/// function of the output word and is handled by [`crate::paper`].
///
/// # Panics
/// If `dim >= NUM_DIMENSIONS`.
#[inline]
pub fn sample_randomized(index: u32, dim: u32, randomize: Randomize) -> u32 {
    randomize.apply(sample(index, dim), dim)
}

/// Four consecutive dimensions `dim..dim + 4` of point `index`, randomized.
/// Equal, value for value, to four calls of [`sample_randomized`].
///
/// # Panics
/// If `dim + 3 >= NUM_DIMENSIONS`.
#[inline]
pub fn sample_4d(index: u32, dim: u32, randomize: Randomize) -> [u32; 4] {
    let d = dim as usize;
    let table = matrices::table();
    let block = &table[d..d + 4];
    let mut words = [0u32; 4];
    let mut rest = index;
    while rest != 0 {
        let c = rest.trailing_zeros() as usize;
        for (w, m) in words.iter_mut().zip(block) {
            *w ^= m[c];
        }
        rest &= rest - 1;
    }
    core::array::from_fn(|k| randomize.apply(words[k], dim + k as u32))
}

#[cfg(test)]
mod tests;
