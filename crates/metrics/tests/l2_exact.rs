//! L2-type discrepancies of the fast blocked, parallel evaluation: exact rational values
//! on product grids (where the heavy cancellation of the formulas is worst), the same
//! bits whatever the number of threads (and for the power spectrum), block and chunk
//! boundaries, and large `d`.

mod common;

use common::{direct, random};
use lowdisc_metrics::{L2Method, PointSet, l2_discrepancy};

/// A small exact rational, always reduced, denominator positive.
#[derive(Clone, Copy, Debug)]
struct Q(i128, i128);

fn gcd(a: i128, b: i128) -> i128 {
    if b == 0 { a.abs() } else { gcd(b, a % b) }
}

impl Q {
    fn new(n: i128, d: i128) -> Q {
        let g = gcd(n, d).max(1) * d.signum();
        Q(n / g, d / g)
    }
    fn add(self, o: Q) -> Q {
        let g = gcd(self.1, o.1);
        let (a, b) = (self.1 / g, o.1 / g);
        Q::new(
            self.0.checked_mul(b).unwrap() + o.0.checked_mul(a).unwrap(),
            self.1.checked_mul(b).unwrap(),
        )
    }
    fn mul(self, o: Q) -> Q {
        let (g1, g2) = (gcd(self.0, o.1).max(1), gcd(o.0, self.1).max(1));
        Q::new(
            (self.0 / g1).checked_mul(o.0 / g2).unwrap(),
            (self.1 / g2).checked_mul(o.1 / g1).unwrap(),
        )
    }
    fn pow(self, e: usize) -> Q {
        (0..e).fold(Q(1, 1), |acc, _| acc.mul(self))
    }
    fn to_f64(self) -> f64 {
        self.0 as f64 / self.1 as f64
    }
}

/// The centred grid `{(2m+1)/(2k)}^d`: `k^d` points.
fn grid(k: usize, d: usize) -> PointSet {
    let n = k.pow(d as u32);
    let coords = (0..n)
        .flat_map(|i| {
            (0..d).map(move |j| (2 * ((i / k.pow(j as u32)) % k) + 1) as f64 / (2 * k) as f64)
        })
        .collect();
    PointSet::new(d, coords).unwrap()
}

/// The exact value of `method` on [`grid`]`(k, d)`. Every kernel is a product over the
/// coordinates, so on a product set both sums factor into powers of 1-D sums:
/// `D = C^d − 2 (S1/k)^d + (S2/k²)^d` (square root for L2-star), all in exact rationals
/// with `x = u/(2k)`, `u` odd.
fn grid_exact(method: L2Method, k: usize, d: usize) -> f64 {
    let s = 2 * k as i128;
    let q = |n: i128, den: i128| Q::new(n, den);
    let x = |u: i128| q(u, s);
    let z = |u: i128| q((2 * u - s).abs(), 2 * s);
    let t = |u: i128, v: i128| q((u - v).abs(), s);
    let neg = |a: Q| Q(-a.0, a.1);
    let single = |u: i128| match method {
        L2Method::L2Star => q(1, 1).add(neg(x(u).mul(x(u)))),
        L2Method::Centered => q(1, 1)
            .add(q(1, 2).mul(z(u)))
            .add(neg(q(1, 2).mul(z(u).mul(z(u))))),
        L2Method::WrapAround => q(0, 1),
        L2Method::Mixture => q(5, 3)
            .add(neg(q(1, 4).mul(z(u))))
            .add(neg(q(1, 4).mul(z(u).mul(z(u))))),
    };
    let pair = |u: i128, v: i128| match method {
        L2Method::L2Star => q(1, 1).add(neg(x(u.max(v)))),
        L2Method::Centered => q(1, 1)
            .add(q(1, 2).mul(z(u).add(z(v))))
            .add(neg(q(1, 2).mul(t(u, v)))),
        L2Method::WrapAround => q(3, 2).add(neg(t(u, v))).add(t(u, v).mul(t(u, v))),
        L2Method::Mixture => q(15, 8)
            .add(neg(q(1, 4).mul(z(u).add(z(v)))))
            .add(neg(q(3, 4).mul(t(u, v))))
            .add(q(1, 2).mul(t(u, v).mul(t(u, v)))),
    };
    let us: Vec<i128> = (0..k as i128).map(|m| 2 * m + 1).collect();
    let s1 = us.iter().fold(q(0, 1), |acc, &u| acc.add(single(u)));
    let s2 = us.iter().fold(q(0, 1), |acc, &u| {
        us.iter().fold(acc, |acc, &v| acc.add(pair(u, v)))
    });
    let kk = k as i128;
    let c = match method {
        L2Method::L2Star => q(1, 3),
        L2Method::Centered => q(13, 12),
        L2Method::WrapAround => q(4, 3),
        L2Method::Mixture => q(19, 12),
    };
    let c_term = if method == L2Method::WrapAround {
        neg(c.pow(d))
    } else {
        c.pow(d)
    };
    let single_term = match method {
        L2Method::L2Star => q(2, 1).mul(q(1, 2).pow(d)).mul(s1.mul(q(1, kk)).pow(d)),
        _ => q(2, 1).mul(s1.mul(q(1, kk)).pow(d)),
    };
    let value = c_term
        .add(neg(single_term))
        .add(s2.mul(q(1, kk * kk)).pow(d))
        .to_f64();
    if method == L2Method::L2Star {
        value.sqrt()
    } else {
        value
    }
}

#[test]
fn equal_exact_rational_values_on_product_grids() {
    for (k, d) in [(3, 1), (7, 2), (8, 4), (4, 6)] {
        let p = grid(k, d);
        for m in L2Method::ALL {
            let (got, want) = (l2_discrepancy(&p, m), grid_exact(m, k, d));
            assert!(
                (got - want).abs() <= 2e-13 * want.abs(),
                "{m:?} k={k} d={d}: {got:e} vs exact {want:e}"
            );
        }
    }
}

#[test]
fn same_bits_for_every_thread_count() {
    let p = random(1000, 5, 21);
    let with_threads = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| L2Method::ALL.map(|m| l2_discrepancy(&p, m).to_bits()))
    };
    let one = with_threads(1);
    assert_eq!(one, with_threads(2));
    assert_eq!(one, with_threads(3));
    assert_eq!(one, L2Method::ALL.map(|m| l2_discrepancy(&p, m).to_bits()));
}

/// Sizes around the 16-point blocks and the 32-row chunks (masked lanes, a short last
/// block, a last chunk of one row), and a dimension past the mixture kernel's rescaled
/// form (d > 256).
#[test]
fn equal_direct_evaluation_at_block_edges_and_large_d() {
    let cases = [
        (15, 3),
        (16, 3),
        (17, 1),
        (31, 4),
        (32, 2),
        (33, 3),
        (47, 2),
        (65, 5),
        (4, 300),
    ];
    for (i, &(n, d)) in cases.iter().enumerate() {
        let p = random(n, d, 40 + i as u64);
        for m in L2Method::ALL {
            let (got, want) = (l2_discrepancy(&p, m), direct(&p, m));
            assert!(
                (got - want).abs() <= 1e-11 * want.abs().max(1.0),
                "{m:?} n={n} d={d}: {got:e} vs {want:e}"
            );
        }
    }
}

#[test]
fn spectrum_has_the_same_bits_for_every_thread_count() {
    let p = random(300, 2, 5);
    let with_threads = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            lowdisc_metrics::radial_power_spectrum(&p, 24)
                .unwrap()
                .power
                .iter()
                .map(|v| v.to_bits())
                .collect::<Vec<_>>()
        })
    };
    let one = with_threads(1);
    assert_eq!(one, with_threads(2));
    assert_eq!(one, with_threads(3));
}
