//! How a run reports what it is doing: the [`Progress`] observer that the
//! caller implements (the CLI draws bars and prints lines; the library
//! never prints), and [`Stage`], which turns the renderer's per-render
//! reports into one count of camera samples per stage.
//!
//! A run first reports its [`Estimate`], then a sequence of stages (the
//! reference, each sampler's runs, the threshold sweep, the convergence
//! series). Each stage announces its total number of camera samples with
//! [`Progress::begin`], reports the samples and rays finished so far
//! ([`Done`]) with [`Progress::advance`] (called from render worker
//! threads, so it must be cheap) and closes with [`Progress::end`].
//! [`crate::eta`] turns these reports into the time left of the stage and
//! of the whole run.

use std::sync::atomic::{AtomicU64, Ordering};

use lowdisc_render::render::{self, ProgressSink};

/// The estimated work and time of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// Camera samples still to render (cached references excluded).
    pub samples: u64,
    /// Samples per second measured by the calibration render.
    pub samples_per_second: f64,
    /// Rays traced per camera sample in the calibration render (the scene's
    /// average over the whole image: a sky pixel's sample traces one ray, a
    /// pixel of glossy metal several).
    pub rays_per_sample: f64,
    /// `samples / samples_per_second`.
    pub seconds: f64,
}

/// The work finished so far in the current stage: camera samples, and the
/// rays they traced (zero when a stage reads finished renders from files).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Done {
    /// Camera samples finished.
    pub samples: u64,
    /// Rays traced by those samples.
    pub rays: u64,
}

/// Receives a run's progress; every method does nothing by default.
pub trait Progress: Sync {
    /// A one-line message (scene warnings, a reused cache file).
    fn note(&self, message: &str) {
        let _ = message;
    }
    /// The run's estimated work and time, from a calibration render, before
    /// the first stage.
    fn estimate(&self, estimate: &Estimate) {
        let _ = estimate;
    }
    /// A stage named `name` of `total` camera samples begins.
    fn begin(&self, name: &str, total: u64) {
        let _ = (name, total);
    }
    /// `done` of the current stage's work is finished. Calls come from
    /// worker threads and may arrive slightly out of order.
    fn advance(&self, done: Done) {
        let _ = done;
    }
    /// The current stage is finished.
    fn end(&self) {}
}

/// An observer that ignores everything.
#[derive(Debug, Clone, Copy, Default)]
pub struct Silent;

impl Progress for Silent {}

/// One stage in progress: forwards each render's samples and rays, offset
/// by those of the stage's earlier renders, to the observer.
pub struct Stage<'a> {
    observer: &'a dyn Progress,
    samples: AtomicU64,
    rays: AtomicU64,
}

impl<'a> Stage<'a> {
    /// Announces stage `name` of `total` samples.
    pub fn begin(observer: &'a dyn Progress, name: &str, total: u64) -> Stage<'a> {
        observer.begin(name, total);
        Stage {
            observer,
            samples: AtomicU64::new(0),
            rays: AtomicU64::new(0),
        }
    }

    /// Marks one render of `samples` samples that traced `rays` rays as
    /// finished.
    pub fn finished_render(&self, samples: u64, rays: u64) {
        let done = Done {
            samples: self.samples.fetch_add(samples, Ordering::Relaxed) + samples,
            rays: self.rays.fetch_add(rays, Ordering::Relaxed) + rays,
        };
        self.observer.advance(done);
    }

    /// Ends the stage.
    pub fn end(self) {
        self.observer.end();
    }
}

impl ProgressSink for Stage<'_> {
    fn report(&self, p: render::Progress) {
        self.observer.advance(Done {
            samples: self.samples.load(Ordering::Relaxed) + p.samples_done,
            rays: self.rays.load(Ordering::Relaxed) + p.rays,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Mutex;

    #[derive(Default)]
    struct Log(Mutex<Vec<String>>);

    impl Progress for Log {
        fn begin(&self, name: &str, total: u64) {
            self.0.lock().unwrap().push(format!("begin {name} {total}"));
        }
        fn advance(&self, done: Done) {
            let Done { samples, rays } = done;
            self.0.lock().unwrap().push(format!("{samples}/{rays}"));
        }
        fn end(&self) {
            self.0.lock().unwrap().push("end".into());
        }
    }

    #[test]
    fn a_stage_counts_samples_and_rays_across_renders() {
        let log = Log::default();
        let stage = Stage::begin(&log, "s", 20);
        let report = |done| render::Progress {
            tiles_done: 0,
            tiles_total: 1,
            samples_done: done,
            samples_total: 10,
            rays: 3 * done,
        };
        stage.report(report(4));
        stage.finished_render(10, 30);
        stage.report(report(6));
        stage.finished_render(10, 50);
        stage.end();
        let got = log.0.into_inner().unwrap();
        let want = ["begin s 20", "4/12", "10/30", "16/48", "20/80", "end"];
        assert_eq!(got, want);
    }
}
