//! Exact Owen scrambling makes every point uniformly distributed over the
//! seeds: the mean and variance of a fixed point's value across seeds must
//! match U[0,1) (1/2 and 1/12) within stated statistical tolerances.

use lowdisc::RandomizeStrategy;
use lowdisc::sobol::sample_randomized;

const SEEDS: u64 = 20_000;

/// Mean and variance of point `index` in dimension `dim` over `SEEDS` seeds.
fn moments(index: u32, dim: u32, strategy: RandomizeStrategy) -> (f64, f64) {
    let xs: Vec<f64> = (0..SEEDS)
        .map(|s| lowdisc::to_f64(sample_randomized(index, dim, strategy, s)))
        .collect();
    let mean = xs.iter().sum::<f64>() / xs.len() as f64;
    let var = xs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / (xs.len() - 1) as f64;
    (mean, var)
}

/// Tolerances: 5 standard errors for N = 20,000 uniform draws:
/// sd(mean) = sqrt(1/12 / N) = 0.00204; sd(var) = sqrt((1/80 - 1/144) / N) = 0.00053.
const MEAN_TOL: f64 = 5.0 * 0.00204;
const VAR_TOL: f64 = 5.0 * 0.00053;

#[test]
fn exact_owen_points_are_uniform_over_seeds() {
    for (index, dim) in [(0u32, 0u32), (1, 0), (3, 1), (1000, 7), (65_535, 21_200)] {
        let (mean, var) = moments(index, dim, RandomizeStrategy::Owen);
        assert!(
            (mean - 0.5).abs() < MEAN_TOL,
            "index {index} dim {dim}: mean {mean}"
        );
        assert!(
            (var - 1.0 / 12.0).abs() < VAR_TOL,
            "index {index} dim {dim}: variance {var}"
        );
    }
}

#[test]
fn xor_points_are_uniform_over_seeds() {
    let (mean, var) = moments(5, 2, RandomizeStrategy::Xor);
    assert!((mean - 0.5).abs() < MEAN_TOL, "mean {mean}");
    assert!((var - 1.0 / 12.0).abs() < VAR_TOL, "variance {var}");
}

#[test]
fn the_unscrambled_point_is_not_uniform() {
    // The check above can fail: a fixed, unscrambled point has variance 0.
    let (_, var) = moments(5, 2, RandomizeStrategy::None);
    assert!(var.abs() < 1e-12);
}

#[test]
fn owen_scrambling_keeps_points_in_distinct_strata() {
    // Under one seed, the first 2^m points of a dimension still fill all 2^m
    // intervals (the scramble is a bijection on each level of digits).

    let mut seen = vec![false; 1024];
    for i in 0..1024u32 {
        let cell = (sample_randomized(i, 4, RandomizeStrategy::Owen, 99) >> 22) as usize;
        assert!(!std::mem::replace(&mut seen[cell], true));
    }
}
