//! `lowdisc experiment plan|unit|merge|status`: the experiment cut into
//! independent units that any scheduler runs (a Slurm job array, GNU
//! parallel, a shell loop), and merged into the one-machine run's report.
//! The work is in `lowdisc_experiment::{planned, units, status}`; this
//! module parses the arguments and prints.

use std::io::Write;
use std::path::PathBuf;

use anyhow::Result;
use clap::{Args, Subcommand};
use lowdisc_experiment::status::{Status, UnitState};
use lowdisc_experiment::units::UnitRun;

use super::one_machine::{Experiment, ExperimentArgs, print_answer};
use crate::progress::{Reporter, duration, si};

/// The long help of `experiment plan`.
pub const PLAN_ABOUT: &str = "\
Cut the experiment into independent units and write DIR/plan.json (DIR is\n\
--out): every option of `experiment` is accepted and kept in the plan, so\n\
`unit`, `merge` and `status` need only DIR. A unit is one render: one\n\
sampler x seed, one threshold x seed of the sweep, or a piece of the\n\
reference, of the convergence reference (each unless cached) or of one\n\
sampler x spp of a convergence series: a render of more camera samples than\n\
--unit-samples is cut into bands of tile rows (a reference also into sample\n\
ranges) whose exact sums the merge adds. There is no calibration render. Prints the unit count;\n\
then run `lowdisc experiment unit DIR --index I` for I in 0..count-1 (in any\n\
order, on any machine sharing DIR) and `lowdisc experiment merge DIR`.";

/// The long help of `experiment unit`.
pub const UNIT_ABOUT: &str = "\
Run unit I of the plan in DIR: its image (I.pfm, or I.exr with the exact\n\
sums of a piece) and record (I.json) go to DIR/units/ (I with four digits),\n\
written atomically. A unit already done is\n\
skipped, so reruns after a failure are safe. While it runs, DIR/units/I.lock\n\
holds its pid, host and start time; a failure is recorded in I.failed. The\n\
images do not depend on --threads.";

/// `experiment`'s subcommands.
#[derive(Debug, Subcommand)]
pub enum Action {
    /// Cut the experiment into independent units: DIR/plan.json (DIR = --out).
    #[command(long_about = PLAN_ABOUT)]
    Plan(Box<ExperimentArgs>),
    /// Run one unit of a plan (idempotent).
    #[command(long_about = UNIT_ABOUT)]
    Unit(UnitArgs),
    /// Check that every unit is done and write the one-machine run's report to DIR.
    Merge(MergeArgs),
    /// Units done, running, stale, failed and pending, and the time left.
    Status(StatusArgs),
}

/// The arguments of `experiment unit`.
#[derive(Debug, Args)]
pub struct UnitArgs {
    /// The plan's folder (holding plan.json).
    dir: PathBuf,
    /// The unit's index, 0 to count-1 (e.g. $SLURM_ARRAY_TASK_ID).
    #[arg(long, value_name = "I")]
    index: usize,
    /// Worker threads [default: the plan's, else all cores].
    #[arg(long, value_name = "T")]
    threads: Option<usize>,
    /// No progress on stderr.
    #[arg(long, short = 'q')]
    quiet: bool,
}

/// The arguments of `experiment merge`.
#[derive(Debug, Args)]
pub struct MergeArgs {
    /// The plan's folder (holding plan.json).
    dir: PathBuf,
    /// No progress or summary on stderr.
    #[arg(long, short = 'q')]
    quiet: bool,
}

/// The arguments of `experiment status`.
#[derive(Debug, Args)]
pub struct StatusArgs {
    /// The plan's folder (holding plan.json).
    dir: PathBuf,
}

/// Runs one of the subcommands.
pub fn run(action: Action, out: impl Write) -> Result<()> {
    match action {
        Action::Plan(args) => plan(&args.into_config()?, out),
        Action::Unit(args) => unit(&args, out),
        Action::Merge(args) => {
            let reporter = Reporter::new(args.quiet);
            let outcome = lowdisc_experiment::planned::merge(&args.dir, &reporter)?;
            reporter.summary(&outcome.files);
            print_answer(&outcome, out)
        }
        Action::Status(args) => {
            let status = lowdisc_experiment::status::status(&args.dir)?;
            print_status(&status, &args.dir, out)
        }
    }
}

fn plan(experiment: &Experiment, mut out: impl Write) -> Result<()> {
    let reporter = Reporter::new(experiment.quiet());
    let config = experiment.config();
    let file = lowdisc_experiment::planned::make_plan(config, &reporter)?;
    let n = file.plan.units.len();
    let dir = config.out.display();
    writeln!(
        out,
        "plan {}: {n} units (indices 0 to {}), {} camera samples, in {dir}/plan.json",
        file.id,
        n.saturating_sub(1),
        si(file.plan.samples() as f64).trim_end()
    )?;
    writeln!(
        out,
        "next: lowdisc experiment unit {dir} --index I (I = 0..{}), then lowdisc experiment merge {dir}",
        n.saturating_sub(1)
    )?;
    Ok(())
}

fn unit(args: &UnitArgs, mut out: impl Write) -> Result<()> {
    let reporter = Reporter::new(args.quiet);
    let run = lowdisc_experiment::units::run_unit(&args.dir, args.index, args.threads, &reporter)?;
    match run {
        UnitRun::Rendered(r) => writeln!(
            out,
            "unit {} ({}): done in {}",
            r.index,
            r.work,
            duration(r.wall_time_s)
        )?,
        UnitRun::AlreadyDone(r) => writeln!(out, "unit {} ({}): already done", r.index, r.work)?,
    }
    Ok(())
}

fn print_status(status: &Status, dir: &std::path::Path, mut out: impl Write) -> Result<()> {
    let done = status.count(|s| matches!(s, UnitState::Done(_)));
    let running = status.count(|s| matches!(s, UnitState::Running(_)));
    let stale = status.count(|s| matches!(s, UnitState::Stale(_)));
    let failed = status.count(|s| matches!(s, UnitState::Failed(_)));
    let pending = status.count(|s| matches!(s, UnitState::Pending));
    writeln!(
        out,
        "plan {}: {} units: {done} done, {running} running, {stale} stale, {failed} failed, {pending} pending",
        status.plan_id,
        status.units.len()
    )?;
    let now = lowdisc_experiment::units::lock::unix_now();
    for (i, (work, state)) in status.units.iter().enumerate() {
        match state {
            UnitState::Running(h) => writeln!(
                out,
                "running: unit {i} ({work}): pid {} on {} for {}",
                h.pid,
                h.host,
                duration(now.saturating_sub(h.start_unix_s) as f64)
            )?,
            UnitState::Stale(h) => writeln!(
                out,
                "stale: unit {i} ({work}): pid {} on {} is gone; rerun the unit",
                h.pid, h.host
            )?,
            UnitState::Failed(e) => writeln!(out, "failed: unit {i} ({work}): {e}")?,
            UnitState::Done(_) | UnitState::Pending => {}
        }
    }
    match &status.eta {
        _ if done == status.units.len() => writeln!(
            out,
            "all units done: lowdisc experiment merge {}",
            dir.display()
        )?,
        Some(eta) => writeln!(
            out,
            "ETA: {} ({} of units left, {} at once; {:.3} µs per camera sample measured)",
            duration(eta.seconds),
            duration(eta.unit_seconds_left),
            eta.parallel,
            eta.seconds_per_sample * 1e6
        )?,
        None => writeln!(out, "ETA: unknown until a unit is done")?,
    }
    Ok(())
}
