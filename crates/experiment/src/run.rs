//! Running the experiment on one machine: the scene, its plan of units
//! ([`crate::plan`]), each unit rendered in this process as
//! [`crate::assemble()`] needs it, and the report ([`crate::report`]). A
//! planned run ([`crate::planned`]) renders the same units elsewhere and
//! assembles them the same way.

use std::path::PathBuf;
use std::time::Instant;

use anyhow::{Context, Result};
use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc_image::{ImageFormat, ReadOptions, decode_image};
use lowdisc_render::integrator::PathIntegrator;
use lowdisc_render::pbrt::{LoadOptions, load_pbrt_scene};
use lowdisc_render::render::RenderOptions;
use lowdisc_render::scene::Scene;
use lowdisc_render::view::{View, ViewSpec};

use crate::assemble::{Measures, report};
use crate::config::ExperimentConfig;
use crate::estimate::calibrate;
use crate::plan::{Plan, shares_reference};
use crate::progress::Progress;
use crate::reference::cached_references;
use crate::report::answer::Answer;
use crate::results::Results;
use crate::scene;
use crate::stats::{FNV_OFFSET, fnv1a};
use crate::units::InProcess;

/// What the experiment renders: its scene and the scene's view, which
/// every render builds at its own resolution.
#[derive(Clone, Debug)]
pub struct Subject {
    /// Geometry, materials, lights.
    pub scene: Scene,
    /// Camera, film and filter.
    pub view: ViewSpec,
}

impl Subject {
    /// The view built at `resolution`.
    pub fn view_at(&self, resolution: [u32; 2]) -> Result<View> {
        Ok(View::new(&self.view, resolution)?)
    }
}

/// The scene and the hash of its content: the built-in scene's id or the
/// scene file's bytes (not the files it includes), and the environment
/// map's bytes. `--envmap` replaces the built-in sky, or every image-based
/// `infinite` light of a scene file (pbrt-v4 scenes often ship without
/// their environment map).
pub(crate) fn load(config: &ExperimentConfig, observer: &dyn Progress) -> Result<(Subject, u64)> {
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
    let (scene, view) = match &config.scene {
        None if config.preset.is_some() => {
            let preset = config.preset.context("no preset")?;
            hash = fnv1a(hash, preset.id().as_bytes());
            preset.scene()?
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
                approximate: config.approximate,
            };
            let loaded = load_pbrt_scene(path, &options)
                .with_context(|| format!("cannot load scene `{}`", path.display()))?;
            for w in &loaded.warnings {
                observer.note(w);
            }
            (loaded.scene, loaded.view)
        }
    };
    Ok((Subject { scene, view }, hash))
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
        spectral: config.spectral,
        ..RenderOptions::default()
    }
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

/// Runs the experiment and writes the report folder, telling `observer`
/// what it does.
pub fn run(config: &ExperimentConfig, observer: &dyn Progress) -> Result<Outcome> {
    config.validate()?;
    let start = Instant::now();
    let (subject, scene_hash) = load(config, observer)?;
    std::fs::create_dir_all(&config.out)
        .with_context(|| format!("cannot create `{}`", config.out.display()))?;
    let plan = Plan::new(
        config.clone(),
        scene_hash,
        cached_references(config, scene_hash),
    );
    observer.estimate(&calibrate(config, &subject, plan.samples())?);
    let measures = Measures::new(&plan, &subject)?;
    let mut source = InProcess {
        config,
        subject: &subject,
        scene_hash,
    };
    let wall = || start.elapsed().as_secs_f64();
    report(&plan, &measures, &mut source, observer, &wall)
}
