//! CIE data: the 1931 2° standard observer (`x̄`, `ȳ`, `z̄` at 1 nm,
//! 360–830 nm, CIE 018:2019 data set `CIE_xyz_1931_2deg`), standard
//! illuminant D65 (5 nm, CIE S 014-2) and the daylight basis `S0`, `S1`,
//! `S2` (5 nm, CIE 015:2018) from which `D(T)` is built. The tables are the
//! CIE's published values, kept as text in `data/` and parsed once.
//!
//! Spectra given at sample points are evaluated by linear interpolation and
//! are zero outside their range ([`Tabulated`]).

use std::sync::LazyLock;

/// Shortest wavelength rendered (nm), the first of the matching functions.
pub const LAMBDA_MIN: f32 = 360.0;
/// Longest wavelength rendered (nm), the last of the matching functions.
pub const LAMBDA_MAX: f32 = 830.0;
/// `∫ ȳ(λ) dλ` over the 1 nm table (the sum of its `ȳ` values, 106.856895
/// as in pbrt-v4): radiance whose `∫ ȳ L dλ` equals it has luminance 1.
pub const CIE_Y_INTEGRAL: f32 = 106.856_895;

/// A spectrum tabulated at increasing wavelengths, linear in between and
/// zero outside.
#[derive(Clone, Debug, PartialEq)]
pub struct Tabulated {
    /// Wavelengths (nm), strictly increasing.
    pub lambda: Vec<f32>,
    /// Values at `lambda`.
    pub value: Vec<f32>,
}

impl Tabulated {
    /// The value at `lambda` (nm).
    pub fn eval(&self, lambda: f32) -> f32 {
        let (l, v) = (&self.lambda, &self.value);
        if l.is_empty() || !(lambda >= l[0] && lambda <= l[l.len() - 1]) {
            return 0.0;
        }
        let i = l.partition_point(|&x| x <= lambda).clamp(1, l.len() - 1) - 1;
        let t = (lambda - l[i]) / (l[i + 1] - l[i]);
        v[i] + t * (v[i + 1] - v[i])
    }
    /// Every value multiplied by `s`.
    pub fn scaled(mut self, s: f32) -> Tabulated {
        self.value.iter_mut().for_each(|v| *v *= s);
        self
    }
}

/// Parses whitespace-separated numeric rows (`#` comments) into columns.
fn columns(text: &str, n: usize) -> Vec<Vec<f32>> {
    let mut cols = vec![Vec::new(); n];
    for line in text.lines() {
        let line = line.split('#').next().unwrap_or("");
        let row: Vec<f32> = line
            .split_whitespace()
            .map(|t| t.parse().expect("CIE data files hold numbers"))
            .collect();
        if row.len() == n {
            row.into_iter()
                .zip(cols.iter_mut())
                .for_each(|(v, c)| c.push(v));
        }
    }
    cols
}

/// The colour-matching functions `[x̄, ȳ, z̄]` at 1 nm from 360 nm.
static CMF: LazyLock<[Vec<f32>; 3]> = LazyLock::new(|| {
    let mut c = columns(include_str!("../data/cie1931_2deg_1nm.txt"), 4);
    let z = c.pop().unwrap_or_default();
    let y = c.pop().unwrap_or_default();
    let x = c.pop().unwrap_or_default();
    [x, y, z]
});

/// [`CMF`] by rows, `[x̄, ȳ, z̄]` at each nanometre 360..=830 (a fixed
/// length, so that [`xyz_bar`] reads it without bounds checks).
static CMF_ROWS: LazyLock<[[f32; 3]; 471]> =
    LazyLock::new(|| std::array::from_fn(|i| CMF.each_ref().map(|c| c[i])));

/// `[x̄(λ), ȳ(λ), z̄(λ)]`, linear between the 1 nm samples, zero outside
/// 360–830 nm.
pub fn xyz_bar(lambda: f32) -> [f32; 3] {
    if !(LAMBDA_MIN..=LAMBDA_MAX).contains(&lambda) {
        return [0.0; 3];
    }
    let x = lambda - LAMBDA_MIN;
    // `x` is in `[0, 470]`: truncating through `i32` is `x as usize`, in
    // one instruction.
    let rows = &*CMF_ROWS;
    let i = (x as i32 as usize).min(rows.len() - 2);
    let t = x - i as i32 as f32;
    let (a, b) = (rows[i], rows[i + 1]);
    std::array::from_fn(|c| a[c] + t * (b[c] - a[c]))
}

/// The matching functions sampled at every nanometre 360..=830 (471 rows).
pub fn xyz_bar_table() -> &'static [Vec<f32>; 3] {
    &CMF
}

/// CIE standard illuminant D65 (relative power, 100 at 560 nm), 300–830 nm.
pub fn d65() -> &'static Tabulated {
    static D65: LazyLock<Tabulated> = LazyLock::new(|| {
        let mut c = columns(include_str!("../data/cie_d65_5nm.txt"), 2);
        let value = c.pop().unwrap_or_default();
        let lambda = c.pop().unwrap_or_default();
        Tabulated { lambda, value }
    });
    &D65
}

/// `∫ ȳ s dλ` over the 1 nm grid (the sum of `ȳ s` at every nanometre).
pub fn y_integral(s: impl Fn(f32) -> f32) -> f32 {
    (0..CMF[1].len())
        .map(|i| f64::from(CMF[1][i]) * f64::from(s(LAMBDA_MIN + i as f32)))
        .sum::<f64>() as f32
}

/// The CIE XYZ of the spectrum `s` (`∫ x̄ s dλ / ∫ ȳ dλ` ...), sums over the
/// 1 nm grid as pbrt-v4's `SpectrumToXYZ`.
pub fn spectrum_to_xyz(s: impl Fn(f32) -> f32) -> [f32; 3] {
    let mut xyz = [0.0f64; 3];
    for i in 0..CMF[0].len() {
        let v = f64::from(s(LAMBDA_MIN + i as f32));
        for c in 0..3 {
            xyz[c] += f64::from(CMF[c][i]) * v;
        }
    }
    xyz.map(|v| (v / f64::from(CIE_Y_INTEGRAL)) as f32)
}

/// The chromaticity `(x, y)` of an XYZ triple.
pub fn chromaticity(xyz: [f32; 3]) -> [f32; 2] {
    let s = xyz[0] + xyz[1] + xyz[2];
    [xyz[0] / s, xyz[1] / s]
}

/// The CIE daylight illuminant of correlated colour temperature `t` kelvin
/// (CIE 015:2018 §3.1, defined for 4000–25000 K and extrapolated outside,
/// as pbrt-v4 does), from the `S0 + M1 S1 + M2 S2` basis, relative power.
pub fn daylight(t: f32) -> Tabulated {
    static BASIS: LazyLock<Vec<Vec<f32>>> =
        LazyLock::new(|| columns(include_str!("../data/cie_daylight_s012_5nm.txt"), 4));
    let t = f64::from(t);
    // Chromaticity of the daylight locus (CIE 015:2018 eqs. 3.3, 3.4).
    let x = if t <= 7000.0 {
        -4.607e9 / t.powi(3) + 2.9678e6 / t.powi(2) + 0.09911e3 / t + 0.244063
    } else {
        -2.0064e9 / t.powi(3) + 1.9018e6 / t.powi(2) + 0.24748e3 / t + 0.23704
    };
    let y = -3.0 * x * x + 2.870 * x - 0.275;
    let m = 0.0241 + 0.2562 * x - 0.7341 * y;
    let m1 = ((-1.3515 - 1.7703 * x + 5.9114 * y) / m) as f32;
    let m2 = ((0.0300 - 31.4424 * x + 30.0717 * y) / m) as f32;
    let b = &*BASIS;
    Tabulated {
        lambda: b[0].clone(),
        value: (0..b[0].len())
            .map(|i| b[1][i] + m1 * b[2][i] + m2 * b[3][i])
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_have_their_published_extents() {
        let t = xyz_bar_table();
        assert!(t.iter().all(|c| c.len() == 471));
        // ȳ peaks at 1 at 555 nm; its 1 nm sum is pbrt-v4's CIE_Y_integral.
        assert_eq!(xyz_bar(555.0)[1], 1.0);
        let sum: f64 = t[1].iter().map(|&v| f64::from(v)).sum();
        assert!((sum as f32 - CIE_Y_INTEGRAL).abs() < 1e-3, "{sum}");
        assert_eq!(d65().eval(560.0), 100.0);
        assert_eq!(xyz_bar(359.0), [0.0; 3]);
    }

    #[test]
    fn d65_has_the_srgb_white_chromaticity() {
        let xy = chromaticity(spectrum_to_xyz(|l| d65().eval(l)));
        assert!(
            (xy[0] - 0.3127).abs() < 2e-4 && (xy[1] - 0.3290).abs() < 2e-4,
            "{xy:?}"
        );
        // The daylight series at 6504 K is D65 (CIE 015:2018, within its rounding).
        let d = daylight(6504.0);
        let xy2 = chromaticity(spectrum_to_xyz(|l| d.eval(l)));
        assert!(
            (xy2[0] - xy[0]).abs() < 5e-4 && (xy2[1] - xy[1]).abs() < 5e-4,
            "{xy2:?}"
        );
    }

    #[test]
    fn tabulated_interpolates_linearly_and_is_zero_outside() {
        let t = Tabulated {
            lambda: vec![400.0, 500.0, 600.0],
            value: vec![1.0, 3.0, 2.0],
        };
        assert_eq!(t.eval(450.0), 2.0);
        assert_eq!(t.eval(600.0), 2.0);
        assert_eq!(t.eval(399.0), 0.0);
        assert_eq!(t.eval(f32::NAN), 0.0);
        assert_eq!(t.scaled(2.0).eval(550.0), 5.0);
    }
}
