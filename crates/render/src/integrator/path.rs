//! The path-tracing loop ([`PathIntegrator::li`]) and next-event estimation.

use super::{LightStrategy, PathIntegrator, PathStats, sqr};
use crate::bsdf::material::BsdfContext;
use crate::bsdf::{Bsdf, LayeredExitWeight, TransportMode, power_heuristic};
use crate::light::LightSampleContext;
use crate::math::{Frame, Ray, SHADOW_EPSILON, Vec3, offset_ray_origin, spawn_ray, spawn_ray_to};
use crate::scene::Scene;
use crate::spectrum::{Colour, Rgb};
use lowdisc::pixel::{Dims, PixelSampler};

/// The sample values one scattering vertex uses, drawn in the documented order.
pub(super) struct VertexSamples {
    pub(super) light_choice: f32,
    pub(super) light: [f32; 2],
    pub(super) lobe: f32,
    pub(super) bsdf: [f32; 2],
    pub(super) rr: f32,
}

impl VertexSamples {
    #[inline]
    pub(super) fn draw<S: PixelSampler>(s: &mut S) -> Self {
        let [[light_choice, _], light, [lobe, _], bsdf, [rr, _]] =
            s.get_values([Dims::One, Dims::Two, Dims::One, Dims::Two, Dims::One]);
        VertexSamples {
            light_choice,
            light,
            lobe,
            bsdf,
            rr,
        }
    }
}

impl PathIntegrator {
    /// Radiance arriving at the camera along `ray` (unit direction), drawing
    /// every random number from `sampler` (whose pixel sample has been
    /// started and whose pixel and lens dimensions have been consumed).
    /// `bsdf_seed` seeds the stochastic (layered) BSDFs' random walks (the
    /// render passes its sampler seed). RGB mode; see [`PathIntegrator::li_for`].
    pub fn li<S: PixelSampler>(
        &self,
        scene: &Scene,
        ray: Ray,
        sampler: &mut S,
        bsdf_seed: u64,
        stats: &mut PathStats,
    ) -> Rgb {
        self.li_for(scene, ray, sampler, bsdf_seed, &(), stats)
    }

    /// [`PathIntegrator::li`] in colour `C` at wavelengths `w` (spectral
    /// mode: `C` = [`SampledSpectrum`](crate::spectrum::SampledSpectrum));
    /// emission and reflectances are made `C` by [`Colour`]'s constructors.
    pub fn li_for<S: PixelSampler, C: Colour>(
        &self,
        scene: &Scene,
        mut ray: Ray,
        sampler: &mut S,
        bsdf_seed: u64,
        w: &C::Wavelengths,
        stats: &mut PathStats,
    ) -> C {
        if scene.has_media() {
            return self.li_volumetric(scene, ray, sampler, bsdf_seed, w, stats);
        }
        let mut l = C::ZERO;
        let mut beta = C::ONE;
        let mut depth = 0u32;
        let mut specular_bounce = false;
        let mut eta_scale = 1.0f32;
        // Density of the BSDF sample that produced `ray`, and where it started.
        let mut p_b = 1.0f32;
        let mut prev_ctx = LightSampleContext::at(ray.o);
        let lights = scene.lights();
        loop {
            stats.rays += 1;
            let Some(hit) = scene.intersect_hit(&ray) else {
                for &i in scene.infinite_lights() {
                    let light = &lights[i];
                    let le = light.le(&ray);
                    if le.is_black() {
                        continue;
                    }
                    let le = C::emission(le, scene.light_spectrum(i), w);
                    let p_l = || scene.light_sampler().pmf(i) * light.pdf_li(&prev_ctx, ray.d);
                    if let Some(mis) = self.emission_weight(depth, specular_bounce, p_b, p_l) {
                        l += beta * le * mis;
                    }
                }
                break;
            };
            let (material, light) = scene.material_and_light(hit.prim);
            let mut surf = hit.surface;
            let wo = -ray.d;
            if let Some(li) = light {
                let light = &lights[li as usize];
                let le = light.l(surf.p, surf.ng, surf.uv, wo);
                if !le.is_black() {
                    let le = C::emission(le, scene.light_spectrum(li as usize), w);
                    let p_l = || {
                        scene.light_sampler().pmf(li as usize)
                            * light.pdf_li_hit(&prev_ctx, surf.p, surf.ng)
                    };
                    if let Some(mis) = self.emission_weight(depth, specular_bounce, p_b, p_l) {
                        l += beta * le * mis;
                    }
                }
            }
            if depth == self.max_depth {
                break;
            }
            depth += 1;
            let u = VertexSamples::draw(sampler);
            let material = &scene.materials()[material as usize];
            let mut bsdf_ctx = BsdfContext {
                ns: surf.ns,
                dpdus: surf.dpdu,
                seed: bsdf_seed,
                p: surf.p,
                uv: surf.uv,
                wo,
            };
            let mut shading = hit.shading;
            if let Some(bump) = material.bump(&bsdf_ctx) {
                let g = scene.shapes().shading_geometry(hit.prim, &surf);
                let g = bump.apply(&bsdf_ctx.texture_context(), surf.ng, &g);
                (surf.ns, surf.dpdu) = (g.n, g.dpdu);
                (bsdf_ctx.ns, bsdf_ctx.dpdus) = (g.n, g.dpdu);
                shading = None;
            }
            // The frame first, so that the BSDF is built in one place.
            let frame = match shading {
                Some(frame) => frame,
                None => Frame::shading(surf.ns, surf.dpdu),
            };
            let mut bsdf = material.bsdf_in_frame::<C>(frame, &bsdf_ctx, w);
            if self.layered_exit_weight != LayeredExitWeight::UNBIASED {
                bsdf.bxdf.set_layered_exit_weight(self.layered_exit_weight);
            }
            let flags = bsdf.flags();
            let ctx = LightSampleContext::new(surf.p, surf.ng, surf.ns);
            if flags.is_non_specular() && self.strategy != LightStrategy::BsdfOnly {
                let ld = self.sample_ld(scene, &bsdf, &ctx, wo, &u, w, stats);
                l += beta * ld;
            }
            let Some(bs) = bsdf.sample_f(wo, u.lobe, u.bsdf, TransportMode::Radiance) else {
                break;
            };
            beta *= bs.f * (bs.wi.abs_dot(surf.ns) / bs.pdf);
            p_b = if bs.pdf_is_proportional {
                bsdf.pdf(wo, bs.wi, TransportMode::Radiance)
            } else {
                bs.pdf
            };
            specular_bounce = bs.is_specular();
            if bs.is_transmission() {
                eta_scale *= sqr(bs.eta);
            }
            prev_ctx = ctx;
            ray = spawn_ray(surf.p, surf.ng, bs.wi);
            if beta.is_black() {
                break;
            }
            let m = (beta * eta_scale).max_component();
            if m < 1.0 && depth > 1 {
                let q = (1.0 - m).max(0.0);
                if u.rr < q {
                    break;
                }
                beta /= 1.0 - q;
            }
        }
        l
    }

    /// The weight of emission reached by a BSDF-sampled (or camera) ray, or
    /// `None` when this strategy does not count it. `p_l` computes the
    /// light-sampling density of the same direction.
    #[inline]
    fn emission_weight(
        &self,
        depth: u32,
        specular_bounce: bool,
        p_b: f32,
        p_l: impl FnOnce() -> f32,
    ) -> Option<f32> {
        if depth == 0 || specular_bounce {
            return Some(1.0);
        }
        match self.strategy {
            LightStrategy::BsdfOnly => Some(1.0),
            LightStrategy::LightOnly => None,
            LightStrategy::Mis => Some(power_heuristic(p_b, p_l())),
        }
    }

    /// Next-event estimation: one light chosen by power, one sample of it,
    /// a shadow ray, weighted against BSDF sampling by the power heuristic.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn sample_ld<C: Colour>(
        &self,
        scene: &Scene,
        bsdf: &Bsdf<C>,
        ctx: &LightSampleContext,
        wo: Vec3,
        u: &VertexSamples,
        w: &C::Wavelengths,
        stats: &mut PathStats,
    ) -> C {
        let Some((index, pmf)) = scene.light_sampler().sample(u.light_choice) else {
            return C::ZERO;
        };
        let light = &scene.lights()[index];
        let Some(ls) = light.sample_li(ctx, u.light) else {
            return C::ZERO;
        };
        let le = C::emission(ls.l, scene.light_spectrum(index), w);
        let f = bsdf.f(wo, ls.wi, TransportMode::Radiance) * ls.wi.abs_dot(ctx.ns);
        if f.is_black() || !(pmf > 0.0) {
            return C::ZERO;
        }
        stats.rays += 1;
        let target = offset_ray_origin(ls.p_light, ls.n_light, ctx.p - ls.p_light);
        if scene.intersect_p(&spawn_ray_to(ctx.p, ctx.n, target), 1.0 - SHADOW_EPSILON) {
            return C::ZERO;
        }
        let p_l = pmf * ls.pdf;
        if ls.is_delta || self.strategy == LightStrategy::LightOnly {
            return f * le / p_l;
        }
        let p_b = bsdf.pdf(wo, ls.wi, TransportMode::Radiance);
        f * le * (power_heuristic(p_l, p_b) / p_l)
    }
}
