//! Tests of the stratified point sets and the keyed permutation.

use super::*;

#[test]
fn grid_shapes() {
    let cases = [
        (0, (0, 0)),
        (1, (1, 1)),
        (2, (1, 2)),
        (7, (1, 7)),
        (12, (3, 4)),
        (16, (4, 4)),
        (30, (5, 6)),
        (64, (8, 8)),
        (1000, (25, 40)),
        (8191, (1, 8191)),
        (u32::MAX, (65535, 65537)),
    ];
    for (n, shape) in cases {
        assert_eq!(grid_shape(n), shape, "n = {n}");
    }
    // Brute force: no divisor pair is closer to square.
    for n in 1..2000u32 {
        let (nx, ny) = grid_shape(n);
        assert_eq!(nx * ny, n);
        let best = (1..=n).filter(|d| n % d == 0 && d * d <= n).max().unwrap();
        assert_eq!(nx, best, "n = {n}");
    }
}

/// Checks that every stratum of every pair (and of an odd last dimension)
/// holds exactly one point.
fn assert_one_point_per_stratum(n: u32, dims: u32, seed: u64) {
    let points = jittered_points(n, dims, seed);
    assert_eq!(points.len(), (n * dims) as usize);
    let (nx, ny) = grid_shape(n);
    let mut d = 0;
    while d < dims as usize {
        let mut seen = alloc::vec![false; n as usize];
        for k in 0..n as usize {
            let row = &points[k * dims as usize..][..dims as usize];
            let cell = if d + 1 < dims as usize {
                let (x, y) = (row[d], row[d + 1]);
                assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y));
                let (cx, cy) = ((x * f64::from(nx)) as u32, (y * f64::from(ny)) as u32);
                assert!(cx < nx && cy < ny);
                cy * nx + cx
            } else {
                let x = row[d];
                assert!((0.0..1.0).contains(&x));
                (x * f64::from(n)) as u32
            };
            assert!(
                !seen[cell as usize],
                "n {n}, dims {dims}, dim {d}: cell {cell} twice"
            );
            seen[cell as usize] = true;
        }
        d += 2;
    }
}

#[test]
fn each_stratum_holds_exactly_one_point() {
    for n in [1, 2, 3, 7, 12, 16, 30, 31, 64, 100, 257] {
        for dims in [1, 2, 3, 5, 6] {
            assert_one_point_per_stratum(n, dims, 3);
        }
    }
    assert!(jittered_points(0, 3, 1).is_empty());
    assert!(jittered_points(5, 0, 1).is_empty());
}

#[test]
fn pairs_are_shuffled_independently() {
    let n = 16;
    let dims = 4;
    let points = jittered_points(n, dims, 11);
    let cells = |d: usize| -> alloc::vec::Vec<u32> {
        (0..n as usize)
            .map(|k| {
                let row = &points[k * dims as usize..];
                (row[d + 1] * 4.0) as u32 * 4 + (row[d] * 4.0) as u32
            })
            .collect()
    };
    assert_ne!(cells(0), cells(2));
    assert_ne!(cells(0), (0..n).collect::<alloc::vec::Vec<_>>());
    // Same seed, same points; other seed, other points.
    assert_eq!(points, jittered_points(n, dims, 11));
    assert_ne!(points, jittered_points(n, dims, 12));
}

#[test]
fn jittered_values_are_pinned() {
    let p = jittered_points(4, 3, 7);
    let words: alloc::vec::Vec<u64> = p.iter().map(|v| v.to_bits()).collect();
    assert_eq!(words, PINNED_JITTERED);
}

const PINNED_JITTERED: [u64; 12] = [
    4595702745972683518,
    4602223682209282957,
    4589363702574722570,
    4606607128693991522,
    4600975829595533205,
    4600372692987656146,
    4592307270306882300,
    4605912448603463564,
    4604907211891427096,
    4604121250571859296,
    4604002669071889828,
    4605651593935366487,
];

#[test]
fn stratum_helpers_stay_inside_the_stratum() {
    let almost_one = 1.0 - f64::EPSILON / 2.0;
    for count in [1u32, 2, 3, 7, 49, 1000, 1 << 20, (1 << 24) + 1, u32::MAX] {
        for cell in [0, count / 3, count - 1] {
            for u in [0.0, 0.5, almost_one] {
                let v = stratum_f64(cell, count, u);
                assert!(v < 1.0);
                assert_eq!((v * f64::from(count)).floor(), f64::from(cell));
            }
            if count <= 1 << 20 {
                for u in [0.0f32, 0.5, crate::ONE_MINUS_EPSILON_F32] {
                    let v = stratum_f32(cell, count, u);
                    assert!(v < 1.0);
                    assert_eq!((v * count as f32).floor(), cell as f32);
                }
            }
        }
    }
}

#[test]
fn permutation_element_is_a_bijection() {
    for n in [1u32, 2, 3, 5, 16, 17, 100, 1000, 4097] {
        for key in [0u64, 1, 0xdead_beef, u64::MAX] {
            let mut seen = alloc::vec![false; n as usize];
            for i in 0..n {
                let p = permutation_element(i, n, key);
                assert!(p < n && !seen[p as usize], "n {n}, key {key}");
                seen[p as usize] = true;
            }
            assert_eq!(
                permutation_element(n + 1, n, key),
                permutation_element(1 % n, n, key)
            );
        }
    }
    assert_eq!(permutation_element(5, 0, 3), 0);
}

#[test]
fn permutation_element_depends_on_the_key() {
    let n = 16;
    let order =
        |key| -> alloc::vec::Vec<u32> { (0..n).map(|i| permutation_element(i, n, key)).collect() };
    let distinct: alloc::collections::BTreeSet<_> = (0..50u64).map(order).collect();
    assert!(
        distinct.len() >= 45,
        "only {} distinct permutations of 16 from 50 keys",
        distinct.len()
    );
    // Each element lands in each position about equally often over many keys.
    let keys = 16_000u64;
    let mut counts = [[0u32; 16]; 16];
    for key in 0..keys {
        for i in 0..n {
            counts[i as usize][permutation_element(i, n, mix64(key)) as usize] += 1;
        }
    }
    // Expected 1000 per cell, standard deviation about 31; allow 6 sigma.
    for row in counts {
        for c in row {
            assert!((810..=1190).contains(&c), "count {c}");
        }
    }
}
