//! Criterion benchmarks of the Sobol core, side by side with `sobol_burley`.
//!
//! * `sample_1d`: one value per call, over the fixed `(index, dimension)` list
//!   of [`lowdisc_benches::pairs_1d`]. lowdisc's `sample_randomized` with each
//!   [`RandomizeStrategy`], the paper's permutation (reproducible and literal), and
//!   `sobol_burley::sample`. `sobol_burley` returns an `f32` and, besides the
//!   Owen scramble of the value, shuffles the index (an Owen scramble of the
//!   index); the like-for-like lowdisc entry is `fast-owen-f32`: fast Owen
//!   scrambling converted with `lowdisc::to_f32` (lowdisc does not shuffle the
//!   index).
//! * `sample_4d`: four consecutive dimensions per call, over
//!   [`lowdisc_benches::pairs_4d`]; `sobol_burley::sample_4d` against
//!   `lowdisc::sobol::sample_4d`.
//! * `gray_batch`: `GrayCodeBatch::fill` (and `fill_f32`) of unscrambled
//!   points, throughput in values per second for several point widths.
//!
//! Throughput is reported per element: one element is one call for
//! `sample_1d` and `sample_4d` (a 4-D call yields four values), and one value
//! for `gray_batch`. Times are the benchmark thread's CPU time
//! ([`ThreadCpuTime`]; `LOWDISC_BENCH_WALL_CLOCK=1` for wall-clock time).
//! `cargo run -p lowdisc-benches --bin bench-table` prints the README table.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use lowdisc::RandomizeStrategy;
use lowdisc::paper::{PaperLiteral, paper_reproducible};
use lowdisc::sobol::{GrayCodeBatch, sample_4d, sample_randomized};
use lowdisc_benches::clock::ThreadCpuTime;
use lowdisc_benches::{BATCH_VALUES, BATCH_WIDTHS, PAIRS, pairs_1d, pairs_4d};

/// The seed of every randomization benchmarked.
const SEED: u64 = 0x1234_5678;

/// The randomizations of `sample_randomized`, by benchmark name.
fn strategies() -> [(&'static str, RandomizeStrategy); 5] {
    RandomizeStrategy::ALL.map(|r| (r.name(), r))
}

fn sample_1d(c: &mut Criterion<ThreadCpuTime>) {
    let pairs = pairs_1d();
    let mut group = c.benchmark_group("sample_1d");
    group.throughput(Throughput::Elements(PAIRS as u64));
    for (name, randomize) in strategies() {
        group.bench_function(BenchmarkId::new("lowdisc", name), |b| {
            b.iter(|| {
                let (randomize, seed) = black_box((randomize, SEED));
                for &(index, dim) in black_box(&pairs) {
                    black_box(sample_randomized(index, dim, randomize, seed));
                }
            })
        });
    }
    group.bench_function(BenchmarkId::new("lowdisc", "fast-owen-f32"), |b| {
        b.iter(|| {
            let (randomize, seed) = black_box((RandomizeStrategy::FastOwen, SEED));
            for &(index, dim) in black_box(&pairs) {
                black_box(lowdisc::to_f32(sample_randomized(
                    index, dim, randomize, seed,
                )));
            }
        })
    });
    group.bench_function(BenchmarkId::new("sobol_burley", "sample"), |b| {
        b.iter(|| {
            let seed = black_box(SEED as u32);
            for &(index, dim) in black_box(&pairs) {
                black_box(sobol_burley::sample(index, dim, seed));
            }
        })
    });
    group.bench_function(BenchmarkId::new("lowdisc", "paper-reproducible"), |b| {
        b.iter(|| {
            let threshold = black_box(0.5);
            for &(index, dim) in black_box(&pairs) {
                black_box(paper_reproducible(index, dim, threshold, SEED));
            }
        })
    });
    group.bench_function(BenchmarkId::new("lowdisc", "paper-literal"), |b| {
        let mut literal = PaperLiteral::new(0.5, Some(SEED)).expect("valid threshold");
        b.iter(|| {
            for &(index, dim) in black_box(&pairs) {
                black_box(literal.sample(index, dim));
            }
        })
    });
    group.finish();
}

fn sample_4d_group(c: &mut Criterion<ThreadCpuTime>) {
    let pairs = pairs_4d();
    let mut group = c.benchmark_group("sample_4d");
    group.throughput(Throughput::Elements(PAIRS as u64));
    for (name, randomize) in strategies() {
        group.bench_function(BenchmarkId::new("lowdisc", name), |b| {
            b.iter(|| {
                let (randomize, seed) = black_box((randomize, SEED));
                for &(index, set) in black_box(&pairs) {
                    black_box(sample_4d(index, 4 * set, randomize, seed));
                }
            })
        });
    }
    group.bench_function(BenchmarkId::new("lowdisc", "fast-owen-f32"), |b| {
        b.iter(|| {
            let (randomize, seed) = black_box((RandomizeStrategy::FastOwen, SEED));
            for &(index, set) in black_box(&pairs) {
                black_box(sample_4d(index, 4 * set, randomize, seed).map(lowdisc::to_f32));
            }
        })
    });
    group.bench_function(BenchmarkId::new("sobol_burley", "sample_4d"), |b| {
        b.iter(|| {
            let seed = black_box(SEED as u32);
            for &(index, set) in black_box(&pairs) {
                black_box(sobol_burley::sample_4d(index, set, seed));
            }
        })
    });
    group.finish();
}

fn gray_batch(c: &mut Criterion<ThreadCpuTime>) {
    let mut group = c.benchmark_group("gray_batch");
    group.throughput(Throughput::Elements(BATCH_VALUES as u64));
    for width in BATCH_WIDTHS {
        let points = BATCH_VALUES / width as usize;
        let mut batch = GrayCodeBatch::new(0, width).expect("dimensions in range");
        let mut out = vec![0u32; BATCH_VALUES];
        group.bench_function(BenchmarkId::new("fill", width), |b| {
            b.iter(|| {
                if batch.remaining() < points as u64 {
                    batch.seek(0);
                }
                black_box(batch.fill(black_box(&mut out)));
            })
        });
        let mut out = vec![0f32; BATCH_VALUES];
        group.bench_function(BenchmarkId::new("fill_f32", width), |b| {
            b.iter(|| {
                if batch.remaining() < points as u64 {
                    batch.seek(0);
                }
                black_box(batch.fill_f32(black_box(&mut out)));
            })
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().with_measurement(ThreadCpuTime::from_env());
    targets = sample_1d, sample_4d_group, gray_batch
}
criterion_main!(benches);
