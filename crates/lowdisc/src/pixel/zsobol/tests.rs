//! Tests of [`ZSobolSampler`]: the cached paths (words and floats) against
//! the definition, and the index map's structure.

use super::*;
use crate::hash::mix64;

#[test]
fn the_table_holds_all_24_distinct_permutations() {
    for (i, p) in BASE4_PERMUTATIONS.iter().enumerate() {
        let mut sorted = *p;
        sorted.sort_unstable();
        assert_eq!(sorted, [0, 1, 2, 3]);
        assert!(BASE4_PERMUTATIONS[..i].iter().all(|q| q != p));
    }
    assert_eq!(BASE4_PERMUTATIONS[0], [0, 1, 2, 3]);
    assert_eq!(BASE4_PERMUTATIONS[23], [3, 2, 1, 0]);
}

#[test]
fn morton_interleaves_x_low() {
    assert_eq!(morton2(1, 0), 1);
    assert_eq!(morton2(0, 1), 2);
    assert_eq!(morton2(3, 5), 0b10_01_11);
    assert_eq!(morton2(u32::MAX, u32::MAX), u64::MAX);
}

#[test]
fn the_cached_path_equals_the_definition() {
    // (spp, resolution): even and odd m, spp not a power of two, more
    // than 32 index bits (high bits in the seed), m above the table.
    let configs = [
        (16u32, [640u32, 360u32]),
        (1, [7, 5]),
        (2, [3, 3]),
        (5, [33, 17]),
        (8, [1 << 15, 3]),
        (3, [1 << 16, 1 << 16]),
        (1 << 12, [64, 64]),
        (2048, [1, 1]),
        // The fast path (even m up to 8), with more than 32 index bits.
        (256, [32, 32]),
        (64, [1 << 13, 1 << 13]),
        (4, [1 << 20, 7]),
    ];
    let mut state = 0x2545_f491_4f6c_dd1du64;
    for (spp, res) in configs {
        for r in RandomizeStrategy::ALL {
            let Ok(mut s) = ZSobolSampler::new(spp, res, r, 11) else {
                assert!(r == RandomizeStrategy::None);
                continue;
            };
            for visit in 0..160u32 {
                state = mix64(state.wrapping_add(u64::from(visit)));
                // Runs of samples of one pixel, jumps between pixels,
                // then a raster scan (neighbours share high digits).
                let pixel = match visit.checked_sub(120) {
                    None => [
                        (state as u32) % (res[0] + 3),
                        ((state >> 20) as u32) % res[1],
                    ],
                    Some(k) => [k % 7, k / 7 % res[1]],
                };
                let start = if visit % 3 == 0 {
                    1020
                } else {
                    (state >> 50) as u32 % 4
                };
                for k in 0..(1 + (state >> 40) as u32 % 4) {
                    s.start_pixel_sample(pixel, (state >> 8) as u32 % spp + k, start);
                    assert_eq!(s.get_pixel_2d_words(), s.direct_words::<2>(PIXEL_KEY));
                    for _ in 0..4 {
                        let key = u64::from(s.dimension);
                        let want1 = s.direct_words::<1>(key);
                        assert_eq!([s.get_1d_word()], want1, "{spp} {res:?} {r:?}");
                        let key = u64::from(s.dimension);
                        let want2 = s.direct_words::<2>(key);
                        assert_eq!(s.get_2d_words(), want2, "{spp} {res:?} {r:?}");
                    }
                    // The floats, which the fast path reads from the
                    // reversed hash, are `to_f32` of the same words.
                    let want = s.direct_words::<2>(PIXEL_KEY).map(to_f32);
                    assert_eq!(s.get_pixel_2d_values(), want);
                    for _ in 0..4 {
                        let key = u64::from(s.dimension);
                        let want1 = s.direct_words::<1>(key).map(to_f32);
                        assert_eq!([s.get_1d_value()], want1, "{spp} {res:?} {r:?}");
                        let key = u64::from(s.dimension);
                        let want2 = s.direct_words::<2>(key).map(to_f32);
                        assert_eq!(s.get_2d_values(), want2, "{spp} {res:?} {r:?}");
                    }
                }
            }
        }
    }
}

#[test]
fn the_index_map_is_a_bijection_preserving_pixel_blocks() {
    for spp in [1u32, 2, 4, 8, 32] {
        let mut s = ZSobolSampler::new(spp, [8, 8], RandomizeStrategy::None, 3).unwrap();
        let m = s.log2_spp;
        let total = 64usize << m;
        let mut seen = alloc::vec![false; total];
        for y in 0..8 {
            for x in 0..8 {
                let mut block = None;
                for k in 0..spp {
                    s.start_pixel_sample([x, y], k, 0);
                    let i = s.sample_index(5);
                    assert!(!seen[i as usize]);
                    seen[i as usize] = true;
                    let b = i >> m;
                    assert!(block.is_none_or(|c| c == b), "pixel block split");
                    block = Some(b);
                }
            }
        }
        assert!(seen.iter().all(|&v| v));
    }
}

#[test]
fn get_values_equals_the_calls_in_order() {
    use crate::pixel::{Dims, PixelSampler};
    let dims = [Dims::One, Dims::Two, Dims::One, Dims::Two, Dims::One];
    // The fast path (spp 256, 16), a general one (spp 5), uncached keys.
    for (spp, res) in [(256u32, [32u32, 32u32]), (16, [64, 48]), (5, [9, 9])] {
        let mut together = ZSobolSampler::new(spp, res, RandomizeStrategy::FastOwen, 3).unwrap();
        let mut one_by_one = together.clone();
        for visit in 0..60u32 {
            let pixel = [visit / 3 % res[0], visit / 11 % res[1]];
            let start = [0, 2, 9, 1020][visit as usize % 4];
            for s in 0..spp.min(9) {
                PixelSampler::start_pixel_sample(&mut together, pixel, s, start);
                PixelSampler::start_pixel_sample(&mut one_by_one, pixel, s, start);
                for _ in 0..3 {
                    let got = PixelSampler::get_values(&mut together, dims);
                    let want = dims.map(|d| match d {
                        Dims::One => [one_by_one.get_1d(), 0.0],
                        Dims::Two => one_by_one.get_2d(),
                    });
                    assert_eq!(got, want, "{spp} {pixel:?} {s} {start}");
                    assert_eq!(together.dimension, one_by_one.dimension);
                }
            }
        }
    }
}
