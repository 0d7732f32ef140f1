//! A conductor: Torrance-Sparrow reflection from a GGX (Trowbridge-Reitz)
//! microfacet distribution with complex Fresnel per RGB channel, sampled by
//! visible normals; a delta mirror when the surface is effectively smooth
//! (pbrt-v4's `ConductorBxDF`).

use super::fresnel::{fr_complex_colour, reflect};
use super::microfacet::TrowbridgeReitz;
use super::{BsdfSample, BxdfFlags, BxdfModel, SampleFlags, TransportMode};
use crate::math::Vec3;
use crate::math::spherical::same_hemisphere;
use crate::spectrum::{Colour, Rgb};

/// A GGX conductor with complex index of refraction `eta + i k` per channel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConductorBxdf<C = Rgb> {
    /// Microfacet distribution.
    pub distrib: TrowbridgeReitz,
    /// Real part of the relative index of refraction.
    pub eta: C,
    /// Absorption coefficient (imaginary part).
    pub k: C,
}

impl<C: Colour> ConductorBxdf<C> {
    /// A conductor with the given distribution and optical constants.
    pub fn new(distrib: TrowbridgeReitz, eta: C, k: C) -> Self {
        ConductorBxdf { distrib, eta, k }
    }
}

impl<C: Colour> BxdfModel<C> for ConductorBxdf<C> {
    fn flags(&self) -> BxdfFlags {
        if self.distrib.effectively_smooth() {
            BxdfFlags::SPECULAR_REFLECTION
        } else {
            BxdfFlags::GLOSSY_REFLECTION
        }
    }

    fn f(&self, wo: Vec3, wi: Vec3, _mode: TransportMode) -> C {
        if !same_hemisphere(wo, wi) || self.distrib.effectively_smooth() {
            return C::ZERO;
        }
        let (cos_o, cos_i) = (wo.z.abs(), wi.z.abs());
        if cos_o == 0.0 || cos_i == 0.0 {
            return C::ZERO;
        }
        let wm = wi + wo;
        if wm.length_squared() == 0.0 {
            return C::ZERO;
        }
        let wm = wm.normalize();
        let fr = fr_complex_colour(wo.abs_dot(wm), self.eta, self.k);
        fr * (self.distrib.d(wm) * self.distrib.g(wo, wi) / (4.0 * cos_i * cos_o))
    }

    fn sample_f(
        &self,
        wo: Vec3,
        _uc: f32,
        u: [f32; 2],
        _mode: TransportMode,
        sample: SampleFlags,
    ) -> Option<BsdfSample<C>> {
        if !sample.reflection() {
            return None;
        }
        if self.distrib.effectively_smooth() {
            let wi = Vec3::new(-wo.x, -wo.y, wo.z);
            let c = wi.z.abs();
            if c == 0.0 {
                return None;
            }
            let f = fr_complex_colour(c, self.eta, self.k) / c;
            return Some(BsdfSample::new(f, wi, 1.0, BxdfFlags::SPECULAR_REFLECTION));
        }
        if wo.z == 0.0 {
            return None;
        }
        let wm = self.distrib.sample_wm(wo, u);
        let wi = reflect(wo, wm);
        if !same_hemisphere(wo, wi) {
            return None;
        }
        let pdf = self.distrib.pdf(wo, wm) / (4.0 * wo.abs_dot(wm));
        let (cos_o, cos_i) = (wo.z.abs(), wi.z.abs());
        if cos_o == 0.0 || cos_i == 0.0 || !(pdf > 0.0) {
            return None;
        }
        let fr = fr_complex_colour(wo.abs_dot(wm), self.eta, self.k);
        let f = fr * (self.distrib.d(wm) * self.distrib.g(wo, wi) / (4.0 * cos_i * cos_o));
        Some(BsdfSample::new(f, wi, pdf, BxdfFlags::GLOSSY_REFLECTION))
    }

    fn pdf(&self, wo: Vec3, wi: Vec3, _mode: TransportMode, sample: SampleFlags) -> f32 {
        if !sample.reflection() || !same_hemisphere(wo, wi) || self.distrib.effectively_smooth() {
            return 0.0;
        }
        let wm = wo + wi;
        if wm.length_squared() == 0.0 {
            return 0.0;
        }
        let wm = wm.normalize().face_forward(Vec3::Z);
        self.distrib.pdf(wo, wm) / (4.0 * wo.abs_dot(wm))
    }

    fn regularize(&mut self) {
        self.distrib.regularize();
    }
}
