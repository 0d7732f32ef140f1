//! Tests of the image environment light: the equal-area mapping and its
//! wrap-around, normalisation of the sampling density on the sphere for both
//! layouts, and irradiance estimates against uniform sampling.

use super::tests::{irradiance, strata};
use super::*;
use crate::math::sampling::sample_uniform_sphere;
use crate::math::spherical::{equal_area_sphere_to_square, equal_area_square_to_sphere};
use crate::math::{Transform, Vec3};
use crate::sampling::tests::TestRng;
use std::f32::consts::PI;
use std::path::PathBuf;

/// A dim sky with a small bright spot, `w × h`.
fn spot_image(w: usize, h: usize) -> Vec<Rgb> {
    (0..w * h)
        .map(|i| {
            let (x, y) = ((i % w) as f32 / w as f32, (i / w) as f32 / h as f32);
            let d2 = (x - 0.3).powi(2) + (y - 0.35).powi(2);
            Rgb::new(0.2 + x, 0.3, 0.1 + y) + Rgb::new(500.0, 400.0, 300.0) * (-d2 / 0.001).exp()
        })
        .collect()
}

fn env(w: usize, h: usize, lookup: EnvLookup, t: &Transform) -> Light {
    let l = ImageInfiniteLight::new(t, w, h, spot_image(w, h), None, lookup, 1.0, None).unwrap();
    Light::ImageInfinite(Box::new(l))
}

/// `∫ pdf dω` by stratified (jittered `side × side`) uniform sphere sampling.
fn pdf_integral(light: &Light, side: usize, seed: u64) -> f64 {
    let ctx = LightSampleContext::at(Vec3::ZERO);
    let mut rng = TestRng::new(seed);
    let samples = strata(side, &mut rng);
    let sum: f64 = samples
        .iter()
        .map(|u| light.pdf_li(&ctx, sample_uniform_sphere(Point2::new(u[0], u[1]))) as f64)
        .sum();
    sum * 4.0 * std::f64::consts::PI / samples.len() as f64
}

/// The density integrates to 1 within the (stratified) sampling noise, which
/// is below 0.5% for these maps.
fn assert_normalised(light: &Light, side: usize, what: &str) {
    let integral = pdf_integral(light, side, 17);
    println!("{what}: integral of pdf over the sphere = {integral:.5}");
    assert!((integral - 1.0).abs() < 5e-3, "{what}: ∫pdf = {integral}");
}

#[test]
fn equal_area_round_trip_and_area_preservation() {
    let mut rng = TestRng::new(2);
    let mut octants = [0.0f64; 8];
    let mut mean = Vec3::ZERO;
    let n = 200_000;
    for _ in 0..n {
        let p = Point2::new(rng.uniform(), rng.uniform());
        let w = equal_area_square_to_sphere(p);
        assert!((w.length() - 1.0).abs() < 1e-5);
        let q = equal_area_sphere_to_square(w);
        assert!(
            (q.x - p.x).abs() < 1e-5 && (q.y - p.y).abs() < 1e-5,
            "{p:?} -> {w:?} -> {q:?}"
        );
        mean += w / n as f32;
        octants[(w.x > 0.0) as usize + 2 * (w.y > 0.0) as usize + 4 * (w.z > 0.0) as usize] += 1.0;
    }
    // Uniform directions: mean 0 (σ per axis ≈ 1/sqrt(3n)), octants binomial(n, 1/8).
    assert!(mean.length() < 5.0 / (3.0 * n as f32).sqrt(), "{mean:?}");
    let sigma = (n as f64 * 0.125 * 0.875).sqrt();
    for c in octants {
        assert!((c - n as f64 / 8.0).abs() < 5.0 * sigma, "{octants:?}");
    }
}

#[test]
fn equal_area_wrap_is_continuous_across_edges() {
    assert_eq!(wrap_equal_area_pixel(-1, 2, 8, 8), (0, 5));
    assert_eq!(wrap_equal_area_pixel(8, 0, 8, 8), (7, 7));
    assert_eq!(wrap_equal_area_pixel(3, -1, 8, 8), (4, 0));
    assert_eq!(wrap_equal_area_pixel(3, 8, 8, 8), (4, 7));
    assert_eq!(wrap_equal_area_pixel(-1, -1, 8, 8), (7, 7));
    assert_eq!(wrap_equal_area_pixel(5, 6, 8, 8), (5, 6));
    // Bilinear radiance of points just inside two edge spots that are the
    // same place on the sphere must agree (a clamping lookup would not).
    let n = 16;
    let mut rng = TestRng::new(4);
    let pixels: Vec<Rgb> = (0..n * n).map(|_| Rgb::splat(rng.uniform())).collect();
    let l = ImageInfiniteLight::new(
        &Transform::IDENTITY,
        n,
        n,
        pixels,
        None,
        EnvLookup::Bilinear,
        1.0,
        None,
    )
    .unwrap();
    let e = 1e-6;
    for t in [0.1f32, 0.23, 0.37, 0.46] {
        for (a, b) in [
            (Point2::new(e, t), Point2::new(e, 1.0 - t)),
            (Point2::new(1.0 - e, t), Point2::new(1.0 - e, 1.0 - t)),
            (Point2::new(t, e), Point2::new(1.0 - t, e)),
            (Point2::new(t, 1.0 - e), Point2::new(1.0 - t, 1.0 - e)),
        ] {
            let (wa, wb) = (
                equal_area_square_to_sphere(a),
                equal_area_square_to_sphere(b),
            );
            assert!(
                (wa - wb).length() < 1e-3,
                "{a:?} and {b:?} are neighbours on the sphere"
            );
            let (la, lb) = (l.lookup_uv(a).r, l.lookup_uv(b).r);
            assert!((la - lb).abs() < 1e-3, "{a:?}: {la} vs {b:?}: {lb}");
        }
    }
}

#[test]
fn layouts_are_detected_and_checked() {
    assert_eq!(EnvLayout::detect(64, 64).unwrap(), EnvLayout::EqualArea);
    assert_eq!(EnvLayout::detect(64, 32).unwrap(), EnvLayout::LatLong);
    assert!(EnvLayout::detect(60, 32).is_err());
    let t = Transform::IDENTITY;
    let img = |w: usize, h: usize| vec![Rgb::ONE; w * h];
    assert!(
        ImageInfiniteLight::new(&t, 8, 4, img(8, 3), None, EnvLookup::Nearest, 1.0, None).is_err()
    );
    assert!(
        ImageInfiniteLight::new(
            &t,
            8,
            4,
            img(8, 4),
            Some(EnvLayout::EqualArea),
            EnvLookup::Nearest,
            1.0,
            None
        )
        .is_err()
    );
    assert!(
        ImageInfiniteLight::new(
            &t,
            6,
            4,
            img(6, 4),
            Some(EnvLayout::LatLong),
            EnvLookup::Nearest,
            1.0,
            None
        )
        .is_ok()
    );
    for (w, h) in [(16, 16), (32, 16)] {
        let u = UniformInfiniteLight::new(Rgb::splat(0.7), 1.0, None).unwrap();
        let mut a = Light::UniformInfinite(u);
        let i = ImageInfiniteLight::new(
            &t,
            w,
            h,
            vec![Rgb::splat(0.7); w * h],
            None,
            EnvLookup::Nearest,
            1.0,
            None,
        );
        let mut b = Light::ImageInfinite(Box::new(i.unwrap()));
        let bounds = Bounds3::new(Vec3::splat(-1.0), Vec3::splat(2.0));
        a.preprocess(&bounds);
        b.preprocess(&bounds);
        assert!(
            (a.phi().r - b.phi().r).abs() < 1e-3 * a.phi().r,
            "{w}x{h}: {:?} vs {:?}",
            a.phi(),
            b.phi()
        );
    }
}

#[test]
fn environment_sampling_is_normalised_for_both_layouts() {
    let rot = Transform::rotate(-90.0, Vec3::X) * Transform::rotate(30.0, Vec3::Z);
    for (w, h) in [(64, 64), (128, 64)] {
        for lookup in [EnvLookup::Nearest, EnvLookup::Bilinear] {
            assert_normalised(
                &env(w, h, lookup, &rot),
                1000,
                &format!("{w}x{h} {lookup:?}"),
            );
        }
    }
}

#[test]
fn sampled_pdf_and_radiance_match_evaluation() {
    let rot = Transform::rotate(40.0, Vec3::new(1.0, 1.0, 0.0));
    let mut rng = TestRng::new(8);
    for (w, h) in [(32, 32), (64, 32)] {
        let light = env(w, h, EnvLookup::Nearest, &rot);
        let ctx = LightSampleContext::at(Vec3::ZERO);
        for _ in 0..5000 {
            let s = light.sample_li(&ctx, rng.pair()).unwrap();
            let pdf = light.pdf_li(&ctx, s.wi);
            assert!(
                (pdf - s.pdf).abs() <= 2e-3 * s.pdf,
                "{w}x{h}: {pdf} vs {:?}",
                s
            );
            let le = light.le(&Ray::new(Vec3::ZERO, s.wi));
            assert!(
                (le - s.l).max_component().abs() <= 1e-3 * s.l.max_component(),
                "{le:?} vs {:?}",
                s.l
            );
        }
    }
}

#[test]
fn image_irradiance_matches_uniform_sampling_and_illuminance() {
    let n_up = Vec3::new(0.2, 0.3, 1.0).normalize();
    let ctx = LightSampleContext::new(Vec3::ZERO, n_up, n_up);
    let mut rng = TestRng::new(12);
    for (w, h) in [(64, 64), (128, 64)] {
        let light = env(w, h, EnvLookup::Nearest, &Transform::IDENTITY);
        let importance = irradiance(&light, &ctx, &strata(128, &mut rng));
        let mut uniform = Rgb::ZERO;
        let m = 1_000_000;
        for _ in 0..m {
            let wi = sample_uniform_sphere(Point2::new(rng.uniform(), rng.uniform()));
            uniform +=
                light.le(&Ray::new(Vec3::ZERO, wi)) * (wi.dot(n_up).max(0.0) * 4.0 * PI / m as f32);
        }
        let rel = (importance - uniform).max_component().abs() / uniform.max_component();
        assert!(
            rel < 0.02,
            "{w}x{h}: importance {importance:?} vs uniform {uniform:?}"
        );
        // Illuminance normalisation: irradiance facing +z has the given luminance.
        let lit = ImageInfiniteLight::new(
            &Transform::IDENTITY,
            w,
            h,
            spot_image(w, h),
            None,
            EnvLookup::Nearest,
            1.0,
            Some(3.0),
        );
        let up = LightSampleContext::new(Vec3::ZERO, Vec3::Z, Vec3::Z);
        let e = irradiance(
            &Light::ImageInfinite(Box::new(lit.unwrap())),
            &up,
            &strata(128, &mut rng),
        );
        assert!((e.luminance() - 3.0).abs() < 0.03, "{w}x{h}: {e:?}");
    }
}

fn scenes() -> Option<PathBuf> {
    shared_scenes::existing(shared_scenes::dir())
}

#[test]
fn real_environment_maps_are_normalised() {
    let Some(dir) = scenes() else { return };
    let rot = Transform::rotate(-90.0, Vec3::X);
    for (name, layout) in [
        (
            "envmaps/pbrt-v4-ganesha-sky-equiarea.exr",
            EnvLayout::EqualArea,
        ),
        (
            "bitterli-classroom/textures/Skydome.pfm",
            EnvLayout::EqualArea,
        ),
        ("envmaps/polyhaven-venice_sunset_1k.hdr", EnvLayout::LatLong),
    ] {
        let path = dir.join(name);
        if !path.is_file() {
            shared_scenes::skip(&format!("{} is absent", path.display()));
            continue;
        }
        let l = ImageInfiniteLight::from_file(&rot, &path, None, EnvLookup::Nearest, 1.0, None)
            .unwrap();
        assert_eq!(l.layout(), layout, "{name}");
        let light = Light::ImageInfinite(Box::new(l));
        assert_normalised(&light, 2500, name);
        let n = Vec3::new(0.1, 0.9, 0.2).normalize();
        let ctx = LightSampleContext::new(Vec3::ZERO, n, n);
        let mut rng = TestRng::new(31);
        let importance = irradiance(&light, &ctx, &strata(256, &mut rng));
        let mut uniform = Rgb::ZERO;
        let m = 2_000_000;
        for _ in 0..m {
            let wi = sample_uniform_sphere(Point2::new(rng.uniform(), rng.uniform()));
            uniform +=
                light.le(&Ray::new(Vec3::ZERO, wi)) * (wi.dot(n).max(0.0) * 4.0 * PI / m as f32);
        }
        let rel = (importance - uniform).max_component().abs() / uniform.max_component();
        println!(
            "{name}: irradiance importance {importance:?} uniform {uniform:?} rel diff {rel:.4}"
        );
        assert!(
            rel < 0.03,
            "{name}: importance {importance:?} vs uniform {uniform:?}"
        );
    }
}
