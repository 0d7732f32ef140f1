//! The time left of the current stage and of the whole run, from the
//! reports of [`crate::progress`]: [`Eta`] keeps the work done and the
//! rates; it reads no clock (every call takes the seconds since the run
//! began), so the caller owns the clock and a test can drive it with a
//! fake one.
//!
//! **Work is counted in rays**, once the run's [`Estimate`] gives the
//! scene's rays per camera sample; without an estimate (a unit, a merge)
//! in camera samples. The rows of an image differ in cost: a sample of a
//! sky pixel traces one ray, a sample of the glossy car or the ground up to
//! ten, and the first tiles a render finishes are its top rows, the sky.
//! Counted in samples, a stage's early speed is that of the cheap rows and
//! its time left far too short; counted in rays, whose cost varies much
//! less, the early speed is representative. A stage's total in rays is its
//! samples times the calibration's rays per sample.
//!
//! **Rates** start from the calibration's speed, weighted as though it had
//! been observed for [`PRIOR_SECONDS`], and move to the speed measured
//! since the first stage began; a stage's own rate starts from the run's.

use crate::progress::{Done, Estimate};

/// The weight of a prior rate, in seconds of observation: the measured
/// rate takes over once a stage (or the run) has run this long.
pub const PRIOR_SECONDS: f64 = 5.0;

/// How far along something is and how long it still takes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Left {
    /// The fraction of its work done, 0 to 1.
    pub fraction: f64,
    /// Seconds left at the current rate.
    pub seconds: f64,
}

/// The stage in progress, in work units.
#[derive(Debug, Clone, Copy)]
struct Current {
    total: f64,
    done: f64,
    start: f64,
}

/// The work and time of a run and its current stage (see the module doc).
///
/// ```
/// use lowdisc_experiment::eta::Eta;
/// use lowdisc_experiment::progress::{Done, Estimate};
///
/// let mut eta = Eta::default();
/// let estimate = Estimate {
///     samples: 1000,
///     samples_per_second: 100.0,
///     rays_per_sample: 2.0,
///     seconds: 10.0,
/// };
/// eta.estimate(&estimate);
/// eta.begin(1000, 0.0);
/// eta.advance(Done { samples: 500, rays: 1000 });
/// let run = eta.run(5.0).unwrap();
/// assert_eq!(run.fraction, 0.5);
/// assert!((run.seconds - 5.0).abs() < 1e-9);
/// ```
#[derive(Debug, Clone, Default)]
pub struct Eta {
    /// Rays per sample and the calibration's rays per second, if estimated.
    rays: Option<(f64, f64)>,
    /// The run's work in all.
    run_total: f64,
    /// Work of the finished stages.
    run_done: f64,
    /// Seconds spent in the finished stages.
    run_busy: f64,
    current: Option<Current>,
}

impl Eta {
    /// Takes the run's estimate: from now on work is counted in rays.
    pub fn estimate(&mut self, e: &Estimate) {
        if e.rays_per_sample > 0.0 && e.samples_per_second > 0.0 {
            let rays_per_second = e.samples_per_second * e.rays_per_sample;
            self.rays = Some((e.rays_per_sample, rays_per_second));
            self.run_total = e.samples as f64 * e.rays_per_sample;
        }
    }

    /// A stage of `samples` camera samples begins `now` seconds into the
    /// run (ending the previous one).
    pub fn begin(&mut self, samples: u64, now: f64) {
        self.end(now);
        let total = match self.rays {
            Some((per_sample, _)) => samples as f64 * per_sample,
            None => samples as f64,
        };
        self.current = Some(Current {
            total,
            done: 0.0,
            start: now,
        });
    }

    /// The current stage has done `done` (reports may arrive out of order:
    /// the most is kept).
    pub fn advance(&mut self, done: Done) {
        let work = match self.rays {
            Some(_) => done.rays as f64,
            None => done.samples as f64,
        };
        if let Some(c) = &mut self.current {
            c.done = c.done.max(work).min(c.total);
        }
    }

    /// The current stage, if any, ended `now` seconds into the run; its
    /// whole estimated work counts as done.
    pub fn end(&mut self, now: f64) {
        if let Some(c) = self.current.take() {
            self.run_done += c.total;
            self.run_busy += (now - c.start).max(0.0);
        }
    }

    /// The current stage's progress `now` seconds into the run.
    pub fn stage(&self, now: f64) -> Option<Left> {
        let c = self.current?;
        let elapsed = (now - c.start).max(0.0);
        let rate = match self.run_rate(now) {
            Some(prior) => blend(c.done, elapsed, prior),
            None => c.done / elapsed.max(1e-9),
        };
        Some(left(c.total, c.done, rate))
    }

    /// The whole run's progress `now` seconds into it, once estimated.
    pub fn run(&self, now: f64) -> Option<Left> {
        let rate = self.run_rate(now)?;
        let done = self.run_done + self.current.map_or(0.0, |c| c.done);
        Some(left(self.run_total.max(done), done, rate))
    }

    /// Work per second over the run's stages so far, starting from the
    /// calibration's.
    fn run_rate(&self, now: f64) -> Option<f64> {
        let (_, calibrated) = self.rays?;
        let (done, busy) = match self.current {
            Some(c) => (c.done, (now - c.start).max(0.0)),
            None => (0.0, 0.0),
        };
        Some(blend(
            self.run_done + done,
            self.run_busy + busy,
            calibrated,
        ))
    }
}

/// The rate of `done` work in `seconds`, starting from `prior` weighted as
/// [`PRIOR_SECONDS`] of observation.
fn blend(done: f64, seconds: f64, prior: f64) -> f64 {
    (done + prior * PRIOR_SECONDS) / (seconds + PRIOR_SECONDS)
}

/// `done` of `total` work at `rate` per second.
fn left(total: f64, done: f64, rate: f64) -> Left {
    Left {
        fraction: if total > 0.0 { done / total } else { 1.0 },
        seconds: (total - done).max(0.0) / rate.max(1e-12),
    }
}

#[cfg(test)]
mod tests;
