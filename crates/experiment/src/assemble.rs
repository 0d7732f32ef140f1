//! From the units' renders to the experiment's [`Results`], report images
//! and report folder: the one code path of the one-machine run (which
//! renders each unit in-process as it is needed) and of `lowdisc experiment
//! merge` (which reads each unit's file). Both hand the renders to
//! [`assemble`] through a [`UnitSource`], in the order of the plan, and end
//! in [`report`] with an [`Outcome`]; the pieces of a cut render are joined
//! by [`join_cut`].

use std::path::PathBuf;

use anyhow::{Context, Result};
use lowdisc::catalog::SamplerName;
use lowdisc_image::RgbImage;

use crate::comparison::fill_statistics;
use crate::config::ExperimentConfig;
use crate::cut::samples;
use crate::metrics::{ErrorStats, MetricSummary, measure};
use crate::plan::{Plan, Target, Work, convergence_cut, convergence_spps, shares_reference};
use crate::progress::{Progress, Stage};
use crate::reference::reference;
use crate::report::answer::Answer;
use crate::results::{
    ConvPoint, Images, Results, RunResult, SamplerResult, SweepPoint, fill_ratios,
};
use crate::source::{Cursor, Measures, UnitSource, join_cut};
use crate::stats::paired::paired_ratio;
use crate::stats::{MeanSd, Summary, series_over_seeds};
use crate::sweep::{THRESHOLDS, pixel_discrepancy};

/// Assembles the units of `plan` from `source` ([`assemble`]) and writes
/// the report folder; `wall_time_s` gives the run's wall time when the
/// report is written. The one ending of both the one-machine and the
/// planned run.
pub fn report(
    plan: &Plan,
    measures: &Measures,
    source: &mut dyn UnitSource,
    observer: &dyn Progress,
    wall_time_s: &dyn Fn() -> f64,
) -> Result<Outcome> {
    let (results, images) = assemble(plan, measures, source, observer)?;
    let wall = wall_time_s();
    let files = crate::report::write_all(&plan.config, &results, &images, wall)?;
    Ok(Outcome::of(&plan.config, files, &results, wall, observer))
}

/// What a finished run leaves behind.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// Every file written to the report folder, then the reference files.
    pub files: Vec<PathBuf>,
    /// Wall time of the whole run, seconds.
    pub seconds: f64,
    /// The answer to the paper's question in one line
    /// ([`crate::report::answer::Answer::line`]).
    pub answer: String,
}

impl Outcome {
    /// The report's `files` and the reference files of `results`, after
    /// telling `observer` where the report is.
    pub(crate) fn of(
        config: &ExperimentConfig,
        mut files: Vec<PathBuf>,
        results: &Results,
        seconds: f64,
        observer: &dyn Progress,
    ) -> Outcome {
        files.push(results.reference.file.clone());
        if !shares_reference(config) {
            files.push(results.convergence_reference.file.clone());
        }
        observer.note(&format!(
            "report written to {}",
            config.out.join("report.md").display()
        ));
        Outcome {
            files,
            seconds,
            answer: Answer::of(config, results).line(),
        }
    }
}

/// The numbers and images of the experiment of `plan`, from the renders
/// of `source`, measured with `measures` (the scene's, at the plan's
/// resolution).
pub fn assemble(
    plan: &Plan,
    measures: &Measures,
    source: &mut dyn UnitSource,
    observer: &dyn Progress,
) -> Result<(Results, Images)> {
    let config = &plan.config;
    let mut cursor = Cursor::new(plan);
    let evaluator = &measures.evaluator;
    let (main, ref_info) = reference(plan, measures, Target::Main, &mut cursor, source, observer)?;
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
            let time_s = out.render_time_s;
            let image = out.into_image(unit)?;
            let m = measure(&image, &main)?;
            runs.push(RunResult {
                seed,
                time_s,
                linear: m.linear,
                srgb8: m.srgb8,
                quality: evaluator.measure(&image, &main)?,
            });
            match &first {
                None => first = Some(image),
                Some(f) => deterministic &= f.pixels() == image.pixels(),
            }
        }
        stage.end();
        samplers.push(sampler_result(name, runs, deterministic && config.runs > 1));
        renders.push(first.context("no runs")?);
    }
    fill_ratios(&mut samplers);
    fill_statistics(&mut samplers);
    let sobol = samplers
        .iter()
        .find(|s| s.name == SamplerName::Sobol.as_str());
    let baseline: Option<Vec<f64>> =
        sobol.map(|s| s.runs.iter().map(|r| r.linear.relmse).collect());
    let threshold_sweep = sweep(
        plan,
        &mut cursor,
        source,
        &main,
        baseline.as_deref(),
        observer,
    )?;
    let conv_own;
    let (conv_reference, conv_ref_info) = if shares_reference(config) {
        (&main, ref_info.clone())
    } else {
        let (image, info) = reference(
            plan,
            measures,
            Target::Convergence,
            &mut cursor,
            source,
            observer,
        )?;
        conv_own = image;
        (&conv_own, info)
    };
    // Spp 1, 2, 4, .. conv_max: 2 conv_max - 1 samples per pixel in all,
    // for each seed.
    let spps: Vec<u32> = convergence_spps(config).collect();
    let per_series = samples(config.conv_res, 2 * config.conv_max - 1);
    let seeds = u64::from(config.conv_seeds);
    let view = measures.view_at(config.conv_res)?;
    for (s, &name) in samplers.iter_mut().zip(&config.samplers) {
        let title = format!(
            "convergence of {}: 1 to {} spp at {}x{}, {} seed{}",
            s.name,
            config.conv_max,
            config.conv_res[0],
            config.conv_res[1],
            seeds,
            if seeds == 1 { "" } else { "s" }
        );
        let stage = Stage::begin(observer, &title, per_series * seeds);
        let mut by_seed = Vec::new();
        for seed in 0..seeds {
            let mut series = Vec::new();
            for &spp in &spps {
                let work = |piece| Work::Convergence {
                    sampler: name,
                    seed,
                    spp,
                    piece,
                };
                let cut = convergence_cut(config, spp);
                let (image, _) = join_cut(
                    &mut cursor,
                    source,
                    &stage,
                    cut,
                    &work,
                    &view,
                    config.spectral,
                )?;
                series.push(measure(&image, conv_reference)?.linear.relmse);
            }
            by_seed.push(series);
        }
        stage.end();
        set_convergence(s, &spps, &by_seed);
    }
    cursor.finish()?;
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

/// Sets `s`'s convergence series from `by_seed[seed][i]`, the relMSE of
/// seed `seed` at `spps[i]` samples per pixel ([`series_over_seeds`]).
fn set_convergence(s: &mut SamplerResult, spps: &[u32], by_seed: &[Vec<f64>]) {
    let fit = series_over_seeds(spps, by_seed);
    let interval = |c: &Summary| (c.n > 1).then_some(c.ci95);
    s.convergence = spps
        .iter()
        .zip(&fit.points)
        .enumerate()
        .map(|(i, (&spp, point))| ConvPoint {
            spp,
            relmse: point.mean,
            relmse_ci95: interval(point),
            relmse_seeds: by_seed.iter().map(|e| e[i]).collect(),
        })
        .collect();
    s.convergence_slope = (fit.slope.n > 0).then_some(fit.slope.mean);
    s.convergence_slope_ci95 = interval(&fit.slope);
    s.convergence_slopes = fit.slopes;
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
        convergence_slope_ci95: None,
        convergence_slopes: Vec::new(),
        convergence: Vec::new(),
    }
}

/// The threshold sweep: for each of [`THRESHOLDS`], the star discrepancy
/// of one pixel's film positions and the errors of the `paper-repro`
/// renders at that threshold (mean and sd over the seeds, and the paired
/// ratio to `baseline`, `sobol`'s linear relMSE per seed, if given).
fn sweep(
    plan: &Plan,
    cursor: &mut Cursor,
    source: &mut dyn UnitSource,
    reference: &RgbImage,
    baseline: Option<&[f64]>,
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
            let image = source.output(unit, &stage)?.into_image(unit)?;
            let m = measure(&image, reference)?;
            linear.push(m.linear.relmse);
            srgb8.push(m.srgb8.relmse);
        }
        out.push(SweepPoint {
            threshold,
            star_discrepancy: pixel_discrepancy(config.spp, threshold)?,
            relmse: MeanSd::of(&linear),
            srgb8_relmse: MeanSd::of(&srgb8),
            ratio_to_sobol: baseline.and_then(|b| paired_ratio(&linear, b)),
        });
    }
    stage.end();
    Ok(out)
}
