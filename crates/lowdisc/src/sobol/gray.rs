//! Sequential Sobol generation in Gray-code order (Antonov & Saleev 1979),
//! the order of Joe & Kuo's reference generator and of `scipy.stats.qmc.Sobol`.
//!
//! Point `k` in this order is the natural-order point `gray_code(k)`; moving
//! from point `k - 1` to `k` XORs one matrix column (column
//! `trailing_zeros(k)`) into every dimension.

use alloc::vec::Vec;

use super::{NUM_DIMENSIONS, matrix, multiply};
use crate::Error;

/// The binary reflected Gray code of `k`.
#[inline]
pub fn gray_code(k: u32) -> u32 {
    k ^ (k >> 1)
}

/// Batch generator of unscrambled Sobol points over a range of dimensions.
#[derive(Debug, Clone)]
pub struct GrayCodeBatch {
    /// Number of dimensions per point.
    width: usize,
    /// `columns[c * width + j]`: column `c` of dimension `first + j`.
    columns: Vec<u32>,
    /// Digit words of the point most recently emitted (or the one before the
    /// next point, before the first call).
    state: Vec<u32>,
    /// Gray-code position of the next point.
    next: u64,
}

impl GrayCodeBatch {
    /// A generator for dimensions `first..first + width`, starting at point 0.
    pub fn new(first: u32, width: u32) -> Result<Self, Error> {
        let end = u64::from(first) + u64::from(width);
        if width == 0 || end > NUM_DIMENSIONS as u64 {
            return Err(Error::DimensionOutOfRange {
                dimension: end.saturating_sub(1).max(u64::from(first)),
                available: NUM_DIMENSIONS as u64,
            });
        }
        let w = width as usize;
        let mut columns = alloc::vec![0u32; 32 * w];
        for j in 0..w {
            let m = matrix(first + j as u32);
            for c in 0..32 {
                columns[c * w + j] = m[c];
            }
        }
        Ok(GrayCodeBatch {
            width: w,
            columns,
            state: alloc::vec![0u32; w],
            next: 0,
        })
    }

    /// Dimensions per point.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Moves so that the next point emitted is Gray-code point `k`.
    pub fn seek(&mut self, k: u32) {
        self.next = u64::from(k);
        if k == 0 {
            self.state.fill(0);
            return;
        }
        let g = gray_code(k - 1);
        for (j, s) in self.state.iter_mut().enumerate() {
            let column: [u32; 32] = core::array::from_fn(|c| self.columns[c * self.width + j]);
            *s = multiply(&column, g);
        }
    }

    /// Points still available before the index range (`2^32`) is exhausted.
    pub fn remaining(&self) -> u64 {
        (1u64 << 32) - self.next
    }

    /// Fills `out` with whole points (`out.len() / width` of them, point-major:
    /// `out[p * width + j]` is dimension `first + j` of the `p`-th point).
    /// Returns the number of points written, which is smaller than asked only
    /// when the index range runs out.
    pub fn fill(&mut self, out: &mut [u32]) -> usize {
        let w = self.width;
        let points = (out.len() / w).min(self.remaining() as usize);
        for point in out.chunks_exact_mut(w).take(points) {
            let k = self.next;
            if k != 0 {
                let c = k.trailing_zeros() as usize;
                let column = &self.columns[c * w..(c + 1) * w];
                for (s, &v) in self.state.iter_mut().zip(column) {
                    *s ^= v;
                }
            }
            point.copy_from_slice(&self.state);
            self.next = k + 1;
        }
        points
    }
}
