//! Tests of the point, spot, distant, area and uniform infinite lights and of
//! the light sampler, against closed-form radiometry.

use super::*;
use crate::geometry::{Disk, ShapeSet, Sphere, TriangleMesh, triangle::MeshData};
use crate::math::sampling::sample_uniform_sphere;
use crate::math::{Transform, Vec3};
use crate::sampling::tests::{TestRng, assert_chi_square};
use std::f32::consts::PI;

const ID: Transform = Transform::IDENTITY;

/// Jittered `n × n` stratified samples of the unit square.
pub(crate) fn strata(n: usize, rng: &mut TestRng) -> Vec<[f32; 2]> {
    let mut v = Vec::with_capacity(n * n);
    for i in 0..n {
        for j in 0..n {
            v.push([
                (i as f32 + rng.uniform()) / n as f32,
                (j as f32 + rng.uniform()) / n as f32,
            ]);
        }
    }
    v
}

/// Irradiance at `ctx` (surface normal `ctx.n`) estimated with `sample_li`.
pub(crate) fn irradiance(light: &Light, ctx: &LightSampleContext, samples: &[[f32; 2]]) -> Rgb {
    let mut sum = Rgb::ZERO;
    for &u in samples {
        if let Some(s) = light.sample_li(ctx, u) {
            sum += s.l * (s.wi.dot(ctx.n).max(0.0) / s.pdf);
        }
    }
    sum / samples.len() as f32
}

fn close(a: f32, b: f32, rel: f32) -> bool {
    (a - b).abs() <= rel * b.abs().max(1e-12)
}

#[test]
fn point_light_inverse_square_and_power() {
    let t = Transform::translate(Vec3::new(1.0, 2.0, 3.0));
    let light = Light::Point(
        PointLight::new(
            &t,
            Vec3::new(0.0, 0.0, 1.0),
            Rgb::new(1.0, 2.0, 3.0),
            2.0,
            None,
        )
        .unwrap(),
    );
    let at = |d: f32| {
        light
            .sample_li(
                &LightSampleContext::at(Vec3::new(1.0, 2.0, 4.0 - d)),
                [0.5, 0.5],
            )
            .unwrap()
    };
    let (a, b) = (at(1.5), at(3.0));
    assert_eq!(a.wi, Vec3::Z);
    assert!(a.is_delta && a.pdf == 1.0 && light.is_delta());
    assert!(close(a.l.g, 4.0 / 2.25, 1e-6), "{:?}", a.l);
    assert!(close(a.l.b / b.l.b, 4.0, 1e-5));
    assert_eq!(a.p_light, Vec3::new(1.0, 2.0, 4.0));
    assert!(close(light.phi().r, 4.0 * PI * 2.0, 1e-6));
    assert_eq!(
        light.pdf_li(&LightSampleContext::at(Vec3::ZERO), Vec3::Z),
        0.0
    );
    let p = PointLight::new(&ID, Vec3::ZERO, Rgb::new(0.2, 0.5, 1.0), 3.0, Some(100.0)).unwrap();
    // pbrt-v4: `scale` still multiplies the power-normalised intensity.
    assert!(close(Light::Point(p).phi().luminance(), 300.0, 1e-5));
}

#[test]
fn spot_light_cone_falloff_and_power() {
    let (from, to) = (Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO);
    let s = SpotLight::new(&ID, from, to, Rgb::splat(10.0), 1.0, 30.0, 10.0, None).unwrap();
    let light = Light::Spot(s.clone());
    let receive = |deg: f32| {
        let w = Vec3::new(deg.to_radians().sin(), 0.0, -deg.to_radians().cos());
        light.sample_li(&LightSampleContext::at(from + w * 2.0), [0.0, 0.0])
    };
    let inside = receive(15.0).unwrap();
    assert!(close(inside.l.r, 10.0 / 4.0, 1e-5), "{inside:?}");
    assert!(receive(31.0).is_none(), "outside the cone");
    let mid = receive(25.0).unwrap().l.r * 4.0;
    let c = 25f32.to_radians().cos();
    let (c0, c1) = (30f32.to_radians().cos(), 20f32.to_radians().cos());
    let t = (c - c0) / (c1 - c0);
    assert!(close(mid, 10.0 * t * t * (3.0 - 2.0 * t), 1e-4), "{mid}");
    // Closed-form power against quadrature of the intensity over cos(theta).
    let n = 200_000;
    let mut integral = 0.0f64;
    for i in 0..n {
        let ct = -1.0 + 2.0 * (i as f32 + 0.5) / n as f32;
        let w = Vec3::new((1.0 - ct * ct).sqrt(), 0.0, -ct);
        integral += s.intensity_towards(w).r as f64 * 2.0 * PI as f64 * 2.0 / n as f64;
    }
    assert!(
        close(light.phi().r, integral as f32, 1e-3),
        "{:?} vs {integral}",
        light.phi()
    );
    let p = SpotLight::new(
        &ID,
        from,
        to,
        Rgb::new(1.0, 0.3, 0.1),
        1.0,
        40.0,
        5.0,
        Some(50.0),
    )
    .unwrap();
    assert!(close(Light::Spot(p).phi().luminance(), 50.0, 1e-5));
    assert!(SpotLight::new(&ID, from, from, Rgb::ONE, 1.0, 30.0, 5.0, None).is_err());
}

#[test]
fn distant_light_direction_power_and_shadow_end() {
    let rot = Transform::rotate(90.0, Vec3::X);
    let mut light = Light::Distant(
        DistantLight::new(&rot, Vec3::Z, Vec3::ZERO, Rgb::splat(2.0), 1.5, None).unwrap(),
    );
    let b = Bounds3::new(Vec3::splat(-1.0), Vec3::splat(1.0));
    light.preprocess(&b);
    let ctx = LightSampleContext::at(Vec3::new(0.5, 0.0, 0.0));
    let s = light.sample_li(&ctx, [0.3, 0.3]).unwrap();
    assert!((s.wi - rot.vector(Vec3::Z)).length() < 1e-6, "{:?}", s.wi);
    assert_eq!(s.l, Rgb::splat(3.0));
    assert!(
        s.p_light.distance(Vec3::ZERO) > 3f32.sqrt(),
        "shadow ray must leave the scene"
    );
    assert!(close(light.phi().r, 3.0 * PI * 3.0, 1e-5));
    let e = DistantLight::new(
        &ID,
        Vec3::Z,
        Vec3::ZERO,
        Rgb::new(1.0, 0.5, 0.2),
        7.0,
        Some(4.0),
    )
    .unwrap();
    assert!(close(
        Light::Distant(e)
            .sample_li(&ctx, [0.0; 2])
            .unwrap()
            .l
            .luminance(),
        28.0,
        1e-5
    ));
}

fn disk_light(radius: f32, l: f32) -> Light {
    let disk = Disk::new(ID, 0.0, radius, 0.0, false).unwrap();
    Light::Area(DiffuseAreaLight::new(AreaShape::Disk(disk), Rgb::splat(l), 1.0, false).unwrap())
}

#[test]
fn disk_light_on_axis_irradiance_matches_closed_form() {
    let mut rng = TestRng::new(3);
    let samples = strata(64, &mut rng);
    for (r, d) in [(0.3f32, 2.0f32), (1.0, 1.0), (0.05, 0.5)] {
        let light = disk_light(r, 3.0);
        let ctx = LightSampleContext::new(Vec3::new(0.0, 0.0, d), -Vec3::Z, -Vec3::Z);
        let e = irradiance(&light, &ctx, &samples).r;
        let exact = PI * 3.0 * r * r / (r * r + d * d);
        assert!(close(e, exact, 5e-3), "r {r} d {d}: {e} vs {exact}");
        // One-sided: nothing reaches the back.
        let back = LightSampleContext::new(Vec3::new(0.0, 0.0, -d), Vec3::Z, Vec3::Z);
        assert_eq!(irradiance(&light, &back, &samples[..64]), Rgb::ZERO);
    }
}

#[test]
fn sphere_light_irradiance_and_pdf_consistency() {
    let sphere = Sphere::new(Transform::translate(Vec3::new(0.0, 0.0, 4.0)), 1.0, false).unwrap();
    let light = Light::Area(
        DiffuseAreaLight::new(AreaShape::Sphere(sphere), Rgb::splat(2.0), 1.0, false).unwrap(),
    );
    let ctx = LightSampleContext::new(Vec3::ZERO, Vec3::Z, Vec3::Z);
    let mut rng = TestRng::new(5);
    let e = irradiance(&light, &ctx, &strata(128, &mut rng)).r;
    let exact = PI * 2.0 / 16.0;
    assert!(close(e, exact, 1e-2), "{e} vs {exact}");
    assert!(close(light.phi().r, 2.0 * PI * 4.0 * PI, 1e-5));
    let mut checked = 0;
    for _ in 0..2000 {
        let s = light.sample_li(&ctx, rng.pair());
        // Away from the silhouette, where the hit point is numerically stable.
        if let Some(s) = s.filter(|s| s.n_light.abs_dot(s.wi) > 1e-2) {
            assert!(close(light.pdf_li(&ctx, s.wi), s.pdf, 1e-3), "{s:?}");
            assert!(close(
                light.pdf_li_hit(&ctx, s.p_light, s.n_light),
                s.pdf,
                1e-5
            ));
            checked += 1;
        }
    }
    assert!(checked > 500, "front half of the sphere is sampled");
}

#[test]
fn triangle_light_power_pdf_and_sides() {
    let mut shapes = ShapeSet::new();
    let data = MeshData {
        positions: vec![
            Vec3::new(0.0, 0.0, 1.0),
            Vec3::new(2.0, 0.0, 1.0),
            Vec3::new(0.0, 1.0, 1.0),
        ],
        indices: vec![[0, 1, 2]],
        normals: None,
        uvs: None,
    };
    let m = shapes.add_mesh(TriangleMesh::new(&ID, data, false).unwrap());
    let prim = shapes.mesh_prims(m).next().unwrap();
    let one = DiffuseAreaLight::from_prim(&shapes, prim, Rgb::splat(1.5), 2.0, false).unwrap();
    let two = DiffuseAreaLight::from_prim(&shapes, prim, Rgb::splat(1.5), 2.0, true).unwrap();
    assert_eq!(one.prim(), Some(prim));
    let (one, two) = (Light::Area(one), Light::Area(two));
    assert!(close(one.phi().r, PI * 3.0 * 1.0, 1e-6));
    assert!(close(two.phi().r, 2.0 * PI * 3.0, 1e-6));
    let n = match &one {
        Light::Area(a) => match a.shape() {
            AreaShape::Triangle { n, .. } => *n,
            _ => unreachable!(),
        },
        _ => unreachable!(),
    };
    let (front, back) = (Vec3::new(0.3, 0.3, 1.0) + n, Vec3::new(0.3, 0.3, 1.0) - n);
    assert_eq!(
        one.l(
            Vec3::new(0.3, 0.3, 1.0),
            n,
            Point2::new(0.0, 0.0),
            front - Vec3::new(0.3, 0.3, 1.0)
        ),
        Rgb::splat(3.0)
    );
    assert_eq!(
        one.l(Vec3::new(0.3, 0.3, 1.0), n, Point2::new(0.0, 0.0), -n),
        Rgb::ZERO
    );
    assert_eq!(
        two.l(Vec3::new(0.3, 0.3, 1.0), n, Point2::new(0.0, 0.0), -n),
        Rgb::splat(3.0)
    );
    let mut rng = TestRng::new(9);
    for ctx in [LightSampleContext::at(front), LightSampleContext::at(back)] {
        for _ in 0..200 {
            let u = rng.pair();
            match two.sample_li(&ctx, u) {
                Some(s) => assert!(close(two.pdf_li(&ctx, s.wi), s.pdf, 1e-3), "{s:?}"),
                None => panic!("a two-sided light is always visible"),
            }
        }
    }
    assert_eq!(
        two.pdf_li(&LightSampleContext::at(front), Vec3::new(0.0, 1.0, 0.0)),
        0.0
    );
    let k = diffuse_power_scale(Rgb::new(1.0, 0.5, 0.5), 30.0, 1.0, false);
    assert!(close(
        k * Rgb::new(1.0, 0.5, 0.5).luminance() * PI,
        30.0,
        1e-5
    ));
}

#[test]
fn uniform_infinite_irradiance_is_pi_l() {
    let mut light = Light::UniformInfinite(
        UniformInfiniteLight::new(Rgb::new(1.0, 2.0, 0.5), 1.0, None).unwrap(),
    );
    light.preprocess(&Bounds3::new(Vec3::splat(-2.0), Vec3::splat(2.0)));
    let n = Vec3::new(0.3, -0.4, 0.5).normalize();
    let ctx = LightSampleContext::new(Vec3::splat(1.0), n, n);
    let mut rng = TestRng::new(21);
    let e = irradiance(&light, &ctx, &strata(200, &mut rng));
    assert!(close(e.g, 2.0 * PI, 5e-3), "{e:?}");
    assert!(close(e.b, 0.5 * PI, 5e-3), "{e:?}");
    let r2 = 12.0f32;
    assert!(close(light.phi().r, 4.0 * PI * PI * r2, 1e-5));
    assert_eq!(
        light.le(&Ray::new(Vec3::ZERO, Vec3::X)),
        Rgb::new(1.0, 2.0, 0.5)
    );
    assert!(close(light.pdf_li(&ctx, Vec3::X), 0.25 / PI, 1e-6));
    let w = sample_uniform_sphere(Point2::new(0.2, 0.7));
    assert!(close(
        light.sample_li(&ctx, [0.2, 0.7]).unwrap().wi.dot(w),
        1.0,
        1e-6
    ));
    let lit = UniformInfiniteLight::new(Rgb::new(0.1, 0.7, 2.0), 1.0, Some(5.0)).unwrap();
    assert!(close(lit.radiance().luminance() * PI, 5.0, 1e-5));
}

#[test]
fn bad_parameters_are_errors_and_bad_samples_are_harmless() {
    assert!(PointLight::new(&ID, Vec3::ZERO, Rgb::new(-1.0, 0.0, 0.0), 1.0, None).is_err());
    assert!(PointLight::new(&ID, Vec3::ZERO, Rgb::ONE, f32::NAN, None).is_err());
    assert!(UniformInfiniteLight::new(Rgb::splat(f32::INFINITY), 1.0, None).is_err());
    assert!(DistantLight::new(&ID, Vec3::ZERO, Vec3::ZERO, Rgb::ONE, 1.0, None).is_err());
    let light = disk_light(1.0, 1.0);
    let ctx = LightSampleContext::new(Vec3::new(0.0, 0.0, 1.0), -Vec3::Z, -Vec3::Z);
    for u in [[f32::NAN, 0.5], [1.0, 1.0], [-3.0, 7.0]] {
        if let Some(s) = light.sample_li(&ctx, u) {
            assert!(s.pdf.is_finite() && s.l.is_finite());
        }
    }
    // A receiver on the light itself gets nothing rather than infinities.
    assert!(
        light
            .sample_li(&LightSampleContext::at(Vec3::ZERO), [0.5, 0.5])
            .is_none()
    );
}

#[test]
fn light_sampler_is_proportional_to_power() {
    let lights = vec![
        Light::Point(PointLight::new(&ID, Vec3::ZERO, Rgb::splat(1.0), 1.0, None).unwrap()),
        Light::Point(PointLight::new(&ID, Vec3::ZERO, Rgb::splat(0.0), 1.0, None).unwrap()),
        Light::Point(PointLight::new(&ID, Vec3::ZERO, Rgb::new(3.0, 3.0, 0.0), 1.0, None).unwrap()),
        disk_light(1.0, 1.0),
    ];
    let sampler = LightSampler::new(&lights);
    let powers: Vec<f32> = lights.iter().map(|l| l.phi().average()).collect();
    let total: f32 = powers.iter().sum();
    let pmf_sum: f32 = (0..4).map(|i| sampler.pmf(i)).sum();
    assert!(close(pmf_sum, 1.0, 1e-6));
    for (i, p) in powers.iter().enumerate() {
        assert!(close(sampler.pmf(i), p / total, 1e-5) || *p == 0.0 && sampler.pmf(i) == 0.0);
    }
    assert_eq!(sampler.pmf(4), 0.0);
    let mut rng = TestRng::new(1);
    let mut hist = vec![0.0; 4];
    let n = 100_000;
    for _ in 0..n {
        let (i, pmf) = sampler.sample(rng.uniform()).unwrap();
        assert_eq!(pmf, sampler.pmf(i));
        hist[i] += 1.0;
    }
    let expected: Vec<f64> = powers
        .iter()
        .map(|&p| n as f64 * (p / total) as f64)
        .collect();
    assert_chi_square(&hist, &expected);
    let dark = LightSampler::from_powers(&[0.0, 0.0, f32::NAN]);
    assert_eq!((dark.pmf(0), dark.pmf(2)), (1.0 / 3.0, 1.0 / 3.0));
    assert_eq!(dark.sample(0.9).map(|s| s.0), Some(2));
    let none = LightSampler::new(&[]);
    assert!(none.is_empty() && none.sample(0.5).is_none() && none.pmf(0) == 0.0);
}
