//! Monte Carlo and analytic checks of every BxDF: sampled pdf and value
//! equal the evaluated ones, albedo never exceeds 1, BSDF sampling is
//! unbiased against uniform sphere sampling, the pdf integrates to the
//! probability that sampling succeeds, reflection is reciprocal, and the
//! exact (delta and analytic) cases are in `bsdf_exact.rs`.
//!
//! Noise bounds: every Monte Carlo comparison uses the sample standard
//! error `σ` of the estimate and allows `5σ` (plus a small absolute slack
//! for float rounding), with seeded PCG32 streams, so the tests are
//! deterministic.

use lowdisc::pcg::Pcg32;
use lowdisc_render::bsdf::{
    Bxdf, BxdfModel, ConductorSpec, Material, Roughness, SampleFlags, TransportMode,
};
use lowdisc_render::math::Point2;
use lowdisc_render::math::Vec3;
use lowdisc_render::math::sampling::sample_uniform_sphere;
use lowdisc_render::spectrum::Rgb;
use std::f64::consts::PI;

const RAD: TransportMode = TransportMode::Radiance;
const ALL: SampleFlags = SampleFlags::All;

/// Running mean and standard error, per channel.
#[derive(Default)]
struct Est {
    n: f64,
    s: [f64; 3],
    s2: [f64; 3],
}

impl Est {
    fn add(&mut self, v: [f64; 3]) {
        self.n += 1.0;
        for (c, x) in v.into_iter().enumerate() {
            self.s[c] += x;
            self.s2[c] += x * x;
        }
    }
    fn mean(&self, c: usize) -> f64 {
        self.s[c] / self.n
    }
    fn err(&self, c: usize) -> f64 {
        let m = self.mean(c);
        ((self.s2[c] / self.n - m * m).max(0.0) / self.n).sqrt()
    }
}

fn rgb64(c: Rgb) -> [f64; 3] {
    [c.r as f64, c.g as f64, c.b as f64]
}

fn dir(theta_deg: f32, phi_deg: f32) -> Vec3 {
    let (t, p) = (theta_deg.to_radians(), phi_deg.to_radians());
    Vec3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos())
}

/// The materials with non-delta lobes under test, with a label.
fn glossy_cases() -> Vec<(&'static str, Bxdf)> {
    let rough = |r: f32| Roughness::isotropic(r, false);
    let aniso = Roughness {
        u: 0.15,
        v: 0.6,
        remap: false,
    };
    let mats = vec![
        (
            "diffuse",
            Material::Diffuse {
                reflectance: Rgb::new(0.2, 0.5, 0.9).into(),
            },
        ),
        (
            "difftrans",
            Material::DiffuseTransmission {
                reflectance: Rgb::new(0.3, 0.1, 0.5).into(),
                transmittance: Rgb::new(0.6, 0.2, 0.4).into(),
                scale: 1.0,
            },
        ),
        (
            "gold a0.3",
            Material::Conductor {
                spec: ConductorSpec::named("Au").unwrap().into(),
                roughness: rough(0.3).into(),
            },
        ),
        (
            "alu aniso",
            Material::Conductor {
                spec: ConductorSpec::named("Al").unwrap().into(),
                roughness: aniso.into(),
            },
        ),
        (
            "refl a0.8",
            Material::Conductor {
                spec: ConductorSpec::Reflectance(Rgb::new(0.9, 0.6, 0.3)).into(),
                roughness: rough(0.8).into(),
            },
        ),
        (
            "glass a0.3",
            Material::Dielectric {
                eta: 1.5,
                roughness: rough(0.3).into(),
            },
        ),
        (
            "water aniso",
            Material::Dielectric {
                eta: 1.33,
                roughness: aniso.into(),
            },
        ),
        (
            "inv a0.5",
            Material::Dielectric {
                eta: 1.0 / 1.5,
                roughness: rough(0.5).into(),
            },
        ),
    ];
    mats.into_iter().map(|(n, m)| (n, m.bxdf(7))).collect()
}

fn layered_cases() -> Vec<(&'static str, Bxdf)> {
    let mut cd = Material::pbrt_default("coateddiffuse").unwrap();
    if let Material::CoatedDiffuse { reflectance, .. } = &mut cd {
        *reflectance = Rgb::new(0.9, 0.5, 0.1).into();
    }
    let rough_cd = Material::CoatedDiffuse {
        reflectance: Rgb::splat(1.0).into(),
        roughness: Roughness::isotropic(0.3, false).into(),
        thickness: 0.01.into(),
        eta: 1.5,
        max_depth: 10,
        n_samples: 1,
    };
    let cc = Material::CoatedConductor {
        interface_roughness: Roughness::isotropic(0.2, false).into(),
        interface_eta: 1.5,
        thickness: 0.01.into(),
        conductor: ConductorSpec::named("Au").unwrap().into(),
        conductor_roughness: Roughness::isotropic(0.3, false).into(),
        max_depth: 10,
        n_samples: 1,
    };
    vec![
        ("coated diffuse smooth", cd.bxdf(3)),
        ("coated diffuse rough", rough_cd.bxdf(3)),
        ("coated gold", cc.bxdf(3)),
    ]
}

/// Outgoing directions: near normal, oblique, grazing, and from below.
fn wos() -> Vec<Vec3> {
    vec![
        dir(10.0, 20.0),
        dir(50.0, 130.0),
        dir(80.0, 250.0),
        dir(120.0, 40.0),
        dir(170.0, 300.0),
    ]
}

fn close(a: f32, b: f32, rel: f32) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs()) + 1e-6
}

#[test]
fn sampled_pdf_and_value_equal_the_evaluated_ones() {
    for (name, b) in glossy_cases() {
        for (k, wo) in wos().into_iter().enumerate() {
            let mut rng = Pcg32::new(11, k as u64);
            let (mut n, mut bad) = (0, 0);
            for _ in 0..20_000 {
                let (uc, u) = (rng.next_f32(), [rng.next_f32(), rng.next_f32()]);
                let Some(s) = b.sample_f(wo, uc, u, RAD, ALL) else {
                    continue;
                };
                n += 1;
                let pdf = b.pdf(wo, s.wi, RAD, ALL);
                let f = b.f(wo, s.wi, RAD);
                let ok = close(pdf, s.pdf, 2e-3)
                    && (0..3).all(|c| close(f[c], s.f[c], 2e-3))
                    && !s.pdf_is_proportional;
                if !ok {
                    bad += 1;
                    assert!(
                        bad < 3,
                        "{name} wo={wo:?} wi={:?}: pdf {} vs {pdf}, f {:?} vs {f:?}",
                        s.wi,
                        s.pdf,
                        s.f
                    );
                }
            }
            // Float rounding at grazing half vectors may spoil one in 10^4.
            assert!(bad * 10_000 <= n.max(1), "{name}: {bad} of {n} disagree");
            assert!(n > 1000, "{name} wo={wo:?}: only {n} samples succeeded");
        }
    }
}

/// Sampled estimates of ∫ f |cos| dω (the directional albedo): all samples,
/// and only the non-delta ones (what uniform sampling can see).
fn albedo_sampled_split(
    b: &Bxdf,
    wo: Vec3,
    n: usize,
    seed: u64,
    mode: TransportMode,
) -> (Est, Est) {
    let mut rng = Pcg32::new(seed, 1);
    let (mut all, mut smooth_free) = (Est::default(), Est::default());
    for _ in 0..n {
        let (uc, u) = (rng.next_f32(), [rng.next_f32(), rng.next_f32()]);
        match b.sample_f(wo, uc, u, mode, ALL) {
            Some(s) if s.pdf > 0.0 => {
                let w = rgb64(s.f * (s.wi.z.abs() / s.pdf));
                all.add(w);
                smooth_free.add(if s.is_specular() { [0.0; 3] } else { w });
            }
            _ => {
                all.add([0.0; 3]);
                smooth_free.add([0.0; 3]);
            }
        }
    }
    (all, smooth_free)
}

fn albedo_sampled(b: &Bxdf, wo: Vec3, n: usize, seed: u64) -> Est {
    albedo_sampled_split(b, wo, n, seed, RAD).0
}

/// Uniform-sphere estimates of ∫ f |cos| dω and of ∫ pdf dω.
fn uniform_estimates(b: &Bxdf, wo: Vec3, n: usize, seed: u64) -> (Est, Est) {
    uniform_estimates_mode(b, wo, n, seed, RAD)
}

fn uniform_estimates_mode(
    b: &Bxdf,
    wo: Vec3,
    n: usize,
    seed: u64,
    mode: TransportMode,
) -> (Est, Est) {
    let mut rng = Pcg32::new(seed, 2);
    let (mut ef, mut ep) = (Est::default(), Est::default());
    for _ in 0..n {
        let wi = sample_uniform_sphere(Point2::new(rng.next_f32(), rng.next_f32()));
        let w = 4.0 * PI;
        ef.add(rgb64(b.f(wo, wi, mode) * wi.z.abs()).map(|x| x * w));
        let p = b.pdf(wo, wi, mode, ALL) as f64 * w;
        ep.add([p; 3]);
    }
    (ef, ep)
}

/// Albedo (importance transport: no `1/η²` radiance scaling, so energy
/// conservation applies) at most 1, and, in both transport modes, the
/// non-delta part of the sampled estimate equal to the uniform estimate.
fn check_albedo_and_unbiased(name: &str, b: &Bxdf, wo: Vec3, n_s: usize, n_u: usize) {
    for mode in [TransportMode::Importance, RAD] {
        let (a, a_glossy) = albedo_sampled_split(b, wo, n_s, 5, mode);
        let (u, _) = uniform_estimates_mode(b, wo, n_u, 6, mode);
        for c in 0..3 {
            let (m, e) = (a.mean(c), a.err(c));
            if mode == TransportMode::Importance {
                assert!(
                    m <= 1.0 + 5.0 * e + 1e-4,
                    "{name} wo={wo:?}: albedo {m} ± {e}"
                );
            }
            let (m, e) = (a_glossy.mean(c), a_glossy.err(c));
            let (mu, eu) = (u.mean(c), u.err(c));
            let tol = 5.0 * (e * e + eu * eu).sqrt() + 2e-3;
            assert!(
                (m - mu).abs() <= tol,
                "{name} {mode:?} wo={wo:?} ch{c}: sampled {m} ± {e}, uniform {mu} ± {eu}"
            );
        }
    }
}

#[test]
fn albedo_at_most_one_and_sampling_unbiased() {
    for (name, b) in glossy_cases() {
        for wo in wos() {
            check_albedo_and_unbiased(name, &b, wo, 100_000, 400_000);
        }
    }
}

#[test]
fn layered_albedo_at_most_one_and_sampling_unbiased() {
    for (name, b) in layered_cases() {
        for wo in [dir(15.0, 0.0), dir(60.0, 100.0), dir(150.0, 200.0)] {
            check_albedo_and_unbiased(name, &b, wo, 50_000, 200_000);
        }
    }
}

#[test]
fn lambertian_albedo_is_exactly_r() {
    let r = Rgb::new(0.2, 0.5, 0.9);
    let b = Material::diffuse(r).bxdf(0);
    for wo in wos() {
        let a = albedo_sampled(&b, wo, 2_000, 9);
        for c in 0..3 {
            assert!(
                (a.mean(c) - r[c] as f64).abs() < 1e-5,
                "{wo:?}: {}",
                a.mean(c)
            );
        }
        let (u, _) = uniform_estimates(&b, wo, 200_000, 10);
        assert!((u.mean(1) - 0.5).abs() < 5.0 * u.err(1), "{}", u.mean(1));
    }
}

#[test]
fn pdf_integrates_to_the_sampling_success_rate() {
    let mut cases = glossy_cases();
    cases.extend(layered_cases());
    for (name, b) in cases {
        for wo in wos() {
            let (_, p) = uniform_estimates(&b, wo, 200_000, 12);
            let (m, e) = (p.mean(0), p.err(0));
            if matches!(b, Bxdf::CoatedDiffuse(_) | Bxdf::CoatedConductor(_)) {
                // pbrt-v4's layered pdf is an approximation for MIS weights
                // only: it measures the base's density in the layer's solid
                // angle, without the refraction Jacobian, so it may integrate
                // above 1 (about 1.55 for a smooth coat on a diffuse base).
                // Only sanity is checked here.
                assert!(
                    m.is_finite() && m > 0.3 && m < 2.5,
                    "{name} wo={wo:?}: ∫pdf = {m}"
                );
                continue;
            }
            assert!(
                m <= 1.0 + 5.0 * e + 1e-3,
                "{name} wo={wo:?}: ∫pdf = {m} ± {e}"
            );
            let mut rng = Pcg32::new(13, 0);
            let n = 100_000;
            let ok = (0..n)
                .filter(|_| {
                    let (uc, u) = (rng.next_f32(), [rng.next_f32(), rng.next_f32()]);
                    b.sample_f(wo, uc, u, RAD, ALL).is_some()
                })
                .count() as f64
                / n as f64;
            let tol = 5.0 * e + 5.0 * (ok * (1.0 - ok) / n as f64).sqrt() + 1e-3;
            assert!(
                (m - ok).abs() <= tol,
                "{name} wo={wo:?}: ∫pdf {m} ± {e} vs success {ok}"
            );
        }
    }
}

#[test]
fn reflection_is_reciprocal() {
    let mut rng = Pcg32::new(21, 0);
    for (name, b) in glossy_cases() {
        for _ in 0..2_000 {
            let a = sample_uniform_sphere(Point2::new(rng.next_f32(), rng.next_f32()));
            let c = sample_uniform_sphere(Point2::new(rng.next_f32(), rng.next_f32()));
            let c = if a.z * c.z < 0.0 {
                Vec3::new(c.x, c.y, -c.z)
            } else {
                c
            };
            let (f1, f2) = (b.f(a, c, RAD), b.f(c, a, RAD));
            for ch in 0..3 {
                assert!(
                    close(f1[ch], f2[ch], 1e-3),
                    "{name}: f({a:?},{c:?}) {f1:?} vs {f2:?}"
                );
            }
        }
    }
}
