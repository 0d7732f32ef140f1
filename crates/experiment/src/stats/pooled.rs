//! The paired ratios of several scenes pooled into one number: the
//! geometric mean over scenes, with two 95 % intervals.
//!
//! Scene `s` gives a paired ratio ([`super::paired`]) whose log-ratios
//! `d_si` over its `n_s` seeds have mean `m_s` and standard error `se_s`.
//! The pooled ratio is `exp(M)` with `M = Σ_s m_s / S`, the geometric mean
//! of the scenes' ratios: each scene counts once, whatever its error's size.
//!
//! **Interval over seeds ([`PooledRatio::ci95`]).** For *these* scenes the
//! `m_s` are independent, so `var(M) = Σ_s se_s² / S²` exactly (the delta
//! method is exact here: `M` is linear in the `m_s`). The interval is
//! `exp(M ± t · sqrt(var(M)))` with Student's t at the Welch-Satterthwaite
//! degrees of freedom `var(M)² / Σ_s (se_s² / S²)² / (n_s - 1)`, which is
//! `n - 1` for one scene (the paired ratio's own interval) and grows as
//! scenes are added. It says how well the seeds pin down the ratio on this
//! collection; it does not cover a scene left out.
//!
//! **Interval over scenes ([`PooledRatio::ci95_scenes`]).** Treating the
//! scenes as a sample of scenes like them, the `m_s` scatter by the scenes'
//! real differences *and* their seed noise; `exp(M ± t_{S-1} · sd(m) /
//! sqrt(S))` covers both (the usual two-stage, summary-statistics
//! interval). With four to eight scenes it is wide: it is the honest width
//! of a claim about scenes in general.
//!
//! [`PooledRatio::range`] gives the smallest and largest scene ratio, so a
//! sampler that wins on most scenes and loses badly on one is visible.

use serde::{Deserialize, Serialize};

use super::paired::PairedRatio;
use super::summary::{CONFIDENCE, Summary, t_quantile};

/// The ratio of a sampler's errors to the baseline's over several scenes.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PooledRatio {
    /// Number of scenes.
    pub scenes: usize,
    /// The geometric mean of the scenes' paired ratios.
    pub ratio: f64,
    /// Its 95 % interval from the seeds' scatter, for these scenes.
    pub ci95: [f64; 2],
    /// Its 95 % interval with the scenes as a sample (`None` for one scene).
    pub ci95_scenes: Option<[f64; 2]>,
    /// The smallest and largest scene ratio.
    pub range: [f64; 2],
}

/// The pooled ratio of the scenes' paired ratios (see the module doc);
/// `None` without scenes.
pub fn pooled_ratio(scenes: &[PairedRatio]) -> Option<PooledRatio> {
    if scenes.is_empty() {
        return None;
    }
    let s = scenes.len() as f64;
    let logs: Vec<f64> = scenes.iter().map(|r| r.log_ratio.mean).collect();
    let m = logs.iter().sum::<f64>() / s;
    let parts: Vec<(f64, f64)> = scenes
        .iter()
        .map(|r| {
            let se = r.log_ratio.se;
            (se * se / (s * s), (r.n as f64 - 1.0).max(1.0))
        })
        .collect();
    let var: f64 = parts.iter().map(|(v, _)| v).sum();
    let ci95 = if var > 0.0 {
        let df = var * var / parts.iter().map(|(v, n1)| v * v / n1).sum::<f64>();
        let half = t_quantile(0.5 + CONFIDENCE / 2.0, df) * var.sqrt();
        [(m - half).exp(), (m + half).exp()]
    } else {
        [m.exp(); 2]
    };
    let ci95_scenes = (scenes.len() > 1).then(|| Summary::of(&logs).ci95.map(f64::exp));
    let lo = logs.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = logs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    Some(PooledRatio {
        scenes: scenes.len(),
        ratio: m.exp(),
        ci95,
        ci95_scenes,
        range: [lo.exp(), hi.exp()],
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stats::paired::paired_ratio;
    use crate::stats::tests_support::normal;
    use lowdisc::pcg::Pcg32;

    /// One scene: the pooled ratio is the paired ratio, interval and all.
    #[test]
    fn one_scene_is_its_paired_ratio() {
        let r = paired_ratio(&[1.0, 2.0, 1.5, 0.7], &[2.0, 2.5, 2.0, 1.0]).unwrap();
        let p = pooled_ratio(&[r]).unwrap();
        assert!((p.ratio - r.ratio).abs() < 1e-14);
        assert!((p.ci95[0] - r.ci95[0]).abs() < 1e-12);
        assert!((p.ci95[1] - r.ci95[1]).abs() < 1e-12);
        assert_eq!(p.ci95_scenes, None);
        assert_eq!(p.range, [r.ratio, r.ratio]);
        assert!(pooled_ratio(&[]).is_none());
    }

    /// Constant ratios 0.5 and 2 on two scenes: geometric mean 1, no seed
    /// scatter (a zero-width seed interval), range [0.5, 2], and a scene
    /// interval of exp(± t_1 · ln 2) = exp(± 12.706 · 0.6931).
    #[test]
    fn hand_example_of_two_scenes() {
        let a = paired_ratio(&[1.0, 2.0, 3.0], &[2.0, 4.0, 6.0]).unwrap();
        let b = paired_ratio(&[2.0, 4.0], &[1.0, 2.0]).unwrap();
        let p = pooled_ratio(&[a, b]).unwrap();
        assert!((p.ratio - 1.0).abs() < 1e-12);
        assert!((p.ci95[0] - 1.0).abs() < 1e-12 && (p.ci95[1] - 1.0).abs() < 1e-12);
        assert!((p.range[0] - 0.5).abs() < 1e-12 && (p.range[1] - 2.0).abs() < 1e-12);
        let hi = (12.706_204_736 * 2f64.ln()).exp();
        let [lo_s, hi_s] = p.ci95_scenes.unwrap();
        assert!((hi_s / hi - 1.0).abs() < 1e-6 && (lo_s * hi - 1.0).abs() < 1e-6);
    }

    /// Over 2000 simulated studies of 4 scenes with different true ratios
    /// (geometric mean 0.8) and 6 seeds each, the seed interval covers the
    /// true pooled ratio about 95 % of the time.
    #[test]
    fn seed_interval_covers_the_collection_ratio() {
        let truth = [0.6f64, 0.8, 0.9, 0.8 * 0.8 * 0.8 * 0.8 / (0.6 * 0.8 * 0.9)];
        let pooled_truth = truth.iter().map(|t| t.ln()).sum::<f64>() / 4.0;
        let mut rng = Pcg32::new(5, 8);
        let sets = 2000;
        let mut covered = 0;
        for _ in 0..sets {
            let scenes: Vec<PairedRatio> = truth
                .iter()
                .enumerate()
                .map(|(k, t)| {
                    let own = 0.1 + 0.1 * k as f64;
                    let b: Vec<f64> = (0..6).map(|_| (0.5 * normal(&mut rng)).exp()).collect();
                    let a: Vec<f64> = b
                        .iter()
                        .map(|x| t * x * (own * normal(&mut rng)).exp())
                        .collect();
                    paired_ratio(&a, &b).unwrap()
                })
                .collect();
            let p = pooled_ratio(&scenes).unwrap();
            let truth = pooled_truth.exp();
            covered += usize::from(p.ci95[0] <= truth && truth <= p.ci95[1]);
        }
        let rate = covered as f64 / sets as f64;
        assert!((rate - 0.95).abs() < 0.02, "coverage {rate}");
    }
}
