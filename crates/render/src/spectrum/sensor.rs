//! The film's sensor in spectral mode, pbrt-v4's `rgb` film with its
//! default `"cie1931"` sensor: a sample's four radiance values become XYZ,
//! `X = (1/4) Σ x̄(λ_i) L_i / p(λ_i)` (likewise Y, Z; pbrt-v4's
//! `PixelSensor::ToSensorRGB`), which the film accumulates (clamped by
//! `maxcomponentvalue` there, as pbrt-v4 clamps sensor values), and the
//! pixel's XYZ becomes linear sRGB by [`output_from_sensor`]:
//!
//! * `whitebalance` 0 (the default): `sRGB ← XYZ` only, no adaptation;
//! * `whitebalance` `T` > 0: first the von Kries (Bradford) adaptation from
//!   the white of the CIE daylight illuminant `D(T)` to sRGB's D65 white
//!   (pbrt-v4's `PixelSensor` for `cie1931`).
//!
//! RGB mode accumulates linear sRGB; with `whitebalance` `T` > 0 its pixels
//! are taken through XYZ and the same adaptation (`sRGB ← WB ← XYZ ← sRGB`),
//! so that a balanced render is the unbalanced one times that matrix, as in
//! pbrt-v4. [`output_matrix`] is the one place that chooses the matrix.
//!
//! The matching functions are the CIE 1931 2° tables (not an analytic fit).

use super::Rgb;
use super::sampled::{N_WAVELENGTHS, SampledSpectrum, SampledWavelengths};
use lowdisc_colour::cie::{chromaticity, daylight, spectrum_to_xyz, xyz_bar};
use lowdisc_colour::matrix::white_balance;
use lowdisc_colour::srgb;

/// The sensor's XYZ of one sample (returned in an [`Rgb`]'s three fields:
/// `r` = X, `g` = Y, `b` = Z). Wavelengths of zero density add nothing.
#[inline]
pub fn sample_xyz(l: SampledSpectrum, w: &SampledWavelengths) -> Rgb {
    let mut xyz = [0.0f32; 3];
    for i in 0..N_WAVELENGTHS {
        if w.pdf[i] == 0.0 {
            continue;
        }
        let v = l.0[i] / w.pdf[i];
        let bar = xyz_bar(w.lambda[i]);
        for c in 0..3 {
            xyz[c] += bar[c] * v;
        }
    }
    Rgb::from_array(xyz) * (1.0 / N_WAVELENGTHS as f32)
}

/// The matrix from the sensor's XYZ to the output's linear sRGB, with white
/// balance for `white_balance_kelvin` > 0 (see the module docs).
pub fn output_from_sensor(white_balance_kelvin: f32) -> [[f32; 3]; 3] {
    let to_rgb = srgb().rgb_from_xyz;
    if white_balance_kelvin > 0.0 {
        let src = daylight_white(white_balance_kelvin);
        to_rgb.mul(&white_balance(src, srgb().white)).to_f32()
    } else {
        to_rgb.to_f32()
    }
}

/// The matrix from linear sRGB to the white-balanced output (RGB mode),
/// `None` for `white_balance_kelvin` 0: the pixels are the output.
pub fn output_from_rgb(white_balance_kelvin: f32) -> Option<[[f32; 3]; 3]> {
    (white_balance_kelvin > 0.0).then(|| {
        let s = srgb();
        s.rgb_from_xyz
            .mul(&white_balance(
                daylight_white(white_balance_kelvin),
                s.white,
            ))
            .mul(&s.xyz_from_rgb)
            .to_f32()
    })
}

/// The matrix a film applies to its pixels' values to give the output:
/// from the sensor's XYZ in spectral mode ([`output_from_sensor`]), from
/// RGB with a white balance otherwise ([`output_from_rgb`]); `None` when
/// the values are the output.
pub fn output_matrix(spectral: bool, white_balance_kelvin: f32) -> Option<[[f32; 3]; 3]> {
    if spectral {
        Some(output_from_sensor(white_balance_kelvin))
    } else {
        output_from_rgb(white_balance_kelvin)
    }
}

/// The chromaticity of the CIE daylight illuminant `D(T)`.
fn daylight_white(kelvin: f32) -> [f64; 2] {
    let d = daylight(kelvin);
    chromaticity(spectrum_to_xyz(|l| d.eval(l))).map(f64::from)
}

/// A pixel's output value from its sensor value `v` (XYZ) and the matrix
/// of [`output_from_sensor`]: the one place the film and split parts apply it.
pub fn sensor_to_output(m: &[[f32; 3]; 3], v: [f32; 3]) -> [f32; 3] {
    m.map(|r| r[0] * v[0] + r[1] * v[1] + r[2] * v[2])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spectrum::Colour;

    fn apply(m: [[f32; 3]; 3], c: Rgb) -> [f32; 3] {
        m.map(|r| r[0] * c.r + r[1] * c.g + r[2] * c.b)
    }

    #[test]
    fn white_light_averages_to_srgb_white() {
        // The mean over stratified wavelength samples of unit-luminance D65.
        let n = 4096;
        let mut sum = Rgb::ZERO;
        for k in 0..n {
            let w = SampledWavelengths::sample_visible((k as f32 + 0.5) / n as f32);
            sum += sample_xyz(SampledSpectrum::illuminant(Rgb::ONE, &w), &w);
        }
        let rgb = apply(output_from_sensor(0.0), sum * (1.0 / n as f32));
        assert!(rgb.iter().all(|c| (c - 1.0).abs() < 2e-3), "{rgb:?}");
        // Balancing for 6504 K (D65's temperature) changes nothing visible.
        let m = output_from_sensor(6504.0);
        let rgb2 = apply(m, sum * (1.0 / n as f32));
        assert!(rgb2.iter().all(|c| (c - 1.0).abs() < 5e-3), "{rgb2:?}");
        // A 5000 K white balance makes the 5000 K daylight illuminant white.
        let d50 = daylight(5000.0);
        let b = crate::spectrum::named::unit_luminance(|l| d50.eval(l)).unwrap();
        let mut s = Rgb::ZERO;
        for k in 0..n {
            let w = SampledWavelengths::sample_visible((k as f32 + 0.5) / n as f32);
            s += sample_xyz(SampledSpectrum::emission(Rgb::ONE, Some(&b), &w), &w);
        }
        let warm = apply(output_from_sensor(5000.0), s * (1.0 / n as f32));
        let spread = warm.iter().fold(0.0f32, |a, &c| a.max((c - warm[1]).abs()));
        assert!(spread < 3e-3 * warm[1], "{warm:?}");
    }
}
