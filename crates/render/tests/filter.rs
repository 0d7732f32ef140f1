//! Pixel filters: integrals, importance sampling (mean weight = integral,
//! offsets in range, histogram following |f| by a chi-square test), pbrt
//! names and defaults.

use lowdisc_render::filter::{Filter, FilterParams};

/// SplitMix64 (Steele, Lea & Flood 2014), a seeded source of `[0,1)` floats.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f32 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        (lowdisc::hash::mix64(self.0) >> 40) as f32 * (1.0 / 16_777_216.0)
    }
    fn u2(&mut self) -> [f32; 2] {
        [self.next(), self.next()]
    }
}

fn all_filters() -> Vec<(&'static str, Filter)> {
    ["box", "gaussian", "triangle", "mitchell", "sinc"]
        .into_iter()
        .map(|n| (n, Filter::create(n, &FilterParams::default()).unwrap()))
        .collect()
}

/// Numerical `∫∫ g` over `[x0,x1] x [y0,y1]` (midpoint rule, n x n).
fn integrate(g: impl Fn(f32, f32) -> f64, x: [f64; 2], y: [f64; 2], n: usize) -> f64 {
    let (hx, hy) = ((x[1] - x[0]) / n as f64, (y[1] - y[0]) / n as f64);
    let mut s = 0.0;
    for j in 0..n {
        for i in 0..n {
            s += g(
                (x[0] + (i as f64 + 0.5) * hx) as f32,
                (y[0] + (j as f64 + 0.5) * hy) as f32,
            );
        }
    }
    s * hx * hy
}

#[test]
fn defaults_and_radii_follow_pbrt() {
    let radii: Vec<[f32; 2]> = all_filters().iter().map(|(_, f)| f.radius()).collect();
    assert_eq!(
        radii,
        vec![[0.5, 0.5], [1.5, 1.5], [2.0, 2.0], [2.0, 2.0], [4.0, 4.0]]
    );
    let p = FilterParams {
        x_radius: Some(1.0),
        ..Default::default()
    };
    assert_eq!(Filter::create("triangle", &p).unwrap().radius(), [1.0, 2.0]);
    assert!(Filter::create("catmull-rom", &p).is_err());
    assert!(
        Filter::create(
            "box",
            &FilterParams {
                x_radius: Some(-1.0),
                ..Default::default()
            }
        )
        .is_err()
    );
    assert!(
        Filter::create(
            "gaussian",
            &FilterParams {
                sigma: Some(0.0),
                ..Default::default()
            }
        )
        .is_err()
    );
}

#[test]
fn analytic_integrals_match_quadrature() {
    for (name, f) in all_filters() {
        let [rx, ry] = f.radius().map(f64::from);
        let q = integrate(
            |x, y| f64::from(f.evaluate([x, y])),
            [-rx, rx],
            [-ry, ry],
            1000,
        );
        let exact = f.integral();
        assert!(
            (q - exact).abs() < 1e-4 * exact.abs().max(1e-3),
            "{name}: quadrature {q} vs {exact}"
        );
    }
    // pbrt-v4 gaussian: (g(x) - g(r))+, so the filter vanishes at the radius.
    let g = Filter::default();
    assert_eq!(g.evaluate([1.5, 0.0]), 0.0);
    assert!(g.evaluate([1.49, 0.0]) > 0.0);
    // Mitchell with B = C = 1/3 integrates to r^2 / 4 and has negative lobes.
    let m = Filter::create("mitchell", &FilterParams::default()).unwrap();
    assert!((m.integral() - 1.0).abs() < 1e-12);
    assert!(m.evaluate([1.5, 0.0]) < 0.0);
}

#[test]
fn box_offsets_are_in_the_half_open_pixel() {
    let f = Filter::box_filter([0.5, 0.5]).unwrap();
    let below_one = 1.0 - f32::EPSILON / 2.0;
    for u in [[0.0, 0.0], [below_one, below_one], [0.5, 0.25]] {
        let s = f.sample(u);
        for o in s.offset {
            assert!((-0.5..0.5).contains(&o), "{o}");
        }
        assert_eq!(s.weight, 1.0);
    }
    assert_eq!(f.sample([0.5, 0.25]).offset, [0.0, -0.25]);
}

#[test]
fn sampling_mean_weight_is_the_integral() {
    let n = 200_000;
    for (name, f) in all_filters() {
        let mut rng = Rng(17);
        let r = f.radius();
        let (mut sum, mut sum2) = (0.0f64, 0.0f64);
        let first = f.sample([0.3, 0.6]).weight;
        let positive = !matches!(name, "mitchell" | "sinc");
        for _ in 0..n {
            let s = f.sample(rng.u2());
            assert!(
                s.offset[0].abs() <= r[0] && s.offset[1].abs() <= r[1],
                "{name}: {:?}",
                s.offset
            );
            if positive {
                assert_eq!(
                    s.weight, first,
                    "{name}: weights of a positive filter are constant"
                );
            }
            sum += f64::from(s.weight);
            sum2 += f64::from(s.weight) * f64::from(s.weight);
        }
        let mean = sum / n as f64;
        let sd = ((sum2 / n as f64 - mean * mean).max(0.0) / n as f64).sqrt();
        // Tabulation (32 cells per unit radius) changes the integral by < 0.1%.
        let tol = 4.0 * sd + 1e-3 * f.integral().abs();
        assert!(
            (mean - f.integral()).abs() < tol,
            "{name}: mean weight {mean} vs integral {}",
            f.integral()
        );
    }
}

#[test]
fn analytic_weights_are_f_over_pdf() {
    let mut rng = Rng(5);
    for name in ["box", "triangle"] {
        let f = Filter::create(name, &FilterParams::default()).unwrap();
        for _ in 0..1000 {
            let s = f.sample(rng.u2());
            let ratio = f.evaluate(s.offset) / f.pdf(s.offset);
            assert!(
                (ratio - s.weight).abs() < 1e-3 * s.weight,
                "{name}: {ratio} vs {}",
                s.weight
            );
        }
    }
}

/// Wilson-Hilferty approximation of the chi-square quantile for `k` degrees of
/// freedom at the normal quantile `z`.
fn chi2_quantile(k: f64, z: f64) -> f64 {
    let a = 2.0 / (9.0 * k);
    k * (1.0 - a + z * a.sqrt()).powi(3)
}

#[test]
fn sample_histograms_follow_abs_f() {
    const BINS: usize = 8;
    let n = 200_000usize;
    for (name, f) in all_filters() {
        let [rx, ry] = f.radius();
        let mut counts = vec![0f64; BINS * BINS];
        let mut rng = Rng(99);
        for _ in 0..n {
            let o = f.sample(rng.u2()).offset;
            let i =
                (((o[0] + rx) / (2.0 * rx)) * BINS as f32).clamp(0.0, BINS as f32 - 1.0) as usize;
            let j =
                (((o[1] + ry) / (2.0 * ry)) * BINS as f32).clamp(0.0, BINS as f32 - 1.0) as usize;
            counts[j * BINS + i] += 1.0;
        }
        // Expected counts from |f| itself, integrated per bin.
        let (bx, by) = (
            2.0 * f64::from(rx) / BINS as f64,
            2.0 * f64::from(ry) / BINS as f64,
        );
        let mut mass = vec![0f64; BINS * BINS];
        for j in 0..BINS {
            for i in 0..BINS {
                let x0 = -f64::from(rx) + i as f64 * bx;
                let y0 = -f64::from(ry) + j as f64 * by;
                mass[j * BINS + i] = integrate(
                    |x, y| f64::from(f.evaluate([x, y]).abs()),
                    [x0, x0 + bx],
                    [y0, y0 + by],
                    64,
                );
            }
        }
        let total: f64 = mass.iter().sum();
        // Pool bins expecting fewer than 5 samples into one.
        let (mut chi2, mut dof) = (0.0, 0usize);
        let (mut pooled_obs, mut pooled_exp) = (0.0, 0.0);
        for (c, m) in counts.iter().zip(&mass) {
            let e = m / total * n as f64;
            if e < 5.0 {
                pooled_obs += c;
                pooled_exp += e;
            } else {
                chi2 += (c - e) * (c - e) / e;
                dof += 1;
            }
        }
        if pooled_exp >= 5.0 {
            chi2 += (pooled_obs - pooled_exp) * (pooled_obs - pooled_exp) / pooled_exp;
            dof += 1;
        } else {
            assert!(
                pooled_obs <= 20.0,
                "{name}: {pooled_obs} samples where |f| is ~0"
            );
        }
        let limit = chi2_quantile((dof - 1) as f64, 3.7); // p ~ 1e-4
        assert!(
            chi2 < limit,
            "{name}: chi2 {chi2} over {dof} bins exceeds {limit}"
        );
    }
}

#[test]
fn gaussian_sampling_follows_f_not_a_uniform_disk() {
    // A histogram test that must fail for a wrong sampler: the central 1/9 of
    // the gaussian's square holds much more than 1/9 of the samples.
    let f = Filter::default();
    let mut rng = Rng(3);
    let n = 10_000;
    let inner = (0..n)
        .filter(|_| f.sample(rng.u2()).offset.iter().all(|o| o.abs() < 0.5))
        .count();
    let want = integrate(
        |x, y| f64::from(f.evaluate([x, y])),
        [-0.5, 0.5],
        [-0.5, 0.5],
        200,
    ) / f.integral();
    assert!(want > 0.4, "{want}"); // a uniform square would give 1/9
    assert!(
        (inner as f64 / n as f64 - want).abs() < 0.02,
        "{inner} vs {want}"
    );
}

#[test]
fn pinned_samples_never_drift() {
    // Renders must stay reproducible: these values were recorded once.
    // Mitchell is pure polynomial arithmetic, so its bits are portable.
    let m = Filter::create("mitchell", &FilterParams::default())
        .unwrap()
        .sample([0.05, 0.999]);
    assert_eq!(m.offset.map(f32::to_bits), [3208913362, 1071836084]);
    assert_eq!(m.weight.to_bits(), 3214052106);
    // The gaussian goes through `exp`, whose last bit may differ between
    // maths libraries: compare to a tight tolerance instead.
    let g = Filter::default().sample([0.05, 0.999]);
    let want = [f32::from_bits(3209394680), f32::from_bits(1068197274)];
    for (a, b) in g.offset.iter().zip(want) {
        assert!((a - b).abs() < 1e-6, "{a} vs {b}");
    }
    assert!((g.weight - f32::from_bits(1064385334)).abs() < 1e-6);
}
