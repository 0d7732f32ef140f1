//! Rays, and the robust origin offset used to spawn rays from a surface.

use super::vector::{Normal3, Point3, Vec3};

/// A ray `o + t d` (the direction need not be normalised).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Origin.
    pub o: Point3,
    /// Direction.
    pub d: Vec3,
}

impl Ray {
    /// Builds a ray.
    #[inline]
    pub const fn new(o: Point3, d: Vec3) -> Self {
        Ray { o, d }
    }
    /// The point at parameter `t`.
    #[inline]
    pub fn at(&self, t: f32) -> Point3 {
        self.o + self.d * t
    }
}

/// Moves a surface point `p` off the surface along the geometric normal `ng`,
/// to the side `w` points to, so that a ray spawned there does not hit the same
/// surface again.
///
/// This is the integer-ULP offset of Wächter & Binder, "A Fast and Robust
/// Method for Avoiding Self-Intersection" (Ray Tracing Gems, ch. 6, 2019):
/// the offset scales with the magnitude of `p`, and near the origin a small
/// absolute offset is used instead. `ng` should be unit length.
pub fn offset_ray_origin(p: Point3, ng: Normal3, w: Vec3) -> Point3 {
    // Constants from the chapter: 1/32 switch point, 1/65536 float scale,
    // 256 integer scale.
    const ORIGIN: f32 = 1.0 / 32.0;
    const FLOAT_SCALE: f32 = 1.0 / 65536.0;
    const INT_SCALE: f32 = 256.0;
    let n = if ng.dot(w) < 0.0 { -ng } else { ng };
    let off = |pc: f32, nc: f32| -> f32 {
        let oi = (INT_SCALE * nc) as i32;
        let bits = pc.to_bits() as i32;
        let moved = f32::from_bits((bits + if pc < 0.0 { -oi } else { oi }) as u32);
        if pc.abs() < ORIGIN {
            pc + FLOAT_SCALE * nc
        } else {
            moved
        }
    };
    Vec3::new(off(p.x, n.x), off(p.y, n.y), off(p.z, n.z))
}

/// A ray from surface point `p` (geometric normal `ng`) in direction `d`,
/// with its origin offset by [`offset_ray_origin`].
pub fn spawn_ray(p: Point3, ng: Normal3, d: Vec3) -> Ray {
    Ray::new(offset_ray_origin(p, ng, d), d)
}

/// A ray from surface point `p` towards point `target`, with the direction
/// scaled so that `t = 1` reaches `target` (use `t_max` slightly below 1 for
/// shadow rays, e.g. [`SHADOW_EPSILON`] below).
pub fn spawn_ray_to(p: Point3, ng: Normal3, target: Point3) -> Ray {
    let o = offset_ray_origin(p, ng, target - p);
    Ray::new(o, target - o)
}

/// `1 - SHADOW_EPSILON` is the usual `t_max` for a shadow ray built with
/// [`spawn_ray_to`], so that the target surface itself is not hit.
pub const SHADOW_EPSILON: f32 = 1e-4;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offset_moves_to_the_side_of_w() {
        for &p in &[Vec3::new(0.0, 0.0, 0.0), Vec3::new(100.0, -3.0, 1e4)] {
            let n = Vec3::Z;
            let up = offset_ray_origin(p, n, Vec3::new(0.3, 0.0, 1.0));
            let down = offset_ray_origin(p, n, Vec3::new(0.3, 0.0, -1.0));
            assert!(up.z > p.z && down.z < p.z, "{p:?} {up:?} {down:?}");
            assert_eq!(up.x, p.x);
        }
    }

    #[test]
    fn ray_at() {
        let r = Ray::new(Vec3::new(1.0, 2.0, 3.0), Vec3::new(0.0, 0.0, -2.0));
        assert_eq!(r.at(1.5), Vec3::new(1.0, 2.0, 0.0));
    }
}
