//! Nearest-neighbour distances: the minimum pairwise distance of a point set and the
//! mean nearest-neighbour distance, Euclidean in `[0,1]^d` or on the unit torus
//! (coordinates wrap: per-axis difference `min(|a−b|, 1−|a−b|)`).
//!
//! Algorithm: a uniform grid of `g^d` cells, `g = ⌊n^{1/d}⌋` (about one point per
//! cell), points bucketed by cell in compressed rows. For each point the cells are
//! visited in rings of growing Chebyshev radius `r` around its own cell (wrapping on the
//! torus); after ring `r` every unvisited point is at least `r/g` away, so the search
//! stops as soon as the best distance found is at most `r/g`, or when all cells were
//! seen. Exact for any input (duplicates give 0). Cost: O(n log n)-like, in practice
//! O(n · 3^d) for evenly spread sets; degrades towards O(n²) for strongly clustered sets
//! or high dimension (where `g` is 1 or 2). Points are processed in parallel (rayon).
//!
//! The `_cancellable` variants take a flag another thread sets to stop them: every
//! point's search checks it before each cell it visits, so a cancelled computation
//! stops within one cell per thread (its values discarded).

use std::sync::atomic::{AtomicBool, Ordering};

use rayon::prelude::*;
use serde::Serialize;

use crate::{MetricsError, PointSet, Result};

/// How distances are measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
pub enum DistanceMetric {
    /// Euclidean distance in the unit cube.
    Euclidean,
    /// Euclidean distance on the unit torus (each axis wraps around).
    Toroidal,
}

/// Minimum and mean nearest-neighbour distance of a point set.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DistanceStats {
    /// The metric used.
    pub metric: DistanceMetric,
    /// Smallest distance between two distinct points (0 with duplicates).
    pub min_distance: f64,
    /// Mean over points of the distance to the nearest other point.
    pub mean_nn_distance: f64,
}

/// Squared distance between two points under `metric`.
pub fn squared_distance(metric: DistanceMetric, a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(&x, &y)| {
            let mut t = (x - y).abs();
            if metric == DistanceMetric::Toroidal {
                t = t.min(1.0 - t);
            }
            t * t
        })
        .sum()
}

struct Grid {
    g: usize,
    start: Vec<usize>,
    members: Vec<u32>,
}

fn cell_of(p: &[f64], g: usize) -> Vec<usize> {
    p.iter()
        .map(|&x| ((x * g as f64) as usize).min(g - 1))
        .collect()
}

fn build_grid(points: &PointSet) -> Grid {
    let (n, d) = (points.len(), points.dims());
    let mut g = (n as f64).powf(1.0 / d as f64).floor().max(1.0) as usize;
    while g > 1 && (g as f64).powi(d as i32) > 4.0 * n as f64 {
        g -= 1;
    }
    let linear = |c: &[usize]| c.iter().rev().fold(0usize, |acc, &v| acc * g + v);
    let cells = g.pow(d as u32);
    let ids: Vec<usize> = points.iter().map(|p| linear(&cell_of(p, g))).collect();
    let mut start = vec![0usize; cells + 1];
    for &c in &ids {
        start[c + 1] += 1;
    }
    for c in 0..cells {
        start[c + 1] += start[c];
    }
    let mut fill = start.clone();
    let mut members = vec![0u32; n];
    for (i, &c) in ids.iter().enumerate() {
        members[fill[c]] = i as u32;
        fill[c] += 1;
    }
    Grid { g, start, members }
}

/// Distance from point `i` to its nearest other point (NaN once `cancel` is set).
fn nearest(
    points: &PointSet,
    grid: &Grid,
    metric: DistanceMetric,
    i: usize,
    cancel: &AtomicBool,
) -> f64 {
    let d = points.dims();
    let g = grid.g as isize;
    let p = points.point(i);
    let home: Vec<isize> = cell_of(p, grid.g).iter().map(|&c| c as isize).collect();
    let torus = metric == DistanceMetric::Toroidal;
    let mut best = f64::INFINITY;
    let mut offset = vec![0isize; d];
    let mut r = 0isize;
    loop {
        if cancel.load(Ordering::Relaxed) {
            return f64::NAN;
        }
        // Visit every offset in [-r, r]^d whose Chebyshev norm is exactly r.
        offset.fill(-r);
        'cells: loop {
            // In high dimension a ring has up to 3^d cells: check here too.
            if cancel.load(Ordering::Relaxed) {
                return f64::NAN;
            }
            if offset.iter().any(|o| o.abs() == r) {
                let mut lin = 0usize;
                let mut inside = true;
                for j in (0..d).rev() {
                    let mut c = home[j] + offset[j];
                    if torus {
                        c = c.rem_euclid(g);
                    } else if c < 0 || c >= g {
                        inside = false;
                        break;
                    }
                    lin = lin * grid.g + c as usize;
                }
                if inside {
                    for &q in &grid.members[grid.start[lin]..grid.start[lin + 1]] {
                        if q as usize != i {
                            best = best.min(squared_distance(metric, p, points.point(q as usize)));
                        }
                    }
                }
            }
            for o in offset.iter_mut() {
                if *o < r {
                    *o += 1;
                    continue 'cells;
                }
                *o = -r;
            }
            break;
        }
        let covered = if torus { 2 * r + 1 >= g } else { r >= g - 1 };
        let reach = r as f64 / g as f64;
        if covered || best <= reach * reach {
            return best.sqrt();
        }
        r += 1;
    }
}

/// Distance from every point to its nearest other point (in input order).
///
/// Errors with [`MetricsError::TooFewPoints`] for a single point.
pub fn nearest_neighbour_distances(points: &PointSet, metric: DistanceMetric) -> Result<Vec<f64>> {
    let never = AtomicBool::new(false);
    Ok(nearest_neighbour_distances_cancellable(points, metric, &never)?.unwrap_or_default())
}

/// [`nearest_neighbour_distances`] that another thread can stop: `Ok(None)` if
/// `cancel` was set before it finished; otherwise exactly its result.
///
/// ```
/// use std::sync::atomic::AtomicBool;
/// use lowdisc_metrics::{DistanceMetric, PointSet, nearest_neighbour_distances_cancellable};
///
/// let points = PointSet::from_slice(2, &[0.1, 0.1, 0.1, 0.6, 0.9, 0.6]).unwrap();
/// let go = AtomicBool::new(false);
/// let nn = nearest_neighbour_distances_cancellable(&points, DistanceMetric::Euclidean, &go);
/// assert_eq!(nn.unwrap().unwrap().len(), 3);
/// let stop = AtomicBool::new(true);
/// let nn = nearest_neighbour_distances_cancellable(&points, DistanceMetric::Euclidean, &stop);
/// assert_eq!(nn.unwrap(), None);
/// ```
pub fn nearest_neighbour_distances_cancellable(
    points: &PointSet,
    metric: DistanceMetric,
    cancel: &AtomicBool,
) -> Result<Option<Vec<f64>>> {
    if points.len() < 2 {
        return Err(MetricsError::TooFewPoints {
            needed: 2,
            got: points.len(),
        });
    }
    let grid = build_grid(points);
    let distances = (0..points.len())
        .into_par_iter()
        .map(|i| nearest(points, &grid, metric, i, cancel))
        .collect();
    Ok((!cancel.load(Ordering::Relaxed)).then_some(distances))
}

/// Minimum pairwise distance and mean nearest-neighbour distance.
///
/// Errors with [`MetricsError::TooFewPoints`] for a single point.
pub fn distance_stats(points: &PointSet, metric: DistanceMetric) -> Result<DistanceStats> {
    let nn = nearest_neighbour_distances(points, metric)?;
    Ok(stats(metric, &nn))
}

/// [`distance_stats`] that another thread can stop: `Ok(None)` if `cancel` was set
/// before it finished; otherwise exactly its result.
pub fn distance_stats_cancellable(
    points: &PointSet,
    metric: DistanceMetric,
    cancel: &AtomicBool,
) -> Result<Option<DistanceStats>> {
    let nn = nearest_neighbour_distances_cancellable(points, metric, cancel)?;
    Ok(nn.map(|nn| stats(metric, &nn)))
}

/// The statistics of the nearest-neighbour distances `nn`.
fn stats(metric: DistanceMetric, nn: &[f64]) -> DistanceStats {
    DistanceStats {
        metric,
        min_distance: nn.iter().copied().fold(f64::INFINITY, f64::min),
        mean_nn_distance: nn.iter().sum::<f64>() / nn.len() as f64,
    }
}

/// Minimum pairwise distance (0 when two points coincide).
pub fn min_distance(points: &PointSet, metric: DistanceMetric) -> Result<f64> {
    Ok(distance_stats(points, metric)?.min_distance)
}

/// [`min_distance`] that another thread can stop: `Ok(None)` if `cancel` was set
/// before it finished; otherwise exactly its result.
pub fn min_distance_cancellable(
    points: &PointSet,
    metric: DistanceMetric,
    cancel: &AtomicBool,
) -> Result<Option<f64>> {
    Ok(distance_stats_cancellable(points, metric, cancel)?.map(|s| s.min_distance))
}
