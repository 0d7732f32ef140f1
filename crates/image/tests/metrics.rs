//! Error metrics against hand-computed values on tiny images.

use lowdisc_image::metrics::{RELMSE_EPSILON, linear_errors, srgb8_errors};
use lowdisc_image::{ErrorKind, PixelError, RgbImage, error_metrics, pixel_errors};

fn close(a: f64, b: f64) {
    assert!((a - b).abs() <= 1e-6 * b.abs().max(1.0), "{a} != {b}");
}

/// test 2x2: (1,0,0) (0.5,0.5,0.5) / (0.1,0,0) (2,1,0)
/// ref  2x2: (1,1,0) (0.5,0.5,0.5) / (0,0,0)   (1,1,1)
fn pair_2x2() -> (RgbImage, RgbImage) {
    let test = RgbImage::from_pixels(
        2,
        2,
        vec![
            [1.0, 0.0, 0.0],
            [0.5, 0.5, 0.5],
            [0.1, 0.0, 0.0],
            [2.0, 1.0, 0.0],
        ],
    )
    .unwrap();
    let reference = RgbImage::from_pixels(
        2,
        2,
        vec![
            [1.0, 1.0, 0.0],
            [0.5, 0.5, 0.5],
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 1.0],
        ],
    )
    .unwrap();
    (test, reference)
}

#[test]
fn linear_metrics_2x2() {
    let (test, reference) = pair_2x2();
    let m = linear_errors(&test, &reference).unwrap();
    // N = 4 pixels * 3 channels = 12. Non-zero differences x - r:
    //   pixel (0,0) G: 0 - 1 = -1      (r = 1)
    //   pixel (0,1) R: 0.1 - 0 = 0.1   (r = 0)
    //   pixel (1,1) R: 2 - 1 = 1       (r = 1)
    //   pixel (1,1) B: 0 - 1 = -1      (r = 1)
    // Sum of squares = 1 + 0.01 + 1 + 1 = 3.01 -> MSE = 3.01 / 12 = 0.2508333.
    // Sum of |d| = 1 + 0.1 + 1 + 1 = 3.1 -> MAE = 3.1 / 12 = 0.2583333.
    // relMSE terms: three of 1 / (1 + 0.01) and 0.01 / (0 + 0.01) = 1
    //   -> (3 / 1.01 + 1) / 12 = (2.9702970 + 1) / 12 = 0.3308581.
    let d = f64::from(0.1f32); // 0.1 as stored in f32
    close(m.mse, (3.0 + d * d) / 12.0);
    close(m.mse, 0.250_833_3);
    close(m.mae, (3.0 + d) / 12.0);
    close(m.rmse, ((3.0 + d * d) / 12.0).sqrt());
    close(m.relmse, (3.0 / 1.01 + d * d / RELMSE_EPSILON) / 12.0);
    close(m.relmse, 0.330_858_1);
}

#[test]
fn srgb8_metrics_2x2() {
    let (test, reference) = pair_2x2();
    let m = srgb8_errors(&test, &reference).unwrap();
    // Codes at exposure 1: 1 -> 255, 0 -> 0, 0.5 -> 188, 2 -> 255 (clamped),
    // 0.1 -> 255 * (1.055 * 0.1^(1/2.4) - 0.055) = 255 * 0.349190 = 89.04 -> 89.
    // test codes: (255,0,0) (188,188,188) (89,0,0) (255,255,0)
    // ref codes:  (255,255,0) (188,188,188) (0,0,0) (255,255,255)
    // Differences: -255 (G of pixel 0), 89 (R of pixel 2), 0 (R of pixel 3,
    // both clamp to 255), -255 (B of pixel 3).
    // MSE = (65025 + 7921 + 65025) / 12 = 137971 / 12 = 11497.583.
    // MAE = (255 + 89 + 255) / 12 = 599 / 12 = 49.916667.
    // relMSE with eps = 0.01 * 255^2 = 650.25:
    //   2 * 65025 / (65025 + 650.25) + 7921 / 650.25 = 2 / 1.01 + 12.181469
    //   -> 14.161667 / 12 = 1.1801389.
    close(m.mse, 137_971.0 / 12.0);
    close(m.mae, 599.0 / 12.0);
    close(m.rmse, (137_971.0f64 / 12.0).sqrt());
    close(m.relmse, (2.0 / 1.01 + 7921.0 / 650.25) / 12.0);
    close(m.relmse, 1.180_138_9);
}

#[test]
fn linear_metrics_3x1() {
    // test: (0.2,0.2,0.2) (1,1,1) (4,0,0); ref: (0.1,0.1,0.1) (1,1,1) (2,0,0).
    let test = RgbImage::from_pixels(3, 1, vec![[0.2; 3], [1.0; 3], [4.0, 0.0, 0.0]]).unwrap();
    let reference = RgbImage::from_pixels(3, 1, vec![[0.1; 3], [1.0; 3], [2.0, 0.0, 0.0]]).unwrap();
    let m = linear_errors(&test, &reference).unwrap();
    // N = 9. Differences: 0.1 three times (r = 0.1), 2 once (r = 2).
    // MSE = (3 * 0.01 + 4) / 9 = 4.03 / 9 = 0.4477778.
    // MAE = (0.3 + 2) / 9 = 0.2555556.
    // relMSE = (3 * 0.01 / (0.01 + 0.01) + 4 / (4 + 0.01)) / 9
    //        = (1.5 + 0.9975062) / 9 = 0.2775007.
    let tol = |a: f64, b: f64| assert!((a - b).abs() < 1e-6, "{a} != {b}");
    tol(m.mse, 4.03 / 9.0);
    tol(m.mae, 2.3 / 9.0);
    tol(m.rmse, (4.03f64 / 9.0).sqrt());
    tol(m.relmse, 0.277_500_7);
}

#[test]
fn identical_images_have_zero_error_and_sizes_must_match() {
    let (test, _) = pair_2x2();
    let m = error_metrics(&test, &test).unwrap();
    assert_eq!(m.linear.mse, 0.0);
    assert_eq!(m.srgb8.relmse, 0.0);
    let other = RgbImage::new(3, 1).unwrap();
    assert_eq!(
        error_metrics(&test, &other).unwrap_err().kind(),
        ErrorKind::SizeMismatch
    );
    assert_eq!(
        pixel_errors(&test, &other, PixelError::Squared)
            .unwrap_err()
            .kind(),
        ErrorKind::SizeMismatch
    );
}

#[test]
fn pixel_error_means_equal_the_metrics() {
    let (test, reference) = pair_2x2();
    let m = linear_errors(&test, &reference).unwrap();
    for (kind, want) in [
        (PixelError::Squared, m.mse),
        (PixelError::RelativeSquared, m.relmse),
        (PixelError::Absolute, m.mae),
    ] {
        let v = pixel_errors(&test, &reference, kind).unwrap();
        let mean = v.iter().map(|&x| f64::from(x)).sum::<f64>() / v.len() as f64;
        assert!((mean - want).abs() < 1e-6, "{kind:?}: {mean} vs {want}");
    }
}

#[test]
fn metrics_serialize_with_named_fields() {
    let (test, reference) = pair_2x2();
    let json = serde_json::to_value(error_metrics(&test, &reference).unwrap()).unwrap();
    for group in ["linear", "srgb8"] {
        for field in ["mse", "relmse", "rmse", "mae"] {
            assert!(
                json[group][field].is_f64(),
                "{group}.{field} missing in {json}"
            );
        }
    }
}
