//! The threshold sweep of the paper's method: for each threshold, the star
//! discrepancy of one pixel's film positions and the error of `paper-repro`
//! renders against the reference (mean and sd over the runs' seeds). The
//! renders are units of the plan (`Work::Sweep`); their errors are
//! collected when the units are assembled.
//!
//! Threshold 1 leaves every generator-matrix column unflipped, so its row
//! is plain Sobol (a deterministic sampler: its runs are identical).

use anyhow::Result;
use lowdisc::catalog::{SamplerConfig, SamplerName};

/// The thresholds swept.
pub const THRESHOLDS: [f64; 7] = [0.0, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0];

/// Star discrepancy of one pixel's `spp` film positions from `paper-repro`
/// (permuting dimensions 0-1 too) at threshold `t`.
pub fn pixel_discrepancy(spp: u32, t: f64) -> Result<f64> {
    let mut c = SamplerConfig::new(SamplerName::PaperRepro);
    c.threshold = t;
    c.paper_all_dims = true;
    c.spp = spp;
    c.resolution = [1, 1];
    let pts = crate::figure::film_positions(&c)?;
    let set = lowdisc_metrics::PointSet::from_rows(&pts)?;
    Ok(lowdisc_metrics::star_discrepancy(&set)?)
}
