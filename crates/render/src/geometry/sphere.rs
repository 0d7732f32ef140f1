//! Full spheres centred at the object-space origin, placed by a transform.

use super::{PrimHit, ShapeSample, SurfaceHit};
use crate::error::Error;
use crate::math::sampling::sample_uniform_sphere;
use crate::math::{Bounds3, Point2, Ray, Transform, Vec3};
use std::f32::consts::PI;

/// A full sphere of `radius` about the object-space origin.
///
/// Normals follow pbrt: outward in object space, flipped when
/// `reverse_orientation ^ transform_swaps_handedness`, then transformed as
/// normals. Area and area sampling assume the transform is a similarity
/// (rotation, translation, uniform scale); under a non-uniform scale the
/// area is that of the sphere scaled by `|det|^(1/3)`.
#[derive(Clone, Debug)]
pub struct Sphere {
    object_to_world: Transform,
    world_to_object: Transform,
    radius: f32,
    flip: bool,
    area: f32,
}

impl Sphere {
    /// A sphere; errors for a non-positive or non-finite radius.
    pub fn new(
        object_to_world: Transform,
        radius: f32,
        reverse_orientation: bool,
    ) -> Result<Self, Error> {
        if !(radius > 0.0 && radius.is_finite()) {
            return Err(Error::InvalidShape(format!(
                "sphere radius {radius} must be positive"
            )));
        }
        let scale = object_to_world.matrix().det3().abs().cbrt();
        Ok(Sphere {
            world_to_object: object_to_world.inverse(),
            flip: reverse_orientation ^ object_to_world.swaps_handedness(),
            area: 4.0 * PI * radius * radius * scale * scale,
            object_to_world,
            radius,
        })
    }
    /// The radius (object space).
    pub fn radius(&self) -> f32 {
        self.radius
    }
    /// Surface area (world space, see the type's note on scaling).
    pub fn area(&self) -> f32 {
        self.area
    }
    /// World-space bounds.
    pub fn bounds(&self) -> Bounds3 {
        let r = Vec3::splat(self.radius);
        self.object_to_world.bounds(&Bounds3::new(-r, r))
    }

    /// Nearest intersection with `0 < t < t_max`.
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<PrimHit> {
        let r = self.world_to_object.ray(ray);
        let a = r.d.length_squared();
        if !(a > 0.0) {
            return None;
        }
        let b = 2.0 * r.d.dot(r.o);
        let c = r.o.length_squared() - self.radius * self.radius;
        // Stable discriminant (Hearn-Baker form, as in pbrt-v4 and
        // Ray Tracing Gems ch. 7): 4a (r + |v|)(r - |v|), v = o - (b/2a) d.
        let f = b / (2.0 * a);
        let len = (r.o - r.d * f).length();
        let disc = 4.0 * a * (self.radius + len) * (self.radius - len);
        if !(disc >= 0.0) {
            return None;
        }
        let root = disc.sqrt();
        let q = if b < 0.0 {
            -0.5 * (b - root)
        } else {
            -0.5 * (b + root)
        };
        let (mut t0, mut t1) = (q / a, c / q);
        if t0 > t1 {
            std::mem::swap(&mut t0, &mut t1);
        }
        let t = if t0 > 0.0 { t0 } else { t1 };
        (t > 0.0 && t < t_max).then_some(PrimHit { t, u: 0.0, v: 0.0 })
    }

    /// Full surface information for a hit found by [`Sphere::intersect`].
    pub fn surface_hit(&self, ray: &Ray, h: &PrimHit) -> SurfaceHit {
        let ro = self.world_to_object.ray(ray);
        let mut p = ro.at(h.t);
        p = p * (self.radius / p.length());
        let (uv, dpdu) = self.param(p);
        let mut n = p / self.radius;
        if self.flip {
            n = -n;
        }
        let ng = self.object_to_world.normal(n).normalize();
        let mut dpdu_w = self.object_to_world.vector(dpdu);
        if !(dpdu_w.length_squared() > 0.0) {
            dpdu_w = crate::math::Frame::from_z(ng).x;
        }
        SurfaceHit {
            t: h.t,
            p: self.object_to_world.point(p),
            uv,
            bary: [0.0; 3],
            ng,
            ns: ng,
            dpdu: dpdu_w,
        }
    }

    /// pbrt's sphere parameterisation: `u = phi / 2π`, `v = 1 - theta / π`.
    fn param(&self, p: Vec3) -> (Point2, Vec3) {
        let mut phi = p.y.atan2(p.x);
        if phi < 0.0 {
            phi += 2.0 * PI;
        }
        let theta = (p.z / self.radius).clamp(-1.0, 1.0).acos();
        let uv = Point2::new(phi / (2.0 * PI), 1.0 - theta / PI);
        (uv, Vec3::new(-2.0 * PI * p.y, 2.0 * PI * p.x, 0.0))
    }

    /// Samples a point uniformly by area; `pdf = 1 / area`.
    pub fn sample(&self, u: Point2) -> Option<ShapeSample> {
        let p_obj = sample_uniform_sphere(u) * self.radius;
        let mut n = p_obj / self.radius;
        if self.flip {
            n = -n;
        }
        Some(ShapeSample {
            p: self.object_to_world.point(p_obj),
            n: self.object_to_world.normal(n).normalize(),
            uv: self.param(p_obj).0,
            pdf: 1.0 / self.area,
        })
    }
}
