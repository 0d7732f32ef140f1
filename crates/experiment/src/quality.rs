//! The per-render measures beyond the plain metrics: the errors with
//! directly visible emitters masked, the blurred (perceptual) MSE and FLIP.
//!
//! **Mask.** Before the renders, the scene's emitter coverage is computed
//! once (`lowdisc_render::first_hit`: a 4x4 raster of camera rays per pixel,
//! lens sampled too): every pixel with a ray whose first hit is an emitter
//! (an area light, or an infinite light seen by an escaping ray, such as the
//! built-in scene's sky) is left out, with a border of `emitter_border`
//! pixels (default [`DEFAULT_EMITTER_BORDER`], 3) around each
//! (`lowdisc_image::mask`). The report states the fraction of pixels kept.
//! If the mask would keep nothing (an image that is all sky), every pixel is
//! kept instead and the report says so through the kept fraction 1.
//!
//! **Blurred MSE.** The error image blurred by a Gaussian of `blur_sigma`
//! pixels (default 1) before squaring, by normalised convolution over the
//! kept pixels (`lowdisc_image::perceptual`): masked pixels never leak.
//!
//! **FLIP.** NVIDIA's LDR FLIP at 67 pixels per degree on the 8-bit sRGB
//! encodings (exposure 1), masked pixels of the render replaced by the
//! reference's, mean over the kept pixels (`lowdisc_image::flip`).

use anyhow::Result;
use lowdisc_image::flip::DEFAULT_PIXELS_PER_DEGREE;
use lowdisc_image::{
    ErrorStats, PixelMask, RgbImage, blurred_mse, flip_error, masked_error_metrics,
};
use lowdisc_render::first_hit::{DEFAULT_COVERAGE_GRID, emitter_coverage};
use lowdisc_render::scene::Scene;
use lowdisc_render::view::View;
use serde::Serialize;

pub use lowdisc_image::DEFAULT_EMITTER_BORDER;
pub use lowdisc_image::perceptual::DEFAULT_SIGMA as DEFAULT_BLUR_SIGMA;

/// The extra measures of one render.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Quality {
    /// Linear MSE, relMSE, RMSE, MAE over the kept pixels.
    pub masked: ErrorStats,
    /// Linear MSE of the Gaussian-blurred error over the kept pixels.
    pub blurred_mse: f64,
    /// Mean FLIP error over the kept pixels.
    pub flip: f64,
}

/// What every render of one scene is measured with.
#[derive(Debug, Clone)]
pub struct Evaluator {
    mask: PixelMask,
    sigma: f64,
}

impl Evaluator {
    /// The evaluator of `scene` seen through `view`: its emitter mask with
    /// `border` pixels, and a blur of `sigma` pixels.
    pub fn new(scene: &Scene, view: &View, border: u32, sigma: f64) -> Result<Evaluator> {
        let coverage = emitter_coverage(scene, view, DEFAULT_COVERAGE_GRID)?;
        let (w, h) = (coverage.width, coverage.height);
        let mut mask = PixelMask::excluding(w, h, &coverage.any(), border)?;
        if mask.kept() == 0 {
            mask = PixelMask::all(w, h);
        }
        Ok(Evaluator { mask, sigma })
    }

    /// The fraction of pixels the metrics keep.
    pub fn kept_fraction(&self) -> f64 {
        self.mask.kept_fraction()
    }

    /// The mask.
    pub fn mask(&self) -> &PixelMask {
        &self.mask
    }

    /// The measures of `image` against `reference`.
    pub fn measure(&self, image: &RgbImage, reference: &RgbImage) -> Result<Quality> {
        Ok(Quality {
            masked: masked_error_metrics(image, reference, &self.mask)?.linear,
            blurred_mse: blurred_mse(image, reference, Some(&self.mask), self.sigma)?,
            flip: flip_error(
                image,
                reference,
                Some(&self.mask),
                DEFAULT_PIXELS_PER_DEGREE,
            )?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use lowdisc_render::cornell::cornell_box;

    #[test]
    fn cornell_mask_drops_the_light_and_its_border_only() {
        let (scene, view) = cornell_box([64, 64]).unwrap();
        let e = Evaluator::new(&scene, &view, 3, 1.0).unwrap();
        let kept = e.kept_fraction();
        assert!(kept > 0.9 && kept < 1.0, "{kept}");
        let wider = Evaluator::new(&scene, &view, 5, 1.0)
            .unwrap()
            .kept_fraction();
        assert!(wider < kept);
        // The light is at the top centre: the bottom row is kept.
        assert!((0..64).all(|x| e.mask().keeps(x, 63)));
        let centre = view
            .camera()
            .raster_from_world(lowdisc_render::math::Point3::new(278.0, 548.8, 279.5))
            .unwrap();
        let (cx, cy) = (centre[0] as usize, centre[1] as usize);
        assert!(cy < 16 && !e.mask().keeps(cx, cy) && !e.mask().keeps(cx, cy + 3));
    }

    #[test]
    fn a_render_equal_to_the_reference_measures_zero() {
        let (scene, view) = cornell_box([16, 16]).unwrap();
        let e = Evaluator::new(&scene, &view, 3, 1.0).unwrap();
        let img =
            RgbImage::from_fn(16, 16, |x, y| [x as f32 / 16.0, y as f32 / 16.0, 0.2]).unwrap();
        let q = e.measure(&img, &img).unwrap();
        assert_eq!((q.masked.mse, q.blurred_mse, q.flip), (0.0, 0.0, 0.0));
    }
}
