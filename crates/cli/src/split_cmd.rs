//! Split renders in the command line: writing a render's part
//! (`lowdisc render --pixel-bounds/--sample-range`) and `lowdisc merge`,
//! which reads parts, merges them with `lowdisc-split` and writes the result
//! atomically. The checks and the assembly are the library's.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use clap::Args;
use lowdisc_render::render::{RenderOptions, RenderOutput};
use lowdisc_render::scene::Scene;
use lowdisc_render::view::View;
use lowdisc_split::{NamedPart, RenderPart, merge, read_part, write_part};

/// The long help of `merge`.
pub const LONG_ABOUT: &str = "\
Merge the parts of a split render into one EXR.\n\
\n\
Each part is an EXR written by `lowdisc render --pixel-bounds X0,X1,Y0,Y1`\n\
and/or `--sample-range A..B`. The parts must come from the same scene (its\n\
hash) and settings (sampler, seed, spp, threshold, maxdepth, light strategy,\n\
layered weight, spectral mode, film sensor, resolution, film\n\
bounds); together they must cover a rectangle of pixels, each pixel by sample\n\
ranges that follow each other without overlap or gap. Any other input is\n\
refused with the part named, and nothing is written.\n\
\n\
A merge of tiles is bit-identical to the single render (for every sampler);\n\
sample ranges add each pixel's f64 sums in range order, which equals the\n\
single render up to f64 rounding. The output is itself a part (merge it\n\
again with more parts; merging it alone rewrites the same bytes), written to\n\
a temporary file and renamed into place. OUT may be one of the PARTS.\n\
";

/// The arguments of `merge`.
#[derive(Debug, Args)]
pub struct MergeArgs {
    /// The merged EXR to write.
    output: PathBuf,
    /// The part files (EXR) to merge.
    #[arg(required = true, num_args = 1..)]
    parts: Vec<PathBuf>,
    /// Print nothing on success.
    #[arg(long, short = 'q')]
    quiet: bool,
}

/// True when `path` ends in `.exr` (any case).
pub fn is_exr(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("exr"))
}

/// Writes the part that `out` (a render of `scene` through `view` with
/// `options`) holds.
pub fn write_render_part(
    path: &Path,
    scene: &Scene,
    view: &View,
    options: &RenderOptions,
    out: &RenderOutput,
) -> Result<()> {
    let part = RenderPart::new(scene, view, options, out);
    write_part(path, &part).with_context(|| format!("cannot write `{}`", path.display()))
}

/// Reads every part, merges them and writes the merged part.
pub fn run(args: &MergeArgs) -> Result<()> {
    if !is_exr(&args.output) {
        bail!("output `{}` must end in .exr", args.output.display());
    }
    let mut parts = Vec::with_capacity(args.parts.len());
    for path in &args.parts {
        let name = path.display().to_string();
        let part = read_part(path)?;
        parts.push(NamedPart { name, part });
    }
    let merged = merge(&parts)?;
    write_part(&args.output, &merged)
        .with_context(|| format!("cannot write `{}`", args.output.display()))?;
    if !args.quiet {
        let i = &merged.info;
        let b = i.window;
        let state = if merged.is_complete() {
            "complete"
        } else {
            "not yet complete"
        };
        println!(
            "merged {} parts into {}: pixels {},{},{},{}, samples {} of {} ({state})",
            parts.len(),
            args.output.display(),
            b.min[0],
            b.max[0],
            b.min[1],
            b.max[1],
            i.samples,
            i.spp
        );
    }
    Ok(())
}
