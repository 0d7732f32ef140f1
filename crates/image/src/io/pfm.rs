//! Portable Float Map (PFM) input and output, written for this crate.
//!
//! A PFM file is a text header `PF` (RGB) or `Pf` (grey), the width and
//! height, and a scale whose sign gives the byte order (negative: little
//! endian, positive: big endian), each separated by white space, with exactly
//! one white-space byte after the scale; then 32-bit floats, rows from the
//! bottom of the image to the top. The scale's magnitude is ignored, as pbrt
//! and most tools do. Grey files are read as R = G = B.

use crate::error::{ImageError, malformed, truncated, unsupported};
use crate::image::{RgbImage, checked_pixel_count};

/// Longest header token accepted (a longer one means a corrupt file).
const MAX_TOKEN: usize = 64;

/// Reads the next white-space separated token starting at `*pos`.
fn token<'a>(bytes: &'a [u8], pos: &mut usize, what: &str) -> Result<&'a str, ImageError> {
    while *pos < bytes.len() && bytes[*pos].is_ascii_whitespace() {
        *pos += 1;
    }
    let start = *pos;
    while *pos < bytes.len() && !bytes[*pos].is_ascii_whitespace() {
        *pos += 1;
        if *pos - start > MAX_TOKEN {
            return Err(malformed(format!("PFM {what} is too long")));
        }
    }
    if *pos == start || *pos == bytes.len() {
        return Err(truncated(format!("PFM header ends before the {what}")));
    }
    std::str::from_utf8(&bytes[start..*pos])
        .map_err(|_| malformed(format!("PFM {what} is not text")))
}

/// Decodes a PFM file held in memory.
pub fn decode(bytes: &[u8]) -> Result<RgbImage, ImageError> {
    let mut pos = 0;
    let magic = token(bytes, &mut pos, "magic")?;
    let channels = match magic {
        "PF" => 3,
        "Pf" => 1,
        "PF4" => return Err(unsupported("PFM with alpha (PF4)")),
        _ => return Err(malformed(format!("not a PFM file (magic {magic:?})"))),
    };
    let width: usize = token(bytes, &mut pos, "width")?
        .parse()
        .map_err(|_| malformed("PFM width is not a number"))?;
    let height: usize = token(bytes, &mut pos, "height")?
        .parse()
        .map_err(|_| malformed("PFM height is not a number"))?;
    let scale: f32 = token(bytes, &mut pos, "scale")?
        .parse()
        .map_err(|_| malformed("PFM scale is not a number"))?;
    if scale == 0.0 || !scale.is_finite() {
        return Err(malformed(format!(
            "PFM scale {scale} is not a non-zero number"
        )));
    }
    let little_endian = scale < 0.0;
    // `token` stopped on the single white-space byte that ends the header.
    pos += 1;
    let n = checked_pixel_count(width, height)?;
    let needed = n * channels * 4;
    let data = &bytes[pos..];
    if data.len() < needed {
        return Err(truncated(format!(
            "PFM {width}x{height} needs {needed} data bytes, the file has {}",
            data.len()
        )));
    }
    let value = |i: usize| {
        let b = [
            data[4 * i],
            data[4 * i + 1],
            data[4 * i + 2],
            data[4 * i + 3],
        ];
        if little_endian {
            f32::from_le_bytes(b)
        } else {
            f32::from_be_bytes(b)
        }
    };
    let mut pixels = Vec::with_capacity(n);
    for y in 0..height {
        // File rows run bottom to top.
        let file_row = height - 1 - y;
        for x in 0..width {
            let i = (file_row * width + x) * channels;
            pixels.push(if channels == 3 {
                [value(i), value(i + 1), value(i + 2)]
            } else {
                let v = value(i);
                [v, v, v]
            });
        }
    }
    RgbImage::from_pixels(width, height, pixels)
}

/// Encodes an image as a little-endian RGB PFM (`PF`, scale -1).
pub fn encode(image: &RgbImage) -> Vec<u8> {
    let (width, height) = (image.width(), image.height());
    let header = format!("PF\n{width} {height}\n-1\n");
    let mut out = Vec::with_capacity(header.len() + width * height * 12);
    out.extend_from_slice(header.as_bytes());
    for y in (0..height).rev() {
        for p in &image.pixels()[y * width..(y + 1) * width] {
            for c in p {
                out.extend_from_slice(&c.to_le_bytes());
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::ErrorKind;

    #[test]
    fn big_endian_grey_bottom_row_first() {
        // 1x2 grey image, big endian (scale +1): file rows are bottom (2.0) then top (0.5).
        let mut file = b"Pf\n1 2\n1.0\n".to_vec();
        file.extend_from_slice(&2.0f32.to_be_bytes());
        file.extend_from_slice(&0.5f32.to_be_bytes());
        let img = decode(&file).unwrap();
        assert_eq!((img.width(), img.height()), (1, 2));
        assert_eq!(img.get(0, 0), Some([0.5; 3]));
        assert_eq!(img.get(0, 1), Some([2.0; 3]));
    }

    #[test]
    fn little_endian_rgb_and_header_checks() {
        let mut file = b"PF 2 1 -1.0\n".to_vec();
        for v in [1.0f32, 2.0, 3.0, 4.0, 5.0, 6.0] {
            file.extend_from_slice(&v.to_le_bytes());
        }
        let img = decode(&file).unwrap();
        assert_eq!(img.pixels(), &[[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]);
        assert_eq!(
            decode(b"P6\n1 1\n255\n").unwrap_err().kind(),
            ErrorKind::Malformed
        );
        assert_eq!(
            decode(b"PF\n1 1\n0\n").unwrap_err().kind(),
            ErrorKind::Malformed
        );
        let huge = b"PF\n100000 100000\n-1\n";
        assert_eq!(decode(huge).unwrap_err().kind(), ErrorKind::TooLarge);
        assert_eq!(
            decode(b"PF\n1 1\n-1\n\0\0").unwrap_err().kind(),
            ErrorKind::Truncated
        );
    }
}
