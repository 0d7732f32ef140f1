//! A (0,4)-sequence in base 4 written as a binary digital sequence: the
//! construction behind the SZ sequences of Ahmed, Pharr, Ostromoukhov and
//! Huang (2025), where each base-4 digit is a pair of bits and every entry
//! of a generator matrix over GF(4) is a 2x2 binary block, so a point is an
//! XOR of 32-bit columns exactly like a Sobol point. The matrices here are
//! generalized Faure matrices (below), not necessarily the paper's.
//!
//! ## The matrices
//! GF(4) = {0, 1, ω, ω² = ω + 1}; an element is the 2-bit label `b1 b0`
//! meaning `b0 + b1 ω` (addition is XOR). Dimension `a` (the element with
//! label `a`, `0..4`) has the generalized Faure matrix (Niederreiter 1987)
//!
//! `C_a[r][c] = binom(c, r) · a^(c - r)` over GF(4), with `a^0 = 1`,
//!
//! so dimension 0 is the base-4 van der Corput sequence and dimension 1 is
//! Faure's Pascal matrix reduced to GF(4). Because the four matrices are
//! `P(a)` for the four distinct elements of the field, every aligned block
//! of `4^m` consecutive points is a (0,m,4)-net in base 4: each box
//! `∏ [k_i 4^-d_i, (k_i + 1) 4^-d_i)` with `Σ d_i = m` holds exactly one
//! point (tested for every aligned block of the first `4^5` points).
//!
//! ## Bits
//! Index digit `c` is bits `2c` (the element ω) and `2c + 1` (the
//! element 1) of the index; output digit `r` is bits `31 - 2r, 30 - 2r` of the word,
//! written through a fixed bijection of digit pairs per dimension
//! (`output_pair`). Both choices keep the base-4 net (they only relabel
//! digits) and were picked, by an exhaustive search over the 6 x 6^4
//! linear relabellings, so that dimensions (0, 1) and (2, 3) are also
//! binary (0,2)-sequences: the first `2^m` points of each of these pairs are
//! a (0,m,2)-net in base 2 for every `m` (tested to `m = 12`), as Sobol's
//! first two dimensions are. The four other pairs have binary t-values of
//! at most 2 (pinned by a test).
//!
//! A base-4 box is a dyadic box with an even number of digits per axis, so
//! the binary scrambles of [`crate::RandomizeStrategy`] (XOR, Owen, fast
//! Owen) keep the (0,m,4)-net property.

use crate::sobol::multiply;

/// Dimensions of the sequence (a (0,s)-sequence in base 4 needs `s <= 4`).
pub const NUM_DIMENSIONS: u32 = 4;

/// The product of two GF(4) labels.
const fn gf4_mul(x: u32, y: u32) -> u32 {
    // Carry-less product of b0 + b1 ω, reduced with ω² = ω + 1.
    let (x0, x1, y0, y1) = (x & 1, x >> 1, y & 1, y >> 1);
    let one = (x0 & y0) ^ (x1 & y1);
    let omega = (x0 & y1) ^ (x1 & y0) ^ (x1 & y1);
    one | (omega << 1)
}

/// `a^k` over GF(4) (`a^0 = 1`).
const fn gf4_pow(a: u32, k: u32) -> u32 {
    let mut out = 1;
    let mut i = 0;
    while i < k {
        out = gf4_mul(out, a);
        i += 1;
    }
    out
}

/// The element of GF(4) that index bit `2c + k` contributes to index digit
/// `c`: bit `2c` is ω, bit `2c + 1` is 1.
const INPUT_ELEMENT: [u32; 2] = [2, 1];

/// The binary digit pair written for output label `label` of dimension
/// `dim` (first digit in bit 1): the identity for dimensions 1 and 3, the
/// map `b0 + b1 ω -> (b0 + b1, b1)` for dimensions 0 and 2. Any bijection of
/// digit pairs keeps the base-4 net; these make pairs (0, 1) and (2, 3)
/// binary (0,2)-sequences (found by a search over all such maps, tested).
const fn output_pair(dim: u32, label: u32) -> u32 {
    if dim % 2 == 1 {
        return label;
    }
    let (b0, b1) = (label & 1, label >> 1);
    ((b0 ^ b1) << 1) | b1
}

/// The 32 binary columns of every dimension: column `j` is the word of the
/// index with only bit `j` set.
const fn build_columns() -> [[u32; 32]; NUM_DIMENSIONS as usize] {
    let mut out = [[0u32; 32]; NUM_DIMENSIONS as usize];
    let mut a = 0;
    while a < NUM_DIMENSIONS {
        let mut bit = 0;
        while bit < 32 {
            let (c, element) = (bit / 2, INPUT_ELEMENT[(bit % 2) as usize]);
            let mut word = 0u32;
            let mut r = 0;
            while r <= c {
                // binom(c, r) is odd iff the bits of r are a subset of c's (Lucas).
                if r & !c == 0 {
                    let digit = gf4_mul(gf4_pow(a, c - r), element);
                    word |= output_pair(a, digit) << (30 - 2 * r);
                }
                r += 1;
            }
            out[a as usize][bit as usize] = word;
            bit += 1;
        }
        a += 1;
    }
    out
}

/// The generator matrices as binary columns.
const COLUMNS: [[u32; 32]; NUM_DIMENSIONS as usize] = build_columns();

/// The binary columns of dimension `dim` (column `j` is the point of the
/// index `1 << j`).
///
/// # Panics
/// If `dim >= NUM_DIMENSIONS`.
pub fn columns(dim: u32) -> &'static [u32; 32] {
    &COLUMNS[dim as usize]
}

/// The unscrambled 32-bit digit word of point `index` in dimension `dim`.
///
/// # Panics
/// If `dim >= NUM_DIMENSIONS`.
#[inline]
pub fn sample(index: u32, dim: u32) -> u32 {
    multiply(columns(dim), index)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::net_check::{is_net, t_value};
    use alloc::vec::Vec;

    #[test]
    fn gf4_is_a_field() {
        for x in 1..4 {
            // Every nonzero element has an inverse and x^3 = 1.
            assert_eq!((1..4).filter(|&y| gf4_mul(x, y) == 1).count(), 1);
            assert_eq!(gf4_pow(x, 3), 1);
            for y in 0..4 {
                for z in 0..4 {
                    let left = gf4_mul(x, y ^ z);
                    assert_eq!(left, gf4_mul(x, y) ^ gf4_mul(x, z), "distributive");
                    assert_eq!(gf4_mul(gf4_mul(x, y), z), gf4_mul(x, gf4_mul(y, z)));
                }
            }
        }
        assert_eq!(gf4_mul(2, 2), 3, "ω² = ω + 1");
    }

    #[test]
    fn dimension_zero_is_a_relabelled_base4_van_der_corput_sequence() {
        // C_0 is the identity: digit c of the index, as an element, is
        // output digit c.
        for index in [0u32, 1, 2, 3, 4, 7, 16, 1000, u32::MAX] {
            let mut want = 0u32;
            for c in 0..16 {
                let bits = (index >> (2 * c)) & 3;
                let element = [0, 2, 1, 3][bits as usize];
                want |= output_pair(0, element) << (30 - 2 * c);
            }
            assert_eq!(sample(index, 0), want, "{index}");
        }
        // Index 1 is the element ω in digit 0; C_1 = P(1) maps it to ω in
        // every digit r with binom(0, r) odd, i.e. digit 0 only: 2/4.
        assert_eq!(sample(1, 1), 2 << 30);
    }

    fn block(start: u32, len: u32, axes: &[u32]) -> Vec<Vec<u32>> {
        (start..start + len)
            .map(|i| axes.iter().map(|&d| sample(i, d)).collect())
            .collect()
    }

    #[test]
    fn every_aligned_block_is_a_0m4_net_in_base_4() {
        for m in 0..=4u32 {
            let len = 1u32 << (2 * m);
            for start in (0..1u32 << 10).step_by(len as usize) {
                let points = block(start, len, &[0, 1, 2, 3]);
                assert!(is_net(&points, m, 2), "m={m} {start}");
            }
        }
    }

    /// The binary t-value of the first `2^m` points of dimensions `x, y`.
    fn binary_t(x: u32, y: u32, m: u32) -> u32 {
        t_value(&block(0, 1 << m, &[x, y]), m)
    }

    #[test]
    fn pairs_01_and_23_are_binary_02_sequences() {
        for m in 1..=12 {
            assert_eq!(binary_t(0, 1, m), 0, "m={m}");
            assert_eq!(binary_t(2, 3, m), 0, "m={m}");
        }
    }

    #[test]
    fn binary_t_values_of_the_other_pairs_are_pinned() {
        // t of the first 2^m points, m = 1..=10, as the search found them.
        let table: Vec<Vec<u32>> = [(0, 2), (0, 3), (1, 2), (1, 3)]
            .iter()
            .map(|&(x, y)| (1..=10).map(|m| binary_t(x, y, m)).collect())
            .collect();
        assert_eq!(
            table,
            [
                [0, 1, 2, 0, 1, 1, 1, 1, 2, 1],
                [0, 0, 1, 1, 2, 1, 1, 1, 1, 1],
                [0, 0, 1, 1, 2, 1, 1, 1, 1, 1],
                [0, 1, 0, 0, 1, 1, 2, 1, 1, 1],
            ]
        );
    }
}
