//! Criterion benchmark of the per-value cost of every catalog pixel sampler,
//! driven the way a path tracer drives it.
//!
//! Each sampler is built from the catalog for a 64x64 image at 16 samples
//! per pixel (seed 7). One benchmark iteration renders one 16x16 tile of that
//! image (the tiles are visited in turn, so all 64x64 pixels are covered
//! every 16 iterations): for every pixel and every sample index it calls
//! `start_pixel_sample`, then `get_pixel_2d` once and ten times `get_2d` then
//! `get_1d` (30 dimensions), the pattern of a camera ray followed by a few
//! bounces. That is 21 sampler calls per pixel sample, 86,016 per iteration;
//! the throughput is reported in calls ("values": a 2-D value counts once),
//! so `1e9 / (elements per second)` is the ns per value, including the
//! share of `start_pixel_sample`. Every value goes through `black_box`.
//!
//! Run with `cargo bench -p lowdisc-benches --bench pixel_samplers`. Times
//! are the benchmark thread's CPU time (see `src/clock.rs`).

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use lowdisc::catalog::{Sampler, SamplerConfig, SamplerName};
use lowdisc::pixel::PixelSampler;
use lowdisc_benches::clock::ThreadCpuTime;

/// Image side in pixels.
const IMAGE: u32 = 64;
/// Tile side in pixels (one benchmark iteration).
const TILE: u32 = 16;
/// Samples per pixel.
const SPP: u32 = 16;
/// `get_2d` + `get_1d` pairs drawn per pixel sample after the pixel offset.
const PAIRS_PER_SAMPLE: u32 = 10;
/// Sampler calls per pixel sample.
const CALLS_PER_SAMPLE: u32 = 1 + 2 * PAIRS_PER_SAMPLE;

/// Renders tile `tile` (row-major over the image's tiles) with `sampler`.
fn render_tile(sampler: &mut Sampler, tile: u32) {
    let per_row = IMAGE / TILE;
    let (tx, ty) = ((tile % per_row) * TILE, (tile / per_row) * TILE);
    for y in ty..ty + TILE {
        for x in tx..tx + TILE {
            for s in 0..SPP {
                sampler.start_pixel_sample([x, y], s, 0);
                black_box(sampler.get_pixel_2d());
                for _ in 0..PAIRS_PER_SAMPLE {
                    black_box(sampler.get_2d());
                    black_box(sampler.get_1d());
                }
            }
        }
    }
}

fn pixel_samplers(c: &mut Criterion<ThreadCpuTime>) {
    let mut group = c.benchmark_group("pixel_samplers");
    let calls = u64::from(TILE * TILE * SPP * CALLS_PER_SAMPLE);
    group.throughput(Throughput::Elements(calls));
    group.sample_size(10);
    let tiles = (IMAGE / TILE) * (IMAGE / TILE);
    for name in SamplerName::ALL {
        let mut config = SamplerConfig::new(name);
        config.seed = 7;
        config.spp = SPP;
        config.resolution = [IMAGE, IMAGE];
        let mut sampler = config.build().expect("a valid catalog configuration");
        let mut tile = 0;
        group.bench_function(BenchmarkId::new("tile", name.as_str()), |b| {
            b.iter(|| {
                render_tile(black_box(&mut sampler), tile);
                tile = (tile + 1) % tiles;
            })
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().with_measurement(ThreadCpuTime::from_env());
    targets = pixel_samplers
}
criterion_main!(benches);
