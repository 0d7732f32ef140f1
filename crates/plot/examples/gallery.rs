//! Writes one plot of each kind (scatter grid, log-log line chart, heatmap)
//! as PNG and SVG into the directory given as the first argument (default
//! `.`): `cargo run -p lowdisc-plot --example gallery -- /tmp/gallery`.

use lowdisc_plot::{ColorMap, Heatmap, LineChart, ScatterGrid, ScatterPanel, Series};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::path::PathBuf::from(std::env::args().nth(1).unwrap_or_else(|| ".".into()));
    // A 2-D lattice and the van der Corput / Hammersley set.
    let lattice: Vec<[f64; 2]> = (0..64)
        .map(|k| [(k % 8) as f64 / 8.0 + 0.0625, (k / 8) as f64 / 8.0 + 0.0625])
        .collect();
    let hammersley: Vec<[f64; 2]> = (0u32..64)
        .map(|k| {
            [
                f64::from(k) / 64.0,
                f64::from(k.reverse_bits()) / 4_294_967_296.0,
            ]
        })
        .collect();
    let grid = ScatterGrid::row(vec![
        ScatterPanel::new("lattice", lattice).with_regular_grid(8),
        ScatterPanel::new("Hammersley", hammersley).with_regular_grid(8),
    ]);
    let scatter = grid.to_canvas();
    // Convergence: N^-1/2 and N^-1 with a reference slope.
    let ns: Vec<f64> = (0..12).map(|k| 2f64.powi(k + 2)).collect();
    let chart = LineChart::log_log("Convergence", "samples N", "RMS error")
        .with(Series::new(
            "random",
            ns.iter().map(|&n| [n, 0.5 / n.sqrt()]).collect(),
        ))
        .with(Series::new(
            "Sobol",
            ns.iter().map(|&n| [n, 0.8 / n]).collect(),
        ))
        .with(Series::reference(
            "N^-1",
            ns.iter().map(|&n| [n, 1.0 / n]).collect(),
        ));
    let line = chart.to_canvas();
    // A heatmap of a smooth function.
    let (w, h) = (64u32, 40u32);
    let values = (0..w * h)
        .map(|i| ((i % w) as f64 * 0.2).sin() * ((i / w) as f64 * 0.15).cos())
        .collect();
    let mut heat = Heatmap::new("sin(x) cos(y)", w, h, values)?;
    heat.scale = 6.0;
    heat.colormap = ColorMap::Diverging;
    let heat = heat.to_canvas();
    for (name, canvas) in [("scatter", &scatter), ("line", &line), ("heatmap", &heat)] {
        canvas.save(dir.join(format!("{name}.png")))?;
        canvas.save(dir.join(format!("{name}.svg")))?;
    }
    Ok(())
}
