//! [`RenderOptions`]: what to render with (the pixel sampler's configuration,
//! the path tracer, threads, and the part of the image and of the
//! sample indices to render) and the one place their ranges are checked
//! ([`RenderOptions::validate`]; the window is checked against the film by
//! [`RenderOptions::window_in`]).
//!
//! The sampler's own fields (samples per pixel at least 1, the paper
//! threshold in `[0, 1]`) are checked by [`SamplerConfig::validate`]; this
//! module adds the renderer's bounds (at most [`MAX_SPP`] samples per pixel,
//! [`MAX_DEPTH_LIMIT`] bounces, [`MAX_THREADS`] threads). Front ends call
//! `validate` on the options they built; [`super::render`] calls it again
//! before any work.

use super::RenderError;
use crate::film::PixelBounds;
use crate::integrator::{MAX_DEPTH_LIMIT, PathIntegrator};
use lowdisc::catalog::{SamplerConfig, SamplerName};

/// The most samples per pixel accepted.
pub const MAX_SPP: u32 = 1 << 24;
/// The most worker threads accepted.
pub const MAX_THREADS: usize = 1024;

/// How to render.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderOptions {
    /// The pixel sampler: name, seed, samples per pixel, paper threshold.
    /// Its `seed` also seeds the BSDFs' random walks; its `resolution` is
    /// not used (the render takes the film's full resolution).
    pub sampler: SamplerConfig,
    /// The path tracer.
    pub integrator: PathIntegrator,
    /// Worker threads; `None` uses rayon's global pool (all cores).
    pub threads: Option<usize>,
    /// The pixels to render, in full-image pixel coordinates, within the
    /// film's pixel bounds (the scene's crop); `None` renders them all. The
    /// tile grid and every tile's sampler stream stay those of the film's
    /// pixel bounds, so a pixel's value never depends on the window.
    pub window: Option<PixelBounds>,
    /// The sample indices to take in every pixel, within `0..spp`; `None`
    /// takes them all.
    pub samples: Option<SampleRange>,
    /// Spectral rendering (four sampled wavelengths per camera sample, RGB
    /// parameters uplifted to spectra, a CIE 1931 sensor); `false` renders
    /// in RGB (see [`crate::spectrum`]).
    pub spectral: bool,
}

/// A half-open range `start..end` of sample indices (`Copy`, unlike
/// `std::ops::Range`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SampleRange {
    /// The first sample index taken.
    pub start: u32,
    /// One past the last sample index taken.
    pub end: u32,
}

impl SampleRange {
    /// `start..end`.
    pub const fn new(start: u32, end: u32) -> SampleRange {
        SampleRange { start, end }
    }
    /// Every sample of a pixel, `0..spp`.
    pub const fn all(spp: u32) -> SampleRange {
        SampleRange { start: 0, end: spp }
    }
    /// Number of indices (0 when empty).
    pub fn len(&self) -> u32 {
        self.end.saturating_sub(self.start)
    }
    /// True when the range holds no index.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// True when `s` is in the range.
    pub fn contains(&self, s: u32) -> bool {
        (self.start..self.end).contains(&s)
    }
}

impl std::fmt::Display for SampleRange {
    /// `start..end`, the form `--sample-range` takes.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}..{}", self.start, self.end)
    }
}

impl Default for RenderOptions {
    /// ZSobol, seed 0, 16 samples per pixel, the default path tracer, all
    /// cores, every pixel and every sample, RGB.
    fn default() -> Self {
        RenderOptions {
            sampler: SamplerConfig::new(SamplerName::ZSobol),
            integrator: PathIntegrator::default(),
            threads: None,
            window: None,
            samples: None,
            spectral: false,
        }
    }
}

impl RenderOptions {
    /// Options with `sampler`, `seed` and `spp` and the other defaults.
    pub fn new(sampler: SamplerName, seed: u64, spp: u32) -> RenderOptions {
        RenderOptions {
            sampler: SamplerConfig {
                seed,
                spp,
                ..SamplerConfig::new(sampler)
            },
            ..RenderOptions::default()
        }
    }

    /// Checks every field's range; the error names the field.
    pub fn validate(&self) -> Result<(), RenderError> {
        let bad = |m: String| Err(RenderError::InvalidOptions(m));
        self.sampler.validate()?;
        if self.sampler.spp > MAX_SPP {
            return bad(format!(
                "samples per pixel {} must be between 1 and {MAX_SPP}",
                self.sampler.spp
            ));
        }
        if self.integrator.max_depth > MAX_DEPTH_LIMIT {
            return bad(format!(
                "max depth {} exceeds {MAX_DEPTH_LIMIT}",
                self.integrator.max_depth
            ));
        }
        if let Some(r) = self.samples {
            if r.is_empty() || r.end > self.sampler.spp {
                return bad(format!(
                    "sample range {r} must be non-empty and within 0..{}",
                    self.sampler.spp
                ));
            }
        }
        if let Some(t) = self.threads {
            if t == 0 || t > MAX_THREADS {
                return bad(format!(
                    "thread count {t} must be between 1 and {MAX_THREADS}"
                ));
            }
        }
        Ok(())
    }

    /// The sample indices every pixel takes: [`Self::samples`] or `0..spp`.
    pub fn sample_range(&self) -> SampleRange {
        self.samples.unwrap_or(SampleRange::all(self.sampler.spp))
    }

    /// The pixels to render within a film's pixel bounds `film`:
    /// [`Self::window`] (which must be non-empty and inside `film`) or
    /// `film` itself.
    pub fn window_in(&self, film: PixelBounds) -> Result<PixelBounds, RenderError> {
        let Some(w) = self.window else {
            return Ok(film);
        };
        if w.area() == 0 || w.intersect(&film) != w {
            return Err(RenderError::InvalidOptions(format!(
                "pixel bounds {},{},{},{} must be non-empty and inside the film's {},{},{},{}",
                w.min[0],
                w.max[0],
                w.min[1],
                w.max[1],
                film.min[0],
                film.max[0],
                film.min[1],
                film.max[1]
            )));
        }
        Ok(w)
    }
}
