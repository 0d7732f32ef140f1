//! [`RenderOptions`]: what to render with (the pixel sampler's configuration,
//! the path tracer, threads, and the part of the image and of the
//! sample indices to render), their defaults ([`RenderOptions::default`],
//! the one place they are declared) and [`RenderOptions::validate`], which
//! checks every field with [`super::ranges`] (the window is checked against
//! the film by [`RenderOptions::window_in`]).

use super::ranges;
use super::sample_range::SampleRange;
use crate::error::RenderError;
use crate::film::PixelBounds;
use crate::integrator::PathIntegrator;
use lowdisc::catalog::{SamplerConfig, SamplerName};

/// How to render.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderOptions {
    /// The pixel sampler: name, seed, samples per pixel, paper threshold.
    /// Its `seed` also seeds the BSDFs' random walks; its `resolution` is
    /// not used (the render takes the view's resolution).
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

    /// Checks every field's range with [`super::ranges`] (options resolved
    /// by [`super::Settings::resolve`] already passed these checks, with
    /// their sources named).
    pub fn validate(&self) -> Result<(), RenderError> {
        let s = &self.sampler;
        ranges::spp(s.spp)
            .and_then(|()| ranges::threshold(s.threshold))
            .and_then(|()| ranges::max_depth(self.integrator.max_depth))
            .and_then(|()| self.samples.map_or(Ok(()), |r| ranges::samples(r, s.spp)))
            .and_then(|()| self.threads.map_or(Ok(()), ranges::threads))
            .map_err(RenderError::InvalidOptions)
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
