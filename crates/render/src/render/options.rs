//! [`RenderOptions`]: what to render with (the pixel sampler's configuration,
//! the path tracer, threads, tiles) and the one place their ranges are
//! checked ([`RenderOptions::validate`]).
//!
//! The sampler's own fields (samples per pixel at least 1, the paper
//! threshold in `[0, 1]`) are checked by [`SamplerConfig::validate`]; this
//! module adds the renderer's bounds (at most [`MAX_SPP`] samples per pixel,
//! [`MAX_DEPTH_LIMIT`] bounces, [`MAX_THREADS`] threads, tiles of at most
//! [`MAX_TILE_SIZE`] pixels). Front ends call `validate` on the options they
//! built; [`super::render`] calls it again before any work.

use super::RenderError;
use crate::integrator::{MAX_DEPTH_LIMIT, PathIntegrator};
use lowdisc::catalog::{SamplerConfig, SamplerName};

/// The most samples per pixel accepted.
pub const MAX_SPP: u32 = 1 << 24;
/// The most worker threads accepted.
pub const MAX_THREADS: usize = 1024;
/// The largest tile side accepted.
pub const MAX_TILE_SIZE: u32 = 4096;

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
    /// Tile side in pixels.
    pub tile_size: u32,
}

impl Default for RenderOptions {
    /// ZSobol, seed 0, 16 samples per pixel, the default path tracer, all
    /// cores, 16-pixel tiles.
    fn default() -> Self {
        RenderOptions {
            sampler: SamplerConfig::new(SamplerName::ZSobol),
            integrator: PathIntegrator::default(),
            threads: None,
            tile_size: lowdisc::catalog::DEFAULT_TILE_SIZE,
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
        if self.tile_size == 0 || self.tile_size > MAX_TILE_SIZE {
            return bad(format!(
                "tile size {} must be between 1 and {MAX_TILE_SIZE}",
                self.tile_size
            ));
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
}
