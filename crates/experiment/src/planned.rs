//! The experiment cut into units in a folder: [`make_plan`] writes
//! `DIR/plan.json` (`lowdisc experiment plan`), [`crate::units::run_unit`]
//! runs one unit (`lowdisc experiment unit`), and [`merge`] checks that
//! every unit is done and writes the report of the one-machine run
//! (`lowdisc experiment merge`) into `DIR`, through the same
//! [`crate::assemble()`]. `status` is in [`crate::status`].

use std::path::Path;
use std::time::Instant;

use anyhow::{Context, Result, bail};

use crate::assemble::{Outcome, report};
use crate::config::ExperimentConfig;
use crate::plan::Plan;
use crate::plan::file::PlanFile;
use crate::progress::Progress;
use crate::reference::cached_references;
use crate::source::Measures;
use crate::subject::load;
use crate::units::store::Store;
use crate::units::{FromFiles, planned_scene};

/// Writes the plan of `config` to `config.out/plan.json` and creates the
/// units folder. Relative paths of the plan start at the current folder.
/// A folder that already holds the same plan keeps it (with its cached
/// flags as they were); a folder holding another plan is refused.
pub fn make_plan(config: &ExperimentConfig, observer: &dyn Progress) -> Result<PlanFile> {
    config.validate()?;
    let cwd = std::env::current_dir().context("cannot read the current folder")?;
    let (_, scene_hash) = load(config, observer)?;
    let dir = &config.out;
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create `{}`", dir.display()))?;
    let path = dir.join("plan.json");
    if path.exists() {
        let existing = PlanFile::read(dir)?;
        let again = Plan::new(config.clone(), scene_hash, existing.plan.cached);
        if PlanFile::new(again, cwd)?.id != existing.id {
            bail!(
                "`{}` holds another plan (id {}); choose another --out or remove that folder",
                path.display(),
                existing.id
            );
        }
        observer.note(&format!("{} already holds this plan", path.display()));
        return Ok(existing);
    }
    let cached = cached_references(config, scene_hash);
    let file = PlanFile::new(Plan::new(config.clone(), scene_hash, cached), cwd)?;
    lowdisc_files::write_bytes(&path, file.to_json()?.as_bytes())?;
    Store::new(dir, file.plan.units.len()).create()?;
    Ok(file)
}

/// The indices of `indices` as text, the first `limit` of them.
fn list(indices: &[usize], limit: usize) -> String {
    let mut s: Vec<String> = indices.iter().take(limit).map(|i| i.to_string()).collect();
    if indices.len() > limit {
        s.push("...".into());
    }
    s.join(", ")
}

/// Merges the units of the plan in `dir` into the report of the
/// one-machine run, written to `dir`. Its wall time is the sum of the
/// units' wall times and the merge's own.
pub fn merge(dir: &Path, observer: &dyn Progress) -> Result<Outcome> {
    let start = Instant::now();
    let plan = PlanFile::read(dir)?;
    let store = Store::new(dir, plan.plan.units.len());
    let mut missing = Vec::new();
    let mut unit_time = 0.0;
    for unit in &plan.plan.units {
        match store.record(unit.index, &plan.id)? {
            Some(r) => unit_time += r.wall_time_s,
            None => missing.push(unit.index),
        }
    }
    if !missing.is_empty() {
        bail!(
            "{} of the plan's {} units are not done (units {}); run them, then merge again",
            missing.len(),
            plan.plan.units.len(),
            list(&missing, 12)
        );
    }
    let (_, subject) = planned_scene(&plan, None, observer)?;
    let measures = Measures::new(&plan.plan, &subject)?;
    let mut source = FromFiles {
        plan: &plan,
        store: &store,
    };
    let wall = || unit_time + start.elapsed().as_secs_f64();
    report(&plan.plan, &measures, &mut source, observer, &wall)
}
