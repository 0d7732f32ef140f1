//! Isotropic point light.

use super::error::{check_rgb, check_scalar};
use super::{LightError, LightLiSample, LightSampleContext, luminance_normaliser};
use crate::content_hash::{ContentHash, ContentSink};
use crate::math::{Point3, Transform, Vec3};
use crate::spectrum::Rgb;
use std::f32::consts::PI;

/// pbrt-v4's `LightSource "point"`: intensity `I` (W/sr) emitted equally in
/// all directions from `from` (in light space).
#[derive(Clone, Debug, PartialEq)]
pub struct PointLight {
    /// World-space position.
    position: Point3,
    /// Intensity with `scale` and power normalisation applied.
    intensity: Rgb,
}

impl PointLight {
    /// A point light at `light_to_world(from)` with intensity `i * scale`.
    /// With `power = Some(p)` the intensity is rescaled so that the luminance
    /// of the total power `4π I` is `p`.
    pub fn new(
        light_to_world: &Transform,
        from: Point3,
        i: Rgb,
        scale: f32,
        power: Option<f32>,
    ) -> Result<Self, LightError> {
        check_rgb("I", i)?;
        check_scalar("scale", scale)?;
        let position = light_to_world.point(from);
        if !position.is_finite() {
            return Err(LightError::InvalidParameter(
                "point light position is not finite".into(),
            ));
        }
        let k = luminance_normaliser(i, 4.0 * PI, power);
        Ok(PointLight {
            position,
            intensity: i * (scale * k),
        })
    }
    /// World-space position.
    pub fn position(&self) -> Point3 {
        self.position
    }
    /// Intensity (W/sr) after scaling.
    pub fn intensity(&self) -> Rgb {
        self.intensity
    }

    pub(crate) fn sample_li(&self, ctx: &LightSampleContext) -> Option<LightLiSample> {
        let d = self.position - ctx.p;
        let d2 = d.length_squared();
        if !(d2 > 0.0) {
            return None;
        }
        Some(LightLiSample {
            l: self.intensity / d2,
            wi: d / d2.sqrt(),
            pdf: 1.0,
            p_light: self.position,
            n_light: Vec3::ZERO,
            is_delta: true,
        })
    }

    pub(crate) fn phi(&self) -> Rgb {
        self.intensity * (4.0 * PI)
    }
}

impl ContentHash for PointLight {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let PointLight {
            position,
            intensity,
        } = self;
        (position, intensity).feed(sink);
    }
}
