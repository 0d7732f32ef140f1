//! Write -> read round trips through files, and format dispatch.

use std::path::PathBuf;

use lowdisc_image::io::write_image_as;
use lowdisc_image::{
    ErrorKind, ImageFormat, ReadOptions, RgbImage, WriteOptions, read_image, read_image_with,
    srgb_encode, srgb8_decode, write_exr, write_hdr, write_image, write_pfm, write_png,
};

/// A fresh folder for one test under Cargo's per-target temporary folder.
fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("image-roundtrip")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A 13x7 image with a gradient, negatives, large values and exact zeros.
fn sample() -> RgbImage {
    RgbImage::from_fn(13, 7, |x, y| {
        let t = (x as f32 + 0.5) / 13.0;
        match (x + y) % 5 {
            0 => [0.0, 0.0, 0.0],
            1 => [t, t * t, 1.0 - t],
            2 => [1e4 * t, 0.25, 3.5],
            3 => [-0.5, t * 0.01, y as f32],
            _ => [t * 2.0, 0.001 * y as f32, 0.75],
        }
    })
    .unwrap()
}

#[test]
fn pfm_is_bit_exact() {
    let dir = scratch("pfm");
    let img = sample();
    write_pfm(dir.join("a.pfm"), &img).unwrap();
    assert_eq!(read_image(dir.join("a.pfm")).unwrap(), img);
}

#[test]
fn exr_is_bit_exact() {
    let dir = scratch("exr");
    let img = sample();
    write_exr(dir.join("a.exr"), &img).unwrap();
    assert_eq!(read_image(dir.join("a.exr")).unwrap(), img);
}

#[test]
fn hdr_is_within_rgbe_precision() {
    let dir = scratch("hdr");
    let img = sample().map(|p| p.map(|v| v.max(0.0)));
    write_hdr(dir.join("a.hdr"), &img).unwrap();
    let back = read_image(dir.join("a.hdr")).unwrap();
    for (a, b) in img.pixels().iter().zip(back.pixels()) {
        let max = a[0].max(a[1]).max(a[2]);
        for c in 0..3 {
            // RGBE keeps 8 mantissa bits relative to the largest channel.
            assert!((a[c] - b[c]).abs() <= max / 128.0 + 1e-30, "{a:?} vs {b:?}");
        }
    }
}

#[test]
fn png_is_within_quantisation() {
    let dir = scratch("png");
    let img = sample();
    write_png(dir.join("a.png"), &img, 1.0).unwrap();
    let back = read_image(dir.join("a.png")).unwrap();
    for (a, b) in img.pixels().iter().zip(back.pixels()) {
        for c in 0..3 {
            let want = srgb_encode(a[c]).clamp(0.0, 1.0);
            let got = srgb_encode(b[c]);
            assert!((want - got).abs() <= 0.5 / 255.0 + 1e-6, "{a:?} vs {b:?}");
        }
    }
    // Exposure multiplies before encoding: 0.25 at exposure 2 reads back as ~0.5.
    let grey = RgbImage::filled(3, 2, [0.25; 3]).unwrap();
    write_image(dir.join("b.PNG"), &grey, &WriteOptions { exposure: 2.0 }).unwrap();
    let back = read_image(dir.join("b.PNG")).unwrap();
    // 0.5 -> code 188 -> srgb8_decode(188).
    assert!(back.pixels().iter().all(|p| *p == [srgb8_decode(188); 3]));
    // Raw reading keeps code / 255: 188 / 255.
    let raw = read_image_with(dir.join("b.PNG"), &ReadOptions::raw()).unwrap();
    assert!(raw.pixels().iter().all(|p| *p == [188.0 / 255.0; 3]));
}

#[test]
fn png_writes_nan_as_black_and_clamps() {
    let dir = scratch("png-nan");
    let img = RgbImage::from_pixels(
        3,
        1,
        vec![[f32::NAN, -1.0, f32::INFINITY], [5.0; 3], [0.0; 3]],
    )
    .unwrap();
    write_png(dir.join("n.png"), &img, 1.0).unwrap();
    let raw = read_image_with(dir.join("n.png"), &ReadOptions::raw()).unwrap();
    assert_eq!(raw.pixels(), &[[0.0, 0.0, 1.0], [1.0; 3], [0.0; 3]]);
}

#[test]
fn dispatch_uses_magic_then_extension() {
    let dir = scratch("dispatch");
    let img = sample();
    // A PFM under a .png name is still read as PFM: magic bytes win.
    write_image_as(
        dir.join("really-pfm.png"),
        &img,
        ImageFormat::Pfm,
        &WriteOptions::default(),
    )
    .unwrap();
    assert_eq!(read_image(dir.join("really-pfm.png")).unwrap(), img);
    // Upper-case extension.
    write_image(dir.join("UPPER.EXR"), &img, &WriteOptions::default()).unwrap();
    assert_eq!(read_image(dir.join("UPPER.EXR")).unwrap(), img);
    // No magic and no known extension.
    std::fs::write(dir.join("mystery.bin"), b"hello world").unwrap();
    let err = read_image(dir.join("mystery.bin")).unwrap_err();
    assert_eq!(err.kind(), ErrorKind::UnknownFormat);
    assert_eq!(err.path(), Some(dir.join("mystery.bin").as_path()));
    // A missing file is an i/o error naming the file.
    let err = read_image(dir.join("absent.exr")).unwrap_err();
    assert_eq!(err.kind(), ErrorKind::Io);
    assert!(err.to_string().contains("absent.exr"));
    // Unwritable formats.
    let e = write_image(dir.join("x.tga"), &img, &WriteOptions::default()).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Unsupported);
    let e = write_image(dir.join("x.jpg"), &img, &WriteOptions::default()).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::UnknownFormat);
    assert!(!dir.join("x.tga").exists() && !dir.join("x.jpg").exists());
}
