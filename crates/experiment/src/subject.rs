//! What the experiment renders and how: the scene and its view
//! ([`Subject`], loaded with the hash of its content by [`load`]) and the
//! render options of one of its renders ([`options`]).

use anyhow::{Context, Result};
use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc_image::{ImageFormat, ReadOptions, decode_image};
use lowdisc_render::integrator::PathIntegrator;
use lowdisc_render::pbrt::{LoadOptions, load_pbrt_scene};
use lowdisc_render::render::RenderOptions;
use lowdisc_render::scene::Scene;
use lowdisc_render::view::{View, ViewSpec};

use crate::config::ExperimentConfig;
use crate::progress::Progress;
use crate::scene;
use crate::stats::{FNV_OFFSET, fnv1a};

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

/// The render options of one compared sampler's render: [`options`] with
/// the experiment's net when the sampler reads one.
pub fn sampler_options(
    config: &ExperimentConfig,
    sampler: SamplerName,
    seed: u64,
    spp: u32,
) -> RenderOptions {
    let mut o = options(config, sampler, seed, spp);
    if sampler.takes_net() {
        o.sampler.net = config.net;
    }
    o
}

/// The render options of one render of the experiment (the built-in
/// Sobol matrices for every sampler).
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
