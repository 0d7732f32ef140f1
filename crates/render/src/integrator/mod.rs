//! Unidirectional path tracing with next-event estimation and multiple
//! importance sampling (pbrt-v4's `PathIntegrator`), in RGB or spectrally.
//!
//! **Colour.** The path is generic over its [`Colour`](crate::spectrum::Colour):
//! RGB triples (the default) or, in spectral mode, the four wavelengths of
//! the camera sample ([`PathIntegrator::li_for`]); materials and emission
//! are turned into that colour at each vertex (see [`crate::spectrum`]).
//! Russian roulette looks at the largest lane of either.
//!
//! **Estimator.** At every non-specular vertex one light is chosen in
//! proportion to its power and sampled (next-event estimation, with a shadow
//! ray), and the BSDF is sampled to continue the path. The two strategies are
//! combined with the power heuristic (β = 2): a light sample is weighted
//! `p_light² / (p_light² + p_bsdf²)`, and emission found by the BSDF-sampled
//! ray `p_bsdf² / (p_bsdf² + p_light²)`, where `p_light` includes the
//! probability of choosing that light. Delta lights (point lights) cannot be
//! hit, so their samples get weight 1; after a specular BSDF sample the light
//! cannot be sampled, so emission found then also gets weight 1. Emission seen
//! directly by the camera ray is added unweighted. [`LightStrategy`] can
//! switch MIS off for tests (BSDF sampling only, or light sampling only).
//!
//! **Depth.** `max_depth` has pbrt's meaning: the number of scattering events.
//! With `max_depth = 0` only emitters seen directly are rendered; with
//! `max_depth = 1` direct lighting is added (light samples at the first hit,
//! plus emission reached by the first BSDF sample); each further unit adds one
//! bounce.
//!
//! **Russian roulette** (pbrt-v4): once two scattering events have happened,
//! with `m` the largest channel of `β · η_scale` (the path throughput with
//! refraction's radiance scaling undone), a path with `m < 1` is terminated
//! with probability `q = 1 - m` and otherwise divided by `1 - q`.
//!
//! **Sampler dimensions, in order** (so the sampler's quality shows in the
//! image; every pixel sample consumes them in exactly this order):
//! 0. spectral mode only: the wavelength sample, `get_1d` (dimension 0, as
//!    pbrt-v4 draws it before the camera sample); every dimension below
//!    is then one higher (lens 1-2, bounce `k` from `3 + 7k`);
//! 1. the film position: `get_pixel_2d` (the sampler's reserved pixel
//!    dimensions, importance-sampling the pixel filter);
//! 2. the lens: `get_2d` (dimensions 0-1, drawn even for a pinhole);
//! 3. at every scattering vertex, before anything else is decided, seven
//!    dimensions: light choice `get_1d`, light position `get_2d`, BSDF lobe
//!    `get_1d`, BSDF direction `get_2d`, Russian roulette `get_1d`. They are
//!    drawn even when unused (specular vertex, no lights, early depth), so
//!    bounce `k` (0-based) always starts at dimension `2 + 7k`.
//!
//! **Scenes with participating media** ([`Scene::has_media`](crate::scene::Scene::has_media))
//! are rendered by the volumetric path tracer (pbrt-v4's `volpath`; see
//! `volpath.rs`), with this layout after the lens:
//! 1. the hero lane: `get_1d` (dimension 2; spectral mode 3), which chooses
//!    the lane (RGB channel or wavelength) whose density samples distances
//!    in media;
//! 2. every bounce, before its ray is traced, [`DIMS_PER_MEDIA_BOUNCE`] = 10
//!    dimensions: free-flight distance `get_1d`, collision event `get_1d`,
//!    stream seed `get_1d`, then the seven vertex dimensions above (at a
//!    point in a medium the lobe and Russian-roulette dimensions are unused
//!    and the BSDF direction samples the phase function). Bounce `k` starts
//!    at dimension `3 + 10k` (spectral mode `4 + 10k`). A bounce's further
//!    collisions and segments (after crossing an `interface` surface) draw
//!    from a PCG32 stream seeded by a hash of its seed dimension.
//!
//! Scenes without media render exactly as before media existed: the branch
//! to the volumetric tracer is taken once per camera sample.

mod path;
mod volpath;

pub use volpath::{DIMS_PER_MEDIA_BOUNCE, transmittance};

use crate::bsdf::LayeredExitWeight;

/// Which estimators of direct lighting are used (tests compare them).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LightStrategy {
    /// Light and BSDF sampling combined with the power heuristic (default).
    #[default]
    Mis,
    /// BSDF sampling only: emission is counted when a path hits it; delta
    /// lights contribute nothing.
    BsdfOnly,
    /// Light sampling only: emission reached by a BSDF sample counts only
    /// from the camera or after a specular bounce.
    LightOnly,
}

/// Counters a path adds to (kept per tile, summed afterwards).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PathStats {
    /// Rays traced: camera, continuation and shadow rays.
    pub rays: u64,
}

/// The path tracer's settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathIntegrator {
    /// Maximum number of scattering events (pbrt's `maxdepth`, default 5).
    pub max_depth: u32,
    /// Direct-lighting strategy.
    pub strategy: LightStrategy,
    /// How layered BSDFs weight their walks' exit connection (unbiased by
    /// default; pbrt-v4's weight to reproduce its images).
    pub layered_exit_weight: LayeredExitWeight,
}

impl Default for PathIntegrator {
    fn default() -> Self {
        PathIntegrator {
            max_depth: 5,
            strategy: LightStrategy::Mis,
            layered_exit_weight: LayeredExitWeight::UNBIASED,
        }
    }
}

/// Sampler dimensions consumed at each scattering vertex.
pub const DIMS_PER_BOUNCE: u32 = 7;

#[inline]
fn sqr(x: f32) -> f32 {
    x * x
}
