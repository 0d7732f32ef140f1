//! The experiment as a plan of independent units ([`Plan`]): every render
//! the one-machine run makes, listed in the order that run makes them, so
//! that any scheduler (a Slurm job array, GNU parallel, one loop) can run
//! them in any order and on any machine, and [`crate::assemble`] can turn
//! their images into the same report.
//!
//! A unit is one render ([`Work`]): one band of rows of a reference that
//! is not cached ([`reference_parts`]), one run (sampler x seed; never split in samples per pixel, since
//! averaging seeds would change the estimator being measured), one render of
//! the threshold sweep (threshold x seed), or one point of a convergence
//! series (sampler x spp). Units need nothing from each other: the metrics
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

use crate::config::{ExperimentConfig, REF_SAMPLER, REF_SEED};
use crate::progress::samples;
use crate::run::options;
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
    /// One band of rows of a reference render ([`band_rows`]).
    Reference {
        /// Which reference.
        target: Target,
        /// The band, `0..parts`, from the top.
        part: u32,
        /// The number of bands of this reference ([`reference_parts`]).
        parts: u32,
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
    /// One point of a sampler's convergence series (seed 0).
    Convergence {
        /// The sampler.
        sampler: SamplerName,
        /// Samples per pixel (a power of two up to `conv_max`).
        spp: u32,
    },
}

impl Work {
    /// A short description: `reference main`, `run sobol seed 3`,
    /// `sweep threshold 0.5 seed 1`, `convergence sobol 64 spp`.
    pub fn describe(&self) -> String {
        match *self {
            Work::Reference {
                target,
                part,
                parts,
            } => {
                let name = match target {
                    Target::Main => "main",
                    Target::Convergence => "convergence",
                };
                format!("reference {name} part {} of {parts}", part + 1)
            }
            Work::Run { sampler, seed } => format!("run {} seed {seed}", sampler.as_str()),
            Work::Sweep { threshold, seed } => format!("sweep threshold {threshold} seed {seed}"),
            Work::Convergence { sampler, spp } => {
                format!("convergence {} {spp} spp", sampler.as_str())
            }
        }
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

    /// The render options of its render.
    pub fn options(&self, config: &ExperimentConfig) -> RenderOptions {
        match self.work {
            Work::Reference { target, .. } => {
                let spp = reference_settings(config, target).1;
                options(config, REF_SAMPLER, REF_SEED, spp)
            }
            Work::Run { sampler, seed } => options(config, sampler, seed, config.spp),
            Work::Sweep { threshold, seed } => {
                let mut o = options(config, SamplerName::PaperRepro, seed, config.spp);
                o.sampler.threshold = threshold;
                o
            }
            Work::Convergence { sampler, spp } => options(config, sampler, 0, spp),
        }
    }

    /// The camera samples of its render (for a reference band of a scene
    /// with a crop window, an upper bound).
    pub fn samples(&self, config: &ExperimentConfig) -> u64 {
        let [w, h] = self.resolution(config);
        let rows = match self.work {
            Work::Reference { part, parts, .. } => {
                let [y0, y1] = band_rows(h, part, parts);
                y1 - y0
            }
            _ => h,
        };
        samples([w, rows], self.options(config).sampler.spp)
    }
}

/// The resolution and spp of reference `target`.
pub fn reference_settings(config: &ExperimentConfig, target: Target) -> ([u32; 2], u32) {
    match target {
        Target::Main => (config.resolution, config.ref_spp),
        Target::Convergence => (config.conv_res, config.conv_ref_spp),
    }
}

/// The rows of a render's tiles ([`crate::run::options`]' tile size): the
/// bands of a reference are whole rows of tiles.
pub const BAND_ROWS: u32 = 16;

/// The number of bands reference `target` is cut into: enough that no band
/// has more samples than the largest other unit (a run, or the last point of
/// a convergence series), at most one band per row of tiles. The bands'
/// pixels are those of the whole render, bit for bit (the tile grid and
/// the tiles' sampler streams are the whole film's); the bands are not
/// split in samples per pixel, whose sums would merge only up to rounding.
pub fn reference_parts(config: &ExperimentConfig, target: Target) -> u32 {
    let ([w, h], spp) = reference_settings(config, target);
    let largest = samples(config.resolution, config.spp)
        .max(samples(config.conv_res, config.conv_max))
        .max(1);
    let wanted = samples([w, h], spp).div_ceil(largest);
    let tile_rows = h.div_ceil(BAND_ROWS);
    wanted.clamp(1, u64::from(tile_rows.max(1))) as u32
}

/// The rows `[y0, y1)` of band `part` of `parts` of an image `height` rows
/// high (counted from the top of the film's pixel bounds): consecutive
/// whole rows of tiles, as equal in number as they can be.
pub fn band_rows(height: u32, part: u32, parts: u32) -> [u32; 2] {
    let tile_rows = u64::from(height.div_ceil(BAND_ROWS));
    let parts = u64::from(parts.max(1));
    let edge = |p: u64| ((p * tile_rows / parts) as u32 * BAND_ROWS).min(height);
    [edge(u64::from(part)), edge(u64::from(part) + 1)]
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
        let parts = reference_parts(config, target);
        for part in 0..parts {
            work.push(Work::Reference {
                target,
                part,
                parts,
            });
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
        let mut spp = 1;
        while spp <= config.conv_max {
            work.push(Work::Convergence { sampler, spp });
            spp *= 2;
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
    /// The hash of the scene's content ([`crate::run`]'s scene loading).
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
