//! Loads PLY files (default: the bmw-m6 geometry), builds the BVH and prints
//! phase times and BVH statistics: `cargo run --release -p lowdisc-render
//! --example bvh_stats [FILE.ply ...]`.

use lowdisc_render::Accel;
use lowdisc_render::geometry::{ShapeSet, TriangleMesh};
use lowdisc_render::math::Transform;
use lowdisc_render::mesh::read_ply;
use std::time::Instant;

/// Process CPU time (user + system) in seconds, from /proc (Linux only).
fn cpu_seconds() -> f64 {
    let stat = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
    let after = stat.rsplit(')').next().unwrap_or("");
    let f: Vec<&str> = after.split_whitespace().collect();
    // Fields 14 and 15 of the full line (utime, stime) in clock ticks (100 Hz);
    // `after` starts at field 3.
    let tick = |i: usize| f.get(i).and_then(|x| x.parse::<f64>().ok()).unwrap_or(0.0);
    (tick(11) + tick(12)) / 100.0
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut files: Vec<std::path::PathBuf> = std::env::args().skip(1).map(Into::into).collect();
    if files.is_empty() {
        let dir = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../../shared/scenes/bmw-m6/geometry"
        );
        files = std::fs::read_dir(dir)?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .collect();
        files.retain(|p| p.extension().is_some_and(|e| e == "ply"));
        files.sort();
    }
    let (t, c) = (Instant::now(), cpu_seconds());
    let mut set = ShapeSet::new();
    for f in &files {
        set.add_mesh(TriangleMesh::new(
            &Transform::IDENTITY,
            read_ply(f)?,
            false,
        )?);
    }
    let (load, load_cpu) = (t.elapsed(), cpu_seconds() - c);
    let (t, c) = (Instant::now(), cpu_seconds());
    let accel = Accel::build(set);
    let (total, total_cpu) = (t.elapsed(), cpu_seconds() - c);
    println!(
        "{} files loaded in {:.1} ms (CPU {:.2} s)",
        files.len(),
        load.as_secs_f64() * 1e3,
        load_cpu
    );
    println!("{}", accel.stats());
    println!(
        "Accel::build total (boxes, BVH, triangle copy): {:.1} ms (CPU {:.2} s)",
        total.as_secs_f64() * 1e3,
        total_cpu
    );
    Ok(())
}
