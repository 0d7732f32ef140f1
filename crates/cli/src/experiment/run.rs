//! Running the experiment: the scene, the cached reference, the repeated
//! renders, the convergence series and the threshold sweep, collected into
//! [`Results`] and handed to [`super::report`].

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Context, Result};
use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc_image::{ErrorStats, RgbImage, error_metrics};
use lowdisc_render::integrator::PathIntegrator;
use lowdisc_render::render::{NoProgress, RenderOptions, render};
use lowdisc_render::scene::{Scene, load_scene_file};
use serde::Serialize;

use super::stats::{FNV_OFFSET, MeanSd, fnv1a, log_log_slope, ratio};
use super::{ExperimentConfig, REF_SAMPLER, REF_SEED, report, scene};

/// One render's numbers.
#[derive(Debug, Clone, Serialize)]
pub struct RunResult {
    /// Seed.
    pub seed: u64,
    /// Render time in seconds.
    pub time_s: f64,
    /// Errors on linear radiance.
    pub linear: ErrorStats,
    /// Errors on 8-bit sRGB.
    pub srgb8: ErrorStats,
}

/// Mean and sd of the four metrics.
#[derive(Debug, Clone, Serialize)]
pub struct MetricSummary {
    /// MSE.
    pub mse: MeanSd,
    /// relMSE.
    pub relmse: MeanSd,
    /// RMSE.
    pub rmse: MeanSd,
    /// MAE.
    pub mae: MeanSd,
}

impl MetricSummary {
    /// Aggregates one metric family over runs.
    pub fn of(stats: &[ErrorStats]) -> MetricSummary {
        let col = |f: fn(&ErrorStats) -> f64| MeanSd::of(&stats.iter().map(f).collect::<Vec<_>>());
        MetricSummary {
            mse: col(|s| s.mse),
            relmse: col(|s| s.relmse),
            rmse: col(|s| s.rmse),
            mae: col(|s| s.mae),
        }
    }
}

/// One point of a convergence series.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct ConvPoint {
    /// Samples per pixel.
    pub spp: u32,
    /// relMSE on linear radiance.
    pub relmse: f64,
}

/// Everything measured for one sampler.
#[derive(Debug, Clone, Serialize)]
pub struct SamplerResult {
    /// Command-line name.
    pub name: String,
    /// One-line description.
    pub description: String,
    /// Whether every run gave a bit-identical image (runs differ only in time).
    pub deterministic: bool,
    /// Render time, seconds.
    pub time_s: MeanSd,
    /// Linear MSE.
    pub mse: MeanSd,
    /// Linear relMSE.
    pub relmse: MeanSd,
    /// Linear RMSE.
    pub rmse: MeanSd,
    /// Linear MAE.
    pub mae: MeanSd,
    /// The same on 8-bit sRGB.
    pub srgb8: MetricSummary,
    /// Mean linear relMSE over `sobol`'s.
    pub relmse_ratio_to_sobol: Option<f64>,
    /// Every run.
    pub runs: Vec<RunResult>,
    /// relMSE against spp (seed 0).
    pub convergence: Vec<ConvPoint>,
    /// Fitted log-log slope of the convergence series.
    pub convergence_slope: Option<f64>,
}

/// One threshold of the sweep.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct SweepPoint {
    /// Threshold.
    pub threshold: f64,
    /// Star discrepancy of dimensions 0-1 of one pixel's samples.
    pub star_discrepancy: f64,
}

/// The reference render.
#[derive(Debug, Clone, Serialize)]
pub struct ReferenceInfo {
    /// Cache file.
    pub file: PathBuf,
    /// Whether it came from the cache.
    pub cached: bool,
    /// Render time (0 when cached).
    pub time_s: f64,
}

/// All results of one experiment.
#[derive(Debug, Clone, Serialize)]
pub struct Results {
    /// Samplers, in the order given.
    pub samplers: Vec<SamplerResult>,
    /// Reference.
    pub reference: ReferenceInfo,
    /// Threshold sweep of the paper's method.
    pub threshold_sweep: Vec<SweepPoint>,
}

/// Images kept for the report.
pub struct Images {
    /// Reference.
    pub reference: RgbImage,
    /// Seed-0 render of each sampler.
    pub renders: Vec<RgbImage>,
}

fn progress(config: &ExperimentConfig, msg: &str) {
    if !config.quiet {
        eprintln!("{msg}");
    }
}

fn load(config: &ExperimentConfig) -> Result<(Scene, u64)> {
    let mut hash = FNV_OFFSET;
    let sky = match &config.envmap {
        Some(p) => {
            hash = fnv1a(
                hash,
                &std::fs::read(p).with_context(|| format!("cannot read `{}`", p.display()))?,
            );
            Some(
                lowdisc_image::read_image(p)
                    .with_context(|| format!("cannot read `{}`", p.display()))?,
            )
        }
        None => None,
    };
    let scene = match &config.scene {
        None => {
            hash = fnv1a(hash, scene::SCENE_ID.as_bytes());
            scene::showroom(config.resolution, sky.as_ref())?
        }
        Some(path) => {
            hash = fnv1a(
                hash,
                &std::fs::read(path)
                    .with_context(|| format!("cannot read `{}`", path.display()))?,
            );
            let mut s = load_scene_file(path)?;
            s.set_resolution(config.resolution)?;
            s
        }
    };
    Ok((scene, hash))
}

fn options(config: &ExperimentConfig, sampler: SamplerName, seed: u64, spp: u32) -> RenderOptions {
    RenderOptions {
        sampler,
        seed,
        spp,
        integrator: PathIntegrator {
            max_depth: config.max_depth,
            ..PathIntegrator::default()
        },
        threads: config.threads,
        tile_size: 16,
    }
}

/// The reference, from the cache when present.
fn reference(
    config: &ExperimentConfig,
    scene: &Scene,
    scene_hash: u64,
) -> Result<(RgbImage, ReferenceInfo)> {
    let key = format!(
        "{scene_hash:016x} {:?} ref_spp={} sampler={} seed={} depth={} v{}",
        config.resolution,
        config.ref_spp,
        REF_SAMPLER.as_str(),
        REF_SEED,
        config.max_depth,
        env!("CARGO_PKG_VERSION")
    );
    let hash = fnv1a(FNV_OFFSET, key.as_bytes());
    let dir = cache_dir(&config.out);
    let file = dir.join(format!("ref-{hash:016x}.pfm"));
    if file.is_file() {
        if let Ok(image) = lowdisc_image::read_image(&file) {
            progress(
                config,
                &format!("reusing cached reference {}", file.display()),
            );
            return Ok((
                image,
                ReferenceInfo {
                    file,
                    cached: true,
                    time_s: 0.0,
                },
            ));
        }
    }
    progress(
        config,
        &format!(
            "rendering reference: {} spp with {}",
            config.ref_spp,
            REF_SAMPLER.as_str()
        ),
    );
    let out = render(
        scene,
        &options(config, REF_SAMPLER, REF_SEED, config.ref_spp),
        &NoProgress,
    )?;
    std::fs::create_dir_all(&dir).with_context(|| format!("cannot create `{}`", dir.display()))?;
    lowdisc_image::write_pfm(&file, &out.image)?;
    progress(config, &format!("cached reference in {}", file.display()));
    Ok((
        out.image,
        ReferenceInfo {
            file,
            cached: false,
            time_s: out.stats.time.as_secs_f64(),
        },
    ))
}

/// `<parent of out>/lowdisc-ref-cache`.
pub fn cache_dir(out: &Path) -> PathBuf {
    out.parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."))
        .join("lowdisc-ref-cache")
}

fn measure_sampler(
    config: &ExperimentConfig,
    scene: &Scene,
    name: SamplerName,
    reference: &RgbImage,
) -> Result<(SamplerResult, RgbImage)> {
    let mut runs = Vec::new();
    let mut first: Option<RgbImage> = None;
    let mut deterministic = true;
    for seed in 0..u64::from(config.runs) {
        let out = render(scene, &options(config, name, seed, config.spp), &NoProgress)?;
        let m = error_metrics(&out.image, reference)?;
        runs.push(RunResult {
            seed,
            time_s: out.stats.time.as_secs_f64(),
            linear: m.linear,
            srgb8: m.srgb8,
        });
        match &first {
            None => first = Some(out.image),
            Some(f) => deterministic &= f.pixels() == out.image.pixels(),
        }
    }
    let mut convergence = Vec::new();
    let mut spp = 1;
    while spp <= config.conv_max {
        let out = render(scene, &options(config, name, 0, spp), &NoProgress)?;
        convergence.push(ConvPoint {
            spp,
            relmse: error_metrics(&out.image, reference)?.linear.relmse,
        });
        spp *= 2;
    }
    let pts: Vec<[f64; 2]> = convergence
        .iter()
        .map(|c| [f64::from(c.spp), c.relmse])
        .collect();
    let linear: Vec<ErrorStats> = runs.iter().map(|r| r.linear).collect();
    let srgb8: Vec<ErrorStats> = runs.iter().map(|r| r.srgb8).collect();
    let lin = MetricSummary::of(&linear);
    let times: Vec<f64> = runs.iter().map(|r| r.time_s).collect();
    let result = SamplerResult {
        name: name.as_str().to_string(),
        description: name.description().to_string(),
        deterministic: deterministic && config.runs > 1,
        time_s: MeanSd::of(&times),
        mse: lin.mse,
        relmse: lin.relmse,
        rmse: lin.rmse,
        mae: lin.mae,
        srgb8: MetricSummary::of(&srgb8),
        relmse_ratio_to_sobol: None,
        runs,
        convergence_slope: log_log_slope(&pts),
        convergence,
    };
    Ok((result, first.context("no runs")?))
}

/// Fills every sampler's `relmse_ratio_to_sobol` from the `sobol` entry.
pub fn fill_ratios(samplers: &mut [SamplerResult]) {
    let base = samplers
        .iter()
        .find(|s| s.name == "sobol")
        .map(|s| s.relmse.mean);
    for s in samplers {
        s.relmse_ratio_to_sobol = ratio(s.relmse.mean, base);
    }
}

/// Star discrepancy of one pixel's `spp` film positions from the paper's
/// sampler (permuting dimensions 0-1 too) at each threshold.
fn threshold_sweep(spp: u32) -> Result<Vec<SweepPoint>> {
    [0.0, 0.25, 0.5, 0.75, 0.9, 1.0]
        .into_iter()
        .map(|t| {
            let mut c = SamplerConfig::new(SamplerName::PaperRepro);
            c.threshold = t;
            c.paper_all_dims = true;
            c.spp = spp;
            c.resolution = [1, 1];
            let pts = crate::figure::film_positions(&c)?;
            let set = lowdisc_metrics::PointSet::from_rows(&pts)?;
            Ok(SweepPoint {
                threshold: t,
                star_discrepancy: lowdisc_metrics::star_discrepancy(&set)?,
            })
        })
        .collect()
}

/// Runs the experiment and writes the report folder.
pub fn run(config: &ExperimentConfig) -> Result<()> {
    let start = Instant::now();
    std::fs::create_dir_all(&config.out)
        .with_context(|| format!("cannot create `{}`", config.out.display()))?;
    let (scene, scene_hash) = load(config)?;
    let (reference, ref_info) = reference(config, &scene, scene_hash)?;
    let mut samplers = Vec::new();
    let mut renders = Vec::new();
    for (k, &name) in config.samplers.iter().enumerate() {
        progress(
            config,
            &format!(
                "[{}/{}] {}: {} runs at {} spp",
                k + 1,
                config.samplers.len(),
                name.as_str(),
                config.runs,
                config.spp
            ),
        );
        let (r, image) = measure_sampler(config, &scene, name, &reference)?;
        samplers.push(r);
        renders.push(image);
    }
    fill_ratios(&mut samplers);
    let results = Results {
        samplers,
        reference: ref_info,
        threshold_sweep: threshold_sweep(config.spp)?,
    };
    let images = Images { reference, renders };
    report::write_all(config, &results, &images, start.elapsed().as_secs_f64())?;
    progress(
        config,
        &format!(
            "report written to {}",
            config.out.join("report.md").display()
        ),
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use lowdisc_image::RgbImage;

    fn result(name: &str, relmse: f64) -> SamplerResult {
        let m = MeanSd {
            mean: relmse,
            sd: 0.0,
        };
        SamplerResult {
            name: name.into(),
            description: String::new(),
            deterministic: false,
            time_s: m,
            mse: m,
            relmse: m,
            rmse: m,
            mae: m,
            srgb8: MetricSummary {
                mse: m,
                relmse: m,
                rmse: m,
                mae: m,
            },
            relmse_ratio_to_sobol: None,
            runs: Vec::new(),
            convergence: Vec::new(),
            convergence_slope: None,
        }
    }

    #[test]
    fn ratios_are_to_sobol_and_absent_without_it() {
        let mut v = vec![
            result("paper", 0.919),
            result("sobol", 1.0),
            result("zsobol", 0.5),
        ];
        fill_ratios(&mut v);
        assert_eq!(v[0].relmse_ratio_to_sobol, Some(0.919));
        assert_eq!(v[1].relmse_ratio_to_sobol, Some(1.0));
        assert_eq!(v[2].relmse_ratio_to_sobol, Some(0.5));
        let mut w = vec![result("paper", 0.919)];
        fill_ratios(&mut w);
        assert_eq!(w[0].relmse_ratio_to_sobol, None);
    }

    #[test]
    fn summary_of_two_hand_computed_runs() {
        // Test images against a reference of 1s: errors 0.5 and 1.5 in every
        // channel of a 1x1 image, then 1.0 everywhere.
        let r = RgbImage::filled(1, 2, [1.0; 3]).unwrap();
        let a = RgbImage::from_pixels(1, 2, vec![[1.5; 3], [2.5; 3]]).unwrap();
        let b = RgbImage::filled(1, 2, [2.0; 3]).unwrap();
        let ea = error_metrics(&a, &r).unwrap().linear;
        let eb = error_metrics(&b, &r).unwrap().linear;
        // a: MSE (0.25 + 2.25)/2 = 1.25, MAE 1.0; b: MSE 1, MAE 1.
        assert!((ea.mse - 1.25).abs() < 1e-12 && (ea.mae - 1.0).abs() < 1e-12);
        assert!((eb.mse - 1.0).abs() < 1e-12);
        // relMSE of b: 1 / (1 + 0.01).
        assert!((eb.relmse - 1.0 / 1.01).abs() < 1e-9);
        let s = MetricSummary::of(&[ea, eb]);
        assert!((s.mse.mean - 1.125).abs() < 1e-12);
        // sd of {1.25, 1}: |1.25 - 1| / sqrt(2).
        assert!((s.mse.sd - 0.25 / 2f64.sqrt()).abs() < 1e-12);
        assert!((s.mae.mean - 1.0).abs() < 1e-12 && s.mae.sd.abs() < 1e-12);
    }
}
