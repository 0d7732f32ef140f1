//! The files of a plan's units in `DIR/units/`, for unit `I` (four digits,
//! more when the plan has 10 000 units or more):
//!
//! - `I.pfm`: the image of a run or a sweep render, linear radiance as
//!   32-bit floats (exact);
//! - `I.exr`: instead, for a piece of a cut reference or convergence point,
//!   a part file of `lowdisc-split` (its pixels' exact `f64` sums over its
//!   sample range, and a header naming the plan's scene hash, the settings,
//!   the window and the range), merged with the other pieces;
//! - `I.json`: its record, written after the image, so a unit is done
//!   exactly when a record of this plan names an image of the recorded
//!   hash: `{ format: "lowdisc-experiment-unit", version: 1, plan_id,
//!   index, work (as `status` prints it), image: "I.pfm" or "I.exr",
//!   image_fnv1a, samples, render_time_s, wall_time_s, host, pid,
//!   finished_unix_s }`;
//! - `I.lock`: present while a process runs the unit ([`super::lock`]);
//! - `I.failed`: the error of the last failed attempt, removed on success.
//!
//! Every file is written to a temporary sibling and renamed into place, so
//! no file is ever partial.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use lowdisc_image::ImageFormat;
use lowdisc_split::{decode_part, encode_part};
use serde::{Deserialize, Serialize};

use crate::source::Rendered;
use crate::stats::{FNV_OFFSET, fnv1a};

/// The `format` field of a unit record.
pub const FORMAT: &str = "lowdisc-experiment-unit";

/// The record of a finished unit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Record {
    /// Always [`FORMAT`].
    pub format: String,
    /// Schema version, 1.
    pub version: u32,
    /// The id of the plan the unit belongs to.
    pub plan_id: String,
    /// The unit's index in that plan.
    pub index: usize,
    /// What it rendered ([`crate::plan::Work::describe`]).
    pub work: String,
    /// The image file's name (in the same folder).
    pub image: String,
    /// FNV-1a of the image file's bytes, 16 hex digits.
    pub image_fnv1a: String,
    /// Camera samples rendered.
    pub samples: u64,
    /// The render's own time, seconds (what `results.json` reports).
    pub render_time_s: f64,
    /// The unit's whole time (scene loading, render, writing), seconds.
    pub wall_time_s: f64,
    /// The machine that ran it.
    pub host: String,
    /// The process that ran it.
    pub pid: u32,
    /// When it finished, seconds since 1970.
    pub finished_unix_s: u64,
}

/// The units folder of a plan folder, and the names of its files.
#[derive(Debug, Clone)]
pub struct Store {
    dir: PathBuf,
    digits: usize,
}

impl Store {
    /// The store of the plan in `plan_dir` with `count` units.
    pub fn new(plan_dir: &Path, count: usize) -> Store {
        let digits = count.saturating_sub(1).to_string().len().max(4);
        Store {
            dir: plan_dir.join("units"),
            digits,
        }
    }

    /// `DIR/units`.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// `DIR/units/I.EXT`.
    pub fn file(&self, index: usize, ext: &str) -> PathBuf {
        self.dir
            .join(format!("{index:0width$}.{ext}", width = self.digits))
    }

    /// Creates the folder.
    pub fn create(&self) -> Result<()> {
        std::fs::create_dir_all(&self.dir)
            .with_context(|| format!("cannot create `{}`", self.dir.display()))
    }

    /// The record of unit `index` if it is done for plan `plan_id`: `None`
    /// when there is no record; an error when there is one that is broken
    /// or belongs to another plan.
    pub fn record(&self, index: usize, plan_id: &str) -> Result<Option<Record>> {
        let path = self.file(index, "json");
        if !path.exists() {
            return Ok(None);
        }
        let record = read_record(&path)?;
        if record.plan_id != plan_id || record.index != index || record.format != FORMAT {
            bail!(
                "`{}` is unit {} of plan {}, not unit {index} of this plan {plan_id}",
                path.display(),
                record.index,
                record.plan_id
            );
        }
        Ok(Some(record))
    }

    /// The render a done unit left, its file checked against its record's
    /// hash: an image (`.pfm`) or a piece's sums (`.exr`).
    pub fn read(&self, record: &Record) -> Result<Rendered> {
        let path = self.dir.join(&record.image);
        let bytes = lowdisc_files::read_input(&path)?;
        if format!("{:016x}", fnv1a(FNV_OFFSET, &bytes)) != record.image_fnv1a {
            bail!(
                "`{}` does not match its record (hash differs); rerun unit {}",
                path.display(),
                record.index
            );
        }
        let what = || format!("cannot read `{}`", path.display());
        if record.image.ends_with(".exr") {
            return Ok(Rendered::Sums(decode_part(&bytes).with_context(what)?));
        }
        let options = lowdisc_image::ReadOptions::default();
        let image = lowdisc_image::decode_image(&bytes, ImageFormat::Pfm, &options);
        Ok(Rendered::Image(image.with_context(what)?))
    }

    /// Writes the file of unit `index` (a `.pfm` image or a piece's `.exr`
    /// part file), then its record (whose image fields are filled in here).
    pub fn write(&self, mut record: Record, rendered: &Rendered) -> Result<Record> {
        let index = record.index;
        let (path, bytes) = match rendered {
            Rendered::Image(image) => {
                let options = lowdisc_image::WriteOptions::default();
                let bytes = lowdisc_image::encode_image(image, ImageFormat::Pfm, &options)?;
                (self.file(index, "pfm"), bytes)
            }
            Rendered::Sums(part) => (self.file(index, "exr"), encode_part(part)?),
        };
        lowdisc_files::write_bytes(&path, &bytes)?;
        record.image = file_name(&path);
        record.image_fnv1a = format!("{:016x}", fnv1a(FNV_OFFSET, &bytes));
        let text = serde_json::to_string_pretty(&record)? + "\n";
        lowdisc_files::write_bytes(self.file(index, "json"), text.as_bytes())?;
        Ok(record)
    }

    /// Records the error of a failed attempt at unit `index`.
    pub fn write_failure(&self, index: usize, error: &str) -> Result<()> {
        let text = format!("{}\n", error.replace('\n', " "));
        Ok(lowdisc_files::write_bytes(
            self.file(index, "failed"),
            text.as_bytes(),
        )?)
    }

    /// The error of the last failed attempt at unit `index`, if any.
    pub fn failure(&self, index: usize) -> Option<String> {
        let text = std::fs::read_to_string(self.file(index, "failed")).ok()?;
        Some(text.trim().to_string())
    }

    /// Removes the failure record of unit `index` (after a success).
    pub fn clear_failure(&self, index: usize) -> Result<()> {
        let path = self.file(index, "failed");
        match std::fs::remove_file(&path) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
                Err(e).with_context(|| format!("cannot remove `{}`", path.display()))
            }
            _ => Ok(()),
        }
    }
}

fn file_name(path: &Path) -> String {
    path.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default()
}

fn read_record(path: &Path) -> Result<Record> {
    let bytes = lowdisc_files::read_input(path)?;
    serde_json::from_slice(&bytes).with_context(|| format!("bad unit record `{}`", path.display()))
}
