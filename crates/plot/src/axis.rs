//! Axes: a data range mapped linearly or logarithmically onto a pixel span,
//! "nice" tick positions and labels, and drawing a framed plot area.

use crate::canvas::{Anchor, Canvas, Stroke, TextStyle};
use crate::color::Color;

/// One axis: a data range, linear or logarithmic.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axis {
    /// Data value at the start of the axis.
    pub min: f64,
    /// Data value at the end of the axis.
    pub max: f64,
    /// Logarithmic (base 10) scale; `min` and `max` must then be positive.
    pub log: bool,
}

impl Axis {
    /// A linear axis over `[min, max]`.
    pub fn linear(min: f64, max: f64) -> Self {
        Axis {
            min,
            max,
            log: false,
        }
    }

    /// A logarithmic axis over `[min, max]` (both positive).
    pub fn log(min: f64, max: f64) -> Self {
        Axis {
            min,
            max,
            log: true,
        }
    }

    /// An axis covering the finite values (positive ones for a log axis),
    /// widened by 4% of the span on each side (of the decades spanned, for
    /// a log axis; half a decade each way for a single value).
    /// Falls back to `[0, 1]` (or `[1, 10]`) when there are none.
    pub fn fit(values: impl IntoIterator<Item = f64>, log: bool) -> Self {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for v in values {
            if v.is_finite() && (!log || v > 0.0) {
                lo = lo.min(v);
                hi = hi.max(v);
            }
        }
        if log {
            if lo > hi {
                return Axis::log(1.0, 10.0);
            }
            let (a, b) = (lo.log10(), hi.log10());
            let pad = if b > a { 0.04 * (b - a) } else { 0.5 };
            Axis::log(10f64.powf(a - pad), 10f64.powf(b + pad))
        } else {
            if lo > hi {
                return Axis::linear(0.0, 1.0);
            }
            let pad = if hi > lo {
                0.04 * (hi - lo)
            } else {
                0.5 * lo.abs().max(1.0)
            };
            Axis::linear(lo - pad, hi + pad)
        }
    }

    /// The position of `v` along the axis as a fraction (0 at `min`, 1 at `max`).
    pub fn fraction(&self, v: f64) -> f64 {
        if self.log {
            (v.log10() - self.min.log10()) / (self.max.log10() - self.min.log10())
        } else {
            (v - self.min) / (self.max - self.min)
        }
    }

    /// Tick positions with labels: powers of ten on a log axis (every k-th
    /// decade when there are many; 1, 2 and 5 times them when fewer than
    /// three fall inside), multiples of 1, 2 or 5 times a power of ten on a
    /// linear axis, about `target` of them.
    pub fn ticks(&self, target: usize) -> Vec<(f64, String)> {
        if self.log {
            let (lo, hi) = (self.min.log10(), self.max.log10());
            if hi.floor() - lo.ceil() < 2.0 {
                let inside =
                    |v: &f64| *v >= self.min * (1.0 - 1e-9) && *v <= self.max * (1.0 + 1e-9);
                return (lo.floor() as i32..=hi.ceil() as i32)
                    .flat_map(|e| [1.0, 2.0, 5.0].map(|m| m * 10f64.powi(e)))
                    .filter(inside)
                    .map(|v| (v, short(v)))
                    .collect();
            }
            let (a, b) = (
                self.min.log10().ceil() as i32,
                self.max.log10().floor() as i32,
            );
            let step = ((b - a) as usize / target.max(1)).max(1) as i32;
            (a..=b)
                .step_by(step as usize)
                .map(|e| (10f64.powi(e), power_label(e)))
                .collect()
        } else {
            let span = self.max - self.min;
            if span <= 0.0 || !span.is_finite() {
                return vec![(self.min, short(self.min))];
            }
            let raw = span / target.max(1) as f64;
            let mag = 10f64.powf(raw.log10().floor());
            let step = [1.0, 2.0, 5.0, 10.0]
                .into_iter()
                .map(|m| m * mag)
                .find(|s| *s >= raw)
                .unwrap_or(10.0 * mag);
            let first = (self.min / step).ceil() as i64;
            let last = (self.max / step + 1e-9).floor() as i64;
            (first..=last)
                .map(|k| k as f64 * step)
                .map(|v| (v, short(v)))
                .collect()
        }
    }
}

fn power_label(e: i32) -> String {
    match e {
        0 => "1".into(),
        1 => "10".into(),
        _ => format!("1e{e}"),
    }
}

/// A short decimal label (up to 4 significant digits, no trailing zeros).
pub fn short(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    if v.abs() >= 1e5 || v.abs() < 1e-3 {
        return format!("{v:.2e}");
    }
    let s = format!("{v:.4}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// A rectangle of the canvas holding a plot, with its two axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    /// Left edge in pixels.
    pub x: f32,
    /// Top edge in pixels.
    pub y: f32,
    /// Width in pixels.
    pub width: f32,
    /// Height in pixels.
    pub height: f32,
    /// Horizontal axis.
    pub x_axis: Axis,
    /// Vertical axis.
    pub y_axis: Axis,
    /// Whether the vertical axis grows downwards (image convention).
    pub y_down: bool,
}

impl Frame {
    /// The canvas position of data point `(x, y)`.
    pub fn to_canvas(&self, x: f64, y: f64) -> [f32; 2] {
        let fx = self.x_axis.fraction(x) as f32;
        let fy = self.y_axis.fraction(y) as f32;
        let fy = if self.y_down { fy } else { 1.0 - fy };
        [self.x + fx * self.width, self.y + fy * self.height]
    }

    /// Whether a canvas point lies inside the frame (with a small margin).
    pub fn contains(&self, p: [f32; 2]) -> bool {
        let m = 0.5;
        p[0] >= self.x - m
            && p[0] <= self.x + self.width + m
            && p[1] >= self.y - m
            && p[1] <= self.y + self.height + m
    }

    /// A vertical line at data `x` across the frame.
    pub fn vline(&self, canvas: &mut Canvas, x: f64, stroke: Stroke) {
        let [px, _] = self.to_canvas(x, self.y_axis.min);
        canvas.line([px, self.y], [px, self.y + self.height], stroke);
    }

    /// A horizontal line at data `y` across the frame.
    pub fn hline(&self, canvas: &mut Canvas, y: f64, stroke: Stroke) {
        let [_, py] = self.to_canvas(self.x_axis.min, y);
        canvas.line([self.x, py], [self.x + self.width, py], stroke);
    }

    /// Draws light grid lines at the ticks, then tick labels and the border.
    pub fn draw_axes(&self, canvas: &mut Canvas, font_size: f32, grid: bool) {
        let grid_stroke = Stroke::solid(Color::GRID, 1.0);
        let label = TextStyle {
            color: Color::GREY,
            ..TextStyle::new(font_size, Anchor::Middle).mono()
        };
        let x_ticks = self
            .x_axis
            .ticks((self.width / (5.0 * font_size)).max(2.0) as usize);
        for (v, text) in x_ticks {
            if grid {
                self.vline(canvas, v, grid_stroke);
            }
            let [px, _] = self.to_canvas(v, self.y_axis.min);
            canvas.text([px, self.y + self.height + 1.3 * font_size], text, label);
        }
        let y_ticks = self
            .y_axis
            .ticks((self.height / (3.0 * font_size)).max(2.0) as usize);
        for (v, text) in y_ticks {
            if grid {
                self.hline(canvas, v, grid_stroke);
            }
            let [_, py] = self.to_canvas(self.x_axis.min, v);
            let style = TextStyle {
                anchor: Anchor::End,
                ..label
            };
            canvas.text(
                [self.x - 0.4 * font_size, py + 0.35 * font_size],
                text,
                style,
            );
        }
        self.draw_border(canvas);
    }

    /// The frame's outline.
    pub fn draw_border(&self, canvas: &mut Canvas) {
        canvas.rect(
            [self.x, self.y],
            [self.width, self.height],
            None,
            Some(Stroke::solid(Color::BLACK, 1.0)),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_ticks_are_nice_and_inside() {
        let t: Vec<f64> = Axis::linear(0.0, 1.0)
            .ticks(5)
            .into_iter()
            .map(|t| t.0)
            .collect();
        assert_eq!(t, vec![0.0, 0.2, 0.4, 0.6000000000000001, 0.8, 1.0]);
        let labels: Vec<String> = Axis::linear(0.0, 1.0)
            .ticks(5)
            .into_iter()
            .map(|t| t.1)
            .collect();
        assert_eq!(labels, ["0", "0.2", "0.4", "0.6", "0.8", "1"]);
    }

    #[test]
    fn log_ticks_are_powers_of_ten() {
        let t: Vec<f64> = Axis::log(1e-3, 10.0)
            .ticks(10)
            .into_iter()
            .map(|t| t.0)
            .collect();
        assert_eq!(t.len(), 5);
        assert!((t[0] - 1e-3).abs() < 1e-15 && (t[4] - 10.0).abs() < 1e-12);
    }

    #[test]
    fn fit_pads_the_data_span_and_maps_ends() {
        // 1 to 1024 spp: 3.01 decades, padded by 4 % of them, not to 1e4.
        let a = Axis::fit([1.0, 1024.0, -1.0, f64::NAN], true);
        let pad = 0.04 * 1024f64.log10();
        assert!((a.min.log10() + pad).abs() < 1e-12, "{a:?}");
        assert!(
            (a.max.log10() - 1024f64.log10() - pad).abs() < 1e-12,
            "{a:?}"
        );
        assert!((a.fraction(1.0) - pad / (1024f64.log10() + 2.0 * pad)).abs() < 1e-12);
        let one = Axis::fit([5.0], true);
        assert!((one.min - 5.0 / 10f64.sqrt()).abs() < 1e-12);
        // Within a decade and a half the ticks are 1, 2, 5 times powers of ten.
        let t: Vec<f64> = Axis::log(0.15, 3.0)
            .ticks(6)
            .into_iter()
            .map(|t| t.0)
            .collect();
        assert_eq!(t, vec![0.2, 0.5, 1.0, 2.0]);
        let f = Frame {
            x: 10.0,
            y: 0.0,
            width: 100.0,
            height: 50.0,
            x_axis: Axis::linear(0.0, 1.0),
            y_axis: Axis::linear(0.0, 1.0),
            y_down: false,
        };
        assert_eq!(f.to_canvas(0.0, 0.0), [10.0, 50.0]);
        assert_eq!(f.to_canvas(1.0, 1.0), [110.0, 0.0]);
    }
}
