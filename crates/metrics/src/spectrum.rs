//! Radially averaged power spectrum of a 2-D point set (the numbers; plots are drawn
//! elsewhere).
//!
//! Periodogram at integer frequency `k = (k_x, k_y)`:
//! `P(k) = |Σ_i exp(−2πi k·x_i)|² / n`, so a random (Poisson) set has `E P(k) = 1` for
//! `k ≠ 0` and `P(0) = n`. The frequencies of `[−K, K]²` except 0 are grouped into rings
//! by radius `|k|`: ring `r` (r = 1..=K) holds `r − ½ ≤ |k| < r + ½`; each ring reports
//! the mean of `P` over its frequencies. Frequencies beyond radius `K + ½` (corners of the
//! square) are not used.
//!
//! Algorithm: the exponentials factor per axis, `e^{−2πi k_x x} e^{−2πi k_y y}`, so the
//! `n(2K+1)` per-axis phases are computed once by complex recurrence from exact
//! `sin/cos` of the first step (re-anchored every 32 steps to bound drift), and each
//! frequency costs one complex product per point. `P(−k) = P(k)` halves the work.
//! Cost O(n K²) multiplications, parallel over `k_x` (rayon); memory O(n K).
//!
//! [`radial_power_spectrum_cancellable`] checks a cancel flag before every frequency
//! (one pass over the points), so another thread can stop it within one pass per thread.

use std::sync::atomic::{AtomicBool, Ordering};

use rayon::prelude::*;
use serde::Serialize;

use crate::{MetricsError, PointSet, Result};

/// Radially averaged periodogram.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RadialSpectrum {
    /// Ring centre radii `1, 2, …, K` (in cycles per unit length).
    pub radii: Vec<f64>,
    /// Mean periodogram value in each ring (1 for white noise, below 1 for blue noise).
    pub power: Vec<f64>,
    /// Number of integer frequencies in each ring.
    pub counts: Vec<usize>,
    /// Number of points `n`.
    pub points: usize,
}

/// Per-axis phases `exp(−2πi k x)` for `k = 0..=K`, as (cos, sin) pairs.
fn phases(x: f64, kmax: usize) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(kmax + 1);
    let (s1, c1) = (-2.0 * std::f64::consts::PI * x).sin_cos();
    let (mut re, mut im) = (1.0, 0.0);
    for k in 0..=kmax {
        if k % 32 == 0 {
            let (s, c) = (-2.0 * std::f64::consts::PI * x * k as f64).sin_cos();
            re = c;
            im = s;
        }
        out.push((re, im));
        (re, im) = (re * c1 - im * s1, re * s1 + im * c1);
    }
    out
}

/// Radially averaged power spectrum with frequencies up to `max_frequency` (K ≥ 1).
///
/// Errors: [`MetricsError::WrongDims`] unless the set is 2-D,
/// [`MetricsError::InvalidOption`] when `max_frequency` is 0 or above 4096.
pub fn radial_power_spectrum(points: &PointSet, max_frequency: usize) -> Result<RadialSpectrum> {
    let never = AtomicBool::new(false);
    let spectrum = radial_power_spectrum_cancellable(points, max_frequency, &never)?;
    Ok(spectrum.expect("never cancelled"))
}

/// [`radial_power_spectrum`] that another thread can stop: `Ok(None)` if `cancel` was
/// set before it finished; otherwise exactly its result.
///
/// ```
/// use std::sync::atomic::AtomicBool;
/// use lowdisc_metrics::{PointSet, radial_power_spectrum, radial_power_spectrum_cancellable};
///
/// let points = PointSet::from_slice(2, &[0.25, 0.75, 0.75, 0.25]).unwrap();
/// let go = AtomicBool::new(false);
/// let s = radial_power_spectrum_cancellable(&points, 8, &go).unwrap();
/// assert_eq!(s, Some(radial_power_spectrum(&points, 8).unwrap()));
/// let stop = AtomicBool::new(true);
/// assert_eq!(radial_power_spectrum_cancellable(&points, 8, &stop).unwrap(), None);
/// ```
pub fn radial_power_spectrum_cancellable(
    points: &PointSet,
    max_frequency: usize,
    cancel: &AtomicBool,
) -> Result<Option<RadialSpectrum>> {
    if points.dims() != 2 {
        return Err(MetricsError::WrongDims {
            expected: 2,
            got: points.dims(),
        });
    }
    if max_frequency == 0 || max_frequency > 4096 {
        return Err(MetricsError::InvalidOption(format!(
            "max_frequency {max_frequency} must be in 1..=4096"
        )));
    }
    let kmax = max_frequency;
    let n = points.len();
    let px: Vec<Vec<(f64, f64)>> = points.iter().map(|p| phases(p[0], kmax)).collect();
    let py: Vec<Vec<(f64, f64)>> = points.iter().map(|p| phases(p[1], kmax)).collect();
    // Half plane: k_x > 0 with any k_y, plus k_x = 0 with k_y > 0; P(-k) = P(k).
    let rings = (0..=kmax)
        .into_par_iter()
        .map(|kx| {
            let mut sum = vec![0.0; kmax + 1];
            let mut cnt = vec![0usize; kmax + 1];
            let ky_lo: isize = if kx == 0 { 1 } else { -(kmax as isize) };
            for ky in ky_lo..=kmax as isize {
                let radius = ((kx * kx) as f64 + (ky * ky) as f64).sqrt();
                let ring = (radius + 0.5).floor() as usize;
                if ring == 0 || ring > kmax || cancel.load(Ordering::Relaxed) {
                    continue;
                }
                let (mut re, mut im) = (0.0, 0.0);
                let kyu = ky.unsigned_abs();
                for (ax, ay) in px.iter().zip(&py) {
                    let (xr, xi) = ax[kx];
                    let (yr, yi) = ay[kyu];
                    // exp(-2πi k_y y) for negative k_y is the conjugate.
                    let yi = if ky < 0 { -yi } else { yi };
                    re += xr * yr - xi * yi;
                    im += xr * yi + xi * yr;
                }
                sum[ring] += 2.0 * (re * re + im * im) / n as f64;
                cnt[ring] += 2;
            }
            (sum, cnt)
        })
        .collect::<Vec<_>>()
        .into_iter()
        // Summed in k_x order, so the result does not depend on the threads.
        .fold((vec![0.0; kmax + 1], vec![0usize; kmax + 1]), |mut a, b| {
            for r in 0..=kmax {
                a.0[r] += b.0[r];
                a.1[r] += b.1[r];
            }
            a
        });
    if cancel.load(Ordering::Relaxed) {
        return Ok(None);
    }
    let (sum, cnt) = rings;
    Ok(Some(RadialSpectrum {
        radii: (1..=kmax).map(|r| r as f64).collect(),
        power: (1..=kmax).map(|r| sum[r] / cnt[r].max(1) as f64).collect(),
        counts: cnt[1..].to_vec(),
        points: n,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn single_point_is_flat_one() {
        let p = PointSet::new(2, vec![0.3, 0.7]).unwrap();
        let s = radial_power_spectrum(&p, 8).unwrap();
        for &v in &s.power {
            assert!((v - 1.0).abs() < 1e-12, "{v}");
        }
        // Ring r holds the lattice points with r-1/2 <= |k| < r+1/2 (both signs).
        assert_eq!(s.counts[0], 8);
    }

    #[test]
    fn equals_direct_periodogram() {
        // 37 irregular points; every frequency of [-K, K]^2 evaluated with sin/cos.
        let coords: Vec<f64> = (0..74)
            .map(|i| ((i * 7919 + 13) % 1000) as f64 / 999.0)
            .collect();
        let p = PointSet::new(2, coords).unwrap();
        let kmax = 40usize;
        let s = radial_power_spectrum(&p, kmax).unwrap();
        let (mut sum, mut cnt) = (vec![0.0; kmax + 1], vec![0usize; kmax + 1]);
        let k = kmax as i64;
        for kx in -k..=k {
            for ky in -k..=k {
                let ring = (((kx * kx + ky * ky) as f64).sqrt() + 0.5).floor() as usize;
                if ring == 0 || ring > kmax {
                    continue;
                }
                let (mut re, mut im) = (0.0f64, 0.0f64);
                for q in p.iter() {
                    let ph = -2.0 * std::f64::consts::PI * (kx as f64 * q[0] + ky as f64 * q[1]);
                    re += ph.cos();
                    im += ph.sin();
                }
                sum[ring] += (re * re + im * im) / p.len() as f64;
                cnt[ring] += 1;
            }
        }
        for r in 1..=kmax {
            assert_eq!(s.counts[r - 1], cnt[r]);
            let want = sum[r] / cnt[r] as f64;
            assert!(
                (s.power[r - 1] - want).abs() < 1e-9,
                "ring {r}: {} vs {want}",
                s.power[r - 1]
            );
        }
    }

    #[test]
    fn regular_lattice_has_peaks_at_multiples() {
        // m x m lattice with spacing 1/m: P(k) = n when m divides both k_x, k_y, else 0.
        let m = 4;
        let coords: Vec<f64> = (0..m * m)
            .flat_map(|i| {
                [
                    ((i % m) as f64 + 0.5) / m as f64,
                    ((i / m) as f64 + 0.5) / m as f64,
                ]
            })
            .collect();
        let p = PointSet::new(2, coords).unwrap();
        let s = radial_power_spectrum(&p, 6).unwrap();
        for r in 0..3 {
            assert!(s.power[r].abs() < 1e-9, "ring {} = {}", r + 1, s.power[r]);
        }
        // Ring 4 holds (±4,0),(0,±4) with P = 16 among 16 frequencies of radius in [3.5, 4.5).
        let expected = 4.0 * 16.0 / s.counts[3] as f64;
        assert!(
            (s.power[3] - expected).abs() < 1e-9,
            "{} vs {expected}",
            s.power[3]
        );
        assert!(radial_power_spectrum(&PointSet::new(1, vec![0.5]).unwrap(), 4).is_err());
    }
}
