//! Distant (directional) light.

use super::error::{check_rgb, check_scalar};
use super::{LightError, LightLiSample, LightSampleContext, SceneSphere, luminance_normaliser};
use crate::content_hash::{ContentHash, ContentSink};
use crate::math::{Bounds3, Point3, Transform, Vec3};
use crate::spectrum::Rgb;
use std::f32::consts::PI;

/// pbrt-v4's `LightSource "distant"`: radiance `L` arriving from direction
/// `from - to` (light space; defaults `from = (0,0,0)`, `to = (0,0,1)`).
#[derive(Clone, Debug, PartialEq)]
pub struct DistantLight {
    /// Unit world direction towards the light.
    w: Vec3,
    l: Rgb,
    scene: SceneSphere,
}

impl DistantLight {
    /// A distant light. With `illuminance = Some(e)` the radiance is rescaled
    /// so that the luminance of the irradiance on a surface facing the light
    /// is `e`.
    pub fn new(
        light_to_world: &Transform,
        from: Point3,
        to: Point3,
        l: Rgb,
        scale: f32,
        illuminance: Option<f32>,
    ) -> Result<Self, LightError> {
        check_rgb("L", l)?;
        check_scalar("scale", scale)?;
        let w = light_to_world.vector(from - to).normalize();
        if !w.is_finite() {
            return Err(LightError::InvalidParameter(
                "distant light needs distinct, finite from and to".into(),
            ));
        }
        let k = luminance_normaliser(l, 1.0, illuminance);
        Ok(DistantLight {
            w,
            l: l * (scale * k),
            scene: SceneSphere::default(),
        })
    }
    /// Unit world direction towards the light.
    pub fn direction(&self) -> Vec3 {
        self.w
    }

    pub(crate) fn preprocess(&mut self, b: &Bounds3) {
        self.scene = SceneSphere::from_bounds(b);
    }

    pub(crate) fn sample_li(&self, ctx: &LightSampleContext) -> Option<LightLiSample> {
        Some(LightLiSample {
            l: self.l,
            wi: self.w,
            pdf: 1.0,
            p_light: self.scene.beyond(ctx.p, self.w),
            n_light: Vec3::ZERO,
            is_delta: true,
        })
    }

    pub(crate) fn phi(&self) -> Rgb {
        self.l * (PI * self.scene.radius * self.scene.radius)
    }
}

/// The scene's bounding sphere is derived from the shapes.
impl ContentHash for DistantLight {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let DistantLight { w, l, scene: _ } = self;
        (w, l).feed(sink);
    }
}
