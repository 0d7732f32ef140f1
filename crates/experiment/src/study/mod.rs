//! The sampler study: the experiment's paired comparison repeated over a
//! collection of scenes and pooled into one number per sampler.
//!
//! For each scene of [`StudyConfig::scenes`] the study loads the scene as
//! the experiment does ([`crate::run`]), takes the experiment's converged
//! reference ([`crate::reference::main_reference`], cached and shared with
//! experiments of the same settings), renders every sampler with seeds
//! `0..runs` ([`crate::units::render_unit`]) and measures each render with
//! the experiment's masked MSE, blurred MSE and FLIP
//! ([`crate::quality::Evaluator`]) and with the error image's structure
//! ([`error_structure`]). Per scene, each sampler's errors are compared with
//! each baseline's by the experiment's paired ratio
//! ([`crate::stats::paired`]); over scenes, those ratios are pooled into a
//! geometric mean with an interval over seeds and one over scenes
//! ([`crate::stats::pooled`]). [`write`] turns the result into `study.md`,
//! `study.csv` and `study.json`.
//!
//! **Structure.** The error image is the render minus the reference,
//! averaged over the three channels, with the masked pixels set to 0;
//! its structure is `lowdisc_metrics::nyquist_power` at the default cutoff
//! 0.4 (power near the checkerboard, column and row Nyquist frequencies
//! over the mean power), summarised by the largest of the three: about 1
//! for white noise, about 25 for a pure pixel checkerboard or stripes,
//! below 1 for an error of mostly low frequencies.

pub mod collection;
pub mod summary;
pub mod write;

use std::path::PathBuf;
use std::time::Instant;

use anyhow::{Context, Result, bail};
use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc::net::Net;
use lowdisc_image::{PixelMask, RgbImage};
use lowdisc_metrics::{NyquistPower, SpectralPeak};
use lowdisc_render::preset::ScenePreset;
use serde::Serialize;

use crate::config::ExperimentConfig;
use crate::cut::samples;
use crate::plan::{Unit, Work};
use crate::progress::{Progress, Stage};
use crate::quality::{DEFAULT_BLUR_SIGMA, DEFAULT_EMITTER_BORDER, Evaluator, Quality};
use crate::reference::main_reference;
use crate::results::ReferenceInfo;
use crate::source::{Measures, Rendered};
use crate::subject::load;
use crate::units::render_unit;
pub use summary::{SamplerSummary, summarise};

/// Where a scene of the study comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum SceneSource {
    /// The experiment's built-in scene ([`crate::scene`]).
    Builtin,
    /// A built-in comparison scene.
    Preset(ScenePreset),
    /// A pbrt-v4 scene file.
    File(PathBuf),
}

/// One scene of the study.
#[derive(Debug, Clone, PartialEq)]
pub struct StudyScene {
    /// Its name in the tables.
    pub name: String,
    /// What to load.
    pub source: SceneSource,
    /// An environment map replacing the scene's (or the built-in sky).
    pub envmap: Option<PathBuf>,
    /// Path depth (`None`: the preset's, else [`StudyConfig::max_depth`]).
    pub max_depth: Option<u32>,
    /// Render the scene file's pbrt-v4 features that lowdisc lacks
    /// approximately instead of refusing it (`--approximate`).
    pub approximate: bool,
}

/// The settings of a study.
#[derive(Debug, Clone)]
pub struct StudyConfig {
    /// The scenes, in table order.
    pub scenes: Vec<StudyScene>,
    /// The samplers, in table order (the baselines among them).
    pub samplers: Vec<SamplerName>,
    /// The generator matrices of the samplers that read a net (`--net`).
    pub net: Net,
    /// The samplers the ratios are relative to: every sampler gets its
    /// ratios to each; the first is the main tables' baseline.
    pub baselines: Vec<SamplerName>,
    /// Samples per pixel of every render.
    pub spp: u32,
    /// Seeds per sampler and scene (`0..runs`).
    pub runs: u32,
    /// Resolution of every scene.
    pub resolution: [u32; 2],
    /// Samples per pixel of the references.
    pub ref_spp: u32,
    /// Path depth of scenes other than the presets.
    pub max_depth: u32,
    /// Render threads (`None`: all cores; images do not depend on it).
    pub threads: Option<usize>,
    /// Output folder (the reference cache is `lowdisc-ref-cache` beside it).
    pub out: PathBuf,
    /// Also write each scene's reference and every sampler's seed-0 render
    /// as `renders/SCENE/reference.pfm` and `renders/SCENE/SAMPLER.pfm`.
    pub save_renders: bool,
    /// The command line, kept in `study.json`.
    pub command: Vec<String>,
}

impl StudyConfig {
    /// Checks the settings: scenes and samplers present, at least one
    /// baseline and every baseline among the samplers, at least two runs (a paired interval needs two),
    /// and every experiment setting in range.
    pub fn validate(&self) -> Result<()> {
        if self.scenes.is_empty() {
            bail!("the study has no scenes");
        }
        if self.baselines.is_empty() {
            bail!("the study needs a baseline");
        }
        for b in &self.baselines {
            if !self.samplers.contains(b) {
                bail!("the baseline `{}` is not among --samplers", b.as_str());
            }
        }
        if self.runs < 2 {
            bail!(
                "--runs must be at least 2 for paired intervals, got {}",
                self.runs
            );
        }
        for scene in &self.scenes {
            self.experiment(scene).validate()?;
        }
        Ok(())
    }

    /// The experiment settings of one scene: the study's renders without
    /// a convergence series (it would share the main reference).
    pub fn experiment(&self, scene: &StudyScene) -> ExperimentConfig {
        let (file, preset) = match &scene.source {
            SceneSource::Builtin => (None, None),
            SceneSource::Preset(p) => (None, Some(*p)),
            SceneSource::File(f) => (Some(f.clone()), None),
        };
        let max_depth = scene
            .max_depth
            .or(preset.map(|p| p.max_depth()))
            .unwrap_or(self.max_depth);
        ExperimentConfig {
            scene: file,
            preset,
            emitter_border: DEFAULT_EMITTER_BORDER,
            blur_sigma: DEFAULT_BLUR_SIGMA,
            samplers: self.samplers.clone(),
            net: self.net,
            spp: self.spp,
            runs: self.runs,
            resolution: self.resolution,
            ref_spp: self.ref_spp,
            conv_max: 1,
            conv_res: self.resolution,
            conv_seeds: 1,
            conv_ref_spp: self.ref_spp,
            envmap: scene.envmap.clone(),
            approximate: scene.approximate,
            threshold: SamplerConfig::DEFAULT_THRESHOLD,
            max_depth,
            threads: self.threads,
            spectral: false,
            unit_samples: None,
            out: self.out.clone(),
            command: self.command.clone(),
        }
    }
}

/// The measures of one render.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct StudyRun {
    /// Its seed.
    pub seed: u64,
    /// Render time, seconds.
    pub time_s: f64,
    /// Linear MSE over all pixels.
    pub mse: f64,
    /// Masked errors, blurred MSE and FLIP.
    pub quality: Quality,
    /// The error image's [`error_structure`].
    pub structure: NyquistPower,
    /// The error image's strongest spectral band ([`error_peak`]).
    pub peak: SpectralPeak,
}

/// One sampler's runs on one scene.
#[derive(Debug, Clone, Serialize)]
pub struct SceneSampler {
    /// The sampler's name.
    pub sampler: String,
    /// Its runs, by seed.
    pub runs: Vec<StudyRun>,
}

/// Everything measured on one scene.
#[derive(Debug, Clone, Serialize)]
pub struct SceneResult {
    /// The scene's name.
    pub name: String,
    /// The scene file, `builtin` or `preset NAME`.
    pub source: String,
    /// The fraction of pixels the masked metrics keep.
    pub kept_fraction: f64,
    /// The reference.
    pub reference: ReferenceInfo,
    /// Every sampler's runs, in the study's sampler order.
    pub samplers: Vec<SceneSampler>,
}

/// The result of a study.
#[derive(Debug, Clone, Serialize)]
pub struct StudyResults {
    /// Each scene's measures.
    pub scenes: Vec<SceneResult>,
    /// Each sampler's ratios pooled over the scenes.
    pub samplers: Vec<SamplerSummary>,
    /// Wall time of the whole study, seconds.
    pub wall_time_s: f64,
}

/// The structure of the error of `image` against `reference`: the
/// channel-mean error with the pixels `mask` drops set to 0, measured by
/// `lowdisc_metrics::nyquist_power` at its default cutoff.
pub fn error_structure(
    image: &RgbImage,
    reference: &RgbImage,
    mask: &PixelMask,
) -> Result<NyquistPower> {
    let (w, h) = (image.width(), image.height());
    let error = error_image(image, reference, mask)?;
    let cutoff = lowdisc_metrics::structure::DEFAULT_CUTOFF;
    Ok(lowdisc_metrics::nyquist_power(&error, w, h, cutoff)?)
}

/// The strongest spectral band of the same error image as
/// [`error_structure`]'s (`lowdisc_metrics::spectral_peak`, default cell).
pub fn error_peak(
    image: &RgbImage,
    reference: &RgbImage,
    mask: &PixelMask,
) -> Result<SpectralPeak> {
    let error = error_image(image, reference, mask)?;
    let cell = lowdisc_metrics::structure::DEFAULT_CELL;
    Ok(lowdisc_metrics::spectral_peak(
        &error,
        image.width(),
        image.height(),
        cell,
    )?)
}

/// The channel-mean error of `image` against `reference`, 0 where `mask`
/// drops the pixel.
fn error_image(image: &RgbImage, reference: &RgbImage, mask: &PixelMask) -> Result<Vec<f64>> {
    let (w, h) = (image.width(), image.height());
    if (reference.width(), reference.height()) != (w, h) || (mask.width(), mask.height()) != (w, h)
    {
        bail!("the image, reference and mask differ in size");
    }
    let error: Vec<f64> = image
        .pixels()
        .iter()
        .zip(reference.pixels())
        .enumerate()
        .map(|(i, (a, b))| {
            if mask.keeps(i % w, i / w) {
                (0..3)
                    .map(|c| f64::from(a[c]) - f64::from(b[c]))
                    .sum::<f64>()
                    / 3.0
            } else {
                0.0
            }
        })
        .collect();
    Ok(error)
}

/// The scene's description in the tables.
fn describe(source: &SceneSource) -> String {
    match source {
        SceneSource::Builtin => "builtin".into(),
        SceneSource::Preset(p) => format!("preset {}", p.name()),
        SceneSource::File(f) => f.display().to_string(),
    }
}

/// Runs the study of `config`, telling `observer` what it does; writes
/// nothing (see [`write::write_all`]).
pub fn run_study(config: &StudyConfig, observer: &dyn Progress) -> Result<StudyResults> {
    config.validate()?;
    let start = Instant::now();
    let mut scenes = Vec::new();
    for (k, scene) in config.scenes.iter().enumerate() {
        observer.note(&format!(
            "scene {}/{}: {}",
            k + 1,
            config.scenes.len(),
            scene.name
        ));
        let result = study_scene(config, scene, observer)
            .with_context(|| format!("scene `{}`", scene.name))?;
        scenes.push(result);
    }
    let samplers = summarise(config, &scenes);
    Ok(StudyResults {
        scenes,
        samplers,
        wall_time_s: start.elapsed().as_secs_f64(),
    })
}

/// Every sampler's runs on one scene.
fn study_scene(
    config: &StudyConfig,
    study_scene: &StudyScene,
    observer: &dyn Progress,
) -> Result<SceneResult> {
    let experiment = config.experiment(study_scene);
    let (subject, hash) = load(&experiment, observer)?;
    let view = subject.view_at(experiment.resolution)?;
    let evaluator = Evaluator::new(
        &subject.scene,
        &view,
        experiment.emitter_border,
        experiment.blur_sigma,
    )?;
    let measures = Measures {
        evaluator,
        view: subject.view.clone(),
    };
    let (reference, info) = main_reference(&experiment, &subject, hash, &measures, observer)?;
    let mut samplers = Vec::new();
    for &name in &config.samplers {
        let title = format!(
            "{}: {} x {} runs at {} spp",
            study_scene.name,
            name.as_str(),
            config.runs,
            config.spp
        );
        let total = u64::from(config.runs) * samples(config.resolution, config.spp);
        let stage = Stage::begin(observer, &title, total);
        let mut runs = Vec::new();
        for seed in 0..u64::from(config.runs) {
            let unit = Unit {
                index: 0,
                work: Work::Run {
                    sampler: name,
                    seed,
                },
            };
            let out = render_unit(&experiment, &subject, hash, &unit, &stage)?;
            let time_s = out.render_time_s;
            let Rendered::Image(image) = out.rendered else {
                bail!("a run left sums, not an image");
            };
            if config.save_renders && seed == 0 {
                let dir = config.out.join("renders").join(&study_scene.name);
                std::fs::create_dir_all(&dir)
                    .with_context(|| format!("cannot create `{}`", dir.display()))?;
                lowdisc_image::write_pfm(dir.join(format!("{}.pfm", name.as_str())), &image)?;
                lowdisc_image::write_pfm(dir.join("reference.pfm"), &reference)?;
            }
            runs.push(StudyRun {
                seed,
                time_s,
                mse: crate::metrics::measure(&image, &reference)?.linear.mse,
                quality: measures.evaluator.measure(&image, &reference)?,
                structure: error_structure(&image, &reference, measures.evaluator.mask())?,
                peak: error_peak(&image, &reference, measures.evaluator.mask())?,
            });
        }
        stage.end();
        samplers.push(SceneSampler {
            sampler: name.as_str().to_string(),
            runs,
        });
    }
    Ok(SceneResult {
        name: study_scene.name.clone(),
        source: describe(&study_scene.source),
        kept_fraction: measures.evaluator.kept_fraction(),
        reference: info,
        samplers,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn structure_of_a_checkerboard_error_and_of_no_error() {
        let reference = RgbImage::filled(16, 16, [0.5; 3]).unwrap();
        let board = RgbImage::from_fn(16, 16, |x, y| {
            let e = if (x + y) % 2 == 0 { 0.1 } else { -0.1 };
            [0.5 + e; 3]
        })
        .unwrap();
        let all = PixelMask::all(16, 16);
        // 16 pixels: k = -8, -7 and 7 reach |k / 16| >= 0.4, 9 corner bins.
        let s = error_structure(&board, &reference, &all).unwrap();
        assert!((s.checkerboard - 256.0 / 9.0).abs() < 1e-3, "{s:?}");
        assert!(s.rows.abs() < 1e-6 && s.columns.abs() < 1e-6, "{s:?}");
        let none = error_structure(&reference, &reference, &all).unwrap();
        assert_eq!(none.max(), 0.0);
        let small = RgbImage::filled(8, 8, [0.5; 3]).unwrap();
        assert!(error_structure(&small, &reference, &all).is_err());
    }

    fn config(scenes: Vec<StudyScene>) -> StudyConfig {
        StudyConfig {
            scenes,
            samplers: vec![SamplerName::Independent, SamplerName::Sobol],
            net: Net::SOBOL,
            baselines: vec![SamplerName::Sobol],
            spp: 2,
            runs: 2,
            resolution: [8, 8],
            ref_spp: 8,
            max_depth: 5,
            threads: Some(1),
            save_renders: false,
            out: std::env::temp_dir().join("lowdisc-study-test").join("out"),
            command: Vec::new(),
        }
    }

    fn preset(p: ScenePreset) -> StudyScene {
        StudyScene {
            name: p.name().into(),
            source: SceneSource::Preset(p),
            envmap: None,
            max_depth: None,
            approximate: false,
        }
    }

    #[test]
    fn validation_names_the_problem() {
        let ok = config(vec![preset(ScenePreset::Direct)]);
        ok.validate().unwrap();
        assert_eq!(ok.experiment(&ok.scenes[0]).max_depth, 1);
        let mut c = ok.clone();
        c.baselines = vec![SamplerName::Sobol, SamplerName::ZSobol];
        assert!(format!("{}", c.validate().unwrap_err()).contains("baseline"));
        let mut c = ok.clone();
        c.runs = 1;
        assert!(format!("{}", c.validate().unwrap_err()).contains("--runs"));
        let c = config(Vec::new());
        assert!(c.validate().is_err());
    }

    /// A tiny study of both presets runs end to end; unscrambled Sobol is
    /// deterministic, so its ratio to itself is exactly 1.
    #[test]
    fn tiny_study_of_two_presets() {
        let c = config(vec![preset(ScenePreset::Direct), preset(ScenePreset::Gi)]);
        let r = run_study(&c, &crate::progress::Silent).unwrap();
        assert_eq!(r.scenes.len(), 2);
        assert!(r.scenes.iter().all(|s| s.samplers.len() == 2));
        let sobol = r.samplers.iter().find(|s| s.sampler == "sobol").unwrap();
        let masked = sobol.ratios[0].metrics[0].pooled.unwrap();
        assert_eq!(masked.ratio, 1.0);
        let ind = r
            .samplers
            .iter()
            .find(|s| s.sampler == "independent")
            .unwrap();
        assert!(ind.ratios[0].metrics[0].pooled.unwrap().ratio > 0.0);
        assert!(ind.structure.mean.is_finite());
    }
}
