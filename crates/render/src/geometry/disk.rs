//! Disks and annuli in the object-space plane `z = height`, facing `+z`.

use super::{PrimHit, ShadingGeometry, ShapeSample, SurfaceHit};
use crate::content_hash::{ContentHash, ContentSink};
use crate::error::Error;
use crate::math::sampling::sample_uniform_disk_concentric;
use crate::math::{Bounds3, Frame, Point2, Ray, Transform, Vec3};
use std::f32::consts::PI;

/// pbrt's disk: radius `radius`, optional hole of `inner_radius`, at
/// `z = height` in object space. The normal is `+z` in object space, flipped
/// when `reverse_orientation ^ transform_swaps_handedness` (pbrt's rule), then
/// transformed as a normal. The area is exact under any affine transform.
#[derive(Clone, Debug)]
pub struct Disk {
    object_to_world: Transform,
    world_to_object: Transform,
    height: f32,
    radius: f32,
    inner_radius: f32,
    normal: Vec3,
    area: f32,
}

impl Disk {
    /// A disk; errors unless `0 <= inner_radius < radius` (finite).
    pub fn new(
        object_to_world: Transform,
        height: f32,
        radius: f32,
        inner_radius: f32,
        reverse_orientation: bool,
    ) -> Result<Self, Error> {
        if !(radius.is_finite()
            && height.is_finite()
            && inner_radius >= 0.0
            && inner_radius < radius)
        {
            return Err(Error::InvalidShape(format!(
                "disk needs 0 <= innerradius < radius (got {inner_radius}, {radius})"
            )));
        }
        let flip = reverse_orientation ^ object_to_world.swaps_handedness();
        let n = object_to_world
            .normal(if flip { -Vec3::Z } else { Vec3::Z })
            .normalize();
        // Area scale of the plane z = const under the linear part.
        let s = object_to_world
            .vector(Vec3::X)
            .cross(object_to_world.vector(Vec3::Y))
            .length();
        Ok(Disk {
            world_to_object: object_to_world.inverse(),
            object_to_world,
            height,
            radius,
            inner_radius,
            normal: n,
            area: PI * (radius * radius - inner_radius * inner_radius) * s,
        })
    }
    /// Surface area (world space).
    pub fn area(&self) -> f32 {
        self.area
    }
    /// World-space bounds.
    pub fn bounds(&self) -> Bounds3 {
        let r = self.radius;
        let b = Bounds3::new(Vec3::new(-r, -r, self.height), Vec3::new(r, r, self.height));
        self.object_to_world.bounds(&b)
    }

    /// Intersection with `0 < t < t_max`.
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<PrimHit> {
        let r = self.world_to_object.ray(ray);
        if r.d.z == 0.0 {
            return None;
        }
        let t = (self.height - r.o.z) / r.d.z;
        if !(t > 0.0 && t < t_max) {
            return None;
        }
        let p = r.at(t);
        let d2 = p.x * p.x + p.y * p.y;
        let ok = d2 <= self.radius * self.radius && d2 >= self.inner_radius * self.inner_radius;
        ok.then_some(PrimHit { t, u: 0.0, v: 0.0 })
    }

    /// pbrt's parameterisation: `u = phi / 2π`, `v = (radius - r) / (radius - inner)`.
    fn param(&self, x: f32, y: f32) -> (Point2, Vec3) {
        let mut phi = y.atan2(x);
        if phi < 0.0 {
            phi += 2.0 * PI;
        }
        let r = (x * x + y * y).sqrt();
        let uv = Point2::new(
            phi / (2.0 * PI),
            (self.radius - r) / (self.radius - self.inner_radius),
        );
        (uv, Vec3::new(-2.0 * PI * y, 2.0 * PI * x, 0.0))
    }

    /// Full surface information for a hit found by [`Disk::intersect`].
    pub fn surface_hit(&self, ray: &Ray, h: &PrimHit) -> SurfaceHit {
        let ro = self.world_to_object.ray(ray);
        let mut p = ro.at(h.t);
        p.z = self.height;
        let (uv, dpdu) = self.param(p.x, p.y);
        let mut dpdu = self.object_to_world.vector(dpdu);
        if !(dpdu.length_squared() > 0.0) {
            dpdu = Frame::from_z(self.normal).x;
        }
        SurfaceHit {
            t: h.t,
            p: self.object_to_world.point(p),
            uv,
            bary: [0.0; 3],
            ng: self.normal,
            ns: self.normal,
            dpdu,
        }
    }

    /// The shading geometry of `hit`, a hit on this disk (see
    /// [`super::differentials`]).
    pub fn shading_geometry(&self, hit: &SurfaceHit) -> ShadingGeometry {
        let p = self.world_to_object.point(hit.p);
        let r = (p.x * p.x + p.y * p.y).sqrt();
        let dpdv = if r > 0.0 {
            let s = (self.inner_radius - self.radius) / r;
            self.object_to_world
                .vector(Vec3::new(p.x * s, p.y * s, 0.0))
        } else {
            Vec3::ZERO
        };
        let dpdv = if dpdv.length_squared() > 0.0 {
            dpdv
        } else {
            self.normal.cross(hit.dpdu.normalize())
        };
        ShadingGeometry::flat(hit.ns, hit.dpdu, dpdv)
    }

    /// Samples a point uniformly by area (also on an annulus); `pdf = 1 / area`.
    pub fn sample(&self, u: Point2) -> Option<ShapeSample> {
        let d = sample_uniform_disk_concentric(u);
        let (ri, ro) = (self.inner_radius, self.radius);
        // Radial warp from the unit disk to the annulus keeping uniform density.
        let rr = d.length();
        let scale = if rr > 0.0 {
            (ri * ri + rr * rr * (ro * ro - ri * ri)).sqrt() / rr
        } else {
            0.0
        };
        let (x, y) = if ri > 0.0 {
            (d.x * scale, d.y * scale)
        } else {
            (d.x * ro, d.y * ro)
        };
        Some(ShapeSample {
            p: self.object_to_world.point(Vec3::new(x, y, self.height)),
            n: self.normal,
            uv: self.param(x, y).0,
            pdf: 1.0 / self.area,
        })
    }
}

/// The inverse transform and the area are derived from the fed fields.
impl ContentHash for Disk {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let Disk {
            object_to_world,
            world_to_object: _,
            height,
            radius,
            inner_radius,
            normal,
            area: _,
        } = self;
        object_to_world.feed(sink);
        [height, radius, inner_radius].feed(sink);
        normal.feed(sink);
    }
}
