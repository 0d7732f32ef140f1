//! Pixel samplers: the interface a renderer drives, after pbrt-v4's `Sampler`.
//!
//! A renderer calls [`PixelSampler::start_pixel_sample`] for each (pixel,
//! sample index) it renders, then asks for values in the order it consumes
//! them: [`PixelSampler::get_pixel_2d`] once for the position inside the pixel
//! (an offset in `[0, 1)^2`, so the film position is `pixel + offset`), then
//! [`PixelSampler::get_1d`] and [`PixelSampler::get_2d`] for every other
//! decision (lens, BSDF, light, Russian roulette...). Each call consumes the
//! next dimension(s); `get_pixel_2d` uses dimensions reserved for it and does
//! not move the counter. Values are always in `[0, 1)`.
//!
//! Every sampler takes an explicit seed; the same (config, pixel, index,
//! dimension) gives the same values whatever order pixels are visited in,
//! except the paper's literal variant, whose single stream makes values
//! depend on call order by design (see [`crate::paper`]).

/// The four calls a renderer makes on a sampler.
pub trait PixelSampler {
    /// Samples per pixel the sampler was configured for.
    fn samples_per_pixel(&self) -> u32;
    /// Starts sample `sample_index` of `pixel` (x, y), with the dimension
    /// counter at `dimension` (0 for a fresh camera ray).
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32);
    /// The next 1-D value in `[0, 1)`.
    fn get_1d(&mut self) -> f32;
    /// The next 2-D value in `[0, 1)^2`.
    fn get_2d(&mut self) -> [f32; 2];
    /// The position inside the current pixel, in `[0, 1)^2`.
    fn get_pixel_2d(&mut self) -> [f32; 2];
}

mod global_sobol;
mod halton;
mod independent;
mod padded_sobol;
mod sampler;
mod stratified;
mod zsobol;

pub use global_sobol::{GlobalSobolMode, GlobalSobolSampler};
pub use halton::HaltonSampler;
pub use independent::IndependentSampler;
pub use padded_sobol::{PaddedSobolSampler, permutation_element};
pub use sampler::Sampler;
pub use stratified::StratifiedSampler;
pub use zsobol::ZSobolSampler;

use crate::Randomize;

/// The seed a [`Randomize`] carries (0 for [`Randomize::None`]).
pub(crate) fn randomize_seed(randomize: Randomize) -> u64 {
    match randomize {
        Randomize::None => 0,
        Randomize::Xor { seed } | Randomize::Owen { seed } | Randomize::FastOwen { seed } => seed,
    }
}

/// The same kind of randomization with its seed replaced.
pub(crate) fn reseed(randomize: Randomize, seed: u64) -> Randomize {
    match randomize {
        Randomize::None => Randomize::None,
        Randomize::Xor { .. } => Randomize::Xor { seed },
        Randomize::Owen { .. } => Randomize::Owen { seed },
        Randomize::FastOwen { .. } => Randomize::FastOwen { seed },
    }
}

/// Checks that a sampler gets at least one sample per pixel.
pub(crate) fn check_spp(spp: u32) -> Result<(), crate::Error> {
    if spp == 0 {
        return Err(crate::Error::InvalidSampleCount {
            count: 0,
            reason: "at least one sample per pixel is needed",
        });
    }
    Ok(())
}

/// Checks that both sides of an image are at least 1 and returns them.
pub(crate) fn check_resolution(resolution: [u32; 2]) -> Result<[u32; 2], crate::Error> {
    let [width, height] = resolution;
    if width == 0 || height == 0 {
        return Err(crate::Error::InvalidResolution {
            width,
            height,
            reason: "both sides must be at least 1",
        });
    }
    Ok(resolution)
}

/// The smallest `k` with `2^k >= n` (`n >= 1`).
pub(crate) fn ceil_log2(n: u64) -> u32 {
    if n <= 1 {
        0
    } else {
        64 - (n - 1).leading_zeros()
    }
}
