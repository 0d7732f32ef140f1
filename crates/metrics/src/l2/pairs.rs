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
//! chunk order, so the value does not depend on the number of threads.
//!
//! Instruction set: each chunk is run through `pulp::Arch::dispatch`, which detects
//! x86-64-v3 (AVX2, FMA, …) at run time and runs a second build of the inlined kernel
//! compiled for it (four f64 per vector instead of two); other machines run the
//! baseline build of the same code. Both builds do the same IEEE operations in the same
//! order (no fused multiply-add is introduced), so both give the same bits.

use rayon::prelude::*;

use super::L2Method;

/// Points per block: four AVX2 registers (or eight SSE2 ones) of running products.
const LANES: usize = 16;

/// Rows per parallel chunk (the chunks depend on `n` only, never on the thread count).
const ROWS_PER_CHUNK: usize = 32;

type Block = [f64; LANES];

/// The per-coordinate factor of one method, in the form the kernel evaluates:
/// `factor(a, ca, b, cb)` where `a`, `ca` are the row point's value and constant and
/// `b`, `cb` the column point's (see [`Prepared`] for what each method stores).
trait Kernel {
    /// The factor.
    fn factor(a: f64, ca: f64, b: f64, cb: f64) -> f64;
}

/// L2-star: `1 − max(x, y) = min(1 − x, 1 − y)` exactly (rounding `1 − ·` is monotone),
/// with the values stored as `1 − x`. Compared with `<` so that it is one `minpd`.
struct Star;
impl Kernel for Star {
    #[inline(always)]
    fn factor(a: f64, _: f64, b: f64, _: f64) -> f64 {
        if a < b { a } else { b }
    }
}

/// Centered, on halved values `x/2` (exact): `K = (1 + z_x/2) + z_y/2 − |x/2 − y/2|`,
/// row constant `1 + z/2`, column constant `z/2`.
struct Centered;
impl Kernel for Centered {
    #[inline(always)]
    fn factor(a: f64, ca: f64, b: f64, cb: f64) -> f64 {
        (ca + cb) - (a - b).abs()
    }
}

/// Wrap-around: `K = 3/2 − t + t²` with `t = |x − y|`, no constants.
struct WrapAround;
impl Kernel for WrapAround {
    #[inline(always)]
    fn factor(a: f64, _: f64, b: f64, _: f64) -> f64 {
        let t = (a - b).abs();
        (1.5 - t) + t * t
    }
}

/// Mixture, doubled: `2K = (15/4 − z_x/2) + (−z_y/2) + t (t − 3/2)` with
/// `t = |x − y|`, row constant `15/4 − z/2`, column constant `−z/2`; the sum is rescaled
/// by `2^{−d}`, exact as long as `2^d` stays far from overflow, so it is used for
/// `d <= MAX_DOUBLED_DIMS` and [`Mixture`] beyond.
struct MixtureDoubled;
impl Kernel for MixtureDoubled {
    #[inline(always)]
    fn factor(a: f64, ca: f64, b: f64, cb: f64) -> f64 {
        let t = (a - b).abs();
        (ca + cb) + t * (t - 1.5)
    }
}

/// Mixture, plain: `K = (15/8 − z_x/4) + (−z_y/4) + t (t/2 − 3/4)`.
struct Mixture;
impl Kernel for Mixture {
    #[inline(always)]
    fn factor(a: f64, ca: f64, b: f64, cb: f64) -> f64 {
        let t = (a - b).abs();
        (ca + cb) + t * (0.5 * t - 0.75)
    }
}

/// Largest dimension for which [`MixtureDoubled`] is used (`3.75^d` stays finite).
const MAX_DOUBLED_DIMS: usize = 256;

/// The points of one method, prepared for its kernel.
///
/// | method | value | row constant | column constant | scale |
/// |---|---|---|---|---|
/// | L2-star | `1 − x` | – | – | 1 |
/// | CD | `x/2` | `1 + z/2` | `z/2` | 1 |
/// | WD | `x` | – | – | 1 |
/// | MD, `d <= 256` | `x` | `15/4 − z/2` | `−z/2` | `2^{−d}` |
/// | MD, `d > 256` | `x` | `15/8 − z/4` | `−z/4` | 1 |
///
/// with `z = |x − 1/2|`.
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
                let (value, row_c, col_c) = match method {
                    L2Method::L2Star => (1.0 - x, 0.0, 0.0),
                    L2Method::Centered => (0.5 * x, 1.0 + 0.5 * z, 0.5 * z),
                    L2Method::WrapAround => (x, 0.0, 0.0),
                    L2Method::Mixture if d <= MAX_DOUBLED_DIMS => (x, 3.75 - 0.5 * z, -0.5 * z),
                    L2Method::Mixture => (x, 1.875 - 0.25 * z, -0.25 * z),
                };
                p.row_values[i * d + k] = value;
                p.row_constants[i * d + k] = row_c;
                let (b, l) = (i / LANES, i % LANES);
                p.values[b * d + k][l] = value;
                p.constants[b * d + k][l] = col_c;
            }
        }
        p
    }

    /// Σ over `j > i` of the products of row `i` with point `j`.
    #[inline(always)]
    fn row_sum<K: Kernel>(&self, i: usize) -> f64 {
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
                    acc[l] *= K::factor(ak, ck, v[l], c[l]);
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
                K::factor(
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
    fn pair_sum<K: Kernel + Sync>(&self) -> f64 {
        let chunks = self.n.div_ceil(ROWS_PER_CHUNK);
        let arch = pulp::Arch::new();
        let sums: Vec<f64> = (0..chunks)
            .into_par_iter()
            .map(|c| {
                arch.dispatch(Chunk::<K> {
                    points: self,
                    chunk: c,
                    kernel: std::marker::PhantomData,
                })
            })
            .collect();
        let off_diagonal = compensated_sum(sums);
        let diagonal = compensated_sum((0..self.n).map(|i| self.diagonal::<K>(i)));
        diagonal + 2.0 * off_diagonal
    }
}

/// One chunk of rows, as an operation that pulp compiles for each instruction set.
struct Chunk<'a, K> {
    points: &'a Prepared,
    chunk: usize,
    kernel: std::marker::PhantomData<K>,
}

impl<K: Kernel> pulp::WithSimd for Chunk<'_, K> {
    type Output = f64;

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) -> f64 {
        let p = self.points;
        let mut sum = Compensated::default();
        for i in p.chunk_rows(self.chunk) {
            sum.add(p.row_sum::<K>(i));
        }
        sum.value()
    }
}

/// `Σ_{i,j} Π_k K(x_ik, x_jk)` for `method`, over the first `n` entries of each column
/// in `cols` (one column per coordinate).
pub(super) fn pair_sum(method: L2Method, cols: &[Vec<f64>], n: usize) -> f64 {
    let p = Prepared::new(method, cols, n);
    let d = cols.len();
    match method {
        L2Method::L2Star => p.pair_sum::<Star>(),
        L2Method::Centered => p.pair_sum::<Centered>(),
        L2Method::WrapAround => p.pair_sum::<WrapAround>(),
        L2Method::Mixture if d <= MAX_DOUBLED_DIMS => {
            p.pair_sum::<MixtureDoubled>() * 0.5f64.powi(d as i32)
        }
        L2Method::Mixture => p.pair_sum::<Mixture>(),
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
