//! L2-type discrepancies with exactly the conventions of `scipy.stats.qmc.discrepancy`
//! (SciPy 1.17): same formulas, same squared/unsquared outputs.
//!
//! With `n` points `x_i` in `[0,1]^d`, `z = |x − 1/2|`:
//! - **L2-star** (Warnock 1972), returned as the *square root*, like SciPy:
//!   `T = sqrt(3^{−d} − 2^{1−d}/n Σ_i Π_k (1 − x_ik²) + 1/n² Σ_{i,j} Π_k (1 − max(x_ik, x_jk)))`,
//!   the root mean square of `A([0,y))/n − V(y)` over `y ∈ [0,1]^d`.
//! - **CD**, centered (Hickernell 1998; Zhou et al. 2013 eq. 9), returned *squared*:
//!   `(13/12)^d − 2/n Σ_i Π_k (1 + z_ik/2 − z_ik²/2)
//!    + 1/n² Σ_{i,j} Π_k (1 + z_ik/2 + z_jk/2 − |x_ik − x_jk|/2)`.
//! - **WD**, wrap-around (eq. 10), returned *squared*:
//!   `−(4/3)^d + 1/n² Σ_{i,j} Π_k (3/2 − |x_ik − x_jk| + |x_ik − x_jk|²)`.
//! - **MD**, mixture (eq. 18), returned *squared*:
//!   `(19/12)^d − 2/n Σ_i Π_k (5/3 − z_ik/4 − z_ik²/4)
//!    + 1/n² Σ_{i,j} Π_k (15/8 − z_ik/4 − z_jk/4 − 3|x_ik − x_jk|/4 + |x_ik − x_jk|²/2)`.
//!
//! Algorithm: the double sum is symmetric, so only `i < j` is visited (plus the
//! diagonal), in blocks of 16 points whose running products stay in vector registers,
//! compiled for AVX2 when the processor has it (detected at run time); fixed chunks of
//! rows run in parallel (rayon) and are added in a fixed order, so the value does not
//! depend on the number of threads (the submodule `pairs` documents layout and kernels). Cost
//! O(n² d / 2) operations, O(n d) memory.
//!
//! Accuracy: the result is a small difference of terms near `c^d` (for CD at d = 8,
//! `(13/12)^8 ≈ 1.9` against a discrepancy near 1e-3), so every rounding of those terms
//! is magnified. The row and chunk sums are compensated (Neumaier), the constants
//! `(p/q)^d` are correctly rounded while `p^d` and `q^d` are exact integers, and no
//! factor uses a rounded constant such as 5/3: at n = 4096, d = 8 the four values agree
//! with an 80-bit evaluation to about 1e-12 relative or better, where SciPy's plain
//! summation is off by up to several 1e-10.

mod pairs;

use std::sync::atomic::AtomicBool;

use serde::Serialize;

use crate::PointSet;

/// The four L2-type discrepancies of SciPy.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum L2Method {
    /// Warnock's L2-star discrepancy (SciPy `"L2-star"`, returned as the square root).
    L2Star,
    /// Centered discrepancy (SciPy `"CD"`, returned squared).
    Centered,
    /// Wrap-around discrepancy (SciPy `"WD"`, returned squared).
    WrapAround,
    /// Mixture discrepancy (SciPy `"MD"`, returned squared).
    Mixture,
}

impl L2Method {
    /// All four methods, in SciPy's documentation order.
    pub const ALL: [L2Method; 4] = [
        Self::Centered,
        Self::WrapAround,
        Self::Mixture,
        Self::L2Star,
    ];

    /// SciPy's name of the method (`"CD"`, `"WD"`, `"MD"`, `"L2-star"`).
    pub fn scipy_name(self) -> &'static str {
        match self {
            Self::L2Star => "L2-star",
            Self::Centered => "CD",
            Self::WrapAround => "WD",
            Self::Mixture => "MD",
        }
    }

    /// Whether the returned value is the square of the discrepancy (true for CD, WD, MD).
    pub fn is_squared(self) -> bool {
        !matches!(self, Self::L2Star)
    }
}

/// All four L2-type discrepancies of one point set, in SciPy's conventions.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct L2Discrepancies {
    /// L2-star (square root taken).
    pub l2_star: f64,
    /// Centered, squared.
    pub cd: f64,
    /// Wrap-around, squared.
    pub wd: f64,
    /// Mixture, squared.
    pub md: f64,
}

/// The single-point factor of the middle term, and the term's constant.
fn single_factor(method: L2Method, x: f64) -> f64 {
    let z = (x - 0.5).abs();
    match method {
        L2Method::L2Star => 1.0 - x * x,
        L2Method::Centered => 1.0 + 0.5 * z - 0.5 * z * z,
        L2Method::WrapAround => 0.0,
        // (20 − 3z − 3z²)/12 rather than 5/3 − …: the rounding of 5/3 would bias
        // every factor the same way.
        L2Method::Mixture => (20.0 - 3.0 * z - 3.0 * z * z) / 12.0,
    }
}

/// `(p/q)^d`, correctly rounded (one division of exact integers) while `p^d` and `q^d`
/// are below 2^53, else by `powf` (the C library's `pow`, as SciPy's compiled code
/// uses). These constants mostly cancel against the sums, so their rounding matters:
/// `(13.0/12.0).powi(8)` alone would carry up to about 4 ulp.
fn ratio_power(p: u64, q: u64, d: usize) -> f64 {
    let exact = |b: u64| {
        u32::try_from(d)
            .ok()
            .and_then(|e| b.checked_pow(e))
            .filter(|&v| v < 1 << 53)
    };
    match (exact(p), exact(q)) {
        (Some(a), Some(b)) => a as f64 / b as f64,
        _ => (p as f64 / q as f64).powf(d as f64),
    }
}

fn columns(points: &PointSet) -> Vec<Vec<f64>> {
    (0..points.dims()).map(|j| points.column(j)).collect()
}

/// The discrepancy of the `n` points in `cols`, normalised as if there were
/// `count` points (`count = n` except for [`l2_discrepancy_iterative`]).
fn evaluate(method: L2Method, cols: &[Vec<f64>], n: usize, count: usize) -> f64 {
    let never = AtomicBool::new(false);
    evaluate_cancellable(method, cols, n, count, &never).unwrap_or(f64::NAN)
}

/// [`evaluate`], or `None` once `cancel` is set.
fn evaluate_cancellable(
    method: L2Method,
    cols: &[Vec<f64>],
    n: usize,
    count: usize,
    cancel: &AtomicBool,
) -> Option<f64> {
    let d = cols.len();
    let nf = count as f64;
    let single = pairs::compensated_sum((0..n).map(|i| {
        cols.iter()
            .map(|c| single_factor(method, c[i]))
            .product::<f64>()
    }));
    let pairs = pairs::pair_sum(method, cols, n, cancel)? / (nf * nf);
    Some(match method {
        L2Method::L2Star => {
            let sq = ratio_power(1, 3, d) - 2.0 * ratio_power(1, 2, d) / nf * single + pairs;
            // Rounding can leave a tiny negative square for near-perfect sets.
            sq.max(0.0).sqrt()
        }
        L2Method::Centered => ratio_power(13, 12, d) - 2.0 / nf * single + pairs,
        L2Method::WrapAround => -ratio_power(4, 3, d) + pairs,
        L2Method::Mixture => ratio_power(19, 12, d) - 2.0 / nf * single + pairs,
    })
}

/// One L2-type discrepancy, in SciPy's convention (see [`L2Method::is_squared`]).
pub fn l2_discrepancy(points: &PointSet, method: L2Method) -> f64 {
    evaluate(method, &columns(points), points.len(), points.len())
}

/// [`l2_discrepancy`] normalised as if the set had one more point (SciPy's
/// `iterative=True`: the start of `update_discrepancy`, which adds it).
pub fn l2_discrepancy_iterative(points: &PointSet, method: L2Method) -> f64 {
    evaluate(method, &columns(points), points.len(), points.len() + 1)
}

/// [`l2_discrepancy`] (or, with `iterative`, [`l2_discrepancy_iterative`])
/// that another thread can stop: `None` if `cancel` was set before it
/// finished. The O(n² d) pair sum checks the flag between chunks of 32 rows.
///
/// ```
/// use std::sync::atomic::AtomicBool;
/// use lowdisc_metrics::{L2Method, PointSet, l2_discrepancy, l2_discrepancy_cancellable};
///
/// let points = PointSet::from_slice(2, &[0.25, 0.75, 0.75, 0.25]).unwrap();
/// let go = AtomicBool::new(false);
/// let value = l2_discrepancy_cancellable(&points, L2Method::Centered, false, &go);
/// assert_eq!(value, Some(l2_discrepancy(&points, L2Method::Centered)));
/// let stop = AtomicBool::new(true);
/// assert_eq!(l2_discrepancy_cancellable(&points, L2Method::Centered, false, &stop), None);
/// ```
pub fn l2_discrepancy_cancellable(
    points: &PointSet,
    method: L2Method,
    iterative: bool,
    cancel: &AtomicBool,
) -> Option<f64> {
    let n = points.len();
    let count = if iterative { n + 1 } else { n };
    evaluate_cancellable(method, &columns(points), n, count, cancel)
}

/// All four L2-type discrepancies (the columns are extracted once).
pub fn l2_discrepancies(points: &PointSet) -> L2Discrepancies {
    let cols = columns(points);
    let n = points.len();
    L2Discrepancies {
        l2_star: evaluate(L2Method::L2Star, &cols, n, n),
        cd: evaluate(L2Method::Centered, &cols, n, n),
        wd: evaluate(L2Method::WrapAround, &cols, n, n),
        md: evaluate(L2Method::Mixture, &cols, n, n),
    }
}
