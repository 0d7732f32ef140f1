//! `lowdisc render --pixel-bounds/--sample-range` and `lowdisc merge` end to
//! end: tile splits of the built-in Cornell box merge to the single render
//! bit for bit for every sampler, sample ranges merge within one `f32` step,
//! scene crops are respected, merging is idempotent, and bad parts are
//! refused with the file named, a non-zero exit and no output.

mod common;

use common::{lowdisc, temp_dir};
use lowdisc::catalog::SamplerName;
use std::path::{Path, PathBuf};

/// The defaults of every render here (each overridden when `extra` gives
/// the flag).
const DEFAULTS: [(&str, &str); 4] = [
    ("--res", "24x16"),
    ("--spp", "4"),
    ("--maxdepth", "2"),
    ("--seed", "1"),
];

/// `render -q -o out`, the defaults and `extra`.
fn render_args<'a>(out: &'a Path, extra: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec!["render", "-q", "-o", out.to_str().unwrap()];
    for (flag, value) in DEFAULTS {
        if !extra.contains(&flag) {
            args.extend([flag, value]);
        }
    }
    args.extend(extra);
    args
}

/// Runs `lowdisc render` on the Cornell box with `extra` into `out`.
fn render_to(out: &Path, extra: &[&str]) {
    let args = render_args(out, extra);
    let o = lowdisc(&args);
    assert!(
        o.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// Runs `lowdisc merge out parts...`; returns (exit code, stderr).
fn merge(out: &Path, parts: &[PathBuf]) -> (i32, String) {
    let mut args = vec!["merge", "-q", out.to_str().unwrap()];
    args.extend(parts.iter().map(|p| p.to_str().unwrap()));
    let o = lowdisc(&args);
    let code = o.status.code().unwrap_or(-1);
    (code, String::from_utf8_lossy(&o.stderr).into_owned())
}

/// Renders one part per window (`X0,X1,Y0,Y1`) with `extra`; returns the files.
fn parts(dir: &Path, tag: &str, windows: &[&str], extra: &[&str]) -> Vec<PathBuf> {
    let files = windows.iter().enumerate().map(|(i, w)| {
        let f = dir.join(format!("{tag}-{i}.exr"));
        let mut args = vec!["--pixel-bounds", w];
        args.extend(extra);
        render_to(&f, &args);
        f
    });
    files.collect()
}

/// The size and every channel of every pixel, as bits.
fn bits(path: &Path) -> (usize, usize, Vec<u32>) {
    let image = lowdisc_image::read_image(path).unwrap();
    let b = image.pixels().iter().flatten().map(|v| v.to_bits());
    (image.width(), image.height(), b.collect())
}

/// Asserts that the images `a` and `b` have the same size and bits.
fn assert_same_bits(a: &Path, b: &Path, what: &str) {
    let (x, y) = (bits(a), bits(b));
    assert_eq!((x.0, x.1), (y.0, y.1), "{what}: sizes");
    let differ = x.2.iter().zip(&y.2).filter(|(p, q)| p != q).count();
    assert_eq!(differ, 0, "{what}: channels that differ");
}

#[test]
fn tile_merges_equal_the_single_render_for_every_sampler() {
    let dir = temp_dir("split-tiles");
    let quarters = ["0,12,0,8", "12,24,0,8", "0,12,8,16", "12,24,8,16"];
    // Uneven, and cutting the 16-pixel tiles of the render loop.
    let uneven = ["0,7,0,16", "7,24,0,5", "7,24,5,16"];
    for name in SamplerName::ALL {
        let s = ["--sampler", name.as_str()];
        let single = dir.join(format!("{name}.exr"));
        render_to(&single, &s);
        for (tag, windows) in [("q", &quarters[..]), ("u", &uneven[..])] {
            let tag = format!("{name}-{tag}");
            let files = parts(&dir, &tag, windows, &s);
            let merged = dir.join(format!("{tag}-merged.exr"));
            assert_eq!(merge(&merged, &files), (0, String::new()));
            assert_same_bits(&merged, &single, &tag);
        }
    }
}

#[test]
fn sample_range_merges_are_within_one_float_step() {
    let dir = temp_dir("split-ranges");
    for name in ["zsobol", "paper", "independent"] {
        let single = dir.join(format!("{name}.exr"));
        render_to(&single, &["--sampler", name]);
        let ranges = ["0..1", "1..3", "3..4"];
        let files: Vec<PathBuf> = (ranges.iter().enumerate())
            .map(|(i, r)| {
                let f = dir.join(format!("{name}-{i}.exr"));
                render_to(&f, &["--sampler", name, "--sample-range", r]);
                f
            })
            .collect();
        let merged = dir.join(format!("{name}-merged.exr"));
        assert_eq!(merge(&merged, &files), (0, String::new()));
        let (m, s) = (bits(&merged), bits(&single));
        assert_eq!((m.0, m.1), (s.0, s.1));
        for (a, b) in m.2.iter().zip(&s.2) {
            assert!(a.abs_diff(*b) <= 1, "{name}: {a:#x} vs {b:#x}");
        }
        // The same parts in another order give the same file.
        let again = dir.join(format!("{name}-again.exr"));
        let reversed: Vec<PathBuf> = files.iter().rev().cloned().collect();
        assert_eq!(merge(&again, &reversed), (0, String::new()));
        assert_eq!(
            std::fs::read(&again).unwrap(),
            std::fs::read(&merged).unwrap()
        );
    }
}

#[test]
fn merging_is_idempotent() {
    let dir = temp_dir("split-idempotent");
    let files = parts(&dir, "h", &["0,10,0,16", "10,24,0,16"], &[]);
    let merged = dir.join("m.exr");
    assert_eq!(merge(&merged, &files), (0, String::new()));
    let first = std::fs::read(&merged).unwrap();
    assert_eq!(merge(&merged, &files), (0, String::new()));
    assert_eq!(std::fs::read(&merged).unwrap(), first, "rerun");
    assert_eq!(
        merge(&merged, std::slice::from_ref(&merged)),
        (0, String::new())
    );
    assert_eq!(std::fs::read(&merged).unwrap(), first, "the merge alone");
    let whole = dir.join("whole.exr");
    render_to(&whole, &["--pixel-bounds", "0,24,0,16"]);
    assert_eq!(std::fs::read(&whole).unwrap(), first, "a one-part render");
}

/// Asserts that merging `parts` fails with exit 1, one stderr line starting
/// with `prefix`, and no output file.
fn refused(dir: &Path, parts: &[PathBuf], prefix: &str) {
    let out = dir.join("refused.exr");
    let (code, stderr) = merge(&out, parts);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.starts_with(prefix), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(!out.exists());
}

#[test]
fn bad_parts_are_refused_naming_the_file() {
    let dir = temp_dir("split-refused");
    let p = |name: &str| dir.join(name).display().to_string();
    let left = parts(&dir, "l", &["0,12,0,16"], &[]).remove(0);
    let wide = parts(&dir, "w", &["11,24,0,16"], &[]).remove(0);
    let right = parts(&dir, "r", &["13,24,0,16"], &[]).remove(0);
    let seed = parts(&dir, "s", &["12,24,0,16"], &["--seed", "2"]).remove(0);
    let depth = parts(&dir, "d", &["12,24,0,16"], &["--maxdepth", "3"]).remove(0);
    let overlap = format!(
        "error: {}: pixel (11, 0) samples 0..4 overlap {}'s",
        p("w-0.exr"),
        p("l-0.exr")
    );
    refused(&dir, &[left.clone(), wide], &overlap);
    refused(
        &dir,
        &[left.clone(), right],
        "error: gap: pixel (12, 0) has no part",
    );
    let seeds = format!(
        "error: {}: seed 2 differs from {}'s 1",
        p("s-0.exr"),
        p("l-0.exr")
    );
    refused(&dir, &[left.clone(), seed], &seeds);
    let depths = format!("error: {}: maxdepth 3 differs", p("d-0.exr"));
    refused(&dir, &[left.clone(), depth], &depths);
    // Parts rendered with another exit weight of layered materials.
    let weight = ["--layered-weight", "pbrt-v4"];
    let layered = parts(&dir, "lw", &["12,24,0,16"], &weight).remove(0);
    let weights = format!(
        "error: {}: layered_weight pbrt-v4 differs from {}'s unbiased",
        p("lw-0.exr"),
        p("l-0.exr")
    );
    refused(&dir, &[left.clone(), layered], &weights);
    // The same window of a taller image.
    let tall = dir.join("tall.exr");
    render_to(&tall, &["--res", "24x17", "--pixel-bounds", "12,24,0,16"]);
    refused(
        &dir,
        &[left.clone(), tall],
        &format!("error: {}: resolution 24x17 differs", p("tall.exr")),
    );
    let missing = dir.join("missing.exr");
    refused(
        &dir,
        &[left.clone(), missing],
        &format!("error: cannot read `{}`", p("missing.exr")),
    );
    let bytes = std::fs::read(&left).unwrap();
    let truncated = dir.join("truncated.exr");
    std::fs::write(&truncated, &bytes[..bytes.len() / 2]).unwrap();
    let t = format!("error: {}: not a readable EXR file", p("truncated.exr"));
    refused(&dir, &[left.clone(), truncated], &t);
    let plain = dir.join("plain.exr");
    render_to(&plain, &[]);
    refused(
        &dir,
        &[plain],
        &format!("error: {}: no `lowdisc.part` header", p("plain.exr")),
    );
    let ranges = ["0..1", "2..4"].map(|r| {
        let f = dir.join(format!("range-{}.exr", &r[..1]));
        render_to(&f, &["--sample-range", r]);
        f
    });
    let gap = format!(
        "error: {}: pixel (0, 0) misses samples 1..2",
        p("range-2.exr")
    );
    refused(&dir, &ranges, &gap);
}

#[test]
fn bad_windows_and_ranges_are_refused_by_render() {
    let dir = temp_dir("split-bad-flags");
    for (flags, needle) in [
        (
            ["--pixel-bounds", "0,25,0,16"],
            "pixel bounds 0,25,0,16 must be non-empty and inside",
        ),
        (["--pixel-bounds", "4,4,0,16"], "need X0 < X1 and Y0 < Y1"),
        (
            ["--sample-range", "2..5"],
            "sample range 2..5 must be non-empty and within 0..4",
        ),
        (["--sample-range", "2-5"], "malformed --sample-range `2-5`"),
    ] {
        let out = dir.join("bad.exr");
        let o = lowdisc(&render_args(&out, &flags));
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{stderr}");
        assert!(stderr.contains(needle), "{stderr}");
        assert!(!out.exists());
    }
}

#[test]
fn a_part_of_a_huge_image_allocates_its_window_alone() {
    let dir = temp_dir("split-huge");
    // The whole 16384x16384 film would exceed the default memory limit.
    let out = dir.join("corner.exr");
    let flags = [
        "--res",
        "16384x16384",
        "--spp",
        "1",
        "--pixel-bounds",
        "8000,8008,8000,8004",
    ];
    render_to(&out, &flags);
    let (w, h, _) = bits(&out);
    assert_eq!((w, h), (8, 4));
    let whole = lowdisc(&render_args(&dir.join("whole.exr"), &flags[..4]));
    assert_eq!(whole.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&whole.stderr).contains("memory"));
}

/// A small pbrt-v4 scene whose film is cropped to its middle half.
const CROPPED: &str = r#"LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" [40]
Film "rgb" "integer xresolution" [24] "integer yresolution" [16]
    "float cropwindow" [0.25 0.75 0 1]
Sampler "sobol" "integer pixelsamples" [4]
WorldBegin
LightSource "point" "point3 from" [0 3 4] "blackbody I" [5500]
Material "diffuse" "rgb reflectance" [0.7 0.3 0.2]
Shape "sphere" "float radius" [1.2]
"#;

#[test]
fn parts_of_a_cropped_film_merge_to_its_single_render() {
    let dir = temp_dir("split-crop");
    let scene = dir.join("crop.pbrt");
    std::fs::write(&scene, CROPPED).unwrap();
    let s = scene.to_str().unwrap();
    let run = |out: &Path, extra: &[&str]| {
        let mut args = vec!["render", s, "-q", "-o", out.to_str().unwrap()];
        args.extend(extra);
        let o = lowdisc(&args);
        (
            o.status.code(),
            String::from_utf8_lossy(&o.stderr).into_owned(),
        )
    };
    let single = dir.join("single.exr");
    assert_eq!(run(&single, &[]), (Some(0), String::new()));
    let files: Vec<PathBuf> = ["6,11,0,16", "11,18,0,16"]
        .iter()
        .enumerate()
        .map(|(i, w)| {
            let f = dir.join(format!("c{i}.exr"));
            assert_eq!(run(&f, &["--pixel-bounds", w]), (Some(0), String::new()));
            f
        })
        .collect();
    let merged = dir.join("merged.exr");
    assert_eq!(merge(&merged, &files), (0, String::new()));
    assert_same_bits(&merged, &single, "crop");
    assert_eq!(bits(&single).0, 12);
    let (code, stderr) = run(&dir.join("out.exr"), &["--pixel-bounds", "0,8,0,16"]);
    assert_eq!(code, Some(1));
    assert!(stderr.contains("inside the film's 6,18,0,16"), "{stderr}");
}
