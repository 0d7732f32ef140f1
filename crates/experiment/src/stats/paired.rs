//! The error of a sampler relative to a baseline, from paired seeds, with a
//! 95 % confidence interval, and the verdict it supports.
//!
//! **Pairing.** Run `i` of both samplers uses the same seed index `i` (and
//! so the same scene, resolution and spp). The per-seed ratio
//! `q_i = a_i / b_i` cancels what the two runs share (a render seed that
//! is hard for every sampler), so its scatter is far smaller than that of
//! `a_i` or `b_i` alone, which scatter by 50-100 % of their mean at 16 spp.
//!
//! **Method: log-ratio mean with a Student-t interval.** With
//! `d_i = ln(a_i / b_i)`, the ratio is `exp(mean(d))` and its 95 % interval
//! `exp(mean(d) ± t_{0.975, n-1} · se(d))` ([`Summary`] of the
//! `d_i`). The estimate is the *geometric* mean of the per-seed ratios: the
//! typical factor between the two samplers' errors on one render, which is
//! what a user choosing a sampler gets. It differs from the ratio of the
//! arithmetic means ([`PairedRatio::ratio_of_means`], reported beside it) when
//! the ratio varies between seeds. Errors are positive and multiplicative
//! (an MSE scatters by a factor), so the logarithm makes `d_i` close to
//! normal, the interval exact for log-normal scatter, and one weak seed
//! shifts the estimate by its log, not by its size. A paired bootstrap would
//! need a random seed and gives a similar interval; the t interval needs
//! neither and is exact in the log-normal case, which the tests simulate.
//!
//! **Verdict.** If the whole interval lies below 1 the sampler is better
//! (lower error) than the baseline at 95 % confidence; above 1 it is worse;
//! otherwise the two are not distinguishable with these runs.

use serde::{Deserialize, Serialize};

use super::summary::Summary;

/// The outcome of comparing a sampler with the baseline.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// The ratio's 95 % interval lies below 1: lower error than the baseline.
    Better,
    /// The interval lies above 1: higher error than the baseline.
    Worse,
    /// The interval contains 1.
    NotDistinguishable,
}

impl Verdict {
    /// A short phrase for reports: "better", "worse", "not distinguishable".
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Better => "better",
            Verdict::Worse => "worse",
            Verdict::NotDistinguishable => "not distinguishable",
        }
    }
}

/// The paired ratio of a sampler's errors to the baseline's.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PairedRatio {
    /// Number of seed pairs.
    pub n: usize,
    /// The geometric mean of the per-seed ratios, `exp(mean ln(a_i / b_i))`.
    pub ratio: f64,
    /// Its 95 % confidence interval `[low, high]`.
    pub ci95: [f64; 2],
    /// The summary of the log-ratios `ln(a_i / b_i)`.
    pub log_ratio: Summary,
    /// `mean(a) / mean(b)`, for comparison with tables of mean errors.
    pub ratio_of_means: f64,
    /// What the interval says.
    pub verdict: Verdict,
}

/// The paired ratio of `errors` to `baseline` (element `i` of both from
/// seed index `i`). `None` unless both have the same length of at least 2
/// and every value is finite and positive.
pub fn paired_ratio(errors: &[f64], baseline: &[f64]) -> Option<PairedRatio> {
    let valid = |v: &[f64]| v.iter().all(|x| x.is_finite() && *x > 0.0);
    if errors.len() != baseline.len() || errors.len() < 2 || !valid(errors) || !valid(baseline) {
        return None;
    }
    let logs: Vec<f64> = errors
        .iter()
        .zip(baseline)
        .map(|(a, b)| (a / b).ln())
        .collect();
    let log_ratio = Summary::of(&logs);
    let ci95 = log_ratio.ci95.map(f64::exp);
    let verdict = if ci95[1] < 1.0 {
        Verdict::Better
    } else if ci95[0] > 1.0 {
        Verdict::Worse
    } else {
        Verdict::NotDistinguishable
    };
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    Some(PairedRatio {
        n: errors.len(),
        ratio: log_ratio.mean.exp(),
        ci95,
        log_ratio,
        ratio_of_means: mean(errors) / mean(baseline),
        verdict,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stats::tests_support::normal;
    use lowdisc::pcg::Pcg32;

    /// `n` paired errors of true ratio `ratio`: a log-normal seed effect of
    /// log-sd `shared` common to both samplers, and an own log-normal
    /// scatter of log-sd `own` on the tested sampler.
    fn synthetic(rng: &mut Pcg32, n: usize, ratio: f64, shared: f64, own: f64) -> [Vec<f64>; 2] {
        let mut a = Vec::with_capacity(n);
        let mut b = Vec::with_capacity(n);
        for _ in 0..n {
            let base = 1e-3 * (shared * normal(rng)).exp();
            b.push(base);
            a.push(ratio * base * (own * normal(rng)).exp());
        }
        [a, b]
    }

    #[test]
    fn hand_example() {
        // Ratios 0.5 and 2: geometric mean 1, ratio of means (1+4)/(2+2) = 1.25.
        let r = paired_ratio(&[1.0, 4.0], &[2.0, 2.0]).unwrap();
        assert!((r.ratio - 1.0).abs() < 1e-15);
        assert!((r.ratio_of_means - 1.25).abs() < 1e-15);
        assert_eq!(r.verdict, Verdict::NotDistinguishable);
        // A constant ratio has a zero-width interval at it.
        let r = paired_ratio(&[0.9, 1.8, 2.7], &[1.0, 2.0, 3.0]).unwrap();
        assert!((r.ratio - 0.9).abs() < 1e-12);
        assert!((r.ci95[0] - 0.9).abs() < 1e-12 && (r.ci95[1] - 0.9).abs() < 1e-12);
        assert_eq!(r.verdict, Verdict::Better);
    }

    #[test]
    fn bad_inputs_give_none() {
        assert!(paired_ratio(&[1.0], &[1.0]).is_none());
        assert!(paired_ratio(&[1.0, 2.0], &[1.0]).is_none());
        assert!(paired_ratio(&[1.0, 0.0], &[1.0, 1.0]).is_none());
        assert!(paired_ratio(&[1.0, f64::NAN], &[1.0, 1.0]).is_none());
        assert!(paired_ratio(&[1.0, 2.0], &[1.0, -1.0]).is_none());
    }

    /// Over 4000 simulated experiments of 8 seeds with true ratio 0.8, the
    /// interval covers 0.8 about 95 % of the time (binomial sd 0.34 %).
    #[test]
    fn interval_covers_the_true_ratio_95_percent_of_the_time() {
        let mut rng = Pcg32::new(2024, 5);
        let sets = 4000;
        let mut covered = 0;
        for _ in 0..sets {
            let [a, b] = synthetic(&mut rng, 8, 0.8, 0.7, 0.1);
            let r = paired_ratio(&a, &b).unwrap();
            covered += usize::from(r.ci95[0] <= 0.8 && 0.8 <= r.ci95[1]);
        }
        let rate = covered as f64 / sets as f64;
        assert!((rate - 0.95).abs() < 0.012, "coverage {rate}");
    }

    /// The estimate is unbiased on the log scale: the mean estimated ratio
    /// over many experiments is the true ratio.
    #[test]
    fn estimate_centres_on_the_true_ratio() {
        let mut rng = Pcg32::new(99, 2);
        let sets = 2000;
        let mean_log: f64 = (0..sets)
            .map(|_| {
                let [a, b] = synthetic(&mut rng, 6, 1.3, 0.5, 0.2);
                paired_ratio(&a, &b).unwrap().ratio.ln()
            })
            .sum::<f64>()
            / sets as f64;
        assert!((mean_log.exp() - 1.3).abs() < 0.005, "{}", mean_log.exp());
    }

    /// Pairing resolves a 5 % difference that unpaired intervals of the same
    /// runs cannot: a shared seed effect of 70 % hides it in the means.
    #[test]
    fn pairing_resolves_what_separate_means_cannot() {
        let mut rng = Pcg32::new(3, 9);
        let [a, b] = synthetic(&mut rng, 16, 0.95, 0.7, 0.02);
        let r = paired_ratio(&a, &b).unwrap();
        assert_eq!(r.verdict, Verdict::Better, "{r:?}");
        assert!(r.ci95[1] < 0.97 && r.ci95[0] > 0.93, "{r:?}");
        let (sa, sb) = (Summary::of(&a), Summary::of(&b));
        assert!(sa.ci95[1] > sb.ci95[0] && sb.ci95[1] > sa.ci95[0]);
    }

    /// With no true difference, "not distinguishable" is the verdict about
    /// 95 % of the time, and "better" and "worse" share the rest.
    #[test]
    fn equal_samplers_are_mostly_not_distinguishable() {
        let mut rng = Pcg32::new(17, 4);
        let sets = 4000;
        let mut counts = [0usize; 3];
        for _ in 0..sets {
            let [a, b] = synthetic(&mut rng, 5, 1.0, 0.6, 0.3);
            let k = match paired_ratio(&a, &b).unwrap().verdict {
                Verdict::Better => 0,
                Verdict::Worse => 1,
                Verdict::NotDistinguishable => 2,
            };
            counts[k] += 1;
        }
        let nd = counts[2] as f64 / sets as f64;
        assert!((nd - 0.95).abs() < 0.012, "{counts:?}");
        assert!(counts[0] > 50 && counts[1] > 50, "{counts:?}");
    }

    #[test]
    fn verdict_serialises_as_words() {
        assert_eq!(Verdict::NotDistinguishable.as_str(), "not distinguishable");
        assert_eq!(Verdict::Better.as_str(), "better");
        assert_eq!(Verdict::Worse.as_str(), "worse");
    }
}
