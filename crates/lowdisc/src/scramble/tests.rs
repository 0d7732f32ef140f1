//! Tests of the scrambles against their definitions and of the four-lane paths.

use super::*;

/// The definition of [`owen_scramble`], one full `hash3` per digit.
fn owen_reference(word: u32, seed: u32) -> u32 {
    let mut out = word;
    for b in 0..32u32 {
        let prefix = if b == 0 { 0 } else { word >> (32 - b) };
        let h = crate::hash::hash3(u64::from(seed), u64::from(b), u64::from(prefix));
        out ^= ((h >> 63) as u32) << (31 - b);
    }
    out
}

#[test]
fn owen_scrambles_equal_the_definition() {
    let mut state = 0x0fed_cba9_8765_4321u64;
    for _ in 0..3000 {
        state = mix64(state.wrapping_add(3));
        let (word, seed) = (state as u32, (state >> 32) as u32);
        let key = OwenKey::new(seed);
        for w in [word, 0, u32::MAX, word & 0xf000_0000] {
            let want = owen_reference(w, seed);
            assert_eq!(owen_scramble(w, seed), want);
            assert_eq!(key.scramble(w), want);
        }
    }
}

#[test]
fn apply_dimension_seed_equals_apply() {
    for seed in [0u64, 9, u64::MAX] {
        for r in RandomizeStrategy::ALL {
            for (dim, word) in [(0u32, 0u32), (1, 0x8000_0001), (77, 0xdead_beef)] {
                let s = dimension_seed(seed, dim);
                let want = r.apply(word, seed, dim);
                assert_eq!(r.apply_dimension_seed(word, s), want);
                let reversed = word.reverse_bits();
                assert_eq!(r.apply_key_reversed(reversed, r.scramble_key(s)), want);
            }
        }
    }
}

#[test]
fn four_lane_paths_equal_the_single_lane_ones() {
    let mut state = 0x0123_4567_89ab_cdefu64;
    for _ in 0..2000 {
        state = mix64(state.wrapping_add(1));
        let seed = state;
        let dim = (state >> 40) as u32 ^ if state & 1 == 0 { u32::MAX - 5 } else { 0 };
        let words: [u32; 4] = core::array::from_fn(|k| mix64(state ^ k as u64) as u32);
        let seeds = dimension_seeds_4(seed, dim);
        let fast = fast_owen_scramble_4(words, seeds);
        for (k, (&s, &f)) in seeds.iter().zip(&fast).enumerate() {
            assert_eq!(s, dimension_seed(seed, dim.wrapping_add(k as u32)));
            assert_eq!(f, fast_owen_scramble(words[k], s));
        }
        for r in RandomizeStrategy::ALL {
            let d = dim.min(u32::MAX - 3);
            let four = r.apply_4(words, seed, d);
            for (k, (&v, &w)) in four.iter().zip(&words).enumerate() {
                assert_eq!(v, r.apply(w, seed, d + k as u32));
            }
        }
    }
}
