//! [`Colour`]: what the BxDFs, materials and the path tracer compute with,
//! implemented by [`Rgb`] (RGB mode) and [`SampledSpectrum`] (spectral
//! mode). Arithmetic is lane-wise in both; the constructors say how an RGB
//! parameter becomes a colour, following pbrt-v4's spectrum types:
//!
//! | constructor | used for | RGB mode | spectral mode |
//! |---|---|---|---|
//! | [`Colour::albedo`] | reflectances, transmittances | the RGB | `RGBAlbedoSpectrum` |
//! | [`Colour::unbounded`] | conductor `eta`, `k` | the RGB | `RGBUnboundedSpectrum` |
//! | [`Colour::illuminant`] | emission, environment maps | the RGB | `RGBIlluminantSpectrum` (× D65) |
//! | [`Colour::measured`] | named metals | its band averages | the measured spectrum |
//! | [`Colour::emission`] | lights with a spectrum (blackbody, files) | the RGB | the spectrum, scaled |
//!
//! In RGB mode every constructor returns its RGB argument unchanged, so RGB
//! renders are what they were before spectral mode existed, bit for bit.

use super::Rgb;
use super::named::NamedSpectrum;
use super::sampled::{SampledSpectrum, SampledWavelengths};
use super::uplift;
use lowdisc_colour::cie::Tabulated;
use std::fmt::Debug;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Sub};

/// A colour the renderer computes with (see the module docs).
pub trait Colour:
    Copy
    + Debug
    + Default
    + PartialEq
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Mul<f32, Output = Self>
    + Div<f32, Output = Self>
    + AddAssign
    + MulAssign
    + DivAssign
    + MulAssign<f32>
    + DivAssign<f32>
{
    /// Where values are sampled: `()` for RGB, the wavelengths for spectra.
    type Wavelengths: Copy + Debug + Send + Sync;
    /// Zero in every lane.
    const ZERO: Self;
    /// One in every lane.
    const ONE: Self;
    /// `v` in every lane.
    fn splat(v: f32) -> Self;
    /// Lane `i` of `f(i)` for every lane, in lane order.
    fn from_fn(f: impl FnMut(usize) -> f32) -> Self;
    /// Lane `i`.
    fn lane(&self, i: usize) -> f32;
    /// `f` applied to every lane.
    fn map(self, f: impl Fn(f32) -> f32) -> Self;
    /// The number of lanes.
    const LANES: usize;
    /// The largest lane.
    fn max_component(self) -> f32;
    /// The mean of the lanes.
    #[inline]
    fn average(self) -> f32 {
        (0..Self::LANES).map(|i| self.lane(i)).sum::<f32>() / Self::LANES as f32
    }
    /// True when every lane is exactly zero.
    fn is_black(self) -> bool;
    /// True when every lane is finite.
    fn is_finite(self) -> bool;
    /// Lanes clamped to `[lo, hi]` (NaN becomes `lo`).
    #[inline]
    fn clamp(self, lo: f32, hi: f32) -> Self {
        self.map(|x| if x > lo { x.min(hi) } else { lo })
    }
    /// Lane-wise square root of the non-negative part.
    #[inline]
    fn sqrt(self) -> Self {
        self.map(|x| x.max(0.0).sqrt())
    }
    /// Lane-wise `e^x`.
    #[inline]
    fn exp(self) -> Self {
        self.map(f32::exp)
    }
    /// A reflectance given as RGB.
    fn albedo(rgb: Rgb, w: &Self::Wavelengths) -> Self;
    /// An unbounded quantity given as RGB (conductor `eta`, `k`).
    fn unbounded(rgb: Rgb, w: &Self::Wavelengths) -> Self;
    /// Emitted radiance given as RGB.
    fn illuminant(rgb: Rgb, w: &Self::Wavelengths) -> Self;
    /// A named measured spectrum.
    fn measured(s: &NamedSpectrum, w: &Self::Wavelengths) -> Self;
    /// Emission `rgb` whose spectrum, when the light has one, is `shape`
    /// (normalised to `∫ ȳ shape = 1`) times `rgb`'s luminance.
    fn emission(rgb: Rgb, shape: Option<&Tabulated>, w: &Self::Wavelengths) -> Self;
}

impl Colour for Rgb {
    type Wavelengths = ();
    const ZERO: Rgb = Rgb::ZERO;
    const ONE: Rgb = Rgb::ONE;
    const LANES: usize = 3;
    #[inline]
    fn splat(v: f32) -> Rgb {
        Rgb::splat(v)
    }
    #[inline]
    fn from_fn(mut f: impl FnMut(usize) -> f32) -> Rgb {
        let r = f(0);
        let g = f(1);
        Rgb::new(r, g, f(2))
    }
    #[inline]
    fn lane(&self, i: usize) -> f32 {
        self[i]
    }
    #[inline]
    fn map(self, f: impl Fn(f32) -> f32) -> Rgb {
        Rgb::map(self, f)
    }
    #[inline]
    fn max_component(self) -> f32 {
        Rgb::max_component(self)
    }
    #[inline]
    fn is_black(self) -> bool {
        Rgb::is_black(self)
    }
    #[inline]
    fn is_finite(self) -> bool {
        Rgb::is_finite(self)
    }
    #[inline]
    fn clamp(self, lo: f32, hi: f32) -> Rgb {
        Rgb::clamp(self, lo, hi)
    }
    #[inline]
    fn sqrt(self) -> Rgb {
        Rgb::sqrt(self)
    }
    #[inline]
    fn exp(self) -> Rgb {
        Rgb::exp(self)
    }
    #[inline]
    fn albedo(rgb: Rgb, _: &()) -> Rgb {
        rgb
    }
    #[inline]
    fn unbounded(rgb: Rgb, _: &()) -> Rgb {
        rgb
    }
    #[inline]
    fn illuminant(rgb: Rgb, _: &()) -> Rgb {
        rgb
    }
    #[inline]
    fn measured(s: &NamedSpectrum, _: &()) -> Rgb {
        s.rgb
    }
    #[inline]
    fn emission(rgb: Rgb, _: Option<&Tabulated>, _: &()) -> Rgb {
        rgb
    }
}

impl Colour for SampledSpectrum {
    type Wavelengths = SampledWavelengths;
    const ZERO: SampledSpectrum = SampledSpectrum([0.0; 4]);
    const ONE: SampledSpectrum = SampledSpectrum([1.0; 4]);
    const LANES: usize = 4;
    #[inline]
    fn splat(v: f32) -> Self {
        SampledSpectrum([v; 4])
    }
    #[inline]
    fn from_fn(f: impl FnMut(usize) -> f32) -> Self {
        SampledSpectrum(std::array::from_fn(f))
    }
    #[inline]
    fn lane(&self, i: usize) -> f32 {
        self.0[i]
    }
    #[inline]
    fn map(self, f: impl Fn(f32) -> f32) -> Self {
        SampledSpectrum(self.0.map(f))
    }
    #[inline]
    fn max_component(self) -> f32 {
        self.0.iter().fold(f32::NEG_INFINITY, |a, &b| a.max(b))
    }
    #[inline]
    fn is_black(self) -> bool {
        self.0.iter().all(|&v| v == 0.0)
    }
    #[inline]
    fn is_finite(self) -> bool {
        self.0.iter().all(|v| v.is_finite())
    }
    fn albedo(rgb: Rgb, w: &SampledWavelengths) -> Self {
        let s = uplift::albedo(rgb);
        Self::from_fn(|i| s.eval(w.lambda[i]))
    }
    fn unbounded(rgb: Rgb, w: &SampledWavelengths) -> Self {
        let s = uplift::unbounded(rgb);
        Self::from_fn(|i| s.eval(w.lambda[i]))
    }
    fn illuminant(rgb: Rgb, w: &SampledWavelengths) -> Self {
        let s = uplift::unbounded(rgb);
        Self::from_fn(|i| s.eval(w.lambda[i]) * uplift::illuminant_d65(w.lambda[i]))
    }
    fn measured(s: &NamedSpectrum, w: &SampledWavelengths) -> Self {
        Self::from_fn(|i| s.spectrum.eval(w.lambda[i]))
    }
    fn emission(rgb: Rgb, shape: Option<&Tabulated>, w: &SampledWavelengths) -> Self {
        match shape {
            None => Self::illuminant(rgb, w),
            Some(t) => {
                let y = rgb.luminance();
                Self::from_fn(|i| t.eval(w.lambda[i]) * y)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rgb_constructors_are_the_identity() {
        let c = Rgb::new(0.3, 2.0, 0.1);
        assert_eq!(Rgb::albedo(c, &()), c);
        assert_eq!(Rgb::unbounded(c, &()), c);
        assert_eq!(Rgb::illuminant(c, &()), c);
        assert_eq!(Rgb::emission(c, None, &()), c);
        assert_eq!(
            <Rgb as Colour>::from_fn(|i| i as f32),
            Rgb::new(0.0, 1.0, 2.0)
        );
    }

    #[test]
    fn sampled_lanes_are_independent() {
        let a = SampledSpectrum([1.0, 2.0, 3.0, 4.0]);
        assert_eq!((a * a - a) / 2.0, SampledSpectrum([0.0, 1.0, 3.0, 6.0]));
        assert_eq!(a.max_component(), 4.0);
        assert!(SampledSpectrum::ZERO.is_black() && !a.is_black());
        assert!(!SampledSpectrum([0.0, f32::NAN, 0.0, 0.0]).is_finite());
        assert_eq!(a.clamp(1.5, 3.5), SampledSpectrum([1.5, 2.0, 3.0, 3.5]));
        let w = SampledWavelengths::sample_visible(0.2);
        // White uplifts to the constant 1, as pbrt-v4's RGBAlbedoSpectrum.
        assert_eq!(SampledSpectrum::albedo(Rgb::ONE, &w), SampledSpectrum::ONE);
        assert_eq!(
            SampledSpectrum::albedo(Rgb::ZERO, &w),
            SampledSpectrum::ZERO
        );
    }
}
