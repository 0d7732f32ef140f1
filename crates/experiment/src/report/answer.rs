//! The answer to the paper's question, written from the run's results: the
//! paper's claim (Song & Ro 2019: the digit-permuted Sobol sequence has
//! about 8 % less error than Sobol at 16 samples per pixel), the measured
//! ratio of the paper's sampler's relMSE to `sobol`'s with its 95 %
//! interval and what that interval says, and the best sampler of the run.
//! [`Answer::markdown`] is the report's first section and
//! [`Answer::line`] the last line the `experiment` command prints.

use crate::comparison::{BASELINE, relmse_ratio};
use crate::config::ExperimentConfig;
use crate::results::{Results, SamplerResult};
use crate::stats::Verdict;

/// The paper's measured error of its sequence over Sobol's (its table:
/// 12.7090 against 13.8215, sportscar at 16 spp, mean of 10 runs).
pub const PAPER_CLAIMED_RATIO: f64 = 12.7090 / 13.8215;

/// The samplers that implement the paper's permutation, in order of
/// preference for the answer: the code as printed, then its reproducible
/// reading.
const PAPER_SAMPLERS: [&str; 2] = ["paper", "paper-repro"];

/// The samples per pixel of the paper's measurement.
pub const PAPER_SPP: u32 = 16;

/// One sampler's relMSE relative to [`BASELINE`].
#[derive(Debug, Clone, PartialEq)]
pub struct Measured {
    /// The sampler's name.
    pub name: String,
    /// The paired ratio (geometric mean over seeds), or with a single run
    /// the ratio of the means.
    pub ratio: f64,
    /// The paired ratio's 95 % interval and verdict, when there are at
    /// least two runs.
    pub interval: Option<([f64; 2], Verdict)>,
}

impl Measured {
    fn of(s: &SamplerResult) -> Option<Measured> {
        match (relmse_ratio(s), s.relmse_ratio_to_sobol) {
            (Some(p), _) => Some(Measured {
                name: s.name.clone(),
                ratio: p.ratio,
                interval: Some((p.ci95, p.verdict)),
            }),
            (None, Some(ratio)) => Some(Measured {
                name: s.name.clone(),
                ratio,
                interval: None,
            }),
            (None, None) => None,
        }
    }

    /// `1.984x [1.956, 2.012]`, or `1.984x (one run, no interval)`.
    fn cell(&self) -> String {
        match self.interval {
            Some(([lo, hi], _)) => format!("{:.3}x [{lo:.3}, {hi:.3}]", self.ratio),
            None => format!("{:.3}x (one run, no interval)", self.ratio),
        }
    }

    fn verdict(&self) -> Option<Verdict> {
        self.interval.map(|(_, v)| v)
    }

    /// [`Measured::cell`], bold when the interval excludes 1.
    fn marked_cell(&self) -> String {
        match self.verdict() {
            Some(Verdict::Better | Verdict::Worse) => format!("**{}**", self.cell()),
            _ => self.cell(),
        }
    }
}

/// What the run says about the paper's claim.
#[derive(Debug, Clone, PartialEq)]
pub struct Answer {
    /// Samples per pixel of the runs.
    pub spp: u32,
    /// Runs (seeds) per sampler.
    pub runs: u32,
    /// Whether the run has the baseline `sobol`.
    pub has_baseline: bool,
    /// The paper's sampler against `sobol`, when the run has both.
    pub paper: Option<Measured>,
    /// The sampler with the lowest relMSE among those whose interval lies
    /// below 1; `None` when no sampler is resolved as better than `sobol`.
    pub best: Option<Measured>,
    /// The sampler with the lowest ratio whatever its interval (the
    /// baseline itself counts as 1).
    pub lowest: Option<Measured>,
}

impl Answer {
    /// The answer of `results`, whose runs used `config`'s settings.
    pub fn of(config: &ExperimentConfig, results: &Results) -> Answer {
        Answer::from_runs(config.spp, config.runs, results)
    }

    /// The answer of `results` of `runs` renders per sampler at `spp`.
    fn from_runs(spp: u32, runs: u32, results: &Results) -> Answer {
        let has_baseline = results.samplers.iter().any(|s| s.name == BASELINE);
        let measured: Vec<Measured> = results
            .samplers
            .iter()
            .filter(|s| s.name != BASELINE)
            .filter_map(Measured::of)
            .collect();
        let paper = PAPER_SAMPLERS
            .iter()
            .find_map(|name| measured.iter().find(|m| m.name == *name))
            .cloned();
        let by_ratio = |a: &&Measured, b: &&Measured| a.ratio.total_cmp(&b.ratio);
        let best = measured
            .iter()
            .filter(|m| m.verdict() == Some(Verdict::Better))
            .min_by(by_ratio)
            .cloned();
        let baseline = has_baseline.then(|| Measured {
            name: BASELINE.to_string(),
            ratio: 1.0,
            interval: None,
        });
        let lowest = measured
            .iter()
            .chain(baseline.as_ref())
            .min_by(by_ratio)
            .cloned();
        Answer {
            spp,
            runs,
            has_baseline,
            paper,
            best,
            lowest,
        }
    }

    /// Whether the claim is reproduced, refuted or left open, in words.
    fn verdict(&self) -> &'static str {
        match self.paper.as_ref().map(Measured::verdict) {
            None => "not tested by this run",
            Some(None) => "not decided by a single run",
            Some(Some(Verdict::Better)) => "reproduced",
            Some(Some(Verdict::Worse)) => "not reproduced",
            Some(Some(Verdict::NotDistinguishable)) => "not shown",
        }
    }

    /// What the paper's sampler measured, as a sentence.
    fn measured_sentence(&self) -> String {
        let Some(p) = &self.paper else {
            return format!(
                "This run cannot test it: it needs `{BASELINE}` and `paper` or `paper-repro` among its samplers."
            );
        };
        let meaning = match p.verdict() {
            Some(Verdict::Better) => "lower error than Sobol's, with 95 % confidence",
            Some(Verdict::Worse) => "higher error than Sobol's, with 95 % confidence",
            Some(Verdict::NotDistinguishable) => {
                "not distinguishable from Sobol's (the interval contains 1)"
            }
            None => "a single run gives no interval",
        };
        let seeds = if self.runs == 1 {
            "one seed".to_string()
        } else {
            format!("{} paired seeds", self.runs)
        };
        format!(
            "Measured here: `{}` has {} Sobol's relMSE at {} spp ({seeds}): {meaning}.",
            p.name,
            p.marked_cell(),
            self.spp
        )
    }

    fn best_sentence(&self) -> String {
        match (&self.best, &self.lowest) {
            (Some(b), _) => format!(
                "Best sampler: `{}`, {} Sobol's relMSE.",
                b.name,
                b.marked_cell()
            ),
            (None, Some(l)) if l.name == BASELINE => {
                format!("Best sampler: `{BASELINE}` itself; no other sampler has a lower relMSE.")
            }
            (None, Some(l)) => format!(
                "No sampler has a lower relMSE than `{BASELINE}` with 95 % confidence; the lowest is `{}`, {}.",
                l.name,
                l.cell()
            ),
            (None, None) => format!("No sampler can be compared with `{BASELINE}` in this run."),
        }
    }

    /// The report's first section.
    pub fn markdown(&self) -> String {
        format!(
            "## Answer\n\n\
The paper (Song & Ro 2019, \"A Method for Better Quality with Improved Sample Sequence in 3D Rendering\") \
claims that permuting the binary digits of Sobol's generator matrices gives about the same render time and \
{:.1} % of Sobol's error at {PAPER_SPP} spp (8 % less). **The claim is {} by this run.** {} {}\n\n\
Ratios are of linear relMSE to `{BASELINE}` (pbrt-v3's global Sobol, the paper's baseline), the geometric mean \
of the per-seed ratios with its 95 % interval; below 1 is less error than Sobol. Bold in the tables below marks \
a ratio whose interval excludes 1.\n\n",
            100.0 * PAPER_CLAIMED_RATIO,
            self.verdict(),
            self.measured_sentence(),
            self.best_sentence()
        )
    }

    /// The answer for `results.json`: the claim, the verdict, the paper's
    /// sampler and the best sampler with their ratios and intervals, and
    /// [`Answer::line`].
    pub fn json(&self) -> serde_json::Value {
        let measured = |m: &Option<Measured>| {
            m.as_ref().map(|m| {
                serde_json::json!({
                    "sampler": m.name,
                    "ratio": m.ratio,
                    "ci95": m.interval.map(|(ci, _)| ci),
                })
            })
        };
        serde_json::json!({
            "claimed_ratio": PAPER_CLAIMED_RATIO,
            "claimed_spp": PAPER_SPP,
            "verdict": self.verdict(),
            "paper": measured(&self.paper),
            "best": measured(&self.best),
            "line": self.line(),
        })
    }

    /// One line for the end of the command's output.
    pub fn line(&self) -> String {
        let claim = format!(
            "the paper's claim ({:.2}x Sobol's error at {PAPER_SPP} spp) is {}",
            PAPER_CLAIMED_RATIO,
            self.verdict()
        );
        let paper = self
            .paper
            .as_ref()
            .map(|p| format!(": {} has {} Sobol's relMSE", p.name, p.cell()))
            .unwrap_or_default();
        let best = match (&self.best, &self.lowest) {
            (Some(b), _) => format!("best sampler {} ({})", b.name, b.cell()),
            (None, Some(l)) => format!("no sampler beats {BASELINE} (lowest {})", l.name),
            (None, None) => String::new(),
        };
        let sep = if best.is_empty() { "" } else { "; " };
        format!("answer: {claim}{paper}{sep}{best}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::results::MetricStats;
    use crate::results::{result, results};
    use crate::stats::{Summary, paired_ratio};

    /// A sampler whose per-seed relMSE is `values` against the baseline's `base`.
    fn paired(name: &str, values: &[f64], base: &[f64]) -> SamplerResult {
        let mut s = result(name, values.iter().sum::<f64>() / values.len() as f64);
        s.statistics = vec![MetricStats {
            metric: "relmse",
            summary: Summary::of(values),
            ratio_to_baseline: paired_ratio(values, base),
        }];
        s
    }

    fn answer(results: &Results) -> Answer {
        Answer::from_runs(16, 3, results)
    }

    const BASE: [f64; 3] = [1.0, 2.0, 4.0];

    #[test]
    fn a_paper_sampler_with_twice_sobols_error_refutes_the_claim() {
        let r = results(vec![
            result("sobol", 2.0),
            paired("paper", &[2.0, 4.2, 7.9], &BASE),
            paired("sobol-xor", &[0.9, 1.8, 3.7], &BASE),
            paired("halton", &[0.5, 3.0, 4.0], &BASE),
        ]);
        let a = answer(&r);
        assert_eq!(a.paper.as_ref().unwrap().name, "paper");
        assert_eq!(a.verdict(), "not reproduced");
        assert_eq!(a.best.as_ref().unwrap().name, "sobol-xor");
        let md = a.markdown();
        assert!(md.starts_with("## Answer\n"), "{md}");
        assert!(md.contains("Song & Ro 2019"), "{md}");
        assert!(
            md.contains("**The claim is not reproduced by this run.**"),
            "{md}"
        );
        assert!(md.contains("higher error than Sobol's"), "{md}");
        assert!(md.contains("`paper` has **2.024x [1.868, 2.194]**"), "{md}");
        assert!(md.contains("Best sampler: `sobol-xor`"), "{md}");
        let json = a.json();
        assert_eq!(json["verdict"], "not reproduced");
        assert_eq!(json["paper"]["sampler"], "paper");
        assert_eq!(json["best"]["sampler"], "sobol-xor");
        assert!(json["paper"]["ci95"][0].as_f64().unwrap() > 1.0, "{json}");
        let line = a.line();
        assert!(
            line.starts_with("answer: the paper's claim (0.92x"),
            "{line}"
        );
        assert!(
            line.contains("is not reproduced: paper has 2.024x [1.868, 2.194]"),
            "{line}"
        );
        assert!(line.contains("best sampler sobol-xor (0.9"), "{line}");
        assert!(!line.contains('\n'));
    }

    #[test]
    fn a_lower_ratio_reproduces_and_an_interval_over_1_leaves_it_open() {
        let better = paired("paper-repro", &[0.9, 1.85, 3.6], &BASE);
        let a = answer(&results(vec![result("sobol", 2.0), better]));
        assert_eq!(a.verdict(), "reproduced");
        let open = paired("paper-repro", &[0.5, 3.0, 4.0], &BASE);
        let a = answer(&results(vec![result("sobol", 2.0), open]));
        assert_eq!(a.verdict(), "not shown");
        assert!(a.best.is_none());
        // Not distinguishable: the ratio is not bold.
        assert!(!a.markdown().contains("has **"), "{}", a.markdown());
        assert!(
            a.markdown().contains("No sampler has a lower relMSE"),
            "{a:?}"
        );
    }

    #[test]
    fn without_the_baseline_or_the_paper_the_run_says_it_cannot_answer() {
        let a = answer(&results(vec![result("independent", 1.0)]));
        assert_eq!(a.verdict(), "not tested by this run");
        assert!(a.markdown().contains("This run cannot test it"), "{a:?}");
        assert!(a.line().contains("not tested by this run"), "{}", a.line());
        let mut one = result("paper", 2.0);
        one.relmse_ratio_to_sobol = Some(2.0);
        let a = answer(&results(vec![result("sobol", 1.0), one]));
        assert_eq!(a.verdict(), "not decided by a single run");
        assert!(
            a.line().contains("2.000x (one run, no interval)"),
            "{}",
            a.line()
        );
        assert_eq!(a.lowest.as_ref().unwrap().name, "sobol");
    }
}
