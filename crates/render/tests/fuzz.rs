//! Mutation fuzzing of the input readers on stable Rust: the pbrt tokenizer
//! and parser, the whole scene loader, the PLY reader and every image
//! decoder get mutated copies of real files (the bad-input corpus's
//! fixtures, and the shared Cornell box when present) and must return,
//! never panic.
//!
//! Each target runs for a bounded time in the normal test suite (a few
//! seconds); `LOWDISC_FUZZ_SECONDS=1800 cargo test -p lowdisc-render --test
//! fuzz -- --nocapture` is the long run (30 minutes per target). A failure
//! prints arbtest's seed, which replays it; a crash found this way becomes a
//! corpus case (crates/cli/tests/corpus/generate.py).

use std::path::{Path, PathBuf};
use std::time::Duration;

use arbtest::arbitrary::{Result, Unstructured};
use lowdisc_image::{ImageFormat, ReadOptions, decode_image};
use lowdisc_render::mesh::ply::parse_ply;
use lowdisc_render::pbrt::{LoadOptions, load_pbrt_scene};
use pbrt_format::{Directive, Loc, ParserTarget, TargetResult, parse_str};

/// The time budget of one target.
fn budget() -> Duration {
    let secs = std::env::var("LOWDISC_FUZZ_SECONDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(3);
    Duration::from_secs(secs)
}

/// Seed files: the corpus fixtures under `sub` whose names end in one of
/// `exts`.
fn seeds(sub: &str, exts: &[&str]) -> Vec<Vec<u8>> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../cli/tests/corpus/files")
        .join(sub);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("the corpus fixtures")
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.is_file() && exts.iter().any(|x| p.to_string_lossy().ends_with(x)))
        .collect();
    files.sort();
    let mut out: Vec<Vec<u8>> = files.iter().filter_map(|p| std::fs::read(p).ok()).collect();
    let cornell = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/scenes/bitterli-cornell-box/scene-v4.pbrt");
    if sub == "scene" {
        out.extend(std::fs::read(cornell));
    }
    assert!(!out.is_empty(), "no seeds in {}", dir.display());
    out
}

/// A mutated copy of one seed: byte flips, insertions of interesting
/// bytes, deletions, duplications of ranges, and splices with another seed.
fn mutate(u: &mut Unstructured<'_>, seeds: &[Vec<u8>]) -> Result<Vec<u8>> {
    let mut data = u.choose(seeds)?.clone();
    const INTERESTING: &[&[u8]] = &[
        b"\"",
        b"[",
        b"]",
        b"#",
        b"\n",
        b"\0",
        b"\xff",
        b"-",
        b"1e308",
        b"nan",
        b"4294967295",
        b"-2147483648",
        b"WorldBegin",
        b"AttributeBegin",
        b"Include",
        b"element vertex ",
        b"end_header\n",
        b"list uint int ",
    ];
    for _ in 0..u.int_in_range(1..=8)? {
        let at = if data.is_empty() {
            0
        } else {
            u.choose_index(data.len() + 1)?
        };
        match u.int_in_range(0..=4)? {
            0 if at < data.len() => data[at] ^= 1 << u.int_in_range(0..=7)?,
            1 => {
                let piece = u.choose(INTERESTING)?;
                data.splice(at..at, piece.iter().copied());
            }
            2 if at < data.len() => {
                let end = (at + u.int_in_range(1..=64)?).min(data.len());
                data.drain(at..end);
            }
            3 if at < data.len() => {
                let end = (at + u.int_in_range(1..=64)?).min(data.len());
                let copy = data[at..end].to_vec();
                data.splice(at..at, copy);
            }
            _ => {
                let other = u.choose(seeds)?;
                let from = u.choose_index(other.len().max(1))?.min(other.len());
                data.truncate(at);
                data.extend_from_slice(&other[from..]);
            }
        }
    }
    Ok(data)
}

/// A parser target that accepts every directive.
struct Accept;

impl ParserTarget for Accept {
    fn directive(&mut self, _d: Directive, _loc: &Loc) -> TargetResult {
        Ok(())
    }
    fn warning(&mut self, _loc: &Loc, _message: &str) {}
}

fn fuzz(name: &str, mut check: impl FnMut(&mut Unstructured<'_>) -> Result<()>) {
    let mut runs = 0u64;
    arbtest::arbtest(|u| {
        runs += 1;
        check(u)
    })
    .budget(budget())
    .run();
    println!("fuzz {name}: {runs} inputs, no panic");
}

#[test]
fn pbrt_parser_never_panics_on_mutated_scenes() {
    let seeds = seeds("scene", &[".pbrt"]);
    fuzz("pbrt-parser", |u| {
        let text = String::from_utf8_lossy(&mutate(u, &seeds)?).into_owned();
        let _ = parse_str(&text, "fuzz.pbrt", &mut Accept);
        Ok(())
    });
}

#[test]
fn scene_loader_never_panics_on_mutated_scenes() {
    let seeds = seeds("scene", &[".pbrt"]);
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fuzz-loader");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("scene.pbrt");
    fuzz("scene-loader", |u| {
        std::fs::write(&file, mutate(u, &seeds)?).unwrap();
        let _ = load_pbrt_scene(&file, &LoadOptions::default());
        Ok(())
    });
}

#[test]
fn ply_reader_never_panics_on_mutated_meshes() {
    let seeds = seeds("ply", &[".ply"]);
    fuzz("ply", |u| {
        let _ = parse_ply(&mutate(u, &seeds)?, Path::new("fuzz.ply"));
        Ok(())
    });
}

#[test]
fn image_decoders_never_panic_on_mutated_images() {
    let seeds = seeds("image", &[".png", ".pfm", ".hdr", ".exr", ".tga"]);
    let formats = [
        ImageFormat::Exr,
        ImageFormat::Hdr,
        ImageFormat::Pfm,
        ImageFormat::Png,
        ImageFormat::Tga,
    ];
    fuzz("images", |u| {
        let bytes = mutate(u, &seeds)?;
        let format = *u.choose(&formats)?;
        let _ = decode_image(&bytes, format, &ReadOptions::default());
        Ok(())
    });
}
