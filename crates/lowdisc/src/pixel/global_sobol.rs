//! The global image-plane Sobol sampler of pbrt-v3 (`SobolSampler`): the
//! paper's baseline, optionally with the paper's permutation.
//!
//! The image is covered by a square of `R = 2^k` pixels per side
//! (`R >= max(width, height)`). Sobol dimensions 0 and 1, scaled by `R`, place
//! point `i` in pixel `(floor(x0 R), floor(y0 R))`, i.e. the top `k` digits of
//! dimensions 0 and 1 name the pixel. Because dimensions 0 and 1 form a
//! (0,2)-sequence, the map from the low `2k` index bits to those `2k` digits
//! is a linear bijection over GF(2); its inverse, built by Gaussian
//! elimination at construction, finds the index of sample `s` of pixel `p`:
//! the high bits are `s << 2k`, their contribution to the top digits is XORed
//! out of the target, and the inverse gives the low bits. Every index
//! `0..R^2 * spp` is used exactly once over the whole square.
//!
//! * [`PixelSampler::get_pixel_2d`] returns the digits of dimensions 0 and 1
//!   below the top `k` (`x R - px`).
//! * [`PixelSampler::get_1d`] / [`PixelSampler::get_2d`] use Sobol dimensions
//!   `2 + d` for sampler dimension `d`; past the table's last dimension they
//!   wrap around to dimension 2.
//! * Any `spp >= 1` works: sample `s` of every pixel comes from index block
//!   `s R^2 .. (s + 1) R^2`. For `spp = 2^m` a pixel's `spp` offsets form a
//!   (0,m,2)-net; for other counts they are the first `spp` points of the
//!   pixel's own (0,2)-sequence (well spread, not a complete net).
//! * Sample indices `s >= spp` continue the sequence; the index is taken
//!   modulo `2^32` (the samples still lie in the pixel). Pixels outside the
//!   `R x R` square wrap modulo `R`.
//!
//! ## Modes
//! * [`GlobalSobolMode::Randomize`]: `None` is pbrt-v3's unscrambled sampler.
//!   With `Xor`, `Owen` or `FastOwen`, dimensions `>= 2` are randomized
//!   (seeded from the sampler seed), and the
//!   in-pixel offset word is randomized with a seed derived per pixel, which
//!   keeps every sample inside its pixel: for Owen this is a nested scramble
//!   that leaves the top `k` digits (the pixel) alone.
//! * [`GlobalSobolMode::PaperLiteral`] / [`GlobalSobolMode::PaperReproducible`]:
//!   dimensions `>= 2` use [`crate::paper`]'s permuted Sobol. The literal mode
//!   keeps one PCG32 stream in the sampler (seeded with the sampler seed; see
//!   [`GlobalSobolSampler::with_stream`]), so its values depend on call order,
//!   as in the paper. With `all_dims = true` the permutation also acts on
//!   dimensions 0 and 1: the pixel is still found with the *unpermuted*
//!   inverse (the permuted top digits no longer name `p`), and the in-pixel
//!   offset is the permuted value's digits below the top `k`. Samples stay in
//!   `p`, but the sub-pixel positions lose their stratification: the flipped
//!   columns no longer form a non-singular system, so the `spp` offsets of a
//!   pixel are no longer a (0,m,2)-net and can coincide.

use alloc::boxed::Box;

use super::{SEED_PAD, WordSampler};
use crate::hash::{hash_words, hash2};
use crate::net::Net;
use crate::paper::{PaperLiteral, check_threshold, paper_reproducible};
use crate::scramble::{PreparedKey, ScrambleCache, dimension_seed};
use crate::sobol::sample;
use crate::{Error, RandomizeStrategy};

/// How a [`GlobalSobolSampler`] turns Sobol points into values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GlobalSobolMode {
    /// A standard randomization, seeded by the sampler seed
    /// (`RandomizeStrategy::None` = pbrt-v3 unscrambled).
    Randomize(RandomizeStrategy),
    /// The paper's permutation with one sequential stream (call-order dependent).
    PaperLiteral {
        /// Probability that a column is left unflipped, in `[0, 1]`.
        threshold: f64,
        /// Also permute dimensions 0-1 (the in-pixel offset).
        all_dims: bool,
    },
    /// The paper's permutation with hashed, order-independent draws.
    PaperReproducible {
        /// Probability that a column is left unflipped, in `[0, 1]`.
        threshold: f64,
        /// Also permute dimensions 0-1 (the in-pixel offset).
        all_dims: bool,
    },
}

/// Salt for per-pixel seeds of the in-pixel offset randomization.
const PIXEL_SALT: u64 = 0x7069_7865_6c5f_6f66;

/// pbrt-v3's global Sobol sampler; see the module documentation.
#[derive(Debug, Clone)]
pub struct GlobalSobolSampler {
    spp: u32,
    resolution: [u32; 2],
    /// `k`: the square covering the image is `2^k` pixels wide.
    log2_res: u32,
    /// Column `j`: the low index bits that produce target digit vector `1 << j`
    /// (bits `0..k`: dimension 0's top digits, `k..2k`: dimension 1's).
    inverse: [u32; 32],
    mode: GlobalSobolMode,
    seed: u64,
    /// The generator matrices (always [`Net::SOBOL`] in the paper modes).
    net: Net,
    /// The randomizations of the Randomize modes, with their hashing kept
    /// (boxed: the sampler enum stays small).
    scrambles: Box<Scrambles>,
    /// The literal mode's stream.
    literal: Option<PaperLiteral>,
    pixel: [u32; 2],
    index: u32,
    dimension: u32,
}

/// The randomizations of a [`GlobalSobolSampler`] in a Randomize mode.
#[derive(Debug, Clone)]
struct Scrambles {
    /// Randomization of dimensions `>= 2`, with its per-dimension seeds kept.
    dims: ScrambleCache,
    /// The in-pixel offset's scramble for the last pixel.
    offset: OffsetScramble,
}

/// The randomization of the in-pixel offset for one pixel, kept while the
/// pixel stays the same.
#[derive(Debug, Clone)]
struct OffsetScramble {
    /// The pixel (reduced modulo `R`) the fields are for, if any.
    pixel: Option<[u32; 2]>,
    /// The pixel's seeds of dimensions 0 and 1.
    seeds: [u32; 2],
    /// Its prepared keys of dimensions 0 and 1 (Owen and LMS only).
    prepared: Option<[PreparedKey; 2]>,
}

/// The top `k` digits of a word as an integer (`k <= 16`).
#[inline]
fn top_digits(word: u32, k: u32) -> u32 {
    if k == 0 { 0 } else { word >> (32 - k) }
}

/// Solves the pixel-placement system: `inverse[j]` is the combination of the
/// low `2k` index bits whose top digits equal target vector `1 << j`.
fn build_inverse(net: Net, k: u32) -> Option<[u32; 32]> {
    let n = (2 * k) as usize;
    // Pairs (target digits produced, index bits used), one per index bit.
    let (m0, m1) = (net.matrix(0), net.matrix(1));
    let mut rows: [(u64, u32); 32] = [(0, 0); 32];
    for (c, row) in rows.iter_mut().enumerate().take(n) {
        let t = u64::from(top_digits(m0[c], k)) | (u64::from(top_digits(m1[c], k)) << k);
        *row = (t, 1u32 << c);
    }
    for j in 0..n {
        let pivot = (j..n).find(|&r| rows[r].0 >> j & 1 == 1)?;
        rows.swap(j, pivot);
        let (pt, pb) = rows[j];
        for (r, row) in rows.iter_mut().enumerate().take(n) {
            if r != j && row.0 >> j & 1 == 1 {
                row.0 ^= pt;
                row.1 ^= pb;
            }
        }
    }
    let mut inverse = [0u32; 32];
    for (j, slot) in inverse.iter_mut().enumerate().take(n) {
        *slot = rows[j].1;
    }
    Some(inverse)
}

impl GlobalSobolSampler {
    /// A sampler for `spp` samples per pixel of a `resolution[0] x
    /// resolution[1]` image. Fails when `spp` or a side is 0, a threshold is
    /// outside `[0, 1]`, or the indices `R^2 * spp` do not fit in 32 bits.
    pub fn new(
        spp: u32,
        resolution: [u32; 2],
        mode: GlobalSobolMode,
        seed: u64,
    ) -> Result<Self, Error> {
        Self::with_net(spp, resolution, mode, seed, Net::SOBOL)
    }

    /// [`GlobalSobolSampler::new`] with the generator matrices of `net` in
    /// place of Sobol's (the same sampler for [`Net::SOBOL`]): dimensions
    /// 0-1 place the pixel, so their top digits must be jointly
    /// nonsingular at the image's resolution, and sampler dimension `d`
    /// reads dimension `2 + d % (n - 2)` of the `n >= 3`. The paper modes
    /// permute Sobol itself and take [`Net::SOBOL`] only.
    ///
    /// ```
    /// use lowdisc::RandomizeStrategy;
    /// use lowdisc::net::{DigitalNet, Net};
    /// use lowdisc::pixel::{GlobalSobolMode, GlobalSobolSampler, WordSampler};
    ///
    /// let columns = (0..3).map(|d| *lowdisc::sobol::matrix(d)).collect();
    /// let net = DigitalNet::from_columns("three", columns)?.into_net();
    /// let mode = GlobalSobolMode::Randomize(RandomizeStrategy::Owen);
    /// let mut a = GlobalSobolSampler::with_net(4, [8, 8], mode, 1, net)?;
    /// let mut b = GlobalSobolSampler::new(4, [8, 8], mode, 1)?;
    /// a.start_pixel_sample([3, 5], 2, 0);
    /// b.start_pixel_sample([3, 5], 2, 0);
    /// assert_eq!(a.get_1d_word(), b.get_1d_word());
    /// # Ok::<(), lowdisc::Error>(())
    /// ```
    pub fn with_net(
        spp: u32,
        resolution: [u32; 2],
        mode: GlobalSobolMode,
        seed: u64,
        net: Net,
    ) -> Result<Self, Error> {
        super::check_spp(spp)?;
        if !net.is_sobol() && !matches!(mode, GlobalSobolMode::Randomize(_)) {
            return Err(Error::NetNotSupported { sampler: "paper" });
        }
        net.require(3, "the global image-plane sampler")?;
        let [w, h] = super::check_resolution(resolution)?;
        let log2_res = super::ceil_log2(u64::from(w.max(h)));
        if log2_res > 16 {
            return Err(Error::InvalidResolution {
                width: w,
                height: h,
                reason: "the global Sobol sampler addresses at most 65536 pixels per side",
            });
        }
        if (u64::from(spp) << (2 * log2_res)) > 1u64 << 32 {
            return Err(Error::InvalidSampleCount {
                count: u64::from(spp),
                reason: "R^2 * spp exceeds the 2^32 Sobol indices (R = resolution rounded up to a power of two)",
            });
        }
        let inverse = build_inverse(net, log2_res).ok_or(Error::InvalidResolution {
            width: w,
            height: h,
            reason: "dimensions 0-1 of the net are singular at this resolution",
        })?;
        let mut literal = None;
        let mut dims_strategy = RandomizeStrategy::None;
        match mode {
            GlobalSobolMode::Randomize(r) => dims_strategy = r,
            GlobalSobolMode::PaperLiteral { threshold, .. } => {
                literal = Some(PaperLiteral::new(threshold, Some(seed))?);
            }
            GlobalSobolMode::PaperReproducible { threshold, .. } => {
                check_threshold(threshold)?;
            }
        }
        Ok(GlobalSobolSampler {
            spp,
            resolution,
            log2_res,
            inverse,
            mode,
            seed,
            net,
            scrambles: Box::new(Scrambles {
                dims: ScrambleCache::new(dims_strategy, hash2(seed, SEED_PAD)),
                offset: OffsetScramble {
                    pixel: None,
                    seeds: [0; 2],
                    prepared: None,
                },
            }),
            literal,
            pixel: [0, 0],
            index: 0,
            dimension: 0,
        })
    }

    /// A copy whose literal-mode stream is re-seeded from `(seed, stream)`
    /// (renderers call this once per tile so output does not depend on the
    /// thread count). Other modes are stateless: a plain clone.
    pub fn with_stream(&self, stream: u64) -> Self {
        let mut copy = self.clone();
        if let GlobalSobolMode::PaperLiteral { threshold, .. } = self.mode {
            // The threshold was validated by `new`.
            copy.literal = PaperLiteral::new(threshold, Some(hash2(self.seed, stream))).ok();
        }
        copy
    }

    /// True in the paper's literal mode, whose values depend on every call
    /// made before them in the stream.
    pub fn is_order_dependent(&self) -> bool {
        matches!(self.mode, GlobalSobolMode::PaperLiteral { .. })
    }

    /// The image resolution given at construction.
    pub fn resolution(&self) -> [u32; 2] {
        self.resolution
    }

    /// `k` with `R = 2^k`, the side of the square the index layout covers.
    pub fn log2_resolution(&self) -> u32 {
        self.log2_res
    }

    /// The mode given at construction.
    pub fn mode(&self) -> GlobalSobolMode {
        self.mode
    }

    /// The Sobol index of the current pixel sample.
    pub fn sample_index(&self) -> u32 {
        self.index
    }

    /// The Sobol index of sample `sample_index` of `pixel` (pixels wrap
    /// modulo `R`; the index is taken modulo `2^32`).
    pub fn index_for(&self, pixel: [u32; 2], sample_index: u32) -> u32 {
        let k = self.log2_res;
        let mask = (1u32 << k) - 1;
        let high = if 2 * k >= 32 {
            0
        } else {
            (u64::from(sample_index) << (2 * k)) as u32
        };
        let net = self.net;
        let high_top =
            top_digits(net.sample(high, 0), k) | (top_digits(net.sample(high, 1), k) << k);
        let target = (pixel[0] & mask) | ((pixel[1] & mask) << k);
        let mut rest = target ^ high_top;
        let mut low = 0u32;
        while rest != 0 {
            low ^= self.inverse[rest.trailing_zeros() as usize];
            rest &= rest - 1;
        }
        high | low
    }

    /// The net's dimension used for sampler dimension `d` (wrapping past
    /// its last dimension back to dimension 2).
    fn sobol_dim(&self, d: u32) -> u32 {
        2 + d % (self.net.dimensions() - 2)
    }

    /// The digit word of sampler dimension `d` at the current index.
    fn value(&mut self, d: u32) -> u32 {
        let dim = self.sobol_dim(d);
        match self.mode {
            GlobalSobolMode::Randomize(_) => {
                let word = self.net.sample(self.index, dim);
                self.scrambles.dims.apply(word, dim)
            }
            GlobalSobolMode::PaperLiteral { .. } => match self.literal.as_mut() {
                Some(stream) => stream.sample(self.index, dim),
                None => sample(self.index, dim),
            },
            GlobalSobolMode::PaperReproducible { threshold, .. } => {
                paper_reproducible(self.index, dim, threshold, self.seed)
            }
        }
    }

    /// The in-pixel offset as digit words (the digits of dimensions 0-1
    /// below the top `k`, randomized or permuted as the mode says).
    fn pixel_words(&mut self) -> [u32; 2] {
        let (k, index) = (self.log2_res, self.index);
        let raw: [u32; 2] = match self.mode {
            GlobalSobolMode::PaperLiteral { all_dims: true, .. } => match self.literal.as_mut() {
                Some(stream) => [stream.sample(index, 0), stream.sample(index, 1)],
                None => [sample(index, 0), sample(index, 1)],
            },
            GlobalSobolMode::PaperReproducible {
                threshold,
                all_dims: true,
            } => [
                paper_reproducible(index, 0, threshold, self.seed),
                paper_reproducible(index, 1, threshold, self.seed),
            ],
            _ => [self.net.sample(index, 0), self.net.sample(index, 1)],
        };
        let offset = raw.map(|w| w << k);
        match self.mode {
            GlobalSobolMode::Randomize(r) if r != RandomizeStrategy::None => {
                let mask = (1u32 << k) - 1;
                let pixel = self.pixel.map(|c| c & mask);
                let cache = &mut self.scrambles.offset;
                if cache.pixel != Some(pixel) {
                    let [px, py] = pixel.map(u64::from);
                    let pixel_seed = hash_words(&[self.seed, SEED_PAD, PIXEL_SALT, px, py]);
                    cache.seeds = [dimension_seed(pixel_seed, 0), dimension_seed(pixel_seed, 1)];
                    cache.prepared = match cache.seeds.map(|s| r.prepare(s)) {
                        [Some(a), Some(b)] => Some([a, b]),
                        _ => None,
                    };
                    cache.pixel = Some(pixel);
                }
                // Equal to `r.apply(offset[d], pixel_seed, d)`.
                core::array::from_fn(|d| match &cache.prepared {
                    Some(keys) => keys[d].scramble(offset[d]),
                    None => r.apply_dimension_seed(offset[d], cache.seeds[d]),
                })
            }
            _ => offset,
        }
    }
}

impl WordSampler for GlobalSobolSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
        self.pixel = pixel;
        self.index = self.index_for(pixel, sample_index);
        self.dimension = dimension;
    }

    fn get_1d_word(&mut self) -> u32 {
        let d = super::next_key(&mut self.dimension, 1) as u32;
        self.value(d)
    }

    fn get_2d_words(&mut self) -> [u32; 2] {
        let d = super::next_key(&mut self.dimension, 2) as u32;
        [self.value(d), self.value(d.wrapping_add(1))]
    }

    fn get_pixel_2d_words(&mut self) -> [u32; 2] {
        self.pixel_words()
    }
}

#[cfg(test)]
mod tests;
