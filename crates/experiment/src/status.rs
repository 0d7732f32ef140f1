//! The progress of a planned experiment (`lowdisc experiment status`):
//! each unit's state from its files (record, lock, failure) and an
//! estimate of the time left from the wall times the finished units
//! measured, per camera sample.

use std::path::Path;

use anyhow::Result;

use crate::plan::file::PlanFile;
use crate::units::lock::{Holder, Liveness, holder};
use crate::units::store::Store;

/// The state of one unit.
#[derive(Debug, Clone, PartialEq)]
pub enum UnitState {
    /// Finished, in this many seconds of wall time.
    Done(f64),
    /// Its lock is held by a live process (or one on another host).
    Running(Holder),
    /// Its lock's process (on this host) is gone.
    Stale(Holder),
    /// Its last attempt failed with this error (or its record is broken).
    Failed(String),
    /// Not started.
    Pending,
}

/// The estimate of the time left.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Eta {
    /// Measured wall seconds per camera sample of the finished units.
    pub seconds_per_sample: f64,
    /// Wall seconds of the units not done, one after the other.
    pub unit_seconds_left: f64,
    /// Units running now (at least 1): the parallelism assumed.
    pub parallel: usize,
    /// `unit_seconds_left / parallel`.
    pub seconds: f64,
}

/// The state of every unit of a plan.
#[derive(Debug, Clone)]
pub struct Status {
    /// The plan's id.
    pub plan_id: String,
    /// Each unit's state, by index, with its description.
    pub units: Vec<(String, UnitState)>,
    /// `None` until a unit is done.
    pub eta: Option<Eta>,
}

impl Status {
    /// How many units are in a state matching `which`.
    pub fn count(&self, which: fn(&UnitState) -> bool) -> usize {
        self.units.iter().filter(|(_, s)| which(s)).count()
    }
}

/// The status of the plan in `dir`.
pub fn status(dir: &Path) -> Result<Status> {
    let plan = PlanFile::read(dir)?;
    let config = &plan.plan.config;
    let store = Store::new(dir, plan.plan.units.len());
    let mut units = Vec::new();
    let (mut done_time, mut done_samples, mut left_samples) = (0.0, 0u64, 0u64);
    for unit in &plan.plan.units {
        let i = unit.index;
        let state = match store.record(i, &plan.id) {
            Ok(Some(r)) => UnitState::Done(r.wall_time_s),
            Err(e) => UnitState::Failed(format!("{e:#}")),
            Ok(None) => match holder(&store.file(i, "lock")) {
                Some(h) if h.liveness() == Liveness::Stale => UnitState::Stale(h),
                Some(h) => UnitState::Running(h),
                None => store
                    .failure(i)
                    .map_or(UnitState::Pending, UnitState::Failed),
            },
        };
        let samples = unit.samples(config);
        if let UnitState::Done(t) = state {
            done_time += t;
            done_samples += samples;
        } else {
            left_samples += samples;
        }
        units.push((unit.work.describe(), state));
    }
    let mut status = Status {
        plan_id: plan.id,
        units,
        eta: None,
    };
    if done_samples > 0 {
        let seconds_per_sample = done_time / done_samples as f64;
        let unit_seconds_left = seconds_per_sample * left_samples as f64;
        let parallel = status.count(|s| matches!(s, UnitState::Running(_))).max(1);
        status.eta = Some(Eta {
            seconds_per_sample,
            unit_seconds_left,
            parallel,
            seconds: unit_seconds_left / parallel as f64,
        });
    }
    Ok(status)
}
