//! `DIR/plan.json`: a [`Plan`] on disk, complete enough that the units and
//! the merge need no other option.
//!
//! Schema (format `lowdisc-experiment-plan`, version 3):
//!
//! ```text
//! { format: "lowdisc-experiment-plan", version: 3,
//!   id: "16 hex digits: FNV-1a of every field below",
//!   lowdisc_version: "0.1.0"   (units and merge refuse another version),
//!   cwd: "/abs/folder"         (relative scene and envmap paths start here),
//!   scene_hash: "16 hex digits" (the scene's content; units check it),
//!   settings: { scene: path|null, preset: name|null, emitter_border,
//!     blur_sigma, samplers: [names], spp, runs, resolution: [w, h],
//!     ref_spp, conv_max, conv_res: [w, h], conv_seeds, conv_ref_spp,
//!     envmap: path|null,
//!     threshold, max_depth, threads: n|null, spectral,
//!     net: { name, id: "16 hex digits", columns: [[32 words] per
//!       dimension] } | absent (the built-in Sobol matrices),
//!     unit_samples: n|null (--unit-samples; null: the default budget),
//!     command: [args] },
//!   cached: [main, convergence]  (references cached when planned: no units),
//!   unit_count: N, samples: camera samples of all units,
//!   units: [ { index, kind: "reference", target: "main"|"convergence",
//!              band, bands, range, ranges }
//!          | { index, kind: "run", sampler, seed }
//!          | { index, kind: "sweep", threshold, seed }
//!          | { index, kind: "convergence", sampler, seed, spp, band, bands } ] }
//! ```
//!
//! A reference unit renders band `band` of `bands` (consecutive whole rows
//! of 16-pixel tiles, from the top, as equal in number as they can be) over
//! sample range `range` of `ranges` (sample indices from `range * spp /
//! ranges` up to `(range + 1) * spp / ranges`, each rounded down); a
//! convergence unit renders band `band` of `bands` of its point with every
//! sample. How a render is cut
//! ([`crate::cut::cut`]): a render of at most the unit budget is one unit;
//! a larger one is cut into bands of as many rows of tiles as fit the
//! budget, and when one row of tiles alone holds more, into one band per
//! row of tiles, each (references only) in the fewest equal sample ranges
//! that fit. The budget is `unit_samples`, else the larger of a run's camera
//! samples (runs and sweep renders are never cut) and 2^23.
//!
//! Each unit also lists its `resolution` and `samples` (a scheduler may
//! balance by them; they are recomputed from the settings, not trusted).
//! Floats are written in shortest round-trip form and read back exactly.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use lowdisc::catalog::SamplerName;
use lowdisc::net::{DigitalNet, Net};
use lowdisc_render::preset::ScenePreset;
use serde::{Deserialize, Serialize};

use super::{Plan, Target, Unit, Work, units};
use crate::config::ExperimentConfig;
use crate::cut::{Cut, Piece};
use crate::stats::{FNV_OFFSET, fnv1a};

/// The `format` field of `plan.json`.
pub const FORMAT: &str = "lowdisc-experiment-plan";
/// The schema version this build writes and reads.
pub const VERSION: u32 = 3;

/// A plan with where it was made, as read from or written to `plan.json`.
#[derive(Debug, Clone)]
pub struct PlanFile {
    /// The plan (its config's `out` is the plan's folder).
    pub plan: Plan,
    /// The folder relative paths of the settings start from.
    pub cwd: PathBuf,
    /// The plan's identity ([`Document::id`]).
    pub id: String,
}

#[derive(Debug, Serialize, Deserialize)]
struct Settings {
    scene: Option<PathBuf>,
    preset: Option<String>,
    emitter_border: u32,
    blur_sigma: f64,
    samplers: Vec<String>,
    spp: u32,
    runs: u32,
    resolution: [u32; 2],
    ref_spp: u32,
    conv_max: u32,
    conv_res: [u32; 2],
    conv_seeds: u32,
    conv_ref_spp: u32,
    envmap: Option<PathBuf>,
    threshold: f64,
    max_depth: u32,
    threads: Option<usize>,
    /// Spectral rendering (`--spectral`); absent in plans that predate it.
    #[serde(default)]
    spectral: bool,
    /// `--approximate`; absent in plans that predate it.
    #[serde(default)]
    approximate: bool,
    /// `--net`'s matrices; absent for the built-in Sobol table.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    net: Option<NetDoc>,
    unit_samples: Option<u64>,
    command: Vec<String>,
}

/// A net written out in full, so units need no file of its own.
#[derive(Debug, Serialize, Deserialize)]
struct NetDoc {
    name: String,
    id: String,
    columns: Vec<[u32; 32]>,
}

impl NetDoc {
    /// The document of `net`, `None` for the built-in table.
    fn of(net: Net) -> Option<NetDoc> {
        net.id().map(|id| NetDoc {
            name: net.name().to_string(),
            id: format!("{id:016x}"),
            columns: net.columns().to_vec(),
        })
    }

    /// The net again, checked against its recorded id.
    fn net(self) -> Result<Net> {
        let net = DigitalNet::from_columns(&self.name, self.columns)?;
        let id = format!("{:016x}", net.id());
        if id != self.id {
            bail!(
                "net `{}`: the matrices hash to {id}, not the recorded {}",
                self.name,
                self.id
            );
        }
        Ok(net.into_net())
    }
}

#[derive(Debug, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
enum UnitDoc {
    Reference {
        target: String,
        band: u32,
        bands: u32,
        range: u32,
        ranges: u32,
    },
    Run {
        sampler: String,
        seed: u64,
    },
    Sweep {
        threshold: f64,
        seed: u64,
    },
    Convergence {
        sampler: String,
        seed: u64,
        spp: u32,
        band: u32,
        bands: u32,
    },
}

#[derive(Debug, Serialize, Deserialize)]
struct UnitEntry {
    index: usize,
    #[serde(flatten)]
    work: UnitDoc,
    resolution: [u32; 2],
    samples: u64,
}

/// The JSON document.
#[derive(Debug, Serialize, Deserialize)]
struct Document {
    format: String,
    version: u32,
    id: String,
    lowdisc_version: String,
    cwd: PathBuf,
    scene_hash: String,
    settings: Settings,
    cached: [bool; 2],
    unit_count: usize,
    samples: u64,
    units: Vec<UnitEntry>,
}

impl Document {
    /// The FNV-1a hash of every field but `id`, as 16 hex digits.
    fn id(&self) -> Result<String> {
        let body = serde_json::to_string(&(
            &self.format,
            self.version,
            &self.lowdisc_version,
            &self.cwd,
            &self.scene_hash,
            &self.settings,
            self.cached,
            &self.units,
        ))?;
        Ok(format!("{:016x}", fnv1a(FNV_OFFSET, body.as_bytes())))
    }
}

fn sampler(name: &str) -> Result<SamplerName> {
    name.parse()
        .map_err(|_| anyhow::anyhow!("unknown sampler `{name}`"))
}

fn unit_doc(work: &Work) -> UnitDoc {
    match *work {
        Work::Reference { target, piece } => UnitDoc::Reference {
            target: match target {
                Target::Main => "main",
                Target::Convergence => "convergence",
            }
            .into(),
            band: piece.band,
            bands: piece.cut.bands,
            range: piece.range,
            ranges: piece.cut.ranges,
        },
        Work::Run { sampler, seed } => UnitDoc::Run {
            sampler: sampler.as_str().into(),
            seed,
        },
        Work::Sweep { threshold, seed } => UnitDoc::Sweep { threshold, seed },
        Work::Convergence {
            sampler,
            seed,
            spp,
            piece,
        } => UnitDoc::Convergence {
            sampler: sampler.as_str().into(),
            seed,
            spp,
            band: piece.band,
            bands: piece.cut.bands,
        },
    }
}

fn work_of(doc: &UnitDoc) -> Result<Work> {
    Ok(match doc {
        UnitDoc::Reference {
            target,
            band,
            bands,
            range,
            ranges,
        } => Work::Reference {
            target: match target.as_str() {
                "main" => Target::Main,
                "convergence" => Target::Convergence,
                other => bail!("unknown reference target `{other}`"),
            },
            piece: Piece {
                band: *band,
                range: *range,
                cut: Cut {
                    bands: *bands,
                    ranges: *ranges,
                },
            },
        },
        UnitDoc::Run { sampler: s, seed } => Work::Run {
            sampler: sampler(s)?,
            seed: *seed,
        },
        UnitDoc::Sweep { threshold, seed } => Work::Sweep {
            threshold: *threshold,
            seed: *seed,
        },
        UnitDoc::Convergence {
            sampler: s,
            seed,
            spp,
            band,
            bands,
        } => Work::Convergence {
            sampler: sampler(s)?,
            seed: *seed,
            spp: *spp,
            piece: Piece {
                band: *band,
                range: 0,
                cut: Cut {
                    bands: *bands,
                    ranges: 1,
                },
            },
        },
    })
}

fn settings(c: &ExperimentConfig) -> Settings {
    Settings {
        scene: c.scene.clone(),
        preset: c.preset.map(|p| p.name().to_string()),
        emitter_border: c.emitter_border,
        blur_sigma: c.blur_sigma,
        samplers: c.samplers.iter().map(|s| s.as_str().to_string()).collect(),
        spp: c.spp,
        runs: c.runs,
        resolution: c.resolution,
        ref_spp: c.ref_spp,
        conv_max: c.conv_max,
        conv_res: c.conv_res,
        conv_seeds: c.conv_seeds,
        conv_ref_spp: c.conv_ref_spp,
        envmap: c.envmap.clone(),
        threshold: c.threshold,
        max_depth: c.max_depth,
        threads: c.threads,
        spectral: c.spectral,
        approximate: c.approximate,
        net: NetDoc::of(c.net),
        unit_samples: c.unit_samples,
        command: c.command.clone(),
    }
}

fn config(s: Settings, out: &Path) -> Result<ExperimentConfig> {
    let preset = match &s.preset {
        Some(name) => {
            Some(ScenePreset::from_name(name).with_context(|| format!("unknown preset `{name}`"))?)
        }
        None => None,
    };
    Ok(ExperimentConfig {
        scene: s.scene,
        preset,
        emitter_border: s.emitter_border,
        blur_sigma: s.blur_sigma,
        samplers: s
            .samplers
            .iter()
            .map(|n| sampler(n))
            .collect::<Result<_>>()?,
        net: s.net.map_or(Ok(Net::SOBOL), NetDoc::net)?,
        spp: s.spp,
        runs: s.runs,
        resolution: s.resolution,
        ref_spp: s.ref_spp,
        conv_max: s.conv_max,
        conv_res: s.conv_res,
        conv_seeds: s.conv_seeds,
        conv_ref_spp: s.conv_ref_spp,
        envmap: s.envmap,
        approximate: s.approximate,
        threshold: s.threshold,
        max_depth: s.max_depth,
        threads: s.threads,
        spectral: s.spectral,
        unit_samples: s.unit_samples,
        out: out.to_path_buf(),
        command: s.command,
    })
}

fn document(plan: &Plan, cwd: &Path) -> Result<Document> {
    let c = &plan.config;
    let mut doc = Document {
        format: FORMAT.into(),
        version: VERSION,
        id: String::new(),
        lowdisc_version: env!("CARGO_PKG_VERSION").into(),
        cwd: cwd.to_path_buf(),
        scene_hash: format!("{:016x}", plan.scene_hash),
        settings: settings(c),
        cached: plan.cached,
        unit_count: plan.units.len(),
        samples: plan.samples(),
        units: plan
            .units
            .iter()
            .map(|u| UnitEntry {
                index: u.index,
                work: unit_doc(&u.work),
                resolution: u.resolution(c),
                samples: u.samples(c),
            })
            .collect(),
    };
    doc.id = doc.id()?;
    Ok(doc)
}

impl PlanFile {
    /// The plan made in folder `cwd`, with its identity.
    pub fn new(plan: Plan, cwd: PathBuf) -> Result<PlanFile> {
        let id = document(&plan, &cwd)?.id;
        Ok(PlanFile { plan, cwd, id })
    }

    /// The text of `plan.json`.
    pub fn to_json(&self) -> Result<String> {
        Ok(serde_json::to_string_pretty(&document(&self.plan, &self.cwd)?)? + "\n")
    }

    /// Parses the text of `DIR/plan.json` (`dir` becomes the config's
    /// `out`); checks the format, version, identity and that the units are
    /// exactly those of the settings.
    pub fn parse(text: &str, dir: &Path) -> Result<PlanFile> {
        let doc: Document = serde_json::from_str(text)?;
        if doc.format != FORMAT || doc.version != VERSION {
            bail!(
                "not a version-{VERSION} experiment plan (format `{}`, version {})",
                doc.format,
                doc.version
            );
        }
        if doc.lowdisc_version != env!("CARGO_PKG_VERSION") {
            bail!(
                "the plan was made by lowdisc {}, this is {}; plan again",
                doc.lowdisc_version,
                env!("CARGO_PKG_VERSION")
            );
        }
        if doc.id()? != doc.id {
            bail!("its id {} does not match its content (edited?)", doc.id);
        }
        let scene_hash = u64::from_str_radix(&doc.scene_hash, 16)
            .with_context(|| format!("bad scene_hash `{}`", doc.scene_hash))?;
        let listed = doc
            .units
            .iter()
            .map(|u| work_of(&u.work))
            .collect::<Result<Vec<_>>>()?;
        let config = config(doc.settings, dir)?;
        config.validate_ranges()?;
        let plan = Plan::new(config, scene_hash, doc.cached);
        let expected: Vec<Work> = units(&plan.config, plan.cached)
            .iter()
            .map(|u| u.work)
            .collect();
        let indices_ok = doc.units.iter().enumerate().all(|(i, u)| u.index == i);
        if listed != expected || !indices_ok || doc.unit_count != plan.units.len() {
            bail!("its units are not those of its settings");
        }
        Ok(PlanFile {
            plan,
            cwd: doc.cwd,
            id: doc.id,
        })
    }

    /// Reads `DIR/plan.json`; errors name the file.
    pub fn read(dir: &Path) -> Result<PlanFile> {
        let path = dir.join("plan.json");
        let text = lowdisc_files::read_input(&path)
            .map_err(anyhow::Error::from)
            .and_then(|b| String::from_utf8(b).context("not UTF-8"))
            .with_context(|| format!("cannot read the plan `{}`", path.display()))?;
        PlanFile::parse(&text, dir).with_context(|| format!("bad plan `{}`", path.display()))
    }

    /// The config with relative scene and envmap paths made absolute from
    /// [`PlanFile::cwd`], for loading the scene in any folder.
    pub fn loading_config(&self) -> ExperimentConfig {
        let mut c = self.plan.config.clone();
        let absolute = |p: &mut Option<PathBuf>| {
            if let Some(path) = p.as_mut().filter(|p| p.is_relative()) {
                *path = self.cwd.join(&*path);
            }
        };
        absolute(&mut c.scene);
        absolute(&mut c.envmap);
        c
    }

    /// The unit `unit` as it would appear in the plan: to check a unit
    /// file against.
    pub fn unit(&self, index: usize) -> Result<&Unit> {
        self.plan.unit(index)
    }
}
