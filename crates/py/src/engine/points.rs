//! Sequences as arrays: Sobol (Joe-Kuo, Gray-code or natural order, any of
//! lowdisc's randomizations), Halton (unscrambled, digit-permuted, Owen),
//! independent (PCG32) and stratified (jittered) points.
//!
//! Point `k` of a request is sequence point `start + k`, so a request can
//! continue where another ended. Requests are split into fixed chunks of
//! points computed in parallel; every value depends only on its index and
//! dimension, so results do not depend on the thread count.

use core::str::FromStr;

use lowdisc::catalog::{MAX_POINT_WORDS, SamplerName};
use lowdisc::halton::{self, Halton, HaltonRandomize};
use lowdisc::independent::Independent;
use lowdisc::scramble::RandomizeStrategy;
use lowdisc::scramble::ScrambleCache;
use lowdisc::sobol::{self, GrayCodeBatch};
use lowdisc::stratified;
use rayon::prelude::*;

use super::{CHUNK_VALUES, Dtype, EngineError, Result, Values};

/// Which sequence a request asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sequence {
    /// Sobol; scrambles `none`, `xor`, `owen`, `fast-owen`.
    Sobol,
    /// Halton; scrambles `none`, `permute`, `owen`.
    Halton,
    /// Independent uniform numbers: dimension `j` of point `k` is draw `k` of
    /// PCG32 stream `j`.
    Independent,
    /// Jittered stratified points (a set of `n`, not a sequence: `start` must be 0).
    Stratified,
}

/// A request for points.
#[derive(Debug, Clone, PartialEq)]
pub struct PointSpec {
    /// The sequence.
    pub sequence: Sequence,
    /// Number of points (0 gives an empty array).
    pub n: u64,
    /// Dimensions `0..d` of each point.
    pub d: u32,
    /// Index of the first point.
    pub start: u64,
    /// Sobol only: natural order (`sobol::sample(k, j)`) instead of Gray code.
    pub natural_order: bool,
    /// The randomization's name (see [`Sequence`]).
    pub scramble: String,
    /// Seed of every random choice.
    pub seed: u64,
    /// Sobol only: leading binary digits kept, `1..=32` (scipy's `bits`).
    pub bits: u32,
    /// Element type of the result.
    pub dtype: Dtype,
}

/// The Sobol dimensions available.
pub const SOBOL_DIMENSIONS: u32 = sobol::NUM_DIMENSIONS as u32;
/// The Halton dimensions available.
pub const HALTON_DIMENSIONS: u32 = halton::NUM_DIMENSIONS;

/// The points of `spec`, point-major (`n * d` values).
pub fn generate(spec: &PointSpec) -> Result<Values> {
    check(spec)?;
    let (n, d) = (spec.n as usize, spec.d as usize);
    let values = match spec.sequence {
        Sequence::Sobol => {
            let r = sobol_strategy(&spec.scramble)?;
            let mask = u32::MAX << (32 - spec.bits);
            match spec.dtype {
                Dtype::F64 => Values::F64(sobol(spec, r, |w| lowdisc::to_f64(w & mask))),
                Dtype::F32 => Values::F32(sobol(spec, r, |w| lowdisc::to_f32(w & mask))),
                Dtype::U32 => Values::U32(sobol(spec, r, |w| w & mask)),
            }
        }
        Sequence::Halton => {
            let kind = HaltonRandomize::from_name(&spec.scramble).ok_or_else(|| {
                EngineError::value(format!(
                    "Halton scramble must be 'none', 'permute' or 'owen', got {:?}",
                    spec.scramble
                ))
            })?;
            let seq = Halton::new(kind, spec.seed);
            match spec.dtype {
                Dtype::F64 => Values::F64(chunked(n, d, spec.start, |k, j| seq.sample(k, j))),
                dtype => {
                    let words = chunked(n, d, spec.start, |k, j| seq.sample_word(k, j));
                    from_words(words, u32::MAX, dtype)
                }
            }
        }
        Sequence::Independent => {
            no_scramble(spec)?;
            let seq = Independent::new(spec.seed);
            let words = chunked(n, d, spec.start, |k, j| seq.sample_u32(u64::from(j), k));
            from_words(words, u32::MAX, spec.dtype)
        }
        Sequence::Stratified => {
            no_scramble(spec)?;
            let x = stratified::jittered_points(spec.n as u32, spec.d, spec.seed);
            match spec.dtype {
                Dtype::F64 => Values::F64(x),
                Dtype::F32 => Values::F32(x.iter().map(|&v| lowdisc::to_f32(word_of(v))).collect()),
                Dtype::U32 => Values::U32(x.iter().map(|&v| word_of(v)).collect()),
            }
        }
    };
    Ok(values)
}

/// Checks every field of `spec` against the sequence's ranges.
fn check(spec: &PointSpec) -> Result<()> {
    if spec.d == 0 {
        return Err(EngineError::value("d must be at least 1"));
    }
    let available = match spec.sequence {
        Sequence::Sobol => SOBOL_DIMENSIONS,
        Sequence::Halton => HALTON_DIMENSIONS,
        Sequence::Independent | Sequence::Stratified => u32::MAX,
    };
    if spec.d > available {
        return Err(EngineError::value(format!(
            "d = {} is beyond this sequence's table: it has {available} dimensions",
            spec.d
        )));
    }
    if spec.n.saturating_mul(u64::from(spec.d)) > MAX_POINT_WORDS {
        return Err(EngineError::value(format!(
            "n * d = {} * {} exceeds {MAX_POINT_WORDS} values (1 GiB); generate in batches \
             with start=",
            spec.n, spec.d
        )));
    }
    let end = spec.start.checked_add(spec.n);
    match spec.sequence {
        Sequence::Sobol => {
            if !(1..=32).contains(&spec.bits) {
                return Err(EngineError::value(format!(
                    "bits must be between 1 and 32, got {}",
                    spec.bits
                )));
            }
            if end.is_none_or(|e| e > 1 << 32) {
                return Err(EngineError::value(format!(
                    "start + n = {} + {} is beyond the 2^32 points of the Sobol sequence",
                    spec.start, spec.n
                )));
            }
        }
        Sequence::Stratified if spec.start != 0 => {
            return Err(EngineError::value(
                "stratified points are a set of n, not a sequence: start must be 0",
            ));
        }
        Sequence::Stratified if spec.n == 0 || spec.n > u64::from(u32::MAX) => {
            return Err(EngineError::value("stratified points need 1 <= n < 2^32"));
        }
        _ if end.is_none() => {
            return Err(EngineError::value("start + n overflows a 64-bit index"));
        }
        _ => {}
    }
    Ok(())
}

fn no_scramble(spec: &PointSpec) -> Result<()> {
    if spec.scramble != "none" {
        return Err(EngineError::value(format!(
            "this sequence has no scramble option (got {:?}); it is random by construction",
            spec.scramble
        )));
    }
    Ok(())
}

/// The randomization strategy of the catalog's `sobol*` sampler of that
/// scramble (the seed is passed beside it).
pub fn sobol_strategy(scramble: &str) -> Result<RandomizeStrategy> {
    let name = match scramble {
        "none" => "sobol",
        "xor" => "sobol-xor",
        "owen" => "sobol-owen",
        "fast-owen" => "sobol-fast-owen",
        other => {
            return Err(EngineError::value(format!(
                "Sobol scramble must be 'none', 'xor', 'owen' or 'fast-owen', got {other:?}"
            )));
        }
    };
    SamplerName::from_str(name)?
        .sobol_strategy()
        .ok_or_else(|| EngineError::value(format!("{name} is not a Sobol randomization")))
}

/// Points per chunk for `d` values per point.
fn chunk_points(d: usize) -> usize {
    (CHUNK_VALUES / d).max(1)
}

/// `n` points of `d` values, `value(start + k, j)` each, in parallel chunks.
fn chunked<T: Send + Copy + Default>(
    n: usize,
    d: usize,
    start: u64,
    value: impl Fn(u64, u32) -> T + Sync,
) -> Vec<T> {
    let mut out = vec![T::default(); n * d];
    let per = chunk_points(d);
    out.par_chunks_mut(per * d)
        .enumerate()
        .for_each(|(c, block)| {
            let first = start + (c * per) as u64;
            for (k, point) in block.chunks_exact_mut(d).enumerate() {
                for (j, v) in point.iter_mut().enumerate() {
                    *v = value(first + k as u64, j as u32);
                }
            }
        });
    out
}

/// The Sobol points of a checked request, each digit word converted by
/// `convert` (chunk by chunk, so no array of words is kept).
fn sobol<T: Send + Copy + Default>(
    spec: &PointSpec,
    r: RandomizeStrategy,
    convert: impl Fn(u32) -> T + Sync,
) -> Vec<T> {
    let (n, d) = (spec.n as usize, spec.d as usize);
    let mut out = vec![T::default(); n * d];
    let per = chunk_points(d);
    out.par_chunks_mut(per * d)
        .enumerate()
        .for_each(|(c, block)| {
            // Checked: start + n <= 2^32 and d <= the table's dimensions.
            let first = (spec.start + (c * per) as u64) as u32;
            let mut words = vec![0u32; block.len()];
            if spec.natural_order {
                for (k, point) in words.chunks_exact_mut(d).enumerate() {
                    for (j, v) in point.iter_mut().enumerate() {
                        *v = sobol::sample(first + k as u32, j as u32);
                    }
                }
            } else if let Ok(mut batch) = GrayCodeBatch::new(0, d as u32) {
                batch.seek(first);
                batch.fill(&mut words);
            }
            if r == RandomizeStrategy::None {
                for (o, &w) in block.iter_mut().zip(&words) {
                    *o = convert(w);
                }
            } else {
                let mut cache = ScrambleCache::new(r, spec.seed);
                for (point, ws) in block.chunks_exact_mut(d).zip(words.chunks_exact(d)) {
                    for (j, (o, &w)) in point.iter_mut().zip(ws).enumerate() {
                        *o = convert(cache.apply(w, j as u32));
                    }
                }
            }
        });
    out
}

/// Digit words (masked to their leading digits) in the requested type.
fn from_words(words: Vec<u32>, mask: u32, dtype: Dtype) -> Values {
    match dtype {
        Dtype::U32 if mask == u32::MAX => Values::U32(words),
        Dtype::U32 => Values::U32(words.par_iter().map(|&w| w & mask).collect()),
        Dtype::F64 => Values::F64(
            words
                .par_iter()
                .map(|&w| lowdisc::to_f64(w & mask))
                .collect(),
        ),
        Dtype::F32 => Values::F32(
            words
                .par_iter()
                .map(|&w| lowdisc::to_f32(w & mask))
                .collect(),
        ),
    }
}

/// `floor(x * 2^32)` for `x` in `[0, 1)`, as lowdisc's points mode words.
fn word_of(x: f64) -> u32 {
    (x * 4_294_967_296.0) as u32
}

/// The 32 generator-matrix columns of Sobol dimensions `0..d`: row `j` holds
/// dimension `j`'s columns, column `c` as a word whose bit 31 is the first
/// output digit (index bit `c` XORs column `c` into the point).
pub fn sobol_matrices(d: u32) -> Result<Vec<u32>> {
    if d == 0 || d > SOBOL_DIMENSIONS {
        return Err(EngineError::value(format!(
            "d must be between 1 and {SOBOL_DIMENSIONS}, got {d}"
        )));
    }
    Ok((0..d).flat_map(|j| *sobol::matrix(j)).collect())
}

#[cfg(test)]
#[path = "points_tests.rs"]
mod tests;
