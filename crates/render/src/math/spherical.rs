//! Spherical coordinates, local-frame trigonometry, and pbrt-v4's equal-area
//! octahedral square-to-sphere mapping (used by its environment maps).

use super::vector::{Point2, Vec3};
use std::f32::consts::{FRAC_PI_2, FRAC_PI_4, PI};

/// The unit direction with polar angle `theta` (from +z) and azimuth `phi`,
/// given `sin(theta)` and `cos(theta)`.
#[inline]
pub fn spherical_direction(sin_theta: f32, cos_theta: f32, phi: f32) -> Vec3 {
    let s = sin_theta.clamp(-1.0, 1.0);
    Vec3::new(s * phi.cos(), s * phi.sin(), cos_theta.clamp(-1.0, 1.0))
}
/// Polar angle of a unit vector, in `[0, π]`.
#[inline]
pub fn spherical_theta(v: Vec3) -> f32 {
    v.z.clamp(-1.0, 1.0).acos()
}
/// Azimuth of a vector, in `[0, 2π)`.
#[inline]
pub fn spherical_phi(v: Vec3) -> f32 {
    let p = v.y.atan2(v.x);
    if p < 0.0 { p + 2.0 * PI } else { p }
}
/// `cos(theta)` of a local-frame direction.
#[inline]
pub fn cos_theta(w: Vec3) -> f32 {
    w.z
}
/// `cos²(theta)` of a local-frame direction.
#[inline]
pub fn cos2_theta(w: Vec3) -> f32 {
    w.z * w.z
}
/// `sin²(theta)` of a local-frame direction.
#[inline]
pub fn sin2_theta(w: Vec3) -> f32 {
    (1.0 - cos2_theta(w)).max(0.0)
}
/// `sin(theta)` of a local-frame direction.
#[inline]
pub fn sin_theta(w: Vec3) -> f32 {
    sin2_theta(w).sqrt()
}
/// `tan(theta)` of a local-frame direction.
#[inline]
pub fn tan_theta(w: Vec3) -> f32 {
    sin_theta(w) / cos_theta(w)
}
/// `cos(phi)` of a local-frame direction (1 at the pole).
#[inline]
pub fn cos_phi(w: Vec3) -> f32 {
    let s = sin_theta(w);
    if s == 0.0 {
        1.0
    } else {
        (w.x / s).clamp(-1.0, 1.0)
    }
}
/// `sin(phi)` of a local-frame direction (0 at the pole).
#[inline]
pub fn sin_phi(w: Vec3) -> f32 {
    let s = sin_theta(w);
    if s == 0.0 {
        0.0
    } else {
        (w.y / s).clamp(-1.0, 1.0)
    }
}
/// True when `a` and `b` are on the same side of the local `z = 0` plane.
#[inline]
pub fn same_hemisphere(a: Vec3, b: Vec3) -> bool {
    a.z * b.z > 0.0
}

/// Clarberg's equal-area octahedral mapping ("Fast Equal-Area Mapping of the
/// (Hemi)Sphere using SIMD", JGT 2008) from `[0,1]^2` to the unit sphere, in
/// the orientation pbrt-v4 uses for its equal-area environment maps.
pub fn equal_area_square_to_sphere(p: Point2) -> Vec3 {
    let u = 2.0 * p.x - 1.0;
    let v = 2.0 * p.y - 1.0;
    let (up, vp) = (u.abs(), v.abs());
    let signed_distance = 1.0 - (up + vp);
    let d = signed_distance.abs();
    let r = 1.0 - d;
    let phi = if r == 0.0 { 1.0 } else { (vp - up) / r + 1.0 } * FRAC_PI_4;
    let z = (1.0 - r * r).copysign(signed_distance);
    let cos_phi = phi.cos().copysign(u);
    let sin_phi = phi.sin().copysign(v);
    let s = r * (2.0 - r * r).max(0.0).sqrt();
    Vec3::new(cos_phi * s, sin_phi * s, z)
}

/// Inverse of [`equal_area_square_to_sphere`] for a unit direction.
pub fn equal_area_sphere_to_square(d: Vec3) -> Point2 {
    let (x, y, z) = (d.x.abs(), d.y.abs(), d.z.abs());
    let r = (1.0 - z).max(0.0).sqrt();
    let a = x.max(y);
    let b = if a == 0.0 { 0.0 } else { x.min(y) / a };
    let mut phi = b.atan() / FRAC_PI_2;
    if x < y {
        phi = 1.0 - phi;
    }
    let mut v = phi * r;
    let mut u = r - v;
    if d.z < 0.0 {
        std::mem::swap(&mut u, &mut v);
        u = 1.0 - u;
        v = 1.0 - v;
    }
    u = u.copysign(d.x);
    v = v.copysign(d.y);
    Point2::new(0.5 * (u + 1.0), 0.5 * (v + 1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spherical_round_trip() {
        let w = spherical_direction(0.6, 0.8, 2.0);
        assert!((w.length() - 1.0).abs() < 1e-6);
        assert!((spherical_theta(w) - 0.8f32.acos()).abs() < 1e-5);
        assert!((spherical_phi(w) - 2.0).abs() < 1e-5);
        assert!((cos_phi(w) - 2.0f32.cos()).abs() < 1e-5);
        assert!((sin_phi(w) - 2.0f32.sin()).abs() < 1e-5);
        assert!((tan_theta(w) - 0.75).abs() < 1e-5);
    }

    #[test]
    fn equal_area_known_points_and_round_trip() {
        let c = equal_area_square_to_sphere(Point2::new(0.5, 0.5));
        assert!((c - Vec3::Z).length() < 1e-6);
        let corner = equal_area_square_to_sphere(Point2::new(0.0, 0.0));
        assert!((corner + Vec3::Z).length() < 1e-6);
        let mut zsum = 0.0f64;
        let n = 64;
        for i in 0..n {
            for j in 0..n {
                let p = Point2::new((i as f32 + 0.5) / n as f32, (j as f32 + 0.5) / n as f32);
                let w = equal_area_square_to_sphere(p);
                assert!((w.length() - 1.0).abs() < 1e-5);
                let q = equal_area_sphere_to_square(w);
                assert!((q - p).length() < 1e-4, "{p:?} -> {w:?} -> {q:?}");
                zsum += w.z as f64;
            }
        }
        // Equal area: a uniform grid on the square is balanced on the sphere.
        assert!((zsum / (n * n) as f64).abs() < 1e-3);
    }
}
