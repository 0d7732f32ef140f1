//! Upper bound of the star discrepancy by grid bracketing, and [`star_bounds`], which
//! pairs it with the lower bounds.
//!
//! Cut `[0,1]^d` into `k^d` cells of width `1/k`. Any corner `y` lies in a cell with lower
//! corner `g⁻` and upper corner `g⁺`; then `[0,g⁻) ⊆ [0,y) ⊆ [0,y] ⊆ [0,g⁺]`, so
//! `A(y)/N − V(y) ≤ A_closed(g⁺)/N − V(g⁻)` and `V(y) − A(y)/N ≤ V(g⁺) − A_open(g⁻)/N`.
//! The maximum of these two over all cells bounds `D*` from above (the volume slack
//! `V(g⁺) − V(g⁻) ≤ d/k` is the price). Counts at all `(k+1)^d` grid corners come from a
//! histogram and `d` prefix-sum passes; cost O(N·d + (k+1)^d·d), memory `(k+1)^d` words.
//! The default `k` is the largest with `(k+1)^d ≤ 2^22` (e.g. 2047 in 2-D, 7 in 8-D):
//! tight in low dimension, weak but valid in high dimension; above 22 dimensions
//! [`star_bounds`] falls back to the trivial bound 1.
//!
//! [`star_bounds_cancellable`] is [`star_bounds`] that another thread can stop: the
//! searches check the flag before every box or move, the grid between prefix-sum passes
//! and every [`CANCEL_CHECK`] corners.

use std::sync::atomic::{AtomicBool, Ordering};

use serde::Serialize;

use super::lower::{random_boxes, threshold_accepting};
use crate::{MetricsError, PointSet, Result};

/// Largest number of grid corners the default upper bound allocates.
const DEFAULT_CORNERS: f64 = (1u64 << 22) as f64;

/// How many grid corners the upper bound visits between checks of its cancel flag.
const CANCEL_CHECK: usize = 1 << 16;

/// Lower and upper bounds of `D*_N`, each with the method that produced it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StarBounds {
    /// A value attained by some anchored box: `lower ≤ D*_N`.
    pub lower: f64,
    /// A proven bound: `D*_N ≤ upper`.
    pub upper: f64,
    /// How `lower` was found (method and parameters).
    pub lower_method: String,
    /// How `upper` was found (method and parameters).
    pub upper_method: String,
}

/// Options of [`star_bounds`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundsOptions {
    /// Random anchored boxes of the paper's method (default 10,000).
    pub random_boxes: usize,
    /// Threshold-accepting moves per restart (default 2,000).
    pub ta_iterations: usize,
    /// Independent threshold-accepting restarts (default 8).
    pub ta_restarts: usize,
    /// Cells per axis of the bracketing grid; `None` picks the default described above.
    pub grid_cells: Option<usize>,
    /// Seed of every random choice.
    pub seed: u64,
}

impl Default for BoundsOptions {
    fn default() -> Self {
        Self {
            random_boxes: 10_000,
            ta_iterations: 2_000,
            ta_restarts: 8,
            grid_cells: None,
            seed: 1,
        }
    }
}

/// Default cells per axis: the largest `k ≥ 1` with `(k+1)^d ≤ 2^22`.
pub fn default_grid_cells(d: usize) -> usize {
    let k = DEFAULT_CORNERS.powf(1.0 / d as f64).floor() as usize;
    k.saturating_sub(1).max(1)
}

/// Index of the first grid value `i/k` satisfying `pred`, exact in floating point.
fn first_corner(x: f64, k: usize, pred: impl Fn(f64) -> bool) -> usize {
    let kf = k as f64;
    let mut i = (x * kf).floor().max(0.0) as usize;
    while i > 0 && pred((i - 1) as f64 / kf) {
        i -= 1;
    }
    while i <= k && !pred(i as f64 / kf) {
        i += 1;
    }
    i
}

/// Grid-bracketing upper bound with `k` cells per axis (`None`: default). Errors with
/// [`MetricsError::InvalidOption`] when `k == 0` or `(k+1)^d` exceeds 2^28 corners.
pub fn grid_upper_bound(points: &PointSet, k: Option<usize>) -> Result<(f64, usize)> {
    let never = AtomicBool::new(false);
    Ok(grid_bound(points, k, &never)?.unwrap_or((f64::NAN, 0)))
}

/// [`grid_upper_bound`], or `Ok(None)` once `cancel` is set.
fn grid_bound(
    points: &PointSet,
    k: Option<usize>,
    cancel: &AtomicBool,
) -> Result<Option<(f64, usize)>> {
    let cancelled = || cancel.load(Ordering::Relaxed);
    let d = points.dims();
    let k = k.unwrap_or_else(|| default_grid_cells(d));
    let side = k + 1;
    let corners = (side as f64).powi(d as i32);
    if k == 0 || corners > (1u64 << 28) as f64 {
        return Err(MetricsError::InvalidOption(format!(
            "grid of {k} cells per axis in {d} dimensions is out of range"
        )));
    }
    let total = side.pow(d as u32);
    // closed[c]: points with x <= corner c; open[c]: points with x < corner c.
    let mut closed = vec![0u32; total];
    let mut open = vec![0u32; total];
    for p in points.iter() {
        let (mut ci, mut oi, mut o_ok) = (0usize, 0usize, true);
        for &x in p.iter().rev() {
            let c = first_corner(x, k, |g| x <= g);
            let o = first_corner(x, k, |g| x < g);
            o_ok &= o <= k;
            ci = ci * side + c;
            oi = oi * side + o.min(k);
        }
        closed[ci] += 1;
        if o_ok {
            open[oi] += 1;
        }
    }
    let mut stride = 1;
    for _ in 0..d {
        for arr in [&mut closed, &mut open] {
            if cancelled() {
                return Ok(None);
            }
            for idx in 0..total {
                if (idx / stride) % side != 0 {
                    arr[idx] += arr[idx - stride];
                }
            }
        }
        stride *= side;
    }
    let inv_n = 1.0 / points.len() as f64;
    let kf = k as f64;
    let mut best = 0.0f64;
    let mut digits = vec![0usize; d];
    for (lo, &open_lo) in open.iter().enumerate() {
        if lo % CANCEL_CHECK == 0 && cancelled() {
            return Ok(None);
        }
        let mut rest = lo;
        for dig in digits.iter_mut() {
            *dig = rest % side;
            rest /= side;
        }
        if digits.contains(&k) {
            continue;
        }
        let (mut v_lo, mut v_hi, mut hi, mut s) = (1.0, 1.0, 0usize, 1usize);
        for &dig in digits.iter() {
            v_lo *= dig as f64 / kf;
            v_hi *= (dig + 1) as f64 / kf;
            hi += (dig + 1) * s;
            s *= side;
        }
        let above = f64::from(closed[hi]) * inv_n - v_lo;
        let below = v_hi - f64::from(open_lo) * inv_n;
        best = best.max(above).max(below);
    }
    Ok(Some((best.min(1.0), k)))
}

/// Lower and upper bounds of the star discrepancy in any dimension.
///
/// `lower` is the better of the paper's random boxes and threshold accepting;
/// `upper` is the grid-bracketing bound. Errors only for an invalid grid option.
pub fn star_bounds(points: &PointSet, options: &BoundsOptions) -> Result<StarBounds> {
    let never = AtomicBool::new(false);
    let bounds = star_bounds_cancellable(points, options, &never)?;
    Ok(bounds.expect("never cancelled"))
}

/// [`star_bounds`] that another thread can stop: `Ok(None)` if `cancel` was set
/// before it finished; otherwise exactly [`star_bounds`]' result.
///
/// ```
/// use std::sync::atomic::AtomicBool;
/// use lowdisc_metrics::{BoundsOptions, PointSet, star_bounds, star_bounds_cancellable};
///
/// let points = PointSet::from_slice(2, &[0.25, 0.75, 0.75, 0.25]).unwrap();
/// let options = BoundsOptions::default();
/// let go = AtomicBool::new(false);
/// let bounds = star_bounds_cancellable(&points, &options, &go).unwrap();
/// assert_eq!(bounds, Some(star_bounds(&points, &options).unwrap()));
/// let stop = AtomicBool::new(true);
/// assert_eq!(star_bounds_cancellable(&points, &options, &stop).unwrap(), None);
/// ```
pub fn star_bounds_cancellable(
    points: &PointSet,
    options: &BoundsOptions,
    cancel: &AtomicBool,
) -> Result<Option<StarBounds>> {
    let Some(random) = random_boxes(points, options.random_boxes, options.seed, cancel) else {
        return Ok(None);
    };
    let Some(ta) = threshold_accepting(
        points,
        options.ta_iterations,
        options.ta_restarts,
        options.seed,
        cancel,
    ) else {
        return Ok(None);
    };
    let d = points.dims();
    // Even k = 1 needs 2^d corners; beyond 2^22 only the trivial bound remains.
    let (upper, upper_method) = if options.grid_cells.is_none() && d > 22 {
        (
            1.0,
            format!("trivial (D* <= 1; a bracketing grid is too large in {d} dimensions)"),
        )
    } else {
        let Some((u, k)) = grid_bound(points, options.grid_cells, cancel)? else {
            return Ok(None);
        };
        (u, format!("grid bracketing ({k} cells per axis)"))
    };
    let (lower, lower_method) = if ta >= random {
        (
            ta,
            format!(
                "threshold accepting over critical boxes ({} x {} moves, seed {})",
                options.ta_restarts, options.ta_iterations, options.seed
            ),
        )
    } else {
        (
            random,
            format!(
                "random anchored boxes ({}, seed {})",
                options.random_boxes, options.seed
            ),
        )
    };
    Ok(Some(StarBounds {
        lower,
        upper,
        lower_method,
        upper_method,
    }))
}
