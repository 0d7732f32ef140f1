//! Light sources with pbrt-v4's parameter meanings, RGB radiometry, and
//! power-proportional light selection.
//!
//! All lights live in one enum, [`Light`], dispatched by `match`:
//! * [`PointLight`] and [`SpotLight`]: delta positions (intensity `I`);
//! * [`DistantLight`]: a delta direction (radiance `L` of a directional source);
//! * [`DiffuseAreaLight`]: a diffuse emitter on a triangle, sphere or disk;
//! * [`UniformInfiniteLight`] and [`ImageInfiniteLight`]: environment lights
//!   (the image one in pbrt-v4's equal-area octahedral layout or lat-long),
//!   importance-sampled by pixel brightness.
//!
//! Conventions (as in pbrt-v4): [`Light::sample_li`] returns incident radiance
//! along `wi` (towards the light) with its solid-angle density; delta lights
//! report `pdf = 1` and `is_delta = true` and their radiance already includes
//! the `1/d²` falloff. Lights at infinity need [`Light::preprocess`] with the
//! scene bounds before use (for shadow-ray end points and power).
//!
//! Normalisation by `power` / `illuminance` makes the *luminance* (Rec. 709
//! weights) of the total power / illuminance equal the given value; `scale`
//! then still multiplies, as in pbrt-v4. pbrt-v4 divides by the photometric
//! value of the RGB illuminant only, which agrees for colours of unit
//! luminance such as `[1 1 1]`.

mod area;
mod distant;
mod env_file;
mod envmap;
mod error;
mod infinite;
mod point;
mod sampler;
mod spot;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_env;

pub use area::{AreaShape, DiffuseAreaLight, diffuse_power_scale};
pub use distant::DistantLight;
pub use envmap::{EnvLayout, EnvLookup, ImageInfiniteLight, wrap_equal_area_pixel};
pub use error::LightError;
pub use infinite::UniformInfiniteLight;
pub use point::PointLight;
pub use sampler::LightSampler;
pub use spot::SpotLight;

use crate::content_hash::{ContentHash, ContentSink};
use crate::math::{Bounds3, Normal3, Point2, Point3, Ray, Vec3};
use crate::spectrum::Rgb;

/// The point (and surface normals) that receives light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSampleContext {
    /// The receiving point.
    pub p: Point3,
    /// Geometric normal there (zero for a point in a medium).
    pub n: Normal3,
    /// Shading normal there (zero for a point in a medium).
    pub ns: Normal3,
}

impl LightSampleContext {
    /// A surface point with geometric normal `n` and shading normal `ns`.
    pub fn new(p: Point3, n: Normal3, ns: Normal3) -> Self {
        LightSampleContext { p, n, ns }
    }
    /// A point without a surface (normals zero).
    pub fn at(p: Point3) -> Self {
        LightSampleContext {
            p,
            n: Vec3::ZERO,
            ns: Vec3::ZERO,
        }
    }
}

/// A light sample as seen from a receiving point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightLiSample {
    /// Incident radiance arriving along `-wi` (for delta lights: the
    /// irradiance-like value `I / d²` or `L`, to be used with `pdf = 1`).
    pub l: Rgb,
    /// Unit direction from the receiving point towards the light.
    pub wi: Vec3,
    /// Solid-angle density of `wi` (1 for delta lights).
    pub pdf: f32,
    /// The point on the light: the end of the shadow ray (for lights at
    /// infinity, a point beyond the scene's bounding sphere).
    pub p_light: Point3,
    /// Normal at `p_light` (zero for point, spot, distant and infinite lights).
    pub n_light: Normal3,
    /// True for point, spot and distant lights (no MIS: BSDF sampling cannot
    /// hit them).
    pub is_delta: bool,
}

impl LightLiSample {
    /// True when the sample is usable: a positive, finite density and a
    /// finite radiance that is not black.
    #[inline]
    pub(crate) fn carries_light(&self) -> bool {
        self.pdf > 0.0 && self.pdf.is_finite() && !self.l.is_black() && self.l.is_finite()
    }
}

/// Classification of a light for the integrator.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LightType {
    /// A point or spot light.
    DeltaPosition,
    /// A distant (directional) light.
    DeltaDirection,
    /// An emitter attached to a shape (hit by rays; see [`Light::l`]).
    Area,
    /// An environment light (seen by escaping rays; see [`Light::le`]).
    Infinite,
}

/// Any light of the renderer.
#[derive(Clone, Debug)]
pub enum Light {
    /// Point light.
    Point(PointLight),
    /// Spot light.
    Spot(SpotLight),
    /// Distant light.
    Distant(DistantLight),
    /// Diffuse area light.
    Area(DiffuseAreaLight),
    /// Constant environment light.
    UniformInfinite(UniformInfiniteLight),
    /// Image environment light.
    ImageInfinite(Box<ImageInfiniteLight>),
}

impl Light {
    /// The light's kind.
    pub fn light_type(&self) -> LightType {
        match self {
            Light::Point(_) | Light::Spot(_) => LightType::DeltaPosition,
            Light::Distant(_) => LightType::DeltaDirection,
            Light::Area(_) => LightType::Area,
            Light::UniformInfinite(_) | Light::ImageInfinite(_) => LightType::Infinite,
        }
    }
    /// True for point, spot and distant lights.
    pub fn is_delta(&self) -> bool {
        matches!(
            self.light_type(),
            LightType::DeltaPosition | LightType::DeltaDirection
        )
    }

    /// Samples incident light at `ctx` from the 2D uniform sample `u`; `None`
    /// when the sample carries no light (zero radiance or density, or the
    /// point is outside a spot light's cone).
    #[inline(always)]
    pub fn sample_li(&self, ctx: &LightSampleContext, u: [f32; 2]) -> Option<LightLiSample> {
        let u = [
            crate::sampling::clamp_unit(u[0]),
            crate::sampling::clamp_unit(u[1]),
        ];
        match self {
            // Area lights, the common case, check their samples themselves
            // (inlined into the caller); every other light here.
            Light::Area(l) => l.sample_li(ctx, u),
            _ => self.sample_li_other(ctx, u),
        }
    }

    /// [`Light::sample_li`] of the lights other than area lights, `u`
    /// clamped to `[0, 1)`.
    #[inline(never)]
    fn sample_li_other(&self, ctx: &LightSampleContext, u: [f32; 2]) -> Option<LightLiSample> {
        let s = match self {
            Light::Point(l) => l.sample_li(ctx),
            Light::Spot(l) => l.sample_li(ctx),
            Light::Distant(l) => l.sample_li(ctx),
            Light::Area(l) => l.sample_li(ctx, u),
            Light::UniformInfinite(l) => l.sample_li(ctx, u),
            Light::ImageInfinite(l) => l.sample_li(ctx, u),
        }?;
        s.carries_light().then_some(s)
    }

    /// Solid-angle density with which [`Light::sample_li`] at `ctx` returns
    /// direction `wi` (unit). Always 0 for delta lights. For an area light
    /// this intersects its shape; when the hit is already known use
    /// [`Light::pdf_li_hit`].
    pub fn pdf_li(&self, ctx: &LightSampleContext, wi: Vec3) -> f32 {
        match self {
            Light::Point(_) | Light::Spot(_) | Light::Distant(_) => 0.0,
            Light::Area(l) => l.pdf_li(ctx, wi),
            Light::UniformInfinite(l) => l.pdf_li(ctx, wi),
            Light::ImageInfinite(l) => l.pdf_li(ctx, wi),
        }
    }

    /// Solid-angle density of sampling the point `p_light` (unit normal
    /// `n_light`) of this area light from `ctx`; 0 for other lights.
    pub fn pdf_li_hit(&self, ctx: &LightSampleContext, p_light: Point3, n_light: Normal3) -> f32 {
        match self {
            Light::Area(l) => l.pdf_li_hit(ctx, p_light, n_light),
            _ => 0.0,
        }
    }

    /// Radiance emitted by an area light at surface point `p` (geometric
    /// normal `n`, texture coordinates `uv`) into direction `w` (pointing away
    /// from the surface); black for other lights.
    pub fn l(&self, p: Point3, n: Normal3, uv: Point2, w: Vec3) -> Rgb {
        match self {
            Light::Area(l) => l.l(p, n, uv, w),
            _ => Rgb::ZERO,
        }
    }

    /// Radiance arriving along a ray that escapes the scene (infinite lights
    /// only; black for others).
    pub fn le(&self, ray: &Ray) -> Rgb {
        match self {
            Light::UniformInfinite(l) => l.le(ray),
            Light::ImageInfinite(l) => l.le(ray),
            _ => Rgb::ZERO,
        }
    }

    /// Total emitted power (lights at infinity: the power through the scene's
    /// bounding disk, so [`Light::preprocess`] must have run).
    pub fn phi(&self) -> Rgb {
        match self {
            Light::Point(l) => l.phi(),
            Light::Spot(l) => l.phi(),
            Light::Distant(l) => l.phi(),
            Light::Area(l) => l.phi(),
            Light::UniformInfinite(l) => l.phi(),
            Light::ImageInfinite(l) => l.phi(),
        }
    }

    /// Records the scene's bounds (needed by distant and infinite lights;
    /// a no-op for the others).
    pub fn preprocess(&mut self, scene_bounds: &Bounds3) {
        match self {
            Light::Distant(l) => l.preprocess(scene_bounds),
            Light::UniformInfinite(l) => l.preprocess(scene_bounds),
            Light::ImageInfinite(l) => l.preprocess(scene_bounds),
            Light::Point(_) | Light::Spot(_) | Light::Area(_) => {}
        }
    }
}

/// Scene extent for lights at infinity: centre and radius of the bounding
/// sphere (radius 0 until preprocessed).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct SceneSphere {
    pub(crate) center: Point3,
    pub(crate) radius: f32,
}

impl SceneSphere {
    pub(crate) fn from_bounds(b: &Bounds3) -> Self {
        let (center, radius) = b.bounding_sphere();
        if radius.is_finite() {
            SceneSphere { center, radius }
        } else {
            SceneSphere::default()
        }
    }
    /// A shadow-ray end point beyond the scene along `wi` from `p` (at least
    /// one unit away when the scene has no extent).
    pub(crate) fn beyond(&self, p: Point3, wi: Vec3) -> Point3 {
        let r = self.radius.max(0.5);
        p + wi * (2.0 * r + p.distance(self.center))
    }
}

/// The factor that makes the luminance of `k * c` equal `target`, or 1 when
/// `target` is `None` (or not positive) or `c` has no luminance.
pub(crate) fn luminance_normaliser(c: Rgb, k: f32, target: Option<f32>) -> f32 {
    match target {
        Some(t) if t > 0.0 && t.is_finite() => {
            let y = c.luminance() * k;
            if y > 0.0 && y.is_finite() { t / y } else { 1.0 }
        }
        _ => 1.0,
    }
}

/// pbrt's smoothstep: 0 below `a`, 1 above `b`, a cubic Hermite ramp between.
#[inline]
pub(crate) fn smooth_step(x: f32, a: f32, b: f32) -> f32 {
    if a == b {
        return if x < a { 0.0 } else { 1.0 };
    }
    let t = ((x - a) / (b - a)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

impl ContentHash for Light {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        match self {
            Light::Point(l) => (0u8, l).feed(sink),
            Light::Spot(l) => (1u8, l).feed(sink),
            Light::Distant(l) => (2u8, l).feed(sink),
            Light::Area(l) => (3u8, l).feed(sink),
            Light::UniformInfinite(l) => (4u8, l).feed(sink),
            Light::ImageInfinite(l) => (5u8, l).feed(sink),
        }
    }
}
