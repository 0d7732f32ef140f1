//! Image maps: texel storage with pbrt-v4's colour encodings for 8-bit files,
//! wrap modes and bilinear lookups.
//!
//! **Decoding as pbrt-v4** (its `Image::Read`): a PNG file's codes (8- or
//! 16-bit) are decoded with the texture's `encoding` parameter (`sRGB`,
//! `linear` or `gamma G`; pbrt-v4's default for `.png` is sRGB). Every other
//! 8-bit format is read by pbrt-v4 through stb_image and tagged sRGB whatever
//! `encoding` says; of those, lowdisc reads TGA (an 8-bit TGA is therefore
//! always sRGB). Float formats (EXR, HDR, PFM) hold linear values, taken as
//! they are. See [`ColorEncoding::for_file`].
//!
//! Lookups follow pbrt-v4's `Image::Bilerp`: a coordinate `s` in `[0,1]`
//! maps to the continuous texel position `s * width - 0.5`, so texel `i`'s
//! centre is at `s = (i + 0.5) / width`. Row 0 is the *top* of the file; the
//! image texture flips `t` before looking up (see [`super::ImageTexture`]).

use super::TextureError;
use crate::content_hash::{ContentHash, ContentSink};
use lowdisc_image::{ImageFormat, ReadOptions, RgbImage, Transfer, read_image_with, srgb_decode};
use std::path::Path;

/// How the 8-bit (or 16-bit) codes of a PNG or TGA file become linear
/// values (pbrt-v4's `encoding` parameter, which only PNG files obey; see
/// [`ColorEncoding::for_file`]). Float images (EXR, HDR, PFM) are always
/// linear.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ColorEncoding {
    /// The sRGB curve.
    Srgb,
    /// `code / max`.
    Linear,
    /// `(code / max) ^ gamma`.
    Gamma(f32),
}

impl ColorEncoding {
    /// Parses pbrt's `"sRGB"`, `"linear"` or `"gamma G"`.
    pub fn parse(s: &str) -> Result<ColorEncoding, TextureError> {
        let bad = || TextureError::UnknownEncoding(s.to_string());
        match s {
            "sRGB" | "srgb" => Ok(ColorEncoding::Srgb),
            "linear" => Ok(ColorEncoding::Linear),
            _ => {
                let g = s.strip_prefix("gamma").ok_or_else(bad)?;
                let g: f32 = g.trim().parse().map_err(|_| bad())?;
                if g > 0.0 && g.is_finite() {
                    Ok(ColorEncoding::Gamma(g))
                } else {
                    Err(bad())
                }
            }
        }
    }

    /// The encoding pbrt-v4 decodes the file `path` with when the texture
    /// declares `declared` (`None`: no `encoding` parameter): a PNG obeys
    /// `declared` (sRGB when absent); float files (EXR, HDR, PFM) are linear;
    /// every other file (8-bit TGA) is sRGB, whatever `declared` says.
    ///
    /// ```
    /// use lowdisc_render::texture::ColorEncoding;
    /// use std::path::Path;
    /// let lin = Some(ColorEncoding::Linear);
    /// assert_eq!(ColorEncoding::for_file(Path::new("a.png"), lin), ColorEncoding::Linear);
    /// assert_eq!(ColorEncoding::for_file(Path::new("a.png"), None), ColorEncoding::Srgb);
    /// assert_eq!(ColorEncoding::for_file(Path::new("a.tga"), lin), ColorEncoding::Srgb);
    /// assert_eq!(ColorEncoding::for_file(Path::new("a.exr"), None), ColorEncoding::Linear);
    /// ```
    pub fn for_file(path: &Path, declared: Option<ColorEncoding>) -> ColorEncoding {
        if Self::is_float_file(path) {
            return ColorEncoding::Linear;
        }
        match ImageFormat::from_extension(path) {
            Some(ImageFormat::Png) => declared.unwrap_or(ColorEncoding::Srgb),
            _ => ColorEncoding::Srgb,
        }
    }

    /// pbrt-v4's default for an image file without an `encoding` parameter:
    /// [`ColorEncoding::for_file`] with `None` (linear only for float files).
    pub fn default_for(path: &Path) -> ColorEncoding {
        Self::for_file(path, None)
    }

    /// Whether `path` names a float image (EXR, HDR, PFM), whose values no
    /// encoding applies to.
    pub fn is_float_file(path: &Path) -> bool {
        ImageFormat::from_extension(path).is_some_and(|f| f.is_high_dynamic_range())
    }

    /// Decodes a normalised code `v` in `[0,1]`.
    pub fn decode(self, v: f32) -> f32 {
        match self {
            ColorEncoding::Srgb => srgb_decode(v),
            ColorEncoding::Linear => v,
            ColorEncoding::Gamma(g) => v.max(0.0).powf(g),
        }
    }
}

/// What a lookup outside `[0,1]^2` sees (pbrt's `wrap` parameter).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum WrapMode {
    /// Tile the image (the default).
    #[default]
    Repeat,
    /// Extend the edge texels.
    Clamp,
    /// Black outside the image.
    Black,
}

impl WrapMode {
    /// Parses `"repeat"`, `"clamp"` or `"black"` (pbrt-v4's `octahedralsphere`
    /// is not supported here).
    pub fn parse(s: &str) -> Result<WrapMode, TextureError> {
        match s {
            "repeat" => Ok(WrapMode::Repeat),
            "clamp" => Ok(WrapMode::Clamp),
            "black" => Ok(WrapMode::Black),
            _ => Err(TextureError::UnknownWrap(s.to_string())),
        }
    }
}

/// A linear RGB texture image.
#[derive(Clone, Debug, PartialEq)]
pub struct TexImage {
    image: RgbImage,
}

impl TexImage {
    /// Wraps a linear image.
    pub fn new(image: RgbImage) -> TexImage {
        TexImage { image }
    }

    /// Reads an image file; for 8-bit/16-bit formats the codes are decoded
    /// with `encoding` (as given: [`ColorEncoding::for_file`] is the
    /// caller's choice of it), float formats are taken as they are.
    pub fn load(path: &Path, encoding: ColorEncoding) -> Result<TexImage, TextureError> {
        // sRGB codes are decoded by the reader (8-bit ones from its table of
        // the curve's values, without a `powf` per texel channel).
        let transfer = match encoding {
            ColorEncoding::Srgb => Transfer::Srgb,
            _ => Transfer::Raw,
        };
        let image = read_image_with(path, &ReadOptions { transfer })?;
        let float = ColorEncoding::is_float_file(path);
        if float || !matches!(encoding, ColorEncoding::Gamma(_)) {
            return Ok(TexImage { image });
        }
        Ok(TexImage {
            image: image.map(|p| p.map(|v| encoding.decode(v))),
        })
    }

    /// The image.
    pub fn image(&self) -> &RgbImage {
        &self.image
    }
    /// `[width, height]`.
    pub fn resolution(&self) -> [usize; 2] {
        [self.image.width(), self.image.height()]
    }

    /// Texel `(x, y)` (row 0 at the top) under `wrap`.
    pub fn texel(&self, x: i64, y: i64, wrap: WrapMode) -> [f32; 3] {
        let (w, h) = (self.image.width() as i64, self.image.height() as i64);
        let (x, y) = match wrap {
            WrapMode::Repeat => (x.rem_euclid(w), y.rem_euclid(h)),
            WrapMode::Clamp => (x.clamp(0, w - 1), y.clamp(0, h - 1)),
            WrapMode::Black => {
                if x < 0 || x >= w || y < 0 || y >= h {
                    return [0.0; 3];
                }
                (x, y)
            }
        };
        self.image.get(x as usize, y as usize).unwrap_or([0.0; 3])
    }

    /// Bilinear interpolation at image coordinates `st` in `[0,1]^2` (s to
    /// the right, t down), texel centres at `(i + 0.5) / size`.
    pub fn bilerp(&self, st: [f32; 2], wrap: WrapMode) -> [f32; 3] {
        let x = f64::from(st[0]) * self.image.width() as f64 - 0.5;
        let y = f64::from(st[1]) * self.image.height() as f64 - 0.5;
        if !(x.is_finite() && y.is_finite()) {
            return [0.0; 3];
        }
        let (xf, yf) = (x.floor(), y.floor());
        let (dx, dy) = ((x - xf) as f32, (y - yf) as f32);
        // Saturating casts keep absurd coordinates from overflowing.
        let (xi, yi) = (xf as i64, yf as i64);
        let v00 = self.texel(xi, yi, wrap);
        let v10 = self.texel(xi + 1, yi, wrap);
        let v01 = self.texel(xi, yi + 1, wrap);
        let v11 = self.texel(xi + 1, yi + 1, wrap);
        std::array::from_fn(|c| {
            (1.0 - dx) * (1.0 - dy) * v00[c]
                + dx * (1.0 - dy) * v10[c]
                + (1.0 - dx) * dy * v01[c]
                + dx * dy * v11[c]
        })
    }
}

impl ContentHash for WrapMode {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let tag: u8 = match self {
            WrapMode::Repeat => 0,
            WrapMode::Clamp => 1,
            WrapMode::Black => 2,
        };
        tag.feed(sink);
    }
}

/// The texels: width, height and every pixel's linear RGB.
impl ContentHash for TexImage {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let TexImage { image } = self;
        [image.width(), image.height()].feed(sink);
        image.pixels().feed(sink);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_textures_hold_the_curve_of_every_8_bit_code_bit_for_bit() {
        let codes: Vec<[f32; 3]> = (0..=255u8).map(|k| [f32::from(k) / 255.0; 3]).collect();
        let path = std::env::temp_dir().join(format!("lowdisc-srgb-{}.png", std::process::id()));
        // Written from the raw codes, so that each texel holds its code.
        let raw = RgbImage::from_pixels(256, 1, codes.clone()).unwrap();
        let encoded = raw.map(|p| p.map(srgb_decode));
        lowdisc_image::write_png(&path, &encoded, 1.0).unwrap();
        let texture = TexImage::load(&path, ColorEncoding::Srgb).unwrap();
        let _ = std::fs::remove_file(&path);
        for (k, code) in codes.iter().enumerate() {
            let got = texture.texel(k as i64, 0, WrapMode::Clamp)[0];
            assert_eq!(got.to_bits(), srgb_decode(code[0]).to_bits(), "code {k}");
        }
    }
}
