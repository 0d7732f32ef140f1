//! Fresnel equations (dielectric and conductor), mirror reflection and
//! Snell refraction, in pbrt-v4's conventions.

use crate::math::Vec3;
use crate::spectrum::Colour;

/// Unpolarized Fresnel reflectance of a dielectric interface with relative
/// index `eta` (inside over outside) for `cos_theta_i` measured from the
/// normal on the outside; negative cosines mean the ray arrives from inside.
/// Returns 1 under total internal reflection.
pub fn fr_dielectric(cos_theta_i: f32, eta: f32) -> f32 {
    let mut cos_i = cos_theta_i.clamp(-1.0, 1.0);
    let mut eta = eta;
    if cos_i < 0.0 {
        eta = 1.0 / eta;
        cos_i = -cos_i;
    }
    let sin2_i = 1.0 - cos_i * cos_i;
    let sin2_t = sin2_i / (eta * eta);
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin2_t).max(0.0).sqrt();
    let r_parl = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    0.5 * (r_parl * r_parl + r_perp * r_perp)
}

/// A minimal complex number for the conductor Fresnel equations.
#[derive(Clone, Copy, Debug)]
struct Complex {
    re: f32,
    im: f32,
}

impl Complex {
    fn new(re: f32, im: f32) -> Self {
        Complex { re, im }
    }
    fn add(self, o: Complex) -> Complex {
        Complex::new(self.re + o.re, self.im + o.im)
    }
    fn sub(self, o: Complex) -> Complex {
        Complex::new(self.re - o.re, self.im - o.im)
    }
    fn mul(self, o: Complex) -> Complex {
        Complex::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
        )
    }
    fn div(self, o: Complex) -> Complex {
        let d = o.re * o.re + o.im * o.im;
        Complex::new(
            (self.re * o.re + self.im * o.im) / d,
            (self.im * o.re - self.re * o.im) / d,
        )
    }
    fn norm(self) -> f32 {
        self.re * self.re + self.im * self.im
    }
    /// Principal square root.
    fn sqrt(self) -> Complex {
        let n = self.norm().sqrt();
        if n == 0.0 {
            return Complex::new(0.0, 0.0);
        }
        let t1 = (0.5 * (n + self.re.abs())).sqrt();
        let t2 = 0.5 * self.im / t1;
        if self.re >= 0.0 {
            Complex::new(t1, t2)
        } else {
            Complex::new(t2.abs(), t1.copysign(self.im))
        }
    }
}

/// Fresnel reflectance of a conductor with complex index `eta + i k` for
/// `cos_theta_i` in `[0, 1]` (one channel).
pub fn fr_complex(cos_theta_i: f32, eta: f32, k: f32) -> f32 {
    let cos_i = cos_theta_i.clamp(0.0, 1.0);
    let eta = Complex::new(eta, k);
    let sin2_i = Complex::new(1.0 - cos_i * cos_i, 0.0);
    let sin2_t = sin2_i.div(eta.mul(eta));
    let cos_t = Complex::new(1.0, 0.0).sub(sin2_t).sqrt();
    let ci = Complex::new(cos_i, 0.0);
    let r_parl = eta.mul(ci).sub(cos_t).div(eta.mul(ci).add(cos_t));
    let r_perp = ci.sub(eta.mul(cos_t)).div(ci.add(eta.mul(cos_t)));
    0.5 * (r_parl.norm() + r_perp.norm())
}

/// [`fr_complex`] per lane (RGB channel or wavelength).
pub fn fr_complex_colour<C: Colour>(cos_theta_i: f32, eta: C, k: C) -> C {
    C::from_fn(|i| fr_complex(cos_theta_i, eta.lane(i), k.lane(i)))
}

/// Mirror reflection of `wo` about `n`: `-wo + 2 (wo·n) n`.
#[inline]
pub fn reflect(wo: Vec3, n: Vec3) -> Vec3 {
    -wo + n * (2.0 * wo.dot(n))
}

/// Refracts `wi` through the interface with normal `n` and relative index
/// `eta` (the side `n` points to is outside). Returns the transmitted
/// direction and the relative index actually used (`1/eta` when `wi` is on
/// the inside), or `None` under total internal reflection.
pub fn refract(wi: Vec3, n: Vec3, eta: f32) -> Option<(Vec3, f32)> {
    let mut cos_i = n.dot(wi);
    let (mut eta, mut n) = (eta, n);
    if cos_i < 0.0 {
        eta = 1.0 / eta;
        cos_i = -cos_i;
        n = -n;
    }
    let sin2_i = (1.0 - cos_i * cos_i).max(0.0);
    let sin2_t = sin2_i / (eta * eta);
    if sin2_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).max(0.0).sqrt();
    Some((-wi / eta + n * (cos_i / eta - cos_t), eta))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_incidence_values() {
        for eta in [1.2f32, 1.5, 2.4] {
            let want = ((eta - 1.0) / (eta + 1.0)).powi(2);
            assert!((fr_dielectric(1.0, eta) - want).abs() < 1e-6);
            // From inside at normal incidence: same value.
            assert!((fr_dielectric(-1.0, eta) - want).abs() < 1e-6);
            // A conductor with k = 0 is a dielectric.
            assert!((fr_complex(1.0, eta, 0.0) - want).abs() < 1e-6);
        }
        // Normal incidence on a conductor: ((n-1)^2 + k^2) / ((n+1)^2 + k^2).
        let (n, k) = (0.2f32, 3.0f32);
        let want = ((n - 1.0).powi(2) + k * k) / ((n + 1.0).powi(2) + k * k);
        assert!((fr_complex(1.0, n, k) - want).abs() < 1e-5);
        assert_eq!(fr_complex(0.7, 1.0, 0.0), 0.0);
    }

    #[test]
    fn total_internal_reflection_and_grazing() {
        // Critical angle for eta 1.5 from inside: sin = 1/1.5.
        let cos_c = (1.0f32 - 1.0 / 2.25).sqrt();
        assert_eq!(fr_dielectric(-(cos_c - 1e-3), 1.5), 1.0);
        assert!(fr_dielectric(-(cos_c + 1e-2), 1.5) < 1.0);
        assert!((fr_dielectric(0.0, 1.5) - 1.0).abs() < 1e-6);
        assert!(refract(Vec3::new(0.9, 0.0, -0.4359).normalize(), Vec3::Z, 1.5).is_none());
    }

    #[test]
    fn refraction_obeys_snell() {
        let wi = Vec3::new(0.6, 0.0, 0.8);
        let (wt, etap) = refract(wi, Vec3::Z, 1.5).unwrap();
        assert_eq!(etap, 1.5);
        assert!((wt.length() - 1.0).abs() < 1e-6);
        assert!(wt.z < 0.0);
        // sin_t * eta = sin_i, with the tangent flipped.
        assert!((-wt.x * 1.5 - 0.6).abs() < 1e-6);
        // Reversibility: from the inside, wt refracts back to wi.
        let (back, etap2) = refract(wt, Vec3::Z, 1.5).unwrap();
        assert!((etap2 - 1.0 / 1.5).abs() < 1e-7);
        assert!((back - wi).length() < 1e-5);
        let r = reflect(wi, Vec3::Z);
        assert!((r - Vec3::new(-0.6, 0.0, 0.8)).length() < 1e-7);
    }
}
