//! A perceptual error: the error image blurred by a Gaussian before squaring.
//!
//! The eye low-pass filters what it sees, so noise whose energy sits at high
//! spatial frequencies (blue noise) looks smoother than white noise of the
//! same MSE. Heitz & Belcour 2019 ("Distributing Monte Carlo errors as a blue
//! noise in screen space") and Chizhov, Georgiev, Myszkowski & Singh 2022
//! ("Perceptual error optimization for Monte Carlo rendering") measure error
//! after such a filter. Here, for a test image `x`, reference `r` and mask
//! `m` (1 for kept pixels, 0 for the others; all ones without a mask):
//!
//! ```text
//! e      = x - r                               (per channel, linear radiance)
//! ê(p)   = Σ_q G(p - q) m(q) e(q) / Σ_q G(p - q) m(q)
//! error  = Σ_{p kept} Σ_c ê_c(p)² / (3 · kept)
//! ```
//!
//! with `G` the 2-D Gaussian of standard deviation `σ` pixels, truncated at
//! radius `ceil(3σ)`. Dividing by the blurred mask (normalised convolution,
//! Knutsson & Westin 1993) makes `ê` a weighted mean of *kept* errors only:
//! an excluded pixel (an emitter) never leaks into its neighbours, and the
//! image edges are handled the same way (the kernel is renormalised over the
//! pixels inside). So a constant error `c` gives `c²` with or without a mask,
//! and a white noise of variance `v` gives about `v · Σ G²`, i.e.
//! `v / (4πσ²)` for large `σ`.
//!
//! [`DEFAULT_SIGMA`] is 1 pixel, the order of the kernel widths used in those
//! papers (the exact width depends on the viewing distance); the experiment
//! states the σ it used.

use crate::error::{ErrorKind, ImageError};
use crate::image::RgbImage;
use crate::mask::PixelMask;
use crate::metrics::check_sizes;

/// The default Gaussian standard deviation, in pixels.
pub const DEFAULT_SIGMA: f64 = 1.0;
/// The largest σ accepted (bounded time: the kernel has `2·ceil(3σ)+1` taps).
pub const MAX_SIGMA: f64 = 64.0;

/// The normalised 1-D Gaussian of standard deviation `sigma`, taps
/// `-R..=R` with `R = ceil(3σ)`.
pub fn gaussian_kernel(sigma: f64) -> Result<Vec<f64>, ImageError> {
    if !(sigma > 0.0 && sigma <= MAX_SIGMA) {
        return Err(ImageError::new(
            ErrorKind::InvalidArgument,
            format!("blur sigma must be in (0, {MAX_SIGMA}] pixels, got {sigma}"),
        ));
    }
    let radius = (3.0 * sigma).ceil() as i64;
    let w: Vec<f64> = (-radius..=radius)
        .map(|k| (-((k * k) as f64) / (2.0 * sigma * sigma)).exp())
        .collect();
    let sum: f64 = w.iter().sum();
    Ok(w.into_iter().map(|v| v / sum).collect())
}

/// Convolves `len` rows of `stride`-spaced lines: `out[i] = Σ_k w_k in[i+k-R]`,
/// taps outside the line dropped (the normalisation happens later).
fn blur_lines(
    data: &[f64],
    width: usize,
    height: usize,
    kernel: &[f64],
    along_x: bool,
) -> Vec<f64> {
    let radius = (kernel.len() / 2) as isize;
    let mut out = vec![0.0; data.len()];
    let (lines, len) = if along_x {
        (height, width)
    } else {
        (width, height)
    };
    let index = |line: usize, i: usize| {
        if along_x {
            line * width + i
        } else {
            i * width + line
        }
    };
    for line in 0..lines {
        for i in 0..len {
            let mut acc = 0.0;
            for (k, w) in kernel.iter().enumerate() {
                let j = i as isize + k as isize - radius;
                if j >= 0 && (j as usize) < len {
                    acc += w * data[index(line, j as usize)];
                }
            }
            out[index(line, i)] = acc;
        }
    }
    out
}

fn blur(data: &[f64], width: usize, height: usize, kernel: &[f64]) -> Vec<f64> {
    let rows = blur_lines(data, width, height, kernel, true);
    blur_lines(&rows, width, height, kernel, false)
}

/// The blurred-error MSE of `test` against `reference` over the pixels
/// `mask` keeps (every pixel for `None`), with a Gaussian of `sigma` pixels
/// (see the module doc). Errors: size mismatch, a mask that keeps nothing,
/// `sigma` outside `(0, MAX_SIGMA]`.
pub fn blurred_mse(
    test: &RgbImage,
    reference: &RgbImage,
    mask: Option<&PixelMask>,
    sigma: f64,
) -> Result<f64, ImageError> {
    check_sizes(test, reference)?;
    let kernel = gaussian_kernel(sigma)?;
    let (w, h) = (test.width(), test.height());
    let all;
    let mask = match mask {
        Some(m) => m,
        None => {
            all = PixelMask::all(w, h);
            &all
        }
    };
    mask.check_fits(test)?;
    let keep = mask.as_slice();
    let weight: Vec<f64> = keep.iter().map(|k| f64::from(u8::from(*k))).collect();
    let blurred_weight = blur(&weight, w, h, &kernel);
    let mut total = 0.0;
    for c in 0..3 {
        // Excluded pixels contribute 0, whatever they hold (NaN included).
        let masked_error: Vec<f64> = test
            .pixels()
            .iter()
            .zip(reference.pixels())
            .zip(keep)
            .map(|((t, r), k)| {
                if *k {
                    f64::from(t[c]) - f64::from(r[c])
                } else {
                    0.0
                }
            })
            .collect();
        let blurred = blur(&masked_error, w, h, &kernel);
        for i in (0..w * h).filter(|&i| keep[i]) {
            let e = blurred[i] / blurred_weight[i];
            total += e * e;
        }
    }
    Ok(total / (3 * mask.kept()) as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::metrics::error_metrics;

    /// A deterministic zero-mean error pattern of variance about 1/12 (LCG).
    fn noise_image(w: usize, h: usize, seed: u64) -> RgbImage {
        let mut s = seed;
        let mut next = || {
            s = s
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (s >> 40) as f32 / (1u64 << 24) as f32 - 0.5
        };
        RgbImage::from_fn(w, h, |_, _| [next(), next(), next()]).unwrap()
    }

    fn constant(w: usize, h: usize, v: f32) -> RgbImage {
        RgbImage::filled(w, h, [v; 3]).unwrap()
    }

    #[test]
    fn kernel_is_normalised_and_symmetric() {
        let k = gaussian_kernel(1.5).unwrap();
        assert_eq!(k.len(), 2 * 5 + 1);
        assert!((k.iter().sum::<f64>() - 1.0).abs() < 1e-15);
        for i in 0..k.len() {
            assert_eq!(k[i], k[k.len() - 1 - i]);
        }
        for bad in [0.0, -1.0, f64::NAN, 65.0] {
            assert!(gaussian_kernel(bad).is_err());
        }
    }

    #[test]
    fn blur_of_a_constant_error_is_that_error() {
        let (t, r) = (constant(13, 9, 0.75), constant(13, 9, 0.5));
        for sigma in [0.5, 1.0, 2.5] {
            let e = blurred_mse(&t, &r, None, sigma).unwrap();
            assert!((e - 0.0625).abs() < 1e-12, "sigma {sigma}: {e}");
        }
        let keep = (0..13 * 9).map(|i| i % 5 != 0).collect();
        let mask = PixelMask::from_keep(13, 9, keep).unwrap();
        let e = blurred_mse(&t, &r, Some(&mask), 2.0).unwrap();
        assert!((e - 0.0625).abs() < 1e-12, "{e}");
    }

    #[test]
    fn masked_pixels_do_not_leak_through_the_blur() {
        let r = constant(16, 16, 0.3);
        let t = noise_image(16, 16, 5).map(|p| p.map(|v| v + 0.3));
        let mut excluded = vec![false; 256];
        excluded[7 * 16 + 8] = true;
        let mask = PixelMask::excluding(16, 16, &excluded, 2).unwrap();
        let before = blurred_mse(&t, &r, Some(&mask), 1.5).unwrap();
        let mut bright = t.clone();
        for y in 5..=9 {
            for x in 6..=10 {
                bright.set(x, y, [1e4, f32::NAN, -3.0]).unwrap();
            }
        }
        assert_eq!(blurred_mse(&bright, &r, Some(&mask), 1.5).unwrap(), before);
        // Unmasked, the same change dominates (or is NaN).
        let unmasked = blurred_mse(&bright, &r, None, 1.5).unwrap();
        assert!(unmasked.is_nan() || unmasked > 1e3, "{unmasked}");
    }

    #[test]
    fn white_noise_is_reduced_by_the_sum_of_squared_weights() {
        let (w, h) = (160, 160);
        let r = constant(w, h, 0.0);
        let t = noise_image(w, h, 42);
        let mse = error_metrics(&t, &r).unwrap().linear.mse;
        let sigma = 2.0;
        let k = gaussian_kernel(sigma).unwrap();
        let gain = k.iter().map(|v| v * v).sum::<f64>().powi(2);
        let e = blurred_mse(&t, &r, None, sigma).unwrap();
        // Edge pixels (renormalised kernels) raise it a little: within 10 %.
        let ratio = e / (mse * gain);
        assert!((0.95..1.10).contains(&ratio), "ratio {ratio}");
        // A blur far below a pixel (neighbour weight e^-12.5) leaves the MSE.
        let tiny = blurred_mse(&t, &r, None, 0.2).unwrap();
        assert!((tiny / mse - 1.0).abs() < 1e-4, "{}", tiny / mse);
    }

    #[test]
    fn size_mismatch_is_an_error() {
        let e = blurred_mse(&constant(4, 4, 0.0), &constant(4, 5, 0.0), None, 1.0);
        assert_eq!(e.unwrap_err().kind(), ErrorKind::SizeMismatch);
    }
}
