//! The EXR reader on variants our writer does not produce: grey `Y`, half
//! floats in tiles with alpha, layer-prefixed channel names, unusable channels.

use std::io::Cursor;

use exr::prelude::{
    AnyChannel, AnyChannels, Encoding, FlatSamples, Image, Layer, LayerAttributes, SmallVec,
    SpecificChannels, Vec2, WritableImage, f16,
};
use lowdisc_image::{ErrorKind, ImageFormat, ReadOptions, RgbImage, decode_image};

const W: usize = 70;
const H: usize = 33;

fn value(i: usize, c: usize) -> f32 {
    ((i * 3 + c) % 97) as f32 * 0.125
}

fn write_any(channels: Vec<AnyChannel<FlatSamples>>, encoding: Encoding) -> Vec<u8> {
    let layer = Layer::new(
        (W, H),
        LayerAttributes::default(),
        encoding,
        AnyChannels::sort(SmallVec::from_vec(channels)),
    );
    let mut out = Cursor::new(Vec::new());
    Image::from_layer(layer)
        .write()
        .to_buffered(&mut out)
        .unwrap();
    out.into_inner()
}

fn decode(bytes: &[u8]) -> Result<RgbImage, lowdisc_image::ImageError> {
    decode_image(bytes, ImageFormat::Exr, &ReadOptions::default())
}

#[test]
fn luminance_only_is_grey() {
    let y: Vec<f32> = (0..W * H).map(|i| value(i, 0)).collect();
    let bytes = write_any(
        vec![AnyChannel::new("Y", FlatSamples::F32(y.clone()))],
        Encoding::SMALL_LOSSLESS,
    );
    let img = decode(&bytes).unwrap();
    assert_eq!((img.width(), img.height()), (W, H));
    for (p, v) in img.pixels().iter().zip(&y) {
        assert_eq!(*p, [*v; 3]);
    }
}

#[test]
fn half_float_rgba_tiles() {
    // FAST_LOSSLESS is RLE in 64x64 tiles; 70x33 makes partial tiles.
    let channels = SpecificChannels::rgba(|pos: Vec2<usize>| {
        let i = pos.1 * W + pos.0;
        (
            f16::from_f32(value(i, 0)),
            f16::from_f32(value(i, 1)),
            f16::from_f32(value(i, 2)),
            f16::from_f32(0.5),
        )
    });
    let layer = Layer::new(
        (W, H),
        LayerAttributes::default(),
        Encoding::FAST_LOSSLESS,
        channels,
    );
    let mut out = Cursor::new(Vec::new());
    Image::from_layer(layer)
        .write()
        .to_buffered(&mut out)
        .unwrap();
    let img = decode(&out.into_inner()).unwrap();
    for (i, p) in img.pixels().iter().enumerate() {
        // Multiples of 1/8 below 12.125 are exact in half precision.
        assert_eq!(*p, [value(i, 0), value(i, 1), value(i, 2)], "pixel {i}");
    }
}

#[test]
fn layer_prefixed_names_are_found() {
    let plane = |c: usize| FlatSamples::F32((0..W * H).map(|i| value(i, c)).collect());
    let bytes = write_any(
        vec![
            AnyChannel::new("diffuse.B", plane(2)),
            AnyChannel::new("diffuse.G", plane(1)),
            AnyChannel::new("diffuse.R", plane(0)),
        ],
        Encoding::UNCOMPRESSED,
    );
    let img = decode(&bytes).unwrap();
    assert_eq!(img.get(5, 2), Some([0, 1, 2].map(|c| value(2 * W + 5, c))));
}

#[test]
fn unusable_channels_are_unsupported() {
    let plane = || FlatSamples::F32(vec![1.0; W * H]);
    let bytes = write_any(
        vec![AnyChannel::new("X", plane()), AnyChannel::new("Z", plane())],
        Encoding::UNCOMPRESSED,
    );
    assert_eq!(decode(&bytes).unwrap_err().kind(), ErrorKind::Unsupported);
    let bytes = write_any(
        vec![
            AnyChannel::new("BY", plane()),
            AnyChannel::new("RY", plane()),
            AnyChannel::new("Y", plane()),
        ],
        Encoding::UNCOMPRESSED,
    );
    assert_eq!(decode(&bytes).unwrap_err().kind(), ErrorKind::Unsupported);
}
