//! Running the experiment on one machine: the scene, its plan of units
//! ([`crate::plan`]), each unit rendered in this process as
//! [`crate::assemble()`] needs it, and the report ([`crate::report`]). A
//! planned run ([`crate::planned`]) renders the same units elsewhere and
//! assembles them the same way.

use std::time::Instant;

use anyhow::{Context, Result};

use crate::assemble::{Outcome, report};
use crate::config::ExperimentConfig;
use crate::estimate::calibrate;
use crate::plan::Plan;
use crate::progress::Progress;
use crate::reference::cached_references;
use crate::source::Measures;
use crate::subject::load;
use crate::units::InProcess;

/// Runs the experiment and writes the report folder, telling `observer`
/// what it does.
pub fn run(config: &ExperimentConfig, observer: &dyn Progress) -> Result<Outcome> {
    config.validate()?;
    let start = Instant::now();
    let (subject, scene_hash) = load(config, observer)?;
    std::fs::create_dir_all(&config.out)
        .with_context(|| format!("cannot create `{}`", config.out.display()))?;
    let plan = Plan::new(
        config.clone(),
        scene_hash,
        cached_references(config, scene_hash),
    );
    observer.estimate(&calibrate(config, &subject, plan.samples())?);
    let measures = Measures::new(&plan, &subject)?;
    let mut source = InProcess {
        config,
        subject: &subject,
        scene_hash,
    };
    let wall = || start.elapsed().as_secs_f64();
    report(&plan, &measures, &mut source, observer, &wall)
}
