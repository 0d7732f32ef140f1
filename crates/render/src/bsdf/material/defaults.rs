//! The materials pbrt-v4 builds when a scene gives no parameters
//! ([`Material::pbrt_default`]), and the stand-in for `measured`
//! ([`Material::measured_fallback`]).

use super::{ConductorSpec, Material, MaterialError, Roughness};
use crate::spectrum::Rgb;

impl Material {
    /// The material pbrt-v4 builds for `type_name` when no parameter is given.
    pub fn pbrt_default(type_name: &str) -> Result<Material, MaterialError> {
        let copper = ConductorSpec::named("Cu")?;
        let smooth = || Roughness::SMOOTH.into();
        Ok(match type_name {
            "diffuse" => Material::diffuse(Rgb::splat(0.5)),
            "conductor" => Material::Conductor {
                spec: copper.into(),
                roughness: smooth(),
            },
            "dielectric" => Material::Dielectric {
                eta: 1.5,
                roughness: smooth(),
            },
            "thindielectric" => Material::ThinDielectric { eta: 1.5 },
            "diffusetransmission" => Material::DiffuseTransmission {
                reflectance: Rgb::splat(0.25).into(),
                transmittance: Rgb::splat(0.25).into(),
                scale: 1.0,
            },
            "coateddiffuse" => Material::CoatedDiffuse {
                reflectance: Rgb::splat(0.5).into(),
                roughness: smooth(),
                thickness: 0.01.into(),
                eta: 1.5,
                max_depth: 10,
                n_samples: 1,
            },
            "coatedconductor" => Material::CoatedConductor {
                interface_roughness: smooth(),
                interface_eta: 1.5,
                thickness: 0.01.into(),
                conductor: copper.into(),
                conductor_roughness: smooth(),
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
                spec: spec.into(),
                roughness: Roughness::isotropic(0.2, false).into(),
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
        Material::diffuse(reflectance)
    }
}
