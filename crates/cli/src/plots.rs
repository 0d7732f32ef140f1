//! Drawing point sets for `points --plot` and `figure`: scatter panels with
//! grid lines at the elementary intervals and heavy lines at pixel edges.

use std::path::Path;

use anyhow::Result;
use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc_plot::{ScatterGrid, ScatterPanel};

/// Cells per axis of the grid drawn for `n` points: `2^ceil(m/2)` across and
/// `2^floor(m/2)` down, `m = floor(log2 n)`; a (0,m,2)-net puts exactly one
/// point in each cell. `None` above 64 cells per axis (too dense to read).
pub fn strata(n: u32) -> Option<[u32; 2]> {
    let m = 31 - n.max(1).leading_zeros();
    let cells = [1u32 << m.div_ceil(2), 1u32 << (m / 2)];
    (cells[0] <= 64).then_some(cells)
}

/// Positions of lines dividing `count` unit intervals from `start` into
/// `cells` parts each, the interval edges excluded.
fn division_lines(start: f64, count: u32, cells: u32) -> Vec<f64> {
    let mut lines = Vec::new();
    for unit in 0..count {
        for k in 1..cells {
            lines.push(start + f64::from(unit) + f64::from(k) / f64::from(cells));
        }
    }
    lines
}

/// A panel of film positions over `size` pixels starting at pixel `origin`
/// (y downwards, as on film), with pixel edges drawn heavily and each pixel
/// divided into the strata of `spp` samples.
pub fn film_panel(
    title: String,
    positions: Vec<[f64; 2]>,
    origin: [u32; 2],
    size: [u32; 2],
    spp: u32,
) -> ScatterPanel {
    let x0 = f64::from(origin[0]);
    let y0 = f64::from(origin[1]);
    let mut panel = ScatterPanel::new(title, positions)
        .with_ranges([x0, x0 + f64::from(size[0])], [y0, y0 + f64::from(size[1])]);
    panel.y_down = true;
    if let Some([cx, cy]) = strata(spp) {
        panel.grid = [
            division_lines(x0, size[0], cx),
            division_lines(y0, size[1], cy),
        ];
    }
    panel.boundaries = [
        (1..size[0]).map(|k| x0 + f64::from(k)).collect(),
        (1..size[1]).map(|k| y0 + f64::from(k)).collect(),
    ];
    panel
}

/// A panel title naming the sampler and, for the paper's samplers, the threshold.
pub fn sampler_title(config: &SamplerConfig) -> String {
    match config.name {
        SamplerName::Paper | SamplerName::PaperRepro => {
            let all = if config.paper_all_dims {
                ", all dims"
            } else {
                ""
            };
            format!("{} (t = {}{all})", config.name, config.threshold)
        }
        name => name.to_string(),
    }
}

/// `points --plot` in sequence mode: the first two dimensions in the unit square.
pub fn unit_square(title: &str, points: Vec<[f64; 2]>, n: u32, path: &Path) -> Result<()> {
    let mut panel = ScatterPanel::new(title, points);
    if let Some([cx, cy]) = strata(n) {
        panel.grid = [division_lines(0.0, 1, cx), division_lines(0.0, 1, cy)];
    }
    let mut grid = ScatterGrid::row(vec![panel]);
    grid.panel_size = 600.0;
    grid.to_canvas().save(path)?;
    Ok(())
}

/// `points --plot` in pixel mode: the film positions inside the pixel.
pub fn pixel(
    config: &SamplerConfig,
    pixel: [u32; 2],
    positions: Vec<[f64; 2]>,
    path: &Path,
) -> Result<()> {
    let title = format!(
        "{}: pixel ({}, {}), {} spp",
        sampler_title(config),
        pixel[0],
        pixel[1],
        config.spp
    );
    let panel = film_panel(title, positions, pixel, [1, 1], config.spp);
    let mut grid = ScatterGrid::row(vec![panel]);
    grid.panel_size = 480.0;
    grid.to_canvas().save(path)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strata_split_the_digits_between_the_axes() {
        assert_eq!(strata(16), Some([4, 4]));
        assert_eq!(strata(32), Some([8, 4]));
        assert_eq!(strata(1), Some([1, 1]));
        assert_eq!(strata(20), Some([4, 4]));
        assert_eq!(strata(1 << 13), None);
    }

    #[test]
    fn film_panel_marks_inner_pixel_edges() {
        let p = film_panel("t".into(), vec![], [0, 0], [2, 2], 16);
        assert_eq!(p.boundaries[0], vec![1.0]);
        assert_eq!(p.grid[0], vec![0.25, 0.5, 0.75, 1.25, 1.5, 1.75]);
        assert!(p.y_down);
    }
}
