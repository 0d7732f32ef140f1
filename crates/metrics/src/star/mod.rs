//! Star discrepancy `D*_N`: exact values (1-D, 2-D, small higher-dimensional sets) and
//! lower/upper bounds for any dimension.
//!
//! # Definition
//! For points `x_1..x_N` in `[0,1]^d`,
//! `D*_N = sup_y max(|#{x_i ∈ [0,y)}/N − V(y)|, |#{x_i ∈ [0,y]}/N − V(y)|)` over
//! `y ∈ [0,1]^d`, `V(y) = y_1⋯y_d`: the supremum over open and closed boxes anchored at
//! the origin. The supremum is attained on the *critical grid*: it equals the maximum of
//! `V(y) − #{x_i < y}/N` over `y_j ∈ {x_{ij}} ∪ {1}` and of `#{x_i ≤ y}/N − V(y)` over
//! `y_j ∈ {x_{ij}}` (Niederreiter; Gnewuch, Srivastav & Winzen 2009). Every value returned
//! here is such a maximum (extra grid values, e.g. 1 in the closed part, are real boxes and
//! so never raise it above the supremum).
//!
//! # Algorithms and cost
//! - 1-D ([`star_discrepancy_1d`]): the closed form on sorted points,
//!   `D* = 1/(2N) + max_i |x_(i) − (2i−1)/(2N)|`; O(N log N).
//! - 2-D ([`star_discrepancy`] with `d = 2`): plane sweep with block-decomposed upper
//!   envelopes, O(N^{3/2}) time, O(N) memory (see the `sweep2d` module).
//! - d ≥ 3: recursion in the style of Dobkin, Eppstein & Mitchell (1996): sweep the first
//!   `d − 2` coordinates over their critical values, each prefix (the points below the
//!   sweep value) recursing with the box volume factor, and solve the last two
//!   coordinates by the 2-D sweep. Cost about `N^{d−2}/(d−2)! · N^{3/2}`; a guard
//!   ([`ExactOptions::max_work`]) refuses larger jobs with
//!   [`crate::MetricsError::TooExpensive`], pointing to [`star_bounds`].
//! - Bounds for any d ([`star_bounds`]): lower bounds by random anchored boxes (the paper's
//!   method) and by threshold accepting over critical boxes; an upper bound by grid
//!   bracketing. See the `lower` and `upper` modules.

mod exact_nd;
mod lower;
pub(crate) mod sweep2d;
mod upper;

pub use exact_nd::estimated_work;
pub use lower::{random_box_lower_bound, threshold_accepting_lower_bound};
pub use upper::{
    BoundsOptions, StarBounds, grid_upper_bound, star_bounds, star_bounds_cancellable,
};

use std::sync::atomic::AtomicBool;

use crate::{MetricsError, PointSet, Result};

/// The most dimensions the exact star discrepancy accepts: its recursion
/// takes one stack level per dimension (a few hundred bytes each), so this
/// bound keeps it well inside a 2 MiB thread stack. Above it the work guard
/// alone would let a few points in thousands of dimensions overflow the stack.
pub const MAX_EXACT_DIMS: usize = 1000;

/// Options of the exact star discrepancy.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExactOptions {
    /// Largest accepted value of [`estimated_work`]; above it the exact computation is
    /// refused. Default `4e9` (a few seconds on two cores).
    pub max_work: f64,
}

impl Default for ExactOptions {
    fn default() -> Self {
        Self { max_work: 4e9 }
    }
}

/// Exact star discrepancy of a 1-D sample from the closed form
/// `1/(2N) + max_i |x_(i) − (2i−1)/(2N)|` on the sorted values.
pub fn star_discrepancy_1d(values: &[f64]) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_unstable_by(f64::total_cmp);
    let n = sorted.len() as f64;
    let worst = sorted
        .iter()
        .enumerate()
        .map(|(i, &x)| (x - (2.0 * i as f64 + 1.0) / (2.0 * n)).abs())
        .fold(0.0, f64::max);
    1.0 / (2.0 * n) + worst
}

/// Exact star discrepancy with the default [`ExactOptions`].
pub fn star_discrepancy(points: &PointSet) -> Result<f64> {
    star_discrepancy_with(points, &ExactOptions::default())
}

/// Exact star discrepancy (sup over open and closed anchored boxes).
///
/// Dispatches on the dimension: closed form for d = 1, the O(N^{3/2}) sweep for d = 2,
/// the guarded recursion for d ≥ 3. Errors with [`MetricsError::TooExpensive`] when
/// `estimated_work(n, d) > options.max_work`, and with [`MetricsError::TooManyDims`]
/// above [`MAX_EXACT_DIMS`] dimensions.
pub fn star_discrepancy_with(points: &PointSet, options: &ExactOptions) -> Result<f64> {
    let never = AtomicBool::new(false);
    let value = star_discrepancy_cancellable(points, options, &never)?;
    Ok(value.unwrap_or(f64::NAN))
}

/// [`star_discrepancy_with`] that another thread can stop: `Ok(None)` if
/// `cancel` was set before it finished (the recursion checks it before every
/// prefix, the 2-D sweep every 1,024 columns).
///
/// ```
/// use std::sync::atomic::AtomicBool;
/// use lowdisc_metrics::{ExactOptions, PointSet, star_discrepancy_cancellable};
///
/// let points = PointSet::from_slice(2, &[0.25, 0.75, 0.75, 0.25]).unwrap();
/// let go = AtomicBool::new(false);
/// let value = star_discrepancy_cancellable(&points, &ExactOptions::default(), &go);
/// assert!(value.unwrap().is_some());
/// let stop = AtomicBool::new(true);
/// let value = star_discrepancy_cancellable(&points, &ExactOptions::default(), &stop);
/// assert_eq!(value.unwrap(), None);
/// ```
pub fn star_discrepancy_cancellable(
    points: &PointSet,
    options: &ExactOptions,
    cancel: &AtomicBool,
) -> Result<Option<f64>> {
    let (n, d) = (points.len(), points.dims());
    if d == 1 {
        return Ok(Some(star_discrepancy_1d(points.coords())));
    }
    if d > MAX_EXACT_DIMS {
        return Err(MetricsError::TooManyDims {
            dims: d,
            limit: MAX_EXACT_DIMS,
        });
    }
    let work = estimated_work(n, d);
    // A NaN limit refuses too.
    let within = matches!(
        work.partial_cmp(&options.max_work),
        Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)
    );
    if !within {
        return Err(MetricsError::TooExpensive {
            n,
            dims: d,
            estimated_work: work,
            limit: options.max_work,
        });
    }
    Ok(exact_nd::exact(points, cancel))
}
