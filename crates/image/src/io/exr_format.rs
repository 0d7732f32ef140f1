//! OpenEXR input and output through the `exr` crate.
//!
//! Reading takes the first valid layer at its largest resolution level
//! (scanline or tiled, any compression `exr` supports, half/float/uint
//! samples) and picks the channels `R`, `G`, `B` (exact names first, then a
//! layer-prefixed name such as `diffuse.R`); a file with `Y` only, or a single
//! channel of any name, is read as grey. Luminance-chroma (`Y`, `RY`, `BY`)
//! files, subsampled channels and deep data are refused as unsupported.
//! Writing produces one RGB layer of 32-bit floats, ZIP-compressed scanlines.
//! The reader ([`read_exr_layer`]) is also the part files' (`lowdisc-split`),
//! which check their own header on it before the pixels are decoded.
//! Both directions run on the calling thread (`exr` would otherwise build a
//! new thread pool on every call, inside the renderer's own pool).

use std::io::Cursor;

use exr::prelude::{
    Encoding, FlatSamples, Image, Layer, LayerAttributes, ReadChannels, ReadLayers,
    SpecificChannels, Vec2, WritableImage,
};

use crate::error::{ErrorKind, ImageError, malformed, unsupported};
use crate::image::{RgbImage, checked_pixel_count};

/// Maps an `exr` error to an [`ImageError`].
fn convert(err: exr::error::Error) -> ImageError {
    match err {
        exr::error::Error::Aborted => ImageError::new(ErrorKind::Io, "EXR operation aborted"),
        exr::error::Error::NotSupported(what) => unsupported(format!("EXR: {what}")),
        exr::error::Error::Invalid(what) => malformed(format!("EXR: {what}")),
        exr::error::Error::Io(io) => {
            ImageError::new(ImageError::io(&io).kind(), format!("EXR: {io}"))
        }
    }
}

/// Index of the channel called `name`: the exact name, else a name whose last
/// `.`-separated component equals it (case-insensitive).
fn find_channel(names: &[String], name: &str) -> Option<usize> {
    names.iter().position(|n| n == name).or_else(|| {
        names.iter().position(|n| {
            n.rsplit('.')
                .next()
                .is_some_and(|last| last.eq_ignore_ascii_case(name))
        })
    })
}

/// The first valid layer of an OpenEXR file: every channel, at the
/// layer's largest resolution level, with the layer's attributes.
pub type ExrLayer = exr::image::Layer<exr::image::AnyChannels<FlatSamples>>;

/// Reads the first valid layer of the OpenEXR file held in `bytes`, on the
/// calling thread: the one EXR reader of the workspace. The headers are
/// read and checked alone first (no deep data, every layer within
/// [`crate::MAX_PIXELS`]), so an absurd data window is refused before
/// anything is allocated for the pixels, and handed to `inspect`, which
/// can refuse the file on its headers too; its value is returned with the
/// layer.
///
/// ```
/// use lowdisc_image::{RgbImage, encode_image, ImageFormat, WriteOptions};
/// use lowdisc_image::io::read_exr_layer;
///
/// let image = RgbImage::from_pixels(2, 1, vec![[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]).unwrap();
/// let bytes = encode_image(&image, ImageFormat::Exr, &WriteOptions::default()).unwrap();
/// let (layers, layer) =
///     read_exr_layer(&bytes, |headers| Ok::<_, lowdisc_image::ImageError>(headers.len())).unwrap();
/// assert_eq!((layers, layer.size.0, layer.size.1), (1, 2, 1));
/// ```
pub fn read_exr_layer<T, E: From<ImageError>>(
    bytes: &[u8],
    inspect: impl FnOnce(&[exr::meta::header::Header]) -> Result<T, E>,
) -> Result<(T, ExrLayer), E> {
    let meta =
        exr::meta::MetaData::read_from_buffered(Cursor::new(bytes), false).map_err(convert)?;
    if meta.headers.is_empty() {
        return Err(malformed("EXR file has no header").into());
    }
    for header in &meta.headers {
        if header.deep {
            return Err(unsupported("EXR deep data").into());
        }
        checked_pixel_count(header.layer_size.0, header.layer_size.1)
            .map_err(|e| ImageError::new(e.kind(), format!("EXR layer: {}", e.message())))?;
    }
    let inspected = inspect(&meta.headers)?;
    let image = exr::prelude::read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .first_valid_layer()
        .all_attributes()
        .non_parallel()
        .from_buffered(Cursor::new(bytes))
        .map_err(convert)?;
    Ok((inspected, image.layer_data))
}

/// Decodes an OpenEXR file held in memory.
pub fn decode(bytes: &[u8]) -> Result<RgbImage, ImageError> {
    let ((), layer) = read_exr_layer(bytes, |_| Ok::<_, ImageError>(()))?;
    let (width, height) = (layer.size.0, layer.size.1);
    let n = checked_pixel_count(width, height)?;
    let channels = &layer.channel_data.list;
    let names: Vec<String> = channels.iter().map(|c| c.name.to_string()).collect();

    let rgb = ["R", "G", "B"].map(|c| find_channel(&names, c));
    let selected: [usize; 3] = match rgb {
        [Some(r), Some(g), Some(b)] => [r, g, b],
        _ => {
            let chroma =
                find_channel(&names, "RY").is_some() || find_channel(&names, "BY").is_some();
            match (find_channel(&names, "Y"), chroma) {
                (Some(_), true) => {
                    return Err(unsupported("EXR luminance-chroma (Y, RY, BY) images"));
                }
                (Some(y), false) => [y; 3],
                (None, _) if channels.len() == 1 => [0; 3],
                _ => {
                    return Err(unsupported(format!(
                        "EXR channels {names:?}: need R, G and B, or Y alone"
                    )));
                }
            }
        }
    };

    let mut planes: Vec<Vec<f32>> = Vec::with_capacity(3);
    for &index in &selected {
        let channel = &channels[index];
        if channel.sampling != Vec2(1, 1) {
            return Err(unsupported(format!(
                "EXR channel {} is subsampled",
                names[index]
            )));
        }
        let plane: Vec<f32> = match &channel.sample_data {
            FlatSamples::F16(v) => v.iter().map(|h| h.to_f32()).collect(),
            FlatSamples::F32(v) => v.clone(),
            FlatSamples::U32(v) => v.iter().map(|&u| u as f32).collect(),
        };
        if plane.len() != n {
            return Err(malformed(format!(
                "EXR channel {} has {} samples for {width}x{height} pixels",
                names[index],
                plane.len()
            )));
        }
        planes.push(plane);
    }
    let pixels = (0..n)
        .map(|i| [planes[0][i], planes[1][i], planes[2][i]])
        .collect();
    RgbImage::from_pixels(width, height, pixels)
}

/// Encodes an image as an OpenEXR file: one RGB layer of 32-bit floats,
/// ZIP compression in blocks of 16 scanlines.
pub fn encode(image: &RgbImage) -> Result<Vec<u8>, ImageError> {
    let width = image.width();
    let pixels = image.pixels();
    let channels = SpecificChannels::rgb(|pos: Vec2<usize>| {
        let p = pixels[pos.1 * width + pos.0];
        (p[0], p[1], p[2])
    });
    let layer = Layer::new(
        (width, image.height()),
        LayerAttributes::default(),
        Encoding::SMALL_LOSSLESS,
        channels,
    );
    let mut out = Cursor::new(Vec::new());
    Image::from_layer(layer)
        .write()
        .non_parallel()
        .to_buffered(&mut out)
        .map_err(convert)?;
    Ok(out.into_inner())
}
