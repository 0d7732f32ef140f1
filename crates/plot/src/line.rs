//! Line charts: several named series on linear or log-log axes, with a
//! legend, axis labels, optional markers, error bars and dashed reference
//! lines (for example an `N^-1` slope in a convergence plot, or a ratio of
//! 1). Tick labels are 0.95 times the label font, which is at least
//! [`MIN_FONT`] pixels, so that they stay readable when a chart is shown
//! at half its size.

use crate::axis::{Axis, Frame};
use crate::canvas::{Anchor, Canvas, Shape, Stroke, TextStyle};
use crate::color::Color;
use crate::raster::text_width;

/// One series of a line chart.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Name shown in the legend.
    pub name: String,
    /// The points `(x, y)`, drawn in order.
    pub points: Vec<[f64; 2]>,
    /// Colour (`None`: the series' palette colour).
    pub color: Option<Color>,
    /// Draw dashed (e.g. for reference slopes).
    pub dashed: bool,
    /// Draw a marker at each point.
    pub markers: bool,
    /// Error bars: `[low, high]` for each point, or empty for none.
    pub bars: Vec<[f64; 2]>,
}

impl Series {
    /// A solid series with markers.
    pub fn new(name: impl Into<String>, points: Vec<[f64; 2]>) -> Self {
        Series {
            name: name.into(),
            points,
            color: None,
            dashed: false,
            markers: true,
            bars: Vec::new(),
        }
    }

    /// The same series with an error bar from `low` to `high` at each
    /// point (one `[low, high]` per point).
    ///
    /// ```
    /// use lowdisc_plot::{LineChart, Series};
    /// let s = Series::new("ratio", vec![[0.0, 2.0], [1.0, 1.0]])
    ///     .with_bars(vec![[1.9, 2.1], [0.95, 1.05]]);
    /// let canvas = LineChart::log_log("t", "x", "y").with(s).to_canvas();
    /// assert!(canvas.width > 0);
    /// ```
    pub fn with_bars(mut self, bars: Vec<[f64; 2]>) -> Self {
        self.bars = bars;
        self
    }

    /// A dashed series without markers, e.g. a reference slope.
    pub fn reference(name: impl Into<String>, points: Vec<[f64; 2]>) -> Self {
        Series {
            name: name.into(),
            points,
            color: Some(Color::GREY),
            dashed: true,
            markers: false,
            bars: Vec::new(),
        }
    }

    /// A dashed horizontal line at `y` from `x0` to `x1` in `color`
    /// (a reference value, such as a ratio of 1).
    pub fn level(name: impl Into<String>, y: f64, [x0, x1]: [f64; 2], color: Color) -> Self {
        Series {
            color: Some(color),
            ..Series::reference(name, vec![[x0, y], [x1, y]])
        }
    }
}

/// The least label font of a chart, in pixels.
pub const MIN_FONT: f32 = 13.0;

/// A line chart.
#[derive(Debug, Clone, PartialEq)]
pub struct LineChart {
    /// Title above the plot.
    pub title: String,
    /// Label of the horizontal axis.
    pub x_label: String,
    /// Label of the vertical axis.
    pub y_label: String,
    /// The series.
    pub series: Vec<Series>,
    /// Logarithmic horizontal axis.
    pub x_log: bool,
    /// Logarithmic vertical axis.
    pub y_log: bool,
    /// Canvas width and height in pixels.
    pub size: [u32; 2],
}

impl LineChart {
    /// An empty log-log chart of 720x480 pixels.
    pub fn log_log(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Self {
        LineChart {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series: Vec::new(),
            x_log: true,
            y_log: true,
            size: [720, 480],
        }
    }

    /// Adds a series.
    pub fn with(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }

    /// Draws the chart. Points that cannot be shown (non-finite, or not
    /// positive on a log axis) are skipped and break the line.
    pub fn to_canvas(&self) -> Canvas {
        let [plot_w, h] = self.size;
        let font = (h as f32 / 34.0).clamp(MIN_FONT, 18.0);
        // The legend sits right of the plot area, so it never hides data.
        let legend_w = self.legend_width(font);
        let w = plot_w + legend_w.ceil() as u32;
        let mut canvas = Canvas::new(w, h);
        let all = self.series.iter().flat_map(|s| s.points.iter());
        let x_axis = Axis::fit(all.clone().map(|p| p[0]), self.x_log);
        let bars = self.series.iter().flat_map(|s| s.bars.iter().flatten());
        let y_axis = Axis::fit(all.map(|p| p[1]).chain(bars.copied()), self.y_log);
        let frame = Frame {
            x: 5.5 * font,
            y: 2.6 * font,
            width: plot_w as f32 - 6.5 * font,
            height: h as f32 - 6.0 * font,
            x_axis,
            y_axis,
            y_down: false,
        };
        canvas.text(
            [plot_w as f32 / 2.0, 1.7 * font],
            &self.title,
            TextStyle::new(1.2 * font, Anchor::Middle),
        );
        frame.draw_axes(&mut canvas, 0.95 * font, true);
        canvas.text(
            [frame.x + frame.width / 2.0, h as f32 - 0.8 * font],
            &self.x_label,
            TextStyle::new(font, Anchor::Middle),
        );
        canvas.text(
            [1.2 * font, frame.y + frame.height / 2.0],
            &self.y_label,
            TextStyle::new(font, Anchor::Middle).vertical(),
        );
        for (i, s) in self.series.iter().enumerate() {
            draw_series(&mut canvas, &frame, s, i);
        }
        self.draw_legend(&mut canvas, &frame, font);
        canvas
    }

    /// The legend box's width (0 without series).
    fn legend_box_width(&self, font: f32) -> f32 {
        if self.series.is_empty() {
            return 0.0;
        }
        let style = TextStyle::new(0.85 * font, Anchor::Start);
        let text_w = self
            .series
            .iter()
            .map(|s| text_width(&s.name, &style))
            .fold(0.0, f32::max);
        text_w + 3.6 * font
    }

    /// The width added right of the plot for the legend.
    fn legend_width(&self, font: f32) -> f32 {
        let b = self.legend_box_width(font);
        if b > 0.0 { b + font } else { 0.0 }
    }

    fn draw_legend(&self, canvas: &mut Canvas, frame: &Frame, font: f32) {
        if self.series.is_empty() {
            return;
        }
        let style = TextStyle::new(0.85 * font, Anchor::Start);
        let line_h = 1.3 * font;
        let box_w = self.legend_box_width(font);
        let box_h = line_h * self.series.len() as f32 + 0.6 * font;
        let x0 = frame.x + frame.width + 0.5 * font;
        let y0 = frame.y;
        canvas.rect(
            [x0, y0],
            [box_w, box_h],
            Some(Color::WHITE.with_alpha(230)),
            Some(Stroke::solid(Color::GRID, 1.0)),
        );
        for (i, s) in self.series.iter().enumerate() {
            let y = y0 + 0.3 * font + line_h * (i as f32 + 0.5);
            let stroke = series_stroke(s, i);
            canvas.line([x0 + 0.5 * font, y], [x0 + 2.5 * font, y], stroke);
            if s.markers {
                canvas.circle([x0 + 1.5 * font, y], 3.0, stroke.color);
            }
            canvas.text([x0 + 3.0 * font, y + 0.3 * font], &s.name, style);
        }
    }
}

fn series_stroke(s: &Series, index: usize) -> Stroke {
    let color = s.color.unwrap_or_else(|| Color::palette(index));
    if s.dashed {
        Stroke::dashed(color, 1.5, 6.0, 4.0)
    } else {
        Stroke::solid(color, 2.0)
    }
}

fn drawable(axis: &Axis, v: f64) -> bool {
    v.is_finite() && (!axis.log || v > 0.0)
}

fn draw_series(canvas: &mut Canvas, frame: &Frame, s: &Series, index: usize) {
    let stroke = series_stroke(s, index);
    let mut run: Vec<[f32; 2]> = Vec::new();
    let flush = |canvas: &mut Canvas, run: &mut Vec<[f32; 2]>| {
        if run.len() > 1 {
            canvas.push(Shape::Polyline {
                points: std::mem::take(run),
                stroke,
            });
        }
        run.clear();
    };
    for p in &s.points {
        if drawable(&frame.x_axis, p[0]) && drawable(&frame.y_axis, p[1]) {
            run.push(frame.to_canvas(p[0], p[1]));
        } else {
            flush(canvas, &mut run);
        }
    }
    flush(canvas, &mut run);
    draw_bars(canvas, frame, s, stroke);
    if s.markers {
        for p in &s.points {
            if drawable(&frame.x_axis, p[0]) && drawable(&frame.y_axis, p[1]) {
                canvas.circle(frame.to_canvas(p[0], p[1]), 3.0, stroke.color);
            }
        }
    }
}

/// The series' error bars: a vertical line with short caps at each point
/// whose bar can be drawn.
fn draw_bars(canvas: &mut Canvas, frame: &Frame, s: &Series, stroke: Stroke) {
    let stroke = Stroke::solid(stroke.color, 1.5);
    for (p, [lo, hi]) in s.points.iter().zip(&s.bars) {
        let ok = |y: f64| drawable(&frame.x_axis, p[0]) && drawable(&frame.y_axis, y);
        if !(ok(*lo) && ok(*hi)) {
            continue;
        }
        let (a, b) = (frame.to_canvas(p[0], *lo), frame.to_canvas(p[0], *hi));
        canvas.line(a, b, stroke);
        for end in [a, b] {
            canvas.line([end[0] - 4.0, end[1]], [end[0] + 4.0, end[1]], stroke);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_gap_in_the_data_splits_the_line() {
        let s = Series::new(
            "e",
            vec![
                [1.0, 1.0],
                [10.0, 0.1],
                [100.0, 0.0],
                [1000.0, 0.01],
                [1e4, 1e-3],
            ],
        );
        let canvas = LineChart::log_log("t", "N", "error").with(s).to_canvas();
        let polylines = canvas
            .shapes
            .iter()
            .filter(|s| matches!(s, Shape::Polyline { .. }))
            .count();
        assert_eq!(polylines, 2, "y = 0 cannot be drawn on a log axis");
        let markers = canvas
            .shapes
            .iter()
            .filter(|s| matches!(s, Shape::Circle { .. }))
            .count();
        assert_eq!(markers, 4 + 1, "four data markers and one legend marker");
    }

    #[test]
    fn error_bars_span_their_interval_and_widen_the_axis() {
        let s =
            Series::new("r", vec![[0.0, 1.0], [1.0, 2.0]]).with_bars(vec![[0.5, 1.5], [1.0, 4.0]]);
        let mut chart = LineChart::log_log("t", "x", "y").with(s);
        chart.x_log = false;
        chart.y_log = false;
        let canvas = chart.to_canvas();
        let lines: Vec<[[f32; 2]; 2]> = canvas
            .shapes
            .iter()
            .filter_map(|s| match s {
                Shape::Line { from, to, .. } if from[0] == to[0] && from[1] != to[1] => {
                    Some([*from, *to])
                }
                _ => None,
            })
            .collect();
        // Grid lines are vertical too; the bars are the two shortest whose
        // lengths are in the ratio of the intervals, 1 : 3.
        let mut lengths: Vec<f32> = lines.iter().map(|l| (l[1][1] - l[0][1]).abs()).collect();
        lengths.sort_by(f32::total_cmp);
        assert!((lengths[1] / lengths[0] - 3.0).abs() < 1e-3, "{lengths:?}");
    }

    #[test]
    fn a_slope_minus_one_series_is_a_straight_diagonal() {
        let pts: Vec<[f64; 2]> = (0..5)
            .map(|k| 10f64.powi(k))
            .map(|x| [x, 1.0 / x])
            .collect();
        let canvas = LineChart::log_log("t", "x", "y")
            .with(Series::new("s", pts))
            .to_canvas();
        let Some(Shape::Polyline { points, .. }) = canvas
            .shapes
            .iter()
            .find(|s| matches!(s, Shape::Polyline { .. }))
        else {
            panic!("no line drawn")
        };
        let d = |i: usize| {
            [
                points[i + 1][0] - points[i][0],
                points[i + 1][1] - points[i][1],
            ]
        };
        for i in 0..3 {
            assert!((d(i)[0] - d(i + 1)[0]).abs() < 1e-3 && (d(i)[1] - d(i + 1)[1]).abs() < 1e-3);
        }
    }
}
