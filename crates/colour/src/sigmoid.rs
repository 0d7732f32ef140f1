//! Jakob & Hanika's RGB-to-spectrum uplift ("A Low-Dimensional Function
//! Space for Efficient Spectral Upsampling", Computer Graphics Forum 38(2),
//! 2019): a reflectance RGB becomes the smooth, bounded spectrum
//! `S(λ) = σ(c0 λ² + c1 λ + c2)` with `σ(x) = ½ + x / (2 √(1 + x²))`.
//!
//! **Fit** ([`SigmoidTable::optimise`], this crate's own implementation of
//! the paper's method). For each RGB of a grid the coefficients minimise the
//! CIE 1976 colour difference (ΔE, CIELAB under the colour space's white)
//! between the target and the RGB of `S` seen under D65 (`∫ x̄ D65 S`, ...,
//! normalised so that `S = 1` gives the white with `Y = 1`, then XYZ→sRGB),
//! by Gauss-Newton iterations with the analytic Jacobian. The grid:
//! for the largest channel `m ∈ {r, g, b}` (3 tables), its value `z` on
//! `res` nodes `smoothstep(smoothstep(k / (res - 1)))` (denser near 0 and 1)
//! and the other two channels divided by `z` on `res x res` uniform nodes.
//! Each column of `z` is solved from `k = res / 5` upwards and then
//! downwards, every cell starting from its neighbour's solution. The fit
//! works on `x = (λ - 360) / 470` and stores coefficients for `λ` in nm.
//! Integrals are the 1 nm sums of [`crate::cie::spectrum_to_xyz`], on 5 nm nodes.
//!
//! **Lookup** ([`SigmoidTable::coefficients`]): greys are exact (`c0 = c1 =
//! 0`, `σ(c2) = v`); other colours interpolate the 8 surrounding cells'
//! coefficients trilinearly.

use crate::cie::{LAMBDA_MAX, LAMBDA_MIN, d65, xyz_bar_table};
use crate::matrix::srgb;

/// `σ(x) = ½ + x / (2 √(1 + x²))`, 0 and 1 at `∓∞`.
#[inline]
pub fn sigmoid(x: f32) -> f32 {
    if x.is_infinite() {
        return if x > 0.0 { 1.0 } else { 0.0 };
    }
    0.5 + x / (2.0 * (1.0 + x * x).sqrt())
}

/// The spectrum of coefficients `c` (for `λ` in nm) at `lambda`.
#[inline]
pub fn eval(c: [f32; 3], lambda: f32) -> f32 {
    sigmoid((c[0] * lambda + c[1]) * lambda + c[2])
}

/// Tabulated sigmoid coefficients over the RGB cube (see the module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct SigmoidTable {
    res: usize,
    z_nodes: Vec<f32>,
    /// `[max channel][z][y][x][c]`, coefficients for `λ` in nm.
    coeffs: Vec<f32>,
}

/// The fit's quadrature: `x` in `[0, 1]` every [`STEP_NM`] nm and the
/// weights of X, Y, Z there. The weights are the 1 nm sums of `x̄ D65`
/// (normalised to `Σ ȳ D65 = 1`) distributed to the nodes by linear
/// interpolation, so a spectrum linear between nodes integrates exactly as
/// on the 1 nm grid, at a fifth of the cost.
struct Quadrature {
    x: Vec<f64>,
    w: [Vec<f64>; 3],
}

/// The spacing of the fit's quadrature nodes.
const STEP_NM: usize = 5;

impl Quadrature {
    fn new() -> Quadrature {
        let cmf = xyz_bar_table();
        let n = cmf[0].len();
        let nodes = (n - 1) / STEP_NM + 1;
        let x = (0..nodes)
            .map(|j| (j * STEP_NM) as f64 / (n - 1) as f64)
            .collect();
        let mut w = [vec![0.0; nodes], vec![0.0; nodes], vec![0.0; nodes]];
        for i in 0..n {
            let e = f64::from(d65().eval(LAMBDA_MIN + i as f32));
            let (j, t) = (i / STEP_NM, (i % STEP_NM) as f64 / STEP_NM as f64);
            for c in 0..3 {
                let v = f64::from(cmf[c][i]) * e;
                w[c][j] += (1.0 - t) * v;
                if t > 0.0 {
                    w[c][j + 1] += t * v;
                }
            }
        }
        let y: f64 = w[1].iter().sum();
        w.iter_mut()
            .for_each(|v| v.iter_mut().for_each(|a| *a /= y));
        Quadrature { x, w }
    }

    /// CIELAB of the spectrum of normalised coefficients `c`, and its
    /// Jacobian `d Lab / d c`.
    fn lab(&self, c: [f64; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
        // Two passes (values, then sums) so that both vectorise.
        let n = self.x.len();
        let (mut s, mut ds) = ([0.0f64; 128], [0.0f64; 128]);
        for i in 0..n {
            let x = self.x[i];
            let p = (c[0] * x + c[1]) * x + c[2];
            let r = 1.0 / (1.0 + p * p).sqrt();
            s[i] = 0.5 + 0.5 * p * r;
            ds[i] = 0.5 * r * r * r;
        }
        let (mut xyz, mut d) = ([0.0; 3], [[0.0; 3]; 3]);
        for k in 0..3 {
            let w = &self.w[k][..n];
            let (mut a, mut b0, mut b1, mut b2) = (0.0, 0.0, 0.0, 0.0);
            for i in 0..n {
                let (x, g) = (self.x[i], w[i] * ds[i]);
                a += w[i] * s[i];
                b0 += g * x * x;
                b1 += g * x;
                b2 += g;
            }
            xyz[k] = a;
            d[k] = [b0, b1, b2];
        }
        let (l, dl) = lab_and_derivative(xyz);
        let mut jac = [[0.0; 3]; 3];
        for r in 0..3 {
            for j in 0..3 {
                jac[r][j] = (0..3).map(|k| dl[r][k] * d[k][j]).sum();
            }
        }
        (l, jac)
    }
}

/// CIE 1976 L*a*b* of `xyz` under the sRGB white (Y = 1).
fn lab(xyz: [f64; 3]) -> [f64; 3] {
    lab_and_derivative(xyz).0
}

/// CIELAB of `xyz` and `d Lab / d XYZ`.
fn lab_and_derivative(xyz: [f64; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
    let w = srgb().xyz_from_rgb.apply([1.0; 3]);
    let d = 6.0 / 29.0;
    let f = |t: f64| {
        if t > d * d * d {
            (t.cbrt(), 1.0 / (3.0 * t.cbrt() * t.cbrt()))
        } else {
            (t / (3.0 * d * d) + 4.0 / 29.0, 1.0 / (3.0 * d * d))
        }
    };
    let [(fx, gx), (fy, gy), (fz, gz)] = [0, 1, 2].map(|k| f(xyz[k] / w[k]));
    let [gx, gy, gz] = [gx / w[0], gy / w[1], gz / w[2]];
    (
        [116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)],
        [
            [0.0, 116.0 * gy, 0.0],
            [500.0 * gx, -500.0 * gy, 0.0],
            [0.0, 200.0 * gy, -200.0 * gz],
        ],
    )
}

/// Solves `a x = b` (3x3) by the inverse; `None` when singular.
fn solve3(a: [[f64; 3]; 3], b: [f64; 3]) -> Option<[f64; 3]> {
    let m = crate::matrix::Mat3(a).inverse()?;
    Some(m.apply(b))
}

/// Gauss-Newton from `c` towards the CIELAB `target`; returns the new `c`.
fn gauss_newton(q: &Quadrature, target: [f64; 3], mut c: [f64; 3]) -> [f64; 3] {
    for _ in 0..20 {
        let (l, jac) = q.lab(c);
        let r = [l[0] - target[0], l[1] - target[1], l[2] - target[2]];
        if r.iter().map(|v| v * v).sum::<f64>() < 1e-10 {
            break;
        }
        let Some(d) = solve3(jac, r) else { break };
        for j in 0..3 {
            c[j] -= d[j];
        }
        let m = c.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        if m > 200.0 {
            c = c.map(|v| v * 200.0 / m);
        }
    }
    c
}

fn smoothstep(x: f64) -> f64 {
    x * x * (3.0 - 2.0 * x)
}

/// The coefficients `[z][y][x][c]` of the table whose largest channel is `m`.
fn fit_channel(q: &Quadrature, z_nodes: &[f32], m: usize) -> Vec<f32> {
    let res = z_nodes.len();
    let to_xyz = srgb().xyz_from_rgb;
    let mut coeffs = vec![0.0f32; res * res * res * 3];
    let (span, lmin) = (f64::from(LAMBDA_MAX - LAMBDA_MIN), f64::from(LAMBDA_MIN));
    let start = res / 5;
    for j in 0..res {
        let y = j as f64 / (res - 1) as f64;
        for i in 0..res {
            let x = i as f64 / (res - 1) as f64;
            let mut c = [0.0; 3];
            for k in (start..res).chain((0..start).rev()) {
                if k + 1 == start {
                    c = [0.0; 3];
                }
                let z = f64::from(z_nodes[k]);
                let mut rgb = [0.0; 3];
                rgb[m] = z;
                rgb[(m + 1) % 3] = x * z;
                rgb[(m + 2) % 3] = y * z;
                c = gauss_newton(q, lab(to_xyz.apply(rgb)), c);
                // From x = (λ - lmin) / span to λ in nm.
                let (a, b, d) = (c[0], c[1], c[2]);
                let out = [
                    a / (span * span),
                    b / span - 2.0 * a * lmin / (span * span),
                    d - b * lmin / span + a * lmin * lmin / (span * span),
                ];
                let at = ((k * res + j) * res + i) * 3;
                for (dst, v) in coeffs[at..at + 3].iter_mut().zip(out) {
                    *dst = v as f32;
                }
            }
        }
    }
    coeffs
}

impl SigmoidTable {
    /// Fits the table at resolution `res` (at least 2) for sRGB under D65,
    /// the three largest-channel tables on three threads.
    pub fn optimise(res: usize) -> SigmoidTable {
        let res = res.max(2);
        let q = Quadrature::new();
        let z_nodes: Vec<f32> = (0..res)
            .map(|k| smoothstep(smoothstep(k as f64 / (res - 1) as f64)) as f32)
            .collect();
        let tables: Vec<Vec<f32>> = std::thread::scope(|s| {
            let handles: Vec<_> = (0..3)
                .map(|m| {
                    let (q, z) = (&q, &z_nodes);
                    s.spawn(move || fit_channel(q, z, m))
                })
                .collect();
            handles
                .into_iter()
                .map(|h| h.join().expect("the fit does not panic"))
                .collect()
        });
        SigmoidTable {
            res,
            z_nodes,
            coeffs: tables.concat(),
        }
    }

    /// The grid resolution.
    pub fn resolution(&self) -> usize {
        self.res
    }

    /// The table as bytes: `res` (u32), the `z` nodes and the coefficients
    /// (f32), little-endian.
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut out = (self.res as u32).to_le_bytes().to_vec();
        for v in self.z_nodes.iter().chain(&self.coeffs) {
            out.extend_from_slice(&v.to_le_bytes());
        }
        out
    }

    /// The table written by [`SigmoidTable::to_bytes`], or `None` when the
    /// bytes do not hold one.
    pub fn from_bytes(bytes: &[u8]) -> Option<SigmoidTable> {
        let res = u32::from_le_bytes(bytes.get(..4)?.try_into().ok()?) as usize;
        let floats: Vec<f32> = bytes[4..]
            .chunks_exact(4)
            .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
            .collect();
        let n = 9 * res.checked_pow(3)?;
        if res < 2 || floats.len() != res + n {
            return None;
        }
        Some(SigmoidTable {
            res,
            z_nodes: floats[..res].to_vec(),
            coeffs: floats[res..].to_vec(),
        })
    }

    /// The coefficients (for `λ` in nm) of the reflectance `rgb`, each
    /// channel in `[0, 1]`.
    pub fn coefficients(&self, rgb: [f32; 3]) -> [f32; 3] {
        let rgb = rgb.map(|v| v.clamp(0.0, 1.0));
        if rgb[0] == rgb[1] && rgb[1] == rgb[2] {
            let v = rgb[0];
            return [0.0, 0.0, (v - 0.5) / (v * (1.0 - v)).sqrt()];
        }
        let m = if rgb[0] > rgb[1] {
            if rgb[0] > rgb[2] { 0 } else { 2 }
        } else if rgb[1] > rgb[2] {
            1
        } else {
            2
        };
        let res = self.res;
        let z = rgb[m];
        let scale = (res - 1) as f32 / z;
        let x = rgb[(m + 1) % 3] * scale;
        let y = rgb[(m + 2) % 3] * scale;
        let zi = self.z_nodes.partition_point(|&n| n <= z).clamp(1, res - 1) - 1;
        let dz = (z - self.z_nodes[zi]) / (self.z_nodes[zi + 1] - self.z_nodes[zi]);
        let (xi, yi) = ((x as usize).min(res - 2), (y as usize).min(res - 2));
        let (dx, dy) = (x - xi as f32, y - yi as f32);
        let at = |k: usize, j: usize, i: usize, c: usize| {
            self.coeffs[(((m * res + k) * res + j) * res + i) * 3 + c]
        };
        let lerp = |t: f32, a: f32, b: f32| a + t * (b - a);
        std::array::from_fn(|c| {
            let plane = |k: usize| {
                lerp(
                    dy,
                    lerp(dx, at(k, yi, xi, c), at(k, yi, xi + 1, c)),
                    lerp(dx, at(k, yi + 1, xi, c), at(k, yi + 1, xi + 1, c)),
                )
            };
            lerp(dz, plane(zi), plane(zi + 1))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sigmoid_limits_and_greys() {
        assert_eq!(sigmoid(0.0), 0.5);
        assert_eq!(sigmoid(f32::INFINITY), 1.0);
        assert_eq!(sigmoid(f32::NEG_INFINITY), 0.0);
        let t = SigmoidTable::optimise(2);
        for v in [0.0f32, 0.18, 0.5, 1.0] {
            let s = eval(t.coefficients([v; 3]), 550.0);
            assert!((s - v).abs() < 1e-6, "{v} -> {s}");
        }
    }

    #[test]
    fn the_fit_reproduces_the_rgb_of_its_grid_nodes() {
        // Interior nodes of a res-16 grid (z nodes are exact fit points; the
        // error left is the 5 nm quadrature's, against the 1 nm sums).
        let t = SigmoidTable::optimise(16);
        let white = crate::cie::spectrum_to_xyz(|l| d65().eval(l))[1];
        let mut worst = 0.0f32;
        for k in (3..14).step_by(2) {
            let z = t.z_nodes[k];
            for (a, b) in [(3, 7), (11, 2), (14, 13), (0, 9)] {
                let rgb = [z, z * a as f32 / 15.0, z * b as f32 / 15.0];
                let c = t.coefficients(rgb);
                let xyz = crate::cie::spectrum_to_xyz(|l| eval(c, l) * d65().eval(l) / white);
                let out = srgb().rgb_from_xyz.apply(xyz.map(f64::from));
                for q in 0..3 {
                    worst = worst.max((out[q] as f32 - rgb[q]).abs());
                }
            }
        }
        assert!(worst < 1e-3, "{worst}");
    }

    #[test]
    fn bytes_round_trip_and_reject_garbage() {
        let t = SigmoidTable::optimise(3);
        assert_eq!(SigmoidTable::from_bytes(&t.to_bytes()), Some(t.clone()));
        assert_eq!(SigmoidTable::from_bytes(&[1, 2]), None);
        assert_eq!(SigmoidTable::from_bytes(&t.to_bytes()[..40]), None);
    }
}
