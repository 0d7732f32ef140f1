//! Participating media (pbrt-v4's `Medium`): what fills the space between
//! surfaces, absorbing, scattering and emitting light along rays.
//!
//! * [`Medium`]: one medium. Only pbrt-v4's `"homogeneous"` type exists: the
//!   absorption and scattering coefficients `σa`, `σs` (per unit of world
//!   distance, `scale` applied), the emitted radiance `Le` and the
//!   Henyey-Greenstein asymmetry `g` are the same everywhere.
//! * [`MediumInterface`]: the media on the two sides of a shape's surface
//!   (`inside` is the side opposite its geometric normal), or of no surface
//!   (the camera's medium is an interface's `outside`).
//! * [`phase`]: the Henyey-Greenstein phase function, evaluated and sampled.
//!
//! Coefficients are given as RGB and become the path's [`Colour`] as pbrt-v4
//! makes its spectra: `σa` and `σs` are unbounded spectra, `Le` an
//! illuminant ([`Colour::unbounded`], [`Colour::illuminant`]). In RGB mode
//! every channel is its own medium (a chromatic medium attenuates red and
//! blue differently); in spectral mode every sampled wavelength is.
//! Media are indexed by `u32` in the scene ([`crate::scene::Scene::media`]).

pub mod phase;

use crate::spectrum::{Colour, Rgb};

/// A homogeneous medium's coefficients as RGB (`scale` already applied).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HomogeneousMedium {
    /// Absorption coefficient `σa` (per unit distance).
    pub sigma_a: Rgb,
    /// Scattering coefficient `σs` (per unit distance).
    pub sigma_s: Rgb,
    /// Emitted radiance `Le` (`Lescale` applied); emission is `σa · Le`.
    pub le: Rgb,
    /// Henyey-Greenstein asymmetry `g` in `(-1, 1)`.
    pub g: f32,
}

/// A participating medium.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Medium {
    /// The same coefficients everywhere.
    Homogeneous(HomogeneousMedium),
}

/// A medium's coefficients in colour `C` at one point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MediumPoint<C> {
    /// Absorption coefficient.
    pub sigma_a: C,
    /// Scattering coefficient.
    pub sigma_s: C,
    /// Emitted radiance (multiplied by `sigma_a` where it is added).
    pub le: C,
    /// Henyey-Greenstein asymmetry.
    pub g: f32,
}

impl<C: Colour> MediumPoint<C> {
    /// The extinction coefficient `σt = σa + σs`.
    #[inline]
    pub fn sigma_t(&self) -> C {
        self.sigma_a + self.sigma_s
    }
}

impl Medium {
    /// The medium's coefficients in colour `C` at wavelengths `w` (the same
    /// at every point of a homogeneous medium).
    ///
    /// ```
    /// use lowdisc_render::medium::{HomogeneousMedium, Medium};
    /// use lowdisc_render::spectrum::Rgb;
    ///
    /// let m = Medium::Homogeneous(HomogeneousMedium {
    ///     sigma_a: Rgb::new(1.0, 2.0, 3.0),
    ///     sigma_s: Rgb::splat(0.5),
    ///     le: Rgb::ZERO,
    ///     g: 0.0,
    /// });
    /// let p = m.point::<Rgb>(&());
    /// assert_eq!(p.sigma_t(), Rgb::new(1.5, 2.5, 3.5));
    /// ```
    pub fn point<C: Colour>(&self, w: &C::Wavelengths) -> MediumPoint<C> {
        match self {
            Medium::Homogeneous(h) => MediumPoint {
                sigma_a: C::unbounded(h.sigma_a, w),
                sigma_s: C::unbounded(h.sigma_s, w),
                le: if h.le.is_black() {
                    C::ZERO
                } else {
                    C::illuminant(h.le, w)
                },
                g: h.g,
            },
        }
    }

    /// The transmittance `exp(-σt d)` along a straight segment of length
    /// `d` inside the medium, in colour `C` (Beer-Lambert; exact for a
    /// homogeneous medium).
    ///
    /// ```
    /// use lowdisc_render::medium::{HomogeneousMedium, Medium};
    /// use lowdisc_render::spectrum::Rgb;
    ///
    /// let m = Medium::Homogeneous(HomogeneousMedium {
    ///     sigma_a: Rgb::splat(0.25),
    ///     sigma_s: Rgb::splat(0.25),
    ///     le: Rgb::ZERO,
    ///     g: 0.0,
    /// });
    /// let t = m.transmittance::<Rgb>(2.0, &());
    /// assert!((t.g - (-1.0f32).exp()).abs() < 1e-6);
    /// ```
    pub fn transmittance<C: Colour>(&self, d: f32, w: &C::Wavelengths) -> C {
        (self.point::<C>(w).sigma_t() * -finite_distance(d)).exp()
    }

    /// True when the medium emits light.
    pub fn emits(&self) -> bool {
        match self {
            Medium::Homogeneous(h) => !h.le.is_black(),
        }
    }
}

/// `d`, with infinity replaced by `f32::MAX` so that a coefficient of zero
/// times it stays zero (pbrt-v4 does the same).
#[inline]
pub fn finite_distance(d: f32) -> f32 {
    d.min(f32::MAX)
}

/// The media on the two sides of a surface, or the camera's medium
/// (`outside`). `None` is vacuum.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MediumInterface {
    /// The medium on the side opposite the geometric normal.
    pub inside: Option<u32>,
    /// The medium on the geometric normal's side.
    pub outside: Option<u32>,
}

impl MediumInterface {
    /// True when the two sides differ: only then does crossing the surface
    /// change the medium (pbrt-v4 keeps the ray's medium otherwise).
    pub fn is_transition(&self) -> bool {
        self.inside != self.outside
    }

    /// The medium a ray leaving the surface (geometric normal `ng`) in
    /// direction `w` travels in.
    ///
    /// ```
    /// use lowdisc_render::math::Vec3;
    /// use lowdisc_render::medium::MediumInterface;
    ///
    /// let mi = MediumInterface { inside: Some(0), outside: None };
    /// assert_eq!(mi.toward(Vec3::Z, Vec3::new(0.0, 0.0, -1.0)), Some(0));
    /// assert_eq!(mi.toward(Vec3::Z, Vec3::Z), None);
    /// ```
    #[inline]
    pub fn toward(&self, ng: crate::math::Vec3, w: crate::math::Vec3) -> Option<u32> {
        if ng.dot(w) > 0.0 {
            self.outside
        } else {
            self.inside
        }
    }
}
