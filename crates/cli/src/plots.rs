//! Drawing point sets for `points --plot`: scatter panels with grid lines at
//! the elementary intervals and heavy lines at pixel edges (the panels of
//! the paper's figure, [`lowdisc_experiment::figure`]).

use std::path::Path;

use anyhow::Result;
use lowdisc::catalog::SamplerConfig;
use lowdisc_experiment::figure::{division_lines, film_panel, sampler_title, strata};
use lowdisc_plot::{ScatterGrid, ScatterPanel};

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
