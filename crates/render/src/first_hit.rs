//! What the camera sees first: per pixel, the fraction of camera rays whose
//! first hit is an emitter (an auxiliary output beside the image, used to
//! leave directly visible lights out of error metrics).
//!
//! For each pixel of the film's pixel bounds (the image that
//! [`crate::render::render`] returns, row-major, top row first),
//! [`emitter_coverage`] traces `grid²` camera rays through the centres of a
//! `grid x grid` raster of sub-pixel positions; ray `(i, j)` uses the lens
//! position `((j + ½)/grid, (i + ½)/grid)` (the transposed raster), so a thin
//! lens is sampled at `grid²` places too and a defocused emitter's blur is
//! seen. A ray *hits an emitter* when its first intersection is an area
//! light with non-black emission towards the camera, or when it escapes and
//! an infinite light is non-black in its direction. No sampler and no
//! random number is involved: the result depends only on the scene and
//! `grid`, whatever the thread count. Samples that a wide pixel filter
//! spreads beyond the pixel are not followed; the caller's mask border
//! covers them (see `lowdisc_image::mask`).

use rayon::prelude::*;

use crate::render::RenderError;
use crate::scene::Scene;
use crate::view::View;

/// The default sub-pixel raster: 4 x 4 rays per pixel.
pub const DEFAULT_COVERAGE_GRID: u32 = 4;
/// The largest raster accepted (64 x 64 rays per pixel).
pub const MAX_COVERAGE_GRID: u32 = 64;

/// Per-pixel fractions of camera rays that first hit an emitter.
#[derive(Debug, Clone, PartialEq)]
pub struct EmitterCoverage {
    /// Width of the image in pixels.
    pub width: usize,
    /// Height of the image in pixels.
    pub height: usize,
    /// Row-major fractions in `[0, 1]`.
    pub fraction: Vec<f32>,
}

impl EmitterCoverage {
    /// Row-major flags: true where any ray of the pixel hit an emitter.
    pub fn any(&self) -> Vec<bool> {
        self.fraction.iter().map(|f| *f > 0.0).collect()
    }
}

/// True when the first hit of the ray is an emitter (see the module doc).
fn sees_emitter(scene: &Scene, ray: &crate::math::Ray) -> bool {
    let lights = scene.lights();
    match scene.intersect(ray) {
        Some(sh) => sh.light.is_some_and(|li| {
            let s = sh.hit.surface;
            !lights[li as usize].l(s.p, s.ng, s.uv, -ray.d).is_black()
        }),
        None => scene
            .infinite_lights()
            .iter()
            .any(|&i| !lights[i].le(ray).is_black()),
    }
}

/// The emitter coverage of every pixel of `scene`'s image through `view`
/// with a `grid x grid` raster of rays per pixel; an error for `grid`
/// outside `1..=MAX_COVERAGE_GRID`.
pub fn emitter_coverage(
    scene: &Scene,
    view: &View,
    grid: u32,
) -> Result<EmitterCoverage, RenderError> {
    if grid == 0 || grid > MAX_COVERAGE_GRID {
        return Err(RenderError::InvalidOptions(format!(
            "emitter coverage grid must be 1 to {MAX_COVERAGE_GRID}, got {grid}"
        )));
    }
    let bounds = view.pixel_bounds();
    let (width, height) = (bounds.width(), bounds.height());
    let camera = view.camera();
    let g = grid as f32;
    let per_pixel = (grid * grid) as f32;
    let rows: Vec<Vec<f32>> = (0..height)
        .into_par_iter()
        .map(|row| {
            let y = bounds.min[1] + row as i32;
            (0..width)
                .map(|col| {
                    let x = bounds.min[0] + col as i32;
                    let mut hits = 0u32;
                    for i in 0..grid {
                        for j in 0..grid {
                            let (fi, fj) = (i as f32 + 0.5, j as f32 + 0.5);
                            let film_pos = [x as f32 + fi / g, y as f32 + fj / g];
                            let ray = camera.generate_ray(film_pos, [fj / g, fi / g]);
                            hits += u32::from(sees_emitter(scene, &ray));
                        }
                    }
                    hits as f32 / per_pixel
                })
                .collect()
        })
        .collect();
    Ok(EmitterCoverage {
        width,
        height,
        fraction: rows.concat(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cornell::cornell_box;
    use crate::math::Point3;

    #[test]
    fn cornell_light_is_seen_only_at_the_top_centre() {
        let (scene, view) = cornell_box([32, 32]).unwrap();
        let c = emitter_coverage(&scene, &view, 4).unwrap();
        assert_eq!((c.width, c.height, c.fraction.len()), (32, 32, 1024));
        let lit: Vec<(usize, usize)> = (0..1024)
            .filter(|&i| c.fraction[i] > 0.0)
            .map(|i| (i % 32, i / 32))
            .collect();
        assert!(!lit.is_empty());
        // The light is small, near the top of the image and centred in x.
        assert!(lit.len() < 40, "{} pixels", lit.len());
        for &(x, y) in &lit {
            assert!(y < 6 && (10..22).contains(&x), "({x}, {y})");
        }
        // Some pixel is fully covered and the outline is partly covered.
        assert!(c.fraction.contains(&1.0));
        assert!(c.fraction.iter().any(|f| *f > 0.0 && *f < 1.0));
        assert_eq!(c.any().iter().filter(|a| **a).count(), lit.len());
    }

    #[test]
    fn coverage_converges_to_the_light_s_projected_area() {
        // The light is an unoccluded planar quad: its image is the
        // quadrilateral of its projected corners (shoelace area, in pixels).
        let (scene, view) = cornell_box([64, 64]).unwrap();
        let corners = [
            [343.0, 548.8, 227.0],
            [343.0, 548.8, 332.0],
            [213.0, 548.8, 332.0],
            [213.0, 548.8, 227.0],
        ]
        .map(|p| {
            view.camera()
                .raster_from_world(Point3::from_array(p))
                .unwrap()
        });
        let exact: f32 = (0..4)
            .map(|k| {
                let (a, b) = (corners[k], corners[(k + 1) % 4]);
                a[0] * b[1] - b[0] * a[1]
            })
            .sum::<f32>()
            .abs()
            / 2.0;
        assert!(exact > 10.0, "{exact}");
        let area = |g| {
            emitter_coverage(&scene, &view, g)
                .unwrap()
                .fraction
                .iter()
                .sum::<f32>()
        };
        let fine = area(32);
        assert!((fine - exact).abs() < 0.01 * exact, "{fine} vs {exact}");
        assert!((area(4) - exact).abs() < 0.08 * exact);
    }

    #[test]
    fn grid_out_of_range_is_an_error() {
        let (scene, view) = cornell_box([4, 4]).unwrap();
        assert!(emitter_coverage(&scene, &view, 0).is_err());
        assert!(emitter_coverage(&scene, &view, MAX_COVERAGE_GRID + 1).is_err());
    }
}
