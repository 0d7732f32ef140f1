//! Golden images: a fixed list of small renders made by the real `lowdisc`
//! binary (the built-in Cornell box with every sampler of the catalog, one
//! and two threads, RGB and spectral, a split render merged back, and the
//! shared pbrt-v4 scenes), each compared bit for bit with the SHA-256 of its
//! pixels committed in `tests/golden/images.txt`.
//!
//! A behaviour-preserving change shows "images unchanged" with
//!
//! ```sh
//! cargo test -p lowdisc-cli --test golden
//! ```
//!
//! and a change that is meant to alter images rewrites the file with
//! `LOWDISC_GOLDEN_UPDATE=1` (the diff then names every image that changed;
//! say why in the commit message). The hash is taken over the decoded
//! `f32` pixels, so it does not depend on the file format's metadata.
//! The scenes come from `../shared/scenes` (see `crates/shared-scenes`).

mod common;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use common::{lowdisc, temp_dir};
use lowdisc::catalog::SamplerName;
use sha2::{Digest, Sha256};

/// Where the committed hashes live.
fn golden_file() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden/images.txt")
}

/// One render of the list: its name and its `lowdisc render` arguments
/// (without `-o`, which the test adds). Every render names its sampler,
/// resolution and samples per pixel, so a change of default shows only
/// where it is meant to.
struct Case {
    name: String,
    args: Vec<String>,
}

fn case(name: impl Into<String>, args: &[&str]) -> Case {
    Case {
        name: name.into(),
        args: args.iter().map(|a| a.to_string()).collect(),
    }
}

/// The built-in box with every sampler, and the render options that must
/// not change pixels (threads) or that change them in a pinned way.
fn builtin_cases() -> Vec<Case> {
    let small = ["--res", "24x20", "--spp", "4", "--seed", "3"];
    let mut cases: Vec<Case> = SamplerName::ALL
        .iter()
        .map(|s| {
            let mut args = vec!["render", "--sampler", s.as_str()];
            args.extend(small);
            case(format!("box/{}", s.as_str()), &args)
        })
        .collect();
    fn box_args<'a>(extra: &[&'a str]) -> Vec<&'a str> {
        let mut args = vec!["render", "--res", "40x32", "--spp", "8"];
        args.extend(extra);
        args
    }
    let zsobol = |extra: &[&'static str]| box_args(&[&["--sampler", "zsobol"], extra].concat());
    cases.push(case("box/zsobol-threads-1", &zsobol(&["--threads", "1"])));
    cases.push(case("box/zsobol-threads-2", &zsobol(&["--threads", "2"])));
    cases.push(case("box/zsobol-spectral", &zsobol(&["--spectral"])));
    cases.push(case(
        "box/independent-spectral-depth-2",
        &box_args(&["--sampler", "independent", "--spectral", "--maxdepth", "2"]),
    ));
    cases.push(case(
        "box/paper-all-dims",
        &box_args(&[
            "--sampler",
            "paper",
            "--threshold",
            "0.3",
            "--paper-all-dims",
        ]),
    ));
    cases
}

/// The shared pbrt-v4 scenes (relative to `../shared/scenes`), each at a
/// small resolution, in RGB and spectral.
fn scene_cases() -> Vec<(Case, &'static str)> {
    let scenes: &[(&str, &str, &[&str])] = &[
        (
            "bitterli-cornell-box",
            "bitterli-cornell-box/scene-v4.pbrt",
            &[],
        ),
        (
            "bitterli-veach-mis",
            "bitterli-veach-mis/scene-v4.pbrt",
            &[],
        ),
        (
            "bitterli-material-testball",
            "bitterli-material-testball/material-testball.pbrt",
            &[
                "--envmap",
                "@SHARED@/envmaps/polyhaven-studio_small_03_1k.hdr",
            ],
        ),
        ("killeroo-simple", "killeroos/killeroo-simple.pbrt", &[]),
        ("killeroo-gold", "killeroos/killeroo-gold.pbrt", &[]),
        (
            "killeroo-coated-gold",
            "killeroos/killeroo-coated-gold.pbrt",
            &["--layered-weight", "pbrt-v4"],
        ),
        // Integrator "bdpt", rendered by the path tracer.
        (
            "caustic-glass",
            "caustic-glass/caustic-glass-v4.pbrt",
            &["--approximate"],
        ),
        (
            "bmw-m6",
            "bmw-m6/bmw-m6.pbrt",
            // Integrator "regularize", not done.
            &[
                "--envmap",
                "@SHARED@/envmaps/pbrt-v4-ganesha-sky-equiarea.exr",
                "--approximate",
            ],
        ),
    ];
    let mut cases = Vec::new();
    for &(name, file, extra) in scenes {
        for (mode, flags) in [("rgb", &[][..]), ("spectral", &["--spectral"][..])] {
            let mut args = vec![
                "render",
                "@SCENE@",
                "--res",
                "32x24",
                "--spp",
                "4",
                "--sampler",
                "zsobol",
                "--seed",
                "1",
            ];
            args.extend(extra);
            args.extend(flags);
            cases.push((case(format!("scene/{name}-{mode}"), &args), file));
        }
    }
    cases
}

/// SHA-256 of an image's size and pixels (each `f32`'s bits, little
/// endian, row by row), as lowercase hex: the same for the same pixels
/// whatever the file format.
fn sha256(path: &Path) -> String {
    let image =
        lowdisc_image::read_image(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut hasher = Sha256::new();
    hasher.update((image.width() as u64).to_le_bytes());
    hasher.update((image.height() as u64).to_le_bytes());
    for channel in image.pixels().iter().flatten() {
        hasher.update(channel.to_le_bytes());
    }
    hasher
        .finalize()
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// Renders `case` into `dir` and returns its image's hash.
fn render_hash(case: &Case, dir: &Path, scene: Option<&Path>) -> String {
    let out = dir.join(format!("{}.pfm", case.name.replace('/', "_")));
    let mut args: Vec<String> = case
        .args
        .iter()
        .map(|a| match (a.as_str(), scene) {
            ("@SCENE@", Some(s)) => s.display().to_string(),
            _ => match a.strip_prefix("@SHARED@/") {
                Some(rel) => shared_scenes::dir().join(rel).display().to_string(),
                None => a.clone(),
            },
        })
        .collect();
    args.extend(["--quiet".into(), "-o".into(), out.display().to_string()]);
    let refs: Vec<&str> = args.iter().map(String::as_str).collect();
    let run = lowdisc(&refs);
    assert!(
        run.status.success(),
        "{}: lowdisc {refs:?} failed: {}",
        case.name,
        String::from_utf8_lossy(&run.stderr)
    );
    sha256(&out)
}

/// A split render (two pixel windows, each part written and merged) must
/// equal the whole render's image; returns the merged image's hash.
fn split_merge_hash(dir: &Path) -> String {
    let common = ["--res", "24x20", "--spp", "4", "--sampler", "sobol-owen"];
    let part = |bounds: &str, name: &str| {
        let out = dir.join(name);
        let mut args = vec!["render", "--quiet", "--pixel-bounds", bounds, "-o"];
        let path = out.display().to_string();
        args.push(&path);
        args.extend(common);
        let run = lowdisc(&args);
        assert!(
            run.status.success(),
            "{}",
            String::from_utf8_lossy(&run.stderr)
        );
        out
    };
    let a = part("0,24,0,9", "part-a.exr");
    let b = part("0,24,9,20", "part-b.exr");
    let merged = dir.join("merged.exr");
    let run = lowdisc(&[
        "merge",
        &merged.display().to_string(),
        &a.display().to_string(),
        &b.display().to_string(),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let whole = Case {
        name: "split-whole".into(),
        args: ["render"]
            .iter()
            .chain(&common)
            .map(|a| a.to_string())
            .collect(),
    };
    let merged_hash = sha256(&merged);
    assert_eq!(
        merged_hash,
        render_hash(&whole, dir, None),
        "merged tiles differ from the whole render"
    );
    merged_hash
}

/// Reads `name  hash` lines.
fn read_golden() -> BTreeMap<String, String> {
    let text = std::fs::read_to_string(golden_file()).unwrap_or_default();
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .filter_map(|l| {
            let (hash, name) = l.split_once("  ")?;
            Some((name.trim().to_string(), hash.trim().to_string()))
        })
        .collect()
}

fn write_golden(hashes: &BTreeMap<String, String>) {
    let mut text = String::from(
        "# SHA-256 of each golden render's pixels (crates/cli/tests/golden.rs).\n\
         # Rewrite with: LOWDISC_GOLDEN_UPDATE=1 cargo test -p lowdisc-cli --test golden\n",
    );
    for (name, hash) in hashes {
        text.push_str(&format!("{hash}  {name}\n"));
    }
    std::fs::create_dir_all(golden_file().parent().unwrap()).unwrap();
    std::fs::write(golden_file(), text).unwrap();
}

#[test]
fn every_golden_render_is_bit_identical_to_its_committed_hash() {
    let dir = temp_dir("golden");
    let mut got = BTreeMap::new();
    for case in builtin_cases() {
        got.insert(case.name.clone(), render_hash(&case, &dir, None));
    }
    got.insert("box/split-merged".into(), split_merge_hash(&dir));
    for (case, file) in scene_cases() {
        let Some(scene) = shared_scenes::file(file) else {
            continue;
        };
        got.insert(case.name.clone(), render_hash(&case, &dir, Some(&scene)));
    }
    // Threads never change pixels, and a merged split is the whole render.
    assert_eq!(got["box/zsobol-threads-1"], got["box/zsobol-threads-2"]);
    if std::env::var("LOWDISC_GOLDEN_UPDATE").is_ok_and(|v| v == "1") {
        write_golden(&got);
        return;
    }
    let want = read_golden();
    let mut diffs = Vec::new();
    for (name, hash) in &got {
        match want.get(name) {
            Some(w) if w == hash => {}
            Some(_) => diffs.push(format!("{name}: image changed")),
            None => diffs.push(format!("{name}: no committed hash")),
        }
    }
    for name in want.keys().filter(|n| !got.contains_key(*n)) {
        if name.starts_with("box/") {
            diffs.push(format!("{name}: committed but no longer rendered"));
        }
    }
    assert!(
        diffs.is_empty(),
        "golden images differ from {} (set LOWDISC_GOLDEN_UPDATE=1 to rewrite it \
         if the change is meant):\n{}",
        golden_file().display(),
        diffs.join("\n")
    );
    let _ = std::fs::remove_dir_all(&dir);
}
