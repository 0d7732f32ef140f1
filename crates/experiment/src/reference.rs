//! The converged reference renders (the main one and the convergence
//! series' own), cached on disk under a key of the scene's content and
//! every setting that changes the image, the number of sample ranges it is
//! cut into included ([`crate::cut`]); a reference that is not cached is
//! rendered as units of the plan ([`crate::plan`]) and joined.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use lowdisc_image::RgbImage;

use crate::config::{ExperimentConfig, REF_SAMPLER, REF_SEED};
use crate::cut::samples;
use crate::plan::{Plan, Target, Unit, Work, reference_cut, reference_settings};
use crate::progress::{Progress, Stage};
use crate::results::ReferenceInfo;
use crate::source::{Cursor, Measures, UnitSource, join_cut};
use crate::stats::{FNV_OFFSET, fnv1a};
use crate::subject::Subject;

/// Whether the main and the convergence reference are in the cache (and
/// readable) for the scene whose content hashes to `scene_hash`.
pub fn cached_references(config: &ExperimentConfig, scene_hash: u64) -> [bool; 2] {
    [Target::Main, Target::Convergence].map(|target| {
        let file = cache_file(config, target, scene_hash);
        file.is_file() && lowdisc_image::read_image(&file).is_ok()
    })
}

/// The main reference of `config` on `subject` (its content hashing to
/// `scene_hash`), without the rest of
/// an experiment: read from the cache, or rendered in this process in the
/// pieces a plan would cut it into, joined and cached. `measures` gives the
/// film; the key and the image are those of [`reference`], so an
/// experiment and a study of the same scene and settings share the file.
pub fn main_reference(
    config: &ExperimentConfig,
    subject: &Subject,
    scene_hash: u64,
    measures: &Measures,
    observer: &dyn Progress,
) -> Result<(RgbImage, ReferenceInfo)> {
    let cached = cached_references(config, scene_hash);
    let units: Vec<Unit> = if cached[0] {
        Vec::new()
    } else {
        reference_cut(config, Target::Main)
            .pieces()
            .enumerate()
            .map(|(index, piece)| Unit {
                index,
                work: Work::Reference {
                    target: Target::Main,
                    piece,
                },
            })
            .collect()
    };
    let plan = Plan {
        config: config.clone(),
        scene_hash,
        cached,
        units,
    };
    let mut cursor = Cursor::new(&plan);
    let mut source = crate::units::InProcess {
        config,
        subject,
        scene_hash,
    };
    reference(
        &plan,
        measures,
        Target::Main,
        &mut cursor,
        &mut source,
        observer,
    )
}

/// Reference `target` of the plan: read from the cache when the plan says
/// it is cached, else joined from its pieces (the next units of `cursor`),
/// whose render times add up, and written to the cache.
pub(crate) fn reference(
    plan: &Plan,
    measures: &Measures,
    target: Target,
    cursor: &mut Cursor,
    source: &mut dyn UnitSource,
    observer: &dyn Progress,
) -> Result<(RgbImage, ReferenceInfo)> {
    let config = &plan.config;
    let (resolution, spp) = reference_settings(config, target);
    let file = cache_file(config, target, plan.scene_hash);
    let dir = cache_dir(&config.out);
    let cached = match target {
        Target::Main => plan.cached[0],
        Target::Convergence => plan.cached[1],
    };
    if cached {
        let image = lowdisc_image::read_image(&file).with_context(|| {
            format!(
                "the planned reference `{}` cannot be read; plan again",
                file.display()
            )
        })?;
        observer.note(&format!("reusing cached reference {}", file.display()));
        let info = ReferenceInfo {
            file,
            cached: true,
            time_s: 0.0,
        };
        return Ok((image, info));
    }
    let title = format!(
        "rendering reference: {}x{}, {} spp with {}",
        resolution[0],
        resolution[1],
        spp,
        REF_SAMPLER.as_str()
    );
    let stage = Stage::begin(observer, &title, samples(resolution, spp));
    let (image, time_s) = join_cut(
        cursor,
        source,
        &stage,
        reference_cut(config, target),
        &|piece| Work::Reference { target, piece },
        &measures.view_at(resolution)?,
        config.spectral,
    )?;
    stage.end();
    std::fs::create_dir_all(&dir).with_context(|| format!("cannot create `{}`", dir.display()))?;
    lowdisc_image::write_pfm(&file, &image)?;
    observer.note(&format!("cached reference in {}", file.display()));
    let info = ReferenceInfo {
        file,
        cached: false,
        time_s,
    };
    Ok((image, info))
}

/// The cache file of reference `target` of the scene whose content hashes
/// to `scene_hash`; the key names the number of sample ranges the
/// reference is cut into, whose sums round differently (keys before the
/// ranges named none, so no older file is reused).
pub fn cache_file(config: &ExperimentConfig, target: Target, scene_hash: u64) -> PathBuf {
    let (resolution, spp) = reference_settings(config, target);
    let mut key = format!(
        "{scene_hash:016x} {:?} ref_spp={} sampler={} seed={} depth={} v{} ranges={}",
        resolution,
        spp,
        REF_SAMPLER.as_str(),
        REF_SEED,
        config.max_depth,
        env!("CARGO_PKG_VERSION"),
        reference_cut(config, target).ranges
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
