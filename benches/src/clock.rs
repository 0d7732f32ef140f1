//! A criterion clock that counts the CPU time of the benchmark thread.
//!
//! The machines this project runs on are small and shared (builds and tests of
//! other work run beside the benchmarks), and wall-clock time then includes
//! the time the benchmark thread spends waiting for a core. The CPU time the
//! thread itself consumed (`CLOCK_THREAD_CPUTIME_ID` on Linux, through the
//! `cpu-time` crate) leaves that waiting out, so the figures stay comparable
//! from run to run. On an idle machine the two clocks agree.
//! Set `LOWDISC_BENCH_WALL_CLOCK=1` to measure wall-clock time instead.

use std::time::{Duration, Instant};

use cpu_time::ThreadTime;
use criterion::measurement::{Measurement, ValueFormatter, WallTime};

/// Wall-clock time, for the formatter criterion uses with durations.
static WALL_TIME: WallTime = WallTime;

/// Criterion measurement: CPU time of the calling thread (or wall-clock
/// time, if `LOWDISC_BENCH_WALL_CLOCK` is set to a non-empty value other than
/// `0`), in nanoseconds.
#[derive(Debug, Clone, Copy)]
pub struct ThreadCpuTime {
    wall: bool,
}

impl ThreadCpuTime {
    /// The clock, choosing between thread CPU time and wall-clock time from
    /// the environment variable `LOWDISC_BENCH_WALL_CLOCK`.
    pub fn from_env() -> Self {
        let wall = std::env::var("LOWDISC_BENCH_WALL_CLOCK")
            .map(|v| !v.is_empty() && v != "0")
            .unwrap_or(false);
        ThreadCpuTime { wall }
    }

    /// Whether this clock measures wall-clock time rather than CPU time.
    pub fn is_wall_clock(&self) -> bool {
        self.wall
    }
}

/// A started measurement of [`ThreadCpuTime`].
#[derive(Debug, Clone, Copy)]
pub enum Started {
    /// Thread CPU time at the start.
    Cpu(ThreadTime),
    /// Wall-clock time at the start.
    Wall(Instant),
}

impl Measurement for ThreadCpuTime {
    type Intermediate = Started;
    type Value = Duration;

    fn start(&self) -> Started {
        if self.wall {
            Started::Wall(Instant::now())
        } else {
            Started::Cpu(ThreadTime::now())
        }
    }

    fn end(&self, started: Started) -> Duration {
        match started {
            Started::Cpu(t) => t.elapsed(),
            Started::Wall(t) => t.elapsed(),
        }
    }

    fn add(&self, a: &Duration, b: &Duration) -> Duration {
        *a + *b
    }

    fn zero(&self) -> Duration {
        Duration::ZERO
    }

    fn to_f64(&self, value: &Duration) -> f64 {
        value.as_nanos() as f64
    }

    fn formatter(&self) -> &dyn ValueFormatter {
        WALL_TIME.formatter()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cpu_clock_advances_with_work() {
        let clock = ThreadCpuTime { wall: false };
        let started = clock.start();
        let mut x = 1u64;
        for i in 0..20_000_000u64 {
            x = std::hint::black_box(x.wrapping_mul(6364136223846793005).wrapping_add(i));
        }
        let spent = clock.end(started);
        assert!(x != 0 || spent > Duration::ZERO);
        assert!(spent > Duration::ZERO, "no CPU time counted for real work");
        assert_eq!(clock.to_f64(&Duration::from_micros(3)), 3000.0);
    }
}
