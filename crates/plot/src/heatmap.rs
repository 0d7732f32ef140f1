//! Heatmaps: a grid of values (row 0 at the top) shown through a colour map,
//! with a title and a colour bar labelled with the value range (its ends
//! and middle, in a font that scales with the picture), and the
//! [`quantile`] that scales an error map so that a few outliers do not wash
//! it out. Values outside the range are clamped to the colour map's ends;
//! NaN is drawn magenta, a colour the maps never produce.

use crate::Error;
use crate::axis::short;
use crate::canvas::{Anchor, Canvas, Raster, Shape, Stroke, TextStyle};
use crate::color::{Color, ColorMap};

/// A heatmap of `width x height` values.
#[derive(Debug, Clone, PartialEq)]
pub struct Heatmap {
    /// Title above the image.
    pub title: String,
    /// Columns of values.
    pub width: u32,
    /// Rows of values.
    pub height: u32,
    /// `width * height` values, row-major, row 0 at the top.
    pub values: Vec<f64>,
    /// Colour map.
    pub colormap: ColorMap,
    /// Values mapped to the two ends of the colour map (`None`: the finite
    /// minimum and maximum of the data).
    pub range: Option<[f64; 2]>,
    /// Displayed pixels per value (nearest-neighbour magnification).
    pub scale: f32,
}

impl Heatmap {
    /// A viridis heatmap, range from the data, one screen pixel per value.
    pub fn new(
        title: impl Into<String>,
        width: u32,
        height: u32,
        values: Vec<f64>,
    ) -> Result<Self, Error> {
        if width == 0 || height == 0 || values.len() != width as usize * height as usize {
            return Err(Error::InvalidData(format!(
                "a {width}x{height} heatmap needs {} values, got {}",
                width as usize * height as usize,
                values.len()
            )));
        }
        Ok(Heatmap {
            title: title.into(),
            width,
            height,
            values,
            colormap: ColorMap::Viridis,
            range: None,
            scale: 1.0,
        })
    }

    /// The value range mapped to the colour map's ends.
    pub fn value_range(&self) -> [f64; 2] {
        if let Some(r) = self.range {
            return r;
        }
        let finite = self.values.iter().copied().filter(|v| v.is_finite());
        let lo = finite.clone().fold(f64::INFINITY, f64::min);
        let hi = finite.fold(f64::NEG_INFINITY, f64::max);
        if lo > hi { [0.0, 1.0] } else { [lo, hi] }
    }

    /// The values as colours, one pixel each.
    pub fn to_raster(&self) -> Raster {
        let [lo, hi] = self.value_range();
        let span = if hi > lo { hi - lo } else { 1.0 };
        let mut rgba = Vec::with_capacity(self.values.len() * 4);
        for &v in &self.values {
            let c = self.colormap.map((v - lo) / span);
            rgba.extend_from_slice(&[c.r, c.g, c.b, 255]);
        }
        Raster {
            width: self.width,
            height: self.height,
            rgba,
        }
    }

    /// Draws the heatmap with its title and colour bar.
    pub fn to_canvas(&self) -> Canvas {
        let img_w = self.width as f32 * self.scale;
        let img_h = self.height as f32 * self.scale;
        // Reports show a heatmap at about half its size beside two other
        // images: the labels scale with the picture's longer side.
        let font = (img_w.max(img_h) / 22.0).clamp(12.0, 28.0);
        let pad = font;
        let top = 2.4 * font;
        let bar_w = 1.5 * font;
        let label_w = 6.0 * font;
        let width = (pad + img_w + pad + bar_w + 0.5 * font + label_w).ceil() as u32;
        let height = (top + img_h + pad).ceil() as u32;
        let mut canvas = Canvas::new(width, height);
        canvas.text(
            [pad + img_w / 2.0, 1.6 * font],
            &self.title,
            TextStyle::new(font, Anchor::Middle),
        );
        canvas.push(Shape::Image {
            origin: [pad, top],
            size: [img_w, img_h],
            raster: self.to_raster(),
        });
        let border = Some(Stroke::solid(Color::BLACK, 1.0));
        canvas.rect([pad, top], [img_w, img_h], None, border);
        // Colour bar: a 1 x 64 raster, top = high.
        let steps = 64u32;
        let mut rgba = Vec::with_capacity(steps as usize * 4);
        for k in 0..steps {
            let c = self.colormap.map(1.0 - f64::from(k) / f64::from(steps - 1));
            rgba.extend_from_slice(&[c.r, c.g, c.b, 255]);
        }
        let bar_x = pad + img_w + pad;
        let bar = Raster {
            width: 1,
            height: steps,
            rgba,
        };
        canvas.push(Shape::Image {
            origin: [bar_x, top],
            size: [bar_w, img_h],
            raster: bar,
        });
        canvas.rect([bar_x, top], [bar_w, img_h], None, border);
        let [lo, hi] = self.value_range();
        let label = TextStyle::new(0.9 * font, Anchor::Start).mono();
        let lx = bar_x + bar_w + 0.4 * font;
        canvas.text([lx, top + 0.8 * font], short(hi), label);
        canvas.text(
            [lx, top + 0.5 * img_h + 0.3 * font],
            short(0.5 * (lo + hi)),
            label,
        );
        canvas.text([lx, top + img_h], short(lo), label);
        canvas
    }
}

/// The `q`-quantile of the finite values, `q` in `(0, 1]`: the
/// `ceil(q n)`-th smallest of the `n` finite values (the largest for
/// `q = 1`). `None` without finite values or for `q` outside `(0, 1]`.
pub fn quantile(values: &[f64], q: f64) -> Option<f64> {
    if !(q > 0.0 && q <= 1.0) {
        return None;
    }
    let mut finite: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
    if finite.is_empty() {
        return None;
    }
    finite.sort_by(f64::total_cmp);
    let index = ((q * finite.len() as f64).ceil() as usize).clamp(1, finite.len()) - 1;
    Some(finite[index])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantile_is_the_ceil_q_n_th_smallest_finite_value() {
        let v = [4.0, 0.0, 2.0, 1.0, f64::NAN, f64::INFINITY];
        // Finite values sorted: 0, 1, 2, 4.
        assert_eq!(quantile(&v, 0.5), Some(1.0));
        assert_eq!(quantile(&v, 0.51), Some(2.0));
        assert_eq!(quantile(&v, 1.0), Some(4.0));
        assert_eq!(quantile(&v, 1e-9), Some(0.0));
        assert_eq!(quantile(&v, 0.0), None);
        assert_eq!(quantile(&v, 1.5), None);
        assert_eq!(quantile(&[f64::NAN], 0.5), None);
    }

    #[test]
    fn values_beyond_the_range_clamp_and_nan_is_magenta() {
        let mut h = Heatmap::new("t", 3, 1, vec![-1.0, 7.0, f64::NAN]).unwrap();
        h.range = Some([0.0, 2.0]);
        let r = h.to_raster();
        let v0 = ColorMap::Viridis.map(0.0);
        let v1 = ColorMap::Viridis.map(1.0);
        assert_eq!(&r.rgba[..4], &[v0.r, v0.g, v0.b, 255]);
        assert_eq!(&r.rgba[4..8], &[v1.r, v1.g, v1.b, 255]);
        assert_eq!(&r.rgba[8..], &[255, 0, 255, 255]);
    }

    #[test]
    fn raster_maps_min_and_max_to_the_ends() {
        let h = Heatmap::new("t", 2, 1, vec![5.0, 9.0]).unwrap();
        let r = h.to_raster();
        let v0 = ColorMap::Viridis.map(0.0);
        let v1 = ColorMap::Viridis.map(1.0);
        assert_eq!(&r.rgba[..4], &[v0.r, v0.g, v0.b, 255]);
        assert_eq!(&r.rgba[4..], &[v1.r, v1.g, v1.b, 255]);
    }

    #[test]
    fn wrong_value_count_is_an_error() {
        assert!(Heatmap::new("t", 2, 2, vec![0.0; 3]).is_err());
        assert!(Heatmap::new("t", 0, 2, vec![]).is_err());
    }

    #[test]
    fn renders_to_both_formats() {
        let mut h = Heatmap::new("ramp", 8, 4, (0..32).map(f64::from).collect()).unwrap();
        h.scale = 10.0;
        let c = h.to_canvas();
        assert!(c.to_svg().contains("data:image/png;base64,"));
        assert_eq!(&c.to_png().unwrap()[..4], b"\x89PNG");
    }
}
