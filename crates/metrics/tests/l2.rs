//! L2-type discrepancies: pinned SciPy values, the closed forms evaluated directly, and
//! the defining integrals of L2-star and CD evaluated exactly cell by cell.

mod common;

use common::{direct, random};
use lowdisc_metrics::{L2Method, PointSet, l2_discrepancies, l2_discrepancy};

fn doc2d() -> PointSet {
    // The example of scipy.stats.qmc.discrepancy's documentation: ((k - 1/2)/6).
    let raw = [[1, 3], [2, 6], [3, 2], [4, 5], [5, 1], [6, 4]];
    let coords = raw
        .iter()
        .flat_map(|r| r.iter().map(|&v| (v as f64 - 0.5) / 6.0))
        .collect();
    PointSet::new(2, coords).unwrap()
}

fn set3d() -> PointSet {
    let coords = (0..10)
        .flat_map(|i| {
            [
                ((i * 7 + 3) % 11) as f64 / 10.0,
                ((i * 5 + 1) % 13) as f64 / 12.0,
                ((i * 3 + 2) % 9) as f64 / 8.0,
            ]
        })
        .collect();
    PointSet::new(3, coords).unwrap()
}

fn set5d() -> PointSet {
    let coords = (0..7)
        .flat_map(|i| (0..5).map(move |j| ((i * (j + 2) + j) % 17) as f64 / 16.0))
        .collect();
    PointSet::new(5, coords).unwrap()
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-13 * (1.0 + b.abs())
}

/// Values computed with SciPy 1.17.1, `scipy.stats.qmc.discrepancy(sample, method=m)`
/// on the same points (order: L2-star, CD, WD, MD), printed with `repr`.
#[test]
fn equal_pinned_scipy_values() {
    let cases = [
        (
            doc2d(),
            [
                0.06833606212558091,
                0.008142039609053464,
                0.01684670781892894,
                0.014895592206789487,
            ],
        ),
        (
            set3d(),
            [
                0.10766789483733635,
                0.05053421585648099,
                0.07688959056712896,
                0.10369819034529071,
            ],
        ),
        (
            set5d(),
            [
                0.09277175364738005,
                0.12053865579056233,
                0.23858730679635798,
                0.43696566192127406,
            ],
        ),
    ];
    for (p, want) in &cases {
        let all = l2_discrepancies(p);
        let got = [all.l2_star, all.cd, all.wd, all.md];
        for (g, w) in got.iter().zip(want) {
            assert!(close(*g, *w), "{g} vs scipy {w} (d = {})", p.dims());
        }
        assert_eq!(l2_discrepancy(p, L2Method::Centered), all.cd);
    }
    assert!(!L2Method::L2Star.is_squared() && L2Method::Mixture.is_squared());
    assert_eq!(L2Method::WrapAround.scipy_name(), "WD");
}

#[test]
fn equal_direct_formula_evaluation() {
    for (n, d, seed) in [(1, 1, 1), (2, 3, 2), (37, 2, 3), (100, 8, 4), (257, 5, 5)] {
        let p = random(n, d, seed);
        for m in L2Method::ALL {
            let (got, want) = (l2_discrepancy(&p, m), direct(&p, m));
            assert!(
                (got - want).abs() <= 1e-11 * (1.0 + want.abs()),
                "{m:?} n={n} d={d}: {got} vs {want}"
            );
        }
    }
}

/// Exact integral of `(c − u·v)²` over `[u1,u2] × [v1,v2]`.
fn cell(c: f64, u1: f64, u2: f64, v1: f64, v2: f64) -> f64 {
    c * c * (u2 - u1) * (v2 - v1) - c * (u2 * u2 - u1 * u1) * (v2 * v2 - v1 * v1) / 2.0
        + (u2.powi(3) - u1.powi(3)) * (v2.powi(3) - v1.powi(3)) / 9.0
}

/// `∫∫ (count(J(x))/n − |J(x)|)² dx` over the unit square, where `J(x)` is the box from
/// corner `anchor(x)` to `x`; exact, piecewise on the grid of coordinates, 1/2, 0 and 1.
fn integral_2d(p: &PointSet, anchor: impl Fn(f64) -> f64) -> f64 {
    let breaks = |j: usize| {
        let mut b = p.column(j);
        b.extend([0.0, 0.5, 1.0]);
        b.sort_by(f64::total_cmp);
        b.dedup();
        b
    };
    let (bx, by) = (breaks(0), breaks(1));
    let n = p.len() as f64;
    let mut total = 0.0;
    for wx in bx.windows(2) {
        for wy in by.windows(2) {
            let (mx, my) = ((wx[0] + wx[1]) / 2.0, (wy[0] + wy[1]) / 2.0);
            let (ax, ay) = (anchor(mx), anchor(my));
            let inside = |v: f64, a: f64, m: f64| v >= a.min(m) && v <= a.max(m);
            let c = p
                .iter()
                .filter(|q| inside(q[0], ax, mx) && inside(q[1], ay, my))
                .count() as f64
                / n;
            let span = |w: &[f64], a: f64| {
                let (s, t) = ((w[0] - a).abs(), (w[1] - a).abs());
                (s.min(t), s.max(t))
            };
            let ((u1, u2), (v1, v2)) = (span(wx, ax), span(wy, ay));
            total += cell(c, u1, u2, v1, v2);
        }
    }
    total
}

/// `∫ (count(J(x))/n − |J(x)|)² dx` for coordinate `j` alone (a 1-D projection).
fn integral_1d(p: &PointSet, j: usize, anchor: impl Fn(f64) -> f64) -> f64 {
    let mut b = p.column(j);
    b.extend([0.0, 0.5, 1.0]);
    b.sort_by(f64::total_cmp);
    b.dedup();
    let n = p.len() as f64;
    b.windows(2)
        .map(|w| {
            let m = (w[0] + w[1]) / 2.0;
            let a = anchor(m);
            let c = p
                .iter()
                .filter(|q| q[j] >= a.min(m) && q[j] <= a.max(m))
                .count() as f64
                / n;
            let (s, t) = ((w[0] - a).abs(), (w[1] - a).abs());
            let (u1, u2) = (s.min(t), s.max(t));
            c * c * (u2 - u1) - c * (u2 * u2 - u1 * u1) + (u2.powi(3) - u1.powi(3)) / 3.0
        })
        .sum()
}

#[test]
fn equal_defining_integrals() {
    for (n, seed) in [(1, 7), (5, 8), (23, 9)] {
        let p = random(n, 2, seed);
        // L2-star: boxes anchored at the origin.
        let star = integral_2d(&p, |_| 0.0).sqrt();
        assert!(
            (l2_discrepancy(&p, L2Method::L2Star) - star).abs() < 1e-12,
            "L2-star n={n}"
        );
        // CD: boxes anchored at the nearest vertex, summed over all non-empty projections.
        let vertex = |x: f64| if x < 0.5 { 0.0 } else { 1.0 };
        let cd = integral_2d(&p, vertex) + integral_1d(&p, 0, vertex) + integral_1d(&p, 1, vertex);
        assert!(
            (l2_discrepancy(&p, L2Method::Centered) - cd).abs() < 1e-12,
            "CD n={n}"
        );
    }
    let p = doc2d();
    assert!((integral_2d(&p, |_| 0.0).sqrt() - 0.06833606212558091).abs() < 1e-12);
}
