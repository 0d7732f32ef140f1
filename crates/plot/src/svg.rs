//! The SVG backend: writes the canvas as a hand-built SVG 1.1 document with
//! real `<text>` elements (font families that fall back to generic ones) and
//! raster images embedded as base64 PNG data.

use std::fmt::Write;

use crate::canvas::{Anchor, Canvas, Face, Shape, Stroke, TextStyle};
use crate::color::Color;

/// Renders `canvas` as an SVG document.
pub(crate) fn render(canvas: &Canvas) -> String {
    let mut out = String::with_capacity(256 + 64 * canvas.shapes.len());
    let (w, h) = (canvas.width, canvas.height);
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}">"#
    );
    let _ = writeln!(
        out,
        r#"<rect width="{w}" height="{h}"{}/>"#,
        fill_attr(canvas.background)
    );
    for shape in &canvas.shapes {
        shape_to_svg(&mut out, shape);
    }
    out.push_str("</svg>\n");
    out
}

fn shape_to_svg(out: &mut String, shape: &Shape) {
    match shape {
        Shape::Line { from, to, stroke } => {
            let _ = writeln!(
                out,
                r#"<line x1="{}" y1="{}" x2="{}" y2="{}"{}/>"#,
                num(from[0]),
                num(from[1]),
                num(to[0]),
                num(to[1]),
                stroke_attr(stroke)
            );
        }
        Shape::Polyline { points, stroke } => {
            out.push_str(r#"<polyline fill="none" points=""#);
            for (i, p) in points.iter().enumerate() {
                if i > 0 {
                    out.push(' ');
                }
                let _ = write!(out, "{},{}", num(p[0]), num(p[1]));
            }
            let _ = writeln!(out, r#""{}/>"#, stroke_attr(stroke));
        }
        Shape::Rect {
            origin,
            size,
            fill,
            stroke,
        } => {
            let fill = fill.map_or_else(|| r#" fill="none""#.to_string(), fill_attr);
            let stroke = stroke.as_ref().map_or_else(String::new, stroke_attr);
            let _ = writeln!(
                out,
                r#"<rect x="{}" y="{}" width="{}" height="{}"{fill}{stroke}/>"#,
                num(origin[0]),
                num(origin[1]),
                num(size[0]),
                num(size[1])
            );
        }
        Shape::Circle {
            center,
            radius,
            fill,
        } => {
            let _ = writeln!(
                out,
                r#"<circle cx="{}" cy="{}" r="{}"{}/>"#,
                num(center[0]),
                num(center[1]),
                num(*radius),
                fill_attr(*fill)
            );
        }
        Shape::Text { at, content, style } => text_to_svg(out, *at, content, style),
        Shape::Image {
            origin,
            size,
            raster,
        } => {
            let png = crate::raster::encode_raster(raster).unwrap_or_default();
            let _ = writeln!(
                out,
                r#"<image x="{}" y="{}" width="{}" height="{}" preserveAspectRatio="none" style="image-rendering:pixelated" href="data:image/png;base64,{}"/>"#,
                num(origin[0]),
                num(origin[1]),
                num(size[0]),
                num(size[1]),
                base64(&png)
            );
        }
    }
}

fn text_to_svg(out: &mut String, at: [f32; 2], content: &str, style: &TextStyle) {
    let anchor = match style.anchor {
        Anchor::Start => "start",
        Anchor::Middle => "middle",
        Anchor::End => "end",
    };
    let family = match style.face {
        Face::Sans => "Ubuntu, 'DejaVu Sans', Arial, sans-serif",
        Face::Mono => "Hack, 'DejaVu Sans Mono', monospace",
    };
    let rotate = if style.vertical {
        format!(r#" transform="rotate(-90 {} {})""#, num(at[0]), num(at[1]))
    } else {
        String::new()
    };
    let _ = writeln!(
        out,
        r#"<text x="{}" y="{}" font-family="{family}" font-size="{}" text-anchor="{anchor}"{}{rotate}>{}</text>"#,
        num(at[0]),
        num(at[1]),
        num(style.size),
        fill_attr(style.color),
        escape(content)
    );
}

fn fill_attr(c: Color) -> String {
    if c.a == 255 {
        format!(r#" fill="{}""#, c.hex())
    } else {
        format!(
            r#" fill="{}" fill-opacity="{:.3}""#,
            c.hex(),
            f32::from(c.a) / 255.0
        )
    }
}

fn stroke_attr(s: &Stroke) -> String {
    let mut attr = format!(
        r#" stroke="{}" stroke-width="{}""#,
        s.color.hex(),
        num(s.width)
    );
    if s.color.a != 255 {
        let _ = write!(
            attr,
            r#" stroke-opacity="{:.3}""#,
            f32::from(s.color.a) / 255.0
        );
    }
    if let Some([on, off]) = s.dash {
        let _ = write!(attr, r#" stroke-dasharray="{},{}""#, num(on), num(off));
    }
    attr
}

/// A coordinate with at most two decimals and no trailing zeros.
fn num(v: f32) -> String {
    let s = format!("{:.2}", v);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_string()
    } else {
        s.to_string()
    }
}

/// Escapes the XML special characters.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for ch in text.chars() {
        match ch {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(ch),
        }
    }
    out
}

/// Standard base64 (RFC 4648, with padding).
fn base64(bytes: &[u8]) -> String {
    const TABLE: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            *chunk.get(1).unwrap_or(&0),
            *chunk.get(2).unwrap_or(&0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(TABLE[((n >> (18 - 6 * k)) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_rfc_4648_vectors() {
        assert_eq!(base64(b""), "");
        assert_eq!(base64(b"f"), "Zg==");
        assert_eq!(base64(b"fo"), "Zm8=");
        assert_eq!(base64(b"foo"), "Zm9v");
        assert_eq!(base64(b"foobar"), "Zm9vYmFy");
    }

    #[test]
    fn text_is_escaped_and_numbers_are_short() {
        assert_eq!(escape("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
        assert_eq!(num(1.0), "1");
        assert_eq!(num(2.5), "2.5");
        assert_eq!(num(-0.001), "0");
    }

    #[test]
    fn a_document_has_its_shapes() {
        let mut c = Canvas::new(10, 20);
        c.circle([1.0, 2.0], 0.5, Color::BLACK);
        c.text([0.0, 0.0], "x<y", TextStyle::new(12.0, Anchor::Start));
        let svg = render(&c);
        assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
        assert!(svg.contains(r##"<circle cx="1" cy="2" r="0.5" fill="#000000"/>"##));
        assert!(svg.contains(">x&lt;y</text>"));
    }
}
