//! The drawing model shared by both backends: a [`Canvas`] is a list of
//! primitives (lines, polylines, rectangles, circles, text, raster images)
//! in pixel coordinates with the origin at the top left.
//!
//! Charts ([`crate::ScatterGrid`], [`crate::LineChart`], [`crate::Heatmap`])
//! build a canvas; [`Canvas::to_svg`] and [`Canvas::to_png`] render it, and
//! [`Canvas::save`] picks the format from the file extension.

use std::path::Path;

use crate::Error;
use crate::color::Color;

/// How a line is stroked.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stroke {
    /// Line colour.
    pub color: Color,
    /// Line width in pixels.
    pub width: f32,
    /// Dash pattern (on, off) in pixels; `None` for a solid line.
    pub dash: Option<[f32; 2]>,
}

impl Stroke {
    /// A solid stroke.
    pub fn solid(color: Color, width: f32) -> Self {
        Stroke {
            color,
            width,
            dash: None,
        }
    }

    /// A dashed stroke.
    pub fn dashed(color: Color, width: f32, on: f32, off: f32) -> Self {
        Stroke {
            color,
            width,
            dash: Some([on, off]),
        }
    }
}

/// Horizontal alignment of a text's anchor point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Anchor {
    /// The anchor is the left end of the text.
    Start,
    /// The anchor is the middle of the text.
    Middle,
    /// The anchor is the right end of the text.
    End,
}

/// A typeface; both are bundled for PNG output.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Face {
    /// A proportional sans-serif face (Ubuntu Light).
    Sans,
    /// A monospaced face (Hack), legible at small sizes.
    Mono,
}

/// How a text is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TextStyle {
    /// Font size (em height) in pixels.
    pub size: f32,
    /// Text colour.
    pub color: Color,
    /// Where the anchor point lies along the text.
    pub anchor: Anchor,
    /// Typeface.
    pub face: Face,
    /// Rotate 90 degrees counter-clockwise (for vertical axis labels).
    pub vertical: bool,
}

impl TextStyle {
    /// Black sans-serif text of `size` pixels anchored at `anchor`.
    pub fn new(size: f32, anchor: Anchor) -> Self {
        TextStyle {
            size,
            color: Color::BLACK,
            anchor,
            face: Face::Sans,
            vertical: false,
        }
    }

    /// The same style in the monospaced face.
    pub fn mono(mut self) -> Self {
        self.face = Face::Mono;
        self
    }

    /// The same style rotated to read bottom-to-top.
    pub fn vertical(mut self) -> Self {
        self.vertical = true;
        self
    }
}

/// An RGBA raster (row-major, 4 bytes per pixel, not premultiplied).
#[derive(Debug, Clone, PartialEq)]
pub struct Raster {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height * 4` bytes.
    pub rgba: Vec<u8>,
}

/// One drawing primitive.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// A straight segment.
    Line {
        /// Start point.
        from: [f32; 2],
        /// End point.
        to: [f32; 2],
        /// Stroke.
        stroke: Stroke,
    },
    /// Connected segments through the points.
    Polyline {
        /// Vertices.
        points: Vec<[f32; 2]>,
        /// Stroke.
        stroke: Stroke,
    },
    /// An axis-aligned rectangle.
    Rect {
        /// Top-left corner.
        origin: [f32; 2],
        /// Width and height.
        size: [f32; 2],
        /// Fill colour, if filled.
        fill: Option<Color>,
        /// Outline, if outlined.
        stroke: Option<Stroke>,
    },
    /// A filled disc.
    Circle {
        /// Centre.
        center: [f32; 2],
        /// Radius.
        radius: f32,
        /// Fill colour.
        fill: Color,
    },
    /// A single line of text; `at` is the anchor on the baseline.
    Text {
        /// Anchor point on the baseline.
        at: [f32; 2],
        /// The text.
        content: String,
        /// Style.
        style: TextStyle,
    },
    /// A raster image stretched over a rectangle (nearest-neighbour).
    Image {
        /// Top-left corner.
        origin: [f32; 2],
        /// Displayed width and height.
        size: [f32; 2],
        /// The pixels.
        raster: Raster,
    },
}

/// A drawing: a size, a background and primitives drawn in order.
#[derive(Debug, Clone, PartialEq)]
pub struct Canvas {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Background colour.
    pub background: Color,
    /// Primitives, drawn first to last.
    pub shapes: Vec<Shape>,
}

/// The output formats, chosen from a file extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// Portable Network Graphics (raster).
    Png,
    /// Scalable Vector Graphics (text, real `<text>` elements).
    Svg,
}

impl Format {
    /// The format named by `path`'s extension (`.png` or `.svg`, any case).
    pub fn from_path(path: &Path) -> Result<Format, Error> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .unwrap_or("")
            .to_ascii_lowercase();
        match ext.as_str() {
            "png" => Ok(Format::Png),
            "svg" => Ok(Format::Svg),
            _ => Err(Error::UnsupportedFormat(path.display().to_string())),
        }
    }
}

impl Canvas {
    /// An empty white canvas.
    pub fn new(width: u32, height: u32) -> Self {
        Canvas {
            width,
            height,
            background: Color::WHITE,
            shapes: Vec::new(),
        }
    }

    /// Adds a primitive.
    pub fn push(&mut self, shape: Shape) {
        self.shapes.push(shape);
    }

    /// Adds a line segment.
    pub fn line(&mut self, from: [f32; 2], to: [f32; 2], stroke: Stroke) {
        self.push(Shape::Line { from, to, stroke });
    }

    /// Adds a filled disc.
    pub fn circle(&mut self, center: [f32; 2], radius: f32, fill: Color) {
        self.push(Shape::Circle {
            center,
            radius,
            fill,
        });
    }

    /// Adds a rectangle.
    pub fn rect(
        &mut self,
        origin: [f32; 2],
        size: [f32; 2],
        fill: Option<Color>,
        stroke: Option<Stroke>,
    ) {
        self.push(Shape::Rect {
            origin,
            size,
            fill,
            stroke,
        });
    }

    /// Adds a line of text anchored at `at` (on the baseline).
    pub fn text(&mut self, at: [f32; 2], content: impl Into<String>, style: TextStyle) {
        self.push(Shape::Text {
            at,
            content: content.into(),
            style,
        });
    }
}
