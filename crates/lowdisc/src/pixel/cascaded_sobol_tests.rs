//! Structural tests of [`CascadedSobolSampler`]: the nets the cascade
//! promises in every consecutive pair of a pixel's samples.

use super::*;
use crate::net_check::{is_net, shapes, stratified, t_value};
use alloc::vec::Vec;

/// Chain positions checked: the offset and the first 60 sampler dimensions.
const POSITIONS: usize = 62;

fn sampler(spp: u32) -> CascadedSobolSampler {
    CascadedSobolSampler::new(spp, RandomizeStrategy::FastOwen, 7).unwrap()
}

/// Chain positions `0..POSITIONS` of sample `k` of `pixel`, drawn as the
/// path tracer draws them (the offset, then 1-D and 2-D values in turn).
fn chain(s: &mut CascadedSobolSampler, pixel: [u32; 2], k: u32) -> Vec<u32> {
    s.start_pixel_sample(pixel, k, 0);
    let mut words = s.get_pixel_2d_words().to_vec();
    while words.len() < POSITIONS {
        if words.len() % 3 == 0 {
            words.push(s.get_1d_word());
        } else {
            words.extend(s.get_2d_words());
        }
    }
    words.truncate(POSITIONS);
    words
}

/// The chains of every sample of `pixel`.
fn pixel_chains(s: &mut CascadedSobolSampler, pixel: [u32; 2]) -> Vec<Vec<u32>> {
    (0..s.samples_per_pixel())
        .map(|k| chain(s, pixel, k))
        .collect()
}

fn project(chains: &[Vec<u32>], axes: &[usize]) -> Vec<Vec<u32>> {
    chains
        .iter()
        .map(|c| axes.iter().map(|&a| c[a]).collect())
        .collect()
}

#[test]
fn every_consecutive_pair_of_a_pixel_is_a_0m2_net() {
    for m in [0u32, 1, 2, 3, 4, 5, 6, 8] {
        let mut s = sampler(1 << m);
        for pixel in [[0, 0], [5, 3], [1000, 77]] {
            let chains = pixel_chains(&mut s, pixel);
            for c in 0..POSITIONS - 1 {
                let pair = project(&chains, &[c, c + 1]);
                assert!(
                    is_net(&pair, m, 1),
                    "m={m} {pixel:?} positions {c}, {}",
                    c + 1
                );
            }
        }
    }
}

#[test]
fn every_dimension_is_stratified_and_every_strategy_keeps_the_nets() {
    for strategy in RandomizeStrategy::ALL {
        for m in [3u32, 4, 7] {
            let mut s = CascadedSobolSampler::new(1 << m, strategy, 3).unwrap();
            let chains = pixel_chains(&mut s, [2, 9]);
            for c in 0..POSITIONS - 1 {
                assert!(
                    is_net(&project(&chains, &[c]), m, 1),
                    "{strategy:?} m={m} {c}"
                );
                let pair = project(&chains, &[c, c + 1]);
                assert!(is_net(&pair, m, 1), "{strategy:?} m={m} {c}");
            }
        }
    }
}

#[test]
fn the_nets_are_the_cascade_not_luck() {
    // Non-consecutive pairs are independent scrambles: over a few pixels at
    // least one of them is not a (0,m,2)-net, so the test above can fail.
    let m = 6;
    let mut s = sampler(1 << m);
    let mut worst = 0;
    for pixel in [[0, 0], [1, 0], [2, 0]] {
        let chains = pixel_chains(&mut s, pixel);
        for c in 0..20 {
            worst = worst.max(t_value(&project(&chains, &[c, c + 2]), m));
        }
    }
    assert!(worst > 0);
}

#[test]
fn unscrambled_values_follow_the_published_cascade() {
    // The definition written out: van der Corput of the sample index, then
    // Sobol dimension 1 of the radical inverse of the previous value.
    let m = 5;
    let mut s = CascadedSobolSampler::new(1 << m, RandomizeStrategy::None, 0).unwrap();
    for k in [0u32, 1, 6, 31] {
        let got = chain(&mut s, [4, 4], k);
        let mut want = Vec::new();
        let mut index = k;
        for c in 0..POSITIONS as u32 {
            let word = if c == 0 {
                index.reverse_bits()
            } else {
                sample(index, 1)
            };
            want.push(word);
            index = (word >> (32 - m)).reverse_bits() >> (32 - m);
        }
        assert_eq!(got, want, "sample {k}");
        // Unscrambled, an index of m bits gives m digits.
        assert!(got.iter().all(|w| w & low_mask(32 - m) == 0));
    }
}

#[test]
fn any_spp_gives_distinct_boxes_of_the_enclosing_net() {
    for spp in [3u32, 5, 12, 24] {
        let m = crate::pixel::ceil_log2(u64::from(spp));
        let mut s = sampler(spp);
        let chains = pixel_chains(&mut s, [4, 4]);
        assert_eq!(chains.len(), spp as usize);
        for c in 0..POSITIONS - 1 {
            let pair = project(&chains, &[c, c + 1]);
            for b in shapes(m, 2) {
                assert!(stratified(&pair, &b), "spp={spp} {c} {b:?}");
            }
        }
    }
}

#[test]
fn values_depend_only_on_pixel_sample_and_dimension() {
    let mut a = sampler(16);
    let forward: Vec<Vec<u32>> = pixel_chains(&mut a, [2, 5]);
    let mut b = sampler(16);
    pixel_chains(&mut b, [9, 1]);
    for k in (0..16).rev() {
        // Started cold at dimension 7 (position 9), then the offset.
        b.start_pixel_sample([2, 5], k, 7);
        let pair = b.get_2d_words();
        assert_eq!(pair.to_vec(), forward[k as usize][9..11]);
        b.start_pixel_sample([2, 5], k + 16, 0);
        assert_eq!(b.get_pixel_2d_words().to_vec(), forward[k as usize][..2]);
    }
    let mut other = CascadedSobolSampler::new(16, RandomizeStrategy::FastOwen, 8).unwrap();
    assert_ne!(
        pixel_chains(&mut other, [2, 5]),
        forward,
        "the seed is used"
    );
    assert_ne!(pixel_chains(&mut a, [3, 5]), forward, "pixels differ");
}

#[test]
fn chains_restart_and_far_dimensions_are_reachable() {
    let length = CHAIN_LENGTH as u32;
    let mut s = sampler(8);
    let far = |s: &mut CascadedSobolSampler, k: u32, d: u32| {
        s.start_pixel_sample([1, 1], k, d);
        s.get_1d_word()
    };
    // Position CHAIN_LENGTH (dimension CHAIN_LENGTH - 2) starts a new chain:
    // its values are a scrambled van der Corput of the sample indices, and
    // the pairs of that chain are nets again.
    let restart: Vec<Vec<u32>> = (0..8)
        .map(|k| {
            s.start_pixel_sample([1, 1], k, length - 2);
            [s.get_1d_word(), s.get_1d_word()].to_vec()
        })
        .collect();
    assert!(is_net(&restart, 3, 1));
    // Stepping there in order gives the same words as starting cold.
    s.start_pixel_sample([1, 1], 5, 0);
    let walked: Vec<u32> = (0..length + 3).map(|_| s.get_1d_word()).collect();
    assert_eq!(walked[(length - 2) as usize..][..2], restart[5][..]);
    assert_eq!(walked[(length + 2) as usize], far(&mut s, 5, length + 2));
    // The last dimension is reachable (one chain's worth of steps).
    let last = far(&mut s, 5, u32::MAX);
    assert_eq!(far(&mut s, 5, u32::MAX), last);
}

#[test]
fn bad_sample_counts_are_errors() {
    assert!(CascadedSobolSampler::new(0, RandomizeStrategy::FastOwen, 0).is_err());
    assert!(CascadedSobolSampler::new((1 << 31) + 1, RandomizeStrategy::FastOwen, 0).is_err());
    assert!(CascadedSobolSampler::new(1 << 31, RandomizeStrategy::FastOwen, 0).is_ok());
}

#[test]
fn only_sobol_dimension_1_pairs_with_van_der_corput_as_a_02_sequence() {
    // Why every position uses the Pascal matrix: with van der Corput, Joe
    // and Kuo's dimension 1 gives (0,m,2)-nets for every m, the next 58
    // dimensions fail by m = 5.
    let pair = |d: u32, m: u32| -> Vec<Vec<u32>> {
        (0..1u32 << m)
            .map(|i| alloc::vec![sample(i, 0), sample(i, d)])
            .collect()
    };
    assert!((0..=12).all(|m| t_value(&pair(1, m), m) == 0));
    for d in 2..60 {
        assert!(
            (1..=5).any(|m| t_value(&pair(d, m), m) > 0),
            "dimension {d}"
        );
    }
}
