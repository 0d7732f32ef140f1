//! Colour helpers: the exact sRGB transfer curve, Rec.709 luminance and 8-bit
//! sRGB quantisation of linear images.
//!
//! The curve is the piecewise one of IEC 61966-2-1: linear below the break
//! points 0.0031308 (linear) and 0.04045 (encoded), a 2.4 power above. All
//! arithmetic is done in `f64` and rounded to `f32` once.

use std::sync::OnceLock;

use crate::image::RgbImage;

/// Linear value where the sRGB curve switches from the line to the power law.
pub const SRGB_LINEAR_BREAK: f32 = 0.003_130_8;
/// Encoded value where the inverse sRGB curve switches (12.92 * the linear break).
pub const SRGB_ENCODED_BREAK: f32 = 0.040_45;

/// Rec.709 / sRGB luminance weights for linear R, G, B.
pub const REC709_LUMINANCE: [f32; 3] = [0.2126, 0.7152, 0.0722];

/// Encodes a linear value with the sRGB curve (no clamping; NaN stays NaN).
pub fn srgb_encode(linear: f32) -> f32 {
    let x = f64::from(linear);
    let v = if linear <= SRGB_LINEAR_BREAK {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    };
    v as f32
}

/// Decodes an sRGB-encoded value to linear (no clamping; NaN stays NaN).
pub fn srgb_decode(encoded: f32) -> f32 {
    let v = f64::from(encoded);
    let x = if encoded <= SRGB_ENCODED_BREAK {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    };
    x as f32
}

/// Linear value of the 8-bit sRGB code `v` (exact curve, table lookup).
pub fn srgb8_decode(v: u8) -> f32 {
    static TABLE: OnceLock<[f32; 256]> = OnceLock::new();
    let table = TABLE.get_or_init(|| {
        let mut t = [0.0f32; 256];
        for (i, e) in t.iter_mut().enumerate() {
            *e = srgb_decode(i as f32 / 255.0);
        }
        t
    });
    table[usize::from(v)]
}

/// Quantises a linear value to an 8-bit sRGB code: NaN and values `<= 0` give
/// 0, values whose encoding is `>= 1` (including +inf) give 255, otherwise
/// `round(255 * srgb_encode(v))` with halves rounded up.
pub fn srgb8_encode(linear: f32) -> u8 {
    if linear.is_nan() || linear <= 0.0 {
        return 0;
    }
    let e = f64::from(srgb_encode(linear)).min(1.0);
    (e * 255.0 + 0.5).floor() as u8
}

/// Rec.709 luminance `0.2126 r + 0.7152 g + 0.0722 b` of a linear RGB value.
pub fn luminance(rgb: [f32; 3]) -> f32 {
    REC709_LUMINANCE[0] * rgb[0] + REC709_LUMINANCE[1] * rgb[1] + REC709_LUMINANCE[2] * rgb[2]
}

/// The image as 8-bit sRGB, row-major top row first: each linear channel is
/// multiplied by `exposure` (a linear factor, not stops) and quantised with
/// [`srgb8_encode`] (NaN to 0, clamped to 0..=255, correctly rounded).
pub fn to_srgb8(image: &RgbImage, exposure: f32) -> Vec<[u8; 3]> {
    image
        .pixels()
        .iter()
        .map(|p| {
            [
                srgb8_encode(p[0] * exposure),
                srgb8_encode(p[1] * exposure),
                srgb8_encode(p[2] * exposure),
            ]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn known_points_of_the_curve() {
        // At the break both pieces meet: 12.92 * 0.0031308 = 0.040449936.
        assert!((srgb_encode(0.003_130_8) - 0.040_449_936).abs() < 1e-8);
        // Just above the break the power piece gives nearly the same value:
        // 1.055 * 0.0031308^(1/2.4) - 0.055 = 0.0404500 (to 7 digits).
        assert!((srgb_encode(0.003_130_9) - 0.040_45).abs() < 2e-6);
        // 0.04045 encoded is on the linear piece: 0.04045 / 12.92 = 0.0031308050.
        assert!((srgb_decode(0.040_45) - 0.003_130_805).abs() < 1e-9);
        assert_eq!(srgb_encode(0.0), 0.0);
        assert_eq!(srgb_decode(0.0), 0.0);
        assert!((srgb_encode(1.0) - 1.0).abs() < 1e-7);
        assert!((srgb_decode(1.0) - 1.0).abs() < 1e-7);
        // 0.5 encoded: ((0.5 + 0.055) / 1.055)^2.4 = 0.21404114.
        assert!((srgb_decode(0.5) - 0.214_041_14).abs() < 1e-7);
        // 0.18 linear (mid grey): 1.055 * 0.18^(1/2.4) - 0.055 = 0.46135613.
        assert!((srgb_encode(0.18) - 0.461_356_13).abs() < 1e-6);
    }

    #[test]
    fn round_trip_over_the_unit_interval() {
        for i in 0..=10_000 {
            let x = i as f32 / 10_000.0;
            let back = srgb_decode(srgb_encode(x));
            assert!(
                (back - x).abs() <= 1e-6 * x.max(1e-3),
                "x = {x}, back = {back}"
            );
            let back = srgb_encode(srgb_decode(x));
            assert!((back - x).abs() <= 1e-6, "x = {x}, back = {back}");
        }
    }

    #[test]
    fn eight_bit_codes_round_trip_and_saturate() {
        for v in 0..=255u8 {
            assert_eq!(srgb8_encode(srgb8_decode(v)), v);
        }
        assert_eq!(srgb8_encode(f32::NAN), 0);
        assert_eq!(srgb8_encode(-1.0), 0);
        assert_eq!(srgb8_encode(f32::INFINITY), 255);
        assert_eq!(srgb8_encode(7.0), 255);
        // 0.5 linear encodes to 0.73536 -> 255 * 0.73536 = 187.52 -> 188.
        assert_eq!(srgb8_encode(0.5), 188);
        // Linear 1/255 / 12.92 encodes to exactly 1/255 -> code 1.
        assert_eq!(srgb8_encode(1.0 / 255.0 / 12.92), 1);
    }

    #[test]
    fn luminance_weights_sum_to_one_and_to_srgb8_applies_exposure() {
        assert!((luminance([1.0, 1.0, 1.0]) - 1.0).abs() < 1e-6);
        assert_eq!(luminance([0.0, 1.0, 0.0]), 0.7152);
        let img =
            RgbImage::from_pixels(2, 1, vec![[0.25, 0.5, 1.0], [f32::NAN, 2.0, 0.0]]).unwrap();
        // Exposure 2 doubles: 0.5 -> 188, 1.0 -> 255, 2.0 -> 255 (clamped).
        assert_eq!(to_srgb8(&img, 2.0), vec![[188, 255, 255], [0, 255, 0]]);
    }
}
