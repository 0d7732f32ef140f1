//! Tests of the Sobol core: exact values, order conventions, net property.
use super::*;
use crate::RandomizeStrategy;

#[test]
fn first_points_are_the_textbook_values() {
    // Dimension 0 is van der Corput: 0, 1/2, 1/4, 3/4, 1/8, ...
    let vdc: [u32; 5] = core::array::from_fn(|i| sample(i as u32, 0));
    assert_eq!(vdc, [0, 0x8000_0000, 0x4000_0000, 0xc000_0000, 0x2000_0000]);
    // Dimension 1 (Joe-Kuo: s = 1, a = 0, m1 = 1): 0, 1/2, 3/4, 1/4, ...
    let d1: [u32; 4] = core::array::from_fn(|i| sample(i as u32, 1));
    assert_eq!(d1, [0, 0x8000_0000, 0xc000_0000, 0x4000_0000]);
    for dim in 0..NUM_DIMENSIONS as u32 {
        assert_eq!(sample(0, dim), 0);
        assert_eq!(sample(1, dim), 0x8000_0000);
    }
}

/// Checks that `points` (pairs of digit words) form a (0,m,2)-net in base 2:
/// for every split `m = a + b`, each box of `2^-a x 2^-b` holds exactly one point.
fn is_02_net(points: &[(u32, u32)], m: u32) -> bool {
    assert_eq!(points.len(), 1 << m);
    (0..=m).all(|a| {
        let b = m - a;
        let mut seen = alloc::vec![false; 1 << m];
        points.iter().all(|&(x, y)| {
            let cx = if a == 0 { 0 } else { (x >> (32 - a)) as usize };
            let cy = if b == 0 { 0 } else { (y >> (32 - b)) as usize };
            let cell = (cx << b) | cy;
            !core::mem::replace(&mut seen[cell], true)
        })
    })
}

/// Every strategy with a seed of its own.
fn strategies() -> [(RandomizeStrategy, u64); 5] {
    [
        (RandomizeStrategy::None, 0),
        (RandomizeStrategy::Xor, 11),
        (RandomizeStrategy::Owen, 12),
        (RandomizeStrategy::FastOwen, 13),
        (RandomizeStrategy::Lms, 14),
    ]
}

#[test]
fn dims_0_1_form_02_nets_under_every_randomization() {
    for (r, seed) in strategies() {
        for m in 0..=16u32 {
            let pts: alloc::vec::Vec<(u32, u32)> = (0..1u32 << m)
                .map(|i| {
                    let x = sample_randomized(i, 0, r, seed);
                    (x, sample_randomized(i, 1, r, seed))
                })
                .collect();
            assert!(
                is_02_net(&pts, m),
                "{r:?}: first 2^{m} points are not a (0,{m},2)-net"
            );
        }
    }
}

#[test]
fn net_check_detects_a_broken_net() {
    // Sanity check of the checker: a duplicated point breaks the net.
    let mut pts: alloc::vec::Vec<(u32, u32)> =
        (0..16u32).map(|i| (sample(i, 0), sample(i, 1))).collect();
    assert!(is_02_net(&pts, 4));
    pts[3] = pts[2];
    assert!(!is_02_net(&pts, 4));
}

#[test]
fn later_blocks_of_2m_points_are_nets_too() {
    // Sobol is a (t,s)-sequence: every aligned block of 2^m points is a net
    // (dims 0 and 1 have t = 0).
    for block in [1u32, 7, 1000] {
        let m = 10;
        let pts: alloc::vec::Vec<(u32, u32)> = (0..1u32 << m)
            .map(|i| {
                let k = (block << m) | i;
                (sample(k, 0), sample(k, 1))
            })
            .collect();
        assert!(is_02_net(&pts, m), "block {block}");
    }
}

#[test]
fn every_dimension_is_stratified_in_1d() {
    // Every generator matrix is non-singular, so each dimension's first 2^m
    // points take each m-digit prefix exactly once.
    let m = 8;
    for dim in (0..NUM_DIMENSIONS as u32)
        .step_by(97)
        .chain([NUM_DIMENSIONS as u32 - 1])
    {
        let mut seen = [false; 256];
        for i in 0..1u32 << m {
            let cell = (sample(i, dim) >> (32 - m)) as usize;
            assert!(!core::mem::replace(&mut seen[cell], true), "dim {dim}");
        }
    }
}

#[test]
fn matrices_are_upper_triangular_with_unit_diagonal() {
    for dim in 0..NUM_DIMENSIONS as u32 {
        for (c, &col) in matrix(dim).iter().enumerate() {
            // Column c has its lowest set bit on the diagonal (digit c, bit
            // 31 - c): digit c of point 2^c is 1 and later digits are 0.
            assert_eq!(col.trailing_zeros(), 31 - c as u32, "dim {dim} column {c}");
        }
    }
}

#[test]
fn gray_code_batch_equals_random_access() {
    let mut batch = GrayCodeBatch::new(3, 5).unwrap();
    let mut out = alloc::vec![0u32; 5 * 300];
    assert_eq!(batch.fill(&mut out), 300);
    for k in 0..300u32 {
        for j in 0..5u32 {
            assert_eq!(out[(k * 5 + j) as usize], sample(gray_code(k), 3 + j));
        }
    }
    // Seeking restarts anywhere.
    batch.seek(123_456);
    let mut one = [0u32; 5];
    batch.fill(&mut one);
    assert_eq!(one[2], sample(gray_code(123_456), 5));
    // The index range ends at 2^32.
    batch.seek(u32::MAX);
    let mut tail = [0u32; 10];
    assert_eq!(batch.fill(&mut tail), 1);
    assert_eq!(tail[0], sample(gray_code(u32::MAX), 3));
}

#[test]
fn gray_code_batch_rejects_bad_ranges() {
    assert!(GrayCodeBatch::new(0, 0).is_err());
    assert!(GrayCodeBatch::new(NUM_DIMENSIONS as u32 - 1, 2).is_err());
    assert!(GrayCodeBatch::new(NUM_DIMENSIONS as u32 - 1, 1).is_ok());
}

#[test]
fn four_dimensional_sampling_equals_one_dimensional() {
    for (r, seed) in strategies() {
        for index in [0u32, 1, 5, 1 << 16, 0xdead_beef] {
            let four = sample_4d(index, 8, r, seed);
            for (k, &value) in four.iter().enumerate() {
                assert_eq!(value, sample_randomized(index, 8 + k as u32, r, seed));
            }
        }
    }
}

/// Pinned randomized values: a change in any scramble is never silent.
#[test]
fn randomized_values_are_stable() {
    let got: alloc::vec::Vec<u32> = strategies()
        .iter()
        .flat_map(|&(r, seed)| {
            [(5u32, 0u32), (1000, 3), (123_456_789, 21_200)]
                .map(|(i, d)| sample_randomized(i, d, r, seed))
        })
        .collect();
    assert_eq!(got, PINNED_RANDOMIZED);
}

const PINNED_RANDOMIZED: [u32; 15] = [
    2684354560, 3904897024, 2167260960, 1006716817, 946614010, 4034898467, 3612639239, 60169538,
    1151766995, 1864917619, 482693418, 1126523575, 1713437331, 1619144032, 3846115874,
];

#[test]
fn lms_is_not_the_identity_nor_a_digital_shift() {
    // LMS keeps the nets above; here it must also move points, and not all
    // by one XOR word (which a digital shift would).
    let lms = |i: u32| sample_randomized(i, 3, RandomizeStrategy::Lms, 5);
    let shift = lms(0);
    assert_ne!(shift, 0);
    let moved = (1..256u32)
        .filter(|&i| lms(i) ^ shift != sample(i, 3))
        .count();
    assert!(
        moved > 200,
        "{moved} of 255 points differ from a digital shift"
    );
}
