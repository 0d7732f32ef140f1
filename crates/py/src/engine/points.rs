//! Sequences as arrays: Sobol (Joe-Kuo, Gray-code or natural order, any of
//! lowdisc's randomizations), Halton (unscrambled, digit-permuted, Owen,
//! nested affine),
//! independent (PCG32) and stratified (jittered) points.
//!
//! Point `k` of a request is sequence point `start + k`, so a request can
//! continue where another ended. Requests are split into fixed chunks of
//! points computed in parallel; every value depends only on its index and
//! dimension, so results do not depend on the thread count.

use lowdisc::halton::{self, Halton, HaltonRandomize};
use lowdisc::independent::Independent;
use lowdisc::sobol;
use lowdisc::stratified;
use rayon::prelude::*;

use super::sobol_fill::{self, Scrambler, SobolRange};
use super::{CHUNK_VALUES, Dtype, EngineError, Result, Values};

/// Which sequence a request asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sequence {
    /// Sobol; scrambles `none`, `xor`, `owen` (the catalog's `sobol-owen`
    /// values), `owen-tree` ([`lowdisc::scramble::OwenTreeKey`]: the same
    /// law, other values), `fast-owen`, `lms`.
    Sobol,
    /// Halton; scrambles `none`, `permute`, `owen`, `nested-affine`.
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

/// The most values one request writes: what a byte-addressed array of
/// 8-byte values can hold (`isize::MAX / 8`). Memory runs out well before
/// this; the caller allocates the output, so that is its error to report.
pub const MAX_VALUES: u64 = (isize::MAX as u64) / 8;

/// The points of `spec`, point-major (`n * d` values).
pub fn generate(spec: &PointSpec) -> Result<Values> {
    let len = check_request(spec)?;
    let mut values = match spec.dtype {
        Dtype::F64 => Values::F64(vec![0.0; len]),
        Dtype::F32 => Values::F32(vec![0.0; len]),
        Dtype::U32 => Values::U32(vec![0; len]),
    };
    let out = match &mut values {
        Values::F64(v) => Output::from(&mut v[..]),
        Values::F32(v) => Output::from(&mut v[..]),
        Values::U32(v) => Output::from(&mut v[..]),
    };
    generate_into(spec, out)?;
    Ok(values)
}

/// An array to write a request's values into: `n * d` of the request's dtype.
#[derive(Debug)]
pub enum Output<'a> {
    /// `float64` values.
    F64(&'a mut [f64]),
    /// `float32` values.
    F32(&'a mut [f32]),
    /// `uint32` digit words.
    U32(&'a mut [u32]),
}

impl<'a> From<&'a mut [f64]> for Output<'a> {
    fn from(values: &'a mut [f64]) -> Self {
        Output::F64(values)
    }
}

impl<'a> From<&'a mut [f32]> for Output<'a> {
    fn from(values: &'a mut [f32]) -> Self {
        Output::F32(values)
    }
}

impl<'a> From<&'a mut [u32]> for Output<'a> {
    fn from(values: &'a mut [u32]) -> Self {
        Output::U32(values)
    }
}

impl Output<'_> {
    fn len(&self) -> usize {
        match self {
            Output::F64(o) => o.len(),
            Output::F32(o) => o.len(),
            Output::U32(o) => o.len(),
        }
    }

    fn dtype(&self) -> Dtype {
        match self {
            Output::F64(_) => Dtype::F64,
            Output::F32(_) => Dtype::F32,
            Output::U32(_) => Dtype::U32,
        }
    }
}

/// Writes the points of `spec` into `out` (point-major, `n * d` values of
/// `spec.dtype`), so the caller chooses where the array lives.
pub fn generate_into(spec: &PointSpec, out: Output<'_>) -> Result<()> {
    let len = check_request(spec)?;
    if out.len() != len || out.dtype() != spec.dtype {
        return Err(EngineError::value(format!(
            "the output must hold n * d = {len} values of {:?}, got {} of {:?}",
            spec.dtype,
            out.len(),
            out.dtype()
        )));
    }
    let d = spec.d as usize;
    match spec.sequence {
        Sequence::Sobol => {
            let scrambler = Scrambler::new(&spec.scramble, spec.seed, spec.d)?;
            let range = SobolRange {
                start: spec.start,
                d,
                natural_order: spec.natural_order,
                digits: spec.bits,
            };
            match out {
                Output::F64(o) => sobol_fill::fill(o, range, &scrambler, lowdisc::to_f64),
                Output::F32(o) => sobol_fill::fill(o, range, &scrambler, lowdisc::to_f32),
                Output::U32(o) => sobol_fill::fill(o, range, &scrambler, |w| w),
            }
        }
        Sequence::Halton => {
            let seq = Halton::new(halton_kind(spec)?, spec.seed);
            match out {
                Output::F64(o) => chunked(o, d, spec.start, |k, j| seq.sample(k, j)),
                other => store_words(other, d, spec.start, |k, j| seq.sample_word(k, j)),
            }
        }
        Sequence::Independent => {
            let seq = Independent::new(spec.seed);
            store_words(out, d, spec.start, |k, j| seq.sample_u32(u64::from(j), k));
        }
        Sequence::Stratified => {
            let x = stratified::jittered_points(spec.n as u32, spec.d, spec.seed);
            match out {
                Output::F64(o) => o.copy_from_slice(&x),
                Output::F32(o) => o
                    .iter_mut()
                    .zip(&x)
                    .for_each(|(o, &v)| *o = lowdisc::to_f32(word_of(v))),
                Output::U32(o) => o.iter_mut().zip(&x).for_each(|(o, &v)| *o = word_of(v)),
            }
        }
    }
    Ok(())
}

/// Checks every field of `spec` against the sequence's ranges and names (so
/// a caller can do it before allocating the output); the number of values,
/// `n * d`.
pub fn check_request(spec: &PointSpec) -> Result<usize> {
    match spec.sequence {
        Sequence::Sobol => Scrambler::check_name(&spec.scramble)?,
        Sequence::Halton => halton_kind(spec).map(|_| ())?,
        Sequence::Independent | Sequence::Stratified => no_scramble(spec)?,
    }
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
    let values = spec.n.saturating_mul(u64::from(spec.d));
    if values > MAX_VALUES {
        return Err(EngineError::value(format!(
            "n * d = {} * {} is more than an array can hold here (at most {MAX_VALUES} values)",
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
    Ok((spec.n * u64::from(spec.d)) as usize)
}

/// The Halton randomization of `spec`'s scramble name.
fn halton_kind(spec: &PointSpec) -> Result<HaltonRandomize> {
    HaltonRandomize::from_name(&spec.scramble).ok_or_else(|| {
        EngineError::value(format!(
            "Halton scramble must be 'none', 'permute', 'owen' or 'nested-affine', got {:?}",
            spec.scramble
        ))
    })
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

/// Points per chunk for `d` values per point.
fn chunk_points(d: usize) -> usize {
    (CHUNK_VALUES / d).max(1)
}

/// Fills `out` (points of `d` values) with `value(start + k, j)`, in
/// parallel chunks.
fn chunked<T: Send>(out: &mut [T], d: usize, start: u64, value: impl Fn(u64, u32) -> T + Sync) {
    let per = chunk_points(d);
    out.par_chunks_mut(per * d)
        .enumerate()
        .for_each(|(c, block)| {
            let first = start + (c * per) as u64;
            for (k, point) in (first..).zip(block.chunks_exact_mut(d)) {
                for (j, v) in point.iter_mut().enumerate() {
                    *v = value(k, j as u32);
                }
            }
        });
}

/// Fills `out` with the digit words `word(start + k, j)` in its type.
fn store_words(out: Output<'_>, d: usize, start: u64, word: impl Fn(u64, u32) -> u32 + Sync) {
    match out {
        Output::F64(o) => chunked(o, d, start, |k, j| lowdisc::to_f64(word(k, j))),
        Output::F32(o) => chunked(o, d, start, |k, j| lowdisc::to_f32(word(k, j))),
        Output::U32(o) => chunked(o, d, start, word),
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
