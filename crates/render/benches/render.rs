//! Path-tracing throughput (rays per second) of whole renders: the built-in
//! Cornell box at 64x64, and bmw-m6 (the shared pbrt-v4 scene, with the
//! ganesha sky as its environment map) at 128x72 when `shared/scenes` is
//! present. Both at 4 spp and maxdepth 5 with the zsobol sampler, all cores.
//! Criterion's throughput is the number of rays one render traces.
//!
//! Full-size figures (1280x720, 16 spp) are measured once with
//! `lowdisc render --stats` and recorded in `docs/thumbnails/README.md`: too
//! slow to repeat in a benchmark loop on a shared machine.

#![allow(missing_docs)] // criterion_group! generates undocumented functions
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use lowdisc_render::cornell::cornell_box;
use lowdisc_render::pbrt::{LoadOptions, load_pbrt_scene};
use lowdisc_render::render::{Progress, RenderOptions, render};
use lowdisc_render::scene::Scene;
use lowdisc_render::view::View;
use std::hint::black_box;

fn options() -> RenderOptions {
    let mut opts = RenderOptions::default();
    opts.sampler.spp = 4;
    opts
}

/// Benchmarks one whole render of `scene` through `view`, throughput in rays.
fn bench_scene(c: &mut Criterion, name: &str, scene: &Scene, view: &View) {
    let opts = options();
    let quiet = |_: Progress| {};
    let rays = match render(scene, view, &opts, &quiet) {
        Ok(out) => out.stats.rays,
        Err(e) => {
            println!("skipped {name}: {e}");
            return;
        }
    };
    let mut group = c.benchmark_group("render");
    group.sample_size(10);
    group.throughput(Throughput::Elements(rays));
    group.bench_function(name, |b| {
        b.iter(|| black_box(render(scene, view, &opts, &quiet).map(|o| o.stats.rays)))
    });
    group.finish();
}

fn cornell(c: &mut Criterion) {
    match cornell_box([64, 64]) {
        Ok((scene, view)) => bench_scene(c, "cornell-64x64-4spp", &scene, &view),
        Err(e) => println!("skipped cornell: {e}"),
    }
}

fn bmw(c: &mut Criterion) {
    let dir = shared_scenes::dir();
    let file = dir.join("bmw-m6/bmw-m6.pbrt");
    if !file.is_file() {
        println!("skipped bmw-m6: {} is absent", file.display());
        return;
    }
    let options = LoadOptions {
        envmap_override: Some(dir.join("envmaps/pbrt-v4-ganesha-sky-equiarea.exr")),
        ..LoadOptions::default()
    };
    let loaded = load_pbrt_scene(&file, &options);
    match loaded.and_then(|l| Ok((View::new(&l.view, [128, 72])?, l.scene))) {
        Ok((view, scene)) => bench_scene(c, "bmw-m6-128x72-4spp", &scene, &view),
        Err(e) => println!("skipped bmw-m6: {e}"),
    }
}

criterion_group!(benches, cornell, bmw);
criterion_main!(benches);
