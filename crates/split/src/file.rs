//! Part files: a [`RenderPart`] as an OpenEXR image that any EXR viewer
//! shows, and that holds its exact sums.
//!
//! Schema (one scanline layer, ZIP-compressed):
//! * display window: the full image, `(0, 0)` to the resolution; data
//!   window: the part's pixel window (full-image pixel coordinates).
//! * channels `R`, `G`, `B` (32-bit float): the pixel values,
//!   [`RenderPart::values`] of the sums (linear sRGB, spectral renders
//!   included).
//! * channels `sum.R.hi`, `sum.R.lo`, `sum.G.*`, `sum.B.*`, `sum.W.*`
//!   (32-bit unsigned): the high and low halves of the bits of each pixel's
//!   `f64` sums `Σ w L` (R, G, B) and `Σ w` (W), so merging is exact.
//! * attribute `lowdisc.part` (text): a JSON object, [`HEADER_FORMAT`] in
//!   `format`, and `scene` (the scene hash), `settings` (name to value),
//!   `resolution` `[w, h]`, `film_bounds` and `window` `[x0, x1, y0, y1]`,
//!   `samples` `[start, end]`, `spp`, `nonfinite`.
//!
//! Reading checks the header before the pixels are decoded (so a forged
//! window cannot allocate without bound), then that the data window,
//! channels and values agree with it.

use crate::part::{PartInfo, RenderPart};
use exr::prelude::{
    AnyChannel, AnyChannels, AttributeValue, Encoding, FlatSamples, Image, ImageAttributes,
    IntegerBounds, Layer, LayerAttributes, SmallVec, Text, Vec2, WritableImage,
};
use lowdisc_image::ImageError;
use lowdisc_image::io::read_exr_layer;
use lowdisc_render::film::{PixelBounds, PixelSum};
use lowdisc_render::render::SampleRange;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::io::Cursor;
use std::path::Path;

/// The `format` of a part header this version writes and reads.
pub const HEADER_FORMAT: &str = "lowdisc-part/1";
/// The EXR attribute holding the part header.
pub const HEADER_ATTRIBUTE: &str = "lowdisc.part";
/// The largest part file read (a 16k x 16k window of 11 channels, compressed).
pub const MAX_PART_BYTES: u64 = 16 << 30;

/// The sums' channels, in the order of a pixel's `[R, G, B, W]`.
const SUMS: [&str; 4] = ["sum.R", "sum.G", "sum.B", "sum.W"];

/// Why a part file could not be read or written (the message names no file:
/// callers add it).
#[derive(Debug)]
pub struct PartError(pub String);

impl std::fmt::Display for PartError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for PartError {}

impl From<ImageError> for PartError {
    fn from(e: ImageError) -> Self {
        PartError(format!("not a readable EXR file ({e})"))
    }
}

impl From<lowdisc_files::Error> for PartError {
    fn from(e: lowdisc_files::Error) -> Self {
        PartError(e.to_string())
    }
}

fn bad(message: impl Into<String>) -> PartError {
    PartError(message.into())
}

/// The JSON header.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Header {
    format: String,
    scene: String,
    settings: BTreeMap<String, String>,
    resolution: [u32; 2],
    film_bounds: [i32; 4],
    window: [i32; 4],
    samples: [u32; 2],
    spp: u32,
    nonfinite: u64,
}

fn to_array(b: &PixelBounds) -> [i32; 4] {
    [b.min[0], b.max[0], b.min[1], b.max[1]]
}

fn from_array(b: [i32; 4]) -> PixelBounds {
    PixelBounds::new([b[0], b[2]], [b[1], b[3]])
}

/// Encodes `part` as a part file's bytes.
pub fn encode_part(part: &RenderPart) -> Result<Vec<u8>, PartError> {
    let i = &part.info;
    let header = Header {
        format: HEADER_FORMAT.into(),
        scene: i.scene.clone(),
        settings: i.settings.clone(),
        resolution: i.resolution,
        film_bounds: to_array(&i.film_bounds),
        window: to_array(&i.window),
        samples: [i.samples.start, i.samples.end],
        spp: i.spp,
        nonfinite: i.nonfinite,
    };
    let json = serde_json::to_string(&header).map_err(|e| bad(e.to_string()))?;
    let text = Text::new_or_none(&json).ok_or_else(|| bad("part header is not ASCII"))?;
    let mut channels: SmallVec<[AnyChannel<FlatSamples>; 4]> = SmallVec::new();
    let values = part.values();
    for (c, name) in ["R", "G", "B"].iter().enumerate() {
        let plane = values.iter().map(|v| v[c]).collect();
        channels.push(AnyChannel::new(*name, FlatSamples::F32(plane)));
    }
    for (c, name) in SUMS.iter().enumerate() {
        let word = |s: &PixelSum| [s.rgb[0], s.rgb[1], s.rgb[2], s.weight][c].to_bits();
        let hi = part.sums.iter().map(|s| (word(s) >> 32) as u32).collect();
        let lo = part.sums.iter().map(|s| word(s) as u32).collect();
        channels.push(AnyChannel::new(
            format!("{name}.hi").as_str(),
            FlatSamples::U32(hi),
        ));
        channels.push(AnyChannel::new(
            format!("{name}.lo").as_str(),
            FlatSamples::U32(lo),
        ));
    }
    let mut attributes = LayerAttributes {
        layer_position: Vec2(i.window.min[0], i.window.min[1]),
        ..LayerAttributes::default()
    };
    let name = Text::new_or_none(HEADER_ATTRIBUTE).expect("an ASCII name");
    attributes.other.insert(name, AttributeValue::Text(text));
    let size = (i.window.width(), i.window.height());
    let layer = Layer::new(
        size,
        attributes,
        Encoding::SMALL_LOSSLESS,
        AnyChannels::sort(channels),
    );
    let [w, h] = i.resolution;
    let display = IntegerBounds::new((0, 0), (w as usize, h as usize));
    let mut out = Cursor::new(Vec::new());
    Image::new(ImageAttributes::new(display), layer)
        .write()
        .non_parallel()
        .to_buffered(&mut out)
        .map_err(|e| bad(format!("EXR: {e}")))?;
    Ok(out.into_inner())
}

/// Decodes a part file's bytes: the EXR is read by the image crate's
/// reader ([`read_exr_layer`]), which hands over the headers first; the part
/// header and the data window are checked on them before any pixel is
/// decoded.
pub fn decode_part(bytes: &[u8]) -> Result<RenderPart, PartError> {
    let (info, layer) = read_exr_layer(bytes, |headers| {
        let [header] = headers else {
            return Err(bad("a part file has exactly one EXR layer"));
        };
        let key = Text::new_or_none(HEADER_ATTRIBUTE).expect("an ASCII name");
        let info = parse_header(header.own_attributes.other.get(&key))?;
        let w = info.window;
        let data = &header.own_attributes.layer_position;
        if (data.0, data.1) != (w.min[0], w.min[1])
            || (header.layer_size.0, header.layer_size.1) != (w.width(), w.height())
        {
            return Err(bad("the EXR data window differs from the header's window"));
        }
        Ok(info)
    })?;
    let w = info.window;
    let channels = &layer.channel_data.list;
    let n = w.area();
    let u32s = |name: String| -> Result<&Vec<u32>, PartError> {
        match channels.iter().find(|c| c.name.to_string() == name) {
            Some(AnyChannel {
                sample_data: FlatSamples::U32(v),
                ..
            }) if v.len() == n => Ok(v),
            _ => Err(bad(format!(
                "channel {name} is missing or not {n} u32 samples"
            ))),
        }
    };
    let mut words = Vec::with_capacity(4);
    for name in SUMS {
        let (hi, lo) = (u32s(format!("{name}.hi"))?, u32s(format!("{name}.lo"))?);
        let plane: Vec<f64> = (hi.iter().zip(lo))
            .map(|(&h, &l)| f64::from_bits(u64::from(h) << 32 | u64::from(l)))
            .collect();
        words.push(plane);
    }
    let sums = (0..n)
        .map(|k| PixelSum {
            rgb: [words[0][k], words[1][k], words[2][k]],
            weight: words[3][k],
        })
        .collect();
    Ok(RenderPart { info, sums })
}

/// The part header from the `lowdisc.part` attribute, checked.
fn parse_header(attribute: Option<&AttributeValue>) -> Result<PartInfo, PartError> {
    let Some(AttributeValue::Text(text)) = attribute else {
        return Err(bad(format!(
            "no `{HEADER_ATTRIBUTE}` header: not a render part (write parts with \
             `lowdisc render --pixel-bounds` or `--sample-range`)"
        )));
    };
    let h: Header = serde_json::from_str(&text.to_string())
        .map_err(|e| bad(format!("bad `{HEADER_ATTRIBUTE}` header: {e}")))?;
    if h.format != HEADER_FORMAT {
        return Err(bad(format!(
            "part format `{}` is not {HEADER_FORMAT}",
            h.format
        )));
    }
    let (film, window) = (from_array(h.film_bounds), from_array(h.window));
    let full = PixelBounds::new([0, 0], [h.resolution[0] as i32, h.resolution[1] as i32]);
    let samples = SampleRange::new(h.samples[0], h.samples[1]);
    if film.area() == 0 || film.intersect(&full) != film {
        return Err(bad("the header's film bounds are outside the image"));
    }
    if window.area() == 0 || window.intersect(&film) != window {
        return Err(bad("the header's window is outside the film bounds"));
    }
    if samples.is_empty() || samples.end > h.spp {
        return Err(bad(format!(
            "the header's samples {samples} are not within 0..{}",
            h.spp
        )));
    }
    Ok(PartInfo {
        scene: h.scene,
        settings: h.settings,
        resolution: h.resolution,
        film_bounds: film,
        window,
        samples,
        spp: h.spp,
        nonfinite: h.nonfinite,
    })
}

/// Writes `part` to `path` atomically (a temporary sibling renamed into
/// place).
pub fn write_part(path: &Path, part: &RenderPart) -> Result<(), PartError> {
    let bytes = encode_part(part)?;
    lowdisc_files::write_bytes(path, &bytes)?;
    Ok(())
}

/// Reads the part file at `path` (a regular file of at most
/// [`MAX_PART_BYTES`]).
/// Every error names the file.
pub fn read_part(path: &Path) -> Result<RenderPart, PartError> {
    let bytes = lowdisc_files::read_input_limited(path, MAX_PART_BYTES)?;
    decode_part(&bytes).map_err(|e| bad(format!("{}: {e}", path.display())))
}
