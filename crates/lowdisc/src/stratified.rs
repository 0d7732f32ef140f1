//! Stratified (jittered) sampling: grid shapes, jittered point sets whose
//! dimension pairs are decorrelated by shuffling, and a keyed permutation of
//! `0..n` with random access, used by the stratified pixel sampler.
//!
//! ## `jittered_points(n, dims, seed)`
//! Point-major, `n * dims` values. Dimensions are taken in pairs
//! `(0, 1), (2, 3), ...`; each pair is an `nx x ny` jittered grid with
//! `(nx, ny) = grid_shape(n)` (`nx * ny = n`, as close to square as `n`'s
//! divisors allow; a prime `n` gives `1 x n`): cell `c` is column `c % nx`,
//! row `c / nx`, and holds one uniform point. Point `k` takes cell `perm(k)`,
//! with `perm` a uniformly random permutation (Fisher-Yates, seeded by the
//! seed and the pair), so different pairs are paired up at random rather
//! than all following the same cell order. An odd last dimension is 1-D
//! jittered with `n` strata, shuffled the same way. Each pair (and the last
//! single dimension) therefore has exactly one point per stratum, where the
//! stratum of a value `v` in a range of `m` strata is `floor(v * m)`
//! evaluated in `f64` (values are nudged by an ulp where rounding would
//! otherwise push them across a boundary).

use alloc::vec::Vec;

use crate::hash::{bounded, hash2, mix64};
use crate::pcg::Pcg32;
use crate::scramble::derive_seed;

/// Salt separating the jittered point sets from other uses of a seed.
const SALT: u64 = 0x4a49_5454_4552_4544; // "JITTERED"

/// The grid `(nx, ny)` with `nx * ny = n` and `nx <= ny` closest to square:
/// `nx` is the largest divisor of `n` not above `sqrt(n)`. A prime `n` gives
/// `(1, n)`; `n = 0` gives `(0, 0)`.
pub fn grid_shape(n: u32) -> (u32, u32) {
    if n == 0 {
        return (0, 0);
    }
    let mut nx = n.isqrt();
    while n % nx != 0 {
        nx -= 1;
    }
    (nx, n / nx)
}

/// `n` jittered points in `dims` dimensions, point-major (value `d` of point
/// `k` at `k * dims + d`); see the module documentation. Empty if `n` or
/// `dims` is 0. Allocates `n * dims` values (plus `n` cells): callers taking
/// `n` and `dims` from users should bound them first.
pub fn jittered_points(n: u32, dims: u32, seed: u64) -> Vec<f64> {
    let (n_us, dims_us) = (n as usize, dims as usize);
    let mut out = alloc::vec![0.0; n_us * dims_us];
    if out.is_empty() {
        return out;
    }
    let (nx, ny) = grid_shape(n);
    let seed = derive_seed(seed, SALT);
    let mut dim = 0usize;
    while dim < dims_us {
        let mut rng = Pcg32::new(hash2(seed, dim as u64), dim as u64);
        let cells = shuffled(n, &mut rng);
        let pair = dim + 1 < dims_us;
        for (k, &cell) in cells.iter().enumerate() {
            let row = &mut out[k * dims_us..(k + 1) * dims_us];
            if pair {
                row[dim] = stratum_f64(cell % nx, nx, uniform_f64(&mut rng));
                row[dim + 1] = stratum_f64(cell / nx, ny, uniform_f64(&mut rng));
            } else {
                row[dim] = stratum_f64(cell, n, uniform_f64(&mut rng));
            }
        }
        dim += 2;
    }
    out
}

/// `0..n` in a uniformly random order (Fisher-Yates).
fn shuffled(n: u32, rng: &mut Pcg32) -> Vec<u32> {
    let mut cells: Vec<u32> = (0..n).collect();
    for i in (1..cells.len()).rev() {
        let j = bounded(random_u64(rng), i as u64 + 1) as usize;
        cells.swap(i, j);
    }
    cells
}

/// 64 random bits from two PCG32 draws.
fn random_u64(rng: &mut Pcg32) -> u64 {
    (u64::from(rng.next_u32()) << 32) | u64::from(rng.next_u32())
}

/// A uniform `f64` in `[0, 1)` with 53 random bits.
fn uniform_f64(rng: &mut Pcg32) -> f64 {
    crate::hash::unit_f64(random_u64(rng))
}

/// `(cell + u) / count`, kept inside stratum `cell`: `floor(v * count)`
/// computed in `f64` equals `cell`, and `v < 1`.
pub fn stratum_f64(cell: u32, count: u32, u: f64) -> f64 {
    let (c, n) = (f64::from(cell), f64::from(count));
    let mut v = ((c + u) / n).clamp(0.0, 1.0);
    // A few ulp steps at most (bounded, so a count too large for the
    // precision cannot loop forever).
    for _ in 0..8 {
        if v * n >= c + 1.0 {
            v = f64::from_bits(v.to_bits() - 1);
        } else if v * n < c {
            v = f64::from_bits(v.to_bits() + 1);
        } else {
            break;
        }
    }
    v.min(1.0 - f64::EPSILON / 2.0)
}

/// `(cell + u) / count` in `f32`, kept inside stratum `cell`: `floor(v *
/// count)` computed in `f32` equals `cell`, and `v < 1`. Exact stratum
/// membership needs `count <= 2^24` (`f32` has 24 significant bits); larger
/// counts still give a value in `[0, 1)`.
pub fn stratum_f32(cell: u32, count: u32, u: f32) -> f32 {
    let (c, n) = (cell as f32, count as f32);
    let mut v = ((c + u) / n).clamp(0.0, 1.0);
    for _ in 0..8 {
        if v * n >= c + 1.0 {
            v = f32::from_bits(v.to_bits() - 1);
        } else if v * n < c {
            v = f32::from_bits(v.to_bits() + 1);
        } else {
            break;
        }
    }
    v.min(crate::ONE_MINUS_EPSILON_F32)
}

/// Element `i mod n` of a pseudo-random permutation of `0..n` chosen by
/// `key`, with random access (no table): a keyed bijection of the `k`-bit
/// integers (`2^k >= n`) built from xor, odd multiplication, addition and
/// xor-shift steps, all invertible modulo `2^k`, applied repeatedly until
/// the result falls in `0..n` ("cycle walking", which keeps it a bijection
/// of `0..n`; fewer than two steps on average). Returns 0 when `n <= 1`.
pub fn permutation_element(i: u32, n: u32, key: u64) -> u32 {
    KeyedPermutation::new(n, key).element(i)
}

/// The permutation of [`permutation_element`] for one `(n, key)`, with the
/// key's hashing done once: `KeyedPermutation::new(n, key).element(i)`
/// equals `permutation_element(i, n, key)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct KeyedPermutation {
    n: u32,
    mask: u32,
    shift: u32,
    keys: [u64; 3],
}

impl KeyedPermutation {
    /// The permutation of `0..n` chosen by `key`.
    pub fn new(n: u32, key: u64) -> Self {
        let bits = 32 - n.saturating_sub(1).leading_zeros();
        let mask = if bits == 32 {
            u32::MAX
        } else {
            (1u32 << bits) - 1
        };
        KeyedPermutation {
            n,
            mask,
            shift: bits / 2 + 1,
            keys: [
                mix64(key),
                mix64(key ^ 0x5851_f42d_4c95_7f2d),
                mix64(key ^ 0x1405_7b7e_f767_814f),
            ],
        }
    }

    /// Element `i mod n` (0 when `n <= 1`).
    #[inline]
    pub fn element(&self, i: u32) -> u32 {
        let (n, mask, shift) = (self.n, self.mask, self.shift);
        if n <= 1 {
            return 0;
        }
        let mut x = i % n;
        loop {
            for &k in &self.keys {
                x ^= k as u32 & mask;
                x = x.wrapping_mul((k >> 32) as u32 | 1) & mask;
                x ^= x >> shift;
                x = x.wrapping_add((k >> 40) as u32) & mask;
                x = x.wrapping_mul(0x2c1b_3c6d) & mask;
                x ^= x >> shift.saturating_sub(1).max(1);
            }
            if x < n {
                return x;
            }
        }
    }
}

#[cfg(test)]
mod tests;
