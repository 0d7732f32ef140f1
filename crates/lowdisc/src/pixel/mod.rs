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
