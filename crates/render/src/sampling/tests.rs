//! Tests of the tabulated distributions: exact small cases, sampled pdf ==
//! evaluated pdf, and chi-square histogram checks.

use super::*;
use crate::math::Point2;

/// A small deterministic generator for tests (SplitMix64).
pub(crate) struct TestRng(u64);

impl TestRng {
    pub(crate) fn new(seed: u64) -> Self {
        TestRng(seed)
    }
    pub(crate) fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        lowdisc::hash::mix64(self.0)
    }
    /// Uniform in `[0, 1)`.
    pub(crate) fn uniform(&mut self) -> f32 {
        (self.next_u64() >> 40) as f32 / (1u64 << 24) as f32
    }
    pub(crate) fn pair(&mut self) -> [f32; 2] {
        [self.uniform(), self.uniform()]
    }
}

/// Pearson's chi-square statistic of `observed` against `expected` counts,
/// pooling bins with expected count below 5 into one; returns (stat, dof).
pub(crate) fn chi_square(observed: &[f64], expected: &[f64]) -> (f64, usize) {
    let (mut stat, mut bins) = (0.0, 0usize);
    let (mut po, mut pe) = (0.0, 0.0);
    for (&o, &e) in observed.iter().zip(expected) {
        if e < 5.0 {
            po += o;
            pe += e;
            if e == 0.0 {
                assert_eq!(o, 0.0, "a sample fell where the expected count is 0");
            }
        } else {
            stat += (o - e) * (o - e) / e;
            bins += 1;
        }
    }
    if pe > 0.0 {
        stat += (po - pe) * (po - pe) / pe;
        bins += 1;
    }
    (stat, bins.saturating_sub(1))
}

/// Passes when the statistic is below `dof + 5 sqrt(2 dof)` (about the
/// 99.9999th percentile for the dof used here).
pub(crate) fn assert_chi_square(observed: &[f64], expected: &[f64]) {
    let (stat, dof) = chi_square(observed, expected);
    let limit = dof as f64 + 5.0 * (2.0 * dof as f64).sqrt();
    assert!(
        stat < limit,
        "chi-square {stat:.1} over {dof} dof exceeds {limit:.1}"
    );
}

fn bumpy(n: usize) -> Vec<f32> {
    (0..n)
        .map(|i| {
            if i % 7 == 3 {
                0.0
            } else {
                1.0 + (i as f32 * 0.37).sin().powi(2) * 5.0
            }
        })
        .collect()
}

#[test]
fn small_exact_case() {
    let d = Distribution1D::new(&[1.0, 3.0]).unwrap();
    assert_eq!(d.integral(), 2.0);
    let s = d.sample_continuous(0.5);
    assert_eq!(s.offset, 1);
    assert!((s.x - 2.0 / 3.0).abs() < 1e-6, "{s:?}");
    assert_eq!(s.pdf, 1.5);
    assert_eq!(d.pdf(0.2), 0.5);
    assert_eq!(d.pmf(0), 0.25);
    let k = d.sample_discrete(0.25);
    assert_eq!((k.index, k.pmf, k.u_remapped), (1, 0.75, 0.0));
    assert_eq!(d.pmf(2), 0.0);
}

#[test]
fn rejects_empty_and_bad_domains() {
    assert!(Distribution1D::new(&[]).is_none());
    assert!(Distribution1D::with_domain(&[1.0], 1.0, 1.0).is_none());
    assert!(Distribution1D::with_domain(&[1.0], 0.0, f32::NAN).is_none());
    assert!(Distribution2D::new(&[1.0; 5], 2, 2).is_none());
    assert!(Distribution2D::new(&[], 0, 0).is_none());
}

#[test]
fn all_zero_is_uniform_with_zero_integral() {
    let d = Distribution1D::with_domain(&[0.0, 0.0, f32::NAN, 0.0], 2.0, 6.0).unwrap();
    assert!(d.is_all_zero());
    assert_eq!(d.integral(), 0.0);
    let s = d.sample_continuous(0.6);
    assert!((s.x - 4.4).abs() < 1e-5);
    assert_eq!(s.pdf, 0.25);
    assert_eq!(d.pmf(3), 0.25);
    let d2 = Distribution2D::new(&[0.0; 6], 3, 2).unwrap();
    let (p, pdf) = d2.sample([0.3, 0.9]);
    assert!((p.x - 0.3).abs() < 1e-6 && (p.y - 0.9).abs() < 1e-6);
    assert_eq!((pdf, d2.pdf(p)), (1.0, 1.0));
}

#[test]
fn bad_inputs_are_clamped() {
    let d = Distribution1D::new(&bumpy(10)).unwrap();
    for u in [f32::NAN, -1.0, 1.0, 2.0, f32::INFINITY] {
        let s = d.sample_continuous(u);
        assert!((0.0..=1.0).contains(&s.x) && s.pdf > 0.0, "{u}: {s:?}");
        assert!(d.sample_discrete(u).index < 10);
    }
    assert_eq!(d.pdf(-0.1), 0.0);
    assert_eq!(d.pdf(f32::NAN), 0.0);
}

#[test]
fn sampling_is_monotone_and_skips_zero_bins() {
    let f = bumpy(23);
    let d = Distribution1D::with_domain(&f, -1.0, 3.0).unwrap();
    let mut last = f32::NEG_INFINITY;
    for i in 0..=4096 {
        let s = d.sample_continuous(i as f32 / 4096.0);
        assert!(s.x >= last, "not monotone at {i}");
        last = s.x;
        assert!(f[s.offset] > 0.0, "sampled a zero bin");
        assert_eq!(s.pdf, d.pdf(s.x), "sampled pdf differs at {s:?}");
    }
    let total: f32 = (0..23).map(|i| d.pmf(i)).sum();
    assert!((total - 1.0).abs() < 1e-5);
}

#[test]
fn continuous_and_discrete_histograms_match() {
    let f = bumpy(40);
    let d = Distribution1D::new(&f).unwrap();
    let n = 200_000;
    let mut rng = TestRng::new(7);
    let (mut hc, mut hd) = (vec![0.0; 40], vec![0.0; 40]);
    for _ in 0..n {
        let s = d.sample_continuous(rng.uniform());
        hc[((s.x * 40.0) as usize).min(39)] += 1.0;
        hd[d.sample_discrete(rng.uniform()).index] += 1.0;
    }
    let sum: f32 = f.iter().sum();
    let expected: Vec<f64> = f.iter().map(|&v| n as f64 * (v / sum) as f64).collect();
    assert_chi_square(&hc, &expected);
    assert_chi_square(&hd, &expected);
}

fn grid(w: usize, h: usize) -> Vec<f32> {
    (0..w * h)
        .map(|i| {
            let (x, y) = ((i % w) as f32, (i / w) as f32);
            let spot = (-((x - 5.0).powi(2) + (y - 3.0).powi(2)) / 4.0).exp() * 50.0;
            if (i * 13) % 17 == 0 {
                0.0
            } else {
                0.1 + spot + 0.05 * x
            }
        })
        .collect()
}

#[test]
fn distribution_2d_pdf_matches_and_normalises() {
    let (w, h) = (16, 9);
    let f = grid(w, h);
    let d = Distribution2D::new(&f, w, h).unwrap();
    let total: f32 = f.iter().sum();
    assert!((d.integral() - total / (w * h) as f32).abs() < 1e-4);
    // Density integrates to 1 over the square (cell centres).
    let mut integral = 0.0f64;
    for y in 0..h {
        for x in 0..w {
            let p = Point2::new((x as f32 + 0.5) / w as f32, (y as f32 + 0.5) / h as f32);
            integral += d.pdf(p) as f64 / (w * h) as f64;
        }
    }
    assert!((integral - 1.0).abs() < 1e-5, "{integral}");
    let mut rng = TestRng::new(11);
    let n = 300_000;
    let mut hist = vec![0.0; w * h];
    for _ in 0..n {
        let (p, pdf) = d.sample(rng.pair());
        let ev = d.pdf(p);
        assert!(
            (pdf - ev).abs() <= 1e-5 * ev,
            "sampled {pdf} vs evaluated {ev} at {p:?}"
        );
        let (cx, cy) = (
            ((p.x * w as f32) as usize).min(w - 1),
            ((p.y * h as f32) as usize).min(h - 1),
        );
        assert!(f[cy * w + cx] > 0.0, "sampled a zero cell");
        hist[cy * w + cx] += 1.0;
    }
    let expected: Vec<f64> = f.iter().map(|&v| n as f64 * (v / total) as f64).collect();
    assert_chi_square(&hist, &expected);
}
