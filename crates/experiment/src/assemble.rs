//! From the units' renders to the experiment's [`Results`] and report
//! images: the one code path of the one-machine run (which renders each
//! unit in-process as it is needed) and of `lowdisc experiment merge`
//! (which reads each unit's file). Both hand the renders to [`assemble`]
//! through a [`UnitSource`], in the order of the plan.

use anyhow::{Context, Result, bail};
use lowdisc::catalog::SamplerName;
use lowdisc_image::RgbImage;

use crate::comparison::fill_statistics;
use crate::metrics::{ErrorStats, MetricSummary, measure};
use crate::plan::{Plan, Target, Unit, Work, shares_reference};
use crate::progress::{Progress, Stage, samples};
use crate::quality::Evaluator;
use crate::reference::reference;
use crate::results::{
    ConvPoint, Images, Results, RunResult, SamplerResult, SweepPoint, fill_ratios,
};
use crate::stats::{MeanSd, log_log_slope};
use crate::sweep::{THRESHOLDS, pixel_discrepancy};

/// The render of one unit.
#[derive(Debug, Clone)]
pub struct UnitOutput {
    /// The image.
    pub image: RgbImage,
    /// The render's time in seconds (what `results.json` reports).
    pub render_time_s: f64,
}

/// Where [`assemble`] gets each unit's render from. `output` reports the
/// render's samples to `stage` (by [`Stage::finished_render`]).
pub trait UnitSource {
    /// The render of `unit`.
    fn output(&mut self, unit: &Unit, stage: &Stage) -> Result<UnitOutput>;
}

/// The plan's units in order; each step of the assembly takes the next one
/// and checks that it is the render it expects.
pub(crate) struct Cursor<'a> {
    units: std::slice::Iter<'a, Unit>,
}

impl<'a> Cursor<'a> {
    /// The unit of `work`, the next in the plan.
    pub(crate) fn next(&mut self, work: Work) -> Result<&'a Unit> {
        match self.units.next() {
            Some(u) if u.work == work => Ok(u),
            Some(u) => bail!(
                "unit {} is `{}`, expected `{}`",
                u.index,
                u.work.describe(),
                work.describe()
            ),
            None => bail!("the plan has no unit `{}`", work.describe()),
        }
    }
}

/// The numbers and images of the experiment of `plan`, from the renders
/// of `source`, measured with `evaluator` (the scene's at the plan's
/// resolution).
pub fn assemble(
    plan: &Plan,
    evaluator: &Evaluator,
    source: &mut dyn UnitSource,
    observer: &dyn Progress,
) -> Result<(Results, Images)> {
    let config = &plan.config;
    let mut cursor = Cursor {
        units: plan.units.iter(),
    };
    let (main, ref_info) = reference(plan, Target::Main, &mut cursor, source, observer)?;
    let mut samplers = Vec::new();
    let mut renders = Vec::new();
    let per_sampler = u64::from(config.runs) * samples(config.resolution, config.spp);
    for (k, &name) in config.samplers.iter().enumerate() {
        let title = format!(
            "[{}/{}] {}: {} runs at {} spp",
            k + 1,
            config.samplers.len(),
            name.as_str(),
            config.runs,
            config.spp
        );
        let stage = Stage::begin(observer, &title, per_sampler);
        let mut runs = Vec::new();
        let mut first: Option<RgbImage> = None;
        let mut deterministic = true;
        for seed in 0..u64::from(config.runs) {
            let unit = cursor.next(Work::Run {
                sampler: name,
                seed,
            })?;
            let out = source.output(unit, &stage)?;
            let m = measure(&out.image, &main)?;
            runs.push(RunResult {
                seed,
                time_s: out.render_time_s,
                linear: m.linear,
                srgb8: m.srgb8,
                quality: evaluator.measure(&out.image, &main)?,
            });
            match &first {
                None => first = Some(out.image),
                Some(f) => deterministic &= f.pixels() == out.image.pixels(),
            }
        }
        stage.end();
        samplers.push(sampler_result(name, runs, deterministic && config.runs > 1));
        renders.push(first.context("no runs")?);
    }
    fill_ratios(&mut samplers);
    fill_statistics(&mut samplers);
    let threshold_sweep = sweep(plan, &mut cursor, source, &main, observer)?;
    let conv_own;
    let (conv_reference, conv_ref_info) = if shares_reference(config) {
        (&main, ref_info.clone())
    } else {
        let (image, info) = reference(plan, Target::Convergence, &mut cursor, source, observer)?;
        conv_own = image;
        (&conv_own, info)
    };
    // Spp 1, 2, 4, .. conv_max: 2 conv_max - 1 samples per pixel in all.
    let per_series = samples(config.conv_res, 2 * config.conv_max - 1);
    for (s, &name) in samplers.iter_mut().zip(&config.samplers) {
        let title = format!(
            "convergence of {}: 1 to {} spp at {}x{}",
            s.name, config.conv_max, config.conv_res[0], config.conv_res[1]
        );
        let stage = Stage::begin(observer, &title, per_series);
        let mut series = Vec::new();
        let mut spp = 1;
        while spp <= config.conv_max {
            let unit = cursor.next(Work::Convergence { sampler: name, spp })?;
            let out = source.output(unit, &stage)?;
            series.push(ConvPoint {
                spp,
                relmse: measure(&out.image, conv_reference)?.linear.relmse,
            });
            spp *= 2;
        }
        stage.end();
        let pts: Vec<[f64; 2]> = series
            .iter()
            .map(|c| [f64::from(c.spp), c.relmse])
            .collect();
        s.convergence_slope = log_log_slope(&pts);
        s.convergence = series;
    }
    if let Some(u) = cursor.units.next() {
        bail!("unit {} (`{}`) is not used", u.index, u.work.describe());
    }
    let results = Results {
        samplers,
        reference: ref_info,
        convergence_reference: conv_ref_info,
        threshold_sweep,
        kept_fraction: evaluator.kept_fraction(),
    };
    let images = Images {
        reference: main,
        renders,
    };
    Ok((results, images))
}

/// The summary of one sampler's runs (ratios and statistics are filled in
/// later, from every sampler).
fn sampler_result(name: SamplerName, runs: Vec<RunResult>, deterministic: bool) -> SamplerResult {
    let linear: Vec<ErrorStats> = runs.iter().map(|r| r.linear).collect();
    let srgb8: Vec<ErrorStats> = runs.iter().map(|r| r.srgb8).collect();
    let lin = MetricSummary::of(&linear);
    let times: Vec<f64> = runs.iter().map(|r| r.time_s).collect();
    SamplerResult {
        name: name.as_str().to_string(),
        description: name.description().to_string(),
        deterministic,
        time_s: MeanSd::of(&times),
        mse: lin.mse,
        relmse: lin.relmse,
        rmse: lin.rmse,
        mae: lin.mae,
        srgb8: MetricSummary::of(&srgb8),
        relmse_ratio_to_sobol: None,
        relmse_ratio_interval: None,
        statistics: Vec::new(),
        runs,
        convergence_slope: None,
        convergence: Vec::new(),
    }
}

/// The threshold sweep: for each of [`THRESHOLDS`], the star discrepancy
/// of one pixel's film positions and the errors of the `paper-repro`
/// renders at that threshold (mean and sd over the seeds).
fn sweep(
    plan: &Plan,
    cursor: &mut Cursor,
    source: &mut dyn UnitSource,
    reference: &RgbImage,
    observer: &dyn Progress,
) -> Result<Vec<SweepPoint>> {
    let config = &plan.config;
    let title = format!(
        "threshold sweep: paper-repro at {} thresholds, {} runs each",
        THRESHOLDS.len(),
        config.runs
    );
    let renders = (THRESHOLDS.len() as u64) * u64::from(config.runs);
    let stage = Stage::begin(
        observer,
        &title,
        renders * samples(config.resolution, config.spp),
    );
    let mut out = Vec::new();
    for threshold in THRESHOLDS {
        let mut linear = Vec::new();
        let mut srgb8 = Vec::new();
        for seed in 0..u64::from(config.runs) {
            let unit = cursor.next(Work::Sweep { threshold, seed })?;
            let rendered = source.output(unit, &stage)?;
            let m = measure(&rendered.image, reference)?;
            linear.push(m.linear.relmse);
            srgb8.push(m.srgb8.relmse);
        }
        out.push(SweepPoint {
            threshold,
            star_discrepancy: pixel_discrepancy(config.spp, threshold)?,
            relmse: MeanSd::of(&linear),
            srgb8_relmse: MeanSd::of(&srgb8),
        });
    }
    stage.end();
    Ok(out)
}
