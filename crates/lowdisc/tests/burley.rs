//! Burley 2020's samplers: agreement with the `sobol_burley` crate, nets
//! within each 4-D group, padding between groups, and the per-pixel digital
//! shift.

#[path = "common/net.rs"]
mod net;

use lowdisc::hash::mix64;
use lowdisc::pixel::{
    BurleySampler, NestedHash, PixelXorSampler, WordSampler, burley_word, seed_hash,
};
use lowdisc::scramble::fast_owen_key;
use net::is_net;

/// `sobol_burley`'s float of a digit word (23 bits).
fn burley_float(word: u32) -> f32 {
    f32::from_bits((word >> 9) | 0x3f80_0000) - 1.0
}

#[test]
fn burley_word_is_sobol_burleys_sample_for_strong_keys() {
    let mut state = 0xb0b_u64;
    let mut compared = 0;
    for _ in 0..4000 {
        state = mix64(state.wrapping_add(1));
        let seed = state as u32;
        let dim = (state >> 32) as u32 % sobol_burley::NUM_DIMENSIONS;
        let index = (state >> 48) as u32;
        let shuffle = seed_hash(seed ^ 0x79c6_8e4a);
        let lane = (dim >> 2)
            ^ seed.wrapping_mul(0x9c8f_2d3b)
            ^ [0x912f_69ba, 0x174f_18ab, 0x691e_72ca, 0xb40c_c1b8][dim as usize & 3];
        let strong = |k: u32| fast_owen_key(k) == k;
        if !(strong(shuffle) && strong(seed_hash(lane))) {
            continue;
        }
        compared += 1;
        let word = burley_word(index, dim, seed, NestedHash::Vegdahl);
        let want = sobol_burley::sample(index, dim, seed);
        assert_eq!(
            burley_float(word),
            want,
            "index {index} dim {dim} seed {seed:#x}"
        );
    }
    // About 0.91^2 of the cases have two strong keys.
    assert!(compared > 3000, "{compared}");
}

/// The words of virtual dimensions `v..v + 2` of every sample of `pixel`.
fn pairs(s: &mut impl WordSampler, pixel: [u32; 2], v: u32) -> Vec<[u32; 2]> {
    (0..s.samples_per_pixel())
        .map(|i| {
            if v == 0 {
                s.start_pixel_sample(pixel, i, 0);
                s.get_pixel_2d_words()
            } else {
                s.start_pixel_sample(pixel, i, v - 2);
                s.get_2d_words()
            }
        })
        .collect()
}

#[test]
fn lanes_0_1_of_every_group_form_nets() {
    for hash in [NestedHash::Vegdahl, NestedHash::LaineKarras] {
        for m in [0u32, 1, 2, 3, 4, 6, 8] {
            let mut s = BurleySampler::new(1 << m, hash, 5).unwrap();
            for pixel in [[0, 0], [3, 9], [100, 7]] {
                // Groups 0 (the in-pixel offset), 1 and 5.
                for v in [0, 4, 20] {
                    let set = pairs(&mut s, pixel, v);
                    assert!(is_net(&set, m), "{hash:?} m {m} {pixel:?} v {v}");
                }
            }
        }
    }
}

/// Occupied cells of a 4x4 grid by the 16 points `(a[i], b[i])`.
fn occupied_4x4(a: &[u32], b: &[u32]) -> usize {
    let mut cells = [false; 16];
    for (&x, &y) in a.iter().zip(b) {
        cells[((x >> 30) * 4 + (y >> 30)) as usize] = true;
    }
    cells.iter().filter(|&&c| c).count()
}

#[test]
fn padding_gives_each_group_its_own_sample_order() {
    // Lane 0 of group 0 (offset x) and of group 1 (sampler dimension 2)
    // are both Sobol dimension 0. Under one shuffle their quarter strata
    // would be in bijection (4 occupied cells of a 4x4 grid, as the
    // control shows); padded, the 16 pairs fall like independent points
    // (about 10.3 cells expected).
    let mut s = BurleySampler::new(16, NestedHash::Vegdahl, 2).unwrap();
    let mut total = 0;
    let pixels = 64;
    for p in 0..pixels {
        let pixel = [p % 8, p / 8];
        let g0: Vec<u32> = pairs(&mut s, pixel, 0).iter().map(|w| w[0]).collect();
        let g1: Vec<u32> = pairs(&mut s, pixel, 4).iter().map(|w| w[0]).collect();
        total += occupied_4x4(&g0, &g1);
        assert_eq!(occupied_4x4(&g0, &g0), 4, "control: one order");
    }
    let mean = total as f64 / f64::from(pixels);
    assert!(mean > 9.0, "mean occupied cells {mean}");
}

#[test]
fn pixel_xor_pixels_share_one_sequence_under_different_shifts() {
    let mut s = PixelXorSampler::new(8, 3).unwrap();
    for v in [0u32, 2, 6] {
        let a = pairs(&mut s, [0, 0], v);
        let b = pairs(&mut s, [5, 2], v);
        let shift = [a[0][0] ^ b[0][0], a[0][1] ^ b[0][1]];
        assert_ne!(shift, [0, 0]);
        for (x, y) in a.iter().zip(&b) {
            assert_eq!([x[0] ^ y[0], x[1] ^ y[1]], shift, "v {v}");
        }
    }
    // Sobol dimensions 0-1 (the offset) form a net; 2-3 do not at m = 3
    // (their pair has t > 0), which is why Burley pads by lanes 0-3.
    let offsets = pairs(&mut s, [4, 4], 0);
    assert!(is_net(&offsets, 3));
    assert!(!is_net(&pairs(&mut s, [4, 4], 2), 3));
}

#[test]
fn any_sample_count_gives_values_and_too_many_are_refused() {
    for spp in [1u32, 3, 5, 100] {
        for hash in [NestedHash::Vegdahl, NestedHash::LaineKarras] {
            let mut s = BurleySampler::new(spp, hash, 1).unwrap();
            let mut x = PixelXorSampler::new(spp, 1).unwrap();
            for i in 0..spp + 2 {
                s.start_pixel_sample([1, 2], i, 0);
                x.start_pixel_sample([1, 2], i, 0);
                let _ = (s.get_2d_words(), s.get_1d_word(), x.get_2d_words());
            }
        }
    }
    assert!(BurleySampler::new(1 << 16, NestedHash::Vegdahl, 0).is_ok());
    assert!(BurleySampler::new((1 << 16) + 1, NestedHash::Vegdahl, 0).is_err());
    assert!(BurleySampler::new(0, NestedHash::Vegdahl, 0).is_err());
}
