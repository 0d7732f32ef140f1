//! Minimum and nearest-neighbour distances against brute force, Euclidean and toroidal.

mod common;

use common::{closed_lattice, coarse, hammersley, random, repeated};
use lowdisc_metrics::{
    DistanceMetric, MetricsError, PointSet, distance_stats, min_distance,
    nearest_neighbour_distances,
};

fn brute_nn(p: &PointSet, metric: DistanceMetric) -> Vec<f64> {
    (0..p.len())
        .map(|i| {
            (0..p.len())
                .filter(|&j| j != i)
                .map(|j| {
                    p.point(i)
                        .iter()
                        .zip(p.point(j))
                        .map(|(a, b)| {
                            let t = (a - b).abs();
                            let t = if metric == DistanceMetric::Toroidal {
                                t.min(1.0 - t)
                            } else {
                                t
                            };
                            t * t
                        })
                        .sum::<f64>()
                        .sqrt()
                })
                .fold(f64::INFINITY, f64::min)
        })
        .collect()
}

fn check(p: &PointSet, what: &str) {
    for metric in [DistanceMetric::Euclidean, DistanceMetric::Toroidal] {
        let got = nearest_neighbour_distances(p, metric).unwrap();
        let want = brute_nn(p, metric);
        for (i, (g, w)) in got.iter().zip(&want).enumerate() {
            assert!(
                (g - w).abs() <= 1e-15,
                "{what} {metric:?} point {i}: {g} vs {w}"
            );
        }
        let s = distance_stats(p, metric).unwrap();
        let min = want.iter().copied().fold(f64::INFINITY, f64::min);
        let mean = want.iter().sum::<f64>() / want.len() as f64;
        assert_eq!(s.min_distance, min, "{what} {metric:?}");
        assert!(
            (s.mean_nn_distance - mean).abs() < 1e-14,
            "{what} {metric:?}"
        );
    }
}

#[test]
fn random_sets_equal_brute_force() {
    for (n, d, seed) in [
        (2, 1, 1),
        (50, 1, 2),
        (500, 2, 3),
        (300, 3, 4),
        (200, 5, 5),
        (64, 8, 6),
    ] {
        check(&random(n, d, seed), &format!("random n={n} d={d}"));
    }
}

#[test]
fn structured_sets_equal_brute_force() {
    check(&hammersley(256), "hammersley");
    check(&closed_lattice(7, 2), "lattice");
    check(&coarse(300, 2, 10, 1), "coarse");
    // Clustered: everything in a tiny corner plus one far point.
    let mut c: Vec<f64> = random(200, 2, 9)
        .coords()
        .iter()
        .map(|v| v * 0.01)
        .collect();
    c.extend([1.0, 1.0]);
    check(&PointSet::new(2, c).unwrap(), "clustered");
}

#[test]
fn duplicates_and_wrapping() {
    let dup = repeated(&random(30, 2, 3), 2);
    assert_eq!(min_distance(&dup, DistanceMetric::Euclidean).unwrap(), 0.0);
    check(&dup, "duplicates");
    // 0 and 1 coincide on the torus.
    let p = PointSet::new(2, vec![0.0, 0.5, 1.0, 0.5, 0.5, 0.0]).unwrap();
    assert_eq!(min_distance(&p, DistanceMetric::Toroidal).unwrap(), 0.0);
    assert_eq!(
        min_distance(&p, DistanceMetric::Euclidean).unwrap(),
        0.5f64.sqrt()
    );
    // The lattice {i/k}, k = 8: spacing 1/8 on the cube and on the torus.
    let k = 8;
    let lat: Vec<f64> = (0..k * k)
        .flat_map(|i| [(i % k) as f64 / k as f64, (i / k) as f64 / k as f64])
        .collect();
    let lat = PointSet::new(2, lat).unwrap();
    let s = distance_stats(&lat, DistanceMetric::Toroidal).unwrap();
    assert_eq!((s.min_distance, s.mean_nn_distance), (0.125, 0.125));
    assert_eq!(
        min_distance(
            &PointSet::new(2, vec![0.5, 0.5]).unwrap(),
            DistanceMetric::Euclidean
        ),
        Err(MetricsError::TooFewPoints { needed: 2, got: 1 })
    );
}
