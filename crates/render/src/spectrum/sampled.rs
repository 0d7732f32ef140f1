//! Hero-wavelength sampling as pbrt-v4: [`SampledWavelengths`] holds
//! [`N_WAVELENGTHS`] = 4 wavelengths per camera sample and their densities,
//! and [`SampledSpectrum`] a value at each.
//!
//! **Visible-range importance sampling.** One uniform number `u` gives the
//! hero wavelength and three more at `u + i/4` (mod 1), each mapped by the
//! inverse CDF of `p(λ) = 0.0039398042 / cosh²(0.0072 (λ − 538))` on
//! 360–830 nm: `λ = 538 − 138.888889 atanh(0.85691062 − 1.82750197 u)`
//! (pbrt-v4's `SampleVisibleWavelengths` and `VisibleWavelengthsPDF`,
//! *Physically Based Rendering*, 4th ed., §5.4.2; the fitted constants are
//! the book's). The density follows the eye's sensitivity, so the sensor's
//! `x̄ L / p` varies little across samples.
//!
//! The four lanes are independent: a BSDF without dispersion scatters all
//! of them with the same direction. (Dispersion, which pbrt-v4 handles by
//! terminating the secondary wavelengths, is not modelled: every index of
//! refraction here is one number.)

use lowdisc_colour::{LAMBDA_MAX, LAMBDA_MIN};

/// Wavelengths carried by one camera sample.
pub const N_WAVELENGTHS: usize = 4;

/// A spectrum's values at the [`N_WAVELENGTHS`] wavelengths of a sample.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SampledSpectrum(pub [f32; N_WAVELENGTHS]);

/// Lane-wise arithmetic for a `[f32; N]` newtype (`+ - * /` with itself and
/// with `f32`, and their assignments).
macro_rules! impl_lanes {
    ($t:ident, $n:expr) => {
        impl_lanes!(@op $t, Add, add, AddAssign, add_assign, +);
        impl_lanes!(@op $t, Sub, sub, SubAssign, sub_assign, -);
        impl_lanes!(@op $t, Mul, mul, MulAssign, mul_assign, *);
        impl_lanes!(@op $t, Div, div, DivAssign, div_assign, /);
    };
    (@op $t:ident, $tr:ident, $f:ident, $tra:ident, $fa:ident, $op:tt) => {
        impl std::ops::$tr for $t {
            type Output = $t;
            #[inline]
            fn $f(self, o: $t) -> $t {
                $t(std::array::from_fn(|i| self.0[i] $op o.0[i]))
            }
        }
        impl std::ops::$tr<f32> for $t {
            type Output = $t;
            #[inline]
            fn $f(self, s: f32) -> $t {
                $t(self.0.map(|v| v $op s))
            }
        }
        impl std::ops::$tra for $t {
            #[inline]
            fn $fa(&mut self, o: $t) {
                *self = *self $op o;
            }
        }
        impl std::ops::$tra<f32> for $t {
            #[inline]
            fn $fa(&mut self, s: f32) {
                *self = *self $op s;
            }
        }
    };
}

impl_lanes!(SampledSpectrum, 4);

/// The wavelengths (nm) of one camera sample and their sampling densities.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampledWavelengths {
    /// Wavelengths in nm.
    pub lambda: [f32; N_WAVELENGTHS],
    /// Density (per nm) of each wavelength.
    pub pdf: [f32; N_WAVELENGTHS],
}

/// pbrt-v4's visible-wavelength density at `lambda` nm (zero outside 360–830).
pub fn visible_wavelengths_pdf(lambda: f32) -> f32 {
    if !(LAMBDA_MIN..=LAMBDA_MAX).contains(&lambda) {
        return 0.0;
    }
    let c = (0.0072 * (lambda - 538.0)).cosh();
    0.003_939_804 / (c * c)
}

/// The inverse CDF of [`visible_wavelengths_pdf`] at `u` in `[0, 1)`.
pub fn sample_visible_wavelength(u: f32) -> f32 {
    538.0 - 138.888_89 * (0.856_910_6 - 1.827_502 * u).atanh()
}

impl SampledWavelengths {
    /// The four wavelengths of sample `u` in `[0, 1)` (see the module docs).
    pub fn sample_visible(u: f32) -> SampledWavelengths {
        let mut lambda = [0.0; N_WAVELENGTHS];
        let mut pdf = [0.0; N_WAVELENGTHS];
        for i in 0..N_WAVELENGTHS {
            let mut up = u + i as f32 / N_WAVELENGTHS as f32;
            if up > 1.0 {
                up -= 1.0;
            }
            lambda[i] = sample_visible_wavelength(up);
            pdf[i] = visible_wavelengths_pdf(lambda[i]);
        }
        SampledWavelengths { lambda, pdf }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn visible_density_integrates_to_one_and_its_sampler_inverts_its_cdf() {
        let n = 47_000;
        let h = (LAMBDA_MAX - LAMBDA_MIN) / n as f32;
        let total: f64 = (0..n)
            .map(|i| f64::from(visible_wavelengths_pdf(LAMBDA_MIN + (i as f32 + 0.5) * h) * h))
            .sum();
        assert!((total - 1.0).abs() < 1e-4, "{total}");
        assert!((sample_visible_wavelength(0.0) - LAMBDA_MIN).abs() < 0.1);
        assert!((sample_visible_wavelength(1.0) - LAMBDA_MAX).abs() < 0.1);
        // The CDF at the sample of u is u.
        for u in [0.1f32, 0.37, 0.5, 0.83] {
            let l = sample_visible_wavelength(u);
            let m = 20_000;
            let step = (l - LAMBDA_MIN) / m as f32;
            let cdf: f64 = (0..m)
                .map(|i| {
                    f64::from(visible_wavelengths_pdf(LAMBDA_MIN + (i as f32 + 0.5) * step) * step)
                })
                .sum();
            assert!((cdf - f64::from(u)).abs() < 1e-3, "{u}: {cdf}");
        }
    }

    #[test]
    fn four_wavelengths_are_stratified_and_carry_their_densities() {
        let w = SampledWavelengths::sample_visible(0.3);
        let direct =
            [0.3f32, 0.3 + 0.25, 0.3 + 0.5, 0.3 + 0.75 - 1.0].map(sample_visible_wavelength);
        assert_eq!(w.lambda, direct);
        for i in 0..N_WAVELENGTHS {
            assert_eq!(w.pdf[i], visible_wavelengths_pdf(w.lambda[i]));
            assert!(w.pdf[i] > 0.0);
        }
    }
}
