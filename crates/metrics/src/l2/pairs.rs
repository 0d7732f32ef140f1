//! The pair sum `Σ_{i,j} Π_k K(x_ik, x_jk)` of the L2-type discrepancies: the O(n² d)
//! part of every method, written for speed and for run-to-run determinism.
//!
//! Layout: the points are packed in blocks of [`LANES`] consecutive points; block `b`
//! holds, for each coordinate `k`, the `LANES` values of that coordinate as one
//! `[f64; LANES]` (so `blocks[b * d + k][l]` is coordinate `k` of point `b·LANES + l`).
//! Row `i` is multiplied against whole blocks: the `LANES` running products stay in
//! registers across the `d` coordinates and the fixed-size lane loop vectorises. Each
//! method's kernel is rewritten in a form that costs few vector operations (see
//! [`Prepared`]); MD is evaluated as `2K` and rescaled by the exact `2^{−d}`.
//!
//! Only `j > i` is visited (the sum is symmetric) and the diagonal is added apart; the
//! lanes of the first and last block of a row are masked. Rows are taken in the order
//! `0, n−1, 1, n−2, …` so that consecutive rows pair a long and a short one, and cut
//! into chunks of [`ROWS_PER_CHUNK`]: every chunk costs about the same. Chunks run in
//! parallel (rayon), each summed in a fixed order, and the chunk sums are added in
//! chunk order, so the value does not depend on the number of threads. A chunk
//! that starts after the caller's cancel flag was set is skipped, so a
//! cancelled sum stops within one chunk per thread (and its value is discarded).
//!
//! Instruction set: each chunk is run through `pulp::Arch::dispatch`, which detects
//! x86-64-v3 (AVX2, FMA, …) at run time and runs a second build of the inlined kernel
//! compiled for it (four f64 per vector instead of two); other machines run the
//! baseline build of the same code. The x86-64-v3 build also fuses the multiply-adds of
//! WD and MD (one rounding fewer), so those two can differ in their last bits between
//! processors with and without FMA; on one machine the value never depends on the
//! number of threads.

use std::sync::atomic::{AtomicBool, Ordering};

use rayon::prelude::*;

use super::L2Method;

/// Points per block: four AVX2 registers (or eight SSE2 ones) of running products.
const LANES: usize = 16;

/// Rows per parallel chunk (the chunks depend on `n` only, never on the thread count).
const ROWS_PER_CHUNK: usize = 32;

type Block = [f64; LANES];

/// The per-coordinate factor of one method, in the form the kernel evaluates:
/// `factor(a, ca, b, cb)` where `a`, `ca` are two numbers stored for the row point and
/// `b`, `cb` two for the column point (see [`Prepared`] for what each method stores).
/// `FUSED` says whether multiply-adds may be fused (only where the processor has FMA).
trait Kernel {
    /// The factor.
    fn factor<const FUSED: bool>(a: f64, ca: f64, b: f64, cb: f64) -> f64;
}

/// `x·y + z`, with one rounding if `FUSED`, else two.
#[inline(always)]
fn mul_add<const FUSED: bool>(x: f64, y: f64, z: f64) -> f64 {
    if FUSED { x.mul_add(y, z) } else { x * y + z }
}

/// The smaller of two numbers, compared with `<` so that it is one `minpd`.
#[inline(always)]
fn min(x: f64, y: f64) -> f64 {
    if x < y { x } else { y }
}

/// L2-star: `1 − max(x, y) = min(1 − x, 1 − y)` exactly (rounding `1 − ·` is monotone),
/// with `a = 1 − x`, `b = 1 − y`.
struct Star;
impl Kernel for Star {
    #[inline(always)]
    fn factor<const FUSED: bool>(a: f64, _: f64, b: f64, _: f64) -> f64 {
        min(a, b)
    }
}

/// Centered: `K = c_x + c_y − |x − y|/2` with `c = 1 + z/2`, is the smaller of
/// `(c_x − x/2) + (c_y + y/2)` and `(c_x + x/2) + (c_y − y/2)`: two additions and a
/// minimum, no absolute value.
struct Centered;
impl Kernel for Centered {
    #[inline(always)]
    fn factor<const FUSED: bool>(a: f64, ca: f64, b: f64, cb: f64) -> f64 {
        min(a + b, ca + cb)
    }
}

/// Wrap-around: `K = 3/2 − t + t² = t (t − 1) + 3/2` with `t = |x − y|`.
struct WrapAround;
impl Kernel for WrapAround {
    #[inline(always)]
    fn factor<const FUSED: bool>(a: f64, _: f64, b: f64, _: f64) -> f64 {
        let t = (a - b).abs();
        mul_add::<FUSED>(t, t - 1.0, 1.5)
    }
}

/// Mixture, doubled: `2K = t (t − 3/2) + ((15/4 − z_x/2) + (−z_y/2))` with
/// `t = |x − y|`; the sum is rescaled by `2^{−d}`, exact as long as `3.75^d` stays far
/// from overflow, so it is used for `d <= MAX_DOUBLED_DIMS` and [`Mixture`] beyond.
struct MixtureDoubled;
impl Kernel for MixtureDoubled {
    #[inline(always)]
    fn factor<const FUSED: bool>(a: f64, ca: f64, b: f64, cb: f64) -> f64 {
        let t = (a - b).abs();
        mul_add::<FUSED>(t, t - 1.5, ca + cb)
    }
}

/// Mixture, plain: `K = t (t/2 − 3/4) + ((15/8 − z_x/4) + (−z_y/4))`.
struct Mixture;
impl Kernel for Mixture {
    #[inline(always)]
    fn factor<const FUSED: bool>(a: f64, ca: f64, b: f64, cb: f64) -> f64 {
        let t = (a - b).abs();
        mul_add::<FUSED>(t, 0.5 * t - 0.75, ca + cb)
    }
}

/// Largest dimension for which [`MixtureDoubled`] is used (`3.75^d` stays finite).
const MAX_DOUBLED_DIMS: usize = 256;

/// The points of one method, prepared for its kernel.
///
/// | method | row `a` | row `ca` | column `b` | column `cb` | scale |
/// |---|---|---|---|---|---|
/// | L2-star | `1 − x` | – | `1 − x` | – | 1 |
/// | CD | `c − x/2` | `c + x/2` | `c' + x/2` | `c' − x/2` | 1 |
/// | WD | `x` | – | `x` | – | 1 |
/// | MD, `d <= 256` | `x` | `15/4 − z/2` | `x` | `−z/2` | `2^{−d}` |
/// | MD, `d > 256` | `x` | `15/8 − z/4` | `x` | `−z/4` | 1 |
///
/// with `z = |x − 1/2|`, `c = 1 + z/2`, `c' = z/2` (the 1 is counted once, on the row).
struct Prepared {
    n: usize,
    d: usize,
    /// Row side, point-major: value and constant of coordinate `k` of point `i` at
    /// `[i·d + k]`.
    row_values: Vec<f64>,
    row_constants: Vec<f64>,
    /// Column side, blocked (see the module documentation); padding lanes hold 0 and
    /// are masked.
    values: Vec<Block>,
    constants: Vec<Block>,
}

impl Prepared {
    fn new(method: L2Method, cols: &[Vec<f64>], n: usize) -> Self {
        let d = cols.len();
        let blocks = n.div_ceil(LANES);
        let mut p = Self {
            n,
            d,
            row_values: vec![0.0; n * d],
            row_constants: vec![0.0; n * d],
            values: vec![[0.0; LANES]; blocks * d],
            constants: vec![[0.0; LANES]; blocks * d],
        };
        for (k, col) in cols.iter().enumerate() {
            for (i, &x) in col.iter().take(n).enumerate() {
                let z = (x - 0.5).abs();
                let (h, c, c2) = (0.5 * x, 1.0 + 0.5 * z, 0.5 * z);
                let (a, ca, b, cb) = match method {
                    L2Method::L2Star => (1.0 - x, 0.0, 1.0 - x, 0.0),
                    L2Method::Centered => (c - h, c + h, c2 + h, c2 - h),
                    L2Method::WrapAround => (x, 0.0, x, 0.0),
                    L2Method::Mixture if d <= MAX_DOUBLED_DIMS => (x, 3.75 - 0.5 * z, x, -0.5 * z),
                    L2Method::Mixture => (x, 1.875 - 0.25 * z, x, -0.25 * z),
                };
                p.row_values[i * d + k] = a;
                p.row_constants[i * d + k] = ca;
                let (blk, l) = (i / LANES, i % LANES);
                p.values[blk * d + k][l] = b;
                p.constants[blk * d + k][l] = cb;
            }
        }
        p
    }

    /// Σ over `j > i` of the products of row `i` with point `j`.
    #[inline(always)]
    fn row_sum<K: Kernel, const FUSED: bool>(&self, i: usize) -> f64 {
        let (n, d) = (self.n, self.d);
        let a = &self.row_values[i * d..(i + 1) * d];
        let ca = &self.row_constants[i * d..(i + 1) * d];
        let first = (i + 1) / LANES;
        let mut total = [0.0f64; LANES];
        let blocks = self.values[first * d..]
            .chunks_exact(d)
            .zip(self.constants[first * d..].chunks_exact(d));
        for (b, (vb, cb)) in (first..).zip(blocks) {
            let mut acc = [1.0f64; LANES];
            for (((&ak, &ck), v), c) in a.iter().zip(ca).zip(vb).zip(cb) {
                for l in 0..LANES {
                    acc[l] *= K::factor::<FUSED>(ak, ck, v[l], c[l]);
                }
            }
            let j0 = b * LANES;
            if j0 > i && j0 + LANES <= n {
                for l in 0..LANES {
                    total[l] += acc[l];
                }
            } else {
                for (l, (t, &p)) in total.iter_mut().zip(&acc).enumerate() {
                    if j0 + l > i && j0 + l < n {
                        *t += p;
                    }
                }
            }
        }
        total.iter().sum()
    }

    /// The diagonal term of point `i` (its product with itself).
    fn diagonal<K: Kernel>(&self, i: usize) -> f64 {
        let d = self.d;
        let (b, l) = (i / LANES, i % LANES);
        (0..d)
            .map(|k| {
                K::factor::<false>(
                    self.row_values[i * d + k],
                    self.row_constants[i * d + k],
                    self.values[b * d + k][l],
                    self.constants[b * d + k][l],
                )
            })
            .product()
    }

    /// The rows of chunk `c`, in the balanced order `0, n−1, 1, n−2, …`.
    fn chunk_rows(&self, c: usize) -> impl Iterator<Item = usize> {
        let n = self.n;
        (c * ROWS_PER_CHUNK..((c + 1) * ROWS_PER_CHUNK).min(n))
            .map(move |t| if t % 2 == 0 { t / 2 } else { n - 1 - t / 2 })
    }

    /// `Σ_{i,j}` of the kernel's products (diagonal plus twice the upper triangle).
    fn pair_sum<K: Kernel + Sync>(&self, cancel: &AtomicBool) -> Option<f64> {
        let chunks = self.n.div_ceil(ROWS_PER_CHUNK);
        let arch = pulp::Arch::new();
        let fused = has_fma(arch);
        let sums: Vec<f64> = (0..chunks)
            .into_par_iter()
            .map(|chunk| {
                if cancel.load(Ordering::Relaxed) {
                    return 0.0;
                }
                let points = self;
                let kernel = std::marker::PhantomData::<K>;
                if fused {
                    arch.dispatch(Chunk::<K, true> {
                        points,
                        chunk,
                        kernel,
                    })
                } else {
                    arch.dispatch(Chunk::<K, false> {
                        points,
                        chunk,
                        kernel,
                    })
                }
            })
            .collect();
        if cancel.load(Ordering::Relaxed) {
            return None;
        }
        let off_diagonal = compensated_sum(sums);
        let diagonal = compensated_sum((0..self.n).map(|i| self.diagonal::<K>(i)));
        Some(diagonal + 2.0 * off_diagonal)
    }
}

/// Whether pulp chose an instruction set with fused multiply-add (x86-64-v3 has FMA).
#[cfg(target_arch = "x86_64")]
fn has_fma(arch: pulp::Arch) -> bool {
    !matches!(arch, pulp::Arch::Scalar)
}

/// Whether pulp chose an instruction set with fused multiply-add (assumed not, here).
#[cfg(not(target_arch = "x86_64"))]
fn has_fma(_: pulp::Arch) -> bool {
    false
}

/// One chunk of rows, as an operation that pulp compiles for each instruction set.
struct Chunk<'a, K, const FUSED: bool> {
    points: &'a Prepared,
    chunk: usize,
    kernel: std::marker::PhantomData<K>,
}

impl<K: Kernel, const FUSED: bool> pulp::WithSimd for Chunk<'_, K, FUSED> {
    type Output = f64;

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) -> f64 {
        let p = self.points;
        let mut sum = Compensated::default();
        for i in p.chunk_rows(self.chunk) {
            sum.add(p.row_sum::<K, FUSED>(i));
        }
        sum.value()
    }
}

/// `Σ_{i,j} Π_k K(x_ik, x_jk)` for `method`, over the first `n` entries of each column
/// in `cols` (one column per coordinate); `None` if `cancel` was set meanwhile.
pub(super) fn pair_sum(
    method: L2Method,
    cols: &[Vec<f64>],
    n: usize,
    cancel: &AtomicBool,
) -> Option<f64> {
    let p = Prepared::new(method, cols, n);
    let d = cols.len();
    match method {
        L2Method::L2Star => p.pair_sum::<Star>(cancel),
        L2Method::Centered => p.pair_sum::<Centered>(cancel),
        L2Method::WrapAround => p.pair_sum::<WrapAround>(cancel),
        L2Method::Mixture if d <= MAX_DOUBLED_DIMS => {
            Some(p.pair_sum::<MixtureDoubled>(cancel)? * 0.5f64.powi(d as i32))
        }
        L2Method::Mixture => p.pair_sum::<Mixture>(cancel),
    }
}

/// Neumaier's compensated summation: the rounding error of every addition is kept and
/// added back at the end, so sums of many row sums lose no accuracy to their count.
#[derive(Default)]
struct Compensated {
    sum: f64,
    error: f64,
}

impl Compensated {
    #[inline(always)]
    fn add(&mut self, v: f64) {
        let t = self.sum + v;
        self.error += if self.sum.abs() >= v.abs() {
            (self.sum - t) + v
        } else {
            (v - t) + self.sum
        };
        self.sum = t;
    }

    fn value(&self) -> f64 {
        self.sum + self.error
    }
}

/// The compensated sum of `values`, added in their order.
pub(super) fn compensated_sum(values: impl IntoIterator<Item = f64>) -> f64 {
    let mut s = Compensated::default();
    for v in values {
        s.add(v);
    }
    s.value()
}
