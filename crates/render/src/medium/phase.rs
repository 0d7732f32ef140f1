//! The Henyey-Greenstein phase function, in pbrt-v4's convention: both
//! directions point away from the scattering point, so with `wo` towards
//! where the light goes (the reverse of the ray) and `wi` where it comes
//! from, `cos θ = wo · wi`, and `g > 0` (forward scattering) favours
//! `wi ≈ -wo`.

use crate::math::{Frame, Vec3};
use std::f32::consts::PI;

/// The Henyey-Greenstein density for `cos θ = wo · wi` and asymmetry `g`:
/// `(1 - g²) / (4π (1 + g² + 2 g cos θ)^{3/2})` (per steradian; it
/// integrates to 1 over the sphere).
///
/// ```
/// use lowdisc_render::medium::phase::henyey_greenstein;
///
/// // g = 0 is isotropic: 1 / (4π) everywhere.
/// let iso = henyey_greenstein(0.3, 0.0);
/// assert!((iso - 1.0 / (4.0 * std::f32::consts::PI)).abs() < 1e-7);
/// // Forward scattering favours wi = -wo (cos θ = -1).
/// assert!(henyey_greenstein(-1.0, 0.8) > henyey_greenstein(1.0, 0.8));
/// ```
#[inline]
pub fn henyey_greenstein(cos_theta: f32, g: f32) -> f32 {
    let denom = 1.0 + g * g + 2.0 * g * cos_theta;
    (1.0 - g * g) / (4.0 * PI * denom * denom.max(0.0).sqrt())
}

/// A direction `wi` drawn from the Henyey-Greenstein density around `wo`
/// with `u` in `[0, 1)²`, and its density (the phase function's value, so
/// the sample's weight `p / pdf` is 1). The cosine between the propagation
/// direction `-wo` and `wi` inverts the distribution's CDF:
/// `μ = (1 + g² - ((1 - g²) / (1 - g + 2 g u₀))²) / (2 g)` (`1 - 2 u₀` for
/// `|g| < 10⁻³`); the azimuth is `2π u₁`.
///
/// ```
/// use lowdisc_render::math::Vec3;
/// use lowdisc_render::medium::phase::{henyey_greenstein, sample_henyey_greenstein};
///
/// let wo = Vec3::new(0.0, 0.0, 1.0);
/// let (wi, pdf) = sample_henyey_greenstein(wo, 0.7, [0.4, 0.9]);
/// assert!((wi.length() - 1.0).abs() < 1e-5);
/// assert!((pdf - henyey_greenstein(wo.dot(wi), 0.7)).abs() < 1e-4 * pdf);
/// ```
pub fn sample_henyey_greenstein(wo: Vec3, g: f32, u: [f32; 2]) -> (Vec3, f32) {
    let mu = if g.abs() < 1e-3 {
        1.0 - 2.0 * u[0]
    } else {
        let s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u[0]);
        (1.0 + g * g - s * s) / (2.0 * g)
    }
    .clamp(-1.0, 1.0);
    let sin = (1.0 - mu * mu).max(0.0).sqrt();
    let phi = 2.0 * PI * u[1];
    let frame = Frame::from_z(-wo);
    let wi = frame.from_local(Vec3::new(sin * phi.cos(), sin * phi.sin(), mu));
    (wi, henyey_greenstein(-mu, g))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The density integrates to 1 over the sphere (midpoint rule in cos θ).
    #[test]
    fn henyey_greenstein_is_normalised() {
        for g in [-0.9, -0.3, 0.0, 0.5, 0.95] {
            let n = 200_000;
            let sum: f64 = (0..n)
                .map(|i| {
                    let c = -1.0 + 2.0 * (i as f64 + 0.5) / n as f64;
                    f64::from(henyey_greenstein(c as f32, g)) * 2.0 / n as f64
                })
                .sum::<f64>()
                * 2.0
                * std::f64::consts::PI;
            assert!((sum - 1.0).abs() < 2e-3, "g {g}: {sum}");
        }
    }

    /// Sampled directions have the distribution's mean cosine `g` between
    /// the propagation direction and `wi`.
    #[test]
    fn samples_have_mean_cosine_g() {
        let wo = Vec3::new(0.6, 0.0, 0.8);
        for g in [-0.6, 0.0, 0.4, 0.9] {
            let n = 4096;
            let mean: f32 = (0..n)
                .map(|i| {
                    let u = [(i as f32 + 0.5) / n as f32, 0.37];
                    let (wi, _) = sample_henyey_greenstein(wo, g, u);
                    (-wo).dot(wi)
                })
                .sum::<f32>()
                / n as f32;
            assert!((mean - g).abs() < 5e-3, "g {g}: mean cosine {mean}");
        }
    }
}
