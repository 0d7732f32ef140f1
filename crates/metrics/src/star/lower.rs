//! Lower bounds of the star discrepancy in any dimension, by evaluating the local
//! discrepancy of chosen anchored boxes and keeping the maximum (every box's value is a
//! true lower bound).
//!
//! - [`random_box_lower_bound`] — the paper's method: `K` corners `y` uniform in
//!   `[0,1]^d`, each scored with open and closed counts. Cost O(K·N·d), parallel over
//!   boxes. Weak: random corners rarely hit the critical grid.
//! - [`threshold_accepting_lower_bound`] — a search over *critical* boxes (corners on
//!   the grid of point coordinates ∪ {1}) by threshold accepting, in the style of Winker
//!   & Fang (1997) and Gnewuch, Wahlström & Winzen (2012): from a random grid corner, a
//!   move shifts one or two coordinates by a random number of grid steps (range shrinking
//!   over time); a move is accepted when it loses less than the current threshold, which
//!   decreases linearly to zero. As in GWW, each evaluation also *snaps* the box: the
//!   closed box shrinks to the largest contained coordinate per axis (same points, less
//!   volume) and the open box grows per axis up to the nearest point blocking only that
//!   axis (re-counted). Independent restarts run in parallel. Cost O(R·I·N·d).
//!
//! All randomness comes from SplitMix64 seeded by the caller: equal seeds give equal
//! results, whatever the thread count.
//!
//! The crate's cancellable bounds ([`super::star_bounds_cancellable`]) pass a cancel
//! flag: once it is set, a random box or a threshold-accepting move is skipped (each
//! costs one pass over the points), so a cancelled search stops within one pass per
//! thread and its value is discarded.

use std::sync::atomic::{AtomicBool, Ordering};

use rayon::prelude::*;

use crate::PointSet;

/// SplitMix64 (Steele, Lea & Flood 2014): small, fast, good enough for search moves.
#[derive(Debug, Clone)]
pub(crate) struct SplitMix64(u64);

impl SplitMix64 {
    pub(crate) fn new(seed: u64) -> Self {
        Self(seed)
    }

    pub(crate) fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub(crate) fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Uniform in 0..bound (bound > 0), by multiply-shift.
    pub(crate) fn below(&mut self, bound: usize) -> usize {
        ((u128::from(self.next_u64()) * bound as u128) >> 64) as usize
    }
}

/// Scratch space of [`local_discrepancy`].
pub(crate) struct Scratch {
    snap: Vec<f64>,
    grow: Vec<f64>,
}

impl Scratch {
    pub(crate) fn new(d: usize) -> Self {
        Self {
            snap: vec![0.0; d],
            grow: vec![0.0; d],
        }
    }
}

fn open_count(points: &PointSet, y: &[f64]) -> usize {
    points
        .iter()
        .filter(|p| p.iter().zip(y).all(|(a, b)| a < b))
        .count()
}

/// Best local discrepancy among three real boxes derived from corner `y`:
/// the open box `[0,y)`, the closed box shrunk to the largest contained coordinate per
/// axis (same points, smaller volume), and the open box grown per axis up to the
/// nearest point that blocks only that axis (re-counted, since growing several axes at
/// once can take in new points).
fn local_discrepancy(points: &PointSet, y: &[f64], s: &mut Scratch) -> f64 {
    let d = points.dims();
    s.snap.fill(0.0);
    s.grow.fill(1.0);
    let (mut open, mut closed) = (0usize, 0usize);
    for p in points.iter() {
        let mut fails = 0usize;
        let mut failed_axis = 0usize;
        let mut le = true;
        for j in 0..d {
            if p[j] >= y[j] {
                fails += 1;
                failed_axis = j;
                le &= p[j] <= y[j];
            }
        }
        if fails == 0 {
            open += 1;
        } else if fails == 1 {
            s.grow[failed_axis] = s.grow[failed_axis].min(p[failed_axis]);
        }
        if le {
            closed += 1;
            for (m, &v) in s.snap.iter_mut().zip(p) {
                *m = m.max(v);
            }
        }
    }
    let inv_n = 1.0 / points.len() as f64;
    let volume: f64 = y.iter().product();
    let mut best = volume - open as f64 * inv_n;
    if closed > 0 {
        best = best.max(closed as f64 * inv_n - s.snap.iter().product::<f64>());
    }
    if s.grow.iter().zip(y).any(|(g, v)| g > v) {
        let grown_volume: f64 = s.grow.iter().product();
        if grown_volume - open as f64 * inv_n > best {
            let grown = std::mem::take(&mut s.grow);
            best = best.max(grown_volume - open_count(points, &grown) as f64 * inv_n);
            s.grow = grown;
        }
    }
    best
}

/// The paper's lower bound: the largest local discrepancy over `boxes` random anchored
/// boxes (corners uniform in `[0,1]^d`, from `seed`). Returns 0 when `boxes == 0`.
pub fn random_box_lower_bound(points: &PointSet, boxes: usize, seed: u64) -> f64 {
    let never = AtomicBool::new(false);
    random_boxes(points, boxes, seed, &never).unwrap_or(0.0)
}

/// [`random_box_lower_bound`], or `None` once `cancel` is set.
pub(crate) fn random_boxes(
    points: &PointSet,
    boxes: usize,
    seed: u64,
    cancel: &AtomicBool,
) -> Option<f64> {
    const CHUNK: usize = 256;
    let d = points.dims();
    let best = (0..boxes.div_ceil(CHUNK))
        .into_par_iter()
        .map(|c| {
            let mut rng = SplitMix64::new(seed ^ (c as u64).wrapping_mul(0xD6E8_FEB8_6659_FD93));
            let mut y = vec![0.0; d];
            let mut snap = Scratch::new(d);
            let count = CHUNK.min(boxes - c * CHUNK);
            (0..count)
                .map(|_| {
                    y.iter_mut().for_each(|v| *v = rng.next_f64());
                    if cancel.load(Ordering::Relaxed) {
                        return 0.0;
                    }
                    local_discrepancy(points, &y, &mut snap)
                })
                .fold(0.0, f64::max)
        })
        .reduce(|| 0.0, f64::max);
    (!cancel.load(Ordering::Relaxed)).then_some(best)
}

/// Threshold-accepting search over critical boxes: `restarts` independent runs of
/// `iterations` moves each (seeded from `seed`), returning the best local discrepancy
/// found (0 when `iterations == 0` or `restarts == 0`).
pub fn threshold_accepting_lower_bound(
    points: &PointSet,
    iterations: usize,
    restarts: usize,
    seed: u64,
) -> f64 {
    let never = AtomicBool::new(false);
    threshold_accepting(points, iterations, restarts, seed, &never).unwrap_or(0.0)
}

/// [`threshold_accepting_lower_bound`], or `None` once `cancel` is set.
pub(crate) fn threshold_accepting(
    points: &PointSet,
    iterations: usize,
    restarts: usize,
    seed: u64,
    cancel: &AtomicBool,
) -> Option<f64> {
    let d = points.dims();
    let grids: Vec<Vec<f64>> = (0..d)
        .map(|j| {
            let mut g = points.column(j);
            g.push(1.0);
            g.sort_unstable_by(f64::total_cmp);
            g.dedup();
            g
        })
        .collect();
    if iterations == 0 {
        return Some(0.0);
    }
    let best = (0..restarts)
        .into_par_iter()
        .map(|r| {
            let mut rng = SplitMix64::new(
                seed.wrapping_add((r as u64 + 1).wrapping_mul(0x2545_F491_4F6C_DD1D)),
            );
            ta_run(points, &grids, iterations, &mut rng, cancel)
        })
        .reduce(|| 0.0, f64::max);
    (!cancel.load(Ordering::Relaxed)).then_some(best)
}

/// One threshold-accepting run; it stops early (its value then meaningless)
/// once `cancel` is set.
fn ta_run(
    points: &PointSet,
    grids: &[Vec<f64>],
    iterations: usize,
    rng: &mut SplitMix64,
    cancel: &AtomicBool,
) -> f64 {
    let d = grids.len();
    let mut snap = Scratch::new(d);
    let corner =
        |idx: &[usize]| -> Vec<f64> { idx.iter().zip(grids).map(|(&i, g)| g[i]).collect() };
    let random_idx =
        |rng: &mut SplitMix64| -> Vec<usize> { grids.iter().map(|g| rng.below(g.len())).collect() };
    let neighbour = |rng: &mut SplitMix64, idx: &[usize], frac: f64| -> Vec<usize> {
        let mut next = idx.to_vec();
        let moves = if d == 1 { 1 } else { 1 + rng.below(2) };
        for _ in 0..moves {
            let j = rng.below(d);
            let len = grids[j].len();
            let range = ((len as f64 * 0.25 * frac).round() as usize).max(1);
            let step = 1 + rng.below(range);
            next[j] = if rng.below(2) == 0 {
                next[j].saturating_sub(step)
            } else {
                (next[j] + step).min(len - 1)
            };
        }
        next
    };
    // Initial threshold: twice the mean change of a full-range random move (tuned on
    // random 2-D/3-D sets: half of it got stuck in local optima).
    let mut total = 0.0;
    const PROBES: usize = 32;
    for _ in 0..PROBES {
        if cancel.load(Ordering::Relaxed) {
            return 0.0;
        }
        let a = random_idx(rng);
        let b = neighbour(rng, &a, 1.0);
        let va = local_discrepancy(points, &corner(&a), &mut snap);
        let vb = local_discrepancy(points, &corner(&b), &mut snap);
        total += (va - vb).abs();
    }
    let t0 = 2.0 * total / PROBES as f64;
    let mut cur = random_idx(rng);
    let mut cur_val = local_discrepancy(points, &corner(&cur), &mut snap);
    let mut best = cur_val;
    for t in 0..iterations {
        if cancel.load(Ordering::Relaxed) {
            break;
        }
        let frac = 1.0 - t as f64 / iterations as f64;
        let cand = neighbour(rng, &cur, frac);
        let val = local_discrepancy(points, &corner(&cand), &mut snap);
        if val >= cur_val - t0 * frac {
            cur = cand;
            cur_val = val;
            best = best.max(val);
        }
    }
    best
}
