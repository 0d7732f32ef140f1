//! Aggregation of repeated measurements: mean and sample standard
//! deviation, error ratios to the baseline sampler, log-log slope fits, and
//! the stable content hash that keys the reference cache; and the
//! statistics that can tell two samplers apart:
//!
//! - [`Summary`] ([`summary`]): the mean error, its standard error
//!   `sd / sqrt(n)` and a two-sided 95 % confidence interval from Student's t
//!   with `n - 1` degrees of freedom ([`t_quantile`]), valid for small `n`;
//! - [`PairedRatio`] ([`paired`]): the error of a sampler relative to the
//!   baseline from *paired* runs (run `i` of both uses seed index `i`),
//!   computed on the logarithms of the per-seed ratios, with its interval;
//! - [`Verdict`]: "better", "worse" or "not distinguishable", from whether
//!   the ratio's interval excludes 1;
//! - [`PooledRatio`] ([`pooled`]): the paired ratios of several scenes as
//!   one geometric mean, with an interval over seeds and one over scenes.

pub mod paired;
pub mod pooled;
pub mod summary;

pub use paired::{PairedRatio, Verdict, paired_ratio};
pub use pooled::{PooledRatio, pooled_ratio};
pub use summary::{CONFIDENCE, Summary, t_quantile};

use serde::Serialize;

/// Mean and sample standard deviation (divisor `n - 1`; 0 for one value).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MeanSd {
    /// Arithmetic mean.
    pub mean: f64,
    /// Sample standard deviation.
    pub sd: f64,
}

impl MeanSd {
    /// The mean and sd of `values` (NaN mean for no values).
    pub fn of(values: &[f64]) -> MeanSd {
        let n = values.len() as f64;
        if values.is_empty() {
            return MeanSd {
                mean: f64::NAN,
                sd: f64::NAN,
            };
        }
        let mean = values.iter().sum::<f64>() / n;
        let sd = if values.len() < 2 {
            0.0
        } else {
            (values.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / (n - 1.0)).sqrt()
        };
        MeanSd { mean, sd }
    }
}

/// `value / baseline`, or `None` when the baseline is absent or not positive.
pub fn ratio(value: f64, baseline: Option<f64>) -> Option<f64> {
    baseline.filter(|b| *b > 0.0).map(|b| value / b)
}

/// Least-squares slope of `log2 y` against `log2 x` over the points with
/// both coordinates positive; `None` with fewer than two such points.
pub fn log_log_slope(points: &[[f64; 2]]) -> Option<f64> {
    let pts: Vec<[f64; 2]> = points
        .iter()
        .filter(|p| p[0] > 0.0 && p[1] > 0.0 && p[1].is_finite())
        .map(|p| [p[0].log2(), p[1].log2()])
        .collect();
    if pts.len() < 2 {
        return None;
    }
    let n = pts.len() as f64;
    let mx = pts.iter().map(|p| p[0]).sum::<f64>() / n;
    let my = pts.iter().map(|p| p[1]).sum::<f64>() / n;
    let sxy: f64 = pts.iter().map(|p| (p[0] - mx) * (p[1] - my)).sum();
    let sxx: f64 = pts.iter().map(|p| (p[0] - mx) * (p[0] - mx)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}

/// A convergence series rendered with several seeds, summarised over them.
#[derive(Debug, Clone, PartialEq)]
pub struct SeriesOverSeeds {
    /// Each point's error over the seeds: mean and 95 % interval.
    pub points: Vec<Summary>,
    /// Each seed's log-log slope ([`log_log_slope`]; seeds without a fit
    /// are left out).
    pub slopes: Vec<f64>,
    /// The slopes' mean and 95 % interval.
    pub slope: Summary,
}

/// Summarises `by_seed[k][i]`, seed `k`'s error at `spp[i]` samples per
/// pixel: the slope is fitted per seed, then averaged, so its interval
/// shows how much one seed's fit can be trusted.
///
/// ```
/// use lowdisc_experiment::stats::series_over_seeds;
///
/// // Two seeds, errors 1/spp and 2/spp: both slopes are exactly -1.
/// let s = series_over_seeds(&[1, 2, 4], &[vec![1.0, 0.5, 0.25], vec![2.0, 1.0, 0.5]]);
/// assert_eq!(s.slopes, [-1.0, -1.0]);
/// assert_eq!(s.slope.mean, -1.0);
/// assert_eq!(s.points[0].mean, 1.5);
/// ```
pub fn series_over_seeds(spp: &[u32], by_seed: &[Vec<f64>]) -> SeriesOverSeeds {
    let points = (0..spp.len())
        .map(|i| Summary::of(&by_seed.iter().map(|s| s[i]).collect::<Vec<_>>()))
        .collect();
    let slopes: Vec<f64> = by_seed
        .iter()
        .filter_map(|s| {
            let pts: Vec<[f64; 2]> = spp
                .iter()
                .zip(s)
                .map(|(&n, &e)| [f64::from(n), e])
                .collect();
            log_log_slope(&pts)
        })
        .collect();
    SeriesOverSeeds {
        points,
        slope: Summary::of(&slopes),
        slopes,
    }
}

/// 64-bit FNV-1a hash of `bytes` continuing from `state` (start with
/// [`FNV_OFFSET`]); stable across platforms and compiler versions.
pub fn fnv1a(state: u64, bytes: &[u8]) -> u64 {
    bytes.iter().fold(state, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// The FNV-1a 64-bit offset basis.
pub const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mean_and_sample_sd_of_hand_numbers() {
        // 2, 4, 4, 4, 5, 5, 7, 9: mean 5, sum of squares 32, sd sqrt(32/7).
        let m = MeanSd::of(&[2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0]);
        assert_eq!(m.mean, 5.0);
        assert!((m.sd - (32.0f64 / 7.0).sqrt()).abs() < 1e-15);
        assert_eq!(MeanSd::of(&[3.5]), MeanSd { mean: 3.5, sd: 0.0 });
        assert!(MeanSd::of(&[]).mean.is_nan());
    }

    #[test]
    fn ratio_to_the_baseline() {
        assert_eq!(ratio(0.919, Some(1.0)), Some(0.919));
        assert_eq!(ratio(3.0, Some(4.0)), Some(0.75));
        assert_eq!(ratio(3.0, Some(0.0)), None);
        assert_eq!(ratio(3.0, None), None);
    }

    #[test]
    fn slope_of_an_exact_power_law() {
        let pts: Vec<[f64; 2]> = (0..6)
            .map(|k| {
                let x = f64::from(1u32 << k);
                [x, 3.0 * x.powf(-1.5)]
            })
            .collect();
        assert!((log_log_slope(&pts).unwrap() + 1.5).abs() < 1e-12);
        assert_eq!(log_log_slope(&pts[..1]), None);
        assert_eq!(log_log_slope(&[[1.0, 1.0], [1.0, 2.0]]), None);
    }

    #[test]
    fn a_slope_over_seeds_is_the_mean_of_each_seeds_fit_with_its_interval() {
        let spp = [1, 2, 4, 8];
        // Seeds with slopes -1 and -2 (errors c / spp^k): mean -1.5, sd
        // 1/sqrt(2), se 1/2, and t(0.975, 1) = 12.706.
        let series = |c: f64, k: f64| spp.iter().map(|&n| c * f64::from(n).powf(-k)).collect();
        let s = series_over_seeds(&spp, &[series(2.0, 1.0), series(0.5, 2.0)]);
        assert!((s.slopes[0] + 1.0).abs() < 1e-12 && (s.slopes[1] + 2.0).abs() < 1e-12);
        assert!((s.slope.mean + 1.5).abs() < 1e-12);
        assert!((s.slope.se - 0.5).abs() < 1e-12);
        assert!((s.slope.ci95[1] - (-1.5 + 12.706 * 0.5)).abs() < 1e-3);
        // Each point is the mean over the seeds: (2 + 0.5) / 2 at 1 spp.
        assert_eq!(s.points[0].mean, 1.25);
        assert_eq!(s.points[0].n, 2);
        // One seed: its own slope, no interval.
        let one = series_over_seeds(&spp, &[series(1.0, 1.5)]);
        assert!((one.slope.mean + 1.5).abs() < 1e-12);
        assert!(one.slope.ci95[0].is_nan());
        // A seed whose series cannot be fitted (all errors zero) is left out.
        let zero = series_over_seeds(&spp, &[series(1.0, 1.0), vec![0.0; 4]]);
        assert_eq!(zero.slopes.len(), 1);
    }

    #[test]
    fn fnv_known_values() {
        // Published FNV-1a 64 test vectors: "" and "a".
        assert_eq!(fnv1a(FNV_OFFSET, b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a(FNV_OFFSET, b"a"), 0xaf63_dc4c_8601_ec8c);
    }
}

#[cfg(test)]
mod tests_support {
    //! Seeded normal variates for the simulation tests.
    use lowdisc::pcg::Pcg32;

    /// A standard normal variate (Box-Muller on two PCG32 uniforms).
    pub fn normal(rng: &mut Pcg32) -> f64 {
        let u1 = 1.0 - rng.next_f64(); // (0, 1]
        let u2 = rng.next_f64();
        (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
    }
}
