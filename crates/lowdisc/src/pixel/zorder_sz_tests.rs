//! Structural tests of [`ZOrderSzSampler`]: the nets its construction
//! promises, per pixel and up the Morton hierarchy.

use super::*;
use crate::net_check::{is_net, shapes, stratified};
use alloc::vec::Vec;

fn sampler(spp: u32) -> ZOrderSzSampler {
    ZOrderSzSampler::new(spp, [16, 16], RandomizeStrategy::FastOwen, 7).unwrap()
}

/// What the path tracer draws first: film offset (0-1), lens (2-3), light
/// choice (4), light position (5-6), lobe (7), BSDF direction (8-9).
fn sample_words(s: &mut ZOrderSzSampler, pixel: [u32; 2], k: u32) -> [u32; 10] {
    s.start_pixel_sample(pixel, k, 0);
    let film = s.get_pixel_2d_words();
    let lens = s.get_2d_words();
    let choice = s.get_1d_word();
    let light = s.get_2d_words();
    let lobe = s.get_1d_word();
    let bsdf = s.get_2d_words();
    [
        film[0], film[1], lens[0], lens[1], choice, light[0], light[1], lobe, bsdf[0], bsdf[1],
    ]
}

/// The words of every sample of the pixels `pixels`, restricted to `axes`.
fn points(s: &mut ZOrderSzSampler, pixels: &[[u32; 2]], axes: &[usize]) -> Vec<Vec<u32>> {
    let spp = s.samples_per_pixel();
    pixels
        .iter()
        .flat_map(|&p| (0..spp).map(move |k| (p, k)))
        .map(|(p, k)| {
            let w = sample_words(s, p, k);
            axes.iter().map(|&a| w[a]).collect()
        })
        .collect()
}

/// The pixels of the aligned `side x side` block at `corner`.
fn block(corner: [u32; 2], side: u32) -> Vec<[u32; 2]> {
    (0..side * side)
        .map(|i| [corner[0] + i % side, corner[1] + i / side])
        .collect()
}

const FILM_AND_LIGHT: [usize; 5] = [0, 1, 4, 5, 6];
const PAIRS: [[usize; 2]; 4] = [[0, 1], [2, 3], [5, 6], [8, 9]];

#[test]
fn slots_are_distinct_and_2d_values_use_a_binary_02_pair() {
    let mut slots: Vec<_> = (0..400).map(slot).collect();
    slots.extend([(0, 0), (0, 1)]);
    let n = slots.len();
    slots.sort_unstable();
    slots.dedup();
    assert_eq!(slots.len(), n);
    assert!(slots.iter().all(|&(_, lane)| lane <= INDEX_LANE));
    // Lens, then each vertex's light position and BSDF direction.
    for first in [0]
        .into_iter()
        .chain((0..50).flat_map(|k| [3 + 7 * k, 6 + 7 * k]))
    {
        let ((g0, a), (g1, b)) = (slot(first), slot(first + 1));
        assert!(g0 == g1 && a % 2 == 0 && b == a + 1, "pair at {first}");
    }
    assert_eq!([slot(2), slot(3), slot(4)], [(0, 4), (0, 2), (0, 3)]);
}

#[test]
fn film_choice_and_light_of_every_pixel_are_a_0m5_net_in_base_4() {
    for (spp, m) in [(1u32, 0u32), (4, 1), (16, 2), (64, 3)] {
        let mut s = sampler(spp);
        for pixel in [[0, 0], [5, 3], [15, 7], [20, 9]] {
            let pts = points(&mut s, &[pixel], &FILM_AND_LIGHT);
            assert!(is_net(&pts, m, 2), "spp={spp} {pixel:?}");
        }
    }
}

/// The sampler dimensions read from the index lane that the path tracer
/// uses: light choice and lobe of vertex 0, light choice of vertex 1.
const INDEX_LANE_DIMS: [u32; 3] = [2, 5, 9];

#[test]
fn index_lane_values_of_a_morton_block_of_pixels_are_in_distinct_intervals() {
    // Neighbouring pixels must not reuse each other's light choices or
    // lobe values: the 4^j spp values of an aligned 2^j x 2^j block lie in
    // 4^j spp distinct intervals (a pixel alone: spp intervals).
    for &d in &INDEX_LANE_DIMS {
        assert_eq!(slot(d).1, INDEX_LANE, "dimension {d}");
    }
    for strategy in [RandomizeStrategy::None, RandomizeStrategy::FastOwen] {
        for (spp, m) in [(1u32, 0u32), (4, 2), (16, 4), (64, 6)] {
            let mut s = ZOrderSzSampler::new(spp, [16, 16], strategy, 7).unwrap();
            for (side, j) in [(1u32, 0u32), (2, 1), (4, 2), (8, 3)] {
                let bits = 2 * j + m;
                for corner in [[0, 0], [side, side], [8, 0]] {
                    for &d in &INDEX_LANE_DIMS {
                        let mut cells: Vec<u32> = block(corner, side)
                            .into_iter()
                            .flat_map(|p| (0..spp).map(move |k| (p, k)))
                            .map(|(p, k)| {
                                s.start_pixel_sample(p, k, d);
                                s.get_1d_word().checked_shr(32 - bits).unwrap_or(0)
                            })
                            .collect();
                        cells.sort_unstable();
                        cells.dedup();
                        assert_eq!(
                            cells.len(),
                            (spp << (2 * j)) as usize,
                            "{strategy:?} spp={spp} side={side} {corner:?} dimension {d}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn the_index_lane_word_leads_with_the_block_position() {
    for (index, m, want) in [
        (
            0b1011_0110u64,
            4u32,
            0x6000_0000u32 | (0b1011u32.reverse_bits() >> 4),
        ),
        (0b1011_0110, 0, 0b1011_0110u32.reverse_bits()),
        (0b10, 1, 1u32.reverse_bits() >> 1),
        (u64::MAX, 32, u32::MAX),
    ] {
        assert_eq!(index_lane_word(index, m), want, "{index:#b} m={m}");
    }
}

#[test]
fn morton_blocks_of_pixels_are_nets_of_the_four_sequence_lanes() {
    // Film offset and light position (lanes 0-3 of group 0): 16 spp in a
    // 2x2 quad is a (0,3,4)-net, in a 4x4 block a (0,4,4)-net; 4 spp in an
    // 8x8 block a (0,4,4)-net.
    for (spp, side, m) in [(16u32, 2u32, 3u32), (16, 4, 4), (4, 8, 4), (1, 4, 2)] {
        let mut s = sampler(spp);
        for corner in [[0, 0], [side, 0], [8, 8]] {
            let pts = points(&mut s, &block(corner, side), &[0, 1, 5, 6]);
            assert!(is_net(&pts, m, 2), "spp={spp} side={side} {corner:?}");
        }
    }
    // A quad that is not Morton-aligned is not a net: the ordering matters.
    let mut s = sampler(16);
    let shifted = block([1, 0], 2);
    assert!(!is_net(&points(&mut s, &shifted, &[0, 1, 5, 6]), 3, 2));
}

#[test]
fn every_2d_value_is_a_binary_0m2_net_per_pixel() {
    for m in 0..=6u32 {
        let mut s = sampler(1 << m);
        for pixel in [[0, 0], [3, 6], [11, 2]] {
            for axes in PAIRS {
                let pts = points(&mut s, &[pixel], &axes);
                assert!(is_net(&pts, m, 1), "m={m} {pixel:?} {axes:?}");
            }
        }
    }
}

#[test]
fn any_spp_gives_distinct_boxes_of_the_enclosing_net() {
    for spp in [3u32, 5, 12, 24] {
        let m = crate::pixel::ceil_log2(u64::from(spp));
        let mut s = sampler(spp);
        for axes in PAIRS {
            let pts = points(&mut s, &[[4, 4]], &axes);
            assert_eq!(pts.len(), spp as usize);
            for b in shapes(m, 2) {
                assert!(stratified(&pts, &b), "spp={spp} {axes:?} {b:?}");
            }
        }
    }
}

#[test]
fn unscrambled_values_are_the_sequence_at_the_permuted_index() {
    let mut s = ZOrderSzSampler::new(16, [8, 8], RandomizeStrategy::None, 3).unwrap();
    let w = sample_words(&mut s, [5, 2], 9);
    let film = s.order.sample_index(GROUP_KEY);
    let lens = s.order.sample_index(GROUP_KEY + 1);
    assert_eq!(
        [w[0], w[1]],
        [0, 1].map(|d| crate::sz::sample(film as u32, d))
    );
    assert_eq!(
        [w[5], w[6]],
        [2, 3].map(|d| crate::sz::sample(film as u32, d))
    );
    assert_eq!(w[4], index_lane_word(film, 4), "choice");
    assert_eq!(w[4] >> 28, (film as u32) & 15, "choice: block position");
    let pixel_digits = ((film >> 4) as u32).reverse_bits() >> 4;
    assert_eq!(w[4] & 0x0fff_ffff, pixel_digits, "choice: pixel digits");
    assert_eq!(
        [w[2], w[3]],
        [0, 1].map(|d| crate::sz::sample(lens as u32, d))
    );
    assert_eq!(
        [w[8], w[9]],
        [2, 3].map(|d| crate::sz::sample(lens as u32, d))
    );
    assert_eq!(w[7], index_lane_word(lens, 4), "lobe");
    assert_eq!(w[7] >> 28, (lens as u32) & 15, "lobe: block position");
}

#[test]
fn values_depend_only_on_pixel_sample_dimension_and_seed() {
    let mut a = sampler(16);
    let mut b = a.clone();
    let forward: Vec<_> = (0..16).map(|k| sample_words(&mut a, [2, 5], k)).collect();
    sample_words(&mut b, [9, 1], 3);
    for k in (0..16).rev() {
        b.start_pixel_sample([2, 5], k, 3);
        let light = b.get_2d_words();
        assert_eq!(light, [forward[k as usize][5], forward[k as usize][6]]);
        assert_eq!(sample_words(&mut b, [2, 5], k), forward[k as usize]);
    }
    let mut other = ZOrderSzSampler::new(16, [16, 16], RandomizeStrategy::FastOwen, 8).unwrap();
    assert_ne!(
        sample_words(&mut other, [2, 5], 0),
        forward[0],
        "the seed is used"
    );
}
