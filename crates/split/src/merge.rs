//! [`merge`]: assembles parts of one render into one part, refusing parts of
//! another scene or settings, overlaps and gaps.
//!
//! Every part must agree on the scene hash, the settings, the resolution,
//! the film bounds and the samples per pixel. The merged window is the
//! bounding box of the parts' windows; every pixel in it must be covered by
//! sample ranges that follow each other without overlap or gap, and every
//! pixel must end up with the same range (the merged part's).
//!
//! Parts are taken in ascending order of their first sample index (then in
//! the order given). A pixel's first part's sums are copied, so a merge of
//! tiles reproduces each pixel's sums bit for bit; later ranges are added in
//! `f64`. Recursive summation gives `|ŝ - s| <= (n - 1) u Σ|x_i|` for `n`
//! terms (`u = 2^-53`; Higham, *Accuracy and Stability of Numerical
//! Algorithms*, 2002, §4.2), so the merge of `m` ranges and the single
//! render's in-order sum of `spp` samples differ by at most
//! `(spp + m) u Σ|w L|` per channel: far below an `f32` pixel's resolution,
//! yet a pixel whose quotient falls next to an `f32` rounding boundary can
//! round to the neighbouring `f32`.

use crate::part::RenderPart;
use lowdisc_render::film::{PixelBounds, PixelSum};
use lowdisc_render::render::SampleRange;

/// A part and the name its errors use (its file's path).
#[derive(Clone, Debug)]
pub struct NamedPart {
    /// The name used in errors.
    pub name: String,
    /// The part.
    pub part: RenderPart,
}

/// Why parts cannot be merged: the part concerned and what is wrong.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MergeError {
    /// The part's name (empty when no part is concerned).
    pub part: String,
    /// What is wrong.
    pub message: String,
}

impl std::fmt::Display for MergeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.part.is_empty() {
            write!(f, "{}", self.message)
        } else {
            write!(f, "{}: {}", self.part, self.message)
        }
    }
}

impl std::error::Error for MergeError {}

fn error(part: &str, message: String) -> MergeError {
    MergeError {
        part: part.to_string(),
        message,
    }
}

/// `x0,x1,y0,y1`, the form `--pixel-bounds` takes.
pub(crate) fn bounds_text(b: &PixelBounds) -> String {
    format!("{},{},{},{}", b.min[0], b.max[0], b.min[1], b.max[1])
}

/// Checks that `p` is a part of the same render as `first`.
fn check_same(first: &NamedPart, p: &NamedPart) -> Result<(), MergeError> {
    let (a, b) = (&first.part.info, &p.part.info);
    let differ = |what: &str, x: String, y: String| {
        Err(error(
            &p.name,
            format!("{what} {y} differs from {}'s {x}", first.name),
        ))
    };
    if a.scene != b.scene {
        return differ("scene hash", a.scene.clone(), b.scene.clone());
    }
    for (k, v) in &a.settings {
        let w = b
            .settings
            .get(k)
            .cloned()
            .unwrap_or_else(|| "(none)".into());
        if *v != w {
            return differ(k, v.clone(), w);
        }
    }
    if let Some(k) = b.settings.keys().find(|k| !a.settings.contains_key(*k)) {
        return differ(k, "(none)".into(), b.settings[k].clone());
    }
    if a.resolution != b.resolution {
        let r = |r: [u32; 2]| format!("{}x{}", r[0], r[1]);
        return differ("resolution", r(a.resolution), r(b.resolution));
    }
    if a.film_bounds != b.film_bounds {
        let (x, y) = (bounds_text(&a.film_bounds), bounds_text(&b.film_bounds));
        return differ("film bounds", x, y);
    }
    if a.spp != b.spp {
        return differ("spp", a.spp.to_string(), b.spp.to_string());
    }
    Ok(())
}

/// Merges `parts` (at least one) of one render into one part; see the
/// module documentation for the checks and the exactness.
pub fn merge(parts: &[NamedPart]) -> Result<RenderPart, MergeError> {
    let Some(first) = parts.first() else {
        return Err(error("", "no parts to merge".into()));
    };
    for p in parts {
        check_same(first, p)?;
        let i = &p.part.info;
        if p.part.sums.len() != i.window.area() {
            return Err(error(&p.name, "sums do not match the window".into()));
        }
        if i.window.area() == 0 || i.window.intersect(&i.film_bounds) != i.window {
            let w = bounds_text(&i.window);
            return Err(error(&p.name, format!("window {w} is outside the film")));
        }
    }
    let window = parts[1..].iter().fold(first.part.info.window, |b, p| {
        let w = p.part.info.window;
        PixelBounds::new(
            [b.min[0].min(w.min[0]), b.min[1].min(w.min[1])],
            [b.max[0].max(w.max[0]), b.max[1].max(w.max[1])],
        )
    });
    let mut order: Vec<&NamedPart> = parts.iter().collect();
    order.sort_by_key(|p| p.part.info.samples.start);
    let start = order[0].part.info.samples.start;
    let n = window.area();
    let mut sums = vec![PixelSum::default(); n];
    // Per pixel: one past the last sample index merged, and the part that
    // merged it.
    let mut end = vec![start; n];
    let mut owner: Vec<Option<&str>> = vec![None; n];
    let mut nonfinite = 0u64;
    for p in &order {
        let i = &p.part.info;
        for (k, px) in i.window.pixels().enumerate() {
            let at = (px[1] - window.min[1]) as usize * window.width()
                + (px[0] - window.min[0]) as usize;
            if end[at] != i.samples.start {
                let msg = match owner[at] {
                    Some(o) if end[at] > i.samples.start => format!(
                        "pixel ({}, {}) samples {} overlap {o}'s (up to {})",
                        px[0], px[1], i.samples, end[at]
                    ),
                    _ => format!(
                        "pixel ({}, {}) misses samples {}..{} before this part's {}",
                        px[0], px[1], end[at], i.samples.start, i.samples
                    ),
                };
                return Err(error(&p.name, msg));
            }
            let s = &p.part.sums[k];
            if owner[at].is_none() {
                sums[at] = *s;
            } else {
                sums[at].add(s);
            }
            end[at] = i.samples.end;
            owner[at] = Some(&p.name);
        }
        nonfinite += i.nonfinite;
    }
    let last = end.iter().copied().max().unwrap_or(start);
    for (at, &e) in end.iter().enumerate() {
        if e != last {
            let (x, y) = (
                window.min[0] + (at % window.width()) as i32,
                window.min[1] + (at / window.width()) as i32,
            );
            let have = if owner[at].is_some() {
                format!("only samples {start}..{e}")
            } else {
                "no part".to_string()
            };
            return Err(error(
                "",
                format!(
                    "gap: pixel ({x}, {y}) has {have} of {start}..{last} (merged window {})",
                    bounds_text(&window)
                ),
            ));
        }
    }
    let mut info = first.part.info.clone();
    info.window = window;
    info.samples = SampleRange::new(start, last);
    info.nonfinite = nonfinite;
    Ok(RenderPart { info, sums })
}
