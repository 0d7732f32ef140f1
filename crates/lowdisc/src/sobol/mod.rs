//! The Sobol sequence with Joe & Kuo's 2008 direction numbers
//! (`new-joe-kuo-6.21201`: 21,201 dimensions, 32 output digits, indices
//! `0..2^32`).
//!
//! [`sample`] is random access in Sobol's natural order: the 32-bit digit word
//! of point `index` in dimension `dim` is the XOR of the generator-matrix
//! columns `c` for which bit `c` of `index` is set. Dimension 0 is the van der
//! Corput sequence and point 0 is all zeros. [`sample_randomized`] applies a
//! [`RandomizeStrategy`] under a seed. [`GrayCodeBatch`] emits the points in Gray-code
//! order (the order of Joe & Kuo's reference generator and of
//! `scipy.stats.qmc.Sobol`) at one XOR per value.

mod gray;
mod matrices;

pub use gray::{GrayCodeBatch, gray_code};
pub use matrices::{NUM_DIMENSIONS, matrices, matrix};

use crate::RandomizeStrategy;

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
///
/// The index is consumed four bits at a time: the four columns of a group are
/// ANDed with the masks of the four index bits (looked up in a 16-entry
/// table) and XORed into four accumulators, a branch-free step the compiler
/// turns into SIMD code. The loop runs `ceil(bits / 4)` times, where `bits`
/// is the bit length of `index`.
#[inline]
pub fn multiply(columns: &[u32; 32], index: u32) -> u32 {
    let [word] = multiply_lanes([columns], index);
    word
}

/// Columns consumed per step of [`multiply_lanes`].
const GROUP: usize = 4;

/// `NIBBLE_MASKS[n][i]` is all ones if bit `i` of `n` is set, else 0.
const NIBBLE_MASKS: [[u32; GROUP]; 16] = {
    let mut table = [[0u32; GROUP]; 16];
    let mut n = 0;
    while n < 16 {
        let mut i = 0;
        while i < GROUP {
            if n & (1 << i) != 0 {
                table[n][i] = u32::MAX;
            }
            i += 1;
        }
        n += 1;
    }
    table
};

/// `L` matrix-vector products with one index: lane `k` is
/// `multiply(matrices[k], index)`.
#[inline(always)]
fn multiply_lanes<const L: usize>(matrices: [&[u32; 32]; L], index: u32) -> [u32; L] {
    let mut acc = [[0u32; GROUP]; L];
    let mut rest = index;
    let mut first = 0;
    while rest != 0 {
        let masks = NIBBLE_MASKS[(rest & 15) as usize];
        for (a, m) in acc.iter_mut().zip(matrices) {
            let columns = &m[first..first + GROUP];
            for i in 0..GROUP {
                a[i] ^= columns[i] & masks[i];
            }
        }
        rest >>= GROUP;
        first += GROUP;
    }
    acc.map(|a| a.iter().fold(0, |x, &y| x ^ y))
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
/// The randomization is seeded per dimension (see
/// [`RandomizeStrategy::apply`]), so
/// dimensions are scrambled independently. The paper's permutation is not a
/// function of the output word and is handled by [`crate::paper`].
///
/// # Panics
/// If `dim >= NUM_DIMENSIONS`.
#[inline]
pub fn sample_randomized(index: u32, dim: u32, strategy: RandomizeStrategy, seed: u64) -> u32 {
    strategy.apply(sample(index, dim), seed, dim)
}

/// Four consecutive dimensions `dim..dim + 4` of point `index`, randomized.
/// Equal, value for value, to four calls of [`sample_randomized`].
///
/// # Panics
/// If `dim + 3 >= NUM_DIMENSIONS`.
#[inline(always)]
pub fn sample_4d(index: u32, dim: u32, strategy: RandomizeStrategy, seed: u64) -> [u32; 4] {
    let table = matrices::table();
    let d = dim as usize;
    let words = multiply_lanes(
        [&table[d], &table[d + 1], &table[d + 2], &table[d + 3]],
        index,
    );
    strategy.apply_4(words, seed, dim)
}

#[cfg(test)]
mod tests;
