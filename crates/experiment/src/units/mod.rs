//! Running the units of a plan: [`render_unit`] renders one (the same
//! function for the one-machine run, through [`InProcess`], and for
//! `lowdisc experiment unit`, through [`run_unit`]); [`FromFiles`] hands the
//! finished units' renders to the merge.
//!
//! [`run_unit`] is idempotent and safe to rerun: a unit whose record and
//! file are in place is skipped; otherwise it takes the unit's lock
//! ([`lock`]), renders, writes the file and then the record ([`store`]),
//! records a failure in `I.failed`, and removes the lock in every case.

pub mod lock;
pub mod store;

use std::path::Path;
use std::time::Instant;

use anyhow::{Context, Result, bail};
use lowdisc_render::render::render;
use lowdisc_render::settings::Given;
use lowdisc_split::RenderPart;

use crate::config::ExperimentConfig;
use crate::plan::Unit;
use crate::plan::file::PlanFile;
use crate::progress::{Progress, Stage};
use crate::source::{Rendered, UnitOutput, UnitSource};
use crate::subject::{Subject, load};
use lock::{Lock, host_name, unix_now};
use store::{Record, Store};

/// Renders `unit` of the experiment `config` with `subject` (whose content
/// hashes to `scene_hash`), its view built at the unit's resolution, reporting
/// its samples to `stage`. A piece of a cut render renders its band's
/// pixels over its sample range and keeps their sums.
pub fn render_unit(
    config: &ExperimentConfig,
    subject: &Subject,
    scene_hash: u64,
    unit: &Unit,
    stage: &Stage,
) -> Result<UnitOutput> {
    let view = subject.view_at(unit.resolution(config))?;
    let mut settings = unit.settings(config);
    let keeps_sums = unit.work.keeps_sums();
    if keeps_sums {
        let window = unit.work.piece().window(view.pixel_bounds());
        if window.area() == 0 {
            // Bands are counted on the resolution; a crop window may hold
            // fewer rows of tiles.
            bail!(
                "the scene's crop window leaves unit {} (`{}`) no pixels; plan with a larger --unit-samples",
                unit.index,
                unit.work.describe()
            );
        }
        let from = format!("unit {}'s band", unit.index);
        settings.window = Some(Given::new(window, from));
    }
    let options = config.render_options(&settings)?;
    let out = render(&subject.scene, &view, &options, stage)?;
    stage.finished_render(out.stats.samples, out.stats.rays);
    let rendered = if keeps_sums {
        let name = format!("{scene_hash:016x}");
        Rendered::Sums(RenderPart::of_render(name, &view, &options, &out))
    } else {
        Rendered::Image(out.image)
    };
    Ok(UnitOutput {
        rendered,
        render_time_s: out.stats.time.as_secs_f64(),
    })
}

/// The units rendered in this process, one after the other, on one scene.
pub struct InProcess<'a> {
    /// The experiment.
    pub config: &'a ExperimentConfig,
    /// Its scene and view.
    pub subject: &'a Subject,
    /// The hash of the scene's content.
    pub scene_hash: u64,
}

impl UnitSource for InProcess<'_> {
    fn output(&mut self, unit: &Unit, stage: &Stage) -> Result<UnitOutput> {
        render_unit(self.config, self.subject, self.scene_hash, unit, stage)
    }
}

/// The finished units of a plan folder.
pub struct FromFiles<'a> {
    /// The plan.
    pub plan: &'a PlanFile,
    /// Its units' files.
    pub store: &'a Store,
}

impl UnitSource for FromFiles<'_> {
    fn output(&mut self, unit: &Unit, stage: &Stage) -> Result<UnitOutput> {
        let record = self
            .store
            .record(unit.index, &self.plan.id)?
            .with_context(|| format!("unit {} is not done", unit.index))?;
        let rendered = self.store.read(&record)?;
        stage.finished_render(record.samples, 0);
        Ok(UnitOutput {
            rendered,
            render_time_s: record.render_time_s,
        })
    }
}

/// What [`run_unit`] did.
#[derive(Debug, Clone)]
pub enum UnitRun {
    /// It rendered the unit.
    Rendered(Record),
    /// The unit was already done.
    AlreadyDone(Record),
}

/// Runs unit `index` of the plan in `dir` (see the module doc); `threads`
/// replaces the plan's thread count (the images do not depend on it).
pub fn run_unit(
    dir: &Path,
    index: usize,
    threads: Option<usize>,
    observer: &dyn Progress,
) -> Result<UnitRun> {
    let plan = PlanFile::read(dir)?;
    let unit = *plan.unit(index)?;
    let store = Store::new(dir, plan.plan.units.len());
    match store.record(index, &plan.id) {
        Ok(Some(record)) => match store.read(&record) {
            Ok(_) => return Ok(UnitRun::AlreadyDone(record)),
            Err(e) => observer.note(&format!("{e:#}: rendering it again")),
        },
        Ok(None) => {}
        Err(e) => observer.note(&format!("{e:#}: rendering it again")),
    }
    store.create()?;
    let lock = Lock::take(&store.file(index, "lock"))?;
    let result = render_and_write(&plan, &store, &unit, threads, observer);
    let recorded = match &result {
        Ok(_) => store.clear_failure(index),
        Err(e) => store.write_failure(index, &format!("{e:#}")),
    };
    let released = lock.release();
    let record = result?;
    recorded?;
    released?;
    Ok(UnitRun::Rendered(record))
}

/// The configuration of the plan for loading (`threads` replacing the
/// plan's thread count, if given) and its scene, checked to be the planned
/// one: what every unit and the merge start from.
pub fn planned_scene(
    plan: &PlanFile,
    threads: Option<usize>,
    observer: &dyn Progress,
) -> Result<(ExperimentConfig, Subject)> {
    let mut config = plan.loading_config();
    config.threads = threads.or(config.threads);
    config.validate()?;
    let (subject, hash) = load(&config, observer)?;
    check_scene(plan, hash)?;
    Ok((config, subject))
}

/// Loads the plan's scene, renders `unit` and writes its file and record.
fn render_and_write(
    plan: &PlanFile,
    store: &Store,
    unit: &Unit,
    threads: Option<usize>,
    observer: &dyn Progress,
) -> Result<Record> {
    let start = Instant::now();
    let (config, subject) = planned_scene(plan, threads, observer)?;
    let title = format!("unit {}: {}", unit.index, unit.work.describe());
    let stage = Stage::begin(observer, &title, unit.samples(&config));
    let hash = plan.plan.scene_hash;
    let out = render_unit(&config, &subject, hash, unit, &stage)?;
    stage.end();
    let record = Record {
        format: store::FORMAT.into(),
        version: 1,
        plan_id: plan.id.clone(),
        index: unit.index,
        work: unit.work.describe(),
        image: String::new(),
        image_fnv1a: String::new(),
        samples: unit.samples(&config),
        render_time_s: out.render_time_s,
        wall_time_s: start.elapsed().as_secs_f64(),
        host: host_name(),
        pid: std::process::id(),
        finished_unix_s: unix_now(),
    };
    store.write(record, &out.rendered)
}

/// Refuses a scene whose content hash is not the plan's.
pub fn check_scene(plan: &PlanFile, hash: u64) -> Result<()> {
    if hash != plan.plan.scene_hash {
        bail!(
            "the scene (or environment map) changed since the plan was made (content hash {hash:016x}, planned {:016x}); plan again",
            plan.plan.scene_hash
        );
    }
    Ok(())
}
