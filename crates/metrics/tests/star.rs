//! Star discrepancy: the paper's 1-D facts, exact results against brute force over the
//! critical grid (open and closed boxes), and lower <= exact <= upper.

mod common;

use common::{closed_lattice, coarse, hammersley, random, repeated};
use lowdisc_metrics::{
    BoundsOptions, ExactOptions, MAX_EXACT_DIMS, MetricsError, PointSet, grid_upper_bound,
    random_box_lower_bound, star_bounds, star_discrepancy, star_discrepancy_1d,
    star_discrepancy_with, threshold_accepting_lower_bound,
};

/// Brute force over the critical grid (coordinates and 1 on every axis), counting open
/// and closed boxes directly: O(n^{d+1}).
fn brute(p: &PointSet) -> f64 {
    let d = p.dims();
    let n = p.len() as f64;
    let grids: Vec<Vec<f64>> = (0..d)
        .map(|j| {
            let mut g = p.column(j);
            g.push(1.0);
            g.sort_by(f64::total_cmp);
            g.dedup();
            g
        })
        .collect();
    let total: usize = grids.iter().map(Vec::len).product();
    let mut best = 0.0f64;
    for mut idx in 0..total {
        let y: Vec<f64> = grids
            .iter()
            .map(|g| {
                let v = g[idx % g.len()];
                idx /= g.len();
                v
            })
            .collect();
        let vol: f64 = y.iter().product();
        let open = p
            .iter()
            .filter(|q| q.iter().zip(&y).all(|(a, b)| a < b))
            .count() as f64;
        let closed = p
            .iter()
            .filter(|q| q.iter().zip(&y).all(|(a, b)| a <= b))
            .count() as f64;
        best = best.max(vol - open / n).max(closed / n - vol);
    }
    best
}

fn assert_close(a: f64, b: f64, what: &str) {
    assert!((a - b).abs() <= 1e-12, "{what}: {a} vs {b}");
}

#[test]
fn paper_one_dimensional_facts() {
    for n in [1usize, 2, 3, 7, 10, 64, 1000] {
        let nf = n as f64;
        let right: Vec<f64> = (1..=n).map(|i| i as f64 / nf).collect();
        let mid: Vec<f64> = (1..=n).map(|i| (i as f64 - 0.5) / nf).collect();
        assert_close(star_discrepancy_1d(&right), 1.0 / nf, "i/N");
        assert_close(star_discrepancy_1d(&mid), 0.5 / nf, "(i-1/2)/N");
        let p = PointSet::new(1, right).unwrap();
        assert_close(star_discrepancy(&p).unwrap(), 1.0 / nf, "i/N via PointSet");
    }
}

#[test]
fn one_dimensional_closed_form_equals_brute_force() {
    for seed in 0..20 {
        let p = coarse(1 + seed as usize, 1, 5, seed);
        assert_close(star_discrepancy(&p).unwrap(), brute(&p), "coarse 1-D");
        let p = random(1 + seed as usize * 3, 1, seed);
        assert_close(star_discrepancy(&p).unwrap(), brute(&p), "random 1-D");
    }
}

#[test]
fn exact_2d_equals_brute_force() {
    let mut sets = vec![
        closed_lattice(5, 2),
        closed_lattice(2, 2),
        hammersley(64),
        repeated(&random(20, 2, 4), 3),
        PointSet::new(2, vec![0.0, 0.0]).unwrap(),
        PointSet::new(2, vec![1.0, 1.0]).unwrap(),
        PointSet::new(2, vec![0.0, 1.0, 1.0, 0.0, 1.0, 1.0]).unwrap(),
    ];
    for seed in 0..12 {
        sets.push(random(1 + 9 * seed as usize, 2, seed));
        sets.push(coarse(
            5 + 11 * seed as usize,
            2,
            1 + seed as usize,
            100 + seed,
        ));
    }
    sets.push(random(300, 2, 77));
    for (k, p) in sets.iter().enumerate() {
        assert_close(
            star_discrepancy(p).unwrap(),
            brute(p),
            &format!("2-D set {k}"),
        );
    }
}

/// O(n·m) reference for larger 2-D sets: for each critical x, prefix counts over y.
fn quadratic_2d(p: &PointSet) -> f64 {
    let n = p.len() as f64;
    let mut ys = p.column(1);
    ys.push(1.0);
    ys.sort_by(f64::total_cmp);
    ys.dedup();
    let mut xs = p.column(0);
    xs.push(1.0);
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    let mut best = 0.0f64;
    for &a in &xs {
        let (mut open_h, mut closed_h) = (vec![0u32; ys.len()], vec![0u32; ys.len()]);
        for q in p.iter() {
            let r = ys.partition_point(|&b| b < q[1]);
            if q[0] < a {
                open_h[r] += 1;
            }
            if q[0] <= a {
                closed_h[r] += 1;
            }
        }
        let (mut open, mut closed) = (0u32, 0u32);
        for (j, &b) in ys.iter().enumerate() {
            closed += closed_h[j];
            best = best.max(f64::from(closed) / n - a * b);
            best = best.max(a * b - f64::from(open) / n);
            open += open_h[j];
        }
    }
    best
}

#[test]
fn exact_2d_equals_quadratic_reference_on_larger_sets() {
    for p in [random(2500, 2, 9), hammersley(1024), coarse(2000, 2, 40, 3)] {
        assert_close(star_discrepancy(&p).unwrap(), quadratic_2d(&p), "large 2-D");
    }
}

#[test]
fn exact_higher_dimensions_equal_brute_force() {
    let mut sets = vec![
        closed_lattice(3, 3),
        repeated(&random(6, 3, 1), 2),
        closed_lattice(2, 4),
    ];
    for seed in 0..6 {
        sets.push(random(3 + 4 * seed as usize, 3, seed));
        sets.push(coarse(4 + 3 * seed as usize, 3, 3, 50 + seed));
        sets.push(random(2 + 2 * seed as usize, 4, 200 + seed));
    }
    sets.push(random(8, 5, 5));
    for (k, p) in sets.iter().enumerate() {
        assert_close(
            star_discrepancy(p).unwrap(),
            brute(p),
            &format!("set {k}, d = {}", p.dims()),
        );
    }
}

#[test]
fn hammersley_value_is_stable() {
    // Pinned output of the exact 2-D algorithm (equal to the brute force above).
    let v = star_discrepancy(&hammersley(16)).unwrap();
    assert_close(v, brute(&hammersley(16)), "brute");
    assert_close(v, 0.171875, "pinned");
}

#[test]
fn cost_guard_refuses_and_names_bounds() {
    let p = random(2000, 6, 1);
    let err = star_discrepancy(&p).unwrap_err();
    assert!(matches!(err, MetricsError::TooExpensive { .. }));
    assert!(err.to_string().contains("star_bounds"), "{err}");
    let tiny = ExactOptions { max_work: 10.0 };
    assert!(star_discrepancy_with(&random(50, 2, 1), &tiny).is_err());
}

#[test]
fn bounds_bracket_the_exact_value() {
    let sets = [
        random(200, 2, 1),
        hammersley(256),
        closed_lattice(6, 2),
        random(60, 3, 2),
        coarse(40, 3, 4, 3),
        random(20, 4, 4),
        random(100, 1, 5),
    ];
    let opts = BoundsOptions {
        random_boxes: 2000,
        ta_iterations: 1500,
        ..BoundsOptions::default()
    };
    for p in &sets {
        let exact = star_discrepancy(p).unwrap();
        let b = star_bounds(p, &opts).unwrap();
        assert!(
            b.lower <= exact + 1e-12 && exact <= b.upper + 1e-12,
            "{b:?} vs {exact}"
        );
        let random_lb = random_box_lower_bound(p, 1000, 9);
        let ta = threshold_accepting_lower_bound(p, 2000, 4, 9);
        assert!(random_lb <= exact + 1e-12 && ta <= exact + 1e-12);
        // The search over critical boxes must come close on these small sets.
        assert!(
            ta >= 0.8 * exact,
            "TA {ta} vs exact {exact} (d = {})",
            p.dims()
        );
        for k in [1, 3, 10, 17] {
            let (u, _) = grid_upper_bound(p, Some(k)).unwrap();
            assert!(exact <= u + 1e-12, "grid {k}: {u} < {exact}");
        }
    }
}

#[test]
fn bounds_are_deterministic_and_named() {
    let p = random(300, 5, 8);
    let a = star_bounds(&p, &BoundsOptions::default()).unwrap();
    let b = star_bounds(&p, &BoundsOptions::default()).unwrap();
    assert_eq!(a, b);
    assert!(a.lower > 0.0 && a.lower <= a.upper && a.upper <= 1.0);
    assert!(a.upper_method.contains("grid bracketing"));
    assert!(!a.lower_method.is_empty());
    assert!(grid_upper_bound(&p, Some(0)).is_err());
    let wide = random(50, 30, 2);
    let opts = BoundsOptions {
        random_boxes: 200,
        ta_iterations: 200,
        ..BoundsOptions::default()
    };
    let b = star_bounds(&wide, &opts).unwrap();
    assert_eq!(b.upper, 1.0);
    assert!(b.upper_method.starts_with("trivial") && b.lower > 0.0 && b.lower <= 1.0);
}

#[test]
fn many_dimensions_are_computed_up_to_the_limit_and_refused_beyond_it() {
    // Two coincident points at c in every coordinate: the worst box is open
    // with one side at c and the others at 1 (volume c, no point inside),
    // so D* = max(c, 1 - c^d) = c.
    let c = 0.9999;
    let at = |d: usize| PointSet::new(d, vec![c; 2 * d]).unwrap();
    let v = star_discrepancy(&at(MAX_EXACT_DIMS)).unwrap();
    assert_close(v, c, "coincident points");
    let err = star_discrepancy(&at(MAX_EXACT_DIMS + 1)).unwrap_err();
    assert!(matches!(err, MetricsError::TooManyDims { .. }), "{err}");
    assert!(err.to_string().contains("star_bounds"), "{err}");
    // The 30,000-column single point of a user's file is refused, not a crash.
    let wide = PointSet::new(30_000, vec![0.5; 30_000]).unwrap();
    assert!(star_discrepancy(&wide).is_err());
}
