//! Statistics that can tell two samplers apart.
//!
//! An experiment renders each sampler with the seeds `0..n` and measures one
//! error per render. This crate turns those numbers into:
//!
//! - [`Summary`]: the mean error, its standard error `sd / sqrt(n)` and a
//!   two-sided 95 % confidence interval from Student's t with `n - 1`
//!   degrees of freedom ([`t_quantile`]), valid for small `n`;
//! - [`PairedRatio`]: the error of a sampler relative to a baseline from
//!   *paired* runs (run `i` of both uses seed index `i`), computed on the
//!   logarithm of the per-seed ratios (see [`paired`] for why and what it
//!   estimates);
//! - [`Verdict`]: "better", "worse" or "not distinguishable" from whether
//!   the ratio's interval excludes 1.
//!
//! Nothing here prints or panics on bad input: empty or non-positive data
//! gives `None` or NaN fields, as documented on each function.

pub mod paired;
pub mod summary;

pub use paired::{PairedRatio, Verdict, paired_ratio};
pub use summary::{CONFIDENCE, Summary, t_quantile};

#[cfg(test)]
mod tests_support {
    //! Seeded normal variates for the simulation tests.
    use lowdisc::pcg::Pcg32;

    /// A standard normal variate (Box-Muller on two PCG32 uniforms).
    pub fn normal(rng: &mut Pcg32) -> f64 {
        let u1 = 1.0 - rng.next_f64(); // (0, 1]
        let u2 = rng.next_f64();
        (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
    }
}
