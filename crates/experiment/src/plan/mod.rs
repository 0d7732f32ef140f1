//! The experiment as a plan of independent units ([`Plan`]): every render
//! the one-machine run makes, listed in the order that run makes them, so
//! that any scheduler (a Slurm job array, GNU parallel, one loop) can run
//! them in any order and on any machine, and the assembly (`assemble`) can turn
//! their images into the same report.
//!
//! A unit is one render ([`Work`]): one piece of a reference that is not
//! cached, one run (sampler x seed; never split in samples per pixel, since
//! averaging seeds would change the estimator being measured), one render of
//! the threshold sweep (threshold x seed), or one piece of a point of a
//! convergence series (sampler x spp). A render of more camera samples than
//! the unit budget ([`ExperimentConfig::unit_budget`]) is cut
//! ([`crate::cut`]): a reference into bands of rows of tiles and, when one
//! row of tiles holds more than the budget, sample ranges; a convergence
//! point into bands only. Units need nothing from each other: the metrics
//! against the reference are computed when the units are assembled.
//!
//! The calibration render of the one-machine run only estimates its time;
//! a plan has no calibration (the per-unit wall times measured by the units
//! serve `lowdisc experiment status` instead).
//!
//! On disk the plan is `DIR/plan.json` ([`file`], with the schema).

pub mod file;

use anyhow::{Result, bail};
use lowdisc::catalog::SamplerName;
use lowdisc_render::render::RenderOptions;
use lowdisc_render::settings::{Given, SettingsLayer};

use crate::config::{ExperimentConfig, REF_SAMPLER, REF_SEED};
use crate::cut::{Cut, Piece, cut, sample_range};
use crate::sweep::THRESHOLDS;

/// Which reference a reference unit renders.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    /// The reference of the compared renders (`--res`, `--ref-spp`).
    Main,
    /// The reference of the convergence series (`--conv-res`, `--conv-ref-spp`).
    Convergence,
}

/// The render of one unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Work {
    /// One piece of a reference render ([`reference_cut`]).
    Reference {
        /// Which reference.
        target: Target,
        /// The piece.
        piece: Piece,
    },
    /// One run of a compared sampler.
    Run {
        /// The sampler.
        sampler: SamplerName,
        /// Its seed (`0..runs`).
        seed: u64,
    },
    /// One `paper-repro` render of the threshold sweep.
    Sweep {
        /// The threshold (one of [`THRESHOLDS`]).
        threshold: f64,
        /// The seed (`0..runs`).
        seed: u64,
    },
    /// One piece of a point of a sampler's convergence series
    /// ([`convergence_cut`]: bands only).
    Convergence {
        /// The sampler.
        sampler: SamplerName,
        /// The series' seed (`0..conv_seeds`).
        seed: u64,
        /// Samples per pixel (a power of two up to `conv_max`).
        spp: u32,
        /// The piece.
        piece: Piece,
    },
}

impl Work {
    /// A short description: `reference main band 2 of 5 range 1 of 8`,
    /// `run sobol seed 3`, `sweep threshold 0.5 seed 1`, `convergence sobol
    /// seed 2 64 spp` (a piece: `... band 1 of 2`).
    pub fn describe(&self) -> String {
        match *self {
            Work::Reference { target, piece } => {
                let name = match target {
                    Target::Main => "main",
                    Target::Convergence => "convergence",
                };
                format!("reference {name}{}", piece.describe())
            }
            Work::Run { sampler, seed } => format!("run {} seed {seed}", sampler.as_str()),
            Work::Sweep { threshold, seed } => format!("sweep threshold {threshold} seed {seed}"),
            Work::Convergence {
                sampler,
                seed,
                spp,
                piece,
            } => format!(
                "convergence {} seed {seed} {spp} spp{}",
                sampler.as_str(),
                piece.describe()
            ),
        }
    }

    /// The piece of a cut render this unit renders ([`Piece::WHOLE`] for a
    /// run or a sweep render).
    pub fn piece(&self) -> Piece {
        match *self {
            Work::Reference { piece, .. } | Work::Convergence { piece, .. } => piece,
            Work::Run { .. } | Work::Sweep { .. } => Piece::WHOLE,
        }
    }

    /// Whether the unit keeps its pixels' sums (a piece of a reference or
    /// of a convergence point, merged with the others) rather than an image.
    pub fn keeps_sums(&self) -> bool {
        matches!(self, Work::Reference { .. } | Work::Convergence { .. })
    }
}

/// One unit of a plan.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unit {
    /// Its position in the plan (`0..units.len()`).
    pub index: usize,
    /// What it renders.
    pub work: Work,
}

impl Unit {
    /// The resolution of its render.
    pub fn resolution(&self, config: &ExperimentConfig) -> [u32; 2] {
        match self.work {
            Work::Reference {
                target: Target::Convergence,
                ..
            }
            | Work::Convergence { .. } => config.conv_res,
            _ => config.resolution,
        }
    }

    /// What its render asks for beyond the experiment's own settings
    /// ([`ExperimentConfig::settings`]): its sampler, seed and spp, a sweep
    /// render's threshold, a piece's sample range (its window depends on
    /// the film, see [`Piece::window`]), the experiment's net for a
    /// compared sampler that reads one (never for a reference or the
    /// sweep), each named by where it comes from.
    pub fn settings(&self, config: &ExperimentConfig) -> SettingsLayer {
        let (sampler, seed, spp) = self.render(config);
        let threshold = match self.work {
            Work::Sweep { threshold, .. } => Some(threshold),
            _ => None,
        };
        let net = match self.work {
            Work::Run { .. } | Work::Convergence { .. } if sampler.takes_net() => Some(config.net),
            _ => None,
        };
        let piece = self.work.piece();
        let samples =
            (piece.cut.ranges > 1).then(|| sample_range(spp, piece.range, piece.cut.ranges));
        let from = format!("unit {} (`{}`)", self.index, self.work.describe());
        SettingsLayer {
            sampler: Some(Given::new(sampler, &from)),
            seed: Some(Given::new(seed, &from)),
            spp: Some(Given::new(spp, &from)),
            threshold: Given::maybe(threshold, &from),
            samples: Given::maybe(samples, &from),
            net: Given::maybe(net, "--net"),
            ..SettingsLayer::default()
        }
    }

    /// The render options of its render: the experiment's settings and
    /// [`Unit::settings`], resolved ([`ExperimentConfig::render_options`]).
    pub fn options(&self, config: &ExperimentConfig) -> Result<RenderOptions> {
        config.render_options(&self.settings(config))
    }

    /// The sampler, seed and samples per pixel of its render.
    fn render(&self, config: &ExperimentConfig) -> (SamplerName, u64, u32) {
        match self.work {
            Work::Reference { target, .. } => {
                (REF_SAMPLER, REF_SEED, reference_settings(config, target).1)
            }
            Work::Run { sampler, seed } => (sampler, seed, config.spp),
            Work::Sweep { seed, .. } => (SamplerName::PaperRepro, seed, config.spp),
            Work::Convergence {
                sampler, seed, spp, ..
            } => (sampler, seed, spp),
        }
    }

    /// The camera samples of its render (for a piece of a scene with a
    /// crop window, an upper bound).
    pub fn samples(&self, config: &ExperimentConfig) -> u64 {
        let spp = self.render(config).2;
        self.work.piece().samples(self.resolution(config), spp)
    }
}

/// The resolution and spp of reference `target`.
pub fn reference_settings(config: &ExperimentConfig, target: Target) -> ([u32; 2], u32) {
    match target {
        Target::Main => (config.resolution, config.ref_spp),
        Target::Convergence => (config.conv_res, config.conv_ref_spp),
    }
}

/// The cut of reference `target` ([`crate::cut::cut`] at the unit budget,
/// with sample ranges).
pub fn reference_cut(config: &ExperimentConfig, target: Target) -> Cut {
    let (resolution, spp) = reference_settings(config, target);
    cut(resolution, spp, config.unit_budget(), true)
}

/// The samples per pixel of a convergence series: 1, 2, 4, .. `conv_max`.
pub fn convergence_spps(config: &ExperimentConfig) -> impl Iterator<Item = u32> {
    (0..=config.conv_max.ilog2()).map(|k| 1 << k)
}

/// The cut of the convergence point at `spp` ([`crate::cut::cut`] at the
/// unit budget, in bands only: its image is the whole render's bit for bit).
pub fn convergence_cut(config: &ExperimentConfig, spp: u32) -> Cut {
    cut(config.conv_res, spp, config.unit_budget(), false)
}

/// Whether the convergence series use the main reference (same resolution
/// and spp), so that there is no second reference.
pub fn shares_reference(config: &ExperimentConfig) -> bool {
    config.conv_res == config.resolution && config.conv_ref_spp == config.ref_spp
}

/// Every unit of an experiment, in the order of the one-machine run: the
/// main reference unless `cached[0]`, each sampler's runs, the threshold
/// sweep, the convergence reference unless it is the main one or
/// `cached[1]`, and each sampler's convergence series.
pub fn units(config: &ExperimentConfig, cached: [bool; 2]) -> Vec<Unit> {
    let mut work = Vec::new();
    let reference = |work: &mut Vec<Work>, target| {
        for piece in reference_cut(config, target).pieces() {
            work.push(Work::Reference { target, piece });
        }
    };
    if !cached[0] {
        reference(&mut work, Target::Main);
    }
    for &sampler in &config.samplers {
        for seed in 0..u64::from(config.runs) {
            work.push(Work::Run { sampler, seed });
        }
    }
    for threshold in THRESHOLDS {
        for seed in 0..u64::from(config.runs) {
            work.push(Work::Sweep { threshold, seed });
        }
    }
    if !shares_reference(config) && !cached[1] {
        reference(&mut work, Target::Convergence);
    }
    for &sampler in &config.samplers {
        for seed in 0..u64::from(config.conv_seeds) {
            for spp in convergence_spps(config) {
                for piece in convergence_cut(config, spp).pieces() {
                    work.push(Work::Convergence {
                        sampler,
                        seed,
                        spp,
                        piece,
                    });
                }
            }
        }
    }
    work.into_iter()
        .enumerate()
        .map(|(index, work)| Unit { index, work })
        .collect()
}

/// An experiment cut into units.
#[derive(Debug, Clone)]
pub struct Plan {
    /// The experiment (its `out` is the plan's folder).
    pub config: ExperimentConfig,
    /// The hash of the scene's content ([`crate::subject::load`]).
    pub scene_hash: u64,
    /// Whether the main and the convergence reference were cached when the
    /// plan was made (cached references have no units).
    pub cached: [bool; 2],
    /// The units, in the order of the one-machine run.
    pub units: Vec<Unit>,
}

impl Plan {
    /// The plan of `config` for a scene of hash `scene_hash`.
    pub fn new(config: ExperimentConfig, scene_hash: u64, cached: [bool; 2]) -> Plan {
        let units = units(&config, cached);
        Plan {
            config,
            scene_hash,
            cached,
            units,
        }
    }

    /// The camera samples of every unit together.
    pub fn samples(&self) -> u64 {
        self.units.iter().map(|u| u.samples(&self.config)).sum()
    }

    /// Unit `index`, or an error naming the plan's range.
    pub fn unit(&self, index: usize) -> Result<&Unit> {
        match self.units.get(index) {
            Some(u) => Ok(u),
            None => bail!(
                "unit index {index} is out of range: the plan has {} units (0 to {})",
                self.units.len(),
                self.units.len().saturating_sub(1)
            ),
        }
    }
}

#[cfg(test)]
mod tests;
