//! 3x3 matrices ([`Mat3`], `f64`), the XYZ↔RGB matrices of a colour space
//! given by its primaries' and white's chromaticities, sRGB ([`srgb`]) and
//! von Kries white balance in the Bradford cone space ([`white_balance`]).
//!
//! As in pbrt-v4, sRGB's white is the chromaticity of the D65 *spectrum*
//! (computed from the CIE tables, 0.3127, 0.3290 to four digits) rather than
//! the rounded nominal value, so that D65 light renders exactly white.

use crate::cie::{chromaticity, d65, spectrum_to_xyz};
use std::sync::LazyLock;

/// A row-major 3x3 matrix.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mat3(pub [[f64; 3]; 3]);

impl Mat3 {
    /// The identity.
    pub const IDENTITY: Mat3 = Mat3([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);

    /// A diagonal matrix.
    pub fn diagonal(d: [f64; 3]) -> Mat3 {
        Mat3([[d[0], 0.0, 0.0], [0.0, d[1], 0.0], [0.0, 0.0, d[2]]])
    }

    /// `self * v`.
    pub fn apply(&self, v: [f64; 3]) -> [f64; 3] {
        self.0.map(|r| r[0] * v[0] + r[1] * v[1] + r[2] * v[2])
    }

    /// `self * o`.
    pub fn mul(&self, o: &Mat3) -> Mat3 {
        let mut m = [[0.0; 3]; 3];
        for (i, row) in m.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                *v = (0..3).map(|k| self.0[i][k] * o.0[k][j]).sum();
            }
        }
        Mat3(m)
    }

    /// The inverse, or `None` when singular.
    pub fn inverse(&self) -> Option<Mat3> {
        let a = &self.0;
        let cof = |r0: usize, r1: usize, c0: usize, c1: usize| {
            a[r0][c0] * a[r1][c1] - a[r0][c1] * a[r1][c0]
        };
        let c = [
            [cof(1, 2, 1, 2), -cof(1, 2, 0, 2), cof(1, 2, 0, 1)],
            [-cof(0, 2, 1, 2), cof(0, 2, 0, 2), -cof(0, 2, 0, 1)],
            [cof(0, 1, 1, 2), -cof(0, 1, 0, 2), cof(0, 1, 0, 1)],
        ];
        let det = a[0][0] * c[0][0] + a[0][1] * c[0][1] + a[0][2] * c[0][2];
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        // The inverse is the transposed cofactor matrix over the determinant.
        Some(Mat3(std::array::from_fn(|i| {
            std::array::from_fn(|j| c[j][i] / det)
        })))
    }

    /// The entries as `f32`.
    pub fn to_f32(&self) -> [[f32; 3]; 3] {
        self.0.map(|r| r.map(|v| v as f32))
    }
}

/// XYZ (Y = 1 for the white) of chromaticity `xy`.
fn xy_to_xyz(xy: [f64; 2]) -> [f64; 3] {
    [xy[0] / xy[1], 1.0, (1.0 - xy[0] - xy[1]) / xy[1]]
}

/// An RGB colour space: its matrices and white chromaticity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ColourSpace {
    /// Linear RGB to XYZ (RGB white (1, 1, 1) to the white with Y = 1).
    pub xyz_from_rgb: Mat3,
    /// XYZ to linear RGB.
    pub rgb_from_xyz: Mat3,
    /// The white's chromaticity.
    pub white: [f64; 2],
}

impl ColourSpace {
    /// The colour space of primaries `r`, `g`, `b` and white `w`
    /// (chromaticities), or `None` when the primaries are degenerate.
    pub fn new(r: [f64; 2], g: [f64; 2], b: [f64; 2], w: [f64; 2]) -> Option<ColourSpace> {
        let [pr, pg, pb] = [r, g, b].map(xy_to_xyz);
        let p = Mat3([
            [pr[0], pg[0], pb[0]],
            [pr[1], pg[1], pb[1]],
            [pr[2], pg[2], pb[2]],
        ]);
        let s = p.inverse()?.apply(xy_to_xyz(w));
        let xyz_from_rgb = p.mul(&Mat3::diagonal(s));
        Some(ColourSpace {
            xyz_from_rgb,
            rgb_from_xyz: xyz_from_rgb.inverse()?,
            white: w,
        })
    }
}

/// sRGB (IEC 61966-2-1 primaries) with the white of the D65 spectrum.
pub fn srgb() -> &'static ColourSpace {
    static SRGB: LazyLock<ColourSpace> = LazyLock::new(|| {
        let w = chromaticity(spectrum_to_xyz(|l| d65().eval(l))).map(f64::from);
        ColourSpace::new([0.64, 0.33], [0.30, 0.60], [0.15, 0.06], w)
            .expect("the sRGB primaries are independent")
    });
    &SRGB
}

/// Bradford's cone response matrix (Lam 1985), XYZ to LMS.
const BRADFORD: Mat3 = Mat3([
    [0.8951, 0.2664, -0.1614],
    [-0.7502, 1.7135, 0.0367],
    [0.0389, -0.0685, 1.0296],
]);

/// The XYZ-to-XYZ matrix that maps white `src` (chromaticity) to white
/// `dst` by scaling the Bradford cone responses (von Kries adaptation).
pub fn white_balance(src: [f64; 2], dst: [f64; 2]) -> Mat3 {
    let (s, d) = (
        BRADFORD.apply(xy_to_xyz(src)),
        BRADFORD.apply(xy_to_xyz(dst)),
    );
    let inv = BRADFORD.inverse().expect("Bradford's matrix is invertible");
    inv.mul(&Mat3::diagonal([d[0] / s[0], d[1] / s[1], d[2] / s[2]]))
        .mul(&BRADFORD)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
        a.iter().zip(b).all(|(x, y)| (x - y).abs() < tol)
    }

    #[test]
    fn srgb_matrices_are_the_standards() {
        let s = srgb();
        // IEC 61966-2-1's XYZ-to-sRGB first row, to its 4 published digits.
        let r = s.rgb_from_xyz.0[0];
        assert!(close(r, [3.2406, -1.5372, -0.4986], 2e-3), "{r:?}");
        assert!(close(
            s.xyz_from_rgb.apply([1.0; 3]),
            xy_to_xyz(s.white),
            1e-12
        ));
        let id = s.rgb_from_xyz.mul(&s.xyz_from_rgb);
        assert!((0..3).all(|i| close(id.0[i], Mat3::IDENTITY.0[i], 1e-12)));
    }

    #[test]
    fn white_balance_maps_white_to_white_and_is_identity_for_equal_whites() {
        let (a, b) = ([0.3457, 0.3585], srgb().white);
        let m = white_balance(a, b);
        let w = m.apply(xy_to_xyz(a));
        assert!(close(w, xy_to_xyz(b), 1e-9), "{w:?}");
        let id = white_balance(b, b);
        assert!((0..3).all(|i| close(id.0[i], Mat3::IDENTITY.0[i], 1e-12)));
        assert!(Mat3([[1.0; 3]; 3]).inverse().is_none());
    }
}
