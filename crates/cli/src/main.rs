//! The `lowdisc` command-line tool.
//!
//! `main` parses the arguments with clap, turns the chosen subcommand's
//! arguments into a validated configuration (`into_config`), and runs it.
//! Every failure ends as one line `error: ...` on stderr and exit status 1
//! (clap's own usage errors exit with 2); a closed output pipe (`| head`)
//! ends quietly with status 0. SIGINT and SIGTERM remove the temporary files
//! of unfinished writes and exit with 130 and 143 (see `interrupt`).
//!
//! Adding a subcommand: a new module with an `Args` struct (clap derive),
//! `into_config` and `run`, plus one variant in [`Command`] and one arm in
//! [`run`].
//!
//! Modules, one per subcommand and a few shared ones:
//! - `points`, `figure`, `discrepancy` (its `rows`; with `pointfile`),
//!   `spectrum`, `claim` (its `measure` and `report`), `render_cmd` (with
//!   `render_stats`), `split_cmd` (`merge`, and the parts `render` writes),
//!   `experiment` (its `one_machine` run and its `units`: plan, unit, merge,
//!   status), `study`: the subcommands; the experiment and the study
//!   themselves are the library `lowdisc-experiment`; a folder's files
//!   import one way only;
//! - `parse`: parsers of structured values (`--pixel`, `--res`, ranges, names);
//! - `sampler_help`: the sampler lists of `--help`, from the catalog's table;
//! - `limits`: the default work and memory limits and their checks;
//! - `output`: tabular output of points (text, CSV, u32, JSON);
//! - `plots`: point-set scatter plots for `points --plot`;
//! - `progress`: bars on a terminal, timed lines elsewhere, the summary;
//! - `interrupt`: the SIGINT/SIGTERM handler that removes live temporaries.

mod claim;
mod default_output;
mod discrepancy;
mod experiment;
mod figure;
mod interrupt;
mod limits;
mod output;
mod parse;
mod plots;
mod pointfile;
mod points;
mod progress;
mod render_cmd;
mod render_stats;
mod sampler_help;
mod spectrum;
mod split_cmd;
mod study;

use std::io::{self, Write};
use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// Low-discrepancy sample sequences for Monte Carlo rendering.
#[derive(Debug, Parser)]
#[command(name = "lowdisc", version, about, propagate_version = true)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// The subcommands; each variant holds its module's clap arguments.
#[derive(Debug, Subcommand)]
enum Command {
    /// Print (or plot) the points of a sequence, or the samples of one pixel.
    #[command(long_about = points::long_about())]
    Points(points::PointsArgs),
    /// Draw the paper's figure: a 2x2-pixel image's samples, one panel per sampler.
    #[command(long_about = figure::LONG_ABOUT)]
    Figure(figure::FigureArgs),
    /// Quality metrics of a point set: star discrepancy, L2 discrepancies, distances.
    #[command(long_about = discrepancy::LONG_ABOUT)]
    Discrepancy(discrepancy::DiscrepancyArgs),
    /// Radially averaged power spectra of several samplers, with their points, in one picture.
    #[command(long_about = spectrum::LONG_ABOUT)]
    Spectrum(spectrum::SpectrumArgs),
    /// The paper's claim, measured: star discrepancy and minimum distance per sampler.
    #[command(long_about = claim::LONG_ABOUT)]
    PaperClaim(claim::ClaimArgs),
    /// Path-trace a scene (default: the built-in Cornell box) to EXR or PNG.
    #[command(long_about = render_cmd::LONG_ABOUT)]
    Render(render_cmd::RenderArgs),
    /// The paper's experiment: every sampler against a converged reference, with a report.
    #[command(long_about = experiment::LONG_ABOUT)]
    Experiment(Box<experiment::ExperimentCommand>),
    /// Samplers compared over a collection of scenes: pooled error ratios and error structure.
    #[command(long_about = study::LONG_ABOUT)]
    Study(Box<study::StudyArgs>),
    /// Merge the parts of a split render (tiles, sample ranges) into one EXR.
    #[command(long_about = split_cmd::LONG_ABOUT)]
    Merge(split_cmd::MergeArgs),
}

/// Validates the subcommand's arguments and runs it.
fn run(command: Command) -> anyhow::Result<()> {
    match command {
        Command::Points(args) => {
            let config = args.into_config()?;
            points::run(&config, io::stdout().lock())
        }
        Command::Figure(args) => figure::run(&args.into_config()?),
        Command::Render(args) => render_cmd::run(&args.into_config()?),
        Command::Experiment(command) => command.run(),
        Command::Merge(args) => split_cmd::run(&args),
        Command::Study(args) => study::run(*args),
        Command::Discrepancy(args) => {
            let config = args.into_config()?;
            discrepancy::run(&config, io::stdout().lock())
        }
        Command::Spectrum(args) => {
            let config = args.into_config()?;
            spectrum::run(&config, io::stdout().lock())
        }
        Command::PaperClaim(args) => {
            let config = args.into_config()?;
            claim::run(&config, io::stdout().lock())
        }
    }
}

/// Whether the error is a write to a closed pipe.
fn is_broken_pipe(err: &anyhow::Error) -> bool {
    err.chain().any(|cause| {
        cause
            .downcast_ref::<io::Error>()
            .is_some_and(|e| e.kind() == io::ErrorKind::BrokenPipe)
    })
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    if let Err(err) = interrupt::install() {
        report_error(&format!("cannot watch for SIGINT/SIGTERM: {err}"));
        return ExitCode::FAILURE;
    }
    match run(cli.command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(err) if is_broken_pipe(&err) => ExitCode::SUCCESS,
        Err(err) => {
            report_error(&error_line(&err));
            ExitCode::FAILURE
        }
    }
}

/// The error and its causes joined by `: `, leaving out a cause whose text
/// the line already holds (an I/O error both quoted in its context and
/// chained as its source would otherwise appear twice).
fn error_line(err: &anyhow::Error) -> String {
    let mut line = String::new();
    for cause in err.chain() {
        let text = cause.to_string();
        if line.contains(&text) {
            continue;
        }
        if !line.is_empty() {
            line.push_str(": ");
        }
        line.push_str(&text);
    }
    line
}

/// Prints `error: MESSAGE` as one line on stderr. A stderr that cannot be
/// written (closed, or a full disk) is ignored: the exit status still tells.
fn report_error(message: &str) {
    let _ = writeln!(io::stderr(), "error: {}", message.replace('\n', " "));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_error_line_names_each_cause_once() {
        let io = io::Error::new(io::ErrorKind::NotFound, "No such file (os error 2)");
        let quoted = format!("cannot write `x.png`: {io}");
        let err = anyhow::Error::new(io)
            .context(quoted)
            .context("cannot draw");
        assert_eq!(
            error_line(&err),
            "cannot draw: cannot write `x.png`: No such file (os error 2)"
        );
    }
}
