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
    /// The next values, one per entry of `dims` in order, exactly as the
    /// same sequence of [`PixelSampler::get_1d`] (lane 1 is 0) and
    /// [`PixelSampler::get_2d`] calls gives them; a sampler may draw them
    /// together (the default sampler checks its caches once).
    #[inline(always)]
    fn get_values<const N: usize>(&mut self, dims: [Dims; N]) -> [[f32; 2]; N]
    where
        Self: Sized,
    {
        values_in_order(self, dims)
    }
}

/// [`PixelSampler::get_values`] by one [`PixelSampler::get_1d`] or
/// [`PixelSampler::get_2d`] call per entry of `dims`, in order: the
/// definition, and the path of a sampler with no faster one.
#[inline(always)]
pub(crate) fn values_in_order<S: PixelSampler + ?Sized, const N: usize>(
    sampler: &mut S,
    dims: [Dims; N],
) -> [[f32; 2]; N] {
    // A plain loop: the array helpers' closures do not always inline.
    let mut values = [[0.0; 2]; N];
    for (value, d) in values.iter_mut().zip(dims) {
        *value = match d {
            Dims::One => [sampler.get_1d(), 0.0],
            Dims::Two => sampler.get_2d(),
        };
    }
    values
}

/// The dimensions of one value of [`PixelSampler::get_values`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dims {
    /// A 1-D value ([`PixelSampler::get_1d`]).
    One,
    /// A 2-D value ([`PixelSampler::get_2d`]).
    Two,
}

impl Dims {
    /// The dimensions the value consumes (1 or 2).
    #[inline(always)]
    pub fn count(self) -> u32 {
        match self {
            Dims::One => 1,
            Dims::Two => 2,
        }
    }
}

mod burley;
mod cascaded_sobol;
mod global_sobol;
mod group_cache;
mod halton;
mod independent;
mod openqmc;
mod padded_sobol;
mod pmj;
mod stratified;
mod zorder_sz;
mod zsobol;
mod zsobol_joint;

pub use burley::{
    BurleySampler, NestedHash, PixelXorSampler, burley_word, laine_karras_scramble_reversed,
    seed_hash,
};
pub use cascaded_sobol::CascadedSobolSampler;
pub use global_sobol::{GlobalSobolMode, GlobalSobolSampler};
pub use halton::HaltonSampler;
pub use independent::IndependentSampler;
pub use openqmc::{OpenQmcKind, OpenQmcSampler};
pub use padded_sobol::{PaddedSobolSampler, permutation_element};
pub use pmj::PmjSampler;
pub use stratified::StratifiedSampler;
pub use zorder_sz::ZOrderSzSampler;
pub use zsobol::ZSobolSampler;
pub use zsobol_joint::{GroupLayout, ZSobolJointSampler};

/// The digit-word form of a pixel sampler: a sampler that produces 32-bit
/// digit words (bit 31 = first binary digit) writes only the five required
/// methods and gets [`PixelSampler`] from them, each word turned into
/// `[0, 1)` by [`crate::to_f32`] (the provided `*_value(s)` methods, which a
/// sampler with a cheaper way to the same floats overrides).
pub trait WordSampler {
    /// Samples per pixel the sampler was configured for.
    fn samples_per_pixel(&self) -> u32;
    /// Starts sample `sample_index` of `pixel`, with the dimension counter at
    /// `dimension` (as [`PixelSampler::start_pixel_sample`]).
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32);
    /// The next 1-D value as a digit word.
    fn get_1d_word(&mut self) -> u32;
    /// The next 2-D value as digit words.
    fn get_2d_words(&mut self) -> [u32; 2];
    /// The in-pixel offset as digit words.
    fn get_pixel_2d_words(&mut self) -> [u32; 2];
    /// The next 1-D value: [`crate::to_f32`] of [`WordSampler::get_1d_word`]
    /// (a sampler may compute it another way, never to another value).
    #[inline]
    fn get_1d_value(&mut self) -> f32 {
        crate::to_f32(self.get_1d_word())
    }
    /// The next 2-D value: [`crate::to_f32`] of [`WordSampler::get_2d_words`].
    #[inline]
    fn get_2d_values(&mut self) -> [f32; 2] {
        self.get_2d_words().map(crate::to_f32)
    }
    /// The in-pixel offset: [`crate::to_f32`] of
    /// [`WordSampler::get_pixel_2d_words`].
    #[inline]
    fn get_pixel_2d_values(&mut self) -> [f32; 2] {
        self.get_pixel_2d_words().map(crate::to_f32)
    }
    /// [`PixelSampler::get_values`]: the `*_value(s)` calls in order.
    #[inline(always)]
    fn get_values<const N: usize>(&mut self, dims: [Dims; N]) -> [[f32; 2]; N]
    where
        Self: Sized + PixelSampler,
    {
        values_in_order(self, dims)
    }
}

impl<T: WordSampler> PixelSampler for T {
    #[inline]
    fn samples_per_pixel(&self) -> u32 {
        WordSampler::samples_per_pixel(self)
    }

    #[inline]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
        WordSampler::start_pixel_sample(self, pixel, sample_index, dimension);
    }

    #[inline(always)]
    fn get_1d(&mut self) -> f32 {
        self.get_1d_value()
    }

    #[inline(always)]
    fn get_2d(&mut self) -> [f32; 2] {
        self.get_2d_values()
    }

    #[inline(always)]
    fn get_pixel_2d(&mut self) -> [f32; 2] {
        self.get_pixel_2d_values()
    }

    #[inline(always)]
    fn get_values<const N: usize>(&mut self, dims: [Dims; N]) -> [[f32; 2]; N]
    where
        Self: Sized,
    {
        WordSampler::get_values(self, dims)
    }
}

/// A fixed word that the padded, Z-order and global Sobol samplers hash
/// right after their seed. It is 0, the second seed the catalog passed when
/// the strategy carried a seed of its own, so every value stays as pinned.
pub(crate) const SEED_PAD: u64 = 0;

/// The key of the next `n` dimensions (the counter's value), advancing the
/// counter past them.
#[inline]
pub(crate) fn next_key(counter: &mut u32, n: u32) -> u64 {
    let key = *counter;
    *counter = key.wrapping_add(n);
    u64::from(key)
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
