//! Progress of the long commands on stderr: an `indicatif` bar (percentage,
//! elapsed time, ETA, throughput) when stderr is a terminal, otherwise one
//! line when a stage starts, a line at each 10 % (or after 10 s without
//! one, never more often than every [`DEFAULT_INTERVAL`], or
//! `LOWDISC_PROGRESS_INTERVAL` seconds) with the same figures, and one
//! when it ends; `--quiet` silences everything. Once a run has reported its
//! estimate (the experiment), every line and the bar also show the whole
//! run's progress and time left; the percentages and times come from
//! [`lowdisc_experiment::eta`], which counts the work in rays.
//! [`Reporter::summary`] prints where the time went, the estimate beside
//! the time taken, and where every file is.

use std::io::IsTerminal;
use std::path::PathBuf;
use std::sync::{Mutex, MutexGuard};
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressStyle};
use lowdisc_experiment::eta::{Eta, Left};
use lowdisc_experiment::{Done, Estimate, Progress};

/// Writes one line to stderr, ignoring failure: a full or closed stderr must
/// not stop (or panic) a job whose progress nobody can read.
macro_rules! note {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr(), $($arg)*);
    }};
}

/// The least time between two progress lines off a terminal.
pub const DEFAULT_INTERVAL: Duration = Duration::from_secs(3);
/// A line at least this often off a terminal, whatever the percentage.
const MAX_SILENCE: Duration = Duration::from_secs(10);
/// Positions of the bar: it shows the stage's fraction of work.
const BAR_STEPS: u64 = 1000;

/// How progress is shown.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mode {
    Quiet,
    Bar,
    Lines,
}

/// The stage in progress.
struct Current {
    name: String,
    unit: &'static str,
    total: u64,
    done: u64,
    start: Instant,
    last_line: Instant,
    last_tenth: u64,
    bar: Option<ProgressBar>,
}

/// The stage in progress, the time left, and the run's first estimate.
#[derive(Default)]
struct State {
    current: Option<Current>,
    eta: Eta,
    estimated_seconds: Option<f64>,
}

/// Prints the progress of one command; shared by its worker threads.
pub struct Reporter {
    mode: Mode,
    interval: Duration,
    state: Mutex<State>,
    finished: Mutex<Vec<(String, Duration)>>,
    start: Instant,
}

/// `1.23 M` style: three significant digits and an SI prefix.
pub fn si(value: f64) -> String {
    let (v, prefix) = match value {
        v if v >= 1e9 => (v / 1e9, " G"),
        v if v >= 1e6 => (v / 1e6, " M"),
        v if v >= 1e3 => (v / 1e3, " k"),
        v => (v, " "),
    };
    let decimals = if v < 10.0 {
        2
    } else if v < 100.0 {
        1
    } else {
        0
    };
    format!("{v:.decimals$}{prefix}")
}

/// A duration as `42 s`, `3 min 05 s` or `1 h 02 min`.
pub fn duration(seconds: f64) -> String {
    let s = seconds.max(0.0).round() as u64;
    match s {
        0..60 => format!("{:.1} s", seconds.max(0.0)),
        60..3600 => format!("{} min {:02} s", s / 60, s % 60),
        _ => format!("{} h {:02} min", s / 3600, s / 60 % 60),
    }
}

/// The figures after a stage's percentage: its ETA, then the whole run's
/// progress and time left when known, else the stage's throughput.
fn figures(stage: Left, run: Option<Left>, rate: f64, unit: &str) -> String {
    let eta = format!("ETA {}", duration(stage.seconds));
    match run {
        Some(r) => format!(
            "{eta}; run {:.0}%, {} left",
            100.0 * r.fraction.min(1.0),
            duration(r.seconds)
        ),
        None => format!("{eta}, {}{unit}/s", si(rate)),
    }
}

impl Reporter {
    /// A reporter for stderr: silent with `quiet`, a bar on a terminal,
    /// lines otherwise.
    pub fn new(quiet: bool) -> Reporter {
        let mode = if quiet {
            Mode::Quiet
        } else if std::io::stderr().is_terminal() {
            Mode::Bar
        } else {
            Mode::Lines
        };
        let interval = std::env::var("LOWDISC_PROGRESS_INTERVAL")
            .ok()
            .and_then(|v| v.parse::<f64>().ok())
            .filter(|v| v.is_finite() && *v >= 0.0)
            .map_or(DEFAULT_INTERVAL, Duration::from_secs_f64);
        Reporter {
            mode,
            interval,
            state: Mutex::new(State::default()),
            finished: Mutex::new(Vec::new()),
            start: Instant::now(),
        }
    }

    fn lock(&self) -> MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Seconds since the reporter was made (the run's clock).
    fn now(&self) -> f64 {
        self.start.elapsed().as_secs_f64()
    }

    /// Prints one line (above the bar on a terminal) unless quiet.
    pub fn line(&self, message: &str) {
        let state = self.lock();
        match (
            self.mode,
            state.current.as_ref().and_then(|c| c.bar.as_ref()),
        ) {
            (Mode::Quiet, _) => {}
            (_, Some(bar)) => bar.println(message),
            (_, None) => note!("{message}"),
        }
    }

    /// Starts a stage of `total` units named `unit` (ends the previous one).
    pub fn begin_stage(&self, name: &str, total: u64, unit: &'static str) {
        self.end_stage();
        let now = self.now();
        self.lock().eta.begin(total, now);
        if self.mode == Mode::Quiet {
            return;
        }
        let bar = (self.mode == Mode::Bar).then(|| {
            let bar = ProgressBar::new(BAR_STEPS);
            let template = "{prefix} {bar:12} {percent:>3}% {elapsed} {msg}";
            let style = ProgressStyle::with_template(template)
                .unwrap_or_else(|_| ProgressStyle::default_bar());
            bar.set_style(style);
            bar.set_prefix(name.to_string());
            bar
        });
        if bar.is_none() {
            note!("{name}");
        }
        let now = Instant::now();
        self.lock().current = Some(Current {
            name: name.to_string(),
            unit,
            total,
            done: 0,
            start: now,
            last_line: now,
            last_tenth: 0,
            bar,
        });
    }

    /// `done` units of the current stage are finished.
    pub fn advance_stage(&self, done: u64) {
        self.advance_work(Done {
            samples: done,
            rays: 0,
        });
    }

    /// `done` of the current stage's work is finished: the stage's units
    /// (`done.samples`) and, once the run is estimated, its rays.
    fn advance_work(&self, done: Done) {
        let now = self.now();
        let mut state = self.lock();
        state.eta.advance(done);
        let (stage, run) = (state.eta.stage(now), state.eta.run(now));
        let Some(c) = state.current.as_mut() else {
            return;
        };
        let Some(stage) = stage else { return };
        c.done = c.done.max(done.samples).min(c.total);
        let elapsed = c.start.elapsed().as_secs_f64();
        let rate = c.done as f64 / elapsed.max(1e-9);
        let fraction = stage.fraction.clamp(0.0, 1.0);
        if let Some(bar) = &c.bar {
            bar.set_position((fraction * BAR_STEPS as f64) as u64);
            bar.set_message(figures(stage, run, rate, c.unit));
            return;
        }
        let tenth = (fraction * 10.0) as u64;
        let since = c.last_line.elapsed();
        let due = (tenth > c.last_tenth && since >= self.interval) || since >= MAX_SILENCE;
        if due && fraction < 1.0 {
            note!(
                "  {:>3.0}%, {} elapsed, {}",
                100.0 * fraction,
                duration(elapsed),
                figures(stage, run, rate, c.unit)
            );
            c.last_line = Instant::now();
            c.last_tenth = tenth;
        }
    }

    /// `units` more units of the current stage are finished.
    pub fn add(&self, units: u64) {
        let done = self.lock().current.as_ref().map(|c| c.done + units);
        if let Some(done) = done {
            self.advance_stage(done);
        }
    }

    /// Ends the current stage, if any, and prints its time.
    pub fn end_stage(&self) {
        let now = self.now();
        let (current, run) = {
            let mut state = self.lock();
            state.eta.end(now);
            (state.current.take(), state.eta.run(now))
        };
        let Some(c) = current else { return };
        let elapsed = c.start.elapsed();
        if let Some(bar) = &c.bar {
            bar.finish_and_clear();
        }
        if self.mode != Mode::Quiet {
            let rate = c.total as f64 / elapsed.as_secs_f64().max(1e-9);
            let head = if c.bar.is_some() {
                c.name.as_str()
            } else {
                " "
            };
            let after = match run {
                Some(r) => format!(
                    "; run {:.0}%, {} left",
                    100.0 * r.fraction,
                    duration(r.seconds)
                ),
                None => format!(" ({}{}/s)", si(rate), c.unit),
            };
            note!("{head} done in {}{after}", duration(elapsed.as_secs_f64()));
        }
        let mut finished = self.finished.lock().unwrap_or_else(|e| e.into_inner());
        finished.push((c.name, elapsed));
    }

    /// Prints where the time went (each stage's time and share, the rest as
    /// "other") and every file, images grouped by folder.
    pub fn summary(&self, files: &[PathBuf]) {
        self.end_stage();
        if self.mode == Mode::Quiet {
            return;
        }
        let total = self.start.elapsed().as_secs_f64().max(1e-9);
        let finished = self.finished.lock().unwrap_or_else(|e| e.into_inner());
        match self.lock().estimated_seconds {
            Some(e) => note!(
                "time: {} in all (estimated {} at the start, {:+.0} %)",
                duration(total),
                duration(e),
                100.0 * (e / total - 1.0)
            ),
            None => note!("time: {} in all", duration(total)),
        }
        let mut staged = 0.0;
        for (name, t) in finished.iter() {
            let t = t.as_secs_f64();
            staged += t;
            note!("  {:>5.1}%  {:>10}  {name}", 100.0 * t / total, duration(t));
        }
        let other = (total - staged).max(0.0);
        note!(
            "  {:>5.1}%  {:>10}  other (loading, calibration, statistics, writing)",
            100.0 * other / total,
            duration(other)
        );
        if files.is_empty() {
            return;
        }
        note!("files:");
        let is_image = |p: &PathBuf| {
            matches!(
                p.extension().and_then(|e| e.to_str()),
                Some("png" | "exr" | "svg")
            )
        };
        for f in files.iter().filter(|f| !is_image(f)) {
            note!("  {}", f.display());
        }
        let images: Vec<&PathBuf> = files.iter().filter(|f| is_image(f)).collect();
        let mut folders: Vec<PathBuf> = images
            .iter()
            .filter_map(|f| f.parent().map(PathBuf::from))
            .collect();
        folders.dedup();
        for folder in folders {
            let n = images
                .iter()
                .filter(|f| f.parent() == Some(&folder))
                .count();
            note!("  {}/: {n} images (.png, .exr)", folder.display());
        }
    }
}

impl Progress for Reporter {
    fn note(&self, message: &str) {
        self.line(message);
    }
    fn estimate(&self, e: &Estimate) {
        {
            let mut state = self.lock();
            state.eta.estimate(e);
            state.estimated_seconds = Some(e.seconds);
        }
        self.line(&format!(
            "estimated run time: {} ({}samples at {}samples/s)",
            duration(e.seconds),
            si(e.samples as f64),
            si(e.samples_per_second),
        ));
    }
    fn begin(&self, name: &str, total: u64) {
        self.begin_stage(name, total, "samples");
    }
    fn advance(&self, done: Done) {
        self.advance_work(done);
    }
    fn end(&self) {
        self.end_stage();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn durations_and_si_prefixes() {
        assert_eq!(duration(4.24), "4.2 s");
        assert_eq!(duration(125.0), "2 min 05 s");
        assert_eq!(duration(3725.0), "1 h 02 min");
        assert_eq!(si(1_234_567.0), "1.23 M");
        assert_eq!(si(169_984.0), "170 k");
        assert_eq!(si(12.0), "12.0 ");
    }
}
