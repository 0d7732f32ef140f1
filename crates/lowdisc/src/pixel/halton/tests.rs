//! Tests of the global image-plane Halton sampler.

use super::*;
use alloc::vec::Vec;

/// The pixel a global index falls in, read from its digits: the first `j`
/// binary digits of `i` mirrored (column) and the first `k` ternary digits
/// mirrored (row), written independently of the library.
fn pixel_of(index: u64, exponents: [u32; 2]) -> [u64; 2] {
    let mirrored = |base: u64, n: u32| {
        let (mut rest, mut v) = (index, 0u64);
        for _ in 0..n {
            v = v * base + rest % base;
            rest /= base;
        }
        v
    };
    [mirrored(2, exponents[0]), mirrored(3, exponents[1])]
}

const ALL: [HaltonRandomize; 4] = HaltonRandomize::ALL;

#[test]
fn inverses_and_crt() {
    for n in 2..200u64 {
        for a in 1..n {
            if (1..=a).filter(|d| a % d == 0 && n % d == 0).count() == 1 {
                assert_eq!(a * multiplicative_inverse(a, n) % n, 1, "{a} mod {n}");
            }
        }
    }
    assert_eq!(multiplicative_inverse(5, 1), 0);
    for (m0, m1) in [(8u64, 9u64), (128, 243), (1, 9), (8, 1), (1, 1)] {
        let mut seen = alloc::vec![false; (m0 * m1) as usize];
        for r0 in 0..m0 {
            for r1 in 0..m1 {
                let h = crt(r0, m0, r1, m1);
                assert!(h < m0 * m1 && h % m0 == r0 && h % m1 == r1);
                assert!(!seen[h as usize]);
                seen[h as usize] = true;
            }
        }
    }
}

#[test]
fn bad_configurations_are_errors() {
    let r = HaltonRandomize::None;
    assert!(matches!(
        HaltonSampler::new(0, [4, 4], r, 0),
        Err(Error::InvalidSampleCount { .. })
    ));
    assert!(matches!(
        HaltonSampler::new(4, [0, 4], r, 0),
        Err(Error::InvalidResolution { .. })
    ));
    assert!(matches!(
        HaltonSampler::new(4, [4, 0], r, 0),
        Err(Error::InvalidResolution { .. })
    ));
    let s = HaltonSampler::new(u32::MAX, [u32::MAX, u32::MAX], r, 0).unwrap();
    assert_eq!(s.scales(), [128, 243]);
    assert_eq!(s.exponents(), [7, 5]);
    assert_eq!(
        HaltonSampler::new(1, [6, 4], r, 0).unwrap().scales(),
        [8, 9]
    );
    assert_eq!(
        HaltonSampler::new(1, [1, 1], r, 0).unwrap().scales(),
        [1, 1]
    );
}

/// Every sample of every pixel lies in that pixel (modulo the tile), for
/// each randomization, and the pixel offset is in [0, 1)^2.
fn assert_samples_land_in_their_pixels(resolution: [u32; 2], spp: u32, pixels: &[[u32; 2]]) {
    for randomize in ALL {
        let mut s = HaltonSampler::new(spp, resolution, randomize, 3).unwrap();
        let [s0, s1] = s.scales();
        for &p in pixels {
            for i in 0..spp {
                let index = s.global_index(p, i);
                let want = [u64::from(p[0]) % s0, u64::from(p[1]) % s1];
                assert_eq!(
                    pixel_of(index, s.exponents()),
                    want,
                    "pixel {p:?}, sample {i}"
                );
                s.start_pixel_sample(p, i, 0);
                let offset = s.get_pixel_2d();
                assert!(offset.iter().all(|v| (0.0..1.0).contains(v)), "{offset:?}");
                let film = [want[0] as f32 + offset[0], want[1] as f32 + offset[1]];
                assert_eq!([film[0].floor() as u64, film[1].floor() as u64], want);
            }
        }
    }
}

#[test]
fn samples_land_in_their_pixels_6x4() {
    let pixels: Vec<[u32; 2]> = (0..4).flat_map(|y| (0..6).map(move |x| [x, y])).collect();
    assert_samples_land_in_their_pixels([6, 4], 16, &pixels);
}

#[test]
fn samples_land_in_their_pixels_128x128() {
    let pixels: Vec<[u32; 2]> = (0..128)
        .flat_map(|y| (0..128).map(move |x| [x, y]))
        .collect();
    assert_samples_land_in_their_pixels([128, 128], 2, &pixels);
}

#[test]
fn samples_land_in_their_tile_pixels_on_large_images() {
    let pixels = [[0u32, 0], [127, 242], [128, 243], [200, 150], [1919, 1079]];
    assert_samples_land_in_their_pixels([1920, 1080], 4, &pixels);
}

/// On an image exactly one tile large, the samples of all pixels are exactly
/// the first `width * height * spp` points, each used once.
#[test]
fn one_tile_uses_exactly_the_first_indices() {
    let (w, h, spp) = (8u32, 9u32, 4u32);
    let s = HaltonSampler::new(spp, [w, h], HaltonRandomize::None, 0).unwrap();
    let mut indices: Vec<u64> = (0..h)
        .flat_map(|y| (0..w).flat_map(move |x| (0..spp).map(move |i| ([x, y], i))))
        .map(|(p, i)| s.global_index(p, i))
        .collect();
    indices.sort_unstable();
    assert_eq!(indices, (0..u64::from(w * h * spp)).collect::<Vec<_>>());
    // The 6x4 image sits in the same 8x9 tile: distinct residues.
    let s = HaltonSampler::new(1, [6, 4], HaltonRandomize::None, 0).unwrap();
    let mut small: Vec<u64> = (0..4)
        .flat_map(|y| (0..6).map(move |x| [x, y]))
        .map(|p| s.global_index(p, 0))
        .collect();
    small.sort_unstable();
    small.dedup();
    assert_eq!(small.len(), 24);
    assert!(small.iter().all(|&i| i < 72));
}

/// Unscrambled, pixel + offset is the global Halton point scaled to the tile.
#[test]
fn unscrambled_offset_completes_the_global_point() {
    let mut s = HaltonSampler::new(8, [6, 4], HaltonRandomize::None, 0).unwrap();
    let [s0, s1] = s.scales();
    for p in [[0u32, 0], [5, 3], [2, 1]] {
        for i in 0..8 {
            s.start_pixel_sample(p, i, 0);
            let offset = s.get_pixel_2d();
            let index = s.global_index(p, i);
            let to_unit = |f: u64| f as f64 / 18_446_744_073_709_551_616.0;
            let h = Halton::new(HaltonRandomize::None, 0);
            let x = to_unit(h.sample_fixed64(index, 0)) * s0 as f64;
            let y = to_unit(h.sample_fixed64(index, 1)) * s1 as f64;
            assert!((x - (f64::from(p[0]) + f64::from(offset[0]))).abs() < 1e-5);
            assert!((y - (f64::from(p[1]) + f64::from(offset[1]))).abs() < 1e-5);
        }
    }
}

#[test]
fn sample_dimensions_start_at_two_and_wrap() {
    let mut s = HaltonSampler::new(4, [6, 4], HaltonRandomize::Owen, 8).unwrap();
    s.start_pixel_sample([1, 1], 2, 0);
    let index = s.global_index([1, 1], 2);
    let h = s.halton().clone();
    assert_eq!(s.get_1d(), crate::to_f32(h.sample_word(index, 2)));
    assert_eq!(
        s.get_2d(),
        [3, 4].map(|d| crate::to_f32(h.sample_word(index, d)))
    );
    s.get_pixel_2d();
    assert_eq!(s.get_1d(), crate::to_f32(h.sample_word(index, 5)));
    s.start_pixel_sample([1, 1], 2, NUM_DIMENSIONS - 1);
    assert_eq!(
        s.get_1d(),
        crate::to_f32(h.sample_word(index, NUM_DIMENSIONS - 1))
    );
    assert_eq!(s.get_1d(), crate::to_f32(h.sample_word(index, 2)));
    s.start_pixel_sample([1, 1], 2, u32::MAX);
    assert_eq!(
        s.get_2d(),
        [2, 3].map(|d| crate::to_f32(h.sample_word(index, d)))
    );
}

#[test]
fn values_do_not_depend_on_call_order() {
    for randomize in ALL {
        let mut s = HaltonSampler::new(4, [5, 5], randomize, 1).unwrap();
        let mut record = |p: [u32; 2], i: u32| -> Vec<f32> {
            s.start_pixel_sample(p, i, 0);
            let mut v = s.get_pixel_2d().to_vec();
            v.push(s.get_1d());
            v.extend(s.get_2d());
            v
        };
        let order: Vec<([u32; 2], u32)> = (0..5)
            .flat_map(|x| (0..4).map(move |i| ([x, 4 - x], i)))
            .collect();
        let forward: Vec<Vec<f32>> = order.iter().map(|&(p, i)| record(p, i)).collect();
        let mut backward: Vec<Vec<f32>> = order.iter().rev().map(|&(p, i)| record(p, i)).collect();
        backward.reverse();
        assert_eq!(forward, backward, "{randomize:?}");
    }
}

#[test]
fn pinned_values() {
    let got: Vec<Vec<u32>> = ALL
        .iter()
        .map(|&randomize| {
            let mut s = HaltonSampler::new(16, [6, 4], randomize, 42).unwrap();
            s.start_pixel_sample([1, 2], 3, 0);
            let mut v = s.get_pixel_2d().to_vec();
            v.push(s.get_1d());
            v.extend(s.get_2d());
            v.iter().map(|x| x.to_bits()).collect()
        })
        .collect();
    assert_eq!(got, PINNED);
}

/// Row 0 (unscrambled) checked independently: pixel (1, 2), sample 3 of a
/// 6x4 image is global index 276; offsets are the radical inverses of
/// 276 >> 3 = 34 (base 2) and 276 / 9 = 30 (base 3), then 276 in bases 5, 7, 11.
/// Rows follow `HaltonRandomize::ALL`: none, permute, Owen, nested affine
/// (the values Owen had when it meant the affine maps; bases 2 and 3, the
/// pixel offsets, agree between the two).
const PINNED: [[u32; 5]; 4] = [
    [1049100288, 1039980264, 1045972176, 1057380369, 1039141176],
    [1056987166, 1031301616, 1056600066, 1056533762, 1057980611],
    [1042646444, 1035205264, 1042815816, 1057768331, 1024022384],
    [1042646444, 1035205264, 1060301871, 1063539154, 1062121781],
];
