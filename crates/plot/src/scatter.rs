//! Scatter plots of 2-D point sets: titled square panels laid out in a grid,
//! each with optional light grid lines (e.g. elementary intervals) and
//! heavier boundary lines (e.g. pixel edges).

use crate::axis::{Axis, Frame};
use crate::canvas::{Anchor, Canvas, Stroke, TextStyle};
use crate::color::Color;

/// One panel: a point set in a data rectangle.
#[derive(Debug, Clone, PartialEq)]
pub struct ScatterPanel {
    /// Title drawn above the panel.
    pub title: String,
    /// The points `(x, y)`.
    pub points: Vec<[f64; 2]>,
    /// Horizontal data range.
    pub x_range: [f64; 2],
    /// Vertical data range.
    pub y_range: [f64; 2],
    /// Whether y grows downwards (image / film convention).
    pub y_down: bool,
    /// Light grid lines: x positions, then y positions.
    pub grid: [Vec<f64>; 2],
    /// Heavy boundary lines: x positions, then y positions.
    pub boundaries: [Vec<f64>; 2],
    /// Point colour (`None`: the panel's palette colour).
    pub color: Option<Color>,
}

impl ScatterPanel {
    /// A panel of `points` in the unit square, y upwards, no grid.
    pub fn new(title: impl Into<String>, points: Vec<[f64; 2]>) -> Self {
        ScatterPanel {
            title: title.into(),
            points,
            x_range: [0.0, 1.0],
            y_range: [0.0, 1.0],
            y_down: false,
            grid: [Vec::new(), Vec::new()],
            boundaries: [Vec::new(), Vec::new()],
            color: None,
        }
    }

    /// Sets the data ranges.
    pub fn with_ranges(mut self, x: [f64; 2], y: [f64; 2]) -> Self {
        self.x_range = x;
        self.y_range = y;
        self
    }

    /// Light grid lines every `1 / divisions` of each range (both axes).
    pub fn with_regular_grid(mut self, divisions: u32) -> Self {
        let lines = |r: [f64; 2]| -> Vec<f64> {
            (1..divisions)
                .map(|k| r[0] + (r[1] - r[0]) * f64::from(k) / f64::from(divisions))
                .collect()
        };
        self.grid = [lines(self.x_range), lines(self.y_range)];
        self
    }
}

/// Panels in a grid, drawn to a [`Canvas`].
#[derive(Debug, Clone, PartialEq)]
pub struct ScatterGrid {
    /// The panels, row by row.
    pub panels: Vec<ScatterPanel>,
    /// Panels per row.
    pub columns: usize,
    /// Side of a panel's plot area in pixels.
    pub panel_size: f32,
    /// Point radius in pixels (`None`: chosen from the number of points).
    pub point_radius: Option<f32>,
    /// Optional overall title.
    pub title: Option<String>,
}

impl ScatterGrid {
    /// All panels in one row, 320 pixels each.
    pub fn row(panels: Vec<ScatterPanel>) -> Self {
        let columns = panels.len().max(1);
        ScatterGrid {
            panels,
            columns,
            panel_size: 320.0,
            point_radius: None,
            title: None,
        }
    }

    /// Draws the grid.
    pub fn to_canvas(&self) -> Canvas {
        let font = (self.panel_size / 26.0).clamp(10.0, 16.0);
        let left = 3.2 * font;
        let top = 2.2 * font
            + if self.title.is_some() {
                2.0 * font
            } else {
                0.0
            };
        let gap = 1.5 * font;
        let bottom = 2.2 * font;
        let cell_w = left + self.panel_size + gap;
        let cell_h = 2.0 * font + self.panel_size + bottom;
        let columns = self.columns.max(1);
        let rows = self.panels.len().div_ceil(columns).max(1);
        let width = (cell_w * columns as f32 + gap).ceil() as u32;
        let height = (top - 2.0 * font + cell_h * rows as f32).ceil() as u32;
        let mut canvas = Canvas::new(width, height);
        if let Some(title) = &self.title {
            canvas.text(
                [width as f32 / 2.0, 1.6 * font],
                title,
                TextStyle::new(1.3 * font, Anchor::Middle),
            );
        }
        for (i, panel) in self.panels.iter().enumerate() {
            let (r, c) = (i / columns, i % columns);
            let x = c as f32 * cell_w + left;
            let y = top + r as f32 * cell_h;
            self.draw_panel(&mut canvas, panel, i, x, y, font);
        }
        canvas
    }

    fn draw_panel(
        &self,
        canvas: &mut Canvas,
        panel: &ScatterPanel,
        index: usize,
        x: f32,
        y: f32,
        font: f32,
    ) {
        let frame = Frame {
            x,
            y,
            width: self.panel_size,
            height: self.panel_size,
            x_axis: Axis::linear(panel.x_range[0], panel.x_range[1]),
            y_axis: Axis::linear(panel.y_range[0], panel.y_range[1]),
            y_down: panel.y_down,
        };
        canvas.text(
            [x + self.panel_size / 2.0, y - 0.6 * font],
            &panel.title,
            TextStyle::new(1.15 * font, Anchor::Middle),
        );
        let grid = Stroke::solid(Color::GRID, 1.0);
        for &v in &panel.grid[0] {
            frame.vline(canvas, v, grid);
        }
        for &v in &panel.grid[1] {
            frame.hline(canvas, v, grid);
        }
        let heavy = Stroke::solid(Color::GREY, 2.0);
        for &v in &panel.boundaries[0] {
            frame.vline(canvas, v, heavy);
        }
        for &v in &panel.boundaries[1] {
            frame.hline(canvas, v, heavy);
        }
        let radius = self.point_radius.unwrap_or_else(|| {
            let n = panel.points.len().max(1) as f32;
            (self.panel_size / n.sqrt() / 5.0).clamp(0.6, 4.0)
        });
        let color = panel.color.unwrap_or_else(|| Color::palette(index));
        for p in &panel.points {
            let at = frame.to_canvas(p[0], p[1]);
            if frame.contains(at) {
                canvas.circle(at, radius, color);
            }
        }
        frame.draw_axes(canvas, 0.8 * font, false);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::canvas::Shape;

    #[test]
    fn every_point_becomes_a_circle_inside_its_panel() {
        let pts = vec![[0.1, 0.2], [0.9, 0.5], [0.5, 0.99]];
        let grid = ScatterGrid::row(vec![
            ScatterPanel::new("a", pts.clone()),
            ScatterPanel::new("b", pts),
        ]);
        let canvas = grid.to_canvas();
        let circles: Vec<[f32; 2]> = canvas
            .shapes
            .iter()
            .filter_map(|s| {
                if let Shape::Circle { center, .. } = s {
                    Some(*center)
                } else {
                    None
                }
            })
            .collect();
        assert_eq!(circles.len(), 6);
        // The second panel's points sit one cell to the right of the first's.
        let dx = circles[3][0] - circles[0][0];
        assert!(dx > grid.panel_size && circles[3][1] == circles[0][1]);
        assert!(canvas.width as f32 > 2.0 * grid.panel_size);
    }

    #[test]
    fn regular_grid_has_divisions_minus_one_lines() {
        let p = ScatterPanel::new("t", vec![])
            .with_ranges([0.0, 2.0], [0.0, 2.0])
            .with_regular_grid(8);
        assert_eq!(p.grid[0].len(), 7);
        assert_eq!(p.grid[1][3], 1.0);
    }
}
