//! Placing several canvases in one picture: rows of canvases side by side,
//! rows stacked top to bottom, each canvas's shapes moved to its place.

use crate::canvas::{Canvas, Shape};

/// `shape` moved by `(dx, dy)`.
pub fn shifted(shape: Shape, dx: f32, dy: f32) -> Shape {
    let at = |p: [f32; 2]| [p[0] + dx, p[1] + dy];
    match shape {
        Shape::Line { from, to, stroke } => Shape::Line {
            from: at(from),
            to: at(to),
            stroke,
        },
        Shape::Polyline { points, stroke } => Shape::Polyline {
            points: points.into_iter().map(at).collect(),
            stroke,
        },
        Shape::Rect {
            origin,
            size,
            fill,
            stroke,
        } => Shape::Rect {
            origin: at(origin),
            size,
            fill,
            stroke,
        },
        Shape::Circle {
            center,
            radius,
            fill,
        } => Shape::Circle {
            center: at(center),
            radius,
            fill,
        },
        Shape::Text {
            at: p,
            content,
            style,
        } => Shape::Text {
            at: at(p),
            content,
            style,
        },
        Shape::Image {
            origin,
            size,
            raster,
        } => Shape::Image {
            origin: at(origin),
            size,
            raster,
        },
    }
}

/// One canvas holding `rows` (each a list of canvases placed left to right),
/// stacked top to bottom; each row is as tall as its tallest canvas.
pub fn grid(rows: Vec<Vec<Canvas>>) -> Canvas {
    let width = rows
        .iter()
        .map(|row| row.iter().map(|c| c.width).sum::<u32>())
        .max()
        .unwrap_or(1)
        .max(1);
    let heights: Vec<u32> = rows
        .iter()
        .map(|row| row.iter().map(|c| c.height).max().unwrap_or(0))
        .collect();
    let mut out = Canvas::new(width, heights.iter().sum::<u32>().max(1));
    let mut y = 0u32;
    for (row, height) in rows.into_iter().zip(heights) {
        let mut x = 0u32;
        for canvas in row {
            let w = canvas.width;
            for shape in canvas.shapes {
                out.push(shifted(shape, x as f32, y as f32));
            }
            x += w;
        }
        y += height;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Color;

    #[test]
    fn canvases_are_placed_side_by_side_and_stacked() {
        let mut a = Canvas::new(10, 20);
        a.circle([1.0, 2.0], 1.0, Color::BLACK);
        let b = a.clone();
        let c = a.clone();
        let out = grid(vec![vec![a, b], vec![c]]);
        assert_eq!((out.width, out.height), (20, 40));
        let centers: Vec<[f32; 2]> = out
            .shapes
            .iter()
            .map(|s| match s {
                Shape::Circle { center, .. } => *center,
                _ => panic!("only circles"),
            })
            .collect();
        assert_eq!(centers, vec![[1.0, 2.0], [11.0, 2.0], [1.0, 22.0]]);
    }
}
