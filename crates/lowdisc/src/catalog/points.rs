//! Points mode: the raw sequence behind each catalog name, as 32-bit digit
//! words (`floor(x * 2^32)`), point-major, made as the name's [`Family`]
//! says:
//!
//! * [`Family::Sobol`]: the Sobol sequence (or the config's net, see
//!   [`crate::net`]) with that randomization (seeded by the config seed). [`Order::Gray`] is the order of Joe & Kuo's
//!   generator and `scipy.stats.qmc.Sobol` (point `k` is natural point
//!   `gray_code(k)`); [`Order::Natural`] is `sobol::sample(k, d)`.
//! * [`Family::PaperLiteral`]: the literal permuted Sobol over the same
//!   indices, with one stream (seeded by the config seed) consumed
//!   point-major, dimensions in the order of the range, so the words depend
//!   on the range asked for. [`Family::PaperReproducible`]: hashed draws,
//!   independent of the range and order.
//! * [`Family::Halton`]: the Halton sequence with that randomization;
//!   [`Family::Independent`]: stream = dimension, offset = point index;
//!   [`Family::Stratified`]: `stratified::jittered_points` over dimensions
//!   `0..end`, sliced to the range.
//! * [`Family::PerPixel`]: the name's pixel sampler, built for a 1x1 image
//!   with `spp = n`; the points are the `n` samples of pixel (0,0):
//!   dimensions 0-1 are the in-pixel offset, dimensions `2j + 2, 2j + 3` the
//!   `get_2d` pair at sampler dimension `2j` (so a dimension's value does
//!   not depend on the range asked for).
//!
//! Only the Sobol family uses the order; the others ignore it.

use alloc::vec::Vec;
use core::ops::Range;

use super::config::SamplerConfig;
use super::family::Family;
use super::params::Params;
use crate::halton::Halton;
use crate::independent::Independent;
use crate::paper::{PaperLiteral, check_threshold, paper_reproducible};
use crate::pixel::WordSampler;
use crate::sobol::{GrayCodeBatch, gray_code};
use crate::{Error, RandomizeStrategy, stratified};

/// The most words one call may return (`n * dims.len()`), 1 GiB of output.
pub const MAX_POINT_WORDS: u64 = 1 << 28;

/// The order in which the Sobol family's points are emitted.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Order {
    /// Gray-code order (Joe-Kuo, scipy): point `k` is natural point `k ^ (k >> 1)`.
    #[default]
    Gray,
    /// Sobol's natural order: point `k` is index `k`.
    Natural,
}

/// The first `n` points of `config.name`'s sequence in dimensions `dims`,
/// point-major (`out[k * dims.len() + j]` is dimension `dims.start + j` of
/// point `k`); see the module documentation. Only `name`, `seed`,
/// `threshold` and `net` of the config are used.
pub fn generate_points(
    config: &SamplerConfig,
    n: u32,
    dims: Range<u32>,
    order: Order,
) -> Result<Vec<u32>, Error> {
    let family = config.name.family();
    if n == 0 {
        return Err(Error::InvalidSampleCount {
            count: 0,
            reason: "at least one point is needed",
        });
    }
    config.validate_net()?;
    let available = match family {
        f if f.is_sobol() => u64::from(config.net.dimensions()),
        f => f.dimensions(),
    };
    if dims.is_empty() || u64::from(dims.end) > available {
        let dimension = if dims.is_empty() {
            dims.start
        } else {
            dims.end - 1
        };
        return Err(Error::DimensionOutOfRange {
            dimension: u64::from(dimension),
            available,
        });
    }
    check_threshold(config.threshold)?;
    let width = dims.len();
    if u64::from(n) * width as u64 > MAX_POINT_WORDS {
        return Err(Error::InvalidSampleCount {
            count: u64::from(n),
            reason: "n times the number of dimensions exceeds 2^28 words; generate in batches",
        });
    }
    let seed = config.seed;
    let index = |k: u32| match order {
        Order::Gray => gray_code(k),
        Order::Natural => k,
    };
    let mut out = Vec::with_capacity(n as usize * width);
    match family {
        Family::Sobol(RandomizeStrategy::None) if order == Order::Gray && config.net.is_sobol() => {
            let mut batch = GrayCodeBatch::new(dims.start, width as u32)?;
            out.resize(n as usize * width, 0);
            batch.fill(&mut out);
        }
        Family::Sobol(r) => {
            for k in 0..n {
                out.extend(
                    dims.clone()
                        .map(|d| r.apply(config.net.sample(index(k), d), seed, d)),
                );
            }
        }
        Family::PaperLiteral => {
            let mut stream = PaperLiteral::new(config.threshold, Some(seed))?;
            for k in 0..n {
                out.extend(dims.clone().map(|d| stream.sample(index(k), d)));
            }
        }
        Family::PaperReproducible => {
            for k in 0..n {
                out.extend(
                    dims.clone()
                        .map(|d| paper_reproducible(index(k), d, config.threshold, seed)),
                );
            }
        }
        Family::Halton(kind) => {
            let seq = Halton::new(kind, seed);
            for k in 0..n {
                out.extend(dims.clone().map(|d| seq.sample_word(u64::from(k), d)));
            }
        }
        Family::Independent => {
            let seq = Independent::new(seed);
            for k in 0..n {
                out.extend(
                    dims.clone()
                        .map(|d| seq.sample_u32(u64::from(d), u64::from(k))),
                );
            }
        }
        Family::Stratified => {
            if u64::from(n) * u64::from(dims.end) > MAX_POINT_WORDS {
                return Err(Error::InvalidSampleCount {
                    count: u64::from(n),
                    reason: "stratified points are generated from dimension 0: n * dims.end exceeds 2^28",
                });
            }
            let all = stratified::jittered_points(n, dims.end, seed);
            for point in all.chunks_exact(dims.end as usize) {
                out.extend(point[dims.start as usize..].iter().map(|&x| word_of(x)));
            }
        }
        Family::PerPixel => {
            let params = Params {
                spp: n,
                resolution: [1, 1],
                ..config.params()
            };
            let mut sampler = config.name.build(&params)?;
            let words = sampler.words().ok_or(Error::InvalidSampleCount {
                count: u64::from(n),
                reason: "the sampler table marks this per-pixel sampler `values`, not `words`",
            })?;
            pixel_points(words, n, dims, &mut out);
        }
    }
    Ok(out)
}

/// `floor(x * 2^32)` for `x` in `[0, 1)` (saturating at the ends).
fn word_of(x: f64) -> u32 {
    (x * 4_294_967_296.0) as u32
}

/// The samples of pixel (0,0) as points (see the module documentation).
fn pixel_points<S: WordSampler + ?Sized>(s: &mut S, n: u32, dims: Range<u32>, out: &mut Vec<u32>) {
    for k in 0..n {
        s.start_pixel_sample([0, 0], k, 0);
        let offset = s.get_pixel_2d_words();
        let mut pair: Option<(u32, [u32; 2])> = None;
        for d in dims.clone() {
            let word = if d < 2 {
                offset[d as usize]
            } else {
                let first = (d - 2) & !1;
                let words = match pair {
                    Some((f, w)) if f == first => w,
                    _ => {
                        s.start_pixel_sample([0, 0], k, first);
                        let w = s.get_2d_words();
                        pair = Some((first, w));
                        w
                    }
                };
                words[((d - 2) & 1) as usize]
            };
            out.push(word);
        }
    }
}
