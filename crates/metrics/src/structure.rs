//! The structure of an error image: how much of its power sits at the
//! highest spatial frequencies, relative to white noise.
//!
//! A sampler whose neighbouring pixels receive complementary samples (one
//! pixel's error high where its neighbour's is low) leaves a checkerboard
//! in the error image: power concentrated near the Nyquist corner
//! `(½, ½)` cycles per pixel. [`nyquist_power_ratio`] measures it:
//!
//! * `e(x, y)`, the `W x H` error values with their mean removed;
//! * its discrete Fourier transform `F(k)` and periodogram
//!   `P(k) = |F(k)|² / (W H)`, at frequencies `f = (k_x / W, k_y / H)`
//!   taken in `[-½, ½)`;
//! * the ratio of the mean of `P` over the *corner* bins, those with
//!   `|f_x| ≥ c` **and** `|f_y| ≥ c` (default `c` = [`DEFAULT_CUTOFF`] = 0.4),
//!   to the mean of `P` over every bin, which by Parseval's theorem is the
//!   variance `Σ e² / (W H)`.
//!
//! Values: white noise has a flat expected periodogram, so its ratio is
//! about 1 (within a few `1/sqrt(bins)`); a pure checkerboard `(-1)^(x+y)`
//! (even `W`, `H`) puts all its power in the bin `(½, ½)`, so its ratio is
//! `W H / (number of corner bins)`, about `1 / (1 - 2c)²` = 25 at `c = 0.4`;
//! a smooth image (low frequencies only) gives about 0. The corner square
//! rather than the annulus `|f| > c`: the annulus at 0.4 covers half of the
//! spectrum, so even a pure checkerboard would reach only about 2.
//!
//! Cost: the DFT is evaluated only at the corner bins, separably (each
//! row at the corner `k_x`, then each of those columns at the corner
//! `k_y`): about `(1 - 2c) (W² H + (1 - 2c) W H²)` complex products, with no
//! restriction on `W` and `H`.

use crate::error::{MetricsError, Result};

/// The default cutoff `c` of [`nyquist_power_ratio`], in cycles per pixel.
pub const DEFAULT_CUTOFF: f64 = 0.4;

/// The mean periodogram power over the corner `|f_x| ≥ cutoff`,
/// `|f_y| ≥ cutoff` of the `width x height` image `values` (row-major, mean
/// removed), divided by its mean power over all frequencies (see the module
/// doc). 0 for a constant image.
///
/// Errors: `values.len() != width * height`, an empty image, a value that
/// is not finite, or a cutoff outside `(0, 0.5]` or that leaves no corner
/// bin (an image less than 2 pixels wide or high).
///
/// ```
/// use lowdisc_metrics::nyquist_power_ratio;
/// // An 8x8 checkerboard: all its power is in the bin (½, ½), and with
/// // k in -4..4 on each axis only k = -4 has |k / 8| ≥ 0.4: one corner bin
/// // of the 64, holding 64 times the mean power.
/// let board: Vec<f64> = (0..64).map(|i| if (i % 8 + i / 8) % 2 == 0 { 1.0 } else { -1.0 }).collect();
/// let r = nyquist_power_ratio(&board, 8, 8, 0.4).unwrap();
/// assert!((r - 64.0).abs() < 1e-9);
/// ```
pub fn nyquist_power_ratio(
    values: &[f64],
    width: usize,
    height: usize,
    cutoff: f64,
) -> Result<f64> {
    check(values, width, height, cutoff)?;
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let variance = values.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / n;
    let kx = corner_bins(width, cutoff);
    let ky = corner_bins(height, cutoff);
    if kx.is_empty() || ky.is_empty() {
        return Err(MetricsError::InvalidOption(format!(
            "cutoff {cutoff} leaves no corner frequency in a {width}x{height} image"
        )));
    }
    if variance == 0.0 {
        return Ok(0.0);
    }
    // Row transforms at the corner k_x: rows[y][j] = Σ_x e(x, y) ω_W^(k_x[j] x).
    let tw_x = twiddles(width, &kx);
    let rows: Vec<Vec<[f64; 2]>> = values
        .chunks_exact(width)
        .map(|row| {
            let centred: Vec<f64> = row.iter().map(|v| v - mean).collect();
            tw_x.iter().map(|t| dot(&centred, t)).collect()
        })
        .collect();
    let tw_y = twiddles(height, &ky);
    let mut corner = 0.0;
    for j in 0..kx.len() {
        let column: Vec<[f64; 2]> = rows.iter().map(|r| r[j]).collect();
        for t in &tw_y {
            let mut s = [0.0; 2];
            for (c, w) in column.iter().zip(t) {
                s[0] += c[0] * w[0] - c[1] * w[1];
                s[1] += c[0] * w[1] + c[1] * w[0];
            }
            corner += (s[0] * s[0] + s[1] * s[1]) / n;
        }
    }
    let bins = (kx.len() * ky.len()) as f64;
    Ok(corner / bins / variance)
}

fn check(values: &[f64], width: usize, height: usize, cutoff: f64) -> Result<()> {
    if width == 0 || height == 0 || values.len() != width * height {
        return Err(MetricsError::InvalidOption(format!(
            "{} values do not form a {width}x{height} image",
            values.len()
        )));
    }
    if !(cutoff > 0.0 && cutoff <= 0.5) {
        return Err(MetricsError::InvalidOption(format!(
            "the cutoff must lie in (0, 0.5] cycles per pixel, got {cutoff}"
        )));
    }
    if let Some(i) = values.iter().position(|v| !v.is_finite()) {
        return Err(MetricsError::InvalidOption(format!(
            "value {i} of the image is not finite ({})",
            values[i]
        )));
    }
    Ok(())
}

/// The frequency indices `k` of an axis of `n` pixels, taken in
/// `[-n/2, n/2)`, with `|k / n| ≥ cutoff`.
fn corner_bins(n: usize, cutoff: f64) -> Vec<i64> {
    let n = n as i64;
    (-(n / 2)..n - n / 2)
        .filter(|&k| (k as f64 / n as f64).abs() >= cutoff)
        .collect()
}

/// For each `k`, the factors `e^{-2πi k t / n}` for `t = 0..n`.
fn twiddles(n: usize, ks: &[i64]) -> Vec<Vec<[f64; 2]>> {
    ks.iter()
        .map(|&k| {
            (0..n)
                .map(|t| {
                    // Reduce k t modulo n first, so the angle stays exact.
                    let phase = (k * t as i64).rem_euclid(n as i64) as f64 / n as f64;
                    let angle = -std::f64::consts::TAU * phase;
                    [angle.cos(), angle.sin()]
                })
                .collect()
        })
        .collect()
}

/// `Σ v_t w_t` for real `v` and complex `w`.
fn dot(v: &[f64], w: &[[f64; 2]]) -> [f64; 2] {
    v.iter()
        .zip(w)
        .fold([0.0; 2], |s, (x, t)| [s[0] + x * t[0], s[1] + x * t[1]])
}

#[cfg(test)]
mod tests {
    use super::*;
    use lowdisc::pcg::Pcg32;

    fn image(w: usize, h: usize, mut f: impl FnMut(usize, usize) -> f64) -> Vec<f64> {
        (0..w * h).map(|i| f(i % w, i / w)).collect()
    }

    /// A pure checkerboard's ratio is W H over the number of corner bins.
    #[test]
    fn checkerboard_has_all_power_in_the_corner() {
        for (w, h) in [(64, 64), (128, 96), (30, 50)] {
            let board = image(w, h, |x, y| if (x + y) % 2 == 0 { 2.5 } else { -0.5 });
            let r = nyquist_power_ratio(&board, w, h, DEFAULT_CUTOFF).unwrap();
            let bins = corner_bins(w, 0.4).len() * corner_bins(h, 0.4).len();
            let expected = (w * h) as f64 / bins as f64;
            assert!(
                (r - expected).abs() < 1e-9 * expected,
                "{w}x{h}: {r} vs {expected}"
            );
        }
        // 64 pixels: |k| ≥ 25.6 gives k = -32..=-26 and 26..=31, 13 bins.
        assert_eq!(corner_bins(64, 0.4).len(), 13);
        let board = image(64, 64, |x, y| if (x + y) % 2 == 0 { 1.0 } else { -1.0 });
        let r = nyquist_power_ratio(&board, 64, 64, 0.4).unwrap();
        assert!((r - 4096.0 / 169.0).abs() < 1e-9, "{r}");
    }

    /// White noise: the ratio of 16 independent 128x128 images averages
    /// to 1 (each about ±0.06: 625 bins, half of them independent).
    #[test]
    fn white_noise_is_about_one() {
        let mut rng = Pcg32::new(7, 3);
        let ratios: Vec<f64> = (0..16)
            .map(|_| {
                let noise = image(128, 128, |_, _| rng.next_f64() - 0.5);
                nyquist_power_ratio(&noise, 128, 128, DEFAULT_CUTOFF).unwrap()
            })
            .collect();
        let mean = ratios.iter().sum::<f64>() / 16.0;
        assert!((mean - 1.0).abs() < 0.05, "{mean}");
        assert!(ratios.iter().all(|r| (r - 1.0).abs() < 0.3), "{ratios:?}");
    }

    /// A smooth image (one low-frequency cosine on each axis, plus a
    /// constant) has no power in the corner: 0 to rounding.
    #[test]
    fn smooth_image_is_about_zero() {
        let smooth = image(64, 48, |x, y| {
            let (fx, fy) = (x as f64 / 64.0, y as f64 / 48.0);
            3.0 + (std::f64::consts::TAU * fx).cos()
                + 0.5 * (std::f64::consts::TAU * 2.0 * fy).sin()
        });
        let r = nyquist_power_ratio(&smooth, 64, 48, DEFAULT_CUTOFF).unwrap();
        assert!(r.abs() < 1e-20, "{r}");
        let constant = vec![4.0; 16];
        assert_eq!(nyquist_power_ratio(&constant, 4, 4, 0.4).unwrap(), 0.0);
    }

    /// Half checkerboard, half white noise of the same power: between the two.
    #[test]
    fn a_mixture_lies_between() {
        let mut rng = Pcg32::new(11, 1);
        let mixed = image(64, 64, |x, y| {
            let board = if (x + y) % 2 == 0 { 1.0 } else { -1.0 };
            board + (rng.next_f64() - 0.5) * 12f64.sqrt()
        });
        let r = nyquist_power_ratio(&mixed, 64, 64, DEFAULT_CUTOFF).unwrap();
        // Expected (24.24 + 1) / 2 ≈ 12.6.
        assert!(r > 10.0 && r < 15.0, "{r}");
    }

    #[test]
    fn bad_input_is_an_error() {
        assert!(nyquist_power_ratio(&[1.0; 5], 2, 2, 0.4).is_err());
        assert!(nyquist_power_ratio(&[], 0, 0, 0.4).is_err());
        assert!(nyquist_power_ratio(&[1.0; 4], 2, 2, 0.0).is_err());
        assert!(nyquist_power_ratio(&[1.0; 4], 2, 2, 0.6).is_err());
        assert!(nyquist_power_ratio(&[1.0, f64::NAN, 0.0, 0.0], 2, 2, 0.4).is_err());
        // One pixel wide: no frequency reaches the corner.
        assert!(nyquist_power_ratio(&[1.0, 2.0], 1, 2, 0.4).is_err());
    }
}
