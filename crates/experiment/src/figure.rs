//! The paper's figure: the film positions of every sample of a few pixels,
//! one scatter panel per sampler, with heavy lines at pixel edges and light
//! lines at the strata of the samples per pixel. Used by the report and by
//! `lowdisc figure` and `lowdisc points --plot`.

use anyhow::Result;
use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc::pixel::PixelSampler;
use lowdisc_plot::{Canvas, ScatterGrid, ScatterPanel};

/// The film positions of every pixel's samples, pixels row by row, all
/// drawn from one sampler (so the literal paper stream runs through them all).
pub fn film_positions(config: &SamplerConfig) -> Result<Vec<[f64; 2]>> {
    let mut sampler = config.build()?;
    let mut positions = Vec::new();
    for y in 0..config.resolution[1] {
        for x in 0..config.resolution[0] {
            for index in 0..config.spp {
                sampler.start_pixel_sample([x, y], index, 0);
                let [ox, oy] = sampler.get_pixel_2d();
                positions.push([f64::from(x) + f64::from(ox), f64::from(y) + f64::from(oy)]);
            }
        }
    }
    Ok(positions)
}

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
pub fn division_lines(start: f64, count: u32, cells: u32) -> Vec<f64> {
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

/// The figure: one panel per sampler configuration (each over its whole
/// `resolution`), side by side, `panel_size` pixels each, under `title`.
pub fn figure(samplers: &[SamplerConfig], panel_size: f32, title: String) -> Result<Canvas> {
    let mut panels = Vec::with_capacity(samplers.len());
    for sampler in samplers {
        panels.push(film_panel(
            sampler_title(sampler),
            film_positions(sampler)?,
            [0, 0],
            sampler.resolution,
            sampler.spp,
        ));
    }
    let mut grid = ScatterGrid::row(panels);
    grid.panel_size = panel_size;
    grid.title = Some(title);
    Ok(grid.to_canvas())
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

    #[test]
    fn film_positions_stay_inside_their_pixels() {
        let mut c = SamplerConfig::new(SamplerName::Sobol);
        c.spp = 4;
        c.resolution = [2, 2];
        let pos = film_positions(&c).unwrap();
        assert_eq!(pos.len(), 16);
        for (k, p) in pos.iter().enumerate() {
            let pixel = k / 4;
            let (x, y) = ((pixel % 2) as f64, (pixel / 2) as f64);
            assert!(
                p[0] >= x && p[0] < x + 1.0 && p[1] >= y && p[1] < y + 1.0,
                "{p:?}"
            );
        }
    }
}
