//! The render loop: the image is cut into the square tiles of
//! [`lowdisc_tiles`], rendered in parallel with rayon, and merged in tile
//! order.
//!
//! **Determinism.** Tile `k` (row-major order over the film's pixel bounds)
//! gets its own copy of the pixel sampler, `sampler.with_stream(k)`, and its
//! own [`FilmTile`] of the view's [`Film`]; a tile's
//! result depends only on the scene, the view, the options and `k`, and tiles are merged
//! in order. The image and every counter are therefore bit-identical whatever
//! the number of threads.
//!
//! **Windows and sample ranges.** [`RenderOptions::window`] renders only
//! some pixels and [`RenderOptions::samples`] only some sample indices of
//! each. The tile grid is always that of the film's pixel bounds and tile
//! `k` keeps stream `k`, so a pixel's sums in a window equal its sums in the
//! whole render bit for bit: every sample goes to its own pixel only (see
//! [`crate::film`]). Each tile takes the camera samples of its
//! [`Walk`] and adds the ones it keeps to the film;
//! for a sampler whose values depend on the order of calls (the paper's
//! literal stream) the walk replays the tile from its first pixel. Each
//! pixel's sums over a sample range are added in index order from 0, so
//! merging ranges adds per-range sums: equal to the whole render's up to
//! `f64` rounding (not bit for bit).
//!
//! **Spectral mode** ([`RenderOptions::spectral`]): each camera sample
//! draws one more dimension, the wavelength sample, first (dimension 0, as
//! pbrt-v4's `Get1D` before `GetCameraSample`), so the lens takes dimensions
//! 1-2 and bounce `k` starts at `3 + 7k`; the radiance at the four
//! wavelengths goes to the film as the sensor's XYZ, which the film turns
//! into sRGB ([`crate::spectrum::sensor`]). RGB mode draws no wavelength
//! dimension (lens 0-1, bounce `k` at `2 + 7k`).
//!
//! **Non-finite samples.** A camera sample whose radiance is NaN or infinite is
//! counted in [`RenderStats::nonfinite_samples`] and dropped by the film
//! (neither its value nor its filter weight reaches the pixel); it is never
//! written.
//!
//! **Progress** goes through a [`ProgressSink`] (any `Fn(Progress) + Sync`
//! closure): the library itself never prints.
//!
//! **Cancellation.** [`render_cancellable`] takes a flag that another thread
//! may set (a front end's Ctrl-C): every tile checks it before each camera
//! sample, so the render stops within one path per worker and returns
//! [`RenderError::Cancelled`]. [`render`] is the same loop with a flag that
//! is never set.

mod camera_sample;

pub use crate::error::RenderError;
pub use crate::settings::ranges::{MAX_SPP, MAX_THREADS};
pub use crate::settings::{RenderOptions, SampleRange};
pub use camera_sample::{FilmColour, Shot, trace_sample};

use crate::film::{Film, FilmError, FilmTile, PixelBounds, PixelSum};
use crate::integrator::PathStats;
use crate::scene::Scene;
use crate::spectrum::sensor::output_matrix;
use crate::spectrum::{Rgb, SampledSpectrum};
use crate::view::View;
use lowdisc::catalog::{Sampler, SamplerConfig};
use lowdisc::pixel::PixelSampler;
use lowdisc_tiles::{Tile, Walk, tiles};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// A progress report, sent after every finished tile.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Progress {
    /// Tiles finished.
    pub tiles_done: usize,
    /// Tiles in the image.
    pub tiles_total: usize,
    /// Camera samples finished.
    pub samples_done: u64,
    /// Camera samples in the image.
    pub samples_total: u64,
    /// Rays traced so far.
    pub rays: u64,
}

/// Receives progress reports (from worker threads, in completion order).
pub trait ProgressSink: Sync {
    /// Called after each tile.
    fn report(&self, p: Progress);
}

impl<F: Fn(Progress) + Sync> ProgressSink for F {
    fn report(&self, p: Progress) {
        self(p)
    }
}

/// A sink that ignores every report.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoProgress;

impl ProgressSink for NoProgress {
    fn report(&self, _: Progress) {}
}

/// What a render counted.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RenderStats {
    /// Rays traced (camera, continuation, shadow).
    pub rays: u64,
    /// Camera samples taken.
    pub samples: u64,
    /// Samples dropped because their radiance was NaN or infinite.
    pub nonfinite_samples: u64,
    /// Worker threads used.
    pub threads: usize,
    /// Wall-clock time of the render loop.
    pub time: Duration,
}

impl RenderStats {
    /// Rays per second (0 when no time elapsed).
    pub fn rays_per_second(&self) -> f64 {
        let s = self.time.as_secs_f64();
        if s > 0.0 { self.rays as f64 / s } else { 0.0 }
    }
}

/// A rendered film, its image (linear RGB, row-major, top row first, the
/// film's pixel bounds) and the render's counters.
#[derive(Clone, Debug)]
pub struct RenderOutput {
    /// The film with every tile merged (its pixel sums).
    pub film: Film,
    /// The film's pixel values.
    pub image: lowdisc_image::RgbImage,
    /// Counters and timing.
    pub stats: RenderStats,
    /// Conditions worth telling the user about (e.g. a scene without lights).
    pub warnings: Vec<String>,
}

impl RenderOutput {
    /// Writes [`Self::image`], choosing the format by extension: `.exr`
    /// (linear float), `.png` (8-bit sRGB after multiplying by `exposure`),
    /// `.pfm`, `.hdr`.
    pub fn write(&self, path: impl AsRef<std::path::Path>, exposure: f32) -> Result<(), FilmError> {
        let options = lowdisc_image::WriteOptions { exposure };
        Ok(lowdisc_image::write_image(path, &self.image, &options)?)
    }

    /// Mean of every pixel, per channel.
    pub fn mean(&self) -> [f64; 3] {
        let mut m = [0.0f64; 3];
        for p in self.image.pixels() {
            for c in 0..3 {
                m[c] += f64::from(p[c]);
            }
        }
        let n = self.image.pixel_count().max(1) as f64;
        m.map(|v| v / n)
    }
}

/// What one tile produced.
struct TileResult {
    film: FilmTile,
    stats: PathStats,
    samples: u64,
}

/// Renders `scene` seen through `view` with `opts`, reporting progress to
/// `progress`.
pub fn render(
    scene: &Scene,
    view: &View,
    opts: &RenderOptions,
    progress: &dyn ProgressSink,
) -> Result<RenderOutput, RenderError> {
    render_cancellable(scene, view, opts, progress, &AtomicBool::new(false))
}

/// [`render`] that stops early, with [`RenderError::Cancelled`], once
/// `cancel` is set (from another thread: the progress sink, a signal
/// handler). A render that finishes before the flag is set is the same
/// image as [`render`]'s.
///
/// ```
/// use std::sync::atomic::AtomicBool;
/// use lowdisc::catalog::SamplerName;
/// use lowdisc_render::cornell::cornell_scene;
/// use lowdisc_render::render::{NoProgress, RenderError, RenderOptions, render_cancellable};
/// use lowdisc_render::view::View;
///
/// let (scene, spec) = cornell_scene().unwrap();
/// let view = View::new(&spec, [8, 8]).unwrap();
/// let opts = RenderOptions::new(SamplerName::ZSobol, 0, 1);
/// let stop = AtomicBool::new(true);
/// let out = render_cancellable(&scene, &view, &opts, &NoProgress, &stop);
/// assert!(matches!(out, Err(RenderError::Cancelled)));
/// let go = AtomicBool::new(false);
/// assert!(render_cancellable(&scene, &view, &opts, &NoProgress, &go).is_ok());
/// ```
pub fn render_cancellable(
    scene: &Scene,
    view: &View,
    opts: &RenderOptions,
    progress: &dyn ProgressSink,
    cancel: &AtomicBool,
) -> Result<RenderOutput, RenderError> {
    opts.validate()?;
    let full = view.pixel_bounds();
    let window = opts.window_in(full)?;
    let range = opts.sample_range();
    let mut film = output_film(view, window, opts.spectral);
    let sampler = SamplerConfig {
        resolution: view.resolution(),
        ..opts.sampler
    }
    .build()?;
    let mut warnings = Vec::new();
    if scene.lights().is_empty() {
        warnings.push("the scene has no lights: the image is black".to_string());
    }
    // The whole film's tile grid, numbered before the window is applied.
    let rects: Vec<Tile> = tiles(full)
        .filter(|t| t.bounds.intersect(&window).area() > 0)
        .collect();
    let total = Totals {
        tiles: rects.len(),
        samples: window.area() as u64 * u64::from(range.len()),
        done: AtomicUsize::new(0),
        samples_done: AtomicU64::new(0),
        rays: AtomicU64::new(0),
    };
    let start = Instant::now();
    let run = || -> Vec<TileResult> {
        rects
            .par_iter()
            .map(|&tile| {
                let r = render_tile(
                    (scene, view, opts),
                    &sampler,
                    tile,
                    film.tile(tile.bounds),
                    cancel,
                );
                total.finished(&r, progress);
                r
            })
            .collect()
    };
    let (results, threads) = match opts.threads {
        None => (run(), rayon::current_num_threads()),
        Some(n) => {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| RenderError::ThreadPool(e.to_string()))?;
            (pool.install(run), n)
        }
    };
    if cancel.load(Ordering::Relaxed) {
        return Err(RenderError::Cancelled);
    }
    let mut stats = RenderStats {
        threads,
        ..RenderStats::default()
    };
    for r in &results {
        film.merge_tile(&r.film);
        stats.rays += r.stats.rays;
        stats.samples += r.samples;
    }
    stats.nonfinite_samples = film.nonfinite_count();
    stats.time = start.elapsed();
    if stats.nonfinite_samples > 0 {
        warnings.push(format!(
            "{} samples had NaN or infinite radiance and were dropped",
            stats.nonfinite_samples
        ));
    }
    let image = film.to_image().map_err(RenderError::Film)?;
    Ok(RenderOutput {
        film,
        image,
        stats,
        warnings,
    })
}

/// The empty film a render accumulates into: the pixels of `window` inside
/// the view's film, whose output is sRGB from the sensor's XYZ when
/// `spectral`, white-balanced as the film asks.
pub fn output_film(view: &View, window: PixelBounds, spectral: bool) -> Film {
    let params = view.film();
    let mut film = Film::with_bounds(params, view.pixel_bounds().intersect(&window));
    film.set_output_matrix(output_matrix(spectral, params.white_balance));
    film
}

/// The image that a render (spectral or not) of `window` of the view's
/// film whose pixel sums are `sums` (row-major over the window) gives:
/// the same values as that render's own image. Merged sums of a split
/// render's parts become the merged image through it.
pub fn image_of_sums(
    view: &View,
    window: PixelBounds,
    spectral: bool,
    sums: &[PixelSum],
) -> Result<lowdisc_image::RgbImage, FilmError> {
    // A window reaching outside the film keeps fewer pixels than `sums`.
    let mut film = output_film(view, window, spectral);
    film.set_sums(sums)?;
    film.to_image()
}

/// Shared progress counters.
struct Totals {
    tiles: usize,
    samples: u64,
    done: AtomicUsize,
    samples_done: AtomicU64,
    rays: AtomicU64,
}

impl Totals {
    fn finished(&self, r: &TileResult, sink: &dyn ProgressSink) {
        let tiles_done = self.done.fetch_add(1, Ordering::Relaxed) + 1;
        let samples_done = self.samples_done.fetch_add(r.samples, Ordering::Relaxed) + r.samples;
        let rays = self.rays.fetch_add(r.stats.rays, Ordering::Relaxed) + r.stats.rays;
        sink.report(Progress {
            tiles_done,
            tiles_total: self.tiles,
            samples_done,
            samples_total: self.samples,
            rays,
        });
    }
}

/// Renders the samples of `film` (the part of `tile` inside the window)
/// with the tile's sampler stream, along the tile's walk.
///
/// The loop is compiled for the default sampler and for `independent` on
/// their own types, so that their calls inline into the integrator; every
/// other sampler goes through the [`Sampler`] enum's dispatch. The values
/// are the same either way.
fn render_tile(
    (scene, view, opts): (&Scene, &View, &RenderOptions),
    sampler: &Sampler,
    tile: Tile,
    film: FilmTile,
    cancel: &AtomicBool,
) -> TileResult {
    let range = opts.sample_range();
    let walk = Walk::new(
        tile.bounds,
        film.bounds(),
        range.start..range.end,
        opts.sampler.spp,
        sampler.is_order_dependent(),
    );
    match sampler.with_stream(tile.index) {
        Sampler::ZSobol(s) => render_tile_with(scene, view, opts, s, (walk, film), cancel),
        Sampler::Independent(s) => render_tile_with(scene, view, opts, s, (walk, film), cancel),
        other => render_tile_with(scene, view, opts, other, (walk, film), cancel),
    }
}

/// [`render_tile`] with a sampler of type `S`: traces every camera sample
/// of `walk` in order and adds the kept ones to `film`, until `cancel` is
/// set.
fn render_tile_with<S: PixelSampler>(
    scene: &Scene,
    view: &View,
    opts: &RenderOptions,
    mut sampler: S,
    (walk, mut film): (Walk, FilmTile),
    cancel: &AtomicBool,
) -> TileResult {
    let mut stats = PathStats::default();
    let shot = Shot {
        scene,
        view,
        integrator: &opts.integrator,
        seed: opts.sampler.seed,
    };
    let mut samples = 0;
    for visit in walk {
        if cancel.load(Ordering::Relaxed) {
            break;
        }
        let (pixel, s) = (visit.pixel, visit.index);
        let (l, weight) = if opts.spectral {
            trace_sample::<SampledSpectrum, _>(&shot, &mut sampler, pixel, s, &mut stats)
        } else {
            trace_sample::<Rgb, _>(&shot, &mut sampler, pixel, s, &mut stats)
        };
        if visit.keep {
            film.add_sample(pixel, l, weight);
            samples += 1;
        }
    }
    TileResult {
        film,
        stats,
        samples,
    }
}
