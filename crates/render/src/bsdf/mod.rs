//! Scattering functions (BSDFs) in pbrt-v4's conventions, generic over the
//! [`Colour`] they carry: RGB, or four sampled wavelengths in spectral mode
//! (no BxDF here is dispersive, so all wavelengths scatter alike).
//!
//! Every BxDF works in a local shading frame with the normal along `+z`;
//! `wo` (towards the viewer) and `wi` (towards the light) both point away
//! from the surface. Values are `f(wo, wi)` without the cosine; sampling
//! returns a [`BsdfSample`] with `wi`, `f`, the solid-angle `pdf` and lobe
//! [`BxdfFlags`] (delta lobes have `pdf` equal to the discrete probability
//! of the lobe and `f` holding the delta's weight divided by `|cos θi|`).
//!
//! * [`diffuse`]: Lambertian reflection and diffuse transmission;
//! * [`conductor`]: GGX (Trowbridge-Reitz) conductor, complex Fresnel;
//! * [`dielectric`]: smooth and rough (Walter et al. 2007) dielectric, thin dielectric;
//! * [`layered`]: pbrt-v4's stochastic layered BxDF (coated diffuse/conductor);
//! * [`world`]: [`Bsdf`], a BxDF plus its shading frame, in world space;
//! * [`material`]: material parameters (constant or textured) to a [`Bsdf`].

pub mod conductor;
pub mod dielectric;
pub mod diffuse;
pub mod fresnel;
pub mod layered;
pub mod material;
pub mod microfacet;
pub mod world;

pub use conductor::ConductorBxdf;
pub use dielectric::{DielectricBxdf, ThinDielectricBxdf};
pub use diffuse::{DiffuseBxdf, DiffuseTransmissionBxdf};
pub use layered::{CoatedConductorBxdf, CoatedDiffuseBxdf, LayeredBxdf, LayeredExitWeight};
pub use material::{
    BsdfContext, Bump, BumpedMaterial, ConductorSpec, Material, MaterialError, MixMaterial,
    Roughness, mix_choice,
};
pub use microfacet::TrowbridgeReitz;
pub use world::Bsdf;

use crate::math::Vec3;
use crate::spectrum::{Colour, Rgb};
use std::ops::BitOr;

/// Lobe flags of a BxDF or of one sample (pbrt-v4's `BxDFFlags`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct BxdfFlags(pub u8);

impl BxdfFlags {
    /// No lobe (an empty BxDF).
    pub const UNSET: BxdfFlags = BxdfFlags(0);
    /// Scatters into the hemisphere of `wo`.
    pub const REFLECTION: BxdfFlags = BxdfFlags(1);
    /// Scatters into the opposite hemisphere.
    pub const TRANSMISSION: BxdfFlags = BxdfFlags(2);
    /// A diffuse (wide) lobe.
    pub const DIFFUSE: BxdfFlags = BxdfFlags(4);
    /// A glossy (finite, peaked) lobe.
    pub const GLOSSY: BxdfFlags = BxdfFlags(8);
    /// A delta lobe: `f` and `pdf` are zero for every given `wi`.
    pub const SPECULAR: BxdfFlags = BxdfFlags(16);
    /// Diffuse reflection.
    pub const DIFFUSE_REFLECTION: BxdfFlags = BxdfFlags(4 | 1);
    /// Diffuse transmission.
    pub const DIFFUSE_TRANSMISSION: BxdfFlags = BxdfFlags(4 | 2);
    /// Glossy reflection.
    pub const GLOSSY_REFLECTION: BxdfFlags = BxdfFlags(8 | 1);
    /// Glossy transmission.
    pub const GLOSSY_TRANSMISSION: BxdfFlags = BxdfFlags(8 | 2);
    /// Specular reflection.
    pub const SPECULAR_REFLECTION: BxdfFlags = BxdfFlags(16 | 1);
    /// Specular transmission.
    pub const SPECULAR_TRANSMISSION: BxdfFlags = BxdfFlags(16 | 2);

    /// True when every bit of `other` is set.
    #[inline]
    pub fn contains(self, other: BxdfFlags) -> bool {
        self.0 & other.0 == other.0
    }
    /// True when a reflection lobe is present.
    #[inline]
    pub fn is_reflective(self) -> bool {
        self.0 & 1 != 0
    }
    /// True when a transmission lobe is present.
    #[inline]
    pub fn is_transmissive(self) -> bool {
        self.0 & 2 != 0
    }
    /// True when a diffuse lobe is present.
    #[inline]
    pub fn is_diffuse(self) -> bool {
        self.0 & 4 != 0
    }
    /// True when a glossy lobe is present.
    #[inline]
    pub fn is_glossy(self) -> bool {
        self.0 & 8 != 0
    }
    /// True when a delta lobe is present.
    #[inline]
    pub fn is_specular(self) -> bool {
        self.0 & 16 != 0
    }
    /// True when a diffuse or glossy lobe is present (light sampling is useful).
    #[inline]
    pub fn is_non_specular(self) -> bool {
        self.0 & (4 | 8) != 0
    }
}

impl BitOr for BxdfFlags {
    type Output = BxdfFlags;
    #[inline]
    fn bitor(self, o: BxdfFlags) -> BxdfFlags {
        BxdfFlags(self.0 | o.0)
    }
}

/// Which hemispheres sampling may choose (pbrt-v4's `BxDFReflTransFlags`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SampleFlags {
    /// Reflection and transmission.
    All,
    /// Reflection only.
    Reflection,
    /// Transmission only.
    Transmission,
}

impl SampleFlags {
    /// True when reflection may be sampled.
    #[inline]
    pub fn reflection(self) -> bool {
        self != SampleFlags::Transmission
    }
    /// True when transmission may be sampled.
    #[inline]
    pub fn transmission(self) -> bool {
        self != SampleFlags::Reflection
    }
}

/// What a path carries: radiance (camera paths) or importance (light
/// paths). Refraction scales radiance by `1/η²`, importance not.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TransportMode {
    /// Camera paths (the usual case).
    #[default]
    Radiance,
    /// Light paths (adjoint transport).
    Importance,
}

impl TransportMode {
    /// The other mode.
    #[inline]
    pub fn flip(self) -> TransportMode {
        match self {
            TransportMode::Radiance => TransportMode::Importance,
            TransportMode::Importance => TransportMode::Radiance,
        }
    }
}

/// One sampled scattering direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BsdfSample<C = Rgb> {
    /// BSDF value for (`wo`, `wi`) (for delta lobes: weight / `|cos θi|`).
    pub f: C,
    /// Sampled incident direction (local or world, as the caller's space).
    pub wi: Vec3,
    /// Solid-angle density of `wi` (for delta lobes: the lobe probability).
    pub pdf: f32,
    /// The lobe sampled.
    pub flags: BxdfFlags,
    /// Relative index of refraction crossed (1 for reflection).
    pub eta: f32,
    /// True when `pdf` is only proportional to the real density (the
    /// stochastic layered BxDF): `f / pdf` is still the right weight, but
    /// MIS must call `pdf()` for the density.
    pub pdf_is_proportional: bool,
}

impl<C> BsdfSample<C> {
    /// A sample with `eta = 1` and an exact pdf.
    #[inline]
    pub fn new(f: C, wi: Vec3, pdf: f32, flags: BxdfFlags) -> Self {
        BsdfSample {
            f,
            wi,
            pdf,
            flags,
            eta: 1.0,
            pdf_is_proportional: false,
        }
    }
    /// True when the sample is a reflection.
    #[inline]
    pub fn is_reflection(&self) -> bool {
        self.flags.is_reflective()
    }
    /// True when the sample is a transmission.
    #[inline]
    pub fn is_transmission(&self) -> bool {
        self.flags.is_transmissive()
    }
    /// True when the sample came from a delta lobe.
    #[inline]
    pub fn is_specular(&self) -> bool {
        self.flags.is_specular()
    }
}

/// The interface every local-frame BxDF implements.
pub trait BxdfModel<C: Colour = Rgb> {
    /// The lobes present.
    fn flags(&self) -> BxdfFlags;
    /// `f(wo, wi)` (zero for delta lobes).
    fn f(&self, wo: Vec3, wi: Vec3, mode: TransportMode) -> C;
    /// Samples `wi` given `wo`, a lobe-choice number `uc` and a 2D sample `u`
    /// (all in `[0,1)`), restricted to `sample` hemispheres.
    fn sample_f(
        &self,
        wo: Vec3,
        uc: f32,
        u: [f32; 2],
        mode: TransportMode,
        sample: SampleFlags,
    ) -> Option<BsdfSample<C>>;
    /// Solid-angle density with which `sample_f` (restricted to `sample`)
    /// returns `wi` (zero for delta lobes).
    fn pdf(&self, wo: Vec3, wi: Vec3, mode: TransportMode, sample: SampleFlags) -> f32;
    /// Widens near-specular lobes (path regularization); a no-op by default.
    fn regularize(&mut self) {}
}

/// Any of the BxDFs, dispatched by `match` (no allocation).
#[derive(Clone, Debug)]
pub enum Bxdf<C = Rgb> {
    /// Lambertian reflection.
    Diffuse(DiffuseBxdf<C>),
    /// Lambertian reflection plus Lambertian transmission.
    DiffuseTransmission(DiffuseTransmissionBxdf<C>),
    /// GGX conductor.
    Conductor(ConductorBxdf<C>),
    /// Smooth or rough dielectric.
    Dielectric(DielectricBxdf),
    /// Thin dielectric sheet.
    ThinDielectric(ThinDielectricBxdf),
    /// Dielectric coating over a diffuse base.
    CoatedDiffuse(CoatedDiffuseBxdf<C>),
    /// Dielectric coating over a conductor base.
    CoatedConductor(CoatedConductorBxdf<C>),
}

macro_rules! dispatch {
    ($s:expr, $b:ident => $e:expr) => {
        match $s {
            Bxdf::Diffuse($b) => $e,
            Bxdf::DiffuseTransmission($b) => $e,
            Bxdf::Conductor($b) => $e,
            Bxdf::Dielectric($b) => $e,
            Bxdf::ThinDielectric($b) => $e,
            Bxdf::CoatedDiffuse($b) => $e,
            Bxdf::CoatedConductor($b) => $e,
        }
    };
}

impl<C: Colour> BxdfModel<C> for Bxdf<C> {
    fn flags(&self) -> BxdfFlags {
        dispatch!(self, b => BxdfModel::<C>::flags(b))
    }
    fn f(&self, wo: Vec3, wi: Vec3, mode: TransportMode) -> C {
        dispatch!(self, b => b.f(wo, wi, mode))
    }
    fn sample_f(
        &self,
        wo: Vec3,
        uc: f32,
        u: [f32; 2],
        mode: TransportMode,
        sample: SampleFlags,
    ) -> Option<BsdfSample<C>> {
        dispatch!(self, b => b.sample_f(wo, uc, u, mode, sample))
    }
    fn pdf(&self, wo: Vec3, wi: Vec3, mode: TransportMode, sample: SampleFlags) -> f32 {
        dispatch!(self, b => BxdfModel::<C>::pdf(b, wo, wi, mode, sample))
    }
    fn regularize(&mut self) {
        dispatch!(self, b => BxdfModel::<C>::regularize(b))
    }
}

impl<C> Bxdf<C> {
    /// Sets how a layered BxDF weights its walks' exit connection; other
    /// BxDFs are unchanged.
    pub fn set_layered_exit_weight(&mut self, exit_weight: LayeredExitWeight) {
        match self {
            Bxdf::CoatedDiffuse(b) => b.exit_weight = exit_weight,
            Bxdf::CoatedConductor(b) => b.exit_weight = exit_weight,
            _ => {}
        }
    }
}

/// Cosine-weighted hemisphere direction (upper hemisphere), pdf `cos θ / π`
/// (Malley's method on the concentric disk).
#[inline]
pub fn sample_cosine_hemisphere(u: [f32; 2]) -> Vec3 {
    let d =
        crate::math::sampling::sample_uniform_disk_concentric(crate::math::Point2::new(u[0], u[1]));
    let z = (1.0 - d.x * d.x - d.y * d.y).max(0.0).sqrt();
    Vec3::new(d.x, d.y, z)
}

/// pbrt's power heuristic with exponent 2 for one sample from each strategy.
#[inline]
pub fn power_heuristic(f_pdf: f32, g_pdf: f32) -> f32 {
    let (f, g) = (f_pdf * f_pdf, g_pdf * g_pdf);
    if f.is_infinite() {
        return 1.0;
    }
    if f + g == 0.0 { 0.0 } else { f / (f + g) }
}
