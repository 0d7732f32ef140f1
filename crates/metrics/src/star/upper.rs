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

use serde::Serialize;

use super::lower::{random_box_lower_bound, threshold_accepting_lower_bound};
use crate::{MetricsError, PointSet, Result};

/// Largest number of grid corners the default upper bound allocates.
const DEFAULT_CORNERS: f64 = (1u64 << 22) as f64;

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
    Ok((best.min(1.0), k))
}

/// Lower and upper bounds of the star discrepancy in any dimension.
///
/// `lower` is the better of the paper's random boxes and threshold accepting;
/// `upper` is the grid-bracketing bound. Errors only for an invalid grid option.
pub fn star_bounds(points: &PointSet, options: &BoundsOptions) -> Result<StarBounds> {
    let random = random_box_lower_bound(points, options.random_boxes, options.seed);
    let ta = threshold_accepting_lower_bound(
        points,
        options.ta_iterations,
        options.ta_restarts,
        options.seed,
    );
    let d = points.dims();
    // Even k = 1 needs 2^d corners; beyond 2^22 only the trivial bound remains.
    let (upper, upper_method) = if options.grid_cells.is_none() && d > 22 {
        (
            1.0,
            format!("trivial (D* <= 1; a bracketing grid is too large in {d} dimensions)"),
        )
    } else {
        let (u, k) = grid_upper_bound(points, options.grid_cells)?;
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
    Ok(StarBounds {
        lower,
        upper,
        lower_method,
        upper_method,
    })
}
