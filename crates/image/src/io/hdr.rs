//! Radiance HDR (RGBE) input, written for this crate.
//!
//! A `#?` first line, header lines up to a blank line (`FORMAT=` must be
//! `32-bit_rle_rgbe`, or `32-bit_rle_xyze`, which is converted to linear
//! Rec.709 RGB), then a resolution line in any of Radiance's eight
//! orientations (the usual `-Y H +X W` is top-to-bottom, left-to-right), then
//! scanlines that may each be flat, old-style run-length encoded (a `1 1 1 n`
//! pixel repeats the previous one), or new-style RLE (`2 2 hi lo`, then four
//! channel planes of runs and literals). `EXPOSURE=` lines are ignored, as in
//! pbrt and stb_image. Pixels decode with [`rgbe_to_rgb`]; the writer is in
//! the `rgbe` module.

use super::rgbe::rgbe_to_rgb;
use crate::error::{ImageError, malformed, truncated, unsupported};
use crate::image::{RgbImage, checked_pixel_count};

/// Longest header accepted, in bytes.
const MAX_HEADER: usize = 1 << 16;

/// XYZ to linear Rec.709 RGB (D65), the standard sRGB matrix.
const XYZ_TO_RGB: [[f32; 3]; 3] = [
    [3.240_454_2, -1.537_138_5, -0.498_531_4],
    [-0.969_266, 1.876_010_8, 0.041_556],
    [0.055_643_4, -0.204_025_9, 1.057_225_2],
];

/// Header facts needed to decode the pixels.
struct Layout {
    width: usize,
    height: usize,
    /// True when scanlines are columns (X is the major axis).
    x_major: bool,
    /// True when Y runs downwards in the file (`-Y`: first row is the top).
    y_down: bool,
    /// True when X runs left to right (`+X`).
    x_right: bool,
    xyz: bool,
}

/// Parses the header and resolution line, returning the layout and the
/// offset of the first scanline.
fn parse_header(bytes: &[u8]) -> Result<(Layout, usize), ImageError> {
    if !bytes.starts_with(b"#?") {
        return Err(malformed("not a Radiance HDR file (no #? signature)"));
    }
    let mut pos = 0;
    let next_line = |pos: &mut usize| -> Result<&[u8], ImageError> {
        let rest = &bytes[*pos..];
        let limit = rest.len().min(MAX_HEADER.saturating_sub(*pos));
        match rest[..limit].iter().position(|&b| b == b'\n') {
            Some(end) => {
                *pos += end + 1;
                Ok(&rest[..end])
            }
            None if limit < rest.len() => Err(malformed("HDR header is too long")),
            None => Err(truncated("HDR header ends before the resolution line")),
        }
    };
    next_line(&mut pos)?; // the #? signature line
    let mut xyz = false;
    loop {
        let line = next_line(&mut pos)?;
        if line.is_empty() {
            break;
        }
        if let Some(format) = line.strip_prefix(b"FORMAT=") {
            match format.trim_ascii() {
                b"32-bit_rle_rgbe" => xyz = false,
                b"32-bit_rle_xyze" => xyz = true,
                other => {
                    return Err(unsupported(format!(
                        "HDR format {}",
                        String::from_utf8_lossy(other)
                    )));
                }
            }
        }
    }
    let line = next_line(&mut pos)?;
    let text =
        std::str::from_utf8(line).map_err(|_| malformed("HDR resolution line is not text"))?;
    let parts: Vec<&str> = text.split_ascii_whitespace().collect();
    let bad = || {
        malformed(format!(
            "HDR resolution line {text:?} is not like -Y 512 +X 1024"
        ))
    };
    if parts.len() != 4 {
        return Err(bad());
    }
    let axis = |s: &str| -> Option<(bool, char)> {
        let mut chars = s.chars();
        let sign = chars.next()?;
        let name = chars.next()?;
        (chars.next().is_none() && (sign == '+' || sign == '-') && (name == 'X' || name == 'Y'))
            .then_some((sign == '+', name))
    };
    let (a1, a2) = (
        axis(parts[0]).ok_or_else(bad)?,
        axis(parts[2]).ok_or_else(bad)?,
    );
    let n1: usize = parts[1].parse().map_err(|_| bad())?;
    let n2: usize = parts[3].parse().map_err(|_| bad())?;
    let (x_major, (y_sign, x_sign), (width, height)) = match (a1.1, a2.1) {
        ('Y', 'X') => (false, (a1.0, a2.0), (n2, n1)),
        ('X', 'Y') => (true, (a2.0, a1.0), (n1, n2)),
        _ => return Err(bad()),
    };
    checked_pixel_count(width, height)?;
    let layout = Layout {
        width,
        height,
        x_major,
        y_down: !y_sign,
        x_right: x_sign,
        xyz,
    };
    Ok((layout, pos))
}

/// Reads one scanline of `out.len()` pixels at `*pos`, in any of the three
/// encodings.
fn read_scanline(bytes: &[u8], pos: &mut usize, out: &mut [[u8; 4]]) -> Result<(), ImageError> {
    let len = out.len();
    let take = |pos: &mut usize, n: usize| -> Result<&[u8], ImageError> {
        let s = bytes
            .get(*pos..*pos + n)
            .ok_or_else(|| truncated("HDR pixel data ends early"))?;
        *pos += n;
        Ok(s)
    };
    let first = take(pos, 4)?;
    let new_rle = (8..=0x7fff).contains(&len)
        && first[0] == 2
        && first[1] == 2
        && first[2] & 0x80 == 0
        && (usize::from(first[2]) << 8 | usize::from(first[3])) == len;
    if new_rle {
        for channel in 0..4 {
            let mut x = 0;
            while x < len {
                let count = take(pos, 1)?[0];
                if count > 128 {
                    let run = usize::from(count - 128);
                    let value = take(pos, 1)?[0];
                    if x + run > len {
                        return Err(malformed("HDR run overflows its scanline"));
                    }
                    out[x..x + run].iter_mut().for_each(|p| p[channel] = value);
                    x += run;
                } else {
                    let run = usize::from(count);
                    if run == 0 || x + run > len {
                        return Err(malformed(
                            "HDR literal run is empty or overflows its scanline",
                        ));
                    }
                    for (p, &v) in out[x..x + run].iter_mut().zip(take(pos, run)?) {
                        p[channel] = v;
                    }
                    x += run;
                }
            }
        }
        return Ok(());
    }
    // Flat or old-style RLE: pixels, where 1 1 1 n repeats the previous pixel
    // n << shift times, the shift growing by 8 for consecutive repeat pixels.
    *pos -= 4;
    let (mut x, mut shift) = (0usize, 0u32);
    while x < len {
        let p = take(pos, 4)?;
        let p = [p[0], p[1], p[2], p[3]];
        if p[0] == 1 && p[1] == 1 && p[2] == 1 {
            if x == 0 || shift > 16 {
                return Err(malformed("HDR repeat marker without a pixel to repeat"));
            }
            let count = usize::from(p[3]) << shift;
            if x + count > len {
                return Err(malformed("HDR repeat overflows its scanline"));
            }
            let prev = out[x - 1];
            out[x..x + count].fill(prev);
            x += count;
            shift += 8;
        } else {
            out[x] = p;
            x += 1;
            shift = 0;
        }
    }
    Ok(())
}

/// Decodes a Radiance HDR file held in memory.
pub fn decode(bytes: &[u8]) -> Result<RgbImage, ImageError> {
    let (layout, mut pos) = parse_header(bytes)?;
    let (width, height) = (layout.width, layout.height);
    let (count, len) = if layout.x_major {
        (width, height)
    } else {
        (height, width)
    };
    let mut image = RgbImage::new(width, height)?;
    let mut scanline = vec![[0u8; 4]; len];
    for i in 0..count {
        read_scanline(bytes, &mut pos, &mut scanline)?;
        for (j, &p) in scanline.iter().enumerate() {
            let (a, b) = if layout.x_major { (i, j) } else { (j, i) };
            let x = if layout.x_right { a } else { width - 1 - a };
            let y = if layout.y_down { b } else { height - 1 - b };
            let mut rgb = rgbe_to_rgb(p);
            if layout.xyz {
                rgb = XYZ_TO_RGB.map(|row| row[0] * rgb[0] + row[1] * rgb[1] + row[2] * rgb[2]);
            }
            image.pixels_mut()[y * width + x] = rgb;
        }
    }
    Ok(image)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::error::ErrorKind;
    use crate::io::rgbe::rgb_to_rgbe;

    pub(crate) fn header(res: &str) -> Vec<u8> {
        format!("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n{res}\n").into_bytes()
    }

    #[test]
    fn orientations_and_old_style_runs() {
        // Two flat scanlines of width 2, pixel values 1, 2 / 3, 4 (as r bytes with e = 136: f = 1).
        let px = |r: u8| [r, 0, 0, 136];
        let mut body = Vec::new();
        for r in [1u8, 2, 3, 4] {
            body.extend_from_slice(&px(r));
        }
        let red = |img: &RgbImage| img.pixels().iter().map(|p| p[0]).collect::<Vec<_>>();
        let mut f = header("-Y 2 +X 2");
        f.extend_from_slice(&body);
        assert_eq!(red(&decode(&f).unwrap()), [1.0, 2.0, 3.0, 4.0]);
        let mut f = header("+Y 2 -X 2");
        f.extend_from_slice(&body);
        assert_eq!(red(&decode(&f).unwrap()), [4.0, 3.0, 2.0, 1.0]);
        // X major: scanlines are columns, top to bottom within each.
        let mut f = header("+X 2 -Y 2");
        f.extend_from_slice(&body);
        assert_eq!(red(&decode(&f).unwrap()), [1.0, 3.0, 2.0, 4.0]);
        // Old-style RLE: pixel 5 then (1,1,1,3) repeats it three times: width 4.
        let mut f = header("-Y 1 +X 4");
        f.extend_from_slice(&[5, 0, 0, 136, 1, 1, 1, 3]);
        assert_eq!(red(&decode(&f).unwrap()), [5.0; 4]);
        let mut f = header("-Y 1 +X 4");
        f.extend_from_slice(&[1, 1, 1, 3]);
        assert_eq!(decode(&f).unwrap_err().kind(), ErrorKind::Malformed);
    }

    #[test]
    fn xyz_white_converts_to_rgb() {
        // XYZ of D65 white (0.9505, 1, 1.089) -> RGB about (1, 1, 1).
        let mut f = b"#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n".to_vec();
        f.extend_from_slice(&rgb_to_rgbe([0.9505, 1.0, 1.089]));
        let p = decode(&f).unwrap().pixels()[0];
        for c in p {
            assert!((c - 1.0).abs() < 0.05, "{p:?}");
        }
    }
}
