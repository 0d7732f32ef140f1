//! Shared helpers of the integration tests: seeded point sets and structured sets.
#![allow(dead_code)]

use lowdisc_metrics::PointSet;

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
