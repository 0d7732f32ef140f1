//! Spot light with pbrt-v4's smoothstep falloff.

use super::error::{check_rgb, check_scalar};
use super::{LightError, LightLiSample, LightSampleContext, luminance_normaliser, smooth_step};
use crate::content_hash::{ContentHash, ContentSink};
use crate::math::{Point3, Transform, Vec3};
use crate::spectrum::Rgb;
use std::f32::consts::PI;

/// pbrt-v4's `LightSource "spot"`: a point light at `from` aimed at `to`,
/// full intensity inside `coneangle - conedelta` (degrees from the axis),
/// smoothstep falloff to zero at `coneangle`.
#[derive(Clone, Debug, PartialEq)]
pub struct SpotLight {
    position: Point3,
    /// World-to-light linear map (for directions).
    world_to_light: Transform,
    /// Unit cone axis in light space.
    axis: Vec3,
    intensity: Rgb,
    cos_falloff_start: f32,
    cos_falloff_end: f32,
}

impl SpotLight {
    /// A spot light. `cone_angle` and `cone_delta` are in degrees (pbrt
    /// defaults: 30 and 5). With `power = Some(p)` the intensity is rescaled
    /// so that the luminance of [`SpotLight`]'s total power is `p`.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        light_to_world: &Transform,
        from: Point3,
        to: Point3,
        i: Rgb,
        scale: f32,
        cone_angle: f32,
        cone_delta: f32,
        power: Option<f32>,
    ) -> Result<Self, LightError> {
        check_rgb("I", i)?;
        check_scalar("scale", scale)?;
        if !(cone_angle.is_finite() && cone_delta.is_finite() && cone_delta >= 0.0) {
            return Err(LightError::InvalidParameter(format!(
                "spot light cone angle {cone_angle} / delta {cone_delta} must be finite, delta >= 0"
            )));
        }
        let axis = (to - from).normalize();
        let position = light_to_world.point(from);
        if !axis.is_finite() || !position.is_finite() {
            return Err(LightError::InvalidParameter(
                "spot light needs distinct, finite from and to".into(),
            ));
        }
        let cos_falloff_end = cone_angle.to_radians().cos();
        let cos_falloff_start = (cone_angle - cone_delta).to_radians().cos();
        let k_e = cone_power_factor(cos_falloff_start, cos_falloff_end);
        let k = luminance_normaliser(i, k_e, power);
        Ok(SpotLight {
            position,
            world_to_light: light_to_world.inverse(),
            axis,
            intensity: i * (scale * k),
            cos_falloff_start,
            cos_falloff_end,
        })
    }
    /// World-space position.
    pub fn position(&self) -> Point3 {
        self.position
    }

    /// Intensity leaving towards world direction `w` (unit, away from the light).
    pub fn intensity_towards(&self, w: Vec3) -> Rgb {
        let wl = self.world_to_light.vector(w).normalize();
        self.intensity
            * smooth_step(
                wl.dot(self.axis),
                self.cos_falloff_end,
                self.cos_falloff_start,
            )
    }

    pub(crate) fn sample_li(&self, ctx: &LightSampleContext) -> Option<LightLiSample> {
        let d = self.position - ctx.p;
        let d2 = d.length_squared();
        if !(d2 > 0.0) {
            return None;
        }
        let wi = d / d2.sqrt();
        Some(LightLiSample {
            l: self.intensity_towards(-wi) / d2,
            wi,
            pdf: 1.0,
            p_light: self.position,
            n_light: Vec3::ZERO,
            is_delta: true,
        })
    }

    pub(crate) fn phi(&self) -> Rgb {
        self.intensity * cone_power_factor(self.cos_falloff_start, self.cos_falloff_end)
    }
}

/// Solid-angle integral of the falloff: full inside the inner cone, the
/// smoothstep ramp counted at half weight (pbrt-v4's closed form).
fn cone_power_factor(cos_start: f32, cos_end: f32) -> f32 {
    2.0 * PI * ((1.0 - cos_start) + (cos_start - cos_end) / 2.0)
}

impl ContentHash for SpotLight {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let SpotLight {
            position,
            world_to_light,
            axis,
            intensity,
            cos_falloff_start,
            cos_falloff_end,
        } = self;
        (position, world_to_light, axis, intensity).feed(sink);
        (cos_falloff_start, cos_falloff_end).feed(sink);
    }
}
