//! The report's images: each render as linear EXR and sRGB PNG, its
//! magnified central crop, and its per-pixel relative-squared-error heatmap
//! with a colour bar.

use std::path::{Path, PathBuf};

use anyhow::Result;
use lowdisc_image::{
    PixelError, RgbImage, crop, pixel_errors, upscale_nearest, write_exr, write_png,
};
use lowdisc_plot::{Heatmap, quantile};

/// Nearest-neighbour magnification of the crops.
pub const CROP_ZOOM: usize = 4;

/// The crop window: a quarter of each side, around the image centre.
fn crop_window(w: usize, h: usize) -> [usize; 4] {
    let cw = (w / 4).max(1);
    let ch = (h / 4).max(1);
    [(w - cw) / 2, (h - ch) / 2, cw, ch]
}

/// `stem.exr` (linear radiance), `stem.png` (sRGB) and `stem_crop.png`;
/// returns the three paths.
pub fn save_with_crop(dir: &Path, stem: &str, image: &RgbImage) -> Result<[PathBuf; 3]> {
    let files = ["", "_crop"].map(|s| dir.join(format!("{stem}{s}.png")));
    let exr = dir.join(format!("{stem}.exr"));
    write_exr(&exr, image)?;
    write_png(&files[0], image, 1.0)?;
    let [x, y, w, h] = crop_window(image.width(), image.height());
    let c = upscale_nearest(&crop(image, x, y, w, h)?, CROP_ZOOM)?;
    write_png(&files[1], &c, 1.0)?;
    let [png, crop_png] = files;
    Ok([exr, png, crop_png])
}

/// The quantile of the per-pixel errors that the heatmaps' colour bar ends at.
pub const HEATMAP_QUANTILE: f64 = 0.99;

/// The per-pixel relative squared error of `image` against `reference`
/// (channel mean).
pub fn pixel_error_values(image: &RgbImage, reference: &RgbImage) -> Result<Vec<f64>> {
    Ok(pixel_errors(image, reference, PixelError::RelativeSquared)?
        .into_iter()
        .map(f64::from)
        .collect())
}

/// The top of the common colour scale: the [`HEATMAP_QUANTILE`] of all
/// the renders' errors together (their maximum when that is 0; 1 when
/// every error is 0).
pub fn common_scale(renders: &[RgbImage], reference: &RgbImage) -> Result<f64> {
    let mut all = Vec::new();
    for image in renders {
        all.extend(pixel_error_values(image, reference)?);
    }
    Ok(quantile(&all, HEATMAP_QUANTILE)
        .filter(|q| *q > 0.0)
        .or_else(|| quantile(&all, 1.0))
        .filter(|q| *q > 0.0)
        .unwrap_or(1.0))
}

/// `name_relse.png`: the per-pixel relative squared error of `image`
/// against `reference`, viridis from 0 to `top` (larger errors clamp to the
/// top colour), with a labelled colour bar, magnified to about 512 pixels
/// across; returns its path.
pub fn save_error_heatmap(
    dir: &Path,
    name: &str,
    image: &RgbImage,
    reference: &RgbImage,
    top: f64,
) -> Result<PathBuf> {
    let errors = pixel_error_values(image, reference)?;
    let (w, h) = (image.width() as u32, image.height() as u32);
    let mut map = Heatmap::new(format!("{name}: relative squared error"), w, h, errors)?;
    map.range = Some([0.0, top]);
    map.scale = (512 / w).max(1) as f32;
    let file = dir.join(format!("{name}_relse.png"));
    map.to_canvas().save(&file)?;
    Ok(file)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_common_scale_pools_every_render() {
        let reference = RgbImage::filled(10, 10, [1.0; 3]).unwrap();
        let exact = reference.clone();
        assert_eq!(
            common_scale(std::slice::from_ref(&exact), &reference).unwrap(),
            1.0
        );
        // One render off by 1 everywhere: relative squared error 1 / 1.01.
        let off = RgbImage::filled(10, 10, [2.0; 3]).unwrap();
        let top = common_scale(&[exact, off], &reference).unwrap();
        assert!((top - 1.0 / 1.01).abs() < 1e-6, "{top}");
    }

    #[test]
    fn the_crop_is_the_central_quarter() {
        assert_eq!(crop_window(32, 24), [12, 9, 8, 6]);
        assert_eq!(crop_window(2, 2), [0, 0, 1, 1]);
    }
}
