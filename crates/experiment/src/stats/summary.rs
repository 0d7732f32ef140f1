//! The mean of repeated measurements with its standard error and a Student-t
//! confidence interval.
//!
//! For values `x_1..x_n`: `mean = Σ x_i / n`, the sample standard deviation
//! `sd = sqrt(Σ (x_i - mean)² / (n - 1))`, the standard error of the mean
//! `se = sd / sqrt(n)`, and the two-sided [`CONFIDENCE`] (95 %) interval
//! `mean ± t_{0.975, n-1} · se`. The t quantile (12.71 for `n = 2`, 2.26 for
//! `n = 10`, 1.96 as `n → ∞`) makes the interval honest for the small `n` of
//! an experiment, where the normal quantile would be too narrow. The interval
//! assumes the mean is about normally distributed over repetitions: true for
//! the sum of many pixel errors, less so for a handful of heavy-tailed runs
//! (see [`super::paired`] for the ratio, computed on logarithms).

use serde::{Deserialize, Serialize};
use statrs::distribution::{ContinuousCDF, Normal, StudentsT};

/// The two-sided confidence level of every interval of this crate.
pub const CONFIDENCE: f64 = 0.95;

/// Above this many degrees of freedom [`t_quantile`] uses the normal
/// quantile: they differ by less than `1e-5` there, and statrs's t inverse
/// loses accuracy for very large `df`.
const NORMAL_LIMIT_DF: f64 = 1e5;

/// The `p` quantile of Student's t distribution with `df` degrees of
/// freedom (NaN unless `0 < p < 1` and `df > 0`).
pub fn t_quantile(p: f64, df: f64) -> f64 {
    if !(p > 0.0 && p < 1.0) {
        return f64::NAN;
    }
    if df > NORMAL_LIMIT_DF {
        return Normal::standard().inverse_cdf(p);
    }
    match StudentsT::new(0.0, 1.0, df) {
        Ok(t) => t.inverse_cdf(p),
        Err(_) => f64::NAN,
    }
}

/// The half-width factor of the two-sided [`CONFIDENCE`] interval for `n`
/// values: `t_{(1 + CONFIDENCE)/2, n-1}` (NaN for `n < 2`).
pub fn interval_factor(n: usize) -> f64 {
    if n < 2 {
        return f64::NAN;
    }
    t_quantile(0.5 + CONFIDENCE / 2.0, (n - 1) as f64)
}

/// Mean, spread and 95 % interval of repeated measurements.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Summary {
    /// Number of values.
    pub n: usize,
    /// Arithmetic mean (NaN for no values).
    pub mean: f64,
    /// Sample standard deviation, divisor `n - 1` (0 for one value).
    pub sd: f64,
    /// Standard error of the mean, `sd / sqrt(n)` (NaN for fewer than two values).
    pub se: f64,
    /// The 95 % confidence interval of the mean, `[low, high]` (NaN for
    /// fewer than two values).
    pub ci95: [f64; 2],
}

impl Summary {
    /// The summary of `values`.
    pub fn of(values: &[f64]) -> Summary {
        let n = values.len();
        if n == 0 {
            return Summary {
                n,
                mean: f64::NAN,
                sd: f64::NAN,
                se: f64::NAN,
                ci95: [f64::NAN; 2],
            };
        }
        let nf = n as f64;
        let mean = values.iter().sum::<f64>() / nf;
        if n == 1 {
            return Summary {
                n,
                mean,
                sd: 0.0,
                se: f64::NAN,
                ci95: [f64::NAN; 2],
            };
        }
        let ss: f64 = values.iter().map(|v| (v - mean) * (v - mean)).sum();
        let sd = (ss / (nf - 1.0)).sqrt();
        let se = sd / nf.sqrt();
        let half = interval_factor(n) * se;
        Summary {
            n,
            mean,
            sd,
            se,
            ci95: [mean - half, mean + half],
        }
    }

    /// The standard error relative to the mean, `se / |mean|`.
    pub fn relative_se(&self) -> f64 {
        self.se / self.mean.abs()
    }

    /// True when `value` lies in the 95 % interval (bounds included).
    pub fn covers(&self, value: f64) -> bool {
        self.ci95[0] <= value && value <= self.ci95[1]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stats::tests_support::normal;
    use lowdisc::pcg::Pcg32;

    #[test]
    fn t_quantiles_match_the_published_table() {
        // Two-sided 95 % critical values (e.g. NIST/SEMATECH e-Handbook, table 1.3.6.7.2).
        for (df, t) in [
            (1.0, 12.706),
            (2.0, 4.303),
            (4.0, 2.776),
            (9.0, 2.262),
            (15.0, 2.131),
            (30.0, 2.042),
            (100.0, 1.984),
        ] {
            let q = t_quantile(0.975, df);
            assert!((q - t).abs() < 6e-4, "df {df}: {q} vs {t}");
        }
        for (df, t) in [(200.0, 1.971_896), (999.0, 1.962_346), (1e4, 1.960_201)] {
            let q = t_quantile(0.975, df);
            assert!((q - t).abs() < 2e-5, "df {df}: {q}");
        }
        let big = t_quantile(0.975, 1e7);
        assert!((big - 1.959_964).abs() < 1e-5, "{big}");
        assert!((t_quantile(0.5, 3.0)).abs() < 1e-12);
        assert!(t_quantile(1.0, 3.0).is_nan() && t_quantile(0.9, 0.0).is_nan());
    }

    #[test]
    fn summary_of_hand_numbers() {
        // 2, 4, 4, 4, 5, 5, 7, 9: mean 5, sum of squares 32, sd sqrt(32/7).
        let s = Summary::of(&[2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0]);
        let sd = (32.0f64 / 7.0).sqrt();
        assert_eq!((s.n, s.mean), (8, 5.0));
        assert!((s.sd - sd).abs() < 1e-15);
        assert!((s.se - sd / 8f64.sqrt()).abs() < 1e-15);
        let half = 2.364_624 * s.se; // t_{0.975, 7}
        assert!((s.ci95[0] - (5.0 - half)).abs() < 1e-5);
        assert!((s.ci95[1] - (5.0 + half)).abs() < 1e-5);
        assert!(s.covers(5.0) && !s.covers(3.0));
    }

    #[test]
    fn degenerate_inputs_give_nan_not_panics() {
        assert!(Summary::of(&[]).mean.is_nan());
        let one = Summary::of(&[3.5]);
        assert_eq!((one.mean, one.sd), (3.5, 0.0));
        assert!(one.se.is_nan() && one.ci95[0].is_nan());
        let same = Summary::of(&[2.0; 4]);
        assert_eq!(same.ci95, [2.0, 2.0]);
    }

    /// Over many simulated data sets of 6 normal values, the interval covers
    /// the true mean in about 95 % of them (binomial sd 0.3 % at 5000 sets).
    #[test]
    fn interval_covers_the_true_mean_95_percent_of_the_time() {
        let mut rng = Pcg32::new(7, 1);
        let sets = 5000;
        let mut covered = 0;
        for _ in 0..sets {
            let values: Vec<f64> = (0..6).map(|_| 3.0 + 0.5 * normal(&mut rng)).collect();
            covered += usize::from(Summary::of(&values).covers(3.0));
        }
        let rate = covered as f64 / sets as f64;
        assert!((rate - 0.95).abs() < 0.01, "coverage {rate}");
    }

    /// The normal quantile (1.96) instead of t would under-cover at n = 3:
    /// the test above would notice a wrong factor.
    #[test]
    fn normal_quantile_would_under_cover_small_samples() {
        let mut rng = Pcg32::new(11, 3);
        let (sets, mut t_cov, mut z_cov) = (5000, 0, 0);
        for _ in 0..sets {
            let values: Vec<f64> = (0..3).map(|_| normal(&mut rng)).collect();
            let s = Summary::of(&values);
            t_cov += usize::from(s.covers(0.0));
            z_cov += usize::from(s.mean.abs() <= 1.96 * s.se);
        }
        let (t, z) = (t_cov as f64 / sets as f64, z_cov as f64 / sets as f64);
        assert!((t - 0.95).abs() < 0.01, "t coverage {t}");
        assert!(z < 0.90, "normal-quantile coverage {z}");
    }
}
