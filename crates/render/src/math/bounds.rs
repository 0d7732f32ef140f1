//! Axis-aligned bounding boxes.

use super::ray::Ray;
use super::vector::{Point3, Vec3};

/// An axis-aligned box; the empty box has `min > max` (see [`Bounds3::EMPTY`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds3 {
    /// Lower corner.
    pub min: Point3,
    /// Upper corner.
    pub max: Point3,
}

impl Default for Bounds3 {
    fn default() -> Self {
        Self::EMPTY
    }
}

impl Bounds3 {
    /// The empty box (neutral element of [`Bounds3::union`]).
    pub const EMPTY: Bounds3 = Bounds3 {
        min: Vec3::splat(f32::INFINITY),
        max: Vec3::splat(f32::NEG_INFINITY),
    };

    /// The box of two corner points (in any order).
    pub fn new(a: Point3, b: Point3) -> Self {
        Bounds3 {
            min: a.min(b),
            max: a.max(b),
        }
    }
    /// The degenerate box holding one point.
    pub fn from_point(p: Point3) -> Self {
        Bounds3 { min: p, max: p }
    }
    /// The box of a set of points (empty for no points).
    pub fn from_points(points: impl IntoIterator<Item = Point3>) -> Self {
        points
            .into_iter()
            .fold(Self::EMPTY, |b, p| b.union_point(p))
    }
    /// True when the box holds no point.
    pub fn is_empty(&self) -> bool {
        self.min.x > self.max.x || self.min.y > self.max.y || self.min.z > self.max.z
    }
    /// The smallest box holding both.
    #[inline]
    pub fn union(&self, o: &Bounds3) -> Bounds3 {
        Bounds3 {
            min: self.min.min(o.min),
            max: self.max.max(o.max),
        }
    }
    /// The smallest box holding `self` and `p`.
    #[inline]
    pub fn union_point(&self, p: Point3) -> Bounds3 {
        Bounds3 {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }
    /// `max - min`.
    #[inline]
    pub fn diagonal(&self) -> Vec3 {
        self.max - self.min
    }
    /// The box centre.
    #[inline]
    pub fn centroid(&self) -> Point3 {
        (self.min + self.max) * 0.5
    }
    /// Surface area (0 for an empty box).
    #[inline]
    pub fn surface_area(&self) -> f32 {
        if self.is_empty() {
            return 0.0;
        }
        let d = self.diagonal();
        2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
    }
    /// Index of the longest axis.
    pub fn max_extent(&self) -> usize {
        self.diagonal().max_dimension()
    }
    /// Position of `p` relative to the corners: 0 at `min`, 1 at `max` per axis
    /// (0 along an axis of zero extent).
    pub fn offset(&self, p: Point3) -> Vec3 {
        let d = self.diagonal();
        let f = |o: f32, e: f32| if e > 0.0 { o / e } else { 0.0 };
        let o = p - self.min;
        Vec3::new(f(o.x, d.x), f(o.y, d.y), f(o.z, d.z))
    }
    /// True when `p` is inside or on the boundary.
    pub fn contains(&self, p: Point3) -> bool {
        p.x >= self.min.x
            && p.x <= self.max.x
            && p.y >= self.min.y
            && p.y <= self.max.y
            && p.z >= self.min.z
            && p.z <= self.max.z
    }
    /// Centre and radius of a sphere holding the box.
    pub fn bounding_sphere(&self) -> (Point3, f32) {
        let c = self.centroid();
        (
            c,
            if self.is_empty() {
                0.0
            } else {
                c.distance(self.max)
            },
        )
    }
    /// Slab test: the parametric interval `[t0, t1]` of the ray inside the box,
    /// clipped to `[0, t_max]`, or `None`. A zero direction component makes the
    /// slab all-or-nothing; NaN from `0 * inf` on a slab plane counts as inside.
    pub fn intersect_p(&self, ray: &Ray, t_max: f32) -> Option<(f32, f32)> {
        let mut t0 = 0.0f32;
        let mut t1 = t_max;
        for a in 0..3 {
            let inv = 1.0 / ray.d[a];
            let mut near = (self.min[a] - ray.o[a]) * inv;
            let mut far = (self.max[a] - ray.o[a]) * inv;
            if inv < 0.0 || (inv == 0.0 && inv.is_sign_negative()) {
                std::mem::swap(&mut near, &mut far);
            }
            far *= 1.0 + 2.0 * super::gamma(3);
            if near > t0 {
                t0 = near;
            }
            if far < t1 {
                t1 = far;
            }
            if t0 > t1 {
                return None;
            }
        }
        Some((t0, t1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn union_area_and_slab() {
        let b = Bounds3::new(Vec3::new(1.0, 1.0, 1.0), Vec3::ZERO);
        assert_eq!(b.surface_area(), 6.0);
        assert_eq!(Bounds3::EMPTY.union(&b), b);
        assert_eq!(Bounds3::EMPTY.surface_area(), 0.0);
        let r = Ray::new(Vec3::new(0.5, 0.5, -1.0), Vec3::Z);
        let (t0, t1) = b.intersect_p(&r, f32::INFINITY).unwrap();
        assert!((t0 - 1.0).abs() < 1e-6 && (t1 - 2.0).abs() < 1e-5);
        // Ray along a face plane with zero direction components: inside.
        let r = Ray::new(Vec3::new(0.0, 0.5, -1.0), Vec3::Z);
        assert!(b.intersect_p(&r, f32::INFINITY).is_some());
        // Parallel and outside.
        let r = Ray::new(Vec3::new(2.0, 0.5, -1.0), Vec3::Z);
        assert!(b.intersect_p(&r, f32::INFINITY).is_none());
        // Too short.
        let r = Ray::new(Vec3::new(0.5, 0.5, -1.0), Vec3::Z);
        assert!(b.intersect_p(&r, 0.5).is_none());
    }
}
