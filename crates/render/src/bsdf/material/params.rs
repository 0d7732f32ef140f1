//! The structured parameters of materials, generic over how a value is
//! given: [`Roughness`] and [`ConductorSpec`] hold plain values (`f32`,
//! [`Rgb`]) once evaluated at a shading point, and textures
//! ([`FloatTexture`], [`SpectrumTexture`]) inside a [`super::Material`].

use super::MaterialError;
use crate::bsdf::microfacet::{TrowbridgeReitz, roughness_to_alpha};
use crate::spectrum::named::{NamedSpectrum, named_metal};
use crate::spectrum::{Colour, Rgb};
use crate::texture::{FloatTexture, SpectrumTexture, TextureEvalContext};

/// Microfacet roughness parameters as pbrt-v4 takes them: values (`R =
/// f32`, the default) or float textures (inside a material).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Roughness<R = f32> {
    /// Roughness along the tangent (`uroughness`, default `roughness`).
    pub u: R,
    /// Roughness along the bitangent (`vroughness`, default `roughness`).
    pub v: R,
    /// `remaproughness`: alpha = sqrt(roughness) when true (pbrt-v4's default).
    pub remap: bool,
}

impl Roughness {
    /// A perfectly smooth surface.
    pub const SMOOTH: Roughness = Roughness {
        u: 0.0,
        v: 0.0,
        remap: true,
    };
    /// Isotropic roughness.
    pub fn isotropic(r: f32, remap: bool) -> Roughness {
        Roughness { u: r, v: r, remap }
    }
    /// The GGX distribution these parameters describe.
    pub fn distribution(&self) -> TrowbridgeReitz {
        let a = |r: f32| if self.remap { roughness_to_alpha(r) } else { r };
        TrowbridgeReitz::new(a(self.u), a(self.v))
    }
}

impl From<Roughness> for Roughness<FloatTexture> {
    fn from(r: Roughness) -> Self {
        Roughness {
            u: r.u.into(),
            v: r.v.into(),
            remap: r.remap,
        }
    }
}

impl Roughness<FloatTexture> {
    /// The roughness at `ctx`.
    #[inline]
    pub fn evaluate(&self, ctx: &TextureEvalContext) -> Roughness {
        Roughness {
            u: self.u.evaluate(ctx),
            v: self.v.evaluate(ctx),
            remap: self.remap,
        }
    }
    /// True when neither texture varies.
    pub fn is_constant(&self) -> bool {
        self.u.as_constant().is_some() && self.v.as_constant().is_some()
    }
}

/// A conductor's optical constants: explicit `eta`/`k`, or pbrt-v4's
/// artist-friendly `reflectance` (then `eta = 1`, `k = 2 sqrt(r) / sqrt(1 - r)`
/// with `r` clamped to `[0, 0.9999]`, which gives exactly `r` at normal
/// incidence), or a named metal's measured spectra. Values (`S = Rgb`, the
/// default) or RGB textures. In spectral mode `eta`/`k` given as RGB are
/// uplifted as unbounded spectra and `reflectance` as an albedo, as pbrt-v4
/// does; named metals are evaluated at the sampled wavelengths.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ConductorSpec<S = Rgb> {
    /// Complex index of refraction per channel.
    EtaK {
        /// Real part.
        eta: S,
        /// Imaginary part (absorption).
        k: S,
    },
    /// Normal-incidence reflectance.
    Reflectance(S),
    /// A named metal (`"metal-Au-eta"`, `"metal-Au-k"` ...): its measured
    /// spectra, and their band averages in RGB mode.
    Named {
        /// Real part.
        eta: &'static NamedSpectrum,
        /// Imaginary part.
        k: &'static NamedSpectrum,
    },
}

impl ConductorSpec {
    /// A named pbrt-v4 metal: `"Cu"` reads `metal-Cu-eta` and `metal-Cu-k`.
    pub fn named(metal: &str) -> Result<ConductorSpec, MaterialError> {
        let get = |which: &str| {
            let name = format!("metal-{metal}-{which}");
            named_metal(&name).ok_or(MaterialError::UnknownSpectrum(name))
        };
        Ok(ConductorSpec::Named {
            eta: get("eta")?,
            k: get("k")?,
        })
    }
    /// `(eta, k)` per channel (RGB mode).
    pub fn eta_k(&self) -> (Rgb, Rgb) {
        self.eta_k_for(&())
    }
    /// `(eta, k)` per lane of colour `C` at wavelengths `w`.
    pub fn eta_k_for<C: Colour>(&self, w: &C::Wavelengths) -> (C, C) {
        match *self {
            ConductorSpec::EtaK { eta, k } => (C::unbounded(eta, w), C::unbounded(k, w)),
            ConductorSpec::Reflectance(r) => {
                let r = C::albedo(r, w).clamp(0.0, 0.9999);
                let k = r.map(|x| 2.0 * x.sqrt() / (1.0 - x).max(0.0).sqrt());
                (C::ONE, k)
            }
            ConductorSpec::Named { eta, k } => (C::measured(eta, w), C::measured(k, w)),
        }
    }
}

impl From<ConductorSpec> for ConductorSpec<SpectrumTexture> {
    fn from(spec: ConductorSpec) -> Self {
        match spec {
            ConductorSpec::EtaK { eta, k } => ConductorSpec::EtaK {
                eta: eta.into(),
                k: k.into(),
            },
            ConductorSpec::Reflectance(r) => ConductorSpec::Reflectance(r.into()),
            ConductorSpec::Named { eta, k } => ConductorSpec::Named { eta, k },
        }
    }
}

impl ConductorSpec<SpectrumTexture> {
    /// The optical constants at `ctx`.
    #[inline]
    pub fn evaluate(&self, ctx: &TextureEvalContext) -> ConductorSpec {
        match self {
            ConductorSpec::EtaK { eta, k } => ConductorSpec::EtaK {
                eta: eta.evaluate(ctx),
                k: k.evaluate(ctx),
            },
            ConductorSpec::Reflectance(r) => ConductorSpec::Reflectance(r.evaluate(ctx)),
            ConductorSpec::Named { eta, k } => ConductorSpec::Named { eta, k },
        }
    }
}
