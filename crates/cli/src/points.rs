//! `lowdisc points`: print (or plot) the points of a named sequence, or the
//! samples a pixel sampler gives one pixel.

use std::io::Write;
use std::ops::Range;
use std::path::PathBuf;

use anyhow::{Result, bail};
use clap::{Args, ValueEnum};
use lowdisc::catalog::{Family, Order, SamplerConfig, generate_points};
use lowdisc_tiles::{pixel_draws, pixel_rows};

use crate::output::{Format, TableWriter};
use crate::{default_output, parse, plots, sampler_help};

/// Point order for the Sobol family.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum OrderArg {
    /// Gray-code order, as Joe & Kuo's generator and scipy.stats.qmc.Sobol.
    Gray,
    /// Sobol's natural order (point k uses index k), as pbrt.
    Natural,
}

/// The most points `--plot` draws.
pub const MAX_PLOT_POINTS: u32 = 1 << 20;

/// The most further values per sample in pixel mode.
pub const MAX_PIXEL_DIMS: u32 = 1 << 16;
/// The most sampler draws of one pixel-mode request, replay included.
const MAX_PIXEL_DRAWS: u64 = 1 << 32;

/// The long help of `points` (`lowdisc points --help`), with the names of
/// each family from the catalog's table.
pub fn long_about() -> String {
    let sobol = sampler_help::names_where(Family::is_sobol, 8, 72);
    let per_pixel = sampler_help::names_where(|f| f == Family::PerPixel, 1, 72);
    format!(
        "\
Print points of a sequence, or the samples of one pixel.\n\
\n\
Sequence mode (default): prints the first N points of the sampler's\n\
sequence in dimensions 0..D (or A..B), one point per line. The Sobol\n\
family ({sobol})\n\
prints in Gray-code order by default, so\n\
`lowdisc points --sampler sobol --n 65536 --dims 1024 --format u32`\n\
prints exactly scipy.stats.qmc.Sobol(1024, scramble=False, bits=32)\n\
.random(65536) as the integers floor(x * 2^32). The per-pixel samplers\n\
({per_pixel})\n\
print the samples of pixel (0,0) of a 1x1 image with N samples per pixel.\n\
\n\
Pixel mode (--pixel X,Y): for each of the --spp samples of that pixel of a\n\
--res image, prints the film position (X + ox, Y + oy), where (ox, oy) is\n\
get_pixel_2d, followed by --dims further values taken as get_2d pairs (and\n\
one get_1d for an odd last value), starting at sampler dimension 0, from\n\
the sampler as the renderer uses it: the stream of the pixel's tile of the\n\
renderer's grid (16-pixel squares). The paper sampler's single stream is\n\
replayed from the tile's first pixel, each earlier sample drawing as many\n\
values as asked for here.\n\
\n\
--plot FILE.png|FILE.svg draws instead of printing: the first two\n\
dimensions of the points (with a grid of 2^ceil(m/2) x 2^floor(m/2) cells,\n\
m = floor(log2 N): a (0,m,2)-net has one point per cell), or in pixel mode\n\
the film positions inside the pixel.\n\
"
    )
}

/// The arguments of `points`.
#[derive(Debug, Args)]
pub struct PointsArgs {
    /// Sampler name (`--help` lists them all).
    #[arg(long, short = 's', value_name = "NAME", long_help = sampler_help::sampler_list("Sampler name, one of:", ""))]
    sampler: String,
    /// Generator matrices for the Sobol samplers: a built-in net (`sobol`,
    /// `onetwo`) or a file of Joe-Kuo direction numbers or matrices
    /// [default: sobol].
    #[arg(long, value_name = "NAME|FILE", long_help = sampler_help::net_help())]
    net: Option<String>,
    /// Seed of every random choice.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Number of points (sequence mode) [default: 16].
    #[arg(long, short = 'n', value_name = "N", conflicts_with = "pixel")]
    n: Option<u32>,
    /// Number of dimensions 0..D [default: 2; pixel mode: further values, default 0].
    #[arg(long, value_name = "D", conflicts_with = "dim_range")]
    dims: Option<u32>,
    /// Dimensions A up to but excluding B (sequence mode).
    #[arg(
        long,
        value_name = "A..B",
        conflicts_with = "pixel",
        allow_hyphen_values = true
    )]
    dim_range: Option<String>,
    /// Paper permutation threshold in [0,1]: probability a matrix column is left unflipped.
    #[arg(long, default_value_t = SamplerConfig::DEFAULT_THRESHOLD, allow_negative_numbers = true)]
    threshold: f64,
    /// Let the paper permutation act on dimensions 0-1 too (pixel samplers);
    /// `--paper-all-dims` alone means true.
    #[arg(long, value_name = "BOOL", default_value_t = false, num_args = 0..=1,
          default_missing_value = "true", require_equals = true, action = clap::ArgAction::Set)]
    paper_all_dims: bool,
    /// Point order of the Sobol family [default: gray]; other samplers ignore it.
    #[arg(long, value_enum, conflicts_with = "pixel")]
    order: Option<OrderArg>,
    /// Output format.
    #[arg(long, short = 'f', value_enum, default_value = "text")]
    format: Format,
    /// Pixel mode: print the samples of pixel X,Y.
    #[arg(long, value_name = "X,Y", allow_hyphen_values = true)]
    pixel: Option<String>,
    /// Samples per pixel (pixel mode).
    #[arg(long, default_value_t = 16, requires = "pixel")]
    spp: u32,
    /// Image resolution (pixel mode) [default: 2x2].
    #[arg(
        long,
        value_name = "WxH",
        requires = "pixel",
        allow_hyphen_values = true
    )]
    res: Option<String>,
    /// Draw the points to FILE.png or FILE.svg instead of printing them.
    #[arg(long, value_name = "FILE")]
    plot: Option<PathBuf>,
}

/// What to print: a validated `points` invocation.
#[derive(Debug, Clone)]
pub struct PointsConfig {
    /// The sampler and its options.
    sampler: SamplerConfig,
    /// Sequence or pixel mode.
    mode: Mode,
    /// Output format.
    format: Format,
    /// Plot file instead of printing.
    plot: Option<PathBuf>,
}

#[derive(Debug, Clone)]
enum Mode {
    Sequence {
        n: u32,
        dims: Range<u32>,
        order: Order,
    },
    Pixel {
        pixel: [u32; 2],
        extra_dims: u32,
    },
}

impl PointsArgs {
    /// Checks every option and builds the configuration.
    pub fn into_config(self) -> Result<PointsConfig> {
        let mut sampler = parse::sampler_config(
            &self.sampler,
            self.seed,
            self.threshold,
            self.paper_all_dims,
        )?;
        if let Some(net) = &self.net {
            sampler.net = parse::net(net)?;
            sampler.validate_net()?;
        }
        if let Some(plot) = &self.plot {
            lowdisc_plot::Format::from_path(plot)?;
        }
        let mode = if let Some(pixel) = &self.pixel {
            let pixel = parse::pixel(pixel)?;
            sampler.resolution = match &self.res {
                Some(res) => parse::resolution(res)?,
                None => [2, 2],
            };
            sampler.spp = self.spp;
            if self.spp == 0 {
                bail!("--spp must be at least 1");
            }
            if pixel[0] >= sampler.resolution[0] || pixel[1] >= sampler.resolution[1] {
                let [w, h] = sampler.resolution;
                bail!(
                    "--pixel {},{} is outside the {w}x{h} image (set --res)",
                    pixel[0],
                    pixel[1]
                );
            }
            if self.format == Format::U32 {
                bail!(
                    "--format u32 is not available in pixel mode (film positions are not digit words)"
                );
            }
            let extra_dims = self.dims.unwrap_or(0);
            if extra_dims > MAX_PIXEL_DIMS {
                bail!("--dims must be at most {MAX_PIXEL_DIMS} in pixel mode");
            }
            if self.plot.is_some() && self.spp > MAX_PLOT_POINTS {
                bail!("--plot draws at most {MAX_PLOT_POINTS} points; lower --spp");
            }
            let draws = pixel_draws(&sampler, &sampler.build()?, pixel, extra_dims + 2);
            if draws > MAX_PIXEL_DRAWS {
                bail!(
                    "pixel {},{} needs {draws} sampler draws (the {} stream is replayed from \
                     its tile's first pixel); the limit is {MAX_PIXEL_DRAWS}: lower --spp or \
                     --dims",
                    pixel[0],
                    pixel[1],
                    sampler.name.as_str()
                );
            }
            Mode::Pixel { pixel, extra_dims }
        } else {
            let n = self.n.unwrap_or(16);
            if n == 0 {
                bail!("--n must be at least 1");
            }
            let dims = parse::dims(self.dim_range.as_deref(), self.dims)?;
            let order = match self.order.unwrap_or(OrderArg::Gray) {
                OrderArg::Gray => Order::Gray,
                OrderArg::Natural => Order::Natural,
            };
            if self.plot.is_some() && n > MAX_PLOT_POINTS {
                bail!("--plot draws at most {MAX_PLOT_POINTS} points; lower --n");
            }
            Mode::Sequence { n, dims, order }
        };
        Ok(PointsConfig {
            sampler,
            mode,
            format: self.format,
            plot: self.plot,
        })
    }
}

/// Runs `points`, printing to `out` (or drawing to the plot file).
pub fn run(config: &PointsConfig, out: impl Write) -> Result<()> {
    match &config.mode {
        Mode::Sequence { n, dims, order } => {
            let words = generate_points(&config.sampler, *n, dims.clone(), *order)?;
            let width = dims.len();
            if let Some(path) = &config.plot {
                if width < 2 {
                    bail!("--plot needs at least 2 dimensions");
                }
                let points = words
                    .chunks_exact(width)
                    .map(|p| [lowdisc::to_f64(p[0]), lowdisc::to_f64(p[1])]);
                let title = format!(
                    "{}: {} points, dims {} and {}",
                    config.sampler.name,
                    n,
                    dims.start,
                    dims.start + 1
                );
                plots::unit_square(&title, points.collect(), *n, path)?;
                default_output::report_written(path);
                return Ok(());
            }
            let columns: Vec<String> = dims.clone().map(|d| format!("x{d}")).collect();
            let mut table = TableWriter::new(out, config.format, &columns);
            for point in words.chunks_exact(width) {
                table.write_words(point)?;
            }
            table.finish()?;
        }
        Mode::Pixel { pixel, extra_dims } => {
            if let Some(path) = &config.plot {
                let mut positions = Vec::with_capacity(config.sampler.spp as usize);
                for_each_pixel_sample(&config.sampler, *pixel, 0, |row| {
                    positions.push([row[0], row[1]]);
                    Ok(())
                })?;
                plots::pixel(&config.sampler, *pixel, positions, path)?;
                default_output::report_written(path);
                return Ok(());
            }
            let mut columns = vec!["film_x".to_string(), "film_y".to_string()];
            columns.extend((0..*extra_dims).map(|d| format!("v{d}")));
            let mut table = TableWriter::new(out, config.format, &columns);
            for_each_pixel_sample(&config.sampler, *pixel, *extra_dims, |row| {
                Ok(table.write_floats(row)?)
            })?;
            table.finish()?;
        }
    }
    Ok(())
}

/// Calls `row` with each sample of one pixel, sample indices `0..spp` in
/// order: the film position, then `extra` values from get_2d pairs (get_1d
/// for an odd last one), starting at sampler dimension 0, drawn as the
/// renderer does ([`pixel_rows`]).
pub fn for_each_pixel_sample(
    config: &SamplerConfig,
    pixel: [u32; 2],
    extra: u32,
    mut row: impl FnMut(&[f64]) -> Result<()>,
) -> Result<()> {
    let sampler = config.build()?;
    let mut values = Vec::with_capacity(2 + extra as usize);
    let mut result = Ok(());
    pixel_rows(config, &sampler, pixel, 2 + extra as usize, |r| {
        if result.is_ok() {
            values.clear();
            values.push(f64::from(pixel[0]) + f64::from(r[0]));
            values.push(f64::from(pixel[1]) + f64::from(r[1]));
            values.extend(r[2..].iter().map(|&v| f64::from(v)));
            result = row(&values);
        }
    });
    result
}
