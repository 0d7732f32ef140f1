//! `lowdisc experiment`: the paper's experiment, run on one machine
//! ([`one_machine`]) or cut into units that any scheduler runs ([`units`]).

use anyhow::Result;
use clap::Args;

mod one_machine;
mod units;

use one_machine::ExperimentArgs;
pub use one_machine::LONG_ABOUT;
use units::Action;

/// `experiment`: the one-machine run, or one of the subcommands of a run
/// cut into units ([`units`]).
#[derive(Debug, Args)]
#[command(args_conflicts_with_subcommands = true)]
pub struct ExperimentCommand {
    /// A subcommand of the run cut into units.
    #[command(subcommand)]
    action: Option<Action>,
    /// The one-machine run's arguments.
    #[command(flatten)]
    args: ExperimentArgs,
}

impl ExperimentCommand {
    /// Runs the one-machine experiment or the subcommand.
    pub fn run(self) -> Result<()> {
        match self.action {
            Some(action) => units::run(action, std::io::stdout().lock()),
            None => one_machine::run(&self.args.into_config()?),
        }
    }
}
