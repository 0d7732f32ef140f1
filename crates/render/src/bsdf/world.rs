//! [`Bsdf`]: a BxDF with its shading frame, taking and returning world-space
//! directions (pbrt-v4's `BSDF`).

use super::{BsdfSample, Bxdf, BxdfFlags, BxdfModel, SampleFlags, TransportMode};
use crate::math::{Frame, Vec3};
use crate::spectrum::{Colour, Rgb};

/// A BxDF placed at a surface point: world-space `f`, `sample_f`, `pdf`.
#[derive(Clone, Debug)]
pub struct Bsdf<C = Rgb> {
    /// The local scattering model.
    pub bxdf: Bxdf<C>,
    /// Shading frame: `z` is the shading normal, `x` follows `dpdu`.
    pub frame: Frame,
}

impl<C: Colour> Bsdf<C> {
    /// A BSDF with shading normal `ns` (need not be unit) and tangent
    /// `dpdus` (projected onto the tangent plane; any vector if unknown).
    #[inline]
    pub fn new(ns: Vec3, dpdus: Vec3, bxdf: Bxdf<C>) -> Bsdf<C> {
        Bsdf {
            bxdf,
            frame: Frame::shading(ns, dpdus),
        }
    }
    /// A BSDF in an explicit frame.
    #[inline]
    pub fn with_frame(frame: Frame, bxdf: Bxdf<C>) -> Bsdf<C> {
        Bsdf { bxdf, frame }
    }
    /// World to local.
    #[inline]
    pub fn to_local(&self, v: Vec3) -> Vec3 {
        self.frame.to_local(v)
    }
    /// Local to world.
    #[inline]
    pub fn from_local(&self, v: Vec3) -> Vec3 {
        self.frame.from_local(v)
    }
    /// The lobes of the BxDF.
    #[inline]
    pub fn flags(&self) -> BxdfFlags {
        self.bxdf.flags()
    }
    /// `f(wo, wi)` for world directions (zero when `wo` is in the tangent plane).
    #[inline]
    pub fn f(&self, wo: Vec3, wi: Vec3, mode: TransportMode) -> C {
        match &self.bxdf {
            Bxdf::Diffuse(b) => self.f_with(b, wo, wi, mode),
            b => self.f_with(b, wo, wi, mode),
        }
    }
    /// Samples an incident world direction; `u_lobe` picks the lobe, `u` the
    /// direction. `None` when sampling fails or yields a useless sample.
    #[inline]
    pub fn sample_f(
        &self,
        wo: Vec3,
        u_lobe: f32,
        u: [f32; 2],
        mode: TransportMode,
    ) -> Option<BsdfSample<C>> {
        self.sample_f_restricted(wo, u_lobe, u, mode, SampleFlags::All)
    }
    /// [`Bsdf::sample_f`] restricted to reflection or transmission. A
    /// Lambertian BxDF, the common case, is sampled inline; the others
    /// through one call.
    #[inline]
    pub fn sample_f_restricted(
        &self,
        wo: Vec3,
        u_lobe: f32,
        u: [f32; 2],
        mode: TransportMode,
        sample: SampleFlags,
    ) -> Option<BsdfSample<C>> {
        match &self.bxdf {
            Bxdf::Diffuse(b) => self.sample_f_with(b, wo, u_lobe, u, mode, sample),
            _ => self.sample_f_other(wo, u_lobe, u, mode, sample),
        }
    }
    /// [`Bsdf::sample_f_restricted`] of the BxDFs other than Lambertian.
    #[inline(never)]
    fn sample_f_other(
        &self,
        wo: Vec3,
        u_lobe: f32,
        u: [f32; 2],
        mode: TransportMode,
        sample: SampleFlags,
    ) -> Option<BsdfSample<C>> {
        self.sample_f_with(&self.bxdf, wo, u_lobe, u, mode, sample)
    }
    /// Solid-angle density of sampling `wi` given `wo` (world directions).
    #[inline]
    pub fn pdf(&self, wo: Vec3, wi: Vec3, mode: TransportMode) -> f32 {
        match &self.bxdf {
            Bxdf::Diffuse(b) => self.pdf_with(b, wo, wi, mode),
            b => self.pdf_with(b, wo, wi, mode),
        }
    }

    /// [`Bsdf::f`] with the BxDF `b` (this BSDF's, or its variant).
    #[inline(always)]
    fn f_with<B: BxdfModel<C>>(&self, b: &B, wo: Vec3, wi: Vec3, mode: TransportMode) -> C {
        let (wo, wi) = (self.to_local(wo), self.to_local(wi));
        if wo.z == 0.0 {
            return C::ZERO;
        }
        b.f(wo, wi, mode)
    }
    /// [`Bsdf::sample_f_restricted`] with the BxDF `b`.
    #[inline(always)]
    fn sample_f_with<B: BxdfModel<C>>(
        &self,
        b: &B,
        wo: Vec3,
        u_lobe: f32,
        u: [f32; 2],
        mode: TransportMode,
        sample: SampleFlags,
    ) -> Option<BsdfSample<C>> {
        let wo = self.to_local(wo);
        let flags = b.flags();
        let allowed = (sample.reflection() && flags.is_reflective())
            || (sample.transmission() && flags.is_transmissive());
        if wo.z == 0.0 || !allowed {
            return None;
        }
        let mut bs = b.sample_f(wo, u_lobe, u, mode, sample)?;
        if bs.f.is_black() || !(bs.pdf > 0.0) || bs.wi.z == 0.0 || !bs.f.is_finite() {
            return None;
        }
        bs.wi = self.from_local(bs.wi);
        Some(bs)
    }
    /// [`Bsdf::pdf`] with the BxDF `b`.
    #[inline(always)]
    fn pdf_with<B: BxdfModel<C>>(&self, b: &B, wo: Vec3, wi: Vec3, mode: TransportMode) -> f32 {
        let (wo, wi) = (self.to_local(wo), self.to_local(wi));
        if wo.z == 0.0 {
            return 0.0;
        }
        b.pdf(wo, wi, mode, SampleFlags::All)
    }
    /// Widens near-specular lobes (for path regularization).
    pub fn regularize(&mut self) {
        self.bxdf.regularize();
    }
}
