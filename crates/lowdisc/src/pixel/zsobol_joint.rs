//! Z-order Sobol padded by groups of four dimensions: the screen-space
//! blue-noise ordering of [`ZSobolSampler`] (Ahmed & Wonka 2020) with the
//! 4-D joint stratification of Burley 2020's padding.
//!
//! ## Groups
//! The in-pixel offset and the sampler dimensions are *slots* `(group,
//! lane)`, lane in `0..4`. Every group has its own dimension key, hence its
//! own Z-order index permutation ([`ZSobolSampler::sample_index`]) and its
//! own randomization seeds; the four lanes of a group read Sobol dimensions
//! 0-3 at the *same* permuted index, so they stay jointly stratified: the
//! `2^m` samples of a pixel are an aligned block of the 4-D Sobol sequence,
//! and neighbouring pixels get hierarchically decorrelated blocks as in
//! `zsobol`. Values of different groups are padded (independent index
//! orders). The offset is always lanes 0-1 of group 0, a (0,m,2)-net per
//! pixel at `spp = 2^m`. [`GroupLayout`] says where sampler dimension `d`
//! goes:
//!
//! * [`GroupLayout::Sequential`] (`zsobol-4d`): Burley's order, slot
//!   `v = d + 2` is lane `v % 4` of group `v / 4`; a 2-D value that
//!   straddles two groups takes one lane of each.
//! * [`GroupLayout::PathVertices`] (`zsobol-joint`): the same groups
//!   aligned with the dimension order of this project's path tracer (the
//!   lens at 0-1, then seven dimensions per scattering vertex: light
//!   choice, light position (2), BSDF lobe, BSDF direction (2), Russian
//!   roulette). Group 0 is the film position with the lens; vertex `k` has
//!   group `1 + 2k` for its light choice, light position and lobe (so the
//!   choice among a mesh light's triangles and the point on it are
//!   jointly stratified) and group `2 + 2k` for its BSDF direction and
//!   roulette (lane 3 unused). No 2-D value straddles two groups. Up to the
//!   first vertex this is `zsobol-4d` exactly (the same values); later
//!   vertices differ. For any other consumer it is still a valid padded
//!   Z-order Sobol sampler.
//!
//! Grouping the film position with the light position instead (lanes 2-3
//! of group 0, choice apart) was measured and is worse on direct lighting
//! than either layout: the light choice then falls out of the light
//! sample's stratification, and Sobol dimensions 2-3 are a weaker pair.
//!
//! Scrambling, the index layout, non-power-of-two `spp` and the limits on
//! index bits are those of [`ZSobolSampler`], whose index permutation this
//! sampler uses (with group keys above every key `zsobol` uses).

use super::group_cache::GroupCache;
use super::{WordSampler, ZSobolSampler};
use crate::net::Net;
use crate::{Error, RandomizeStrategy};

/// Dimension key of group 0 (groups are `GROUP_KEY + g`); above `zsobol`'s
/// dimension keys and its pixel key `2^32`.
const GROUP_KEY: u64 = 1 << 33;

/// Where the sampler dimensions go; see the module documentation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GroupLayout {
    /// Slot `d + 2` in order, four lanes per group (Burley 2020).
    Sequential,
    /// Groups aligned with the path tracer's scattering vertices.
    PathVertices,
}

/// Slots of the seven dimensions of a vertex, relative to its first group:
/// light choice, light position (2), lobe, BSDF direction (2), roulette.
const VERTEX: [(u64, u32); 7] = [(0, 0), (0, 1), (0, 2), (0, 3), (1, 0), (1, 1), (1, 2)];

impl GroupLayout {
    /// The `(group, lane)` of sampler dimension `d`.
    pub fn slot(self, d: u32) -> (u64, u32) {
        match self {
            GroupLayout::Sequential => {
                let v = u64::from(d) + 2;
                (v / 4, (v % 4) as u32)
            }
            GroupLayout::PathVertices if d < 2 => (0, d + 2),
            GroupLayout::PathVertices => {
                let vertex = u64::from((d - 2) / 7);
                let (group, lane) = VERTEX[((d - 2) % 7) as usize];
                (1 + 2 * vertex + group, lane)
            }
        }
    }
}

/// Z-order Sobol padded by 4-D groups; see the module documentation.
#[derive(Debug, Clone)]
pub struct ZSobolJointSampler {
    /// The Z-order index permutation (and the current pixel sample).
    order: ZSobolSampler,
    layout: GroupLayout,
    strategy: RandomizeStrategy,
    seed: u64,
    dimension: u32,
    /// The groups' permuted indices and scramble keys.
    cache: GroupCache,
}

impl ZSobolJointSampler {
    /// A sampler for `spp` samples per pixel of a `resolution` image with
    /// `layout`, scrambled by `strategy` under `seed` (the limits of
    /// [`ZSobolSampler::new`]).
    pub fn new(
        spp: u32,
        resolution: [u32; 2],
        layout: GroupLayout,
        strategy: RandomizeStrategy,
        seed: u64,
    ) -> Result<Self, Error> {
        Self::with_net(spp, resolution, layout, strategy, seed, Net::SOBOL)
    }

    /// [`ZSobolJointSampler::new`] reading dimensions 0-3 of `net` in place
    /// of Sobol's (the same sampler for [`Net::SOBOL`]).
    pub fn with_net(
        spp: u32,
        resolution: [u32; 2],
        layout: GroupLayout,
        strategy: RandomizeStrategy,
        seed: u64,
        net: Net,
    ) -> Result<Self, Error> {
        net.require(4, "a sampler padded by 4-D groups")?;
        Ok(ZSobolJointSampler {
            order: ZSobolSampler::with_net(spp, resolution, strategy, seed, net)?,
            layout,
            strategy,
            seed,
            dimension: 0,
            cache: GroupCache::default(),
        })
    }

    /// The scrambled word of `lane` in `group` at the current sample.
    fn word(&mut self, (group, lane): (u64, u32)) -> u32 {
        let key = GROUP_KEY + group;
        let index = self.cache.index(&self.order, group, key);
        let word = self.order.net().sample(index as u32, lane);
        self.cache
            .scramble(self.strategy, self.seed, (group, key), index, lane, word)
    }
}

impl WordSampler for ZSobolJointSampler {
    fn samples_per_pixel(&self) -> u32 {
        WordSampler::samples_per_pixel(&self.order)
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
        WordSampler::start_pixel_sample(&mut self.order, pixel, sample_index, 0);
        self.dimension = dimension;
        self.cache.clear();
    }

    fn get_1d_word(&mut self) -> u32 {
        let d = self.dimension;
        self.dimension = d.wrapping_add(1);
        self.word(self.layout.slot(d))
    }

    fn get_2d_words(&mut self) -> [u32; 2] {
        let d = self.dimension;
        self.dimension = d.wrapping_add(2);
        let first = self.word(self.layout.slot(d));
        [first, self.word(self.layout.slot(d.wrapping_add(1)))]
    }

    fn get_pixel_2d_words(&mut self) -> [u32; 2] {
        [self.word((0, 0)), self.word((0, 1))]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::net_check::{shapes, stratified, t_value};
    use crate::sobol::sample;
    use alloc::vec::Vec;

    const LAYOUTS: [GroupLayout; 2] = [GroupLayout::Sequential, GroupLayout::PathVertices];

    fn sampler(spp: u32, layout: GroupLayout) -> ZSobolJointSampler {
        ZSobolJointSampler::new(spp, [16, 8], layout, RandomizeStrategy::FastOwen, 7).unwrap()
    }

    /// The film offset, the first light choice, the first light position
    /// and the first BSDF direction of every sample of `pixel`, as the path
    /// tracer draws them.
    fn pixel_words(s: &mut ZSobolJointSampler, pixel: [u32; 2]) -> Vec<[u32; 7]> {
        (0..s.samples_per_pixel())
            .map(|k| {
                s.start_pixel_sample(pixel, k, 0);
                let film = s.get_pixel_2d_words();
                let _lens = s.get_2d_words();
                let choice = s.get_1d_word();
                let light = s.get_2d_words();
                let _lobe = s.get_1d_word();
                let bsdf = s.get_2d_words();
                [
                    film[0], film[1], choice, light[0], light[1], bsdf[0], bsdf[1],
                ]
            })
            .collect()
    }

    #[test]
    fn slots_are_distinct_and_path_pairs_stay_in_one_group() {
        for layout in LAYOUTS {
            let mut slots: Vec<_> = (0..300).map(|d| layout.slot(d)).collect();
            slots.extend([(0, 0), (0, 1)]);
            let n = slots.len();
            slots.sort_unstable();
            slots.dedup();
            assert_eq!(slots.len(), n, "{layout:?}");
            assert!(slots.iter().all(|&(_, lane)| lane < 4));
        }
        let l = GroupLayout::PathVertices;
        for d in 0..9 {
            assert_eq!(l.slot(d), GroupLayout::Sequential.slot(d), "{d}");
        }
        assert_ne!(l.slot(9), GroupLayout::Sequential.slot(9));
        assert_eq!(
            [l.slot(2), l.slot(3), l.slot(4)],
            [(1, 0), (1, 1), (1, 2)],
            "light choice with the light position"
        );
        for first in [0]
            .into_iter()
            .chain((0..40).flat_map(|k| [3 + 7 * k, 6 + 7 * k]))
        {
            let ((g0, a), (g1, b)) = (l.slot(first), l.slot(first + 1));
            assert!(g0 == g1 && b == a + 1, "pair at {first}");
        }
    }

    #[test]
    fn the_film_offset_of_every_pixel_is_a_0m2_net() {
        for layout in LAYOUTS {
            for m in [0u32, 2, 3, 4, 6] {
                let mut s = sampler(1 << m, layout);
                for pixel in [[0, 0], [5, 3], [15, 7], [20, 9]] {
                    let film: Vec<Vec<u32>> = pixel_words(&mut s, pixel)
                        .iter()
                        .map(|w| w[..2].to_vec())
                        .collect();
                    assert_eq!(t_value(&film, m), 0, "{layout:?} m={m} {pixel:?}");
                }
            }
        }
    }

    #[test]
    fn the_first_light_choice_and_position_are_jointly_stratified() {
        // An aligned block of 2^m points of the Sobol sequence in
        // dimensions 0-2 is a (t, m, 3)-net; scrambling keeps t.
        for m in [2u32, 4, 5] {
            let block: Vec<Vec<u32>> = (0..1u32 << m)
                .map(|i| (0..3).map(|d| sample(i, d)).collect())
                .collect();
            let sobol_t = t_value(&block, m);
            assert!(sobol_t < m);
            let mut s = sampler(1 << m, GroupLayout::PathVertices);
            for pixel in [[0, 0], [3, 6], [11, 2]] {
                let joint: Vec<Vec<u32>> = pixel_words(&mut s, pixel)
                    .iter()
                    .map(|w| w[2..5].to_vec())
                    .collect();
                assert!(t_value(&joint, m) <= sobol_t, "m={m} {pixel:?}");
            }
        }
    }

    #[test]
    fn any_spp_gives_distinct_boxes_of_the_enclosing_net() {
        for spp in [3u32, 5, 12] {
            let m = crate::pixel::ceil_log2(u64::from(spp));
            let mut s = sampler(spp, GroupLayout::PathVertices);
            let words = pixel_words(&mut s, [4, 4]);
            assert_eq!(words.len(), spp as usize);
            // Lanes 0-1 (Sobol dimensions 0-1): film and first BSDF direction.
            for pair in [0..2, 5..7] {
                let pts: Vec<Vec<u32>> = words.iter().map(|w| w[pair.clone()].to_vec()).collect();
                for b in shapes(m, 2) {
                    assert!(stratified(&pts, &b), "spp={spp} {pair:?} {b:?}");
                }
            }
        }
    }

    #[test]
    fn values_depend_only_on_pixel_sample_and_dimension() {
        let mut a = sampler(16, GroupLayout::PathVertices);
        let mut b = a.clone();
        let forward = pixel_words(&mut a, [2, 5]);
        // Another pixel first, then the samples of [2, 5] in reverse.
        pixel_words(&mut b, [9, 1]);
        for k in (0..16).rev() {
            b.start_pixel_sample([2, 5], k, 3);
            let light = b.get_2d_words();
            b.start_pixel_sample([2, 5], k, 0);
            assert_eq!(
                b.get_pixel_2d_words(),
                [forward[k as usize][0], forward[k as usize][1]]
            );
            assert_eq!(light, [forward[k as usize][3], forward[k as usize][4]]);
        }
        let mut other = ZSobolJointSampler::new(
            16,
            [16, 8],
            GroupLayout::PathVertices,
            RandomizeStrategy::FastOwen,
            8,
        )
        .unwrap();
        assert_ne!(pixel_words(&mut other, [2, 5]), forward, "the seed is used");
    }
}
