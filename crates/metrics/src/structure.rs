//! The structure of an error image: how much of its power sits near the
//! Nyquist frequencies, relative to white noise.
//!
//! A sampler whose neighbouring pixels receive complementary samples (one
//! pixel's error high where its neighbour's is low) leaves a pattern of
//! period two pixels in the error image: a checkerboard (power near
//! `(½, ½)` cycles per pixel), alternate columns (near `(½, 0)`) or
//! alternate rows (near `(0, ½)`). [`nyquist_power`] measures all three:
//!
//! * `e(x, y)`, the `W x H` error values with their mean removed;
//! * its discrete Fourier transform `F(k)` and periodogram
//!   `P(k) = |F(k)|² / (W H)`, at frequencies `f = (k_x / W, k_y / H)`
//!   taken in `[-½, ½)`;
//! * for each region, the mean of `P` over its bins divided by the mean of
//!   `P` over every bin, which by Parseval's theorem is the variance
//!   `Σ e² / (W H)`. With `c` = [`DEFAULT_CUTOFF`] = 0.4 the regions are
//!   `|f_x| ≥ c, |f_y| ≥ c` (checkerboard), `|f_x| ≥ c, |f_y| < ½ - c`
//!   (columns) and `|f_x| < ½ - c, |f_y| ≥ c` (rows): squares of side
//!   `1 - 2c` = 0.2 around the three Nyquist points, each 4 % of the
//!   spectrum.
//!
//! Values: white noise has a flat expected periodogram, so each ratio is
//! about 1 (within a few `1/sqrt(bins)`); a pure checkerboard `(-1)^(x+y)`
//! (even `W`, `H`) puts all its power in the bin `(½, ½)`, so its
//! checkerboard ratio is `W H / (number of its bins)`, about
//! `1 / (1 - 2c)²` = 25, and pure stripes score the same in their region;
//! a smooth image (low frequencies only) gives about 0 everywhere. Small
//! squares rather than the annulus `|f| > c`: the annulus at 0.4 covers
//! half of the spectrum, so even a pure checkerboard would reach only
//! about 2.
//!
//! Cost: the DFT is evaluated only at the bins used, separably (each row at
//! the `k_x` used, then each of those columns at the `k_y` used): about
//! `0.4 W² H + 0.16 W H²` complex products, with no restriction on `W`
//! and `H`.

use crate::error::{MetricsError, Result};

/// The default cutoff `c` of [`nyquist_power`], in cycles per pixel.
pub const DEFAULT_CUTOFF: f64 = 0.4;

/// The error power near the three Nyquist frequencies of an image, each
/// relative to the image's mean power (white noise: about 1 each).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct NyquistPower {
    /// Around `(½, ½)`: `|f_x| ≥ c` and `|f_y| ≥ c` (a pixel checkerboard).
    pub checkerboard: f64,
    /// Around `(½, 0)`: `|f_x| ≥ c` and `|f_y| < ½ - c` (alternate columns).
    pub columns: f64,
    /// Around `(0, ½)`: `|f_x| < ½ - c` and `|f_y| ≥ c` (alternate rows).
    pub rows: f64,
}

impl NyquistPower {
    /// The largest of the three.
    pub fn max(&self) -> f64 {
        self.checkerboard.max(self.columns).max(self.rows)
    }
}

/// The mean periodogram power of the `width x height` image `values`
/// (row-major, mean removed) in each of the three Nyquist regions of
/// [`NyquistPower`], divided by its mean power over all frequencies (see
/// the module doc). All 0 for a constant image.
///
/// Errors: `values.len() != width * height`, an empty image, a value that
/// is not finite, or a cutoff outside `[0.25, 0.5]` or that leaves a region
/// without bins (an image less than 2 pixels wide or high).
///
/// ```
/// use lowdisc_metrics::nyquist_power;
/// // An 8x8 checkerboard: all its power is in the bin (½, ½), and with
/// // k in -4..4 on each axis only k = -4 has |k / 8| ≥ 0.4: one corner bin
/// // of the 64, holding 64 times the mean power.
/// let board: Vec<f64> = (0..64).map(|i| if (i % 8 + i / 8) % 2 == 0 { 1.0 } else { -1.0 }).collect();
/// let p = nyquist_power(&board, 8, 8, 0.4).unwrap();
/// assert!((p.checkerboard - 64.0).abs() < 1e-9);
/// assert!(p.rows.abs() < 1e-9 && p.columns.abs() < 1e-9);
/// ```
pub fn nyquist_power(
    values: &[f64],
    width: usize,
    height: usize,
    cutoff: f64,
) -> Result<NyquistPower> {
    check(values, width, height, cutoff)?;
    let n = values.len() as f64;
    let (mean, variance) = mean_variance(values);
    let (hx, lx) = (bins(width, cutoff, true), bins(width, cutoff, false));
    let (hy, ly) = (bins(height, cutoff, true), bins(height, cutoff, false));
    if [&hx, &lx, &hy, &ly].iter().any(|b| b.is_empty()) {
        return Err(MetricsError::InvalidOption(format!(
            "cutoff {cutoff} leaves a Nyquist region without frequencies in a {width}x{height} image"
        )));
    }
    if variance == 0.0 {
        return Ok(NyquistPower {
            checkerboard: 0.0,
            columns: 0.0,
            rows: 0.0,
        });
    }
    // Row transforms at every k_x used: rows[y][j] = Σ_x e(x, y) ω_W^(k_x[j] x).
    let kx: Vec<i64> = hx.iter().chain(&lx).copied().collect();
    let tw_x = twiddles(width, &kx);
    let rows = row_transforms(values, width, mean, &tw_x);
    // power[j][i]: the periodogram at (kx[j], ky[i]) for ky = hy then ly.
    let ky: Vec<i64> = hy.iter().chain(&ly).copied().collect();
    let tw_y = twiddles(height, &ky);
    let mut sums = [0.0; 3];
    for (j, _) in kx.iter().enumerate() {
        let column: Vec<[f64; 2]> = rows.iter().map(|r| r[j]).collect();
        for (i, t) in tw_y.iter().enumerate() {
            let (x_high, y_high) = (j < hx.len(), i < hy.len());
            let region = match (x_high, y_high) {
                (true, true) => 0,
                (true, false) => 1,
                (false, true) => 2,
                (false, false) => continue,
            };
            let mut s = [0.0; 2];
            for (c, w) in column.iter().zip(t) {
                s[0] += c[0] * w[0] - c[1] * w[1];
                s[1] += c[0] * w[1] + c[1] * w[0];
            }
            sums[region] += (s[0] * s[0] + s[1] * s[1]) / n;
        }
    }
    let mean_of = |sum: f64, a: usize, b: usize| sum / (a * b) as f64 / variance;
    Ok(NyquistPower {
        checkerboard: mean_of(sums[0], hx.len(), hy.len()),
        columns: mean_of(sums[1], hx.len(), ly.len()),
        rows: mean_of(sums[2], lx.len(), hy.len()),
    })
}

/// The default cell side of [`spectral_peak`], in cycles per pixel.
pub const DEFAULT_CELL: f64 = 0.1;

/// The strongest band of an image's spectrum: its mean power relative to
/// the image's mean power, and the band's centre frequency.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SpectralPeak {
    /// The largest cell's mean power over the mean power of all bins.
    pub ratio: f64,
    /// The cell's centre `(f_x, f_y)`, cycles per pixel (`f_y ≥ 0`; the
    /// periodogram of a real image is symmetric, `P(f) = P(-f)`).
    pub frequency: [f64; 2],
}

/// The largest mean periodogram power over the square cells of side
/// `cell` that tile the frequency plane `[-½, ½)²` (from -½), leaving out
/// the cells that touch `f = 0`, divided by the mean power of all bins:
/// a pattern of any period, in any direction, shows as a peak. White noise
/// gives a little over 1 (the largest of many cells' noisy means: about
/// 1.2 at 256x144, 1.5 at 64x64 with the default cell), a pure checkerboard
/// about `1 / cell²` = 100, a smooth image about 0. Compare images of the
/// same size. The full DFT is computed separably: `W² H + W H²` products.
///
/// Errors: as [`nyquist_power`], and a `cell` outside `[1/16, 1/4]`.
///
/// ```
/// use lowdisc_metrics::spectral_peak;
/// // Vertical stripes of period 4 pixels: all power at f = (±1/4, 0).
/// let w = 40;
/// let stripes: Vec<f64> = (0..w * w).map(|i| [1.0, 0.0, -1.0, 0.0][i % w % 4]).collect();
/// let p = spectral_peak(&stripes, w, w, 0.1).unwrap();
/// assert!((p.frequency[0].abs() - 0.25).abs() < 0.05 && p.frequency[1] < 0.1);
/// assert!(p.ratio > 30.0);
/// ```
pub fn spectral_peak(
    values: &[f64],
    width: usize,
    height: usize,
    cell: f64,
) -> Result<SpectralPeak> {
    check(values, width, height, 0.4)?;
    if !(1.0 / 16.0..=0.25).contains(&cell) {
        return Err(MetricsError::InvalidOption(format!(
            "the cell side must lie in [1/16, 1/4] cycles per pixel, got {cell}"
        )));
    }
    let n = values.len() as f64;
    let (mean, variance) = mean_variance(values);
    if variance == 0.0 {
        return Ok(SpectralPeak {
            ratio: 0.0,
            frequency: [0.0; 2],
        });
    }
    let all = |m: usize| -> Vec<i64> { (-(m as i64 / 2)..m as i64 - m as i64 / 2).collect() };
    let (kx, ky) = (all(width), all(height));
    let tw_x = twiddles(width, &kx);
    let rows = row_transforms(values, width, mean, &tw_x);
    let tw_y = twiddles(height, &ky);
    let cells = (1.0 / cell).ceil() as usize;
    let index = |f: f64| (((f + 0.5) / cell).floor() as usize).min(cells - 1);
    let mut sums = vec![(0.0, 0usize); cells * cells];
    for (j, &kj) in kx.iter().enumerate() {
        let column: Vec<[f64; 2]> = rows.iter().map(|r| r[j]).collect();
        let cx = index(kj as f64 / width as f64);
        for (i, t) in tw_y.iter().enumerate() {
            let cy = index(ky[i] as f64 / height as f64);
            let mut s = [0.0; 2];
            for (c, w) in column.iter().zip(t) {
                s[0] += c[0] * w[0] - c[1] * w[1];
                s[1] += c[0] * w[1] + c[1] * w[0];
            }
            let e = &mut sums[cy * cells + cx];
            e.0 += (s[0] * s[0] + s[1] * s[1]) / n;
            e.1 += 1;
        }
    }
    let edge = |c: usize| -0.5 + c as f64 * cell;
    let touches_zero = |c: usize| edge(c) <= 0.0 && edge(c + 1) >= 0.0;
    let mut best = SpectralPeak {
        ratio: 0.0,
        frequency: [0.0; 2],
    };
    for cy in 0..cells {
        for cx in 0..cells {
            let (sum, count) = sums[cy * cells + cx];
            if count == 0 || (touches_zero(cx) && touches_zero(cy)) {
                continue;
            }
            let ratio = sum / count as f64 / variance;
            if ratio > best.ratio {
                let mut f = [edge(cx) + cell / 2.0, edge(cy) + cell / 2.0];
                if f[1] < 0.0 {
                    f = [-f[0], -f[1]];
                }
                best = SpectralPeak {
                    ratio,
                    frequency: f,
                };
            }
        }
    }
    Ok(best)
}

fn check(values: &[f64], width: usize, height: usize, cutoff: f64) -> Result<()> {
    if width == 0 || height == 0 || values.len() != width * height {
        return Err(MetricsError::InvalidOption(format!(
            "{} values do not form a {width}x{height} image",
            values.len()
        )));
    }
    if !(0.25..=0.5).contains(&cutoff) {
        return Err(MetricsError::InvalidOption(format!(
            "the cutoff must lie in [0.25, 0.5] cycles per pixel, got {cutoff}"
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
/// `[-n/2, n/2)`, with `|k / n| ≥ cutoff` (`high`) or `|k / n| < ½ - cutoff`.
fn bins(n: usize, cutoff: f64, high: bool) -> Vec<i64> {
    let n = n as i64;
    (-(n / 2)..n - n / 2)
        .filter(|&k| {
            let f = (k as f64 / n as f64).abs();
            if high { f >= cutoff } else { f < 0.5 - cutoff }
        })
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
/// The mean and the (population) variance of `values`.
fn mean_variance(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let variance = values.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / n;
    (mean, variance)
}

/// Each row's discrete Fourier transform at the frequencies of `tw_x`
/// (from [`twiddles`]), after removing `mean`: `rows[y][j] = Σ_x (e(x, y)
/// - mean) ω^(k_j x)` over the `width`-wide rows of `values`.
fn row_transforms(
    values: &[f64],
    width: usize,
    mean: f64,
    tw_x: &[Vec<[f64; 2]>],
) -> Vec<Vec<[f64; 2]>> {
    values
        .chunks_exact(width)
        .map(|row| {
            let centred: Vec<f64> = row.iter().map(|v| v - mean).collect();
            tw_x.iter().map(|t| dot(&centred, t)).collect()
        })
        .collect()
}

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

    fn count(n: usize, high: bool) -> f64 {
        bins(n, DEFAULT_CUTOFF, high).len() as f64
    }

    /// A pure checkerboard's ratio is W H over the number of its bins; the
    /// stripes' regions hold nothing.
    #[test]
    fn checkerboard_has_all_power_in_the_corner() {
        for (w, h) in [(64, 64), (128, 96), (30, 50)] {
            let board = image(w, h, |x, y| if (x + y) % 2 == 0 { 2.5 } else { -0.5 });
            let p = nyquist_power(&board, w, h, DEFAULT_CUTOFF).unwrap();
            let expected = (w * h) as f64 / (count(w, true) * count(h, true));
            let c = p.checkerboard;
            assert!(
                (c - expected).abs() < 1e-9 * expected,
                "{w}x{h}: {c} vs {expected}"
            );
            assert!(p.rows.abs() < 1e-9 && p.columns.abs() < 1e-9, "{p:?}");
            assert_eq!(p.max(), c);
        }
        // 64 pixels: |k| ≥ 25.6 gives k = -32..=-26 and 26..=31, 13 bins.
        assert_eq!(count(64, true), 13.0);
        let board = image(64, 64, |x, y| if (x + y) % 2 == 0 { 1.0 } else { -1.0 });
        let p = nyquist_power(&board, 64, 64, 0.4).unwrap();
        assert!((p.checkerboard - 4096.0 / 169.0).abs() < 1e-9, "{p:?}");
    }

    /// Alternate rows and alternate columns land in their own regions.
    #[test]
    fn stripes_have_all_power_on_an_axis() {
        let (w, h) = (64, 48);
        let rows = image(w, h, |_, y| if y % 2 == 0 { 1.0 } else { -1.0 });
        let p = nyquist_power(&rows, w, h, DEFAULT_CUTOFF).unwrap();
        let expected = (w * h) as f64 / (count(w, false) * count(h, true));
        assert!((p.rows - expected).abs() < 1e-9 * expected, "{p:?}");
        assert!(
            p.columns.abs() < 1e-9 && p.checkerboard.abs() < 1e-9,
            "{p:?}"
        );
        let columns = image(w, h, |x, _| if x % 2 == 0 { 1.0 } else { -1.0 });
        let p = nyquist_power(&columns, w, h, DEFAULT_CUTOFF).unwrap();
        let expected = (w * h) as f64 / (count(w, true) * count(h, false));
        assert!((p.columns - expected).abs() < 1e-9 * expected, "{p:?}");
        assert!(p.rows.abs() < 1e-9 && p.checkerboard.abs() < 1e-9, "{p:?}");
    }

    /// White noise: each ratio of 16 independent 128x128 images averages
    /// to 1 (each about ±0.06: 625 bins, half of them independent).
    #[test]
    fn white_noise_is_about_one() {
        let mut rng = Pcg32::new(7, 3);
        let all: Vec<NyquistPower> = (0..16)
            .map(|_| {
                let noise = image(128, 128, |_, _| rng.next_f64() - 0.5);
                nyquist_power(&noise, 128, 128, DEFAULT_CUTOFF).unwrap()
            })
            .collect();
        for f in [
            |p: &NyquistPower| p.checkerboard,
            |p: &NyquistPower| p.rows,
            |p: &NyquistPower| p.columns,
        ] {
            let values: Vec<f64> = all.iter().map(f).collect();
            let mean = values.iter().sum::<f64>() / 16.0;
            assert!((mean - 1.0).abs() < 0.05, "{mean}");
            assert!(values.iter().all(|r| (r - 1.0).abs() < 0.3), "{values:?}");
        }
    }

    /// A smooth image (one low-frequency cosine on each axis, plus a
    /// constant) has no power near Nyquist: 0 to rounding.
    #[test]
    fn smooth_image_is_about_zero() {
        let smooth = image(64, 48, |x, y| {
            let (fx, fy) = (x as f64 / 64.0, y as f64 / 48.0);
            3.0 + (std::f64::consts::TAU * fx).cos()
                + 0.5 * (std::f64::consts::TAU * 2.0 * fy).sin()
        });
        let p = nyquist_power(&smooth, 64, 48, DEFAULT_CUTOFF).unwrap();
        assert!(p.max().abs() < 1e-20, "{p:?}");
        let constant = vec![4.0; 16];
        assert_eq!(nyquist_power(&constant, 4, 4, 0.4).unwrap().max(), 0.0);
    }

    /// Half checkerboard, half white noise of the same power: between the two.
    #[test]
    fn a_mixture_lies_between() {
        let mut rng = Pcg32::new(11, 1);
        let mixed = image(64, 64, |x, y| {
            let board = if (x + y) % 2 == 0 { 1.0 } else { -1.0 };
            board + (rng.next_f64() - 0.5) * 12f64.sqrt()
        });
        let p = nyquist_power(&mixed, 64, 64, DEFAULT_CUTOFF).unwrap();
        // Expected (24.24 + 1) / 2 ≈ 12.6, and about 1/2 in the stripes' regions.
        assert!(p.checkerboard > 10.0 && p.checkerboard < 15.0, "{p:?}");
        assert!(p.rows > 0.3 && p.rows < 0.7, "{p:?}");
    }

    #[test]
    fn spectral_peak_finds_patterns_of_any_period() {
        let (w, h) = (64, 48);
        let board = image(w, h, |x, y| if (x + y) % 2 == 0 { 1.0 } else { -1.0 });
        let p = spectral_peak(&board, w, h, DEFAULT_CELL).unwrap();
        // All power in the one bin (-½, -½); its cell [-0.5, -0.4)² holds
        // 7 x 5 bins (k_x = -32..=-26, k_y = -24..=-20).
        assert!((p.ratio - (w * h) as f64 / 35.0).abs() < 1e-6, "{p:?}");
        assert!((p.frequency[0].abs() - 0.45).abs() < 1e-9, "{p:?}");
        // Diagonal stripes of period 4 along x + y: f = ±(¼, ¼).
        let diagonal = image(w, h, |x, y| [1.0, 0.0, -1.0, 0.0][(x + y) % 4]);
        let p = spectral_peak(&diagonal, w, h, DEFAULT_CELL).unwrap();
        assert!((p.frequency[0] - 0.25).abs() < 0.051, "{p:?}");
        assert!((p.frequency[1] - 0.25).abs() < 0.051, "{p:?}");
        assert!(p.ratio > 20.0, "{p:?}");
        // White noise: a little above 1; smooth: 0.
        let mut rng = Pcg32::new(3, 3);
        let noise = image(128, 128, |_, _| rng.next_f64() - 0.5);
        let p = spectral_peak(&noise, 128, 128, DEFAULT_CELL).unwrap();
        assert!(p.ratio > 1.0 && p.ratio < 1.5, "{p:?}");
        let smooth = image(w, h, |x, _| {
            (std::f64::consts::TAU * x as f64 / w as f64).cos()
        });
        assert!(spectral_peak(&smooth, w, h, DEFAULT_CELL).unwrap().ratio < 1e-20);
        assert!(spectral_peak(&smooth, w, h, 0.01).is_err());
    }

    #[test]
    fn bad_input_is_an_error() {
        assert!(nyquist_power(&[1.0; 5], 2, 2, 0.4).is_err());
        assert!(nyquist_power(&[], 0, 0, 0.4).is_err());
        assert!(nyquist_power(&[1.0; 4], 2, 2, 0.2).is_err());
        assert!(nyquist_power(&[1.0; 4], 2, 2, 0.6).is_err());
        assert!(nyquist_power(&[1.0, f64::NAN, 0.0, 0.0], 2, 2, 0.4).is_err());
        // One pixel wide: no frequency reaches Nyquist.
        assert!(nyquist_power(&[1.0, 2.0], 1, 2, 0.4).is_err());
    }
}
