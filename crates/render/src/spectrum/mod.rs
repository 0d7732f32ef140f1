//! Colour in the renderer: RGB ([`Rgb`]) or four sampled wavelengths
//! ([`SampledSpectrum`] at [`SampledWavelengths`]), behind one trait,
//! [`Colour`], which the BxDFs, the materials and the path tracer are
//! generic over.
//!
//! * **RGB mode** (the default; `lowdisc experiment` and the built-in
//!   scenes): every value is three linear sRGB channels and arithmetic is
//!   channel-wise. Measured spectra are reduced to RGB by band averages
//!   ([`file`]).
//! * **Spectral mode** (`--spectral`, as pbrt-v4): each camera sample
//!   carries four wavelengths (hero-wavelength sampling, [`sampled`]); RGB
//!   parameters are uplifted to smooth spectra with Jakob & Hanika's
//!   sigmoid-polynomial table, fitted at build time ([`uplift`]); named
//!   metals and blackbodies are evaluated as spectra ([`named`]); the film's
//!   sensor turns the samples into XYZ and then sRGB ([`sensor`]).
//! * Named spectra in RGB mode: the named metals' band averages and the
//!   named glasses' refractive indices ([`metals`]).

pub mod colour;
pub mod file;
pub mod metals;
pub mod named;
pub mod sampled;
pub mod sensor;
pub mod uplift;

pub use colour::Colour;
pub use file::{
    RGB_BANDS_NM, SpectrumError, parse_spectrum_text, spectrum_file_to_rgb, spectrum_samples_to_rgb,
};
pub use sampled::{SampledSpectrum, SampledWavelengths};

use crate::content_hash::{ContentHash, ContentSink};
use std::ops::{Add, AddAssign, Div, DivAssign, Index, Mul, MulAssign, Sub};

/// A linear RGB triple (radiance, reflectance, or optical constants).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Rgb {
    /// Red channel.
    pub r: f32,
    /// Green channel.
    pub g: f32,
    /// Blue channel.
    pub b: f32,
}

impl Rgb {
    /// Black.
    pub const ZERO: Rgb = Rgb::splat(0.0);
    /// White (1, 1, 1).
    pub const ONE: Rgb = Rgb::splat(1.0);

    /// Builds a colour from its channels.
    #[inline]
    pub const fn new(r: f32, g: f32, b: f32) -> Rgb {
        Rgb { r, g, b }
    }
    /// All channels equal to `v`.
    #[inline]
    pub const fn splat(v: f32) -> Rgb {
        Rgb { r: v, g: v, b: v }
    }
    /// From an array `[r, g, b]`.
    #[inline]
    pub const fn from_array(a: [f32; 3]) -> Rgb {
        Rgb::new(a[0], a[1], a[2])
    }
    /// The channels as an array.
    #[inline]
    pub const fn to_array(self) -> [f32; 3] {
        [self.r, self.g, self.b]
    }
    /// Applies `f` to every channel.
    #[inline]
    pub fn map(self, f: impl Fn(f32) -> f32) -> Rgb {
        Rgb::new(f(self.r), f(self.g), f(self.b))
    }
    /// Largest channel.
    #[inline]
    pub fn max_component(self) -> f32 {
        self.r.max(self.g).max(self.b)
    }
    /// Smallest channel.
    #[inline]
    pub fn min_component(self) -> f32 {
        self.r.min(self.g).min(self.b)
    }
    /// Mean of the channels.
    #[inline]
    pub fn average(self) -> f32 {
        (self.r + self.g + self.b) / 3.0
    }
    /// Luminance with the Rec. 709 / sRGB weights.
    #[inline]
    pub fn luminance(self) -> f32 {
        0.2126 * self.r + 0.7152 * self.g + 0.0722 * self.b
    }
    /// True when every channel is exactly zero.
    #[inline]
    pub fn is_black(self) -> bool {
        self.r == 0.0 && self.g == 0.0 && self.b == 0.0
    }
    /// True when every channel is finite.
    #[inline]
    pub fn is_finite(self) -> bool {
        self.r.is_finite() && self.g.is_finite() && self.b.is_finite()
    }
    /// Channels clamped to `[lo, hi]` (NaN becomes `lo`).
    #[inline]
    pub fn clamp(self, lo: f32, hi: f32) -> Rgb {
        self.map(|x| if x > lo { x.min(hi) } else { lo })
    }
    /// Channel-wise square root of the non-negative part.
    #[inline]
    pub fn sqrt(self) -> Rgb {
        self.map(|x| x.max(0.0).sqrt())
    }
    /// Channel-wise `e^x`.
    #[inline]
    pub fn exp(self) -> Rgb {
        self.map(f32::exp)
    }
}

impl Index<usize> for Rgb {
    type Output = f32;
    #[inline]
    fn index(&self, i: usize) -> &f32 {
        match i {
            0 => &self.r,
            1 => &self.g,
            _ => &self.b,
        }
    }
}

macro_rules! rgb_binop {
    ($tr:ident, $f:ident, $op:tt, $tra:ident, $fa:ident) => {
        impl $tr for Rgb {
            type Output = Rgb;
            #[inline]
            fn $f(self, o: Rgb) -> Rgb {
                Rgb::new(self.r $op o.r, self.g $op o.g, self.b $op o.b)
            }
        }
        impl $tr<f32> for Rgb {
            type Output = Rgb;
            #[inline]
            fn $f(self, s: f32) -> Rgb {
                Rgb::new(self.r $op s, self.g $op s, self.b $op s)
            }
        }
        impl $tra for Rgb {
            #[inline]
            fn $fa(&mut self, o: Rgb) {
                *self = *self $op o;
            }
        }
        impl $tra<f32> for Rgb {
            #[inline]
            fn $fa(&mut self, s: f32) {
                *self = *self $op s;
            }
        }
    };
}
rgb_binop!(Add, add, +, AddAssign, add_assign);
rgb_binop!(Mul, mul, *, MulAssign, mul_assign);
rgb_binop!(Div, div, /, DivAssign, div_assign);

impl Sub for Rgb {
    type Output = Rgb;
    #[inline]
    fn sub(self, o: Rgb) -> Rgb {
        Rgb::new(self.r - o.r, self.g - o.g, self.b - o.b)
    }
}
impl Mul<Rgb> for f32 {
    type Output = Rgb;
    #[inline]
    fn mul(self, c: Rgb) -> Rgb {
        c * self
    }
}

impl ContentHash for Rgb {
    #[inline]
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let Rgb { r, g, b } = self;
        [r, g, b].feed(sink);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rgb_ops() {
        let a = Rgb::new(1.0, 2.0, 4.0);
        assert_eq!(a * 2.0 - a, a);
        assert_eq!(a / a, Rgb::ONE);
        assert_eq!(a.max_component(), 4.0);
        assert_eq!(a.min_component(), 1.0);
        assert!((Rgb::ONE.luminance() - 1.0).abs() < 1e-6);
        assert_eq!(
            Rgb::new(f32::NAN, -1.0, 3.0).clamp(0.0, 1.0),
            Rgb::new(0.0, 0.0, 1.0)
        );
        assert!(Rgb::ZERO.is_black() && !a.is_black());
        assert_eq!(a[2], 4.0);
    }
}
