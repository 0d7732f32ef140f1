//! `lowdisc render`: path-trace a pbrt-v4 scene file or the built-in Cornell
//! box with any of lowdisc's samplers and write EXR or PNG.
//!
//! Arguments become a [`RenderConfig`] before any work starts: the flags'
//! settings form one [`SettingsLayer`], checked by
//! [`Settings::resolve`] (the renderer's one definition of every range,
//! whose errors name the flag) and resolved again over the scene file's
//! layer once it is loaded. The render itself runs in the `lowdisc-render` library, which reports progress
//! through a callback that drives [`crate::progress::Reporter`] (a bar on a
//! terminal, lines otherwise, nothing with `--quiet`), which also says where
//! the image went. Warnings go to stderr, each distinct
//! one once (also suppressed by `--quiet`); `--stats` prints the counters and
//! the time per phase to stdout. A scene file's own settings (sampler, spp,
//! maxdepth, resolution, output file) apply unless a flag overrides them.

mod prepare;

use std::collections::HashSet;
use std::path::PathBuf;
use std::time::Instant;

use anyhow::{Context, Result, bail};
use clap::Args;
use lowdisc_render::bsdf::LayeredExitWeight;
use lowdisc_render::render::{Progress, render};
use lowdisc_render::settings::{Given, Settings, SettingsLayer};

use crate::progress::Reporter;
use crate::render_stats::{self, Phases};
use crate::{limits, parse, split_cmd};
use prepare::{check_output, prepare, warn_once};

/// The long help of `render`.
pub const LONG_ABOUT: &str = "\
Path-trace a scene and write the image.\n\
\n\
Without SCENE the built-in Cornell box is rendered (the published Cornell\n\
Box Data geometry, RGB reflectances, 35 mm camera). A pbrt-v4 scene file's\n\
Sampler, pixelsamples, maxdepth, Film resolution and filename are used\n\
unless --sampler, --spp, --maxdepth, --res or -o is given; --envmap replaces\n\
the image of every image-based infinite light. A pbrt-v4 feature lowdisc\n\
lacks and that changes the image (grid media, curves and the hair\n\
material, the measured material, bdpt, sppm and mlt, ...) is an error\n\
naming it with file:line:column;\n\
--approximate renders it approximately with a warning instead. Features\n\
without effect on the pixels are warnings; syntax errors are errors.\n\
\n\
The renderer is a unidirectional path tracer with next-event estimation and\n\
MIS (a volumetric one, as pbrt-v4's volpath, for scenes with homogeneous\n\
media), in RGB by default or spectrally as pbrt-v4 with --spectral. Every random\n\
decision comes from the chosen pixel sampler, in a fixed order of dimensions\n\
(with --spectral the wavelengths first; film position, lens, then seven per\n\
bounce: light choice, light position, BSDF lobe, BSDF direction, Russian\n\
roulette). The output is bit-identical for the same options whatever\n\
--threads is.\n\
\n\
Output: .exr (linear float), .png (8-bit sRGB), .pfm or .hdr, written to a\n\
temporary file and renamed into place.\n\
\n\
Split renders: --pixel-bounds X0,X1,Y0,Y1 renders only those pixels (full-\n\
image coordinates, inside the scene's Film pixelbounds/cropwindow) and\n\
--sample-range A..B only sample indices A to B-1 of every pixel. Either one\n\
writes a part: an EXR whose data window is the window and whose display\n\
window is the full image, with the exact per-pixel sums and a header naming\n\
the scene (hash), settings, window and range. `lowdisc merge OUT.exr PARTS..`\n\
assembles parts: a merge of tiles equals the single render bit for bit (every\n\
sampler); merged sample ranges equal it up to f64 rounding of the sums.\n\
";

/// The arguments of `render`.
#[derive(Debug, Args)]
pub struct RenderArgs {
    /// A pbrt-v4 scene file (omit for the built-in Cornell box).
    scene: Option<PathBuf>,
    /// Pixel sampler (`--help` lists them all) [default: the scene's, else
    /// zsobol].
    #[arg(long, short = 's', value_name = "NAME", long_help = crate::sampler_help::sampler_list(
        "Pixel sampler, one of:",
        "[default: the scene's, else zsobol]",
    ))]
    sampler: Option<String>,
    /// Generator matrices for the Sobol samplers: a built-in net (`sobol`,
    /// `onetwo`) or a file of Joe-Kuo direction numbers or matrices
    /// [default: sobol].
    #[arg(long, value_name = "NAME|FILE", long_help = crate::sampler_help::net_help())]
    net: Option<String>,
    /// Samples per pixel [default: the scene's, else 16].
    #[arg(long, value_name = "N")]
    spp: Option<u32>,
    /// Seed of every random choice [default: 0].
    #[arg(long, value_name = "S")]
    seed: Option<u64>,
    /// Image resolution [default: the scene's; 512x512 for the Cornell box].
    #[arg(long, value_name = "WxH", allow_hyphen_values = true)]
    res: Option<String>,
    /// Maximum number of bounces (pbrt's maxdepth) [default: the scene's, else 5].
    #[arg(long, value_name = "D")]
    maxdepth: Option<u32>,
    /// Worker threads [default: all cores].
    #[arg(long, value_name = "T")]
    threads: Option<usize>,
    /// Environment map replacing a scene's missing one (scene files only).
    #[arg(long, value_name = "FILE")]
    envmap: Option<PathBuf>,
    /// Render the scene file's pbrt-v4 features that lowdisc lacks (grid media,
    /// curves, measured BSDFs, other integrators, ...) approximately, each with a
    /// warning saying how, instead of refusing the scene.
    #[arg(long)]
    approximate: bool,
    /// Output image: .exr, .png, .pfm or .hdr [default: in out/ (created),
    /// the scene's Film filename, else render.exr].
    #[arg(long, short = 'o', value_name = "OUT")]
    output: Option<PathBuf>,
    /// Paper permutation threshold in [0,1] (samplers paper and paper-repro):
    /// the probability that a generator-matrix column is left unflipped
    /// [default: 0.5].
    #[arg(long, value_name = "T")]
    threshold: Option<f64>,
    /// Let the paper permutation act on the film dimensions 0-1 too;
    /// `--paper-all-dims` alone means true [default: false].
    #[arg(long, value_name = "BOOL", num_args = 0..=1,
          default_missing_value = "true", require_equals = true)]
    paper_all_dims: Option<bool>,
    /// Largest memory (MiB) of the film and its image.
    #[arg(long, value_name = "MIB", default_value_t = limits::DEFAULT_MAX_MEMORY_MIB)]
    max_memory: u64,
    /// Render only these pixels, `X0,X1,Y0,Y1` (half-open, full-image
    /// coordinates), and write a part for `lowdisc merge`.
    #[arg(long, value_name = "X0,X1,Y0,Y1", allow_hyphen_values = true)]
    pixel_bounds: Option<String>,
    /// Take only sample indices `A..B` (half-open, within 0..spp) of every
    /// pixel, and write a part for `lowdisc merge`.
    #[arg(long, value_name = "A..B")]
    sample_range: Option<String>,
    /// Render spectrally as pbrt-v4 (four sampled wavelengths per sample, RGB
    /// uplifted to spectra, CIE 1931 sensor) instead of in RGB, the default.
    #[arg(long)]
    spectral: bool,
    /// MIS weight of the light leaving a coated (layered) material:
    /// `unbiased` (the default) or `pbrt-v4`, pbrt-v4's reverse-density
    /// weight, which is brighter and matches pbrt-v4's images.
    #[arg(long, value_enum, value_name = "WEIGHT")]
    layered_weight: Option<LayeredWeight>,
    /// Print rays traced, rays/s, BVH statistics and time per phase.
    #[arg(long)]
    stats: bool,
    /// No progress bar and no warnings.
    #[arg(long, short = 'q')]
    quiet: bool,
}

/// A `render` invocation, its flags' settings checked.
#[derive(Debug, Clone)]
pub struct RenderConfig {
    /// Scene file, or `None` for the Cornell box.
    pub scene: Option<PathBuf>,
    /// The settings the flags give (resolved over the scene's).
    pub settings: SettingsLayer,
    /// Environment map replacing the scene's.
    pub envmap: Option<PathBuf>,
    /// Render missing pbrt-v4 features approximately (`--approximate`).
    pub approximate: bool,
    /// Output file override.
    pub output: Option<PathBuf>,
    /// Print statistics.
    pub stats: bool,
    /// Suppress progress and warnings.
    pub quiet: bool,
    /// Memory limit (MiB) of the film.
    pub max_memory: u64,
}

/// `--layered-weight`: which MIS weight layered BSDFs use for the walk's
/// connection out through the coat.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum LayeredWeight {
    /// Weights that sum to 1: `f` agrees with the BSDF's own sampling.
    Unbiased,
    /// pbrt-v4's reverse density, for comparisons with pbrt-v4's images.
    #[value(name = "pbrt-v4")]
    PbrtV4,
}

impl LayeredWeight {
    /// The renderer's value of this choice.
    pub fn exit_weight(self) -> LayeredExitWeight {
        match self {
            LayeredWeight::Unbiased => LayeredExitWeight::UNBIASED,
            LayeredWeight::PbrtV4 => LayeredExitWeight::PBRT_V4,
        }
    }
}

impl RenderConfig {
    /// True when the render writes a part (a window or a sample range).
    pub fn is_part(&self) -> bool {
        self.settings.window.is_some() || self.settings.samples.is_some()
    }
}

impl RenderArgs {
    /// Checks every argument and builds the configuration.
    pub fn into_config(self) -> Result<RenderConfig> {
        let settings = self.settings()?;
        Settings::resolve(&[&settings])?;
        if self.envmap.is_some() && self.scene.is_none() {
            bail!("--envmap applies to scene files; the built-in Cornell box has no environment");
        }
        if let Some(out) = &self.output {
            check_output(out)?;
        }
        for (what, file) in [("scene", &self.scene), ("--envmap", &self.envmap)] {
            if let Some(file) = file {
                lowdisc_files::check_input(file, u64::MAX)
                    .with_context(|| format!("{what} file"))?;
            }
        }
        Ok(RenderConfig {
            scene: self.scene,
            settings,
            envmap: self.envmap,
            approximate: self.approximate,
            output: self.output,
            stats: self.stats,
            quiet: self.quiet,
            max_memory: self.max_memory,
        })
    }

    /// The settings the flags give, each naming its flag.
    fn settings(&self) -> Result<SettingsLayer> {
        let weight = self.layered_weight.map(LayeredWeight::exit_weight);
        Ok(SettingsLayer {
            sampler: flag("--sampler", &self.sampler, parse::sampler_name)?,
            net: flag("--net", &self.net, parse::net)?,
            spp: Given::maybe(self.spp, "--spp"),
            seed: Given::maybe(self.seed, "--seed"),
            threshold: Given::maybe(self.threshold, "--threshold"),
            paper_all_dims: Given::maybe(self.paper_all_dims, "--paper-all-dims"),
            max_depth: Given::maybe(self.maxdepth, "--maxdepth"),
            layered_exit_weight: Given::maybe(weight, "--layered-weight"),
            resolution: flag("--res", &self.res, parse::resolution)?,
            threads: Given::maybe(self.threads, "--threads"),
            window: flag("--pixel-bounds", &self.pixel_bounds, parse::pixel_bounds)?,
            samples: flag("--sample-range", &self.sample_range, parse::sample_range)?,
            spectral: self.spectral.then(|| Given::new(true, "--spectral")),
        })
    }
}

/// The value of `name`'s `text`, parsed by `parse`, if given.
fn flag<T>(
    name: &str,
    text: &Option<String>,
    parse: impl Fn(&str) -> Result<T>,
) -> Result<Option<Given<T>>> {
    Ok(Given::maybe(text.as_deref().map(parse).transpose()?, name))
}

/// Loads (or builds) the scene, renders it and writes the image.
pub fn run(config: &RenderConfig) -> Result<()> {
    let t0 = Instant::now();
    let mut seen = HashSet::new();
    let (scene, view, options, output) = prepare(config, &mut seen)?;
    let mut phases = Phases {
        load: t0.elapsed(),
        ..Phases::default()
    };

    let reporter = Reporter::new(config.quiet);
    let [w, h] = view.resolution();
    let pixels = options
        .window
        .map_or(u64::from(w) * u64::from(h), |b| b.area() as u64);
    let total = pixels * u64::from(options.sample_range().len());
    let title = format!(
        "rendering {w}x{h}, {} spp with {}",
        options.sampler.spp, options.sampler.name
    );
    reporter.begin_stage(&title, total, "samples");
    let on_progress = |p: Progress| reporter.advance_stage(p.samples_done);
    let t1 = Instant::now();
    let out = render(&scene, &view, &options, &on_progress)?;
    phases.render = t1.elapsed();
    reporter.end_stage();
    for w in &out.warnings {
        warn_once(&mut seen, config.quiet, w);
    }
    let t2 = Instant::now();
    if config.is_part() {
        split_cmd::write_render_part(&output, &scene, &view, &options, &out)?;
    } else {
        out.write(&output, view.exposure())
            .with_context(|| format!("cannot write `{}`", output.display()))?;
    }
    phases.write = t2.elapsed();
    reporter.line(&format!("wrote {}", output.display()));
    if config.stats {
        render_stats::print_stats(std::io::stdout().lock(), &scene, &out, &phases)
            .context("cannot print the statistics")?;
    }
    Ok(())
}
