//! Truncated copies of files of every format give an error, never a panic.

use std::panic::{AssertUnwindSafe, catch_unwind};

use lowdisc_image::{ImageFormat, ReadOptions, RgbImage, WriteOptions, decode_image, encode_image};

/// The lengths to try for a file of `n` bytes: every length for small files,
/// else the first and last 64 and 64 evenly spaced ones.
fn lengths(n: usize) -> Vec<usize> {
    if n <= 256 {
        return (0..n).collect();
    }
    let mut v: Vec<usize> = (0..64).chain(n - 64..n).collect();
    v.extend((0..64).map(|i| i * n / 64));
    v.sort_unstable();
    v.dedup();
    v
}

/// Decodes every truncation of `bytes`; each must return an error unless it
/// keeps at least `n - optional_tail` bytes (a trailer some decoders do not
/// need, such as PNG's IEND chunk). A panic fails with the length.
fn check(name: &str, bytes: &[u8], format: ImageFormat, optional_tail: usize) {
    assert!(
        decode_image(bytes, format, &ReadOptions::default()).is_ok(),
        "{name}: full file must load"
    );
    for len in lengths(bytes.len()) {
        let result = catch_unwind(AssertUnwindSafe(|| {
            decode_image(&bytes[..len], format, &ReadOptions::default())
        }));
        match result {
            Err(_) => panic!(
                "{name}: decoder panicked on the first {len} of {} bytes",
                bytes.len()
            ),
            Ok(Ok(_)) if len + optional_tail < bytes.len() => {
                panic!(
                    "{name}: the first {len} of {} bytes decoded without error",
                    bytes.len()
                )
            }
            Ok(_) => {}
        }
    }
}

fn sample() -> RgbImage {
    RgbImage::from_fn(21, 9, |x, y| {
        let v = ((x * 7 + y * 13) % 17) as f32 / 4.0;
        [v, 0.5 * v + 0.1, if x > 10 { 0.3 } else { v * v }]
    })
    .unwrap()
}

#[test]
fn own_files_of_every_written_format() {
    let img = sample();
    for (format, tail) in [
        (ImageFormat::Pfm, 0),
        (ImageFormat::Hdr, 0),
        (ImageFormat::Exr, 0),
        // The 12-byte IEND chunk carries no pixels.
        (ImageFormat::Png, 12),
    ] {
        let bytes = encode_image(&img, format, &WriteOptions::default()).unwrap();
        check(format.extension(), &bytes, format, tail);
    }
}

#[test]
fn real_scene_files() {
    let root = shared_scenes::dir();
    let files = [
        (
            "envmaps/pbrt-v4-ganesha-sky-equiarea.exr",
            ImageFormat::Exr,
            0,
        ),
        ("envmaps/mitsuba-tutorials-envmap.exr", ImageFormat::Exr, 0),
        (
            "envmaps/polyhaven-venice_sunset_1k.hdr",
            ImageFormat::Hdr,
            0,
        ),
        (
            "bitterli-classroom/textures/Skydome.pfm",
            ImageFormat::Pfm,
            0,
        ),
        ("killeroos/textures/lines.png", ImageFormat::Png, 12),
        // A TGA 2.0 file ends in a 26-byte footer that carries no pixels.
        (
            "bitterli-classroom/textures/wood1.tga",
            ImageFormat::Tga,
            26,
        ),
    ];
    for (rel, format, tail) in files {
        let path = root.join(rel);
        let Ok(bytes) = std::fs::read(&path) else {
            shared_scenes::skip(&format!("{} is absent", path.display()));
            continue;
        };
        check(rel, &bytes, format, tail);
    }
}

#[test]
fn absurd_sizes_are_refused_before_allocating() {
    let pfm = b"PF\n4000000000 4000000000\n-1\n";
    let hdr = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 70000 +X 70000\n";
    for (bytes, format) in [(&pfm[..], ImageFormat::Pfm), (&hdr[..], ImageFormat::Hdr)] {
        let err = decode_image(bytes, format, &ReadOptions::default()).unwrap_err();
        assert_eq!(err.kind(), lowdisc_image::ErrorKind::TooLarge);
    }
    // A PNG header announcing 2^20 x 2^20 pixels (valid IHDR CRC not needed
    // to be refused: either the size check or the CRC check stops it).
    let mut png = b"\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR".to_vec();
    png.extend_from_slice(&(1u32 << 20).to_be_bytes());
    png.extend_from_slice(&(1u32 << 20).to_be_bytes());
    png.extend_from_slice(&[8, 2, 0, 0, 0, 0, 0, 0, 0]);
    assert!(decode_image(&png, ImageFormat::Png, &ReadOptions::default()).is_err());
}
