//! Materials: pbrt-v4 material parameters turned into a [`Bsdf`] at a
//! shading point; plus the stochastic choice of a `mix` material and a
//! documented fallback for `measured`.
//!
//! Every parameter pbrt-v4 lets be a texture is a [`Texture`](crate::texture::Texture)
//! here: diffuse `reflectance`; conductor `roughness`/`uroughness`/`vroughness`
//! and `eta`/`k`/`reflectance`; dielectric roughness; diffusetransmission
//! `reflectance`/`transmittance`; coateddiffuse `reflectance`, roughness and
//! `thickness`; coatedconductor interface and conductor roughness, conductor
//! `eta`/`k`/`reflectance` and `thickness`. Indices of refraction, `scale`,
//! `maxdepth` and `nsamples` stay constants, as in pbrt-v4. An untextured
//! parameter is a constant texture, stored inline, so constant materials cost
//! one branch per parameter. [`Material::bsdf`] evaluates the textures at the
//! hit's `uv` and position ([`BsdfContext`]); [`Material::Mix`] picks one of two
//! materials per point. Textures are point-evaluated (no ray differentials; see
//! [`crate::texture`]). Adding a material means adding a variant here and its
//! arm in [`Material::bxdf_at`]. A material with a bump or normal map is a
//! [`Material::Bumped`] (see [`bump`]): the integrator perturbs the shading
//! geometry with [`Material::bump`] before building the BSDF.

pub mod bump;
mod content_hash;
mod defaults;
mod mix;
mod params;

use super::conductor::ConductorBxdf;
use super::dielectric::{DielectricBxdf, ThinDielectricBxdf};
use super::diffuse::{DiffuseBxdf, DiffuseTransmissionBxdf};
use super::layered::LayeredBxdf;
use super::{Bsdf, Bxdf, BxdfModel};
use crate::math::{Frame, Point2, Point3, Vec3};
use crate::spectrum::{Colour, Rgb};
use crate::texture::{FloatTexture, SpectrumTexture, TextureEvalContext};
pub use bump::{BUMP_DELTA, Bump, BumpedMaterial};
pub use mix::{MixMaterial, mix_choice};
pub use params::{ConductorSpec, Roughness};
use std::sync::Arc;

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

/// A material whose parameters are textures (constant ones for untextured
/// parameters), or a mix of two materials.
#[derive(Clone, Debug, PartialEq)]
pub enum Material {
    /// pbrt `diffuse`: `reflectance` (default 0.5).
    Diffuse {
        /// Lambertian reflectance.
        reflectance: SpectrumTexture,
    },
    /// pbrt `conductor` (defaults: copper, smooth).
    Conductor {
        /// Optical constants.
        spec: ConductorSpec<SpectrumTexture>,
        /// Roughness.
        roughness: Roughness<FloatTexture>,
    },
    /// pbrt `dielectric` (default eta 1.5, smooth).
    Dielectric {
        /// Relative index of refraction.
        eta: f32,
        /// Roughness.
        roughness: Roughness<FloatTexture>,
    },
    /// pbrt `thindielectric` (default eta 1.5).
    ThinDielectric {
        /// Relative index of refraction.
        eta: f32,
    },
    /// pbrt `diffusetransmission` (defaults 0.25, 0.25, scale 1).
    DiffuseTransmission {
        /// Reflectance.
        reflectance: SpectrumTexture,
        /// Transmittance.
        transmittance: SpectrumTexture,
        /// Multiplies both.
        scale: f32,
    },
    /// pbrt `coateddiffuse`.
    CoatedDiffuse {
        /// Base reflectance (default 0.5).
        reflectance: SpectrumTexture,
        /// Coating roughness (default smooth).
        roughness: Roughness<FloatTexture>,
        /// Layer thickness (default 0.01).
        thickness: FloatTexture,
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
        interface_roughness: Roughness<FloatTexture>,
        /// `interface.eta` (default 1.5).
        interface_eta: f32,
        /// Layer thickness (default 0.01).
        thickness: FloatTexture,
        /// `conductor.eta`/`conductor.k` or `reflectance` (default copper).
        conductor: ConductorSpec<SpectrumTexture>,
        /// `conductor.roughness` (default smooth).
        conductor_roughness: Roughness<FloatTexture>,
        /// Random-walk depth (default 10).
        max_depth: u32,
        /// Walks per estimate (default 1).
        n_samples: u32,
    },
    /// pbrt `mix`: one of two materials per shading point.
    Mix(Arc<MixMaterial>),
    /// A material with pbrt's `displacement` (bump map) or `normalmap`.
    Bumped(Arc<BumpedMaterial>),
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
    /// The context [`Material::bxdf`] uses: normal `+z`, tangent `+x`, the
    /// origin with `uv = (0, 0)`, seen from `+z`.
    pub fn at_origin(seed: u64) -> BsdfContext {
        BsdfContext {
            ns: Vec3::Z,
            dpdus: Vec3::X,
            seed,
            p: Point3::ZERO,
            uv: Point2::default(),
            wo: Vec3::Z,
        }
    }

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
    /// A Lambertian material of constant reflectance.
    pub fn diffuse(reflectance: Rgb) -> Material {
        Material::Diffuse {
            reflectance: reflectance.into(),
        }
    }

    /// The local-frame BxDF at [`BsdfContext::at_origin`] (`seed` drives the
    /// layered random walks): textures are evaluated at `uv = (0, 0)`,
    /// `p = 0`, and a mix takes the choice made there for `wo = +z`; shading
    /// uses [`Material::bsdf`], which evaluates at the hit.
    pub fn bxdf(&self, seed: u64) -> Bxdf {
        self.bxdf_at(&BsdfContext::at_origin(seed))
    }

    /// The world-space BSDF at a shading point, with textures evaluated at
    /// `ctx.uv` / `ctx.p` (RGB mode).
    pub fn bsdf(&self, ctx: &BsdfContext) -> Bsdf {
        self.bsdf_for(ctx, &())
    }

    /// [`Material::bsdf`] in colour `C` at wavelengths `w` (RGB parameters
    /// uplifted as [`Colour`]'s constructors say).
    pub fn bsdf_for<C: Colour>(&self, ctx: &BsdfContext, w: &C::Wavelengths) -> Bsdf<C> {
        Bsdf::new(ctx.ns, ctx.dpdus, self.bxdf_for(ctx, w))
    }

    /// [`Material::bsdf_for`] given its shading frame, `frame =
    /// Frame::shading(ctx.ns, ctx.dpdus)` (which a caller may keep per
    /// triangle, see [`crate::accel::Hit::shading`]). Each branch builds
    /// the BSDF where it is returned (no copy of the BxDF).
    #[inline]
    pub fn bsdf_in_frame<C: Colour>(
        &self,
        frame: Frame,
        ctx: &BsdfContext,
        w: &C::Wavelengths,
    ) -> Bsdf<C> {
        match self {
            Material::Diffuse { .. } => Bsdf::with_frame(frame, self.bxdf_for(ctx, w)),
            _ => self.bsdf_in_frame_other(frame, ctx, w),
        }
    }

    /// [`Material::bsdf_in_frame`] of the materials other than diffuse.
    #[inline(never)]
    fn bsdf_in_frame_other<C: Colour>(
        &self,
        frame: Frame,
        ctx: &BsdfContext,
        w: &C::Wavelengths,
    ) -> Bsdf<C> {
        Bsdf::with_frame(frame, self.bxdf_for_other(ctx, w))
    }

    /// The local-frame BxDF at a shading point (textures evaluated there).
    pub fn bxdf_at(&self, ctx: &BsdfContext) -> Bxdf {
        self.bxdf_for(ctx, &())
    }

    /// [`Material::bxdf_at`] in colour `C` at wavelengths `w`. A diffuse
    /// material, the common case, is built inline; the others through one
    /// call.
    #[inline]
    pub fn bxdf_for<C: Colour>(&self, ctx: &BsdfContext, w: &C::Wavelengths) -> Bxdf<C> {
        match self {
            Material::Diffuse { reflectance } => {
                let r = C::albedo(reflectance.evaluate(&ctx.texture_context()), w);
                Bxdf::Diffuse(DiffuseBxdf::new(r))
            }
            _ => self.bxdf_for_other(ctx, w),
        }
    }

    /// [`Material::bxdf_for`] of every material (called for those other
    /// than diffuse).
    #[inline(never)]
    fn bxdf_for_other<C: Colour>(&self, ctx: &BsdfContext, w: &C::Wavelengths) -> Bxdf<C> {
        let fix_eta = |e: f32| if e > 0.0 && e.is_finite() { e } else { 1.0 };
        let tc = ctx.texture_context();
        let seed = ctx.seed;
        let albedo = |t: &SpectrumTexture| C::albedo(t.evaluate(&tc), w);
        match self {
            Material::Mix(m) => m.choose(ctx).bxdf_for(ctx, w),
            Material::Bumped(b) => b.material.bxdf_for(ctx, w),
            Material::Diffuse { reflectance } => {
                Bxdf::Diffuse(DiffuseBxdf::new(albedo(reflectance)))
            }
            Material::Conductor { spec, roughness } => {
                let (eta, k) = spec.evaluate(&tc).eta_k_for(w);
                let distribution = roughness.evaluate(&tc).distribution();
                Bxdf::Conductor(ConductorBxdf::new(distribution, eta, k))
            }
            Material::Dielectric { eta, roughness } => Bxdf::Dielectric(DielectricBxdf::new(
                fix_eta(*eta),
                roughness.evaluate(&tc).distribution(),
            )),
            Material::ThinDielectric { eta } => {
                Bxdf::ThinDielectric(ThinDielectricBxdf::new(fix_eta(*eta)))
            }
            Material::DiffuseTransmission {
                reflectance,
                transmittance,
                scale,
            } => Bxdf::DiffuseTransmission(DiffuseTransmissionBxdf::new(
                albedo(reflectance) * *scale,
                albedo(transmittance) * *scale,
            )),
            Material::CoatedDiffuse {
                reflectance,
                roughness,
                thickness,
                eta,
                max_depth,
                n_samples,
            } => Bxdf::CoatedDiffuse(LayeredBxdf::new(
                DielectricBxdf::new(fix_eta(*eta), roughness.evaluate(&tc).distribution()),
                DiffuseBxdf::new(albedo(reflectance)),
                thickness.evaluate(&tc),
                *max_depth,
                *n_samples,
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
                let ieta = fix_eta(*interface_eta);
                // As pbrt-v4: the conductor sits under the coating, so its
                // index is relative to the coating's.
                let (eta, k): (C, C) = conductor.evaluate(&tc).eta_k_for(w);
                let distribution = conductor_roughness.evaluate(&tc).distribution();
                let base = ConductorBxdf::new(distribution, eta / ieta, k / ieta);
                Bxdf::CoatedConductor(LayeredBxdf::new(
                    DielectricBxdf::new(ieta, interface_roughness.evaluate(&tc).distribution()),
                    base,
                    thickness.evaluate(&tc),
                    *max_depth,
                    *n_samples,
                    seed,
                ))
            }
        }
    }

    /// The bump or normal map of the material used at `ctx` (for a mix,
    /// the material it chooses there), if it has one.
    #[inline]
    pub fn bump(&self, ctx: &BsdfContext) -> Option<&Bump> {
        match self {
            Material::Bumped(b) => Some(&b.bump),
            // The choice evaluates the amount texture and a hash: only
            // worth it when a side has a map.
            Material::Mix(m) if m.materials.iter().any(Material::has_bump) => {
                m.choose(ctx).bump(ctx)
            }
            _ => None,
        }
    }

    /// True when the material, or a material a mix may choose, has a bump
    /// or normal map.
    pub fn has_bump(&self) -> bool {
        match self {
            Material::Bumped(_) => true,
            Material::Mix(m) => m.materials.iter().any(Material::has_bump),
            _ => false,
        }
    }

    /// True when no texture of the material varies (for a mix: neither side's
    /// nor the amount's).
    pub fn is_constant(&self) -> bool {
        let rgb = |t: &SpectrumTexture| t.as_constant().is_some();
        let float = |t: &FloatTexture| t.as_constant().is_some();
        let spec = |s: &ConductorSpec<SpectrumTexture>| match s {
            ConductorSpec::EtaK { eta, k } => rgb(eta) && rgb(k),
            ConductorSpec::Reflectance(r) => rgb(r),
            ConductorSpec::Named { .. } => true,
        };
        self.roughness_is_constant()
            && match self {
                Material::Diffuse { reflectance } => rgb(reflectance),
                Material::Conductor { spec: s, .. } => spec(s),
                Material::Dielectric { .. } | Material::ThinDielectric { .. } => true,
                Material::DiffuseTransmission {
                    reflectance,
                    transmittance,
                    ..
                } => rgb(reflectance) && rgb(transmittance),
                Material::CoatedDiffuse {
                    reflectance,
                    thickness,
                    ..
                } => rgb(reflectance) && float(thickness),
                Material::CoatedConductor {
                    thickness,
                    conductor,
                    ..
                } => float(thickness) && spec(conductor),
                Material::Mix(m) => {
                    float(&m.amount) && m.materials.iter().all(Material::is_constant)
                }
                Material::Bumped(b) => b.bump.is_constant() && b.material.is_constant(),
            }
    }

    /// True when no roughness texture varies (so whether the material is
    /// specular does not vary over the surface).
    fn roughness_is_constant(&self) -> bool {
        match self {
            Material::Diffuse { .. }
            | Material::DiffuseTransmission { .. }
            | Material::ThinDielectric { .. } => true,
            Material::Conductor { roughness, .. }
            | Material::Dielectric { roughness, .. }
            | Material::CoatedDiffuse { roughness, .. } => roughness.is_constant(),
            Material::CoatedConductor {
                interface_roughness,
                conductor_roughness,
                ..
            } => interface_roughness.is_constant() && conductor_roughness.is_constant(),
            Material::Mix(m) => m.materials.iter().all(Material::roughness_is_constant),
            Material::Bumped(b) => b.material.roughness_is_constant(),
        }
    }

    /// True when the BSDF has only delta lobes everywhere (light sampling is
    /// useless); false for a material whose roughness is textured, or a mix
    /// of which one side is not specular.
    pub fn is_specular_only(&self) -> bool {
        match self {
            Material::Mix(m) => m.materials.iter().all(Material::is_specular_only),
            Material::Bumped(b) => b.material.is_specular_only(),
            _ => {
                self.roughness_is_constant() && {
                    let f = self.bxdf(0).flags();
                    f.is_specular() && !f.is_non_specular()
                }
            }
        }
    }
}
