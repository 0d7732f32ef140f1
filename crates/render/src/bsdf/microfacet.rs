//! The anisotropic Trowbridge-Reitz (GGX) microfacet distribution with
//! Smith masking and visible-normal sampling (Heitz 2018, "Sampling the GGX
//! Distribution of Visible Normals", JCGT 7(4)), following pbrt-v4's
//! `TrowbridgeReitzDistribution`.

use crate::math::Vec3;
use crate::math::spherical::{cos_phi, cos2_theta, sin_phi, sin2_theta};
use std::f32::consts::PI;

/// Below this alpha (in both directions) a surface is treated as perfectly
/// smooth: a delta lobe.
pub const SMOOTH_ALPHA: f32 = 1e-3;

/// pbrt-v4's `RoughnessToAlpha`: `sqrt(roughness)` (used when
/// `remaproughness` is true).
#[inline]
pub fn roughness_to_alpha(roughness: f32) -> f32 {
    roughness.max(0.0).sqrt()
}

/// `tan²θ` of a local direction (infinite at the horizon).
#[inline]
fn tan2_theta_of(w: Vec3) -> f32 {
    sin2_theta(w) / cos2_theta(w)
}

/// An anisotropic GGX distribution of microfacet normals.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrowbridgeReitz {
    /// Roughness along the local x axis.
    pub alpha_x: f32,
    /// Roughness along the local y axis.
    pub alpha_y: f32,
}

impl TrowbridgeReitz {
    /// A distribution with the given alphas (non-finite or negative values
    /// become 0, i.e. smooth). Alphas that are not smooth are kept above
    /// `1e-4` to keep the densities finite.
    pub fn new(alpha_x: f32, alpha_y: f32) -> Self {
        let fix = |a: f32| if a > 0.0 && a.is_finite() { a } else { 0.0 };
        let mut d = TrowbridgeReitz {
            alpha_x: fix(alpha_x),
            alpha_y: fix(alpha_y),
        };
        if !d.effectively_smooth() {
            d.alpha_x = d.alpha_x.max(1e-4);
            d.alpha_y = d.alpha_y.max(1e-4);
        }
        d
    }
    /// True when the surface is a perfect mirror/refractor (delta lobe).
    #[inline]
    pub fn effectively_smooth(&self) -> bool {
        self.alpha_x.max(self.alpha_y) < SMOOTH_ALPHA
    }
    /// The microfacet normal density `D(wm)` (projected-area normalised:
    /// `∫ D(wm) cos θm dωm = 1`).
    pub fn d(&self, wm: Vec3) -> f32 {
        let tan2 = tan2_theta_of(wm);
        if !tan2.is_finite() {
            return 0.0;
        }
        let cos4 = cos2_theta(wm) * cos2_theta(wm);
        if cos4 < 1e-16 {
            return 0.0;
        }
        let e =
            tan2 * ((cos_phi(wm) / self.alpha_x).powi(2) + (sin_phi(wm) / self.alpha_y).powi(2));
        1.0 / (PI * self.alpha_x * self.alpha_y * cos4 * (1.0 + e) * (1.0 + e))
    }
    /// Smith's auxiliary function `Λ(w)`.
    pub fn lambda(&self, w: Vec3) -> f32 {
        let tan2 = tan2_theta_of(w);
        if !tan2.is_finite() {
            return 0.0;
        }
        let alpha2 = (cos_phi(w) * self.alpha_x).powi(2) + (sin_phi(w) * self.alpha_y).powi(2);
        0.5 * ((1.0 + alpha2 * tan2).sqrt() - 1.0)
    }
    /// Masking `G1(w) = 1 / (1 + Λ(w))`.
    #[inline]
    pub fn g1(&self, w: Vec3) -> f32 {
        1.0 / (1.0 + self.lambda(w))
    }
    /// Height-correlated masking-shadowing `G(wo, wi)`.
    #[inline]
    pub fn g(&self, wo: Vec3, wi: Vec3) -> f32 {
        1.0 / (1.0 + self.lambda(wo) + self.lambda(wi))
    }
    /// The distribution of normals visible from `w`:
    /// `D_w(wm) = G1(w) / |cos θ(w)| · D(wm) · |w·wm|`.
    pub fn d_visible(&self, w: Vec3, wm: Vec3) -> f32 {
        let c = w.z.abs();
        if c == 0.0 {
            return 0.0;
        }
        self.g1(w) / c * self.d(wm) * w.abs_dot(wm)
    }
    /// Density of [`TrowbridgeReitz::sample_wm`] (equal to `d_visible`).
    #[inline]
    pub fn pdf(&self, w: Vec3, wm: Vec3) -> f32 {
        self.d_visible(w, wm)
    }
    /// Samples a microfacet normal visible from `w` (either hemisphere of `w`;
    /// the normal is always in the upper hemisphere).
    pub fn sample_wm(&self, w: Vec3, u: [f32; 2]) -> Vec3 {
        // Stretch to the hemisphere configuration.
        let mut wh = Vec3::new(self.alpha_x * w.x, self.alpha_y * w.y, w.z).normalize();
        if wh.z < 0.0 {
            wh = -wh;
        }
        let t1 = if wh.z < 0.99999 {
            Vec3::Z.cross(wh).normalize()
        } else {
            Vec3::X
        };
        let t2 = wh.cross(t1);
        // Uniform polar disk sample, warped to the visible half.
        let r = u[0].sqrt();
        let phi = 2.0 * PI * u[1];
        let (px, mut py) = (r * phi.cos(), r * phi.sin());
        let h = (1.0 - px * px).max(0.0).sqrt();
        let s = 0.5 * (1.0 + wh.z);
        py = (1.0 - s) * h + s * py;
        let pz = (1.0 - px * px - py * py).max(0.0).sqrt();
        let nh = t1 * px + t2 * py + wh * pz;
        Vec3::new(self.alpha_x * nh.x, self.alpha_y * nh.y, nh.z.max(1e-6)).normalize()
    }
    /// pbrt-v4's `Regularize`: widens near-specular lobes (alpha below 0.3
    /// becomes `clamp(2 alpha, 0.1, 0.3)`).
    pub fn regularize(&mut self) {
        let f = |a: f32| {
            if a < 0.3 {
                (2.0 * a).clamp(0.1, 0.3)
            } else {
                a
            }
        };
        self.alpha_x = f(self.alpha_x);
        self.alpha_y = f(self.alpha_y);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Deterministic 2D grid in [0,1)^2.
    fn grid(n: usize) -> impl Iterator<Item = [f32; 2]> {
        (0..n * n).map(move |i| {
            [
                ((i / n) as f32 + 0.5) / n as f32,
                ((i % n) as f32 + 0.5) / n as f32,
            ]
        })
    }

    #[test]
    fn d_is_normalised_over_projected_area() {
        for (ax, ay) in [(0.1f32, 0.1f32), (0.5, 0.5), (0.2, 0.7), (1.0, 1.0)] {
            let d = TrowbridgeReitz::new(ax, ay);
            // Integrate D(wm) cos(theta) over the hemisphere in (cos, phi),
            // with substitution cos = t^2 near the grazing end handled by a fine grid.
            let n = 1000;
            let mut sum = 0.0f64;
            for [a, b] in grid(n) {
                let c = a; // cos theta uniform in [0,1): dω = dcos dphi
                let s = (1.0 - c * c).sqrt();
                let phi = 2.0 * PI * b;
                let wm = Vec3::new(s * phi.cos(), s * phi.sin(), c);
                sum += (d.d(wm) * c) as f64;
            }
            let integral = sum * 2.0 * std::f64::consts::PI / (n * n) as f64;
            assert!((integral - 1.0).abs() < 0.02, "{ax} {ay}: {integral}");
        }
    }

    #[test]
    fn visible_normals_face_the_viewer_and_are_unit() {
        let d = TrowbridgeReitz::new(0.3, 0.6);
        let w = Vec3::new(0.5, -0.3, 0.4).normalize();
        for u in grid(40) {
            let wm = d.sample_wm(w, u);
            assert!((wm.length() - 1.0).abs() < 1e-4);
            assert!(wm.z > 0.0 && wm.dot(w) >= -1e-4, "{wm:?}");
        }
        assert!(TrowbridgeReitz::new(5e-4, 1e-4).effectively_smooth());
        assert!(!TrowbridgeReitz::new(5e-4, 2e-3).effectively_smooth());
        assert_eq!(roughness_to_alpha(0.25), 0.5);
    }
}
