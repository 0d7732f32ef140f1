//! Z-order sampling over the base-4 (0,4)-sequence of [`crate::sz`]
//! (`zorder-sz`): the screen-space blue-noise ordering of
//! [`ZSobolSampler`] (Ahmed & Wonka 2020) with the film position, the light
//! choice and the light position of the first vertex stratified jointly in
//! 5-D.
//!
//! ## Why base 4 nests with Z-order
//! [`ZSobolSampler::sample_index`] permutes the base-4 digits of the Morton
//! index, so the `4^j` samples of every aligned `2^j' x 2^j'` block of
//! pixels (and of the pixel itself) take an aligned block of `4^j`
//! consecutive sequence indices. In a (0,4)-sequence in base 4 every such
//! block is a (0,j,4)-net in base 4: at 16 spp each pixel's samples are a
//! (0,2,4)-net, the 64 samples of a 2x2 pixel quad a (0,3,4)-net, and so on
//! up the Morton hierarchy, in all four lanes at once.
//!
//! ## Groups and lanes
//! The sampler's values are *slots* `(group, lane)`. Every group has its
//! own dimension key, hence its own index permutation and scramble seeds;
//! within a group, lanes 0-3 are the four dimensions of [`crate::sz`] at
//! the group's permuted index and lane 4 ([`INDEX_LANE`]) leads with the
//! sample's position in its pixel's block, `(index mod 2^m) / 2^m` (`m =
//! ceil(log2 spp)`), the extra Hammersley coordinate that turns the block
//! of `4^j` points into a (0,j,5)-net in base 4, and continues below those
//! `m` digits with the radical inverse of the pixel's permuted Morton
//! digits (see [Pixel digits](#pixel-digits)). Lanes (0, 1) and (2, 3) are binary
//! (0,2)-sequences, so every 2-D value below is a (0,m,2)-net per pixel at
//! `spp = 2^m`. The slots follow the path tracer's dimension order (film
//! offset; lens at sampler dimensions 0-1; then per vertex light choice,
//! light position (2), BSDF lobe, BSDF direction (2), Russian roulette):
//!
//! | group | lanes 0-1 | lanes 2-3 | lane 4 |
//! |---|---|---|---|
//! | 0 | film offset | light position, vertex 0 | light choice, vertex 0 |
//! | 1 | lens | BSDF direction, vertex 0 | BSDF lobe, vertex 0 |
//! | 2 | roulette, vertex 0 (lane 0) | – | – |
//! | `2k + 1` (`k >= 1`) | light position, vertex k | BSDF direction, vertex k | light choice, vertex k |
//! | `2k + 2` (`k >= 1`) | roulette, lobe of vertex k | – | – |
//!
//! So at every power-of-four spp the 5-D point (film, light choice, light
//! position) of each pixel is a (0,m/2,5)-net in base 4. Other groups are
//! padded (independent index orders), as in `zsobol`. For any other
//! consumer it is still a valid padded Z-order sampler.
//!
//! ## Pixel digits
//! The block position alone is the same set of `2^m` values in every pixel,
//! and the scramble of a group is the same for every pixel (as in
//! `zsobol`), so without the lower digits each pixel would get exactly the
//! same light choices and, at the first vertex, the same BSDF lobe values:
//! the number of samples that pick the coating's reflection (say) would be
//! the same step function of the reflectance in every pixel, and the error
//! of neighbouring pixels would share its sign over whole regions (clumps
//! of low-frequency error, as on the coated floor and car of bmw-m6). The
//! digits below the block position are those of the pixel's permuted
//! Morton index, lowest level first, as Sobol's dimension 0 has them in
//! `zsobol`: each pixel's values are jittered within their strata by its
//! own offset, and the `4^j spp` values of an aligned `2^j x 2^j` block of
//! pixels lie in distinct intervals of width `1 / (4^j spp)` (tested),
//! while the leading `m` digits, and with them the per-pixel nets, are
//! unchanged.
//!
//! ## Limits
//! * `spp` a power of two with odd `m` (2, 8, 32...): a pixel's block is
//!   two (0,(m-1)/2,4)-nets in base 4; lanes (0, 1) and (2, 3) are still
//!   binary (0,m,2)-nets.
//! * `spp` not a power of two: as [`ZSobolSampler`], the first `spp` of the
//!   pixel's `2^m` slots (distinct boxes of the enclosing net); sample
//!   indices `>= spp` are reduced modulo `spp`.
//! * The index bits and the scrambling are [`ZSobolSampler`]'s: index bits
//!   above 31 do not enter the point and are hashed into the scramble seed,
//!   and unscrambled use needs `2 log2 R + m <= 32`.

use super::group_cache::GroupCache;
use super::{WordSampler, ZSobolSampler};
use crate::{Error, RandomizeStrategy};

/// The lane of a group that holds the sample's position in its pixel.
pub const INDEX_LANE: u32 = 4;
/// Dimension key of group 0 (groups are `GROUP_KEY + g`), apart from the
/// keys of `zsobol` and `zsobol-joint`.
const GROUP_KEY: u64 = 3 << 33;

/// The `(group, lane)` of sampler dimension `d`; see the module table.
pub fn slot(d: u32) -> (u64, u32) {
    if d < 2 {
        return (1, d);
    }
    let (vertex, j) = (u64::from((d - 2) / 7), (d - 2) % 7);
    let (first, second) = if vertex == 0 {
        (0, 1)
    } else {
        (2 * vertex + 1, 2 * vertex + 1)
    };
    match (vertex, j) {
        (_, 0) => (first, INDEX_LANE),
        (0, 1 | 2) => (0, j + 1),
        (_, 1 | 2) => (first, j - 1),
        (0, 3) => (1, INDEX_LANE),
        (_, 3) => (2 * vertex + 2, 1),
        (_, 4 | 5) => (second, j - 2),
        _ => (2 * vertex + 2, 0),
    }
}

/// The unscrambled word of the index lane at permuted index `index` with
/// `block_bits` (`m`) bits per pixel block: the block position `index mod
/// 2^m` as the leading `m` binary digits, then the pixel's permuted Morton
/// digits `index >> m`, lowest first (their radical inverse), as the
/// digits below. The leading digits make the per-pixel 5-D net; the lower
/// ones jitter each pixel's values within their strata differently, so
/// that the `4^j spp` values of an aligned `2^j x 2^j` block of pixels
/// fall in distinct intervals of width `1 / (4^j spp)` (for
/// `2j + m <= 32`).
fn index_lane_word(index: u64, block_bits: u32) -> u32 {
    let block = (index as u32 & low_mask(block_bits))
        .checked_shl(32 - block_bits)
        .unwrap_or(0);
    let pixel = (index.checked_shr(block_bits).unwrap_or(0) as u32).reverse_bits();
    block | pixel.checked_shr(block_bits).unwrap_or(0)
}

/// The mask of the `bits` lowest bits (`bits <= 32`).
fn low_mask(bits: u32) -> u32 {
    1u32.checked_shl(bits).map_or(u32::MAX, |b| b - 1)
}

/// Z-order sampler over the base-4 (0,4)-sequence; see the module
/// documentation.
#[derive(Debug, Clone)]
pub struct ZOrderSzSampler {
    /// The Z-order index permutation (and the current pixel sample).
    order: ZSobolSampler,
    strategy: RandomizeStrategy,
    seed: u64,
    /// `m`, the bits of a pixel's block.
    block_bits: u32,
    dimension: u32,
    /// The groups' permuted indices and scramble keys.
    cache: GroupCache,
}

impl ZOrderSzSampler {
    /// A sampler for `spp` samples per pixel of a `resolution` image,
    /// scrambled by `strategy` under `seed` (the limits of
    /// [`ZSobolSampler::new`]).
    pub fn new(
        spp: u32,
        resolution: [u32; 2],
        strategy: RandomizeStrategy,
        seed: u64,
    ) -> Result<Self, Error> {
        let order = ZSobolSampler::new(spp, resolution, strategy, seed)?;
        let block_bits = super::ceil_log2(u64::from(spp));
        Ok(ZOrderSzSampler {
            order,
            strategy,
            seed,
            block_bits,
            dimension: 0,
            cache: GroupCache::default(),
        })
    }

    /// The unscrambled word of `lane` at sequence index `index`.
    fn lane_word(&self, index: u64, lane: u32) -> u32 {
        if lane == INDEX_LANE {
            index_lane_word(index, self.block_bits)
        } else {
            crate::sz::sample(index as u32, lane)
        }
    }

    /// The scrambled word of slot `(group, lane)` at the current sample.
    fn word(&mut self, (group, lane): (u64, u32)) -> u32 {
        let key = GROUP_KEY + group;
        let index = self.cache.index(&self.order, group, key);
        let word = self.lane_word(index, lane);
        self.cache
            .scramble(self.strategy, self.seed, (group, key), index, lane, word)
    }
}

impl WordSampler for ZOrderSzSampler {
    fn samples_per_pixel(&self) -> u32 {
        WordSampler::samples_per_pixel(&self.order)
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
        WordSampler::start_pixel_sample(&mut self.order, pixel, sample_index, 0);
        self.dimension = dimension;
        self.cache.clear();
    }

    fn get_1d_word(&mut self) -> u32 {
        let d = super::next_key(&mut self.dimension, 1) as u32;
        self.word(slot(d))
    }

    fn get_2d_words(&mut self) -> [u32; 2] {
        let d = super::next_key(&mut self.dimension, 2) as u32;
        [slot(d), slot(d.wrapping_add(1))].map(|s| self.word(s))
    }

    fn get_pixel_2d_words(&mut self) -> [u32; 2] {
        [self.word((0, 0)), self.word((0, 1))]
    }
}

#[cfg(test)]
#[path = "zorder_sz_tests.rs"]
mod tests;
