//! Materials whose parameters are textures, evaluated at each shading point
//! into a constant-parameter [`Material`], and pbrt-v4's `mix` material.
//!
//! [`TexturedMaterial`] mirrors the texturable variants of [`Material`] with
//! [`FloatTexture`]/[`SpectrumTexture`] parameters where pbrt-v4 allows a
//! texture: diffuse `reflectance`; conductor `roughness`/`uroughness`/
//! `vroughness` and `eta`/`k`/`reflectance`; dielectric roughness;
//! diffusetransmission `reflectance`/`transmittance`; coateddiffuse
//! `reflectance`, roughness and `thickness`; coatedconductor interface and
//! conductor roughness, conductor `eta`/`k`/`reflectance` and `thickness`.
//! Indices of refraction (`eta` of dielectrics and coatings), `scale`,
//! `maxdepth` and `nsamples` stay constants, as they are in pbrt-v4 (which
//! only textures the former through spectra).
//!
//! [`TexturedMaterial::into_material`] keeps the common untextured case fast:
//! when every parameter is a constant texture it returns the plain
//! [`Material`] variant, so such materials are built and shaded exactly as
//! before. [`super::MixMaterial`] is pbrt-v4's `mix`. Textures are point-evaluated (no ray differentials): image maps
//! are filtered bilinearly, checkerboards are not antialiased (see
//! [`crate::texture`]).

use super::{ConductorSpec, Material, Roughness};
use crate::spectrum::Rgb;
use crate::texture::{FloatTexture, SpectrumTexture, TextureEvalContext};
use std::sync::Arc;

/// A float texture (shared).
pub type FloatTex = Arc<FloatTexture>;
/// An RGB texture (shared).
pub type RgbTex = Arc<SpectrumTexture>;

/// A constant float texture.
pub fn const_float(v: f32) -> FloatTex {
    Arc::new(FloatTexture::Constant(v))
}
/// A constant RGB texture.
pub fn const_rgb(v: Rgb) -> RgbTex {
    Arc::new(SpectrumTexture::Constant(v))
}

/// [`Roughness`] with textured `u` and `v`.
#[derive(Clone, Debug, PartialEq)]
pub struct TexturedRoughness {
    /// Roughness along the tangent.
    pub u: FloatTex,
    /// Roughness along the bitangent.
    pub v: FloatTex,
    /// `remaproughness`.
    pub remap: bool,
}

impl TexturedRoughness {
    /// Constant roughness.
    pub fn constant(r: Roughness) -> TexturedRoughness {
        TexturedRoughness {
            u: const_float(r.u),
            v: const_float(r.v),
            remap: r.remap,
        }
    }
    /// The roughness at `ctx`.
    pub fn evaluate(&self, ctx: &TextureEvalContext) -> Roughness {
        Roughness {
            u: self.u.evaluate(ctx),
            v: self.v.evaluate(ctx),
            remap: self.remap,
        }
    }
    fn is_constant(&self) -> bool {
        self.u.as_constant().is_some() && self.v.as_constant().is_some()
    }
}

/// [`ConductorSpec`] with textured values.
#[derive(Clone, Debug, PartialEq)]
pub enum TexturedConductor {
    /// Complex index of refraction.
    EtaK {
        /// Real part.
        eta: RgbTex,
        /// Imaginary part.
        k: RgbTex,
    },
    /// Normal-incidence reflectance.
    Reflectance(RgbTex),
}

impl TexturedConductor {
    /// Constant optical constants.
    pub fn constant(spec: ConductorSpec) -> TexturedConductor {
        match spec {
            ConductorSpec::EtaK { eta, k } => TexturedConductor::EtaK {
                eta: const_rgb(eta),
                k: const_rgb(k),
            },
            ConductorSpec::Reflectance(r) => TexturedConductor::Reflectance(const_rgb(r)),
        }
    }
    /// The optical constants at `ctx`.
    pub fn evaluate(&self, ctx: &TextureEvalContext) -> ConductorSpec {
        match self {
            TexturedConductor::EtaK { eta, k } => ConductorSpec::EtaK {
                eta: eta.evaluate(ctx),
                k: k.evaluate(ctx),
            },
            TexturedConductor::Reflectance(r) => ConductorSpec::Reflectance(r.evaluate(ctx)),
        }
    }
    fn is_constant(&self) -> bool {
        match self {
            TexturedConductor::EtaK { eta, k } => {
                eta.as_constant().is_some() && k.as_constant().is_some()
            }
            TexturedConductor::Reflectance(r) => r.as_constant().is_some(),
        }
    }
}

/// The texturable pbrt-v4 materials with texture-valued parameters (the
/// fields mean what they mean in the [`Material`] variant of the same name).
#[derive(Clone, Debug, PartialEq)]
pub enum TexturedMaterial {
    /// pbrt `diffuse`.
    Diffuse {
        /// Lambertian reflectance.
        reflectance: RgbTex,
    },
    /// pbrt `conductor`.
    Conductor {
        /// Optical constants.
        spec: TexturedConductor,
        /// Roughness.
        roughness: TexturedRoughness,
    },
    /// pbrt `dielectric`.
    Dielectric {
        /// Relative index of refraction.
        eta: f32,
        /// Roughness.
        roughness: TexturedRoughness,
    },
    /// pbrt `diffusetransmission`.
    DiffuseTransmission {
        /// Reflectance.
        reflectance: RgbTex,
        /// Transmittance.
        transmittance: RgbTex,
        /// Multiplies both.
        scale: f32,
    },
    /// pbrt `coateddiffuse`.
    CoatedDiffuse {
        /// Base reflectance.
        reflectance: RgbTex,
        /// Coating roughness.
        roughness: TexturedRoughness,
        /// Layer thickness.
        thickness: FloatTex,
        /// Coating index.
        eta: f32,
        /// Random-walk depth.
        max_depth: u32,
        /// Walks per estimate.
        n_samples: u32,
    },
    /// pbrt `coatedconductor`.
    CoatedConductor {
        /// `interface.roughness`.
        interface_roughness: TexturedRoughness,
        /// `interface.eta`.
        interface_eta: f32,
        /// Layer thickness.
        thickness: FloatTex,
        /// The conductor's optical constants.
        conductor: TexturedConductor,
        /// `conductor.roughness`.
        conductor_roughness: TexturedRoughness,
        /// Random-walk depth.
        max_depth: u32,
        /// Walks per estimate.
        n_samples: u32,
    },
}

impl TexturedMaterial {
    /// The textured form of a constant material (every texture a constant);
    /// `None` for variants without texturable parameters (`ThinDielectric`,
    /// `Textured`, `Mix`).
    pub fn from_constant(m: &Material) -> Option<TexturedMaterial> {
        let r = TexturedRoughness::constant;
        Some(match *m {
            Material::Diffuse { reflectance } => TexturedMaterial::Diffuse {
                reflectance: const_rgb(reflectance),
            },
            Material::Conductor { spec, roughness } => TexturedMaterial::Conductor {
                spec: TexturedConductor::constant(spec),
                roughness: r(roughness),
            },
            Material::Dielectric { eta, roughness } => TexturedMaterial::Dielectric {
                eta,
                roughness: r(roughness),
            },
            Material::DiffuseTransmission {
                reflectance,
                transmittance,
                scale,
            } => TexturedMaterial::DiffuseTransmission {
                reflectance: const_rgb(reflectance),
                transmittance: const_rgb(transmittance),
                scale,
            },
            Material::CoatedDiffuse {
                reflectance,
                roughness,
                thickness,
                eta,
                max_depth,
                n_samples,
            } => TexturedMaterial::CoatedDiffuse {
                reflectance: const_rgb(reflectance),
                roughness: r(roughness),
                thickness: const_float(thickness),
                eta,
                max_depth,
                n_samples,
            },
            Material::CoatedConductor {
                interface_roughness,
                interface_eta,
                thickness,
                conductor,
                conductor_roughness,
                max_depth,
                n_samples,
            } => TexturedMaterial::CoatedConductor {
                interface_roughness: r(interface_roughness),
                interface_eta,
                thickness: const_float(thickness),
                conductor: TexturedConductor::constant(conductor),
                conductor_roughness: r(conductor_roughness),
                max_depth,
                n_samples,
            },
            Material::ThinDielectric { .. } | Material::Textured(_) | Material::Mix(_) => {
                return None;
            }
        })
    }

    /// The constant-parameter material at `ctx`.
    pub fn evaluate(&self, ctx: &TextureEvalContext) -> Material {
        match self {
            TexturedMaterial::Diffuse { reflectance } => Material::Diffuse {
                reflectance: reflectance.evaluate(ctx),
            },
            TexturedMaterial::Conductor { spec, roughness } => Material::Conductor {
                spec: spec.evaluate(ctx),
                roughness: roughness.evaluate(ctx),
            },
            TexturedMaterial::Dielectric { eta, roughness } => Material::Dielectric {
                eta: *eta,
                roughness: roughness.evaluate(ctx),
            },
            TexturedMaterial::DiffuseTransmission {
                reflectance,
                transmittance,
                scale,
            } => Material::DiffuseTransmission {
                reflectance: reflectance.evaluate(ctx),
                transmittance: transmittance.evaluate(ctx),
                scale: *scale,
            },
            TexturedMaterial::CoatedDiffuse {
                reflectance,
                roughness,
                thickness,
                eta,
                max_depth,
                n_samples,
            } => Material::CoatedDiffuse {
                reflectance: reflectance.evaluate(ctx),
                roughness: roughness.evaluate(ctx),
                thickness: thickness.evaluate(ctx),
                eta: *eta,
                max_depth: *max_depth,
                n_samples: *n_samples,
            },
            TexturedMaterial::CoatedConductor {
                interface_roughness,
                interface_eta,
                thickness,
                conductor,
                conductor_roughness,
                max_depth,
                n_samples,
            } => Material::CoatedConductor {
                interface_roughness: interface_roughness.evaluate(ctx),
                interface_eta: *interface_eta,
                thickness: thickness.evaluate(ctx),
                conductor: conductor.evaluate(ctx),
                conductor_roughness: conductor_roughness.evaluate(ctx),
                max_depth: *max_depth,
                n_samples: *n_samples,
            },
        }
    }

    /// True when every parameter is a constant texture.
    pub fn is_constant(&self) -> bool {
        let c = |t: &RgbTex| t.as_constant().is_some();
        match self {
            TexturedMaterial::Diffuse { reflectance } => c(reflectance),
            TexturedMaterial::Conductor { spec, roughness } => {
                spec.is_constant() && roughness.is_constant()
            }
            TexturedMaterial::Dielectric { roughness, .. } => roughness.is_constant(),
            TexturedMaterial::DiffuseTransmission {
                reflectance,
                transmittance,
                ..
            } => c(reflectance) && c(transmittance),
            TexturedMaterial::CoatedDiffuse {
                reflectance,
                roughness,
                thickness,
                ..
            } => c(reflectance) && roughness.is_constant() && thickness.as_constant().is_some(),
            TexturedMaterial::CoatedConductor {
                interface_roughness,
                thickness,
                conductor,
                conductor_roughness,
                ..
            } => {
                interface_roughness.is_constant()
                    && thickness.as_constant().is_some()
                    && conductor.is_constant()
                    && conductor_roughness.is_constant()
            }
        }
    }

    /// True when the roughness textures are constant (so whether the
    /// material is specular does not vary over the surface).
    fn roughness_is_constant(&self) -> bool {
        match self {
            TexturedMaterial::Diffuse { .. } | TexturedMaterial::DiffuseTransmission { .. } => true,
            TexturedMaterial::Conductor { roughness, .. }
            | TexturedMaterial::Dielectric { roughness, .. }
            | TexturedMaterial::CoatedDiffuse { roughness, .. } => roughness.is_constant(),
            TexturedMaterial::CoatedConductor {
                interface_roughness,
                conductor_roughness,
                ..
            } => interface_roughness.is_constant() && conductor_roughness.is_constant(),
        }
    }

    /// The plain [`Material`] when every parameter is constant (the fast
    /// path: bit-identical to building that material directly), else
    /// [`Material::Textured`].
    pub fn into_material(self) -> Material {
        if self.is_constant() {
            self.evaluate(&TextureEvalContext::default())
        } else {
            Material::Textured(Arc::new(self))
        }
    }

    /// True when the material has only delta lobes everywhere (false when a
    /// roughness texture varies, to stay on the safe side).
    pub(super) fn is_specular_only(&self) -> bool {
        self.roughness_is_constant()
            && self
                .evaluate(&TextureEvalContext::default())
                .is_specular_only()
    }
}
