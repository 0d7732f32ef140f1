//! The global image-plane Halton sampler of pbrt-v3/v4.
//!
//! The first two Halton dimensions (bases 2 and 3) are laid over the image:
//! with `2^j` the smallest power of two `>= min(width, 128)` and `3^k` the
//! smallest power of three `>= min(height, 128)`, point `i` of the sequence
//! falls in pixel column `floor(x_i * 2^j)` and row `floor(y_i * 3^k)` of a
//! `2^j x 3^k` tile repeated over the image. The first `j` base-2 digits of
//! `x_i` are the first `j` binary digits of `i` mirrored, so the column fixes
//! `i mod 2^j`; likewise the row fixes `i mod 3^k`. The Chinese remainder
//! theorem (`2^j` and `3^k` are coprime) turns the pair into the unique
//! residue `h` of `i` modulo `2^j 3^k`, and sample `s` of pixel `p` is point
//! `h + s * 2^j 3^k`: each pixel gets its own subsequence, and the samples of
//! a `2^j x 3^k` image are exactly the first `2^j 3^k spp` points. Pixel
//! coordinates are taken modulo `2^j` and `3^k`.
//!
//! The offset inside the pixel is the rest of the point: `x_i * 2^j - column`
//! is the radical inverse of `floor(i / 2^j)` in base 2, and the row offset
//! that of `floor(i / 3^k)` in base 3. These are evaluated with the
//! sampler's randomization applied to dimensions 0 and 1 at those quotient
//! indices (pbrt-v4 leaves the offset unscrambled; scrambling the digits
//! below the pixel keeps every sample in its pixel and lets the seed move
//! it). `get_1d`/`get_2d` use dimensions 2, 3, ... at the global index; past
//! the last dimension they wrap to dimension 2, as pbrt does.

use super::PixelSampler;
use crate::Error;
use crate::halton::{Halton, HaltonRandomize, NUM_DIMENSIONS, inverse_radical_inverse};

/// Largest tile side: pbrt's `MaxHaltonResolution`.
const MAX_RESOLUTION: u32 = 128;

/// Global image-plane Halton sampling.
#[derive(Debug, Clone)]
pub struct HaltonSampler {
    spp: u32,
    resolution: [u32; 2],
    halton: Halton,
    /// `2^j` and `3^k`.
    scales: [u64; 2],
    /// `j` and `k`.
    exponents: [u32; 2],
    /// The global index of the current sample.
    index: u64,
    dimension: u32,
}

impl HaltonSampler {
    /// A sampler for a `resolution` (width, height) image with `spp` samples
    /// per pixel and the given randomization and seed.
    ///
    /// # Errors
    /// [`Error::InvalidSampleCount`] for `spp == 0`;
    /// [`Error::InvalidResolution`] for a zero width or height. (Every
    /// other configuration fits: the largest global index is below
    /// `128 * 243 * 2^32 < 2^47`.)
    pub fn new(
        spp: u32,
        resolution: [u32; 2],
        randomize: HaltonRandomize,
        seed: u64,
    ) -> Result<Self, Error> {
        super::check_spp(spp)?;
        let [width, height] = super::check_resolution(resolution)?;
        let (s0, e0) = smallest_power_at_least(2, width.min(MAX_RESOLUTION));
        let (s1, e1) = smallest_power_at_least(3, height.min(MAX_RESOLUTION));
        // Checked, though it cannot fail with the bounds above.
        (s0 * s1)
            .checked_mul(u64::from(spp))
            .ok_or(Error::InvalidSampleCount {
                count: u64::from(spp),
                reason: "the global Halton index would not fit 64 bits",
            })?;
        Ok(HaltonSampler {
            spp,
            resolution,
            halton: Halton::new(randomize, seed),
            scales: [s0, s1],
            exponents: [e0, e1],
            index: 0,
            dimension: 2,
        })
    }

    /// The image resolution the sampler was made for.
    pub fn resolution(&self) -> [u32; 2] {
        self.resolution
    }

    /// The tile scales `[2^j, 3^k]`.
    pub fn scales(&self) -> [u64; 2] {
        self.scales
    }

    /// The tile exponents `[j, k]`.
    pub fn exponents(&self) -> [u32; 2] {
        self.exponents
    }

    /// The underlying sequence.
    pub fn halton(&self) -> &Halton {
        &self.halton
    }

    /// The global sequence index of sample `sample_index` of `pixel`.
    pub fn global_index(&self, pixel: [u32; 2], sample_index: u32) -> u64 {
        let [s0, s1] = self.scales;
        let [e0, e1] = self.exponents;
        let r0 = inverse_radical_inverse(u64::from(pixel[0]) % s0, 2, e0);
        let r1 = inverse_radical_inverse(u64::from(pixel[1]) % s1, 3, e1);
        crt(r0, s0, r1, s1) + u64::from(sample_index) * (s0 * s1)
    }
}

/// `(base^e, e)` for the smallest `e` with `base^e >= n`.
fn smallest_power_at_least(base: u64, n: u32) -> (u64, u32) {
    let (mut scale, mut exponent) = (1u64, 0u32);
    while scale < u64::from(n) {
        scale *= base;
        exponent += 1;
    }
    (scale, exponent)
}

/// The inverse of `a` modulo `n` (`gcd(a, n) = 1`), by the extended Euclidean
/// algorithm; 0 when `n == 1`.
pub fn multiplicative_inverse(a: u64, n: u64) -> u64 {
    let (mut r0, mut r1) = (i128::from(n), i128::from(a % n));
    let (mut t0, mut t1) = (0i128, 1i128);
    while r1 != 0 {
        let q = r0 / r1;
        (r0, r1) = (r1, r0 - q * r1);
        (t0, t1) = (t1, t0 - q * t1);
    }
    // r0 = gcd = 1 and t0 * a = 1 (mod n).
    t0.rem_euclid(i128::from(n)) as u64
}

/// The unique `h < m0 m1` with `h = r0 (mod m0)` and `h = r1 (mod m1)`, for
/// coprime moduli (Chinese remainder theorem).
pub fn crt(r0: u64, m0: u64, r1: u64, m1: u64) -> u64 {
    let m = u128::from(m0) * u128::from(m1);
    let a = u128::from(r0) * u128::from(m1) * u128::from(multiplicative_inverse(m1, m0));
    let b = u128::from(r1) * u128::from(m0) * u128::from(multiplicative_inverse(m0, m1));
    ((a + b) % m) as u64
}

impl PixelSampler for HaltonSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
        self.index = self.global_index(pixel, sample_index);
        self.dimension = dimension.max(2);
    }

    fn get_1d(&mut self) -> f32 {
        if self.dimension >= NUM_DIMENSIONS {
            self.dimension = 2;
        }
        let word = self.halton.sample_word(self.index, self.dimension);
        self.dimension += 1;
        crate::to_f32(word)
    }

    fn get_2d(&mut self) -> [f32; 2] {
        if self.dimension.saturating_add(1) >= NUM_DIMENSIONS {
            self.dimension = 2;
        }
        let d = self.dimension;
        self.dimension += 2;
        [
            crate::to_f32(self.halton.sample_word(self.index, d)),
            crate::to_f32(self.halton.sample_word(self.index, d + 1)),
        ]
    }

    fn get_pixel_2d(&mut self) -> [f32; 2] {
        let [_, s1] = self.scales;
        [
            crate::to_f32(self.halton.sample_word(self.index >> self.exponents[0], 0)),
            crate::to_f32(self.halton.sample_word(self.index / s1, 1)),
        ]
    }
}

#[cfg(test)]
mod tests;
