//! Lambertian reflection ([`DiffuseBxdf`]) and Lambertian reflection plus
//! transmission ([`DiffuseTransmissionBxdf`]), as pbrt-v4's `DiffuseBxDF`
//! and `DiffuseTransmissionBxDF`.

use super::{
    BsdfSample, BxdfFlags, BxdfModel, SampleFlags, TransportMode, sample_cosine_hemisphere,
};
use crate::math::Vec3;
use crate::math::spherical::same_hemisphere;
use crate::spectrum::{Colour, Rgb};
use std::f32::consts::FRAC_1_PI;

/// Lambertian reflection `f = R / π`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiffuseBxdf<C = Rgb> {
    /// Reflectance (albedo), each channel in `[0, 1]`.
    pub r: C,
}

impl<C: Colour> DiffuseBxdf<C> {
    /// A Lambertian reflector; `r` is clamped to `[0, 1]` per channel.
    #[inline]
    pub fn new(r: C) -> Self {
        DiffuseBxdf {
            r: r.clamp(0.0, 1.0),
        }
    }
}

impl<C: Colour> BxdfModel<C> for DiffuseBxdf<C> {
    #[inline]
    fn flags(&self) -> BxdfFlags {
        if self.r.is_black() {
            BxdfFlags::UNSET
        } else {
            BxdfFlags::DIFFUSE_REFLECTION
        }
    }
    #[inline]
    fn f(&self, wo: Vec3, wi: Vec3, _mode: TransportMode) -> C {
        if !same_hemisphere(wo, wi) {
            return C::ZERO;
        }
        self.r * FRAC_1_PI
    }
    #[inline]
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
        let mut wi = sample_cosine_hemisphere(u);
        if wo.z < 0.0 {
            wi.z = -wi.z;
        }
        let pdf = wi.z.abs() * FRAC_1_PI;
        Some(BsdfSample::new(
            self.r * FRAC_1_PI,
            wi,
            pdf,
            BxdfFlags::DIFFUSE_REFLECTION,
        ))
    }
    #[inline]
    fn pdf(&self, wo: Vec3, wi: Vec3, _mode: TransportMode, sample: SampleFlags) -> f32 {
        if !sample.reflection() || !same_hemisphere(wo, wi) {
            return 0.0;
        }
        wi.z.abs() * FRAC_1_PI
    }
}

/// Lambertian reflection `R / π` on the side of `wo` plus Lambertian
/// transmission `T / π` to the other side. `R + T` should not exceed 1 per
/// channel (the constructor clamps each to `[0, 1]` only; pbrt-v4 does not
/// enforce the sum either).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiffuseTransmissionBxdf<C = Rgb> {
    /// Reflectance.
    pub r: C,
    /// Transmittance.
    pub t: C,
}

impl<C: Colour> DiffuseTransmissionBxdf<C> {
    /// A diffuse reflector/transmitter (each channel clamped to `[0, 1]`).
    pub fn new(r: C, t: C) -> Self {
        DiffuseTransmissionBxdf {
            r: r.clamp(0.0, 1.0),
            t: t.clamp(0.0, 1.0),
        }
    }
    /// Probabilities of choosing reflection and transmission under `sample`.
    fn lobe_probs(&self, sample: SampleFlags) -> (f32, f32) {
        let pr = if sample.reflection() {
            self.r.max_component()
        } else {
            0.0
        };
        let pt = if sample.transmission() {
            self.t.max_component()
        } else {
            0.0
        };
        (pr, pt)
    }
}

impl<C: Colour> BxdfModel<C> for DiffuseTransmissionBxdf<C> {
    fn flags(&self) -> BxdfFlags {
        let mut f = BxdfFlags::UNSET;
        if !self.r.is_black() {
            f = f | BxdfFlags::DIFFUSE_REFLECTION;
        }
        if !self.t.is_black() {
            f = f | BxdfFlags::DIFFUSE_TRANSMISSION;
        }
        f
    }
    fn f(&self, wo: Vec3, wi: Vec3, _mode: TransportMode) -> C {
        if same_hemisphere(wo, wi) {
            self.r * FRAC_1_PI
        } else {
            self.t * FRAC_1_PI
        }
    }
    fn sample_f(
        &self,
        wo: Vec3,
        uc: f32,
        u: [f32; 2],
        _mode: TransportMode,
        sample: SampleFlags,
    ) -> Option<BsdfSample<C>> {
        let (pr, pt) = self.lobe_probs(sample);
        if pr + pt == 0.0 {
            return None;
        }
        let mut wi = sample_cosine_hemisphere(u);
        let cos_pdf = wi.z * FRAC_1_PI;
        if uc < pr / (pr + pt) {
            if wo.z < 0.0 {
                wi.z = -wi.z;
            }
            let pdf = cos_pdf * pr / (pr + pt);
            Some(BsdfSample::new(
                self.r * FRAC_1_PI,
                wi,
                pdf,
                BxdfFlags::DIFFUSE_REFLECTION,
            ))
        } else {
            if wo.z > 0.0 {
                wi.z = -wi.z;
            }
            let pdf = cos_pdf * pt / (pr + pt);
            Some(BsdfSample::new(
                self.t * FRAC_1_PI,
                wi,
                pdf,
                BxdfFlags::DIFFUSE_TRANSMISSION,
            ))
        }
    }
    fn pdf(&self, wo: Vec3, wi: Vec3, _mode: TransportMode, sample: SampleFlags) -> f32 {
        let (pr, pt) = self.lobe_probs(sample);
        if pr + pt == 0.0 {
            return 0.0;
        }
        let p = if same_hemisphere(wo, wi) { pr } else { pt };
        wi.z.abs() * FRAC_1_PI * p / (pr + pt)
    }
}
