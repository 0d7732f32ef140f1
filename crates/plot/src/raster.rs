//! The PNG backend: rasterises the canvas with `tiny-skia` (anti-aliased
//! paths) and draws text with `ab_glyph` from fonts bundled as bytes, so the
//! output is the same on machines with no system fonts.

use ab_glyph::{Font, FontRef, Glyph, PxScale, ScaleFont, point};
use tiny_skia::{
    FillRule, FilterQuality, IntSize, LineCap, Paint, PathBuilder, Pixmap, PixmapPaint, Rect,
    StrokeDash, Transform,
};

use crate::Error;
use crate::canvas::{Anchor, Canvas, Face, Raster, Shape, Stroke, TextStyle};
use crate::color::Color;

/// Renders `canvas` to PNG bytes.
pub(crate) fn render(canvas: &Canvas) -> Result<Vec<u8>, Error> {
    let mut pixmap = Pixmap::new(canvas.width, canvas.height).ok_or_else(|| {
        Error::InvalidData(format!(
            "cannot make a {}x{} image",
            canvas.width, canvas.height
        ))
    })?;
    pixmap.fill(sk_color(canvas.background));
    for shape in &canvas.shapes {
        draw(&mut pixmap, shape)?;
    }
    pixmap
        .encode_png()
        .map_err(|e| Error::Encode(e.to_string()))
}

/// Encodes a raster on its own as PNG (used to embed images in SVG).
pub(crate) fn encode_raster(raster: &Raster) -> Result<Vec<u8>, Error> {
    to_pixmap(raster)?
        .encode_png()
        .map_err(|e| Error::Encode(e.to_string()))
}

fn to_pixmap(raster: &Raster) -> Result<Pixmap, Error> {
    let expected = raster.width as usize * raster.height as usize * 4;
    if raster.rgba.len() != expected {
        return Err(Error::InvalidData(format!(
            "raster of {}x{} needs {expected} bytes, has {}",
            raster.width,
            raster.height,
            raster.rgba.len()
        )));
    }
    let mut data = raster.rgba.clone();
    for px in data.chunks_exact_mut(4) {
        let a = u16::from(px[3]);
        for c in &mut px[..3] {
            *c = ((u16::from(*c) * a + 127) / 255) as u8;
        }
    }
    let size = IntSize::from_wh(raster.width, raster.height)
        .ok_or_else(|| Error::InvalidData("empty raster".into()))?;
    Pixmap::from_vec(data, size).ok_or_else(|| Error::InvalidData("bad raster".into()))
}

fn sk_color(c: Color) -> tiny_skia::Color {
    tiny_skia::Color::from_rgba8(c.r, c.g, c.b, c.a)
}

fn paint(c: Color) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color(sk_color(c));
    p.anti_alias = true;
    p
}

fn sk_stroke(s: &Stroke) -> tiny_skia::Stroke {
    tiny_skia::Stroke {
        width: s.width,
        line_cap: LineCap::Butt,
        dash: s
            .dash
            .and_then(|[on, off]| StrokeDash::new(vec![on, off], 0.0)),
        ..Default::default()
    }
}

fn draw(pixmap: &mut Pixmap, shape: &Shape) -> Result<(), Error> {
    let id = Transform::identity();
    match shape {
        Shape::Line { from, to, stroke } => {
            let mut pb = PathBuilder::new();
            pb.move_to(from[0], from[1]);
            pb.line_to(to[0], to[1]);
            if let Some(path) = pb.finish() {
                pixmap.stroke_path(&path, &paint(stroke.color), &sk_stroke(stroke), id, None);
            }
        }
        Shape::Polyline { points, stroke } => {
            let mut pb = PathBuilder::new();
            for (i, p) in points.iter().enumerate() {
                if i == 0 {
                    pb.move_to(p[0], p[1]);
                } else {
                    pb.line_to(p[0], p[1]);
                }
            }
            if let Some(path) = pb.finish() {
                pixmap.stroke_path(&path, &paint(stroke.color), &sk_stroke(stroke), id, None);
            }
        }
        Shape::Rect {
            origin,
            size,
            fill,
            stroke,
        } => {
            if let Some(rect) = Rect::from_xywh(origin[0], origin[1], size[0], size[1]) {
                if let Some(fill) = fill {
                    pixmap.fill_rect(rect, &paint(*fill), id, None);
                }
                if let Some(stroke) = stroke {
                    let path = PathBuilder::from_rect(rect);
                    pixmap.stroke_path(&path, &paint(stroke.color), &sk_stroke(stroke), id, None);
                }
            }
        }
        Shape::Circle {
            center,
            radius,
            fill,
        } => {
            if let Some(path) = PathBuilder::from_circle(center[0], center[1], *radius) {
                pixmap.fill_path(&path, &paint(*fill), FillRule::Winding, id, None);
            }
        }
        Shape::Text { at, content, style } => draw_text(pixmap, *at, content, style)?,
        Shape::Image {
            origin,
            size,
            raster,
        } => {
            let image = to_pixmap(raster)?;
            let sx = size[0] / raster.width as f32;
            let sy = size[1] / raster.height as f32;
            let transform = Transform::from_row(sx, 0.0, 0.0, sy, origin[0], origin[1]);
            let paint = PixmapPaint {
                quality: FilterQuality::Nearest,
                ..Default::default()
            };
            pixmap.draw_pixmap(0, 0, image.as_ref(), &paint, transform, None);
        }
    }
    Ok(())
}

/// The bundled font of a face.
fn font(face: Face) -> Result<FontRef<'static>, Error> {
    let bytes = match face {
        Face::Sans => epaint_default_fonts::UBUNTU_LIGHT,
        Face::Mono => epaint_default_fonts::HACK_REGULAR,
    };
    FontRef::try_from_slice(bytes).map_err(|e| Error::Encode(format!("bundled font: {e}")))
}

/// Lays out one line of text from x = 0 on the baseline y = 0; returns the
/// positioned glyphs and the advance width.
fn layout(font: &FontRef<'static>, text: &str, size: f32) -> (Vec<Glyph>, f32) {
    let scale = PxScale::from(size);
    let scaled = font.as_scaled(scale);
    let mut caret = 0.0f32;
    let mut previous = None;
    let mut glyphs = Vec::with_capacity(text.len());
    for ch in text.chars() {
        let id = font.glyph_id(ch);
        if let Some(p) = previous {
            caret += scaled.kern(p, id);
        }
        glyphs.push(id.with_scale_and_position(scale, point(caret, 0.0)));
        caret += scaled.h_advance(id);
        previous = Some(id);
    }
    (glyphs, caret)
}

/// The advance width in pixels of `text` in `style` (as the PNG backend
/// draws it; SVG viewers use similar metrics).
pub fn text_width(text: &str, style: &TextStyle) -> f32 {
    font(style.face).map_or(0.6 * style.size * text.chars().count() as f32, |f| {
        layout(&f, text, style.size).1
    })
}

fn draw_text(
    pixmap: &mut Pixmap,
    at: [f32; 2],
    text: &str,
    style: &TextStyle,
) -> Result<(), Error> {
    let font = font(style.face)?;
    let (glyphs, width) = layout(&font, text, style.size);
    let shift = match style.anchor {
        Anchor::Start => 0.0,
        Anchor::Middle => -width / 2.0,
        Anchor::End => -width,
    };
    let (w, h) = (pixmap.width() as i64, pixmap.height() as i64);
    let data = pixmap.data_mut();
    let c = style.color;
    for glyph in glyphs {
        let Some(outline) = font.outline_glyph(glyph) else {
            continue;
        };
        let bounds = outline.px_bounds();
        outline.draw(|x, y, coverage| {
            // Offset from the anchor along and across the text.
            let along = bounds.min.x + x as f32 + shift;
            let across = bounds.min.y + y as f32;
            let (px, py) = if style.vertical {
                (at[0] + across, at[1] - along)
            } else {
                (at[0] + along, at[1] + across)
            };
            let (px, py) = (px.round() as i64, py.round() as i64);
            if px < 0 || py < 0 || px >= w || py >= h {
                return;
            }
            let alpha = coverage.clamp(0.0, 1.0) * f32::from(c.a) / 255.0;
            let i = ((py * w + px) * 4) as usize;
            let px = &mut data[i..i + 4];
            for (k, src) in [c.r, c.g, c.b].into_iter().enumerate() {
                px[k] = (f32::from(src) * alpha + f32::from(px[k]) * (1.0 - alpha)).round() as u8;
            }
            px[3] = (255.0 * alpha + f32::from(px[3]) * (1.0 - alpha)).round() as u8;
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn png_output_has_the_signature_and_draws_text() {
        let mut c = Canvas::new(60, 30);
        c.text([5.0, 20.0], "Ag", TextStyle::new(16.0, Anchor::Start));
        let png = render(&c).unwrap();
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
        let blank = render(&Canvas::new(60, 30)).unwrap();
        assert_ne!(png, blank, "text must put ink on the image");
    }

    #[test]
    fn wider_text_measures_wider() {
        let s = TextStyle::new(12.0, Anchor::Start);
        assert!(text_width("sobol-owen", &s) > text_width("sobol", &s));
        assert!(text_width("", &s) == 0.0);
    }

    #[test]
    fn a_raster_of_the_wrong_size_is_an_error() {
        let r = Raster {
            width: 2,
            height: 2,
            rgba: vec![0; 15],
        };
        assert!(encode_raster(&r).is_err());
    }
}
