//! Materials: pbrt-v4 material parameters turned into a [`Bsdf`] at a
//! shading point; plus the stochastic choice of a `mix` material and a
//! documented fallback for `measured`.
//!
//! Most variants of [`Material`] hold constant parameters (the cheap common
//! case). [`Material::Textured`] holds a [`TexturedMaterial`] whose textures
//! are evaluated at the hit's `uv` and position ([`BsdfContext`]) by
//! [`Material::bsdf`], and [`Material::Mix`] picks one of two materials per
//! point (see [`textured`]).

mod mix;
pub mod textured;

use super::conductor::ConductorBxdf;
use super::dielectric::{DielectricBxdf, ThinDielectricBxdf};
use super::diffuse::{DiffuseBxdf, DiffuseTransmissionBxdf};
use super::layered::LayeredBxdf;
use super::metals::named_spectrum_rgb;
use super::microfacet::{TrowbridgeReitz, roughness_to_alpha};
use super::{Bsdf, Bxdf, BxdfModel};
use crate::math::{Point2, Point3, Vec3};
use crate::spectrum::Rgb;
use crate::texture::TextureEvalContext;
pub use mix::{MixMaterial, mix_choice};
use std::sync::Arc;
pub use textured::{TexturedConductor, TexturedMaterial, TexturedRoughness};

/// Errors building a material from pbrt-v4 names.
#[derive(Debug, Clone, PartialEq)]
pub enum MaterialError {
    /// The material type is not one this renderer knows.
    UnknownType(String),
    /// A named spectrum (e.g. `"metal-CuZn-eta"`) has no RGB value here.
    UnknownSpectrum(String),
}

impl std::fmt::Display for MaterialError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            MaterialError::UnknownType(t) => write!(f, "unknown material type {t:?}"),
            MaterialError::UnknownSpectrum(s) => write!(f, "no RGB value for named spectrum {s:?}"),
        }
    }
}

impl std::error::Error for MaterialError {}

/// Microfacet roughness parameters as pbrt-v4 takes them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Roughness {
    /// Roughness along the tangent (`uroughness`, default `roughness`).
    pub u: f32,
    /// Roughness along the bitangent (`vroughness`, default `roughness`).
    pub v: f32,
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

/// A conductor's optical constants: explicit `eta`/`k`, or pbrt-v4's
/// artist-friendly `reflectance` (then `eta = 1`, `k = 2 sqrt(r) / sqrt(1 - r)`
/// with `r` clamped to `[0, 0.9999]`, which gives exactly `r` at normal
/// incidence).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ConductorSpec {
    /// Complex index of refraction per channel.
    EtaK {
        /// Real part.
        eta: Rgb,
        /// Imaginary part (absorption).
        k: Rgb,
    },
    /// Normal-incidence reflectance.
    Reflectance(Rgb),
}

impl ConductorSpec {
    /// A named pbrt-v4 metal: `"Cu"` reads `metal-Cu-eta` and `metal-Cu-k`.
    pub fn named(metal: &str) -> Result<ConductorSpec, MaterialError> {
        let get = |which: &str| {
            let name = format!("metal-{metal}-{which}");
            named_spectrum_rgb(&name).ok_or(MaterialError::UnknownSpectrum(name))
        };
        Ok(ConductorSpec::EtaK {
            eta: get("eta")?,
            k: get("k")?,
        })
    }
    /// `(eta, k)` per channel.
    pub fn eta_k(&self) -> (Rgb, Rgb) {
        match *self {
            ConductorSpec::EtaK { eta, k } => (eta, k),
            ConductorSpec::Reflectance(r) => {
                let r = r.clamp(0.0, 0.9999);
                let k = r.map(|x| 2.0 * x.sqrt() / (1.0 - x).max(0.0).sqrt());
                (Rgb::ONE, k)
            }
        }
    }
}

/// A material: constant parameters, or textured ones, or a mix.
#[derive(Clone, Debug, PartialEq)]
pub enum Material {
    /// pbrt `diffuse`: `reflectance` (default 0.5).
    Diffuse {
        /// Lambertian reflectance.
        reflectance: Rgb,
    },
    /// pbrt `conductor` (defaults: copper, smooth).
    Conductor {
        /// Optical constants.
        spec: ConductorSpec,
        /// Roughness.
        roughness: Roughness,
    },
    /// pbrt `dielectric` (default eta 1.5, smooth).
    Dielectric {
        /// Relative index of refraction.
        eta: f32,
        /// Roughness.
        roughness: Roughness,
    },
    /// pbrt `thindielectric` (default eta 1.5).
    ThinDielectric {
        /// Relative index of refraction.
        eta: f32,
    },
    /// pbrt `diffusetransmission` (defaults 0.25, 0.25, scale 1).
    DiffuseTransmission {
        /// Reflectance.
        reflectance: Rgb,
        /// Transmittance.
        transmittance: Rgb,
        /// Multiplies both.
        scale: f32,
    },
    /// pbrt `coateddiffuse`.
    CoatedDiffuse {
        /// Base reflectance (default 0.5).
        reflectance: Rgb,
        /// Coating roughness (default smooth).
        roughness: Roughness,
        /// Layer thickness (default 0.01).
        thickness: f32,
        /// Coating index (default 1.5).
        eta: f32,
        /// Random-walk depth (default 10).
        max_depth: u32,
        /// Walks per estimate (default 1).
        n_samples: u32,
    },
    /// pbrt `coatedconductor`.
    CoatedConductor {
        /// `interface.roughness` (default smooth).
        interface_roughness: Roughness,
        /// `interface.eta` (default 1.5).
        interface_eta: f32,
        /// Layer thickness (default 0.01).
        thickness: f32,
        /// `conductor.eta`/`conductor.k` or `reflectance` (default copper).
        conductor: ConductorSpec,
        /// `conductor.roughness` (default smooth).
        conductor_roughness: Roughness,
        /// Random-walk depth (default 10).
        max_depth: u32,
        /// Walks per estimate (default 1).
        n_samples: u32,
    },
    /// A material with textured parameters, evaluated at each shading point
    /// (build it with [`TexturedMaterial::into_material`], which keeps
    /// constant materials in the variants above).
    Textured(Arc<TexturedMaterial>),
    /// pbrt `mix`: one of two materials per shading point.
    Mix(Arc<MixMaterial>),
}

/// Where and how a material's BSDF is built.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BsdfContext {
    /// Shading normal (world space).
    pub ns: Vec3,
    /// Shading tangent `dpdu` (world space; orients anisotropic roughness).
    pub dpdus: Vec3,
    /// Seed for the layered BxDF's random walks (e.g. the render seed).
    pub seed: u64,
    /// Hit point (world space): 3-D and planar textures, `mix` choices.
    pub p: Point3,
    /// Surface texture coordinates at the hit.
    pub uv: Point2,
    /// Direction towards the viewer (world space, unit): `mix` choices.
    pub wo: Vec3,
}

impl BsdfContext {
    /// Where the material's textures are evaluated.
    #[inline]
    pub fn texture_context(&self) -> TextureEvalContext {
        TextureEvalContext {
            p: self.p,
            uv: self.uv,
        }
    }
}

impl Material {
    /// The material pbrt-v4 builds for `type_name` when no parameter is given.
    pub fn pbrt_default(type_name: &str) -> Result<Material, MaterialError> {
        let copper = ConductorSpec::named("Cu")?;
        Ok(match type_name {
            "diffuse" => Material::Diffuse {
                reflectance: Rgb::splat(0.5),
            },
            "conductor" => Material::Conductor {
                spec: copper,
                roughness: Roughness::SMOOTH,
            },
            "dielectric" => Material::Dielectric {
                eta: 1.5,
                roughness: Roughness::SMOOTH,
            },
            "thindielectric" => Material::ThinDielectric { eta: 1.5 },
            "diffusetransmission" => Material::DiffuseTransmission {
                reflectance: Rgb::splat(0.25),
                transmittance: Rgb::splat(0.25),
                scale: 1.0,
            },
            "coateddiffuse" => Material::CoatedDiffuse {
                reflectance: Rgb::splat(0.5),
                roughness: Roughness::SMOOTH,
                thickness: 0.01,
                eta: 1.5,
                max_depth: 10,
                n_samples: 1,
            },
            "coatedconductor" => Material::CoatedConductor {
                interface_roughness: Roughness::SMOOTH,
                interface_eta: 1.5,
                thickness: 0.01,
                conductor: copper,
                conductor_roughness: Roughness::SMOOTH,
                max_depth: 10,
                n_samples: 1,
            },
            other => return Err(MaterialError::UnknownType(other.to_string())),
        })
    }

    /// The stand-in for pbrt-v4's `measured` material (tabulated RGL BRDFs
    /// are not supported). Chosen from the file name: names containing
    /// "metal" become a rough aluminium conductor (alpha 0.2); otherwise a
    /// Lambertian surface whose reflectance follows a colour word in the
    /// name ("white" 0.8, "gray"/"grey" 0.18, "blue" (0.1, 0.15, 0.5)) or 0.5.
    pub fn measured_fallback(filename: &str) -> Material {
        let name = filename.to_ascii_lowercase();
        if name.contains("metal")
            && let Ok(spec) = ConductorSpec::named("Al")
        {
            return Material::Conductor {
                spec,
                roughness: Roughness::isotropic(0.2, false),
            };
        }
        let reflectance = if name.contains("white") {
            Rgb::splat(0.8)
        } else if name.contains("gray") || name.contains("grey") {
            Rgb::splat(0.18)
        } else if name.contains("blue") {
            Rgb::new(0.1, 0.15, 0.5)
        } else {
            Rgb::splat(0.5)
        };
        Material::Diffuse { reflectance }
    }

    /// The local-frame BxDF (`seed` drives the layered random walks). A
    /// textured material is evaluated at `uv = (0, 0)`, `p = 0`, and a mix
    /// takes the choice made there for `wo = +z`; shading uses
    /// [`Material::bsdf`], which evaluates at the hit.
    pub fn bxdf(&self, seed: u64) -> Bxdf {
        let fix_eta = |e: f32| if e > 0.0 && e.is_finite() { e } else { 1.0 };
        match *self {
            Material::Textured(ref t) => t.evaluate(&TextureEvalContext::default()).bxdf(seed),
            Material::Mix(ref m) => m
                .choose(&BsdfContext {
                    ns: Vec3::Z,
                    dpdus: Vec3::X,
                    seed,
                    p: Point3::ZERO,
                    uv: Point2::default(),
                    wo: Vec3::Z,
                })
                .bxdf(seed),
            Material::Diffuse { reflectance } => Bxdf::Diffuse(DiffuseBxdf::new(reflectance)),
            Material::Conductor { spec, roughness } => {
                let (eta, k) = spec.eta_k();
                Bxdf::Conductor(ConductorBxdf::new(roughness.distribution(), eta, k))
            }
            Material::Dielectric { eta, roughness } => {
                Bxdf::Dielectric(DielectricBxdf::new(fix_eta(eta), roughness.distribution()))
            }
            Material::ThinDielectric { eta } => {
                Bxdf::ThinDielectric(ThinDielectricBxdf::new(fix_eta(eta)))
            }
            Material::DiffuseTransmission {
                reflectance,
                transmittance,
                scale,
            } => Bxdf::DiffuseTransmission(DiffuseTransmissionBxdf::new(
                reflectance * scale,
                transmittance * scale,
            )),
            Material::CoatedDiffuse {
                reflectance,
                roughness,
                thickness,
                eta,
                max_depth,
                n_samples,
            } => Bxdf::CoatedDiffuse(LayeredBxdf::new(
                DielectricBxdf::new(fix_eta(eta), roughness.distribution()),
                DiffuseBxdf::new(reflectance),
                thickness,
                max_depth,
                n_samples,
                seed,
            )),
            Material::CoatedConductor {
                interface_roughness,
                interface_eta,
                thickness,
                conductor,
                conductor_roughness,
                max_depth,
                n_samples,
            } => {
                let ieta = fix_eta(interface_eta);
                // As pbrt-v4: the conductor sits under the coating, so its
                // index is relative to the coating's.
                let (eta, k) = conductor.eta_k();
                let base =
                    ConductorBxdf::new(conductor_roughness.distribution(), eta / ieta, k / ieta);
                Bxdf::CoatedConductor(LayeredBxdf::new(
                    DielectricBxdf::new(ieta, interface_roughness.distribution()),
                    base,
                    thickness,
                    max_depth,
                    n_samples,
                    seed,
                ))
            }
        }
    }

    /// The world-space BSDF at a shading point, with textures evaluated at
    /// `ctx.uv` / `ctx.p` (constant materials skip that step).
    pub fn bsdf(&self, ctx: &BsdfContext) -> Bsdf {
        Bsdf::new(ctx.ns, ctx.dpdus, self.bxdf_at(ctx))
    }

    /// The local-frame BxDF at a shading point (textures evaluated there).
    pub fn bxdf_at(&self, ctx: &BsdfContext) -> Bxdf {
        match self {
            Material::Textured(t) => t.evaluate(&ctx.texture_context()).bxdf(ctx.seed),
            Material::Mix(m) => m.choose(ctx).bxdf_at(ctx),
            _ => self.bxdf(ctx.seed),
        }
    }

    /// True when the BSDF has only delta lobes everywhere (light sampling is
    /// useless); false for a material whose roughness is textured, or a mix
    /// of which one side is not specular.
    pub fn is_specular_only(&self) -> bool {
        match self {
            Material::Textured(t) => t.is_specular_only(),
            Material::Mix(m) => m.materials.iter().all(Material::is_specular_only),
            _ => {
                let f = self.bxdf(0).flags();
                f.is_specular() && !f.is_non_specular()
            }
        }
    }
}
