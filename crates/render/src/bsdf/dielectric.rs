//! Dielectric interfaces: smooth (delta reflection or refraction chosen by
//! Fresnel) and rough (GGX microfacet reflection and transmission, Walter et
//! al. 2007, "Microfacet Models for Refraction through Rough Surfaces"),
//! following pbrt-v4's `DielectricBxDF`; and the thin dielectric sheet
//! (`ThinDielectricBxDF`).

use super::fresnel::{fr_dielectric, reflect, refract};
use super::microfacet::TrowbridgeReitz;
use super::{BsdfSample, BxdfFlags, BxdfModel, SampleFlags, TransportMode};
use crate::math::Vec3;
use crate::math::spherical::same_hemisphere;
use crate::spectrum::Colour;

/// A dielectric interface with relative index `eta` (inside, `-z`, over
/// outside, `+z`). `eta == 1` is an index-matched pass-through.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DielectricBxdf {
    /// Relative index of refraction (positive).
    pub eta: f32,
    /// Microfacet distribution (smooth when tiny).
    pub distrib: TrowbridgeReitz,
}

/// Lobe probabilities `(pr, pt)` restricted to `sample`.
fn lobe_probs(r: f32, t: f32, sample: SampleFlags) -> (f32, f32) {
    (
        if sample.reflection() { r } else { 0.0 },
        if sample.transmission() { t } else { 0.0 },
    )
}

impl DielectricBxdf {
    /// A dielectric; a non-finite or non-positive `eta` becomes 1.
    pub fn new(eta: f32, distrib: TrowbridgeReitz) -> Self {
        let eta = if eta > 0.0 && eta.is_finite() {
            eta
        } else {
            1.0
        };
        DielectricBxdf { eta, distrib }
    }

    /// The generalized half vector of a (wo, wi) pair, with its relative
    /// index; `None` for degenerate or back-facing configurations.
    fn half_vector(&self, wo: Vec3, wi: Vec3) -> Option<(Vec3, f32, bool)> {
        let (cos_o, cos_i) = (wo.z, wi.z);
        let reflect = cos_i * cos_o > 0.0;
        let etap = if reflect {
            1.0
        } else if cos_o > 0.0 {
            self.eta
        } else {
            1.0 / self.eta
        };
        let wm = wi * etap + wo;
        if cos_i == 0.0 || cos_o == 0.0 || wm.length_squared() == 0.0 {
            return None;
        }
        let wm = wm.normalize().face_forward(Vec3::Z);
        // Discard back-facing microfacets.
        if wm.dot(wi) * cos_i < 0.0 || wm.dot(wo) * cos_o < 0.0 {
            return None;
        }
        Some((wm, etap, reflect))
    }

    fn smooth_sample<C: Colour>(
        &self,
        wo: Vec3,
        uc: f32,
        mode: TransportMode,
        sample: SampleFlags,
    ) -> Option<BsdfSample<C>> {
        let r = fr_dielectric(wo.z, self.eta);
        let t = 1.0 - r;
        let (pr, pt) = lobe_probs(r, t, sample);
        if pr == 0.0 && pt == 0.0 {
            return None;
        }
        if uc < pr / (pr + pt) {
            let wi = Vec3::new(-wo.x, -wo.y, wo.z);
            let fr = C::splat(r / wi.z.abs());
            Some(BsdfSample::new(
                fr,
                wi,
                pr / (pr + pt),
                BxdfFlags::SPECULAR_REFLECTION,
            ))
        } else {
            let (wi, etap) = refract(wo, Vec3::Z, self.eta)?;
            if wi.z == 0.0 {
                return None;
            }
            let mut ft = t / wi.z.abs();
            if mode == TransportMode::Radiance {
                ft /= etap * etap;
            }
            let mut s = BsdfSample::new(
                C::splat(ft),
                wi,
                pt / (pr + pt),
                BxdfFlags::SPECULAR_TRANSMISSION,
            );
            s.eta = etap;
            Some(s)
        }
    }
}

/// The colour-independent parts of the dielectric (inherent, so that calls
/// need no colour type).
impl DielectricBxdf {
    /// The lobes present.
    pub fn flags(&self) -> BxdfFlags {
        if self.eta == 1.0 {
            return BxdfFlags::SPECULAR_TRANSMISSION;
        }
        let lobe = if self.distrib.effectively_smooth() {
            BxdfFlags::SPECULAR
        } else {
            BxdfFlags::GLOSSY
        };
        BxdfFlags::REFLECTION | BxdfFlags::TRANSMISSION | lobe
    }

    /// Solid-angle density of sampling `wi` (zero for delta lobes).
    pub fn pdf(&self, wo: Vec3, wi: Vec3, _mode: TransportMode, sample: SampleFlags) -> f32 {
        if self.eta == 1.0 || self.distrib.effectively_smooth() {
            return 0.0;
        }
        let Some((wm, etap, is_reflect)) = self.half_vector(wo, wi) else {
            return 0.0;
        };
        let r = fr_dielectric(wo.dot(wm), self.eta);
        let (pr, pt) = lobe_probs(r, 1.0 - r, sample);
        if pr == 0.0 && pt == 0.0 {
            return 0.0;
        }
        if is_reflect {
            self.distrib.pdf(wo, wm) / (4.0 * wo.abs_dot(wm)) * pr / (pr + pt)
        } else {
            let denom = (wi.dot(wm) + wo.dot(wm) / etap).powi(2);
            let dwm_dwi = wi.abs_dot(wm) / denom;
            self.distrib.pdf(wo, wm) * dwm_dwi * pt / (pr + pt)
        }
    }

    /// Widens a near-specular lobe.
    pub fn regularize(&mut self) {
        self.distrib.regularize();
    }
}

impl<C: Colour> BxdfModel<C> for DielectricBxdf {
    fn flags(&self) -> BxdfFlags {
        DielectricBxdf::flags(self)
    }

    fn f(&self, wo: Vec3, wi: Vec3, mode: TransportMode) -> C {
        if self.eta == 1.0 || self.distrib.effectively_smooth() {
            return C::ZERO;
        }
        let Some((wm, etap, is_reflect)) = self.half_vector(wo, wi) else {
            return C::ZERO;
        };
        let d = &self.distrib;
        let fr = fr_dielectric(wo.dot(wm), self.eta);
        if is_reflect {
            C::splat(d.d(wm) * d.g(wo, wi) * fr / (4.0 * wi.z * wo.z).abs())
        } else {
            let denom = (wi.dot(wm) + wo.dot(wm) / etap).powi(2) * wi.z * wo.z;
            let mut ft =
                d.d(wm) * (1.0 - fr) * d.g(wo, wi) * (wi.dot(wm) * wo.dot(wm) / denom).abs();
            if mode == TransportMode::Radiance {
                ft /= etap * etap;
            }
            C::splat(ft)
        }
    }

    fn sample_f(
        &self,
        wo: Vec3,
        uc: f32,
        u: [f32; 2],
        mode: TransportMode,
        sample: SampleFlags,
    ) -> Option<BsdfSample<C>> {
        if self.eta == 1.0 || self.distrib.effectively_smooth() {
            return self.smooth_sample(wo, uc, mode, sample);
        }
        if wo.z == 0.0 {
            return None;
        }
        let d = &self.distrib;
        let wm = d.sample_wm(wo, u);
        let r = fr_dielectric(wo.dot(wm), self.eta);
        let (pr, pt) = lobe_probs(r, 1.0 - r, sample);
        if pr == 0.0 && pt == 0.0 {
            return None;
        }
        if uc < pr / (pr + pt) {
            let wi = reflect(wo, wm);
            if !same_hemisphere(wo, wi) {
                return None;
            }
            let pdf = d.pdf(wo, wm) / (4.0 * wo.abs_dot(wm)) * pr / (pr + pt);
            let f = d.d(wm) * d.g(wo, wi) * r / (4.0 * wi.z * wo.z);
            (pdf > 0.0).then(|| BsdfSample::new(C::splat(f), wi, pdf, BxdfFlags::GLOSSY_REFLECTION))
        } else {
            let (wi, etap) = refract(wo, wm, self.eta)?;
            if same_hemisphere(wo, wi) || wi.z == 0.0 {
                return None;
            }
            let denom = (wi.dot(wm) + wo.dot(wm) / etap).powi(2);
            let dwm_dwi = wi.abs_dot(wm) / denom;
            let pdf = d.pdf(wo, wm) * dwm_dwi * pt / (pr + pt);
            let mut ft = (1.0 - r)
                * d.d(wm)
                * d.g(wo, wi)
                * (wi.dot(wm) * wo.dot(wm) / (wi.z * wo.z * denom)).abs();
            if mode == TransportMode::Radiance {
                ft /= etap * etap;
            }
            if !(pdf > 0.0) {
                return None;
            }
            let mut s = BsdfSample::new(C::splat(ft), wi, pdf, BxdfFlags::GLOSSY_TRANSMISSION);
            s.eta = etap;
            Some(s)
        }
    }

    fn pdf(&self, wo: Vec3, wi: Vec3, mode: TransportMode, sample: SampleFlags) -> f32 {
        DielectricBxdf::pdf(self, wo, wi, mode, sample)
    }

    fn regularize(&mut self) {
        DielectricBxdf::regularize(self);
    }
}

/// A thin dielectric sheet (a window pane): delta reflection with the
/// inter-reflected Fresnel sum `R + T² R / (1 - R²)` and straight-through
/// delta transmission of the rest (pbrt-v4's `ThinDielectricBxDF`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThinDielectricBxdf {
    /// Relative index of refraction of the sheet.
    pub eta: f32,
}

impl ThinDielectricBxdf {
    /// The lobes present (delta reflection and transmission).
    pub fn flags(&self) -> BxdfFlags {
        BxdfFlags::REFLECTION | BxdfFlags::TRANSMISSION | BxdfFlags::SPECULAR
    }
    /// A thin sheet; a non-finite or non-positive `eta` becomes 1.
    pub fn new(eta: f32) -> Self {
        let eta = if eta > 0.0 && eta.is_finite() {
            eta
        } else {
            1.0
        };
        ThinDielectricBxdf { eta }
    }
}

impl<C: Colour> BxdfModel<C> for ThinDielectricBxdf {
    fn flags(&self) -> BxdfFlags {
        ThinDielectricBxdf::flags(self)
    }
    fn f(&self, _wo: Vec3, _wi: Vec3, _mode: TransportMode) -> C {
        C::ZERO
    }
    fn sample_f(
        &self,
        wo: Vec3,
        uc: f32,
        _u: [f32; 2],
        _mode: TransportMode,
        sample: SampleFlags,
    ) -> Option<BsdfSample<C>> {
        let mut r = fr_dielectric(wo.z.abs(), self.eta);
        let mut t = 1.0 - r;
        if r < 1.0 {
            r += t * t * r / (1.0 - r * r);
            t = 1.0 - r;
        }
        let (pr, pt) = lobe_probs(r, t, sample);
        if pr == 0.0 && pt == 0.0 {
            return None;
        }
        let c = wo.z.abs();
        if c == 0.0 {
            return None;
        }
        if uc < pr / (pr + pt) {
            let wi = Vec3::new(-wo.x, -wo.y, wo.z);
            Some(BsdfSample::new(
                C::splat(r / c),
                wi,
                pr / (pr + pt),
                BxdfFlags::SPECULAR_REFLECTION,
            ))
        } else {
            Some(BsdfSample::new(
                C::splat(t / c),
                -wo,
                pt / (pr + pt),
                BxdfFlags::SPECULAR_TRANSMISSION,
            ))
        }
    }
    fn pdf(&self, _wo: Vec3, _wi: Vec3, _mode: TransportMode, _sample: SampleFlags) -> f32 {
        0.0
    }
}
