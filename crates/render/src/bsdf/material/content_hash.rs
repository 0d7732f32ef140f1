//! The content of materials and their parameters
//! ([`crate::content_hash`]): each variant's tag, then its parameters.

use super::{Bump, BumpedMaterial, ConductorSpec, Material, MixMaterial, Roughness};
use crate::content_hash::{ContentHash, ContentSink};

impl ContentHash for Material {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        match self {
            Material::Diffuse { reflectance } => (0u8, reflectance).feed(sink),
            Material::Conductor { spec, roughness } => (1u8, spec, roughness).feed(sink),
            Material::Dielectric { eta, roughness } => (2u8, eta, roughness).feed(sink),
            Material::ThinDielectric { eta } => (3u8, eta).feed(sink),
            Material::DiffuseTransmission {
                reflectance,
                transmittance,
                scale,
            } => (4u8, reflectance, transmittance, scale).feed(sink),
            Material::CoatedDiffuse {
                reflectance,
                roughness,
                thickness,
                eta,
                max_depth,
                n_samples,
            } => (
                5u8,
                reflectance,
                roughness,
                thickness,
                eta,
                [max_depth, n_samples],
            )
                .feed(sink),
            Material::CoatedConductor {
                interface_roughness,
                interface_eta,
                thickness,
                conductor,
                conductor_roughness,
                max_depth,
                n_samples,
            } => {
                (6u8, interface_roughness, interface_eta, thickness).feed(sink);
                (conductor, conductor_roughness, [max_depth, n_samples]).feed(sink);
            }
            Material::Mix(mix) => (7u8, mix).feed(sink),
            Material::Bumped(bumped) => (8u8, bumped).feed(sink),
        }
    }
}

impl ContentHash for MixMaterial {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let MixMaterial { materials, amount } = self;
        (materials, amount).feed(sink);
    }
}

impl ContentHash for BumpedMaterial {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let BumpedMaterial { material, bump } = self;
        (material, bump).feed(sink);
    }
}

impl ContentHash for Bump {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        match self {
            Bump::Displacement(texture) => (0u8, texture).feed(sink),
            Bump::NormalMap(image) => (1u8, image).feed(sink),
        }
    }
}

impl<R: ContentHash> ContentHash for Roughness<R> {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let Roughness { u, v, remap } = self;
        (u, v, remap).feed(sink);
    }
}

impl<T: ContentHash> ContentHash for ConductorSpec<T> {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        match self {
            ConductorSpec::EtaK { eta, k } => (0u8, eta, k).feed(sink),
            ConductorSpec::Reflectance(r) => (1u8, r).feed(sink),
            ConductorSpec::Named { eta, k } => (2u8, eta, k).feed(sink),
        }
    }
}
