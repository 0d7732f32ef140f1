//! The report's images: each render as linear EXR and sRGB PNG, its
//! magnified central crop, and its per-pixel relative-squared-error heatmap
//! with a colour bar.

use std::path::Path;

use anyhow::Result;
use lowdisc_image::{
    PixelError, RgbImage, crop, pixel_errors, upscale_nearest, write_exr, write_png,
};
use lowdisc_plot::{Heatmap, quantile};

/// Nearest-neighbour magnification of the crops.
const CROP_ZOOM: usize = 4;

/// The crop window: a quarter of each side, around the image centre.
fn crop_window(w: usize, h: usize) -> [usize; 4] {
    let cw = (w / 4).max(1);
    let ch = (h / 4).max(1);
    [(w - cw) / 2, (h - ch) / 2, cw, ch]
}

/// `stem.exr` (linear radiance), `stem.png` (sRGB) and `stem_crop.png`.
pub fn save_with_crop(dir: &Path, stem: &str, image: &RgbImage) -> Result<()> {
    write_exr(dir.join(format!("{stem}.exr")), image)?;
    write_png(dir.join(format!("{stem}.png")), image, 1.0)?;
    let [x, y, w, h] = crop_window(image.width(), image.height());
    let c = upscale_nearest(&crop(image, x, y, w, h)?, CROP_ZOOM)?;
    write_png(dir.join(format!("{stem}_crop.png")), &c, 1.0)?;
    Ok(())
}

/// The quantile of the per-pixel errors that the heatmap's colour bar ends at.
pub const HEATMAP_QUANTILE: f64 = 0.99;

/// `name_relse.png`: the per-pixel relative squared error of `image`
/// against `reference` (channel mean), viridis from 0 to its
/// [`HEATMAP_QUANTILE`] (larger errors clamp to the top colour), with a
/// colour bar, magnified to about 512 pixels across.
pub fn save_error_heatmap(
    dir: &Path,
    name: &str,
    image: &RgbImage,
    reference: &RgbImage,
) -> Result<()> {
    let errors: Vec<f64> = pixel_errors(image, reference, PixelError::RelativeSquared)?
        .into_iter()
        .map(f64::from)
        .collect();
    let top = quantile(&errors, HEATMAP_QUANTILE)
        .filter(|q| *q > 0.0)
        .or_else(|| quantile(&errors, 1.0))
        .filter(|q| *q > 0.0)
        .unwrap_or(1.0);
    let (w, h) = (image.width() as u32, image.height() as u32);
    let mut map = Heatmap::new(format!("{name}: relative squared error"), w, h, errors)?;
    map.range = Some([0.0, top]);
    map.scale = (512 / w).max(1) as f32;
    map.to_canvas()
        .save(dir.join(format!("{name}_relse.png")))?;
    Ok(())
}
