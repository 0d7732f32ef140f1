//! Running the experiment: the scene, the repeated renders of every sampler
//! and their convergence series, collected with the reference and the
//! threshold sweep into [`Results`] and handed to [`crate::report`].

use std::path::PathBuf;
use std::time::Instant;

use anyhow::{Context, Result};
use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc_image::{ImageFormat, ReadOptions, RgbImage, decode_image};
use lowdisc_render::integrator::PathIntegrator;
use lowdisc_render::pbrt::{LoadOptions, load_pbrt_scene};
use lowdisc_render::render::{RenderOptions, render};
use lowdisc_render::scene::Scene;

use crate::comparison::fill_statistics;
use crate::config::ExperimentConfig;
use crate::metrics::{ErrorStats, MetricSummary, measure};
use crate::plan::{calibrate, total_samples};
use crate::progress::{Progress, Stage, samples};
use crate::quality::Evaluator;
use crate::reference::{cache_file, reference as render_reference};
use crate::results::{ConvPoint, Images, Results, RunResult, SamplerResult, fill_ratios};
use crate::stats::{FNV_OFFSET, MeanSd, fnv1a, log_log_slope};
use crate::sweep::threshold_sweep;
use crate::{report, scene};

/// The scene and the hash of its content: the built-in scene's id or the
/// scene file's bytes (not the files it includes), and the environment
/// map's bytes. `--envmap` replaces the built-in sky, or every image-based
/// `infinite` light of a scene file (pbrt-v4 scenes often ship without
/// their environment map).
fn load(config: &ExperimentConfig, observer: &dyn Progress) -> Result<(Scene, u64)> {
    let mut hash = FNV_OFFSET;
    let read = |p: &std::path::Path| {
        std::fs::read(p).with_context(|| format!("cannot read `{}`", p.display()))
    };
    let envmap_bytes = match &config.envmap {
        Some(p) => Some((p, read(p)?)),
        None => None,
    };
    if let Some((_, bytes)) = &envmap_bytes {
        hash = fnv1a(hash, bytes);
    }
    let scene = match &config.scene {
        None if config.preset.is_some() => {
            let preset = config.preset.context("no preset")?;
            hash = fnv1a(hash, preset.id().as_bytes());
            preset.scene(config.resolution)?
        }
        None => {
            hash = fnv1a(hash, scene::SCENE_ID.as_bytes());
            // The sky is decoded from the bytes already read for the hash.
            let sky = match &envmap_bytes {
                Some((p, bytes)) => Some(
                    ImageFormat::detect(p, bytes)
                        .and_then(|f| decode_image(bytes, f, &ReadOptions::default()))
                        .with_context(|| format!("cannot read `{}`", p.display()))?,
                ),
                None => None,
            };
            scene::showroom(config.resolution, sky.as_ref())?
        }
        Some(path) => {
            hash = fnv1a(hash, &read(path)?);
            let options = LoadOptions {
                envmap_override: config.envmap.clone(),
            };
            let loaded = load_pbrt_scene(path, &options)
                .with_context(|| format!("cannot load scene `{}`", path.display()))?;
            for w in &loaded.warnings {
                observer.note(w);
            }
            let mut s = loaded.scene;
            s.set_resolution(config.resolution)?;
            s
        }
    };
    Ok((scene, hash))
}

/// The render options of one render of the experiment.
pub fn options(
    config: &ExperimentConfig,
    sampler: SamplerName,
    seed: u64,
    spp: u32,
) -> RenderOptions {
    RenderOptions {
        sampler: SamplerConfig {
            seed,
            spp,
            threshold: config.threshold,
            ..SamplerConfig::new(sampler)
        },
        integrator: PathIntegrator {
            max_depth: config.max_depth,
            ..PathIntegrator::default()
        },
        threads: config.threads,
        tile_size: 16,
        spectral: config.spectral,
    }
}

fn measure_sampler(
    config: &ExperimentConfig,
    scene: &Scene,
    name: SamplerName,
    reference: &RgbImage,
    evaluator: &Evaluator,
    stage: &Stage,
) -> Result<(SamplerResult, RgbImage)> {
    let mut runs = Vec::new();
    let mut first: Option<RgbImage> = None;
    let mut deterministic = true;
    for seed in 0..u64::from(config.runs) {
        let out = render(scene, &options(config, name, seed, config.spp), stage)?;
        stage.finished_render(out.stats.samples);
        let m = measure(&out.image, reference)?;
        runs.push(RunResult {
            seed,
            time_s: out.stats.time.as_secs_f64(),
            linear: m.linear,
            srgb8: m.srgb8,
            quality: evaluator.measure(&out.image, reference)?,
        });
        match &first {
            None => first = Some(out.image),
            Some(f) => deterministic &= f.pixels() == out.image.pixels(),
        }
    }
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
        relmse_ratio_interval: None,
        statistics: Vec::new(),
        runs,
        convergence_slope: None,
        convergence: Vec::new(),
    };
    Ok((result, first.context("no runs")?))
}

/// The convergence series of sampler `name` (seed 0, spp 1, 2, 4, ..
/// `conv_max`) against `reference`, and its fitted log-log slope.
fn convergence(
    config: &ExperimentConfig,
    scene: &Scene,
    name: SamplerName,
    reference: &RgbImage,
    stage: &Stage,
) -> Result<(Vec<ConvPoint>, Option<f64>)> {
    let mut series = Vec::new();
    let mut spp = 1;
    while spp <= config.conv_max {
        let out = render(scene, &options(config, name, 0, spp), stage)?;
        stage.finished_render(out.stats.samples);
        series.push(ConvPoint {
            spp,
            relmse: measure(&out.image, reference)?.linear.relmse,
        });
        spp *= 2;
    }
    let pts: Vec<[f64; 2]> = series
        .iter()
        .map(|c| [f64::from(c.spp), c.relmse])
        .collect();
    Ok((series, log_log_slope(&pts)))
}

/// What a finished run leaves behind.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// Every file written to the report folder, then the reference files.
    pub files: Vec<PathBuf>,
    /// Wall time of the whole run, seconds.
    pub seconds: f64,
}

/// Runs the experiment and writes the report folder, telling `observer`
/// what it does.
pub fn run(config: &ExperimentConfig, observer: &dyn Progress) -> Result<Outcome> {
    config.validate()?;
    let start = Instant::now();
    let (mut scene, scene_hash) = load(config, observer)?;
    std::fs::create_dir_all(&config.out)
        .with_context(|| format!("cannot create `{}`", config.out.display()))?;
    let cached = [
        (config.resolution, config.ref_spp),
        (config.conv_res, config.conv_ref_spp),
    ]
    .map(|(res, spp)| cache_file(config, res, scene_hash, spp).is_file());
    observer.estimate(&calibrate(config, &scene, total_samples(config, cached))?);
    let (reference, ref_info) =
        render_reference(config, &scene, scene_hash, config.ref_spp, observer)?;
    let evaluator = Evaluator::new(&scene, config.emitter_border, config.blur_sigma)?;
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
        let (r, image) = measure_sampler(config, &scene, name, &reference, &evaluator, &stage)?;
        stage.end();
        samplers.push(r);
        renders.push(image);
    }
    fill_ratios(&mut samplers);
    fill_statistics(&mut samplers);
    let threshold_sweep = threshold_sweep(config, &scene, &reference, observer)?;
    // The convergence series: at `conv_res` against their own reference
    // (the main one when resolution and spp are the same).
    let same = config.conv_res == config.resolution && config.conv_ref_spp == config.ref_spp;
    let conv_own;
    let (conv_reference, conv_ref_info) = if same {
        (&reference, ref_info.clone())
    } else {
        scene.set_resolution(config.conv_res)?;
        let (image, info) =
            render_reference(config, &scene, scene_hash, config.conv_ref_spp, observer)?;
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
        (s.convergence, s.convergence_slope) =
            convergence(config, &scene, name, conv_reference, &stage)?;
        stage.end();
    }
    let results = Results {
        samplers,
        reference: ref_info,
        convergence_reference: conv_ref_info,
        threshold_sweep,
        kept_fraction: evaluator.kept_fraction(),
    };
    let images = Images { reference, renders };
    let mut files = report::write_all(config, &results, &images, start.elapsed().as_secs_f64())?;
    files.push(results.reference.file.clone());
    if !same {
        files.push(results.convergence_reference.file.clone());
    }
    observer.note(&format!(
        "report written to {}",
        config.out.join("report.md").display()
    ));
    Ok(Outcome {
        files,
        seconds: start.elapsed().as_secs_f64(),
    })
}
