//! Point-set metrics of point-major `f64` arrays: SciPy's L2-type
//! discrepancies, the exact star discrepancy and its bounds, nearest-neighbour
//! distances and the radial power spectrum, all from `lowdisc-metrics`.
//!
//! Every function validates the points first (finite, inside `[0, 1]`, a
//! whole number of points); the metrics crate's messages name the first bad
//! point and coordinate.

use lowdisc_metrics::{
    BoundsOptions, DistanceMetric, ExactOptions, L2Method, PointSet, estimated_work,
};

use std::sync::atomic::AtomicBool;

use super::{EngineError, Result};

/// The points as a validated set (`coords` point-major, `d` per point).
fn point_set(coords: &[f64], d: usize) -> Result<PointSet> {
    Ok(PointSet::from_slice(d, coords)?)
}

/// The L2-type discrepancy `method` (SciPy's name: `CD`, `WD`, `MD`,
/// `L2-star`) in SciPy's convention: CD, WD and MD squared, L2-star rooted.
/// `iterative` normalises as if one more point were to be added. Setting
/// `cancel` from another thread stops the sum (the error says so).
pub fn discrepancy(
    coords: &[f64],
    d: usize,
    method: &str,
    iterative: bool,
    cancel: &AtomicBool,
) -> Result<f64> {
    let method = L2Method::ALL
        .into_iter()
        .find(|m| m.scipy_name() == method)
        .ok_or_else(|| {
            EngineError::value(format!(
                "{method:?} is not a valid method. It must be one of \
                 {{'CD', 'WD', 'MD', 'L2-star'}}"
            ))
        })?;
    let points = point_set(coords, d)?;
    lowdisc_metrics::l2_discrepancy_cancellable(&points, method, iterative, cancel)
        .ok_or_else(|| EngineError::value("the discrepancy was cancelled"))
}

/// The pairs times dimensions the L2 discrepancies of `n` points in `d`
/// dimensions visit, `n (n + 1) / 2 * d`: their work.
pub fn discrepancy_work(n: usize, d: usize) -> f64 {
    let n = n as f64;
    n * (n + 1.0) / 2.0 * d as f64
}

/// The estimated elementary operations of the exact star discrepancy.
pub fn star_work(n: usize, d: usize) -> f64 {
    estimated_work(n, d)
}

/// The exact star discrepancy, refused when its estimated work exceeds
/// `max_work` (the message says to use the bounds instead). Setting
/// `cancel` from another thread stops it (the error says so).
pub fn star_discrepancy(
    coords: &[f64],
    d: usize,
    max_work: f64,
    cancel: &AtomicBool,
) -> Result<f64> {
    let points = point_set(coords, d)?;
    let options = ExactOptions { max_work };
    lowdisc_metrics::star_discrepancy_cancellable(&points, &options, cancel)?
        .ok_or_else(|| EngineError::value("the star discrepancy was cancelled"))
}

/// Lower and upper bounds of the star discrepancy.
#[derive(Debug, Clone, PartialEq)]
pub struct StarBounds {
    /// A value attained by some anchored box.
    pub lower: f64,
    /// A proven upper bound.
    pub upper: f64,
    /// How `lower` was found.
    pub lower_method: String,
    /// How `upper` was found.
    pub upper_method: String,
}

/// Options of [`star_bounds`]; `None` keeps the metrics crate's default.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BoundsRequest {
    /// Random anchored boxes.
    pub random_boxes: Option<usize>,
    /// Threshold-accepting moves per restart.
    pub ta_iterations: Option<usize>,
    /// Threshold-accepting restarts.
    pub ta_restarts: Option<usize>,
    /// Cells per axis of the bracketing grid.
    pub grid_cells: Option<usize>,
    /// Seed of the random searches.
    pub seed: u64,
}

/// Lower and upper bounds of the star discrepancy (for sets too large for
/// the exact value). Setting `cancel` from another thread stops them (the
/// error says so).
pub fn star_bounds(
    coords: &[f64],
    d: usize,
    request: &BoundsRequest,
    cancel: &AtomicBool,
) -> Result<StarBounds> {
    let points = point_set(coords, d)?;
    let default = BoundsOptions::default();
    if request.grid_cells == Some(0) {
        return Err(EngineError::value("grid_cells must be at least 1"));
    }
    let options = BoundsOptions {
        random_boxes: request.random_boxes.unwrap_or(default.random_boxes),
        ta_iterations: request.ta_iterations.unwrap_or(default.ta_iterations),
        ta_restarts: request.ta_restarts.unwrap_or(default.ta_restarts),
        grid_cells: request.grid_cells.or(default.grid_cells),
        seed: request.seed,
    };
    let b = lowdisc_metrics::star_bounds_cancellable(&points, &options, cancel)?
        .ok_or_else(|| cancelled("the star-discrepancy bounds"))?;
    Ok(StarBounds {
        lower: b.lower,
        upper: b.upper,
        lower_method: b.lower_method,
        upper_method: b.upper_method,
    })
}

/// The metric called `name`: `euclidean` or `toroidal`.
fn distance_metric(name: &str) -> Result<DistanceMetric> {
    match name {
        "euclidean" => Ok(DistanceMetric::Euclidean),
        "toroidal" => Ok(DistanceMetric::Toroidal),
        other => Err(EngineError::value(format!(
            "metric must be 'euclidean' or 'toroidal', got {other:?}"
        ))),
    }
}

/// Each point's distance to its nearest other point (input order).
/// Setting `cancel` from another thread stops it (the error says so).
pub fn nearest_neighbour_distances(
    coords: &[f64],
    d: usize,
    metric: &str,
    cancel: &AtomicBool,
) -> Result<Vec<f64>> {
    let metric = distance_metric(metric)?;
    let points = point_set(coords, d)?;
    lowdisc_metrics::nearest_neighbour_distances_cancellable(&points, metric, cancel)?
        .ok_or_else(|| cancelled("the nearest-neighbour distances"))
}

/// The smallest distance between two points (0 with duplicates). Setting
/// `cancel` from another thread stops it (the error says so).
pub fn min_distance(coords: &[f64], d: usize, metric: &str, cancel: &AtomicBool) -> Result<f64> {
    let metric = distance_metric(metric)?;
    let points = point_set(coords, d)?;
    lowdisc_metrics::min_distance_cancellable(&points, metric, cancel)?
        .ok_or_else(|| cancelled("the minimum distance"))
}

/// The radially averaged power spectrum of 2-D points: ring radii, mean
/// periodogram per ring, frequencies per ring. Setting `cancel` from
/// another thread stops it (the error says so).
pub fn power_spectrum(
    coords: &[f64],
    d: usize,
    max_frequency: usize,
    cancel: &AtomicBool,
) -> Result<(Vec<f64>, Vec<f64>, Vec<usize>)> {
    let points = point_set(coords, d)?;
    let s = lowdisc_metrics::radial_power_spectrum_cancellable(&points, max_frequency, cancel)?
        .ok_or_else(|| cancelled("the power spectrum"))?;
    Ok((s.radii, s.power, s.counts))
}

/// The error of a computation stopped by its cancel flag.
fn cancelled(what: &str) -> EngineError {
    EngineError::value(format!("{what} was cancelled"))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 16 points of a 4x4 grid of cell centres in 2-D.
    fn grid() -> Vec<f64> {
        (0..16)
            .flat_map(|k| [(k % 4) as f64 / 4.0 + 0.125, (k / 4) as f64 / 4.0 + 0.125])
            .collect()
    }

    #[test]
    fn star_discrepancy_of_one_point_is_its_analytic_value() {
        // One point at x: D* = max(x, 1 - x) in 1-D.
        let go = AtomicBool::new(false);
        assert_eq!(star_discrepancy(&[0.25], 1, 1e9, &go).unwrap(), 0.75);
        let b = star_bounds(&grid(), 2, &BoundsRequest::default(), &go).unwrap();
        let exact = star_discrepancy(&grid(), 2, 1e9, &go).unwrap();
        // A set flag stops it.
        let stop = AtomicBool::new(true);
        let cancelled = star_discrepancy(&grid(), 2, 1e9, &stop).unwrap_err();
        assert!(cancelled.to_string().contains("cancelled"), "{cancelled}");
        assert!(b.lower <= exact && exact <= b.upper, "{b:?} {exact}");
    }

    #[test]
    fn iterative_normalises_by_one_more_point() {
        // WD of n points: -(4/3)^d + S/n^2, so S is recovered from either.
        let x = grid();
        let go = AtomicBool::new(false);
        let plain = discrepancy(&x, 2, "WD", false, &go).unwrap();
        let iter = discrepancy(&x, 2, "WD", true, &go).unwrap();
        let c = (4.0f64 / 3.0).powi(2);
        let s = (plain + c) * 256.0;
        assert!((iter - (s / 289.0 - c)).abs() < 1e-12, "{plain} {iter}");
    }

    #[test]
    fn distances_of_a_grid_are_its_spacing() {
        let go = AtomicBool::new(false);
        assert!((min_distance(&grid(), 2, "euclidean", &go).unwrap() - 0.25).abs() < 1e-15);
        assert!((min_distance(&grid(), 2, "toroidal", &go).unwrap() - 0.25).abs() < 1e-15);
        // Toroidal distance wraps: 0.05 and 0.95 are 0.1 apart.
        let pair = [0.05, 0.5, 0.95, 0.5];
        assert!((min_distance(&pair, 2, "toroidal", &go).unwrap() - 0.1).abs() < 1e-15);
        let nn = nearest_neighbour_distances(&grid(), 2, "euclidean", &go).unwrap();
        assert_eq!(nn.len(), 16);
    }

    #[test]
    fn a_set_flag_stops_the_bounds_the_distances_and_the_spectrum() {
        let stop = AtomicBool::new(true);
        let x = grid();
        let bounds = star_bounds(&x, 2, &BoundsRequest::default(), &stop).unwrap_err();
        assert!(bounds.to_string().contains("cancelled"), "{bounds}");
        let min = min_distance(&x, 2, "euclidean", &stop).unwrap_err();
        assert!(min.to_string().contains("cancelled"), "{min}");
        let nn = nearest_neighbour_distances(&x, 2, "toroidal", &stop).unwrap_err();
        assert!(nn.to_string().contains("cancelled"), "{nn}");
        let spectrum = power_spectrum(&x, 2, 8, &stop).unwrap_err();
        assert!(spectrum.to_string().contains("cancelled"), "{spectrum}");
        let go = AtomicBool::new(false);
        let (radii, power, counts) = power_spectrum(&x, 2, 8, &go).unwrap();
        assert_eq!((radii.len(), power.len(), counts.len()), (8, 8, 8));
    }

    #[test]
    fn bad_input_is_refused_with_the_reason() {
        let err = |r: Result<f64>| r.unwrap_err().to_string();
        let go = AtomicBool::new(false);
        assert!(err(discrepancy(&[0.5, f64::NAN], 2, "CD", false, &go)).contains("not finite"));
        assert!(err(discrepancy(&[0.5], 1, "XD", false, &go)).contains("is not a valid method"));
        let stop = AtomicBool::new(true);
        assert!(err(discrepancy(&grid(), 2, "CD", false, &stop)).contains("cancelled"));
        assert!(err(min_distance(&grid(), 2, "cosine", &go)).contains("'euclidean' or 'toroidal'"));
        assert!(err(star_discrepancy(&grid(), 2, 1.0, &go)).contains("star_bounds"));
    }
}
