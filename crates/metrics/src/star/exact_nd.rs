//! Exact star discrepancy for d ≥ 2 by recursion over the critical values of the first
//! `d − 2` coordinates, with the 2-D sweep as the base case.
//!
//! At a level sweeping coordinate `k` over the distinct values `v_1 < … < v_m` of the
//! current subset `S`, the prefix `P_i = {p ∈ S : p_k ≤ v_i}` holds exactly the points of
//! the closed boxes with `y_k = v_i` and of the open boxes with `y_k = v_{i+1}` (or 1).
//! Only values present in `S` matter: between them the count is constant, so the open
//! side is maximised at the next value up and the closed side at the value itself.
//! Hence one recursive call on `P_i` with the two volume factors
//! `f_open · v_{i+1}` and `f_closed · v_i` covers both sides. Sub-calls are skipped when
//! simple bounds (open ≤ factor, closed ≤ |P_i|/N) cannot beat the best found so far.
//! The top level is parallel over prefixes (rayon). Every prefix checks the
//! caller's cancel flag first, and so does the 2-D sweep between blocks of
//! points, so a cancelled computation stops within one sweep per thread.

use std::sync::atomic::{AtomicBool, Ordering};

use rayon::prelude::*;

use super::sweep2d::one_sided_2d;
use crate::PointSet;

/// Estimated elementary operations of the exact star discrepancy for `n` points in `d`
/// dimensions: `n log2 n` for d = 1, `n^{3/2}` for d = 2 and
/// `n^{d−2}/(d−2)! · n^{3/2}` for d ≥ 3 (all times a small constant of 4).
pub fn estimated_work(n: usize, d: usize) -> f64 {
    let nf = n.max(1) as f64;
    if d <= 1 {
        return nf * nf.log2().max(1.0);
    }
    let mut w = 4.0 * nf.powf(1.5);
    for k in 1..=(d - 2) {
        w *= nf / k as f64;
    }
    w
}

/// Exact star discrepancy of a set of dimension ≥ 2 (no cost guard);
/// `None` if `cancel` was set before it finished.
pub(crate) fn exact(points: &PointSet, cancel: &AtomicBool) -> Option<f64> {
    let n = points.len();
    let run = Run {
        points,
        inv_n: 1.0 / n as f64,
        cancel,
    };
    let rows: Vec<u32> = (0..n as u32).collect();
    let (open, closed) = level(&run, &rows, 0, Some(1.0), Some(1.0), true);
    if cancel.load(Ordering::Relaxed) {
        return None;
    }
    Some(open.max(closed).clamp(0.0, 1.0))
}

/// What every level of one computation shares.
struct Run<'a> {
    points: &'a PointSet,
    /// `1 / N`.
    inv_n: f64,
    /// Set by the caller to stop.
    cancel: &'a AtomicBool,
}

fn level(
    run: &Run<'_>,
    rows: &[u32],
    k: usize,
    f_open: Option<f64>,
    f_closed: Option<f64>,
    parallel: bool,
) -> (f64, f64) {
    let (points, inv_n) = (run.points, run.inv_n);
    let none = (f64::NEG_INFINITY, f64::NEG_INFINITY);
    if run.cancel.load(Ordering::Relaxed) {
        return none;
    }
    let d = points.dims();
    let coord = |r: u32, j: usize| points.coords()[r as usize * d + j];
    if rows.is_empty() {
        // No points: the open side is the full remaining volume, the closed side is void.
        return (f_open.unwrap_or(f64::NEG_INFINITY), f64::NEG_INFINITY);
    }
    if k + 2 == d {
        let xs: Vec<f64> = rows.iter().map(|&r| coord(r, k)).collect();
        let ys: Vec<f64> = rows.iter().map(|&r| coord(r, k + 1)).collect();
        return one_sided_2d(&xs, &ys, (f_open, f_closed), inv_n, run.cancel);
    }
    let mut sorted = rows.to_vec();
    sorted.sort_unstable_by(|&a, &b| coord(a, k).total_cmp(&coord(b, k)));
    // Group ends: prefix i (1-based) is sorted[..ends[i-1]], with value values[i-1].
    let mut values = Vec::new();
    let mut ends = Vec::new();
    for (idx, &r) in sorted.iter().enumerate() {
        let v = coord(r, k);
        if values.last() != Some(&v) {
            if !values.is_empty() {
                ends.push(idx);
            }
            values.push(v);
        }
    }
    ends.push(sorted.len());
    let m = values.len();
    // Task i covers prefix P_i (P_0 empty): open factor for the next value, closed for v_i.
    let task = |i: usize| -> (Option<f64>, Option<f64>, usize) {
        let fo = f_open.and_then(|f| {
            if i < m {
                Some(f * values[i])
            } else if values[m - 1] < 1.0 {
                Some(f)
            } else {
                None
            }
        });
        let fc = if i >= 1 {
            f_closed.map(|f| f * values[i - 1])
        } else {
            None
        };
        let len = if i == 0 { 0 } else { ends[i - 1] };
        (fo, fc, len)
    };
    let prefix = |i: usize| {
        let (fo, fc, len) = task(i);
        level(run, &sorted[..len], k + 1, fo, fc, false)
    };
    let merge = |a: (f64, f64), b: (f64, f64)| (a.0.max(b.0), a.1.max(b.1));
    if parallel {
        return (0..=m).into_par_iter().map(prefix).reduce(|| none, merge);
    }
    let mut best = none;
    for i in 0..=m {
        let (fo, fc, len) = task(i);
        let open_cap = fo.unwrap_or(f64::NEG_INFINITY);
        let closed_cap = if fc.is_some() {
            len as f64 * inv_n
        } else {
            f64::NEG_INFINITY
        };
        if open_cap <= best.0 && closed_cap <= best.1 {
            continue;
        }
        let fo = fo.filter(|&f| f > best.0);
        let fc = fc.filter(|_| closed_cap > best.1);
        let got = level(run, &sorted[..len], k + 1, fo, fc, false);
        best = merge(best, got);
    }
    best
}
