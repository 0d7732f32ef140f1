//! Tests of [`OwenTreeKey`]: its values against the node-by-node definition,
//! the nested property, nets, and the distribution of the flips over seeds.

use super::*;
use crate::sobol;

/// The module's definition, one node at a time: digit `l` in layer
/// `t = l / 6` at local depth `i = l % 6` is flipped by bit `2^i - 1 + q` of
/// `mix64(K_t + r * GAMMA)`.
fn reference(seed: u64, dim: u32, word: u32) -> u32 {
    let mut out = word;
    for l in 0..32u32 {
        let (t, i) = (l / 6, l % 6);
        let root = if t == 0 { 0 } else { word >> (32 - 6 * t) };
        let before = if l == 0 { 0 } else { word >> (32 - l) };
        let q = before & ((1 << i) - 1);
        let k_t = hash3(derive_seed(seed, SALT), u64::from(dim), u64::from(t));
        let bits = mix64(k_t.wrapping_add(u64::from(root).wrapping_mul(GAMMA)));
        let flip = ((bits >> ((1 << i) - 1 + q)) & 1) as u32;
        out ^= flip << (31 - l);
    }
    out
}

/// A few pseudo-random words.
fn words(salt: u64, n: usize) -> impl Iterator<Item = u32> {
    (0..n as u64).map(move |k| (mix64(k ^ salt.rotate_left(17)) >> 16) as u32)
}

#[test]
fn values_equal_the_definition_at_every_digit_count() {
    for (seed, dim) in [(0u64, 0u32), (7, 1), (u64::MAX, 63), (12345, 21_200)] {
        let key = OwenTreeKey::new(seed, dim);
        let small = OwenTreeKey::with_table(seed, dim, 6);
        for w in words(seed, 400).chain([0, u32::MAX, 1 << 20, 0xffc0_0000]) {
            let full = reference(seed, dim, w);
            assert_eq!(key.scramble(w), full, "seed {seed} dim {dim} word {w:#x}");
            assert_eq!(small.scramble(w), full, "6-digit table");
            for digits in 1..=32 {
                let keep = u32::MAX << (32 - digits);
                assert_eq!(
                    key.scramble_digits(w, digits),
                    full & keep,
                    "{digits} digits"
                );
            }
        }
    }
}

#[test]
fn each_flip_depends_only_on_the_digits_before_it() {
    let key = OwenTreeKey::new(3, 2);
    for (w, noise) in words(1, 300).zip(words(2, 300)) {
        let flips = key.scramble(w) ^ w;
        for b in 0..32u32 {
            // Keep digits 0..b of w, replace digits b.. (bit 31 - b down).
            let high = if b == 0 { 0 } else { u32::MAX << (32 - b) };
            let other = (w & high) | (noise & !high);
            let other_flips = key.scramble(other) ^ other;
            let bit = 1u32 << (31 - b);
            assert_eq!(flips & bit, other_flips & bit, "digit {b} of {w:#x}");
        }
    }
}

#[test]
fn the_scramble_permutes_every_set_of_prefixes() {
    let key = OwenTreeKey::new(11, 5);
    let mut seen = vec![false; 1 << 16];
    for p in 0..1u32 << 16 {
        let out = key.scramble_digits(p << 16, 16) >> 16;
        assert!(!seen[out as usize], "prefix {p:#x} collides");
        seen[out as usize] = true;
    }
}

#[test]
fn scrambled_sobol_points_are_0_m_2_nets_up_to_m_16() {
    for seed in [1u64, 2] {
        let (kx, ky) = (OwenTreeKey::new(seed, 0), OwenTreeKey::new(seed, 1));
        let points: Vec<[u32; 2]> = (0..1u32 << 16)
            .map(|k| {
                [
                    kx.scramble(sobol::sample(k, 0)),
                    ky.scramble(sobol::sample(k, 1)),
                ]
            })
            .collect();
        for m in 0..=16u32 {
            for a in 0..=m {
                // One point in each of the 2^a x 2^(m-a) cells.
                let mut seen = vec![false; 1 << m];
                for p in &points[..1 << m] {
                    let x = if a == 0 { 0 } else { p[0] >> (32 - a) };
                    let y = if a == m { 0 } else { p[1] >> (32 - (m - a)) };
                    let cell = ((x << (m - a)) | y) as usize;
                    assert!(!seen[cell], "seed {seed} m {m} split {a}");
                    seen[cell] = true;
                }
            }
        }
    }
}

/// The flip of digit `b` of `word` under `key`, as 0 or 1.
fn flip(key: &OwenTreeKey, word: u32, b: u32) -> u32 {
    ((key.scramble(word) ^ word) >> (31 - b)) & 1
}

#[test]
fn flips_are_fair_and_pairwise_independent_over_seeds() {
    const SEEDS: u64 = 4000;
    // Tolerance: 5 standard deviations of a fraction of 4000 fair trials.
    let tol = |p: f64| 5.0 * (p * (1.0 - p) / SEEDS as f64).sqrt();
    let w = 0x9b3c_5e71u32;
    // Pairs of nodes: parent and child in one subtree, two layers, the table
    // and a hashed layer, the last layer, and nodes of sibling prefixes.
    let pairs = [
        ((w, 13), (w, 14)),
        ((w, 5), (w, 6)),
        ((w, 11), (w, 12)),
        ((w, 29), (w, 31)),
        ((w, 20), (w ^ (1 << 12), 20)),
        ((w, 3), (w ^ (1 << 29), 3)),
    ];
    // Per pair: how often the first, the second and both flipped.
    let mut counts = [[0u32; 3]; 6];
    for seed in 0..SEEDS {
        let key = OwenTreeKey::new(seed, 4);
        for (((w1, b1), (w2, b2)), c) in pairs.iter().zip(&mut counts) {
            let (f, g) = (flip(&key, *w1, *b1), flip(&key, *w2, *b2));
            c[0] += f;
            c[1] += g;
            c[2] += f & g;
        }
    }
    let frac = |c: u32| f64::from(c) / SEEDS as f64;
    for (((_, b1), (_, b2)), [one, two, both]) in pairs.iter().zip(counts) {
        assert!(
            (frac(one) - 0.5).abs() < tol(0.5),
            "digit {b1}: {}",
            frac(one)
        );
        assert!(
            (frac(two) - 0.5).abs() < tol(0.5),
            "digit {b2}: {}",
            frac(two)
        );
        assert!(
            (frac(both) - 0.25).abs() < tol(0.25),
            "{b1}/{b2}: {}",
            frac(both)
        );
    }
}

#[test]
fn a_scrambled_value_is_uniform_over_seeds() {
    // Mean 1/2 and variance 1/12 of U[0, 1), within 5 standard errors.
    const SEEDS: u64 = 20_000;
    let words = [0u32, 0x8000_0000, 0x1234_5678];
    let (mut sum, mut sum_sq) = ([0f64; 3], [0f64; 3]);
    for seed in 0..SEEDS {
        let key = OwenTreeKey::new(seed, 9);
        for (k, &w) in words.iter().enumerate() {
            let x = f64::from(key.scramble(w)) / 4_294_967_296.0;
            sum[k] += x;
            sum_sq[k] += x * x;
        }
    }
    let n = SEEDS as f64;
    for k in 0..words.len() {
        let mean = sum[k] / n;
        let var = sum_sq[k] / n - mean * mean;
        assert!(
            (mean - 0.5).abs() < 5.0 * (1.0 / 12.0 / n).sqrt(),
            "mean {mean}"
        );
        assert!(
            (var - 1.0 / 12.0).abs() < 5.0 * (1.0 / 180.0 / n).sqrt(),
            "variance {var}"
        );
    }
}

#[test]
fn dimensions_and_seeds_get_different_scrambles() {
    let w = 0x4000_0001;
    let a = OwenTreeKey::new(1, 0);
    assert_ne!(a, OwenTreeKey::new(1, 1));
    assert_ne!(a, OwenTreeKey::new(2, 0));
    assert_eq!(a.scramble(w), OwenTreeKey::new(1, 0).scramble(w));
}
