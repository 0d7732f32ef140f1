//! Shared helpers of the integration tests: seeded point sets and structured sets.
#![allow(dead_code)]

use lowdisc_metrics::{L2Method, PointSet};

/// A tiny seeded generator (64-bit LCG, top 53 bits) for test inputs.
pub struct Lcg(pub u64);

impl Lcg {
    /// Next value uniform in [0, 1).
    pub fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `n` uniform random points in `[0,1)^d`.
pub fn random(n: usize, d: usize, seed: u64) -> PointSet {
    let mut g = Lcg(seed);
    PointSet::new(d, (0..n * d).map(|_| g.next()).collect()).unwrap()
}

/// `n` random points whose coordinates are multiples of `1/levels` (many ties, 0 and 1).
pub fn coarse(n: usize, d: usize, levels: usize, seed: u64) -> PointSet {
    let mut g = Lcg(seed);
    let coords = (0..n * d)
        .map(|_| ((g.next() * (levels + 1) as f64) as usize).min(levels) as f64 / levels as f64)
        .collect();
    PointSet::new(d, coords).unwrap()
}

/// The full `k^d` lattice `{i/(k-1)}` including both 0 and 1 on every axis.
pub fn closed_lattice(k: usize, d: usize) -> PointSet {
    let n = k.pow(d as u32);
    let coords = (0..n)
        .flat_map(|i| (0..d).map(move |j| ((i / k.pow(j as u32)) % k) as f64 / (k - 1) as f64))
        .collect();
    PointSet::new(d, coords).unwrap()
}

/// Every point of `p` repeated `times` times.
pub fn repeated(p: &PointSet, times: usize) -> PointSet {
    let coords = p
        .iter()
        .flat_map(|q| std::iter::repeat_n(q.to_vec(), times).flatten())
        .collect();
    PointSet::new(p.dims(), coords).unwrap()
}

/// Radical inverse of `i` in base 2.
pub fn van_der_corput(mut i: u64) -> f64 {
    let (mut v, mut f) = (0.0, 0.5);
    while i > 0 {
        v += f * (i & 1) as f64;
        i >>= 1;
        f *= 0.5;
    }
    v
}

/// The 2-D Hammersley set `(i/n, φ2(i))`.
pub fn hammersley(n: usize) -> PointSet {
    let coords = (0..n)
        .flat_map(|i| [i as f64 / n as f64, van_der_corput(i as u64)])
        .collect();
    PointSet::new(2, coords).unwrap()
}

/// The closed forms, written as plain double loops over all (i, j).
pub fn direct(p: &PointSet, m: L2Method) -> f64 {
    let (n, d) = (p.len() as f64, p.dims() as i32);
    let z = |x: f64| (x - 0.5).abs();
    let (mut s1, mut s2) = (0.0, 0.0);
    for a in p.iter() {
        s1 += a
            .iter()
            .map(|&x| match m {
                L2Method::L2Star => 1.0 - x * x,
                L2Method::Centered => 1.0 + z(x) / 2.0 - z(x) * z(x) / 2.0,
                L2Method::WrapAround => 0.0,
                L2Method::Mixture => 5.0 / 3.0 - z(x) / 4.0 - z(x) * z(x) / 4.0,
            })
            .product::<f64>();
        for b in p.iter() {
            s2 += a
                .iter()
                .zip(b)
                .map(|(&x, &y)| {
                    let t = (x - y).abs();
                    match m {
                        L2Method::L2Star => 1.0 - x.max(y),
                        L2Method::Centered => 1.0 + z(x) / 2.0 + z(y) / 2.0 - t / 2.0,
                        L2Method::WrapAround => 1.5 - t + t * t,
                        L2Method::Mixture => {
                            1.875 - z(x) / 4.0 - z(y) / 4.0 - 0.75 * t + t * t / 2.0
                        }
                    }
                })
                .product::<f64>();
        }
    }
    let (s1, s2) = (s1 / n, s2 / (n * n));
    match m {
        L2Method::L2Star => (3f64.powi(-d) - 2f64.powi(1 - d) * s1 + s2).sqrt(),
        L2Method::Centered => (13.0f64 / 12.0).powi(d) - 2.0 * s1 + s2,
        L2Method::WrapAround => -(4.0f64 / 3.0).powi(d) + s2,
        L2Method::Mixture => (19.0f64 / 12.0).powi(d) - 2.0 * s1 + s2,
    }
}
