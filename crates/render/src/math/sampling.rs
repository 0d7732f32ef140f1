//! The sample warps the shapes need for area sampling (more live with the
//! integrator): uniform triangle, concentric disk, uniform sphere.

use super::vector::{Point2, Vec3};
use std::f32::consts::{FRAC_PI_4, PI};

/// Uniform barycentrics `(b0, b1, b2)` on a triangle from `u` in `[0,1)^2`
/// (the square-root warp: `b0 = 1 - sqrt(u0)`, `b1 = u1 sqrt(u0)`).
#[inline]
pub fn sample_uniform_triangle(u: Point2) -> [f32; 3] {
    let s = u.x.sqrt();
    let b0 = 1.0 - s;
    let b1 = u.y * s;
    [b0, b1, 1.0 - b0 - b1]
}

/// Shirley-Chiu concentric map of `[0,1)^2` onto the unit disk (area-preserving).
#[inline]
pub fn sample_uniform_disk_concentric(u: Point2) -> Point2 {
    let ox = 2.0 * u.x - 1.0;
    let oy = 2.0 * u.y - 1.0;
    if ox == 0.0 && oy == 0.0 {
        return Point2::new(0.0, 0.0);
    }
    let (r, theta) = if ox.abs() > oy.abs() {
        (ox, FRAC_PI_4 * (oy / ox))
    } else {
        (oy, 2.0 * FRAC_PI_4 - FRAC_PI_4 * (ox / oy))
    };
    Point2::new(r * theta.cos(), r * theta.sin())
}

/// A uniformly distributed unit vector (pdf `1 / 4π` per steradian).
#[inline]
pub fn sample_uniform_sphere(u: Point2) -> Vec3 {
    let z = 1.0 - 2.0 * u.x;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = 2.0 * PI * u.y;
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn warps_stay_in_their_domains() {
        for i in 0..32 {
            for j in 0..32 {
                let u = Point2::new(i as f32 / 32.0, j as f32 / 32.0);
                let b = sample_uniform_triangle(u);
                assert!(b.iter().all(|&x| (-1e-6..=1.0 + 1e-6).contains(&x)));
                assert!((b.iter().sum::<f32>() - 1.0).abs() < 1e-6);
                assert!(sample_uniform_disk_concentric(u).length() <= 1.0 + 1e-6);
                assert!((sample_uniform_sphere(u).length() - 1.0).abs() < 1e-5);
            }
        }
    }
}
