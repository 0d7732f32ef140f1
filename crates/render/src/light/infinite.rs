//! Constant environment light.

use super::error::{check_rgb, check_scalar};
use super::{LightError, LightLiSample, LightSampleContext, SceneSphere, luminance_normaliser};
use crate::content_hash::{ContentHash, ContentSink};
use crate::math::sampling::sample_uniform_sphere;
use crate::math::{Bounds3, Point2, Ray, Vec3};
use crate::spectrum::Rgb;
use std::f32::consts::PI;

/// pbrt-v4's `LightSource "infinite"` with a constant `L`: the same radiance
/// from every direction, sampled uniformly over the sphere.
#[derive(Clone, Debug, PartialEq)]
pub struct UniformInfiniteLight {
    l: Rgb,
    scene: SceneSphere,
}

impl UniformInfiniteLight {
    /// A constant environment of radiance `l * scale`. With
    /// `illuminance = Some(e)` the radiance is rescaled so that the luminance
    /// of the irradiance on an unoccluded surface (`π L`) is `e`.
    pub fn new(l: Rgb, scale: f32, illuminance: Option<f32>) -> Result<Self, LightError> {
        check_rgb("L", l)?;
        check_scalar("scale", scale)?;
        let k = luminance_normaliser(l, PI, illuminance);
        Ok(UniformInfiniteLight {
            l: l * (scale * k),
            scene: SceneSphere::default(),
        })
    }
    /// The radiance.
    pub fn radiance(&self) -> Rgb {
        self.l
    }

    pub(crate) fn preprocess(&mut self, b: &Bounds3) {
        self.scene = SceneSphere::from_bounds(b);
    }

    pub(crate) fn sample_li(&self, ctx: &LightSampleContext, u: [f32; 2]) -> Option<LightLiSample> {
        let wi = sample_uniform_sphere(Point2::new(u[0], u[1]));
        Some(LightLiSample {
            l: self.l,
            wi,
            pdf: 1.0 / (4.0 * PI),
            p_light: self.scene.beyond(ctx.p, wi),
            n_light: Vec3::ZERO,
            is_delta: false,
        })
    }

    pub(crate) fn pdf_li(&self, _ctx: &LightSampleContext, _wi: Vec3) -> f32 {
        1.0 / (4.0 * PI)
    }

    pub(crate) fn le(&self, _ray: &Ray) -> Rgb {
        self.l
    }

    pub(crate) fn phi(&self) -> Rgb {
        self.l * (4.0 * PI * PI * self.scene.radius * self.scene.radius)
    }
}

/// The scene's bounding sphere is derived from the shapes.
impl ContentHash for UniformInfiniteLight {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let UniformInfiniteLight { l, scene: _ } = self;
        l.feed(sink);
    }
}
