//! Sequential Sobol generation in Gray-code order (Antonov & Saleev 1979),
//! the order of Joe & Kuo's reference generator and of `scipy.stats.qmc.Sobol`.
//!
//! Point `k` in this order is the natural-order point `gray_code(k)`; moving
//! from point `k - 1` to `k` XORs one matrix column (column
//! `trailing_zeros(k)`) into every dimension.
//!
//! ## Blocks
//! For `k` a multiple of `B = 2^b` and `j < B`, `gray(k + j) = gray(k) ^
//! gray(j)`, so point `k + j` is point `k` XOR a fixed offset word `T[j]` (the
//! matrix times `gray(j)`). [`GrayCodeBatch::fill`] therefore writes aligned
//! blocks of `B` points as `base ^ T[j]`: one load, one XOR and one store per
//! value, in loops the compiler vectorises. Unaligned points at the ends of a
//! call take the one-column step.

use alloc::vec::Vec;

use super::{NUM_DIMENSIONS, matrix, multiply};
use crate::Error;

/// The binary reflected Gray code of `k`.
#[inline]
pub fn gray_code(k: u32) -> u32 {
    k ^ (k >> 1)
}

/// Largest block length, in points.
const MAX_BLOCK_LOG2: u32 = 6;
/// Largest offset table, in values (8 KiB: stays in the L1 cache).
const MAX_TABLE_VALUES: usize = 2048;

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
    /// `log2` of the block length `B`.
    block_log2: u32,
    /// `offsets[j * width + i]`: dimension `first + i` of natural-order point
    /// `gray(j)`, for `j < B`.
    offsets: Vec<u32>,
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
        let mut block_log2 = 0;
        while block_log2 < MAX_BLOCK_LOG2 && (2usize << block_log2) * w <= MAX_TABLE_VALUES {
            block_log2 += 1;
        }
        let block = 1usize << block_log2;
        let mut offsets = alloc::vec![0u32; block * w];
        for j in 1..block {
            // Row j is row j - 1 with column trailing_zeros(j) XORed in.
            let c = j.trailing_zeros() as usize;
            let (done, rest) = offsets.split_at_mut(j * w);
            let previous = &done[(j - 1) * w..];
            let column = &columns[c * w..(c + 1) * w];
            for ((o, &p), &v) in rest[..w].iter_mut().zip(previous).zip(column) {
                *o = p ^ v;
            }
        }
        Ok(GrayCodeBatch {
            width: w,
            columns,
            state: alloc::vec![0u32; w],
            next: 0,
            block_log2,
            offsets,
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
        self.fill_map(out, |word| word)
    }

    /// [`fill`](Self::fill), with every value converted to `[0, 1)` by
    /// [`crate::to_f32`].
    pub fn fill_f32(&mut self, out: &mut [f32]) -> usize {
        self.fill_map(out, crate::to_f32)
    }

    /// [`fill`](Self::fill), with every value converted to `[0, 1)` by
    /// [`crate::to_f64`].
    pub fn fill_f64(&mut self, out: &mut [f64]) -> usize {
        self.fill_map(out, crate::to_f64)
    }

    /// The common body of the `fill` methods; `map` converts each digit word.
    #[inline]
    fn fill_map<T: Copy>(&mut self, out: &mut [T], map: impl Fn(u32) -> T + Copy) -> usize {
        let w = self.width;
        let points = (out.len() / w).min(self.remaining() as usize);
        let block = 1usize << self.block_log2;
        let mut written = 0;
        // Single steps up to a block boundary.
        while written < points && (self.next as usize) & (block - 1) != 0 {
            self.step(&mut out[written * w..(written + 1) * w], map);
            written += 1;
        }
        // Whole aligned blocks.
        while block > 1 && points - written >= block {
            let chunk = &mut out[written * w..(written + block) * w];
            match w {
                1 => self.block_rows::<1, T>(chunk, map),
                2 => self.block_rows::<2, T>(chunk, map),
                4 => self.block_rows::<4, T>(chunk, map),
                8 => self.block_rows::<8, T>(chunk, map),
                _ => self.block_any(chunk, map),
            }
            written += block;
        }
        // The rest, one point at a time.
        while written < points {
            self.step(&mut out[written * w..(written + 1) * w], map);
            written += 1;
        }
        points
    }

    /// Emits the next point into `point` (length `width`) by one column step.
    #[inline]
    fn step<T: Copy>(&mut self, point: &mut [T], map: impl Fn(u32) -> T) {
        let w = self.width;
        let k = self.next;
        if k != 0 {
            let c = k.trailing_zeros() as usize;
            let column = &self.columns[c * w..(c + 1) * w];
            for (s, &v) in self.state.iter_mut().zip(column) {
                *s ^= v;
            }
        }
        for (o, &s) in point.iter_mut().zip(&self.state) {
            *o = map(s);
        }
        self.next = k + 1;
    }

    /// Emits one aligned block of `B` points of a compile-time width `W`.
    #[inline]
    fn block_rows<const W: usize, T: Copy>(&mut self, chunk: &mut [T], map: impl Fn(u32) -> T) {
        let k = self.next;
        let mut base: [u32; W] = self.state[..W].try_into().expect("width is W");
        if k != 0 {
            let c = k.trailing_zeros() as usize;
            for (b, &v) in base.iter_mut().zip(&self.columns[c * W..(c + 1) * W]) {
                *b ^= v;
            }
        }
        let block = 1usize << self.block_log2;
        for (row, offset) in chunk.chunks_exact_mut(W).zip(self.offsets.chunks_exact(W)) {
            for i in 0..W {
                row[i] = map(base[i] ^ offset[i]);
            }
        }
        let last = &self.offsets[(block - 1) * W..];
        for ((s, &b), &o) in self.state.iter_mut().zip(&base).zip(last) {
            *s = b ^ o;
        }
        self.next = k + block as u64;
    }

    /// Emits one aligned block of `B` points of any width. The first and last
    /// rows update the state in the same pass as they write.
    #[inline]
    fn block_any<T: Copy>(&mut self, chunk: &mut [T], map: impl Fn(u32) -> T) {
        let w = self.width;
        let k = self.next;
        let block = 1usize << self.block_log2;
        let (first, rest) = chunk.split_at_mut(w);
        if k != 0 {
            let c = k.trailing_zeros() as usize;
            let column = &self.columns[c * w..(c + 1) * w];
            for ((o, s), &v) in first.iter_mut().zip(self.state.iter_mut()).zip(column) {
                *s ^= v;
                *o = map(*s);
            }
        } else {
            for (o, &s) in first.iter_mut().zip(&self.state) {
                *o = map(s);
            }
        }
        let (middle, last) = rest.split_at_mut((block - 2) * w);
        let offsets = &self.offsets[w..];
        for (row, offset) in middle.chunks_exact_mut(w).zip(offsets.chunks_exact(w)) {
            for ((o, &s), &t) in row.iter_mut().zip(&self.state).zip(offset) {
                *o = map(s ^ t);
            }
        }
        let offset = &self.offsets[(block - 1) * w..];
        for ((o, s), &t) in last.iter_mut().zip(self.state.iter_mut()).zip(offset) {
            *s ^= t;
            *o = map(*s);
        }
        self.next = k + block as u64;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sobol::sample;

    /// Checks `count` points from Gray-code position `start` against random
    /// access, filling in chunks of `chunk` points.
    fn check(first: u32, width: u32, start: u32, count: usize, chunk: usize) {
        let mut batch = GrayCodeBatch::new(first, width).unwrap();
        batch.seek(start);
        let w = width as usize;
        let mut k = u64::from(start);
        let mut out = alloc::vec![0u32; chunk * w];
        let mut done = 0;
        while done < count {
            let n = batch.fill(&mut out);
            assert!(n > 0 || k == 1 << 32);
            for p in out.chunks_exact(w).take(n) {
                for (j, &v) in p.iter().enumerate() {
                    assert_eq!(
                        v,
                        sample(gray_code(k as u32), first + j as u32),
                        "k {k} dim {j}"
                    );
                }
                k += 1;
            }
            if n == 0 {
                break;
            }
            done += n;
        }
    }

    #[test]
    fn blocks_match_random_access() {
        for width in [1u32, 2, 3, 4, 5, 8, 17, 64, 100, 1024, 3000] {
            check(0, width, 0, 300, 97);
            check(7, width, 13, 200, 64);
            check(1, width, 0, 200, 128);
        }
    }

    #[test]
    fn end_of_range_is_exact() {
        for width in [1u32, 4, 9] {
            check(3, width, u32::MAX - 150, 400, 70);
        }
        let mut batch = GrayCodeBatch::new(0, 1).unwrap();
        batch.seek(u32::MAX - 2);
        let mut out = [0u32; 100];
        assert_eq!(batch.fill(&mut out), 3);
        assert_eq!(batch.remaining(), 0);
        assert_eq!(batch.fill(&mut out), 0);
    }

    #[test]
    fn float_fills_convert_the_words() {
        let mut words = GrayCodeBatch::new(2, 4).unwrap();
        let mut floats = words.clone();
        let mut doubles = words.clone();
        let mut w = [0u32; 400];
        let mut f = [0f32; 400];
        let mut d = [0f64; 400];
        assert_eq!(words.fill(&mut w), 100);
        assert_eq!(floats.fill_f32(&mut f), 100);
        assert_eq!(doubles.fill_f64(&mut d), 100);
        for i in 0..400 {
            assert_eq!(f[i], crate::to_f32(w[i]));
            assert_eq!(d[i], crate::to_f64(w[i]));
        }
    }
}
