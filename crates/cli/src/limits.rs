//! Guards on user-controlled cost: every subcommand estimates the work and
//! the memory of a job before starting it and refuses, with one line naming
//! the limit and the flag that raises it, what would run for hours or
//! exhaust memory.
//!
//! Work is in elementary operations (see `lowdisc_metrics::cost`), memory in
//! MiB. The defaults keep a job to about a minute and a few GiB on a small
//! machine; `--max-work` and `--max-memory` raise them.

use anyhow::{Result, bail};

/// Default of `--max-work`: about a few seconds of metric work on two cores.
pub const DEFAULT_MAX_WORK: f64 = 4e9;

/// Default of `--max-memory`, in MiB.
pub const DEFAULT_MAX_MEMORY_MIB: u64 = 4096;

const MIB: f64 = 1024.0 * 1024.0;

/// Refuses `what` when its estimated `work` exceeds `max_work` (the value
/// of `--max-work`).
pub fn check_work(what: &str, work: f64, max_work: f64) -> Result<()> {
    if work.partial_cmp(&max_work) == Some(std::cmp::Ordering::Greater) || work.is_nan() {
        bail!(
            "{what} would take about {work:.1e} operations, above the limit --max-work {max_work:.1e}; \
             raise --max-work to run it anyway"
        );
    }
    Ok(())
}

/// Refuses `what` when its estimated memory `bytes` exceeds `max_mib` MiB
/// (the value of `--max-memory`).
pub fn check_memory(what: &str, bytes: f64, max_mib: u64) -> Result<()> {
    let limit = max_mib as f64 * MIB;
    if bytes > limit || bytes.is_nan() {
        let need = (bytes / MIB).ceil();
        bail!(
            "{what} would take about {need:.0} MiB of memory, above the limit --max-memory {max_mib} \
             (MiB); raise --max-memory to run it anyway"
        );
    }
    Ok(())
}

/// Checks that a `--max-work` value is a positive number.
pub fn check_max_work(max_work: f64) -> Result<()> {
    if max_work.is_nan() || max_work <= 0.0 {
        bail!("--max-work must be positive");
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refusals_name_the_limit_and_the_flag() {
        assert!(check_work("cd", 4e9, 4e9).is_ok());
        let err = check_work("cd", 1e12, 4e9).unwrap_err().to_string();
        assert!(
            err.contains("--max-work 4.0e9") && err.contains("1.0e12"),
            "{err}"
        );
        assert!(check_work("cd", f64::NAN, 4e9).is_err());
        assert!(check_memory("film", 1024.0 * MIB, 1024).is_ok());
        let err = check_memory("film", 1025.0 * MIB, 1024)
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("1025 MiB") && err.contains("--max-memory 1024"),
            "{err}"
        );
        assert!(check_max_work(0.0).is_err() && check_max_work(f64::NAN).is_err());
    }
}
