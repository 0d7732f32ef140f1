//! The volumetric path tracer (pbrt-v4's `VolPathIntegrator`), used for
//! scenes with participating media ([`Scene::has_media`]).
//!
//! **Free flights** are sampled by delta tracking against a majorant (for a
//! homogeneous medium its extinction `σt`, so every tentative collision is
//! real): a distance with density `σ_maj e^{-σ_maj t}` in one *hero* lane,
//! then absorption, scattering or a null collision with probabilities
//! `σa/σ_maj`, `σs/σ_maj`, `σn/σ_maj` of that lane. The other lanes are
//! weighted by the ratio of their densities to the hero's (pbrt-v4's spectral
//! MIS, Miller et al. 2019, "A null-scattering path integral formulation of
//! light transport"): `r_u` and `r_l` carry the path's density under
//! unidirectional and light sampling relative to the hero lane's, and every
//! contribution is divided by their lane average, which is the one-sample
//! balance heuristic over the lanes. The hero lane is chosen uniformly per
//! camera sample, so the estimate is unbiased in every lane: a chromatic
//! medium is handled per RGB channel in RGB mode and per wavelength in
//! spectral mode.
//!
//! **Next-event estimation** from surfaces and from points in media (with
//! the Henyey-Greenstein phase function in place of the BSDF) multiplies the
//! light's contribution by the transmittance of the shadow ray, traced
//! through surfaces with the `interface` material and the media between
//! them; it is combined with BSDF or phase sampling by the balance
//! heuristic through `r_u` and `r_l`, as pbrt-v4's volpath does. In a
//! homogeneous medium the shadow ray's transmittance is `e^{-σt d}`, the
//! expectation of pbrt-v4's ratio-tracking estimate, computed exactly.
//!
//! **Emission** of a medium (`σa Le`) is added at every tentative collision
//! below the maximum depth. **Depth** counts surface and medium scattering
//! events; crossing an `interface` surface is not one. **Russian roulette**
//! applies at surface vertices after two scattering events, to
//! `β · η² / avg(r_u)`.
//!
//! **Sampler dimensions** (in scenes with media; see the module docs of
//! [`crate::integrator`]): after the lens, one dimension chooses the hero
//! lane; then every bounce draws [`DIMS_PER_MEDIA_BOUNCE`] dimensions before
//! it is traced: the free-flight distance and the collision event of its
//! first segment in a medium, the seed of a random stream, and the seven
//! dimensions of the vertex that ends the bounce (light choice, light
//! position, BSDF lobe, BSDF or phase direction, Russian roulette). Further
//! collisions of the same bounce (null collisions, segments after crossing
//! an `interface` surface) draw from the random stream (PCG32 seeded by a
//! hash of the seed dimension), as pbrt-v4 draws them from an RNG seeded by
//! sampler values.

use super::path::VertexSamples;
use super::{PathIntegrator, PathStats};
use crate::accel::Hit;
use crate::bsdf::material::BsdfContext;
use crate::bsdf::{Bsdf, LayeredExitWeight, TransportMode};
use crate::geometry::SurfaceHit;
use crate::light::LightSampleContext;
use crate::math::{
    Frame, Normal3, Point3, Ray, SHADOW_EPSILON, Vec3, offset_ray_origin, spawn_ray, spawn_ray_to,
};
use crate::medium::phase::{henyey_greenstein, sample_henyey_greenstein};
use crate::medium::{MediumPoint, finite_distance};
use crate::scene::{INTERFACE, Scene};
use crate::spectrum::Colour;
use lowdisc::pcg::Pcg32;
use lowdisc::pixel::{Dims, PixelSampler};

/// Sampler dimensions of one bounce in a scene with media: three for the
/// medium (distance, event, stream seed), then the vertex's seven.
pub const DIMS_PER_MEDIA_BOUNCE: u32 = 3 + super::DIMS_PER_BOUNCE;

/// The sample values of one bounce in a scene with media.
struct MediaBounce {
    /// Free-flight distance and collision event of the first segment.
    flight: [f32; 2],
    /// Seeds the stream of the bounce's further collisions.
    stream: f32,
    vertex: VertexSamples,
}

impl MediaBounce {
    #[inline]
    fn draw<S: PixelSampler>(s: &mut S) -> Self {
        let [[distance, _], [event, _], [stream, _]] =
            s.get_values([Dims::One, Dims::One, Dims::One]);
        MediaBounce {
            flight: [distance, event],
            stream,
            vertex: VertexSamples::draw(s),
        }
    }
}

/// The state of one volumetric path.
struct VolPath<C: Colour> {
    l: C,
    beta: C,
    /// Density of the path under unidirectional sampling, per lane,
    /// relative to the hero lane's.
    r_u: C,
    /// The same under light sampling (of the last vertex's light).
    r_l: C,
    /// The lane whose density samples distances and events.
    hero: usize,
    depth: u32,
    specular_bounce: bool,
    eta_scale: f32,
    prev_ctx: LightSampleContext,
    medium: Option<u32>,
}

impl<C: Colour> VolPath<C> {
    /// Multiplies `beta`, `r_u` and `r_l` by `t / t[hero]` (a free flight
    /// without collision: its density is the hero lane's transmittance).
    #[inline]
    fn pass(&mut self, t: C) {
        let ratio = t / t.lane(self.hero);
        self.beta *= ratio;
        self.r_u *= ratio;
        self.r_l *= ratio;
    }

    /// Adds emission `le` reached without light sampling, from a vertex whose
    /// light-sampling density (light choice included) is `p_l`.
    #[inline]
    fn add_emission(&mut self, le: C, p_l: impl FnOnce() -> f32) {
        if self.depth == 0 || self.specular_bounce {
            self.l += self.beta * le / self.r_u.average();
        } else {
            let r_l = self.r_l * p_l();
            self.l += self.beta * le / (self.r_u + r_l).average();
        }
    }
}

/// How a free flight through a medium ended.
enum Flight<C> {
    /// Absorbed (or the path's weight became zero).
    Absorbed,
    /// Scattered at a point with these coefficients.
    Scattered(Point3, MediumPoint<C>),
    /// Reached the end of the segment.
    Through,
}

/// How a vertex scatters light for next-event estimation.
#[derive(Clone, Copy)]
enum Scatter<'a, C: Colour> {
    /// A surface BSDF with its shading normal, at a hit.
    Surface(&'a Bsdf<C>, Normal3, &'a Hit),
    /// A Henyey-Greenstein phase function with asymmetry `g`.
    Phase(f32),
}

impl PathIntegrator {
    /// [`PathIntegrator::li_for`] for a scene with media (see the module
    /// docs): the camera ray starts in the scene's camera medium. Never
    /// inlined, so that the path tracer of scenes without media compiles
    /// as it did before media existed.
    #[inline(never)]
    pub(super) fn li_volumetric<S: PixelSampler, C: Colour>(
        &self,
        scene: &Scene,
        mut ray: Ray,
        sampler: &mut S,
        bsdf_seed: u64,
        w: &C::Wavelengths,
        stats: &mut PathStats,
    ) -> C {
        let hero = ((sampler.get_1d() * C::LANES as f32) as usize).min(C::LANES - 1);
        let mut path = VolPath {
            l: C::ZERO,
            beta: C::ONE,
            r_u: C::ONE,
            r_l: C::ONE,
            hero,
            depth: 0,
            specular_bounce: false,
            eta_scale: 1.0,
            prev_ctx: LightSampleContext::at(ray.o),
            medium: scene.camera_medium(),
        };
        let lights = scene.lights();
        'bounces: loop {
            let u = MediaBounce::draw(sampler);
            let mut rng: Option<Pcg32> = None;
            // Segments of this bounce until a vertex (or the end).
            loop {
                stats.rays += 1;
                let hit = scene.intersect_hit(&ray);
                if let Some(m) = path.medium {
                    let t_max = hit.as_ref().map_or(f32::INFINITY, |h| h.surface.t);
                    let first = rng.is_none();
                    let stream = rng.get_or_insert_with(|| stream(u.stream));
                    let flight = if first {
                        u.flight
                    } else {
                        [stream.next_f32(), stream.next_f32()]
                    };
                    let mp = scene.media()[m as usize].point::<C>(w);
                    match self.free_flight(&mut path, &mp, &ray, t_max, flight, stream) {
                        Flight::Absorbed => break 'bounces,
                        Flight::Through => {}
                        Flight::Scattered(p, mp) => {
                            if path.depth >= self.max_depth {
                                break 'bounces;
                            }
                            path.depth += 1;
                            match self
                                .medium_vertex(scene, &mut path, p, &mp, &ray, &u.vertex, w, stats)
                            {
                                Some(next) => {
                                    ray = next;
                                    continue 'bounces;
                                }
                                None => break 'bounces,
                            }
                        }
                    }
                }
                let prev = path.prev_ctx;
                let Some(hit) = hit else {
                    for &i in scene.infinite_lights() {
                        let light = &lights[i];
                        let le = light.le(&ray);
                        if le.is_black() {
                            continue;
                        }
                        let le = C::emission(le, scene.light_spectrum(i), w);
                        let p_l = || scene.light_sampler().pmf(i) * light.pdf_li(&prev, ray.d);
                        path.add_emission(le, p_l);
                    }
                    break 'bounces;
                };
                let (material, light) = scene.material_and_light(hit.prim);
                let surf = hit.surface;
                if let Some(li) = light {
                    let light = &lights[li as usize];
                    let le = light.l(surf.p, surf.ng, surf.uv, -ray.d);
                    if !le.is_black() {
                        let le = C::emission(le, scene.light_spectrum(li as usize), w);
                        let p_l = || {
                            scene.light_sampler().pmf(li as usize)
                                * light.pdf_li_hit(&prev, surf.p, surf.ng)
                        };
                        path.add_emission(le, p_l);
                    }
                }
                if material == INTERFACE {
                    path.medium = medium_after(scene, &hit, ray.d, path.medium);
                    ray = spawn_ray(surf.p, surf.ng, ray.d);
                    continue;
                }
                if path.depth == self.max_depth {
                    break 'bounces;
                }
                path.depth += 1;
                match self.surface_vertex(
                    scene, &mut path, &hit, material, &ray, &u.vertex, bsdf_seed, w, stats,
                ) {
                    Some(next) => {
                        ray = next;
                        continue 'bounces;
                    }
                    None => break 'bounces,
                }
            }
        }
        path.l
    }

    /// Delta tracking along `ray` up to `t_max` (in ray parameter) through
    /// a medium with coefficients `mp`: `u` decides the first collision,
    /// `stream` any further ones. Updates the path's weights (and adds the
    /// medium's emission at each collision).
    fn free_flight<C: Colour>(
        &self,
        path: &mut VolPath<C>,
        mp: &MediumPoint<C>,
        ray: &Ray,
        t_max: f32,
        mut u: [f32; 2],
        stream: &mut Pcg32,
    ) -> Flight<C> {
        let h = path.hero;
        let sigma_maj = mp.sigma_t();
        let s_h = sigma_maj.lane(h);
        let len = ray.d.length();
        let d_max = finite_distance(t_max * len);
        let mut d0 = 0.0f32;
        loop {
            let d = d0 - (1.0 - u[0]).ln() / s_h;
            if !(s_h > 0.0) || !(d < d_max) {
                path.pass((sigma_maj * -(d_max - d0)).exp());
                return Flight::Through;
            }
            let t_maj = (sigma_maj * -(d - d0)).exp();
            let pdf = t_maj.lane(h) * s_h;
            if path.depth < self.max_depth && !mp.le.is_black() {
                let r_e = path.r_u * sigma_maj * t_maj / pdf;
                if !r_e.is_black() {
                    let beta_p = path.beta * t_maj / pdf;
                    path.l += beta_p * mp.sigma_a * mp.le / r_e.average();
                }
            }
            let p_absorb = mp.sigma_a.lane(h) / s_h;
            let p_scatter = mp.sigma_s.lane(h) / s_h;
            if u[1] < p_absorb {
                return Flight::Absorbed;
            }
            if u[1] < p_absorb + p_scatter {
                let pdf = t_maj.lane(h) * mp.sigma_s.lane(h);
                let f = t_maj * mp.sigma_s / pdf;
                path.beta *= f;
                path.r_u *= f;
                if path.beta.is_black() || path.r_u.is_black() {
                    return Flight::Absorbed;
                }
                return Flight::Scattered(ray.at(d / len), *mp);
            }
            // A null collision (never in a homogeneous medium but for
            // rounding): continue from it.
            let sigma_n = (sigma_maj - mp.sigma_a - mp.sigma_s).map(|x| x.max(0.0));
            let pdf = t_maj.lane(h) * sigma_n.lane(h);
            if !(pdf > 0.0) {
                return Flight::Absorbed;
            }
            path.beta *= t_maj * sigma_n / pdf;
            path.r_u *= t_maj * sigma_n / pdf;
            path.r_l *= t_maj * sigma_maj / pdf;
            if path.beta.is_black() || path.r_u.is_black() {
                return Flight::Absorbed;
            }
            d0 = d;
            u = [stream.next_f32(), stream.next_f32()];
        }
    }

    /// A scattering vertex at `p` in a medium: next-event estimation with
    /// the phase function, then a phase-sampled direction. Returns the
    /// continuation ray, or `None` when the path ends.
    #[allow(clippy::too_many_arguments)]
    fn medium_vertex<C: Colour>(
        &self,
        scene: &Scene,
        path: &mut VolPath<C>,
        p: Point3,
        mp: &MediumPoint<C>,
        ray: &Ray,
        u: &VertexSamples,
        w: &C::Wavelengths,
        stats: &mut PathStats,
    ) -> Option<Ray> {
        let wo = -ray.d.normalize();
        let ctx = LightSampleContext::at(p);
        let ld =
            self.sample_ld_volumetric(scene, path, &ctx, Scatter::Phase(mp.g), wo, u, w, stats);
        path.l += ld;
        let (wi, pdf) = sample_henyey_greenstein(wo, mp.g, u.bsdf);
        if !(pdf > 0.0) {
            return None;
        }
        // The phase function is sampled exactly: `beta` keeps its value.
        path.r_l = path.r_u / pdf;
        path.prev_ctx = ctx;
        path.specular_bounce = false;
        Some(Ray::new(p, wi))
    }

    /// A scattering vertex on a surface: next-event estimation, BSDF
    /// sampling and Russian roulette. Returns the continuation ray, or
    /// `None` when the path ends.
    #[allow(clippy::too_many_arguments)]
    fn surface_vertex<C: Colour>(
        &self,
        scene: &Scene,
        path: &mut VolPath<C>,
        hit: &Hit,
        material: u32,
        ray: &Ray,
        u: &VertexSamples,
        bsdf_seed: u64,
        w: &C::Wavelengths,
        stats: &mut PathStats,
    ) -> Option<Ray> {
        let wo = -ray.d;
        let (bsdf, surf) = self.surface_bsdf::<C>(scene, hit, material, wo, bsdf_seed, w);
        let ctx = LightSampleContext::new(surf.p, surf.ng, surf.ns);
        if bsdf.flags().is_non_specular() {
            let scatter = Scatter::Surface(&bsdf, surf.ns, hit);
            let ld = self.sample_ld_volumetric(scene, path, &ctx, scatter, wo, u, w, stats);
            path.l += ld;
        }
        let bs = bsdf.sample_f(wo, u.lobe, u.bsdf, TransportMode::Radiance)?;
        path.beta *= bs.f * (bs.wi.abs_dot(surf.ns) / bs.pdf);
        let pdf = if bs.pdf_is_proportional {
            bsdf.pdf(wo, bs.wi, TransportMode::Radiance)
        } else {
            bs.pdf
        };
        path.r_l = path.r_u / pdf;
        path.specular_bounce = bs.is_specular();
        if bs.is_transmission() {
            path.eta_scale *= bs.eta * bs.eta;
        }
        path.prev_ctx = ctx;
        path.medium = medium_after(scene, hit, bs.wi, path.medium);
        if path.beta.is_black() {
            return None;
        }
        let m = (path.beta * path.eta_scale / path.r_u.average()).max_component();
        if m < 1.0 && path.depth > 1 {
            let q = (1.0 - m).max(0.0);
            if u.rr < q {
                return None;
            }
            path.beta /= 1.0 - q;
        }
        Some(spawn_ray(surf.p, surf.ng, bs.wi))
    }

    /// The BSDF of material `material` (a scene index) at `hit`, seen from
    /// `wo`, with its bump or normal map applied, and the surface with the
    /// shading normal and tangent that the map gives (what the path tracer
    /// does inline at each vertex; it keeps its own copy so that its loop
    /// compiles as it did before media existed).
    pub(super) fn surface_bsdf<C: Colour>(
        &self,
        scene: &Scene,
        hit: &Hit,
        material: u32,
        wo: Vec3,
        bsdf_seed: u64,
        w: &C::Wavelengths,
    ) -> (Bsdf<C>, SurfaceHit) {
        let mut surf = hit.surface;
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
        (bsdf, surf)
    }

    /// Next-event estimation at `ctx` (a surface point, or a point in a
    /// medium with zero normals), in a scene with media: one light chosen
    /// by power, one sample of it, the transmittance of the shadow ray,
    /// weighted against BSDF or phase sampling by the balance heuristic of
    /// the path's densities.
    #[allow(clippy::too_many_arguments)]
    fn sample_ld_volumetric<C: Colour>(
        &self,
        scene: &Scene,
        path: &VolPath<C>,
        ctx: &LightSampleContext,
        scatter: Scatter<'_, C>,
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
        let (f, scatter_pdf) = match scatter {
            Scatter::Surface(bsdf, ns, _) => (
                bsdf.f(wo, ls.wi, TransportMode::Radiance) * ls.wi.abs_dot(ns),
                bsdf.pdf(wo, ls.wi, TransportMode::Radiance),
            ),
            Scatter::Phase(g) => {
                let p = henyey_greenstein(wo.dot(ls.wi), g);
                (C::splat(p), p)
            }
        };
        if f.is_black() || !(pmf > 0.0) {
            return C::ZERO;
        }
        let target = offset_ray_origin(ls.p_light, ls.n_light, ctx.p - ls.p_light);
        let medium = match scatter {
            Scatter::Surface(_, _, hit) => medium_after(scene, hit, ls.wi, path.medium),
            Scatter::Phase(_) => path.medium,
        };
        let rays = &mut stats.rays;
        let Some(tr) = transmittance::<C>(scene, ctx.p, ctx.n, target, medium, w, rays) else {
            return C::ZERO;
        };
        let le = C::emission(ls.l, scene.light_spectrum(index), w);
        let r_l = path.r_u * (pmf * ls.pdf);
        let contribution = path.beta * f * tr * le;
        if ls.is_delta {
            return contribution / r_l.average();
        }
        let r_u = path.r_u * scatter_pdf;
        contribution / (r_l + r_u).average()
    }
}

/// The medium a ray leaving `hit` in direction `d` travels in: the side of
/// the surface `d` points to when the surface separates two media, else
/// `current`.
#[inline]
fn medium_after(scene: &Scene, hit: &Hit, d: Vec3, current: Option<u32>) -> Option<u32> {
    match scene.medium_interface(hit.prim) {
        Some(mi) => mi.toward(hit.surface.ng, d),
        None => current,
    }
}

/// The random stream of a bounce's further collisions, seeded by a hash of
/// the sampler value `u`.
fn stream(u: f32) -> Pcg32 {
    let mut x = u64::from(u.to_bits()) ^ 0x9e37_79b9_7f4a_7c15;
    x = (x ^ (x >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    Pcg32::new(x ^ (x >> 31), 0)
}

/// The transmittance from the point `p` (on a surface with geometric normal
/// `n`, or in a medium with `n` zero) to `target`, for a ray that starts in
/// `medium`: through surfaces with the `interface` material
/// (which change the medium) and the media between them. `None` when a
/// surface with a material is in the way. Counts the rays it traces.
///
/// ```
/// use lowdisc_render::integrator::transmittance;
/// use lowdisc_render::math::Vec3;
/// use lowdisc_render::scene::SceneBuilder;
/// use lowdisc_render::spectrum::Rgb;
///
/// let scene = SceneBuilder::new().build().unwrap();
/// let (p, target) = (Vec3::ZERO, Vec3::new(0.0, 0.0, 5.0));
/// let mut rays = 0;
/// let t = transmittance::<Rgb>(&scene, p, Vec3::ZERO, target, None, &(), &mut rays);
/// assert_eq!(t, Some(Rgb::ONE));
/// ```
pub fn transmittance<C: Colour>(
    scene: &Scene,
    p: Point3,
    n: Normal3,
    target: Point3,
    mut medium: Option<u32>,
    w: &C::Wavelengths,
    rays: &mut u64,
) -> Option<C> {
    let mut ray = spawn_ray_to(p, n, target);
    let mut tr = C::ONE;
    let t_end = 1.0 - SHADOW_EPSILON;
    loop {
        *rays += 1;
        let hit = scene.intersect_hit_before(&ray, t_end);
        if let Some(m) = medium {
            let t = hit.as_ref().map_or(t_end, |h| h.surface.t);
            tr *= scene.media()[m as usize].transmittance::<C>(t * ray.d.length(), w);
        }
        let Some(hit) = hit else {
            return Some(tr);
        };
        if scene.material_and_light(hit.prim).0 != INTERFACE || tr.is_black() {
            return None;
        }
        medium = medium_after(scene, &hit, ray.d, medium);
        ray = spawn_ray_to(hit.surface.p, hit.surface.ng, target);
    }
}
