//! Sphere area lights sampled by solid angle (the cone of directions the
//! sphere subtends) from outside, by area from inside: the sampled pdf
//! equals `pdf_li` for the same direction, the cone pdf is
//! `1 / (2π (1 - cos θmax))`, every sample lands on the visible cap, and the
//! irradiance estimate matches the analytic `π L (r/d)²`.

mod common;

use lowdisc_render::geometry::Sphere;
use lowdisc_render::light::{AreaShape, DiffuseAreaLight, Light, LightSampleContext};
use lowdisc_render::math::{Point2, Point3, Transform, Vec3};
use lowdisc_render::spectrum::Rgb;
use std::f64::consts::PI;

fn sphere_light(centre: Point3, r: f32, reverse: bool) -> (Sphere, Light) {
    let s = Sphere::new(Transform::translate(centre), r, reverse).unwrap();
    let light = Light::Area(
        DiffuseAreaLight::new(AreaShape::Sphere(s.clone()), Rgb::splat(3.0), 1.0, false).unwrap(),
    );
    (s, light)
}

/// `n × n` jittered strata.
fn strata(n: usize, rng: &mut common::Rng) -> Vec<[f32; 2]> {
    let mut v = Vec::with_capacity(n * n);
    for i in 0..n {
        for j in 0..n {
            v.push([
                (i as f32 + rng.f32()) / n as f32,
                (j as f32 + rng.f32()) / n as f32,
            ]);
        }
    }
    v
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn cone_pdf_matches_pdf_li_and_the_closed_form() {
    let mut rng = common::Rng::new(7);
    // From a grazing distance to a tiny, distant sphere (sin θmax = 1e-3,
    // below pbrt's small-angle threshold).
    for (r, d) in [(1.0f32, 1.05f32), (1.0, 2.0), (0.5, 10.0), (0.01, 10.0)] {
        let (s, light) = sphere_light(Point3::new(0.0, 0.0, d), r, false);
        let ctx = LightSampleContext::new(Point3::ZERO, Vec3::Z, Vec3::Z);
        let sin2 = (r as f64 / d as f64).powi(2);
        let one_minus_cos = 1.0 - (1.0 - sin2).sqrt();
        let want = 1.0 / (2.0 * PI * one_minus_cos);
        let pdf = s.pdf_solid_angle(ctx.p).unwrap() as f64;
        assert!(rel(pdf, want) < 1e-3, "r {r} d {d}: {pdf} vs {want}");
        let mut checked = 0;
        for _ in 0..500 {
            let u = [rng.f32(), rng.f32()];
            let Some(ls) = light.sample_li(&ctx, u) else {
                continue;
            };
            // Every sample is on the cap facing the point (outward normal).
            assert!(ls.n_light.dot(-ls.wi) > -1e-3, "{ls:?}");
            assert_eq!(ls.pdf.to_bits(), (pdf as f32).to_bits());
            assert_eq!(
                light.pdf_li_hit(&ctx, ls.p_light, ls.n_light).to_bits(),
                ls.pdf.to_bits()
            );
            // The direction hits the sphere, and pdf_li agrees (away from
            // the silhouette, where the hit is numerically stable).
            if ls.n_light.dot(-ls.wi) > 1e-2 {
                let p = light.pdf_li(&ctx, ls.wi);
                assert!(rel(p as f64, ls.pdf as f64) < 1e-6, "{p} vs {}", ls.pdf);
                checked += 1;
            }
        }
        assert!(checked > 400, "r {r} d {d}: {checked}");
        // A direction missing the sphere has density 0.
        assert_eq!(light.pdf_li(&ctx, Vec3::new(1.0, 0.0, 0.0)), 0.0);
    }
}

#[test]
fn irradiance_from_a_sphere_light_is_pi_l_r2_over_d2() {
    let mut rng = common::Rng::new(11);
    for (r, d) in [(1.0f32, 1.2f32), (1.0, 4.0), (0.2, 10.0), (0.01, 30.0)] {
        let (_, light) = sphere_light(Point3::new(0.0, 0.0, d), r, false);
        let ctx = LightSampleContext::new(Point3::ZERO, Vec3::Z, Vec3::Z);
        let samples = strata(32, &mut rng);
        let (mut sum, mut sum2) = (0.0f64, 0.0f64);
        for &u in &samples {
            let e = light
                .sample_li(&ctx, u)
                .map_or(0.0, |s| (s.l.r * s.wi.dot(ctx.n).max(0.0) / s.pdf) as f64);
            sum += e;
            sum2 += e * e;
        }
        let n = samples.len() as f64;
        let mean = sum / n;
        let exact = PI * 3.0 * (r as f64 / d as f64).powi(2);
        assert!(rel(mean, exact) < 2e-3, "r {r} d {d}: {mean} vs {exact}");
        // Only cos θ varies, uniformly over [cos θmax, 1], so the relative
        // spread of single samples is (1 - c) / √12 / ((1 + c) / 2) (area
        // sampling would put half of them on the far side: about 1).
        let c = (1.0 - (r as f64 / d as f64).powi(2)).sqrt();
        let want_sd = (1.0 - c) / 12f64.sqrt() / ((1.0 + c) / 2.0);
        let sd = (sum2 / n - mean * mean).max(0.0).sqrt() / mean;
        assert!(
            sd <= 1.1 * want_sd + 1e-4,
            "r {r} d {d}: relative sd {sd} vs {want_sd}"
        );
    }
}

#[test]
fn inside_the_sphere_area_sampling_is_used_consistently() {
    // A sphere emitting inwards, the point at its centre region.
    let (s, light) = sphere_light(Point3::ZERO, 2.0, true);
    let ctx = LightSampleContext::new(Point3::new(0.3, -0.2, 0.5), Vec3::Z, Vec3::Z);
    assert_eq!(s.pdf_solid_angle(ctx.p), None);
    assert!(s.sample_solid_angle(ctx.p, Point2::new(0.5, 0.5)).is_none());
    // On the surface (a path vertex on the light) the inside is visible:
    // area sampling too, whatever the rounding of the point.
    for p in [
        Point3::new(2.0, 0.0, 0.0),
        Point3::new(0.0, f32::from_bits(2f32.to_bits() + 1), 0.0),
    ] {
        assert_eq!(s.pdf_solid_angle(p), None, "{p:?}");
    }
    let mut rng = common::Rng::new(2);
    let samples = strata(32, &mut rng);
    let mut sum = 0.0f64;
    for &u in &samples {
        let ls = light.sample_li(&ctx, u).unwrap();
        let p = light.pdf_li(&ctx, ls.wi);
        assert!(rel(p as f64, ls.pdf as f64) < 1e-3, "{p} vs {}", ls.pdf);
        sum += (ls.l.r * ls.wi.dot(ctx.n).max(0.0) / ls.pdf) as f64;
    }
    // Inside a uniformly emitting sphere the irradiance is π L.
    let e = sum / samples.len() as f64;
    assert!(rel(e, PI * 3.0) < 0.02, "{e}");
}

#[test]
fn non_uniform_scale_falls_back_to_area_sampling() {
    let t = Transform::translate(Vec3::new(0.0, 0.0, 5.0))
        * Transform::scale(Vec3::new(1.0, 2.0, 1.0)).unwrap();
    let s = Sphere::new(t, 1.0, false).unwrap();
    assert_eq!(s.pdf_solid_angle(Point3::ZERO), None);
    // A rotation and uniform scale is a similarity: the cone applies.
    let t = Transform::translate(Vec3::new(0.0, 0.0, 5.0))
        * Transform::rotate(30.0, Vec3::new(1.0, 1.0, 0.0))
        * Transform::scale(Vec3::splat(2.0)).unwrap();
    let s = Sphere::new(t, 0.5, false).unwrap();
    let pdf = s.pdf_solid_angle(Point3::ZERO).unwrap() as f64;
    let want = 1.0 / (2.0 * PI * (1.0 - (1.0 - 1.0 / 25.0f64).sqrt()));
    assert!(rel(pdf, want) < 1e-3, "{pdf} vs {want}");
}
