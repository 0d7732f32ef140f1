//! The built-in Cornell box's ceiling light, seen directly (emission only,
//! `max_depth` 0), against its exact per-pixel coverage.
//!
//! With a box pixel filter of radius 0.5 a pixel's expected value is the
//! light's radiance times the fraction of the pixel's square the light
//! covers. The light's outline in the image is computed here from the
//! published data alone, in `f64` and independently of the renderer's
//! camera code: the pinhole at `(278, 273, -800)` looking down `+z`, the
//! field of view `2 atan(12.5 / 35)` on the shorter image axis, the image
//! mirrored in `x` (red wall on the left), raster `y` down, pixel `(i, j)`
//! covering `[i, i+1) x [j, j+1)`. Any disagreement on the light's place,
//! the camera, the pixel filter or the pixel-centre convention moves the
//! outline by a sizeable fraction of a pixel, far beyond the tolerance.

use lowdisc::catalog::SamplerName;
use lowdisc_render::cornell::{CORNELL_LIGHT_RGB, cornell_box};
use lowdisc_render::integrator::PathIntegrator;
use lowdisc_render::render::{NoProgress, RenderOptions, render};

/// The light quad's corners (x, z) at `y = 548.8`, as published.
const LIGHT_XZ: [[f64; 2]; 4] = [
    [343.0, 227.0],
    [343.0, 332.0],
    [213.0, 332.0],
    [213.0, 227.0],
];
const LIGHT_Y: f64 = 548.8;

/// Raster position of world point `p` for a `w x h` image.
fn project(p: [f64; 3], w: f64, h: f64) -> [f64; 2] {
    let t = 12.5 / 35.0; // tan of half the field of view
    // Camera space: mirrored x, y up, looking down +z.
    let (x, y, z) = (-(p[0] - 278.0), p[1] - 273.0, p[2] + 800.0);
    // The screen half-extents: 1 on the shorter axis.
    let (ax, ay) = if w > h { (w / h, 1.0) } else { (1.0, h / w) };
    let (sx, sy) = (x / (z * t), y / (z * t));
    [(sx + ax) / (2.0 * ax) * w, (ay - sy) / (2.0 * ay) * h]
}

/// Clips polygon `poly` to the half-plane `sign * (v[axis] - at) >= 0`.
fn clip(poly: &[[f64; 2]], axis: usize, at: f64, sign: f64) -> Vec<[f64; 2]> {
    let mut out = Vec::new();
    for (k, &a) in poly.iter().enumerate() {
        let b = poly[(k + 1) % poly.len()];
        let (da, db) = (sign * (a[axis] - at), sign * (b[axis] - at));
        if da >= 0.0 {
            out.push(a);
        }
        if (da >= 0.0) != (db >= 0.0) {
            let s = da / (da - db);
            out.push([a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])]);
        }
    }
    out
}

fn area(poly: &[[f64; 2]]) -> f64 {
    let n = poly.len();
    let twice: f64 = (0..n)
        .map(|k| poly[k][0] * poly[(k + 1) % n][1] - poly[(k + 1) % n][0] * poly[k][1])
        .sum();
    twice.abs() / 2.0
}

/// The fraction of each pixel (row-major) that the light quad, grown by
/// `grow_mm` on every side, covers.
fn coverage(w: u32, h: u32, grow_mm: f64) -> Vec<f64> {
    let (cx, cz) = (278.0, 279.5);
    let poly: Vec<[f64; 2]> = LIGHT_XZ
        .iter()
        .map(|&[x, z]| {
            let x = x + grow_mm * (x - cx).signum();
            let z = z + grow_mm * (z - cz).signum();
            project([x, LIGHT_Y, z], f64::from(w), f64::from(h))
        })
        .collect();
    let mut cov = vec![0.0; (w * h) as usize];
    for j in 0..h {
        for i in 0..w {
            let (x, y) = (f64::from(i), f64::from(j));
            let mut q = clip(&poly, 0, x, 1.0);
            q = clip(&q, 0, x + 1.0, -1.0);
            q = clip(&q, 1, y, 1.0);
            q = clip(&q, 1, y + 1.0, -1.0);
            if q.len() >= 3 {
                cov[(j * w + i) as usize] = area(&q);
            }
        }
    }
    cov
}

/// Largest per-pixel difference between `image` (one channel divided by the
/// light's radiance) and `cov`.
fn worst(image: &[f64], cov: &[f64]) -> f64 {
    image
        .iter()
        .zip(cov)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max)
}

#[test]
fn directly_seen_light_covers_each_pixel_exactly() {
    // Not square, so the field of view's axis matters too.
    let (w, h) = (96u32, 64u32);
    let (scene, view) = cornell_box([w, h]).unwrap();
    let opts = RenderOptions {
        integrator: PathIntegrator {
            max_depth: 0,
            ..PathIntegrator::default()
        },
        ..RenderOptions::new(SamplerName::SobolOwen, 3, 1024)
    };
    let out = render(&scene, &view, &opts, &NoProgress).unwrap();
    let cov = coverage(w, h, 0.0);
    let grown = coverage(w, h, 1.0);
    let partial = cov.iter().filter(|&&c| c > 0.0 && c < 1.0).count();
    assert!(partial >= 20, "only {partial} pixels on the outline");
    for (c, &l) in CORNELL_LIGHT_RGB.iter().enumerate() {
        let img: Vec<f64> = out
            .image
            .pixels()
            .iter()
            .map(|p| f64::from(p[c]) / f64::from(l))
            .collect();
        // 1024 Owen-scrambled Sobol points per pixel integrate a straight
        // edge to ~1e-3; a sub-pixel shift of the outline by 0.01 px already
        // moves an edge pixel's coverage by 0.01.
        let err = worst(&img, &cov);
        assert!(err < 0.01, "channel {c}: worst pixel off by {err}");
        let total: f64 = img.iter().sum::<f64>() - cov.iter().sum::<f64>();
        assert!(
            total.abs() < 0.02,
            "channel {c}: total coverage off by {total} px"
        );
        // The test can fail: a light 1 mm larger on each side (its outline
        // ~0.05 px further out) is told apart.
        assert!(worst(&img, &grown) > 0.03, "channel {c}: 1 mm not resolved");
    }
}
