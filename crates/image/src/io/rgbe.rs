//! RGBE pixels and Radiance HDR output, written for this crate.
//!
//! An RGBE pixel `(r, g, b, e)` decodes to `r * 2^(e - 136)` (the common
//! convention of stb_image and Walter's rgbe.c, without Radiance's half-step
//! offset); `e = 0` is black. Files are written as `-Y H +X W` with new-style
//! run-length encoding when 8 <= width <= 32767, flat scanlines otherwise.

use crate::image::RgbImage;

/// Decodes one RGBE pixel to linear floats.
pub fn rgbe_to_rgb(p: [u8; 4]) -> [f32; 3] {
    if p[3] == 0 {
        return [0.0; 3];
    }
    // 2^(e - 136) is a normal f32 for every e in 1..=255.
    let f = f32::from_bits(((i32::from(p[3]) - 136 + 127) as u32) << 23);
    [
        f32::from(p[0]) * f,
        f32::from(p[1]) * f,
        f32::from(p[2]) * f,
    ]
}

/// Encodes linear floats as one RGBE pixel: NaN and negatives become 0, values
/// too large for RGBE saturate, values whose largest channel is below 1e-32
/// become black.
pub fn rgb_to_rgbe(rgb: [f32; 3]) -> [u8; 4] {
    let c = rgb.map(|v| {
        if v > 0.0 {
            f64::from(v.min(f32::MAX))
        } else {
            0.0
        }
    });
    let v = c[0].max(c[1]).max(c[2]);
    if v < 1e-32 {
        return [0; 4];
    }
    // v = m * 2^e with m in [0.5, 1): read e from the f64 exponent bits.
    let e = ((v.to_bits() >> 52) & 0x7ff) as i32 - 1022;
    let e = e.min(127);
    let scale = 256.0 / 2f64.powi(e);
    let byte = |x: f64| (x * scale).min(255.0) as u8;
    [byte(c[0]), byte(c[1]), byte(c[2]), (e + 128) as u8]
}

/// Run-length encodes one channel plane of a new-style RLE scanline.
fn encode_plane(plane: &[u8], out: &mut Vec<u8>) {
    let run_at = |i: usize, max: usize| {
        let mut r = 1;
        while i + r < plane.len() && r < max && plane[i + r] == plane[i] {
            r += 1;
        }
        r
    };
    let mut i = 0;
    while i < plane.len() {
        let run = run_at(i, 127);
        if run >= 4 {
            out.push(128 + run as u8);
            out.push(plane[i]);
            i += run;
            continue;
        }
        let start = i;
        while i < plane.len() && i - start < 128 && run_at(i, 4) < 4 {
            i += 1;
        }
        out.push((i - start) as u8);
        out.extend_from_slice(&plane[start..i]);
    }
}

/// Encodes an image as a Radiance HDR file (`-Y H +X W`).
pub fn encode(image: &RgbImage) -> Vec<u8> {
    let (width, height) = (image.width(), image.height());
    let mut out = format!(
        "#?RADIANCE\n# Written by lowdisc-image\nFORMAT=32-bit_rle_rgbe\n\n-Y {height} +X {width}\n"
    )
    .into_bytes();
    let rle = (8..=0x7fff).contains(&width);
    let mut planes = vec![vec![0u8; width]; 4];
    for y in 0..height {
        let row = &image.pixels()[y * width..(y + 1) * width];
        if !rle {
            row.iter()
                .for_each(|&p| out.extend_from_slice(&rgb_to_rgbe(p)));
            continue;
        }
        for (x, &p) in row.iter().enumerate() {
            for (c, v) in rgb_to_rgbe(p).into_iter().enumerate() {
                planes[c][x] = v;
            }
        }
        out.extend_from_slice(&[2, 2, (width >> 8) as u8, (width & 0xff) as u8]);
        planes
            .iter()
            .for_each(|plane| encode_plane(plane, &mut out));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::ErrorKind;
    use crate::io::hdr::decode;
    use crate::io::hdr::tests::header;

    #[test]
    fn rgbe_known_values() {
        // (128, 64, 0, 129): f = 2^(129 - 136) = 1/128 -> 1.0, 0.5, 0.0.
        assert_eq!(rgbe_to_rgb([128, 64, 0, 129]), [1.0, 0.5, 0.0]);
        assert_eq!(rgbe_to_rgb([200, 10, 5, 0]), [0.0; 3]);
        // 1.0 = 0.5 * 2^1: e = 1 -> byte 129, mantissa 0.5 * 256 = 128.
        assert_eq!(rgb_to_rgbe([1.0, 0.5, 0.0]), [128, 64, 0, 129]);
        assert_eq!(rgb_to_rgbe([f32::NAN, -1.0, 0.0]), [0; 4]);
        // Saturation: +inf clamps to f32::MAX, whose exponent 128 is clamped to 127.
        assert_eq!(rgb_to_rgbe([f32::INFINITY, 0.0, 0.0]), [255, 0, 0, 255]);
        for v in [1e-20f32, 0.001, 0.3, 1.0, 7.5, 1e6, 3e30] {
            let back = rgbe_to_rgb(rgb_to_rgbe([v, v, v]))[0];
            assert!(back <= v && (v - back) / v < 1.0 / 128.0, "{v} -> {back}");
        }
    }

    #[test]
    fn rle_writer_matches_flat_and_reader_checks() {
        let img = RgbImage::from_fn(37, 3, |x, y| {
            let v = if x < 20 { 0.5 } else { (x * y) as f32 * 0.37 };
            [v, 2.0 * v, 0.01]
        })
        .unwrap();
        let rle = encode(&img);
        let flat_img = RgbImage::from_fn(7, 3, |x, y| [x as f32, y as f32, 1.0]).unwrap();
        let flat = encode(&flat_img);
        let start = rle.windows(6).position(|w| w == b"+X 37\n").unwrap() + 6;
        assert_eq!(rle[start..start + 4], [2, 2, 0, 37]);
        assert!(rle.len() - start < 3 * 37 * 4, "RLE did not compress");
        let back = decode(&rle).unwrap();
        for (a, b) in img.pixels().iter().zip(back.pixels()) {
            assert_eq!(rgb_to_rgbe(*a), rgb_to_rgbe(*b));
        }
        assert_eq!(decode(&flat).unwrap(), flat_img);
        let mut bad = header("-Y 1 +X 8");
        bad.extend_from_slice(&[2, 2, 0, 8, 200]);
        assert_eq!(decode(&bad).unwrap_err().kind(), ErrorKind::Truncated);
        let mut bad = header("-Y 1 +X 8");
        bad.extend_from_slice(&[2, 2, 0, 8, 137, 0]);
        assert_eq!(decode(&bad).unwrap_err().kind(), ErrorKind::Malformed);
        assert_eq!(
            decode(&header("-Y 100000 +X 100000")).unwrap_err().kind(),
            ErrorKind::TooLarge
        );
        assert_eq!(
            decode(&header("-Y 2 +Y 2")).unwrap_err().kind(),
            ErrorKind::Malformed
        );
        let f = b"#?RADIANCE\nFORMAT=32-bit_rle_wat\n\n-Y 1 +X 1\n\0\0\0\0";
        assert_eq!(decode(f).unwrap_err().kind(), ErrorKind::Unsupported);
    }
}
