//! Progress of the long commands on stderr: an `indicatif` bar (percentage,
//! elapsed time, ETA, throughput) when stderr is a terminal, otherwise one
//! line when a stage starts, a line at each 10 % (or after 10 s without
//! one, never more often than every [`DEFAULT_INTERVAL`], or
//! `LOWDISC_PROGRESS_INTERVAL` seconds) with the same figures, and one
//! when it ends; `--quiet` silences everything. [`Reporter::summary`]
//! prints where the time went and where every file is.

use std::io::IsTerminal;
use std::path::PathBuf;
use std::sync::{Mutex, MutexGuard};
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressStyle};
use lowdisc_experiment::{Estimate, Progress};

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

/// Prints the progress of one command; shared by its worker threads.
pub struct Reporter {
    mode: Mode,
    interval: Duration,
    current: Mutex<Option<Current>>,
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
            current: Mutex::new(None),
            finished: Mutex::new(Vec::new()),
            start: Instant::now(),
        }
    }

    fn lock(&self) -> MutexGuard<'_, Option<Current>> {
        self.current.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Prints one line (above the bar on a terminal) unless quiet.
    pub fn line(&self, message: &str) {
        match (self.mode, self.lock().as_ref().and_then(|c| c.bar.as_ref())) {
            (Mode::Quiet, _) => {}
            (_, Some(bar)) => bar.println(message),
            (_, None) => note!("{message}"),
        }
    }

    /// Starts a stage of `total` units named `unit` (ends the previous one).
    pub fn begin_stage(&self, name: &str, total: u64, unit: &'static str) {
        self.end_stage();
        if self.mode == Mode::Quiet {
            return;
        }
        let bar = (self.mode == Mode::Bar).then(|| {
            let bar = ProgressBar::new(total.max(1));
            let template = "{prefix} {bar:20} {percent:>3}% {elapsed} ETA {eta} {msg}";
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
        *self.lock() = Some(Current {
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
        let mut guard = self.lock();
        let Some(c) = guard.as_mut() else { return };
        c.done = c.done.max(done).min(c.total);
        let elapsed = c.start.elapsed().as_secs_f64();
        let rate = c.done as f64 / elapsed.max(1e-9);
        if let Some(bar) = &c.bar {
            bar.set_position(c.done);
            bar.set_message(format!("{}{}/s", si(rate), c.unit));
            return;
        }
        let tenth = c.done * 10 / c.total.max(1);
        let since = c.last_line.elapsed();
        let due = (tenth > c.last_tenth && since >= self.interval) || since >= MAX_SILENCE;
        if due && c.done < c.total {
            let eta = (c.total - c.done) as f64 / rate.max(1e-9);
            note!(
                "  {:>3}%, {} elapsed, ETA {}, {}{}/s",
                c.done * 100 / c.total.max(1),
                duration(elapsed),
                duration(eta),
                si(rate),
                c.unit
            );
            c.last_line = Instant::now();
            c.last_tenth = tenth;
        }
    }

    /// `units` more units of the current stage are finished.
    pub fn add(&self, units: u64) {
        let done = self.lock().as_ref().map(|c| c.done + units);
        if let Some(done) = done {
            self.advance_stage(done);
        }
    }

    /// Ends the current stage, if any, and prints its time.
    pub fn end_stage(&self) {
        let Some(c) = self.lock().take() else { return };
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
            note!(
                "{head} done in {} ({}{}/s)",
                duration(elapsed.as_secs_f64()),
                si(rate),
                c.unit
            );
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
        note!("time: {} in all", duration(total));
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
        self.line(&format!(
            "estimated time: {} for {}samples at {}samples/s (from a {}-spp calibration render)",
            duration(e.seconds),
            si(e.samples as f64),
            si(e.samples_per_second),
            lowdisc_experiment::estimate::CALIBRATION_SPP
        ));
    }
    fn begin(&self, name: &str, total: u64) {
        self.begin_stage(name, total, "samples");
    }
    fn advance(&self, done: u64) {
        self.advance_stage(done);
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
