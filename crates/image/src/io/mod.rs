//! Reading and writing image files: format detection, `read_image`,
//! `write_image` and per-format helpers.
//!
//! Readers load the whole file, detect the format from its magic bytes (EXR,
//! PNG, PFM and Radiance HDR have one) or else from its extension
//! (case-insensitive; needed for TGA), and decode it in memory, so each
//! decoder is also available on bytes through [`decode_image`]. Writers encode
//! in memory and then write atomically (see [`write_atomically`]).

mod atomic;
mod exr_format;
mod hdr;
mod ldr;
mod pfm;
mod rgbe;

use std::path::Path;

pub use atomic::{write_atomically, write_bytes_atomically};
pub use exr_format::{ExrLayer, read_exr_layer};
pub use ldr::Transfer;
pub use rgbe::{rgb_to_rgbe, rgbe_to_rgb};

use crate::error::{ErrorKind, ImageError};
use crate::image::RgbImage;
use ldr::LdrFormat;

/// An image file format this crate knows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ImageFormat {
    /// OpenEXR (`.exr`): read and write.
    Exr,
    /// Radiance RGBE (`.hdr`, `.rgbe`, `.pic`): read and write.
    Hdr,
    /// Portable float map (`.pfm`): read and write.
    Pfm,
    /// PNG (`.png`): read 8/16-bit, write 8-bit sRGB.
    Png,
    /// Truevision TGA (`.tga`, `.targa`): read only.
    Tga,
}

impl ImageFormat {
    /// The format named by a path's extension (case-insensitive), if any.
    pub fn from_extension(path: impl AsRef<Path>) -> Option<Self> {
        let ext = path.as_ref().extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "exr" => Some(ImageFormat::Exr),
            "hdr" | "rgbe" | "pic" => Some(ImageFormat::Hdr),
            "pfm" => Some(ImageFormat::Pfm),
            "png" => Some(ImageFormat::Png),
            "tga" | "targa" => Some(ImageFormat::Tga),
            _ => None,
        }
    }

    /// The format announced by a file's first bytes, if recognisable (TGA has
    /// no signature and is never detected here).
    pub fn from_magic(bytes: &[u8]) -> Option<Self> {
        if bytes.starts_with(&[0x76, 0x2f, 0x31, 0x01]) {
            Some(ImageFormat::Exr)
        } else if bytes.starts_with(b"\x89PNG\r\n\x1a\n") {
            Some(ImageFormat::Png)
        } else if bytes.starts_with(b"#?") {
            Some(ImageFormat::Hdr)
        } else if bytes.len() >= 3
            && bytes[0] == b'P'
            && (bytes[1] == b'F' || bytes[1] == b'f')
            && bytes[2].is_ascii_whitespace()
        {
            Some(ImageFormat::Pfm)
        } else {
            None
        }
    }

    /// The format of a file: its magic bytes when recognisable, else its
    /// extension; an [`ErrorKind::UnknownFormat`] error when neither tells.
    pub fn detect(path: impl AsRef<Path>, bytes: &[u8]) -> Result<Self, ImageError> {
        let path = path.as_ref();
        Self::from_magic(bytes)
            .or_else(|| Self::from_extension(path))
            .ok_or_else(|| {
                ImageError::new(
                    ErrorKind::UnknownFormat,
                    "neither the file's first bytes nor its extension name a known image format",
                )
                .with_path(path)
            })
    }

    /// The usual lower-case file extension, without the dot.
    pub fn extension(self) -> &'static str {
        match self {
            ImageFormat::Exr => "exr",
            ImageFormat::Hdr => "hdr",
            ImageFormat::Pfm => "pfm",
            ImageFormat::Png => "png",
            ImageFormat::Tga => "tga",
        }
    }

    /// True for formats that store floating-point radiance (EXR, HDR, PFM).
    pub fn is_high_dynamic_range(self) -> bool {
        matches!(self, ImageFormat::Exr | ImageFormat::Hdr | ImageFormat::Pfm)
    }
}

/// Options for reading.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ReadOptions {
    /// How PNG and TGA codes become linear values; ignored by float formats.
    pub transfer: Transfer,
}

impl ReadOptions {
    /// Options that keep 8-bit values raw (`code / 255`), for non-colour data.
    pub fn raw() -> Self {
        ReadOptions {
            transfer: Transfer::Raw,
        }
    }
}

/// Options for writing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WriteOptions {
    /// Linear multiplier applied before 8-bit sRGB quantisation (PNG only;
    /// float formats store the values unchanged). Default 1.
    pub exposure: f32,
}

impl Default for WriteOptions {
    fn default() -> Self {
        WriteOptions { exposure: 1.0 }
    }
}

/// Reads an image file as linear RGB (8-bit formats decoded as sRGB).
pub fn read_image(path: impl AsRef<Path>) -> Result<RgbImage, ImageError> {
    read_image_with(path, &ReadOptions::default())
}

/// Reads an image file as linear RGB with the given options.
pub fn read_image_with(
    path: impl AsRef<Path>,
    options: &ReadOptions,
) -> Result<RgbImage, ImageError> {
    let path = path.as_ref();
    let bytes = lowdisc_files::read_input(path)?;
    let format = ImageFormat::detect(path, &bytes)?;
    decode_image(&bytes, format, options).map_err(|e| e.with_path(path))
}

/// Decodes an image held in memory, in the given format.
pub fn decode_image(
    bytes: &[u8],
    format: ImageFormat,
    options: &ReadOptions,
) -> Result<RgbImage, ImageError> {
    match format {
        ImageFormat::Exr => exr_format::decode(bytes),
        ImageFormat::Hdr => hdr::decode(bytes),
        ImageFormat::Pfm => pfm::decode(bytes),
        ImageFormat::Png => ldr::decode(bytes, LdrFormat::Png, options.transfer),
        ImageFormat::Tga => ldr::decode(bytes, LdrFormat::Tga, options.transfer),
    }
}

/// Encodes an image in memory in the given format (TGA is not written).
pub fn encode_image(
    image: &RgbImage,
    format: ImageFormat,
    options: &WriteOptions,
) -> Result<Vec<u8>, ImageError> {
    match format {
        ImageFormat::Exr => exr_format::encode(image),
        ImageFormat::Hdr => Ok(rgbe::encode(image)),
        ImageFormat::Pfm => Ok(pfm::encode(image)),
        ImageFormat::Png => ldr::encode_png(image, options.exposure),
        ImageFormat::Tga => Err(ImageError::new(
            ErrorKind::Unsupported,
            "writing TGA is not supported; use PNG, EXR, PFM or HDR",
        )),
    }
}

/// Writes an image in the format named by the path's extension, atomically.
pub fn write_image(
    path: impl AsRef<Path>,
    image: &RgbImage,
    options: &WriteOptions,
) -> Result<(), ImageError> {
    let path = path.as_ref();
    let format = ImageFormat::from_extension(path).ok_or_else(|| {
        ImageError::new(
            ErrorKind::UnknownFormat,
            "output extension must be .exr, .png, .pfm or .hdr",
        )
        .with_path(path)
    })?;
    write_image_as(path, image, format, options)
}

/// Writes an image in the given format, atomically, whatever the extension.
pub fn write_image_as(
    path: impl AsRef<Path>,
    image: &RgbImage,
    format: ImageFormat,
    options: &WriteOptions,
) -> Result<(), ImageError> {
    let path = path.as_ref();
    let bytes = encode_image(image, format, options).map_err(|e| e.with_path(path))?;
    write_bytes_atomically(path, &bytes)
}

/// Writes linear 32-bit float RGB OpenEXR, atomically.
pub fn write_exr(path: impl AsRef<Path>, image: &RgbImage) -> Result<(), ImageError> {
    write_image_as(path, image, ImageFormat::Exr, &WriteOptions::default())
}

/// Writes 8-bit sRGB PNG after multiplying by `exposure`, atomically.
pub fn write_png(
    path: impl AsRef<Path>,
    image: &RgbImage,
    exposure: f32,
) -> Result<(), ImageError> {
    write_image_as(path, image, ImageFormat::Png, &WriteOptions { exposure })
}

/// Writes little-endian RGB PFM, atomically.
pub fn write_pfm(path: impl AsRef<Path>, image: &RgbImage) -> Result<(), ImageError> {
    write_image_as(path, image, ImageFormat::Pfm, &WriteOptions::default())
}

/// Writes Radiance RGBE HDR, atomically.
pub fn write_hdr(path: impl AsRef<Path>, image: &RgbImage) -> Result<(), ImageError> {
    write_image_as(path, image, ImageFormat::Hdr, &WriteOptions::default())
}
