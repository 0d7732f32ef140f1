//! The converged reference render, cached on disk under a key of the
//! scene's content and every setting that changes the image.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use lowdisc_image::RgbImage;
use lowdisc_render::render::render;
use lowdisc_render::scene::Scene;

use crate::config::{ExperimentConfig, REF_SAMPLER, REF_SEED};
use crate::progress::{Progress, Stage, samples};
use crate::results::ReferenceInfo;
use crate::run::options;
use crate::stats::{FNV_OFFSET, fnv1a};

/// The reference of `scene` at its film's resolution (part of the cache
/// key) with `spp` samples per pixel, from the cache when present.
pub fn reference(
    config: &ExperimentConfig,
    scene: &Scene,
    scene_hash: u64,
    spp: u32,
    observer: &dyn Progress,
) -> Result<(RgbImage, ReferenceInfo)> {
    let resolution = scene.film().params.resolution;
    let file = cache_file(config, resolution, scene_hash, spp);
    let dir = cache_dir(&config.out);
    if file.is_file() {
        if let Ok(image) = lowdisc_image::read_image(&file) {
            observer.note(&format!("reusing cached reference {}", file.display()));
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
    let title = format!(
        "rendering reference: {}x{}, {} spp with {}",
        resolution[0],
        resolution[1],
        spp,
        REF_SAMPLER.as_str()
    );
    let stage = Stage::begin(observer, &title, samples(resolution, spp));
    let out = render(scene, &options(config, REF_SAMPLER, REF_SEED, spp), &stage)?;
    stage.finished_render(out.stats.samples);
    stage.end();
    std::fs::create_dir_all(&dir).with_context(|| format!("cannot create `{}`", dir.display()))?;
    lowdisc_image::write_pfm(&file, &out.image)?;
    observer.note(&format!("cached reference in {}", file.display()));
    Ok((
        out.image,
        ReferenceInfo {
            file,
            cached: false,
            time_s: out.stats.time.as_secs_f64(),
        },
    ))
}

/// The cache file of the reference at `resolution` with `spp` samples of
/// the scene whose content hashes to `scene_hash`.
pub fn cache_file(
    config: &ExperimentConfig,
    resolution: [u32; 2],
    scene_hash: u64,
    spp: u32,
) -> PathBuf {
    let mut key = format!(
        "{scene_hash:016x} {:?} ref_spp={} sampler={} seed={} depth={} v{}",
        resolution,
        spp,
        REF_SAMPLER.as_str(),
        REF_SEED,
        config.max_depth,
        env!("CARGO_PKG_VERSION")
    );
    if config.spectral {
        key.push_str(" spectral");
    }
    let hash = fnv1a(FNV_OFFSET, key.as_bytes());
    cache_dir(&config.out).join(format!("ref-{hash:016x}.pfm"))
}

/// `<parent of out>/lowdisc-ref-cache`.
pub fn cache_dir(out: &Path) -> PathBuf {
    out.parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."))
        .join("lowdisc-ref-cache")
}
