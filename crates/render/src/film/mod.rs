//! pbrt-v4's `Film "rgb"`: per-pixel weighted sums of radiance, tiles for
//! deterministic parallel accumulation, and EXR / PNG output.
//!
//! Each pixel keeps `Σ w L` and `Σ w` in `f64`; its value is their ratio
//! (black where `Σ w = 0`). A sample's radiance is first multiplied by the
//! sensor's imaging ratio, `exposure_time * iso / 100` (pbrt-v4's
//! `PixelSensor`; the exposure time is the camera's shutter interval, 1 by
//! default), then clamped so that its largest channel is at most
//! `maxcomponentvalue` (infinite by default), as pbrt-v4's `RGBFilm` does.
//!
//! Samples whose radiance or weight is NaN or infinite are *counted and
//! dropped*: they add neither radiance nor weight ([`Film::nonfinite_count`]).
//!
//! As in pbrt-v4 with filter importance sampling, a sample only ever goes to
//! the pixel it was generated for (no splatting to neighbours), so tiles are
//! independent: a [`FilmTile`] is filled by one thread and merged into the
//! film with [`Film::merge_tile`]. Merging adds the tile's sums to the film's;
//! for disjoint tiles into a fresh film each pixel receives exactly one
//! addition, so the image is bit-identical whatever the merge order.

pub use lowdisc_tiles::PixelBounds;

use crate::spectrum::Rgb;
use lowdisc_image::{ImageError, RgbImage, WriteOptions};
use std::path::Path;

/// Estimated peak bytes per pixel of a render: the film's `f64` sums (32),
/// the tiles' copies until they are merged (32), the RGB image (12) and its
/// encoded file (up to 20); callers multiply it by the resolution to refuse
/// a film that cannot be allocated, before allocating it.
pub const PEAK_BYTES_PER_PIXEL: u64 = 96;

/// Why a film could not be built or written.
#[derive(Clone, Debug, PartialEq)]
pub enum FilmError {
    /// The resolution has a zero side (or exceeds `i32`).
    InvalidResolution([u32; 2]),
    /// The crop window is not within `[0,1]` with `min < max`.
    InvalidCropWindow([f32; 4]),
    /// The pixel bounds are empty after clipping to the image.
    EmptyPixelBounds([i32; 4]),
    /// ISO, exposure time or maximum component value not positive and finite
    /// (the maximum may be infinite).
    InvalidSensor(&'static str, f32),
    /// Sums given for a film ([`Film::set_sums`]) whose pixel count differs.
    SumCount {
        /// The film's pixels.
        pixels: usize,
        /// The sums given.
        sums: usize,
    },
    /// Building or writing the image failed.
    Image(ImageError),
}

impl std::fmt::Display for FilmError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FilmError::InvalidResolution(r) => {
                write!(f, "film resolution {}x{} is invalid", r[0], r[1])
            }
            FilmError::InvalidCropWindow(c) => write!(f, "film crop window {c:?} is invalid"),
            FilmError::EmptyPixelBounds(b) => write!(f, "film pixel bounds {b:?} are empty"),
            FilmError::InvalidSensor(n, v) => {
                write!(f, "film parameter \"{n}\" = {v} must be positive")
            }
            FilmError::SumCount { pixels, sums } => {
                write!(f, "{sums} pixel sums given for a film of {pixels} pixels")
            }
            FilmError::Image(e) => write!(f, "{e}"),
        }
    }
}

/// No `source()`: the message already contains the image error's.
impl std::error::Error for FilmError {}

impl From<ImageError> for FilmError {
    fn from(e: ImageError) -> Self {
        FilmError::Image(e)
    }
}

/// The parameters of pbrt's `Film "rgb"`.
#[derive(Clone, Debug, PartialEq)]
pub struct FilmParams {
    /// `xresolution`, `yresolution` (pbrt default 1280x720).
    pub resolution: [u32; 2],
    /// `cropwindow` `[x0, x1, y0, y1]` in `[0,1]` (NDC of the full image).
    pub crop_window: Option<[f32; 4]>,
    /// `pixelbounds` `[x0, x1, y0, y1]` in pixels; wins over the crop window.
    pub pixel_bounds: Option<[i32; 4]>,
    /// `iso` (default 100).
    pub iso: f32,
    /// The camera's shutter interval, `shutterclose - shutteropen` (default 1).
    pub exposure_time: f32,
    /// `maxcomponentvalue` (default infinite: no clamping).
    pub max_component_value: f32,
    /// `whitebalance`: 0 (the default) for none, otherwise the colour
    /// temperature (K) whose daylight white becomes the output's white.
    pub white_balance: f32,
    /// `filename` (default `pbrt.exr`).
    pub filename: String,
}

impl Default for FilmParams {
    fn default() -> Self {
        FilmParams {
            resolution: [1280, 720],
            crop_window: None,
            pixel_bounds: None,
            iso: 100.0,
            exposure_time: 1.0,
            max_component_value: f32::INFINITY,
            white_balance: 0.0,
            filename: "pbrt.exr".to_string(),
        }
    }
}

/// One pixel's running sums: `Σ w L` per channel and `Σ w`, each added in
/// sample order from 0.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PixelSum {
    /// The weighted radiance sums `Σ w L` (R, G, B).
    pub rgb: [f64; 3],
    /// The weight sum `Σ w`.
    pub weight: f64,
}

impl PixelSum {
    /// The pixel's value, `Σ w L / Σ w` rounded to `f32` (black where
    /// `Σ w = 0`): the one definition of a pixel from its sums.
    pub fn value(&self) -> [f32; 3] {
        if self.weight == 0.0 {
            return [0.0; 3];
        }
        self.rgb.map(|s| (s / self.weight) as f32)
    }
    /// Adds `o`'s sums to these.
    pub fn add(&mut self, o: &PixelSum) {
        for c in 0..3 {
            self.rgb[c] += o.rgb[c];
        }
        self.weight += o.weight;
    }
}

/// Weighted sums over a rectangle of pixels: the body of both [`Film`] and
/// [`FilmTile`].
#[derive(Clone, Debug)]
struct Accumulator {
    bounds: PixelBounds,
    pixels: Vec<PixelSum>,
    scale: f32,
    max_component: f32,
    nonfinite: u64,
    outside: u64,
}

impl Accumulator {
    fn new(bounds: PixelBounds, scale: f32, max_component: f32) -> Accumulator {
        Accumulator {
            bounds,
            pixels: vec![PixelSum::default(); bounds.area()],
            scale,
            max_component,
            nonfinite: 0,
            outside: 0,
        }
    }

    fn index(&self, p: [i32; 2]) -> Option<usize> {
        self.bounds.contains(p).then(|| {
            (p[1] - self.bounds.min[1]) as usize * self.bounds.width()
                + (p[0] - self.bounds.min[0]) as usize
        })
    }

    fn add(&mut self, p: [i32; 2], rgb: Rgb, weight: f32) {
        let mut c = rgb * self.scale;
        let m = c.max_component();
        if m > self.max_component {
            c *= self.max_component / m;
        }
        if !c.is_finite() || !weight.is_finite() {
            self.nonfinite += 1;
            return;
        }
        let Some(i) = self.index(p) else {
            self.outside += 1;
            return;
        };
        let w = f64::from(weight);
        let px = &mut self.pixels[i];
        for (s, v) in px.rgb.iter_mut().zip(c.to_array()) {
            *s += w * f64::from(v);
        }
        px.weight += w;
    }

    fn value(&self, i: usize) -> [f32; 3] {
        self.pixels[i].value()
    }
}

/// A rectangle of pixel sums owned by one thread; merge it into its film
/// with [`Film::merge_tile`].
#[derive(Clone, Debug)]
pub struct FilmTile {
    acc: Accumulator,
}

impl FilmTile {
    /// The tile's pixels.
    pub fn bounds(&self) -> PixelBounds {
        self.acc.bounds
    }
    /// Adds a sample of radiance `rgb` with filter weight `weight` to `pixel`
    /// (non-finite samples are counted and dropped; pixels outside the tile
    /// are counted in [`Self::outside_count`] and dropped).
    pub fn add_sample(&mut self, pixel: [i32; 2], rgb: Rgb, weight: f32) {
        self.acc.add(pixel, rgb, weight);
    }
    /// Samples dropped for a NaN or infinite value or weight.
    pub fn nonfinite_count(&self) -> u64 {
        self.acc.nonfinite
    }
    /// Samples dropped for falling outside the tile.
    pub fn outside_count(&self) -> u64 {
        self.acc.outside
    }
}

/// pbrt-v4's RGB film.
#[derive(Clone, Debug)]
pub struct Film {
    full_resolution: [u32; 2],
    filename: String,
    acc: Accumulator,
    /// The matrix from the accumulated values to the output (spectral
    /// mode's sensor XYZ, or a white balance; see
    /// [`crate::spectrum::sensor::output_matrix`]).
    output: Option<[[f32; 3]; 3]>,
}

impl Film {
    /// The pixel bounds `params` ask for, after every check [`Film::new`]
    /// makes, without allocating the film (a loader calls it to report a bad
    /// crop window or sensor setting where the scene gives it).
    pub fn checked_bounds(params: &FilmParams) -> Result<PixelBounds, FilmError> {
        let [w, h] = params.resolution;
        if w == 0 || h == 0 || w > i32::MAX as u32 || h > i32::MAX as u32 {
            return Err(FilmError::InvalidResolution(params.resolution));
        }
        let full = PixelBounds::new([0, 0], [w as i32, h as i32]);
        let bounds = if let Some(b) = params.pixel_bounds {
            let pb = PixelBounds::new([b[0], b[2]], [b[1], b[3]]).intersect(&full);
            if pb.area() == 0 {
                return Err(FilmError::EmptyPixelBounds(b));
            }
            pb
        } else if let Some(c) = params.crop_window {
            let ok = c.iter().all(|v| (0.0..=1.0).contains(v)) && c[0] < c[1] && c[2] < c[3];
            if !ok {
                return Err(FilmError::InvalidCropWindow(c));
            }
            // pbrt-v4: ceil(resolution * crop) on both corners.
            let px = |r: u32, t: f32| (f64::from(r) * f64::from(t)).ceil() as i32;
            let pb = PixelBounds::new([px(w, c[0]), px(h, c[2])], [px(w, c[1]), px(h, c[3])]);
            if pb.area() == 0 {
                return Err(FilmError::EmptyPixelBounds([
                    pb.min[0], pb.max[0], pb.min[1], pb.max[1],
                ]));
            }
            pb
        } else {
            full
        };
        for (name, v) in [("iso", params.iso), ("exposuretime", params.exposure_time)] {
            if !(v > 0.0 && v.is_finite()) {
                return Err(FilmError::InvalidSensor(name, v));
            }
        }
        if !(params.max_component_value > 0.0) {
            return Err(FilmError::InvalidSensor(
                "maxcomponentvalue",
                params.max_component_value,
            ));
        }
        Ok(bounds)
    }

    /// A film from pbrt parameters.
    pub fn new(params: &FilmParams) -> Result<Film, FilmError> {
        Film::with_window(params, None)
    }

    /// A film from pbrt parameters that stores only the pixels of `window`
    /// inside its pixel bounds (all of them for `None`): the film of a
    /// render of part of the image, allocated for that part alone.
    pub fn with_window(
        params: &FilmParams,
        window: Option<PixelBounds>,
    ) -> Result<Film, FilmError> {
        let mut bounds = Film::checked_bounds(params)?;
        if let Some(w) = window {
            bounds = w.intersect(&bounds);
        }
        Ok(Film::with_bounds(params, bounds))
    }

    /// A film of `params` that stores the pixels of `bounds`, which the
    /// caller took from [`Film::checked_bounds`] (a view's, checked once).
    pub fn with_bounds(params: &FilmParams, bounds: PixelBounds) -> Film {
        let ratio = params.exposure_time * params.iso / 100.0;
        Film {
            full_resolution: params.resolution,
            filename: params.filename.clone(),
            acc: Accumulator::new(bounds, ratio, params.max_component_value),
            output: None,
        }
    }

    /// The full image resolution (what the camera projects onto).
    pub fn full_resolution(&self) -> [u32; 2] {
        self.full_resolution
    }
    /// The pixels this film stores (the crop).
    pub fn pixel_bounds(&self) -> PixelBounds {
        self.acc.bounds
    }
    /// The `filename` parameter.
    pub fn filename(&self) -> &str {
        &self.filename
    }
    /// The sensor's imaging ratio `exposure_time * iso / 100`.
    pub fn imaging_ratio(&self) -> f32 {
        self.acc.scale
    }

    /// Every pixel's sums, row-major over [`Self::pixel_bounds`].
    pub fn sums(&self) -> &[PixelSum] {
        &self.acc.pixels
    }

    /// Replaces every pixel's sums with `sums` (row-major over
    /// [`Self::pixel_bounds`]), such as the merged sums of a split render's
    /// parts; the counters are kept.
    pub fn set_sums(&mut self, sums: &[PixelSum]) -> Result<(), FilmError> {
        if sums.len() != self.acc.pixels.len() {
            return Err(FilmError::SumCount {
                pixels: self.acc.pixels.len(),
                sums: sums.len(),
            });
        }
        self.acc.pixels.copy_from_slice(sums);
        Ok(())
    }

    /// An empty tile over `bounds` clipped to the film, with the film's
    /// sensor settings.
    pub fn tile(&self, bounds: PixelBounds) -> FilmTile {
        FilmTile {
            acc: Accumulator::new(
                bounds.intersect(&self.acc.bounds),
                self.acc.scale,
                self.acc.max_component,
            ),
        }
    }

    /// Adds a tile's sums and counters to the film.
    pub fn merge_tile(&mut self, tile: &FilmTile) {
        let t = &tile.acc;
        for (k, p) in t.bounds.pixels().enumerate() {
            if let Some(i) = self.acc.index(p) {
                self.acc.pixels[i].add(&t.pixels[k]);
            }
        }
        self.acc.nonfinite += t.nonfinite;
        self.acc.outside += t.outside;
    }

    /// Adds a sample directly to the film (single-threaded use).
    pub fn add_sample(&mut self, pixel: [i32; 2], rgb: Rgb, weight: f32) {
        self.acc.add(pixel, rgb, weight);
    }

    /// Samples dropped for a NaN or infinite value or weight (including merged tiles').
    pub fn nonfinite_count(&self) -> u64 {
        self.acc.nonfinite
    }
    /// Samples dropped for falling outside the film's (or their tile's) pixels.
    pub fn outside_count(&self) -> u64 {
        self.acc.outside
    }

    /// The weighted mean of `pixel`, or `None` outside the pixel bounds.
    pub fn pixel_rgb(&self, pixel: [i32; 2]) -> Option<Rgb> {
        self.acc
            .index(pixel)
            .map(|i| Rgb::from_array(self.value(i)))
    }

    /// Pixels are `m · v` for the accumulated value `v` (the sensor's XYZ
    /// in spectral mode, or RGB to white-balance); `None`, the default: the
    /// accumulated values are the output RGB.
    pub fn set_output_matrix(&mut self, m: Option<[[f32; 3]; 3]>) {
        self.output = m;
    }

    /// Pixel `i`'s output value.
    fn value(&self, i: usize) -> [f32; 3] {
        let v = self.acc.value(i);
        match &self.output {
            None => v,
            Some(m) => crate::spectrum::sensor::sensor_to_output(m, v),
        }
    }

    /// The image of the pixel bounds (its top-left pixel is `pixel_bounds().min`).
    pub fn to_image(&self) -> Result<RgbImage, FilmError> {
        let b = self.acc.bounds;
        let pixels = (0..b.area()).map(|i| self.value(i)).collect();
        Ok(RgbImage::from_pixels(b.width(), b.height(), pixels)?)
    }

    /// Writes the image, choosing the format by extension: `.exr` (linear
    /// float), `.png` (8-bit sRGB after multiplying by `exposure`), `.pfm`, `.hdr`.
    pub fn write(&self, path: impl AsRef<Path>, exposure: f32) -> Result<(), FilmError> {
        lowdisc_image::write_image(path, &self.to_image()?, &WriteOptions { exposure })?;
        Ok(())
    }
}
