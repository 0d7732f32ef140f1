//! PNG and TGA input, PNG output, through the `image` crate (PNG and TGA
//! features only).
//!
//! 8-bit and 16-bit codes are colour data in sRGB by default and are decoded
//! with the exact sRGB curve; [`Transfer::Raw`] keeps them as `code / max`
//! for non-colour data (roughness, bump, alpha masks). Grey images become
//! R = G = B; an alpha channel is dropped.

use std::io::Cursor;

use image::{DynamicImage, ImageEncoder, ImageReader, Limits};

use crate::color::{srgb_decode, srgb8_decode, to_srgb8};
use crate::error::{ErrorKind, ImageError, malformed, unsupported};
use crate::image::{MAX_PIXELS, RgbImage, checked_pixel_count};

/// How 8-bit and 16-bit codes of PNG and TGA files become linear values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Transfer {
    /// Codes are sRGB-encoded colour: decode with the exact sRGB curve.
    #[default]
    Srgb,
    /// Codes are linear data: `code / 255` (or `/ 65535`), no curve.
    Raw,
}

/// Which 8-bit container a file is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum LdrFormat {
    Png,
    Tga,
}

impl LdrFormat {
    fn codec(self) -> image::ImageFormat {
        match self {
            LdrFormat::Png => image::ImageFormat::Png,
            LdrFormat::Tga => image::ImageFormat::Tga,
        }
    }
}

/// Maps an `image` crate error to an [`ImageError`].
fn convert(err: image::ImageError, format: LdrFormat) -> ImageError {
    let name = match format {
        LdrFormat::Png => "PNG",
        LdrFormat::Tga => "TGA",
    };
    match err {
        image::ImageError::IoError(io) => {
            ImageError::new(ImageError::io(&io).kind(), format!("{name}: {io}"))
        }
        image::ImageError::Limits(e) => {
            ImageError::new(ErrorKind::TooLarge, format!("{name}: {e}"))
        }
        image::ImageError::Unsupported(e) => unsupported(format!("{name}: {e}")),
        other => malformed(format!("{name}: {other}")),
    }
}

/// Decodes a PNG or TGA file held in memory.
pub(crate) fn decode(
    bytes: &[u8],
    format: LdrFormat,
    transfer: Transfer,
) -> Result<RgbImage, ImageError> {
    // Look at the header first so an absurd size is refused before decoding.
    let (w, h) = ImageReader::with_format(Cursor::new(bytes), format.codec())
        .into_dimensions()
        .map_err(|e| convert(e, format))?;
    let (width, height) = (w as usize, h as usize);
    checked_pixel_count(width, height)?;
    let mut reader = ImageReader::with_format(Cursor::new(bytes), format.codec());
    let mut limits = Limits::default();
    // Room for the largest allowed image at 4 channels of 16 bits.
    limits.max_alloc = Some(MAX_PIXELS as u64 * 8);
    reader.limits(limits);
    let decoded = reader.decode().map_err(|e| convert(e, format))?;
    let pixels: Vec<[f32; 3]> = match decoded {
        DynamicImage::ImageLuma8(_)
        | DynamicImage::ImageLumaA8(_)
        | DynamicImage::ImageRgb8(_)
        | DynamicImage::ImageRgba8(_) => {
            let rgb = decoded.to_rgb8();
            let f: fn(u8) -> f32 = match transfer {
                Transfer::Srgb => srgb8_decode,
                Transfer::Raw => |v| f32::from(v) / 255.0,
            };
            rgb.pixels().map(|p| p.0.map(f)).collect()
        }
        _ => {
            // 16-bit or float: to_rgb32f gives code / 65535 (or the float).
            let rgb = decoded.to_rgb32f();
            rgb.pixels()
                .map(|p| match transfer {
                    Transfer::Srgb => p.0.map(srgb_decode),
                    Transfer::Raw => p.0,
                })
                .collect()
        }
    };
    RgbImage::from_pixels(width, height, pixels)
}

/// Encodes an image as an 8-bit sRGB PNG after multiplying by `exposure`
/// (see [`to_srgb8`]: NaN to 0, clamped, correctly rounded).
pub(crate) fn encode_png(image: &RgbImage, exposure: f32) -> Result<Vec<u8>, ImageError> {
    let (w, h) = (image.width(), image.height());
    let too_large = || ImageError::new(ErrorKind::TooLarge, "PNG sides are limited to 2^32 - 1");
    let (w32, h32) = (
        u32::try_from(w).map_err(|_| too_large())?,
        u32::try_from(h).map_err(|_| too_large())?,
    );
    let bytes: Vec<u8> = to_srgb8(image, exposure).into_iter().flatten().collect();
    let mut out = Vec::new();
    image::codecs::png::PngEncoder::new(&mut out)
        .write_image(&bytes, w32, h32, image::ExtendedColorType::Rgb8)
        .map_err(|e| convert(e, LdrFormat::Png))?;
    Ok(out)
}
