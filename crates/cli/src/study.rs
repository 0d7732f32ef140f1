//! `lowdisc study`: samplers compared over a collection of scenes, each
//! sampler's paired error ratio to a baseline pooled over the scenes
//! ([`lowdisc_experiment::study`] does the work; this module turns the
//! arguments into a [`StudyConfig`] and prints progress).

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use clap::Args;
use lowdisc::catalog::SamplerName;
use lowdisc::net::Net;
use lowdisc_experiment::comparison::BASELINE;
use lowdisc_experiment::study::collection::{available, collection};
use lowdisc_experiment::study::{SceneSource, StudyConfig, StudyScene, run_study, write};

use crate::parse;
use lowdisc_experiment::Progress;

use crate::progress::Reporter;

/// The samplers compared by default.
const DEFAULT_SAMPLERS: &str =
    "independent,sobol,sobol-owen,sobol-fast-owen,padded-sobol,zsobol,zsobol-4d,zorder-sz";
/// Default resolution, spp, runs and reference spp; then those of `--quick`.
const DEFAULT_SIZES: ([u32; 2], u32, u32, u32) = ([64, 64], 16, 8, 1024);
const QUICK_SIZES: ([u32; 2], u32, u32, u32) = ([16, 16], 4, 2, 32);
/// The scenes of `--quick` (when `--scenes` is not given).
const QUICK_SCENES: &str = "direct,gi";

pub const LONG_ABOUT: &str = "\
Compare samplers over a collection of scenes. Each scene is rendered with\n\
every sampler --runs times (seeds 0..runs) and measured against its cached\n\
converged reference (as `lowdisc experiment` does): masked MSE, blurred MSE,\n\
FLIP, and the error image's structure (error power at the Nyquist corner\n\
relative to white noise: 1 = white noise, about 25 = a pixel checkerboard).\n\
Per scene, each sampler's errors are divided by the baseline's from the same\n\
seed (paired ratios); over scenes, the ratios' geometric mean is reported\n\
with a 95 % interval over seeds and one with the scenes as a sample.\n\
\n\
Scenes: the presets `direct` and `gi`, the built-in scene `builtin`, and the\n\
public pbrt-v4 scenes of --shared (cornell-box, veach-mis, killeroo-simple,\n\
material-testball, bmw-m6; skipped with a note when absent), plus any pbrt-v4\n\
FILEs given (lit by --envmap if given). --scenes picks from the collection\n\
by name (`none`: only the FILEs).\n\
\n\
Defaults: 64x64, 16 spp, 8 runs, references of 1024 spp, ratios to sobol: a\n\
few minutes on 2 cores. --quick: 16x16, 4 spp, 2 runs, references of 32 spp,\n\
scenes direct and gi (seconds, for tests). Writes study.md, study.csv and\n\
study.json to --out (--save-renders: also the references and every\n\
sampler's seed-0 render as PFM); references are cached in lowdisc-ref-cache\n\
beside it.";

/// `study` arguments.
#[derive(Debug, Args)]
pub struct StudyArgs {
    /// pbrt-v4 scene files added to the study (named by their file stem).
    files: Vec<PathBuf>,
    /// Scenes of the collection, comma-separated (default: all available;
    /// with --quick, direct and gi).
    #[arg(long, value_name = "LIST", value_delimiter = ',')]
    scenes: Option<Vec<String>>,
    /// The folder of the public pbrt-v4 scenes.
    #[arg(long, value_name = "DIR", default_value = "../shared/scenes")]
    shared: PathBuf,
    /// Environment map of the FILEs given.
    #[arg(long, value_name = "FILE")]
    envmap: Option<PathBuf>,
    /// Render the FILEs' pbrt-v4 features that lowdisc lacks approximately,
    /// with a warning, instead of refusing them.
    #[arg(long)]
    approximate: bool,
    /// Samplers (comma-separated catalog names, or `all`).
    #[arg(long, value_name = "LIST", value_delimiter = ',', default_value = DEFAULT_SAMPLERS,
          long_help = crate::sampler_help::sampler_list("Samplers (comma-separated, or `all`), of:", ""))]
    samplers: Vec<String>,
    /// Generator matrices of the compared Sobol samplers (a built-in net:
    /// `sobol`, `onetwo`; or a file); the reference and the other samplers
    /// keep theirs [default: sobol].
    #[arg(long, value_name = "NAME|FILE", long_help = crate::sampler_help::net_help())]
    net: Option<String>,
    /// The samplers the ratios are relative to (comma-separated; the first
    /// is the main tables' baseline).
    #[arg(long, value_name = "LIST", value_delimiter = ',', default_value = BASELINE)]
    baseline: Vec<String>,
    /// Samples per pixel.
    #[arg(long, value_name = "N")]
    spp: Option<u32>,
    /// Seeds per sampler and scene (at least 2).
    #[arg(long, value_name = "N")]
    runs: Option<u32>,
    /// Resolution of every scene.
    #[arg(long, value_name = "WxH")]
    res: Option<String>,
    /// Samples per pixel of the references.
    #[arg(long, value_name = "N")]
    ref_spp: Option<u32>,
    /// Path depth of the scenes other than the presets.
    #[arg(long, value_name = "D", default_value_t = lowdisc_render::integrator::PathIntegrator::default().max_depth)]
    maxdepth: u32,
    /// Render threads (images do not depend on it).
    #[arg(long, value_name = "T")]
    threads: Option<usize>,
    /// Output folder.
    #[arg(long, value_name = "DIR", default_value = "study")]
    out: PathBuf,
    /// Also write each scene's reference and every sampler's seed-0 render
    /// to DIR/renders/SCENE/ (PFM).
    #[arg(long)]
    save_renders: bool,
    /// A small study of seconds (for tests).
    #[arg(long)]
    quick: bool,
    /// No progress on stderr.
    #[arg(long, short = 'q')]
    quiet: bool,
}

fn samplers(names: &[String]) -> Result<Vec<SamplerName>> {
    let mut out = Vec::new();
    for name in names.iter().map(|s| s.trim()).filter(|s| !s.is_empty()) {
        let add: Vec<SamplerName> = if name == "all" {
            SamplerName::ALL.to_vec()
        } else {
            vec![parse::sampler_name(name)?]
        };
        for s in add {
            if !out.contains(&s) {
                out.push(s);
            }
        }
    }
    Ok(out)
}

impl StudyArgs {
    /// The scenes picked from the collection, then the FILEs; `notes`
    /// receives the shared scenes skipped because they are absent.
    fn scenes(&self, notes: &mut Vec<String>) -> Result<Vec<StudyScene>> {
        let all = collection(&self.shared);
        let picked: Vec<StudyScene> = match (&self.scenes, self.quick) {
            (Some(names), _) => picked(&all, names)?,
            (None, true) => picked(
                &all,
                &QUICK_SCENES
                    .split(',')
                    .map(String::from)
                    .collect::<Vec<_>>(),
            )?,
            (None, false) => all
                .into_iter()
                .filter(|s| {
                    let ok = available(s);
                    if !ok {
                        notes.push(format!("skipping scene `{}`: its files are absent", s.name));
                    }
                    ok
                })
                .collect(),
        };
        let mut scenes = picked;
        for file in &self.files {
            let stem = file
                .file_stem()
                .map_or("scene".into(), |s| s.to_string_lossy().into_owned());
            let mut name = stem.clone();
            let mut k = 2;
            while scenes.iter().any(|s| s.name == name) {
                name = format!("{stem}-{k}");
                k += 1;
            }
            scenes.push(StudyScene {
                name,
                source: SceneSource::File(file.clone()),
                envmap: self.envmap.clone(),
                max_depth: None,
                approximate: self.approximate,
            });
        }
        Ok(scenes)
    }

    /// The validated study.
    pub fn into_config(self) -> Result<(StudyConfig, Vec<String>, bool)> {
        if self.envmap.is_some() && self.files.is_empty() {
            bail!("--envmap lights the scene FILEs given, and none is given");
        }
        let mut notes = Vec::new();
        let scenes = self.scenes(&mut notes)?;
        let (res, spp, runs, ref_spp) = if self.quick {
            QUICK_SIZES
        } else {
            DEFAULT_SIZES
        };
        let resolution = match self.res.as_deref() {
            Some(text) => parse::resolution(text)?,
            None => res,
        };
        let config = StudyConfig {
            scenes,
            samplers: samplers(&self.samplers)?,
            net: self.net.as_deref().map_or(Ok(Net::SOBOL), parse::net)?,
            baselines: samplers(&self.baseline).context("--baseline")?,
            spp: self.spp.unwrap_or(spp),
            runs: self.runs.unwrap_or(runs),
            resolution,
            ref_spp: self.ref_spp.unwrap_or(ref_spp),
            max_depth: self.maxdepth,
            threads: self.threads,
            out: self.out,
            save_renders: self.save_renders,
            command: std::env::args().collect(),
        };
        config.validate()?;
        Ok((config, notes, self.quiet))
    }
}

/// The scenes of `all` called `names`, in the order given.
fn picked(all: &[StudyScene], names: &[String]) -> Result<Vec<StudyScene>> {
    let mut out: Vec<StudyScene> = Vec::new();
    for name in names.iter().map(|s| s.trim()).filter(|s| !s.is_empty()) {
        if name == "none" {
            continue;
        }
        let Some(scene) = all.iter().find(|s| s.name == name) else {
            let known: Vec<&str> = all.iter().map(|s| s.name.as_str()).collect();
            bail!(
                "unknown scene `{name}` in --scenes; known: {}",
                known.join(", ")
            );
        };
        if !available(scene) {
            bail!("scene `{name}` needs files that are absent (see --shared)");
        }
        if !out.iter().any(|s| s.name == name) {
            out.push(scene.clone());
        }
    }
    Ok(out)
}

/// Runs the study and writes its folder, printing progress and the files
/// written unless `--quiet`.
pub fn run(args: StudyArgs) -> Result<()> {
    let (config, notes, quiet) = args.into_config()?;
    let reporter = Reporter::new(quiet);
    for note in &notes {
        reporter.note(note);
    }
    let results = run_study(&config, &reporter)?;
    let files = write::write_all(&config, &results)?;
    reporter.summary(&files);
    Ok(())
}
