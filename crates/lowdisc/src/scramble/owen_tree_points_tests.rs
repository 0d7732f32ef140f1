//! Tests of [`OwenTreePoints`]: both kernels give [`OwenTreeKey`]'s values
//! bit for bit, for every digit count, dimension count and seed.

use super::*;
use crate::hash::mix64;
use alloc::vec;

/// `n` points of `d` pseudo-random words, with the extreme words mixed in.
fn points(salt: u64, n: usize, d: usize) -> Vec<u32> {
    let edge = [0, u32::MAX, 1 << 31, 0x3fff_ffff, 0xffff_fffc, 1];
    (0..(n * d) as u64)
        .map(|k| match k % 97 {
            r @ 0..=5 => edge[r as usize],
            _ => (mix64(k ^ salt.rotate_left(23)) >> 13) as u32,
        })
        .collect()
}

/// The words of `input` scrambled one at a time by each dimension's key.
fn one_by_one(seed: u64, d: usize, input: &[u32], digits: u32) -> Vec<u32> {
    let keys: Vec<_> = (0..d as u32).map(|j| OwenTreeKey::new(seed, j)).collect();
    input
        .iter()
        .enumerate()
        .map(|(i, &w)| keys[i % d].scramble_digits(w, digits))
        .collect()
}

#[test]
fn every_kernel_equals_the_key_of_each_dimension() {
    let cases = [
        (0u64, 1usize),
        (1, 3),
        (7, 8),
        (u64::MAX, 13),
        (12345, 64),
        (99, 70),
    ];
    for (seed, d) in cases {
        let input = points(seed ^ d as u64, 300, d);
        let kernels = [
            OwenTreePoints::new(seed, d as u32),
            OwenTreePoints::portable(seed, d as u32),
            // The 64-entry tables (as beyond 1024 dimensions).
            OwenTreePoints::from_keys(
                (0..d as u32)
                    .map(|j| OwenTreePoints::portable_key(seed, j, 2000))
                    .collect(),
            ),
        ];
        for digits in 1..=32 {
            let want = one_by_one(seed, d, &input, digits);
            for kernel in &kernels {
                let mut got = input.clone();
                kernel.scramble_points(&mut got, digits);
                let vectorised = kernel.is_vectorised();
                assert_eq!(
                    got, want,
                    "seed {seed} d {d} digits {digits} vector {vectorised}"
                );
            }
        }
    }
}

#[test]
fn many_seeds_and_dimensions_agree_at_30_and_32_digits() {
    // Dimensions up to 1100: past the portable kernel's switch to the small
    // table, and layer keys of far dimensions.
    let d = 1100;
    for seed in [3u64, 1 << 40, 0x5eed] {
        let input = points(seed, 20, d);
        for digits in [30, 32] {
            let mut got = input.clone();
            OwenTreePoints::new(seed, d as u32).scramble_points(&mut got, digits);
            assert_eq!(got, one_by_one(seed, d, &input, digits), "seed {seed}");
        }
    }
}

#[test]
fn a_partial_trailing_point_is_left_alone() {
    let keys = OwenTreePoints::new(5, 4);
    assert_eq!(keys.dimensions(), 4);
    let mut words = vec![0x1234_5678u32; 10];
    keys.scramble_points(&mut words, 32);
    assert_eq!(&words[8..], &[0x1234_5678, 0x1234_5678]);
    assert_ne!(&words[..4], &[0x1234_5678; 4]);
    let mut none = vec![9u32; 3];
    keys.scramble_points(&mut none, 32);
    assert_eq!(none, [9, 9, 9]);
}

#[test]
fn the_vector_kernel_runs_where_the_cpu_has_it() {
    #[cfg(all(target_arch = "x86_64", lowdisc_avx512))]
    let expected = std::arch::is_x86_feature_detected!("avx512f")
        && std::arch::is_x86_feature_detected!("avx512dq")
        && std::arch::is_x86_feature_detected!("avx512bw")
        && std::arch::is_x86_feature_detected!("avx512vl")
        && std::arch::is_x86_feature_detected!("avx512vbmi")
        && std::arch::is_x86_feature_detected!("avx512bitalg");
    #[cfg(not(all(target_arch = "x86_64", lowdisc_avx512)))]
    let expected = false;
    assert_eq!(OwenTreePoints::new(1, 9).is_vectorised(), expected);
    assert_eq!(OwenTreePoints::vector_kernel_available(), expected);
    assert!(!OwenTreePoints::portable(1, 9).is_vectorised());
}
