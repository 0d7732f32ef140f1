//! BVH build time and ray throughput on the bmw-m6 meshes (all PLY files in
//! `shared/scenes/bmw-m6/geometry`, untransformed) when present, else on a
//! generated mesh of about 800k triangles; and ray throughput in the
//! built-in Cornell box (38 triangles) for rays leaving points inside it.

#![allow(missing_docs)] // criterion_group! generates undocumented functions
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use lowdisc_render::Accel;
use lowdisc_render::geometry::{MeshData, ShapeSet, TriangleMesh};
use lowdisc_render::math::{Point3, Ray, Transform, Vec3};
use lowdisc_render::mesh::read_ply;
use std::hint::black_box;

/// A bumpy height-field grid of `2 n^2` triangles.
fn generated(n: u32) -> MeshData {
    let mut m = MeshData::default();
    for j in 0..=n {
        for i in 0..=n {
            let (x, y) = (i as f32 / n as f32, j as f32 / n as f32);
            let z = 0.05 * ((x * 40.0).sin() * (y * 37.0).cos());
            m.positions.push(Point3::new(x, y, z));
        }
    }
    for j in 0..n {
        for i in 0..n {
            let v = j * (n + 1) + i;
            m.indices.push([v, v + 1, v + n + 1]);
            m.indices.push([v + 1, v + n + 2, v + n + 1]);
        }
    }
    m
}

fn ply_files() -> Vec<std::path::PathBuf> {
    let dir = shared_scenes::dir().join("bmw-m6/geometry");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .map(|rd| rd.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    files.retain(|p| p.extension().is_some_and(|e| e == "ply"));
    files.sort();
    files
}

fn shapes() -> (ShapeSet, String) {
    let mut set = ShapeSet::new();
    let files = ply_files();
    for f in &files {
        let data = read_ply(f).expect("bmw-m6 PLY loads");
        set.add_mesh(TriangleMesh::new(&Transform::IDENTITY, data, false).expect("valid mesh"));
    }
    if set.meshes.is_empty() {
        let m = TriangleMesh::new(&Transform::IDENTITY, generated(632), false).expect("valid mesh");
        set.add_mesh(m);
        return (set, "generated grid".into());
    }
    (set, format!("bmw-m6 ({} files)", files.len()))
}

/// SplitMix64 from `state`: uniform values in `[0, 1)` with 24 bits.
fn uniform_stream(mut state: u64) -> impl FnMut() -> f32 {
    move || {
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        (lowdisc::hash::mix64(state) >> 40) as f32 / (1u64 << 24) as f32
    }
}

/// Rays from points inside `accel`'s bounds in all directions (SplitMix64).
fn inner_rays(accel: &Accel, n: usize) -> Vec<Ray> {
    let mut next = uniform_stream(0x2545f4914f6cdd1d);
    let b = accel.bounds();
    (0..n)
        .map(|_| {
            let o = b.min
                + b.diagonal() * Vec3::new(next(), next(), next()) * 0.98
                + b.diagonal() * 0.01;
            let d = Vec3::new(next() - 0.5, next() - 0.5, next() - 0.5);
            Ray::new(o, d.normalize())
        })
        .collect()
}

fn bench_cornell(c: &mut Criterion) {
    let (scene, _) = lowdisc_render::cornell::cornell_box([64, 64]).expect("built-in scene");
    let accel = Accel::build(scene.shapes().clone());
    let rs = inner_rays(&accel, 100_000);
    let mut g = c.benchmark_group("bvh");
    g.sample_size(10);
    g.throughput(Throughput::Elements(rs.len() as u64));
    g.bench_function("closest-hit rays cornell box", |b| {
        b.iter(|| {
            rs.iter()
                .filter(|r| accel.intersect(r, f32::INFINITY).is_some())
                .count()
        })
    });
    // Shadow rays: half the distance to the closest hit (unoccluded).
    let shadow: Vec<(Ray, f32)> = rs
        .iter()
        .map(|r| {
            (
                *r,
                accel
                    .intersect(r, f32::INFINITY)
                    .map_or(1.0, |h| 0.5 * h.surface.t),
            )
        })
        .collect();
    g.bench_function("any-hit rays cornell box", |b| {
        b.iter(|| {
            shadow
                .iter()
                .filter(|(r, t)| accel.intersect_p(r, *t))
                .count()
        })
    });
    g.finish();
}

/// Rays from points around the scene towards points inside it (SplitMix64).
fn rays(accel: &Accel, n: usize) -> Vec<Ray> {
    let mut next = uniform_stream(0x9e3779b97f4a7c15);
    let b = accel.bounds();
    let (c, r) = b.bounding_sphere();
    (0..n)
        .map(|_| {
            let o = c + Vec3::new(next() - 0.5, next() - 0.5, next() - 0.5).normalize() * (1.5 * r);
            let t = b.min + b.diagonal() * Vec3::new(next(), next(), next());
            Ray::new(o, (t - o).normalize())
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let (set, name) = shapes();
    let accel = Accel::build(set.clone());
    eprintln!("{name}: {}", accel.stats());
    let mut g = c.benchmark_group("bvh");
    g.sample_size(10);
    let files = ply_files();
    if !files.is_empty() {
        g.bench_function("load bmw-m6 PLY files", |b| {
            b.iter(|| {
                files
                    .iter()
                    .map(|f| read_ply(f).map(|m| m.indices.len()).unwrap_or(0))
                    .sum::<usize>()
            })
        });
    }
    g.bench_function(format!("build {name}"), |b| {
        b.iter(|| black_box(Accel::build(set.clone())))
    });
    let rs = rays(&accel, 100_000);
    g.throughput(Throughput::Elements(rs.len() as u64));
    g.bench_function(format!("closest-hit rays {name}"), |b| {
        b.iter(|| {
            rs.iter()
                .filter(|r| accel.intersect(r, f32::INFINITY).is_some())
                .count()
        })
    });
    g.bench_function(format!("any-hit rays {name}"), |b| {
        b.iter(|| {
            rs.iter()
                .filter(|r| accel.intersect_p(r, f32::INFINITY))
                .count()
        })
    });
    g.finish();
}

criterion_group!(benches, bench_cornell, bench);
criterion_main!(benches);
