//! Full spheres centred at the object-space origin, placed by a transform;
//! sampled uniformly by area, or (seen from outside) uniformly over the cone
//! of directions the sphere subtends, as pbrt-v4's `Sphere::Sample(ctx, u)`.

use super::{PrimHit, ShadingGeometry, ShapeSample, SurfaceHit};
use crate::content_hash::{ContentHash, ContentSink};
use crate::error::Error;
use crate::math::sampling::sample_uniform_sphere;
use crate::math::{Bounds3, Frame, Point2, Point3, Ray, Transform, Vec3};
use std::f32::consts::PI;

fn sqr(x: f32) -> f32 {
    x * x
}

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
    /// World-space centre and radius when the transform is a similarity
    /// (solid-angle sampling needs a true sphere).
    world: Option<(Point3, f32)>,
}

/// Relative tolerance on the transform's column lengths and angles for
/// treating it as a similarity.
const SIMILARITY_TOLERANCE: f32 = 1e-4;

/// The world-space centre and radius of a sphere of `radius` under `t`, when
/// `t`'s linear part is a rotation times a uniform scale.
fn similarity_sphere(t: &Transform, radius: f32) -> Option<(Point3, f32)> {
    let m = &t.matrix().m;
    let col = |j: usize| Vec3::new(m[0][j], m[1][j], m[2][j]);
    let (a, b, c) = (col(0), col(1), col(2));
    let l2 = a.length_squared();
    let tol = SIMILARITY_TOLERANCE * l2;
    let similar = l2 > 0.0
        && (b.length_squared() - l2).abs() <= tol
        && (c.length_squared() - l2).abs() <= tol
        && a.dot(b).abs() <= tol
        && a.dot(c).abs() <= tol
        && b.dot(c).abs() <= tol
        && m[3] == [0.0, 0.0, 0.0, 1.0];
    similar.then(|| (t.point(Point3::ZERO), radius * l2.sqrt()))
}

/// How far outside the sphere (relative to the size of its coordinates) a
/// point must be for solid-angle sampling. A point on the surface (a path
/// vertex on the light itself, up to rounding) sees the inside of the sphere,
/// which the outside cone does not cover, so it must get area sampling;
/// points within the margin get it too (unbiased, only noisier).
const OUTSIDE_MARGIN: f32 = 1e-4;

/// The cone of directions subtending a sphere seen from outside it.
struct Cone {
    /// Unit vector from the centre towards the reference point.
    axis: Vec3,
    /// `sin² θmax = r² / d²`.
    sin2_max: f32,
    /// `1 - cos θmax`, computed as `sin² θmax / (1 + cos θmax)` (no
    /// cancellation for small, distant spheres).
    one_minus_cos_max: f32,
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
            world: similarity_sphere(&object_to_world, radius),
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

    /// The shading geometry of `hit`, a hit on this sphere (see
    /// [`super::differentials`]).
    pub fn shading_geometry(&self, hit: &SurfaceHit) -> ShadingGeometry {
        let p = self.world_to_object.point(hit.p);
        let z_radius = (p.x * p.x + p.y * p.y).sqrt();
        let (cos_phi, sin_phi) = if z_radius > 0.0 {
            (p.x / z_radius, p.y / z_radius)
        } else {
            (1.0, 0.0)
        };
        let sin_theta = (1.0 - sqr(p.z / self.radius)).max(0.0).sqrt();
        // v = 1 - theta / π, so ∂θ/∂v = -π.
        let dpdv = Vec3::new(p.z * cos_phi, p.z * sin_phi, -self.radius * sin_theta) * -PI;
        let dpdu = self.param(p).1;
        let dpdv_w = self.object_to_world.vector(dpdv);
        ShadingGeometry {
            n: hit.ns,
            dpdu: hit.dpdu,
            dpdv: if dpdv_w.length_squared() > 0.0 {
                dpdv_w
            } else {
                hit.ns.cross(hit.dpdu.normalize())
            },
            dndu: self.object_to_world.normal(dpdu / self.radius),
            dndv: self.object_to_world.normal(dpdv / self.radius),
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

    /// The cone seen from `p_ref`, or `None` inside, on or very near the
    /// sphere (see [`OUTSIDE_MARGIN`]) or under a transform that is not a
    /// similarity.
    fn cone(&self, p_ref: Point3) -> Option<(Cone, Point3, f32)> {
        let (c, r) = self.world?;
        let d = p_ref - c;
        let d2 = d.length_squared();
        let scale = c.x.abs().max(c.y.abs()).max(c.z.abs()) + r;
        let r_out = r + OUTSIDE_MARGIN * scale;
        if !(d2 > r_out * r_out && d2.is_finite()) {
            return None;
        }
        let sin2_max = r * r / d2;
        let cos_max = (1.0 - sin2_max).max(0.0).sqrt();
        let cone = Cone {
            axis: d / d2.sqrt(),
            sin2_max,
            one_minus_cos_max: sin2_max / (1.0 + cos_max),
        };
        Some((cone, c, r))
    }

    /// The solid-angle density, at `p_ref`, of
    /// [`Sphere::sample_solid_angle`]: `1 / (2π (1 - cos θmax))` when
    /// `p_ref` is outside the sphere; `None` where area sampling applies
    /// (inside, or under a non-similarity transform).
    pub fn pdf_solid_angle(&self, p_ref: Point3) -> Option<f32> {
        let (cone, _, _) = self.cone(p_ref)?;
        Some(1.0 / (2.0 * PI * cone.one_minus_cos_max))
    }

    /// A point on the part of the sphere visible from `p_ref`, its direction
    /// uniform over the cone the sphere subtends; `pdf` is the solid-angle
    /// density ([`Sphere::pdf_solid_angle`]). `None` where area sampling
    /// applies. The cone angle `θ` has `1 - cos θ = u0 (1 - cos θmax)`, the
    /// azimuth is `2π u1`, and the point is the nearer intersection of that
    /// direction with the sphere, found through the angle `α` at the centre:
    /// by the law of sines `α = asin(sin θ / sin θmax) - θ`.
    pub fn sample_solid_angle(&self, p_ref: Point3, u: Point2) -> Option<ShapeSample> {
        let (cone, c, r) = self.cone(p_ref)?;
        let t = u.x * cone.one_minus_cos_max;
        let sin_theta = (t * (2.0 - t)).max(0.0).sqrt();
        let ratio = (sin_theta / cone.sin2_max.sqrt()).min(1.0);
        let alpha = (ratio.asin() - sin_theta.min(1.0).asin()).max(0.0);
        let (sin_a, cos_a) = alpha.sin_cos();
        let (sin_p, cos_p) = (2.0 * PI * u.y).sin_cos();
        let frame = Frame::from_z(cone.axis);
        let n_out = frame.from_local(Vec3::new(sin_a * cos_p, sin_a * sin_p, cos_a));
        let p = c + n_out * r;
        let mut p_obj = self.world_to_object.point(p);
        let len = p_obj.length();
        if len > 0.0 {
            p_obj *= self.radius / len;
        }
        Some(ShapeSample {
            p,
            n: if self.flip { -n_out } else { n_out },
            uv: self.param(p_obj).0,
            pdf: 1.0 / (2.0 * PI * cone.one_minus_cos_max),
        })
    }
}

/// The inverse transform, the area and the world-space sphere are derived
/// from the fed fields.
impl ContentHash for Sphere {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let Sphere {
            object_to_world,
            world_to_object: _,
            radius,
            flip,
            area: _,
            world: _,
        } = self;
        object_to_world.feed(sink);
        radius.feed(sink);
        flip.feed(sink);
    }
}
