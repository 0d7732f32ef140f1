//! Participating media against analytic truths, through the public API:
//! Beer-Lambert transmittance of a homogeneous slab, a furnace (a purely
//! scattering medium inside an emitter of radiance 1 renders 1 in every
//! channel, also for a chromatic medium), energy loss with albedo below 1,
//! the single-scattering radiance of a slab lit by a distant light, and the
//! emission of an absorbing, emitting slab.

use lowdisc::pixel::{IndependentSampler, PixelSampler};
use lowdisc_render::bsdf::Material;
use lowdisc_render::geometry::{Disk, Sphere};
use lowdisc_render::integrator::{PathIntegrator, PathStats, transmittance};
use lowdisc_render::light::{DistantLight, Light};
use lowdisc_render::math::{Point3, Ray, Transform, Vec3};
use lowdisc_render::medium::{HomogeneousMedium, Medium, MediumInterface};
use lowdisc_render::scene::{Emission, INTERFACE, Scene, SceneBuilder};
use lowdisc_render::spectrum::{Colour, Rgb, SampledSpectrum, SampledWavelengths};
use std::f32::consts::PI;

fn homogeneous(sigma_a: Rgb, sigma_s: Rgb, le: Rgb, g: f32) -> Medium {
    Medium::Homogeneous(HomogeneousMedium {
        sigma_a,
        sigma_s,
        le,
        g,
    })
}

/// A slab `0 <= z <= 1` of `medium` between two large `interface` disks
/// (the lower one reversed, so that the slab is inside both), plus `light`.
fn slab(medium: Medium, light: Option<Light>) -> Scene {
    let mut b = SceneBuilder::new();
    let m = b.add_medium(medium);
    b.set_medium_interface(MediumInterface {
        inside: Some(m),
        outside: None,
    });
    let up = Transform::IDENTITY;
    b.add_disk(
        Disk::new(up, 1.0, 1e4, 0.0, false).unwrap(),
        INTERFACE,
        None,
    );
    b.add_disk(Disk::new(up, 0.0, 1e4, 0.0, true).unwrap(), INTERFACE, None);
    if let Some(l) = light {
        b.add_light(l);
    }
    b.build().unwrap()
}

#[test]
fn slab_transmittance_is_beer_lambert_per_channel() {
    let sigma_a = Rgb::new(0.1, 0.5, 1.0);
    let sigma_s = Rgb::new(0.2, 0.0, 0.5);
    let scene = slab(homogeneous(sigma_a, sigma_s, Rgb::ZERO, 0.0), None);
    assert!(scene.has_media());
    let (from, to) = (Point3::new(0.0, 0.0, -2.0), Point3::new(0.3, 0.0, 3.0));
    let mut rays = 0;
    let t = transmittance::<Rgb>(&scene, from, Vec3::ZERO, to, None, &(), &mut rays).unwrap();
    // The segment crosses the unit slab at a slant: its length inside is
    // 1 / cos θ.
    let d = (to - from).length() / (to.z - from.z);
    let expected = ((sigma_a + sigma_s) * -d).exp();
    for c in 0..3 {
        assert!((t[c] - expected[c]).abs() < 1e-5, "{t:?} vs {expected:?}");
    }
    assert_eq!(rays, 3, "one ray per segment between interfaces");
    // Starting inside the slab, only the part inside counts.
    let inside = Point3::new(0.0, 0.0, 0.75);
    let t = transmittance::<Rgb>(&scene, inside, Vec3::ZERO, to, Some(0), &(), &mut rays).unwrap();
    let d = (to - inside).length() * 0.25 / (to.z - inside.z);
    assert!((t.g - (-0.5 * d).exp()).abs() < 1e-5, "{t:?}");
    // Spectral: every wavelength by its own uplifted coefficients.
    let w = SampledWavelengths::sample_visible(0.3);
    let t = transmittance::<SampledSpectrum>(&scene, from, Vec3::ZERO, to, None, &w, &mut rays);
    let sigma_t = homogeneous(sigma_a, sigma_s, Rgb::ZERO, 0.0)
        .point::<SampledSpectrum>(&w)
        .sigma_t();
    let d = (to - from).length() / (to.z - from.z);
    let t = t.unwrap();
    for i in 0..4 {
        let e = (-sigma_t.lane(i) * d).exp();
        assert!((t.lane(i) - e).abs() < 1e-5, "lane {i}: {t:?}");
    }
}

/// Mean and standard error of `n` samples of `f(sampler)`, per lane.
fn estimate<C: Colour>(
    n: u32,
    seed: u64,
    mut f: impl FnMut(&mut IndependentSampler) -> C,
) -> (Vec<f64>, Vec<f64>) {
    let mut sampler = IndependentSampler::new(n, seed).unwrap();
    let (mut sum, mut sq) = (vec![0.0f64; C::LANES], vec![0.0f64; C::LANES]);
    for i in 0..n {
        sampler.start_pixel_sample([3, 5], i, 2);
        let v = f(&mut sampler);
        for c in 0..C::LANES {
            let x = f64::from(v.lane(c));
            sum[c] += x;
            sq[c] += x * x;
        }
    }
    let n = f64::from(n);
    let mean: Vec<f64> = sum.iter().map(|s| s / n).collect();
    let se = sq
        .iter()
        .zip(&mean)
        .map(|(q, m)| ((q / n - m * m).max(0.0) / n).sqrt())
        .collect();
    (mean, se)
}

/// The camera at the centre of a unit sphere that emits radiance 1 inwards
/// and reflects nothing, filled with `medium`.
fn furnace(medium: Medium) -> Scene {
    let mut b = SceneBuilder::new();
    let m = b.add_medium(medium);
    let black = b.add_material(Material::diffuse(Rgb::ZERO));
    b.set_medium_interface(MediumInterface {
        inside: Some(m),
        outside: None,
    });
    let emission = Emission {
        l: Rgb::ONE,
        two_sided: true,
    };
    let sphere = Sphere::new(Transform::IDENTITY, 1.0, false).unwrap();
    b.add_sphere(sphere, black, Some(emission));
    b.set_camera_medium(Some(m));
    b.build().unwrap()
}

fn radiance_inside(scene: &Scene, n: u32) -> (Vec<f64>, Vec<f64>) {
    let integrator = PathIntegrator {
        max_depth: 1000,
        ..PathIntegrator::default()
    };
    let ray = Ray::new(Point3::new(0.1, -0.2, 0.0), Vec3::new(0.0, 0.6, 0.8));
    estimate::<Rgb>(n, 7, |s| {
        integrator.li(scene, ray, s, 0, &mut PathStats::default())
    })
}

#[test]
fn furnace_with_a_purely_scattering_medium_renders_one() {
    // Grey and chromatic (each channel its own medium; the hero channel
    // samples the distances of all three).
    for sigma_s in [Rgb::splat(2.0), Rgb::new(0.5, 2.0, 4.0)] {
        let scene = furnace(homogeneous(Rgb::ZERO, sigma_s, Rgb::ZERO, 0.6));
        let (mean, se) = radiance_inside(&scene, 20_000);
        for c in 0..3 {
            assert!(
                (mean[c] - 1.0).abs() < 4.0 * se[c] + 1e-4 && se[c] < 0.02,
                "sigma_s {sigma_s:?}, channel {c}: {} ± {}",
                mean[c],
                se[c]
            );
        }
    }
}

#[test]
fn absorption_loses_energy() {
    let scene = furnace(homogeneous(
        Rgb::splat(1.0),
        Rgb::splat(1.0),
        Rgb::ZERO,
        0.0,
    ));
    let (mean, se) = radiance_inside(&scene, 4_000);
    // Albedo 1/2 in a sphere of optical radius 2: well below 1, and above
    // the unscattered light alone (at least e^{-2 · 1.2} along this ray).
    for c in 0..3 {
        assert!(
            mean[c] + 4.0 * se[c] < 0.8 && mean[c] > 0.05,
            "{mean:?} ± {se:?}"
        );
    }
}

/// Single scattering of a slab: a distant light of irradiance `E` shining
/// straight down on the slab `0 <= z <= 1`, seen straight down from above,
/// with one scattering event: `σs E p(1) (1 - e^{-2 σt}) / (2 σt)` where
/// `p(1)` is the Henyey-Greenstein density at `cos θ = 1` (back-scattering).
#[test]
fn thin_slab_single_scattering_matches_the_analytic_value() {
    let (sigma_a, sigma_s, g) = (Rgb::new(0.05, 0.1, 0.0), Rgb::new(0.05, 0.1, 0.2), 0.3);
    let e = 2.0;
    let light = DistantLight::new(
        &Transform::IDENTITY,
        Point3::new(0.0, 0.0, 1.0),
        Point3::ZERO,
        Rgb::splat(e),
        1.0,
        None,
    )
    .unwrap();
    let scene = slab(
        homogeneous(sigma_a, sigma_s, Rgb::ZERO, g),
        Some(Light::Distant(light)),
    );
    let integrator = PathIntegrator {
        max_depth: 1,
        ..PathIntegrator::default()
    };
    let ray = Ray::new(Point3::new(0.0, 0.0, 5.0), Vec3::new(0.0, 0.0, -1.0));
    let (mean, se) = estimate::<Rgb>(40_000, 3, |s| {
        integrator.li(&scene, ray, s, 0, &mut PathStats::default())
    });
    let p = (1.0 - g * g) / (4.0 * PI * (1.0 + g).powi(3));
    for c in 0..3 {
        let st = sigma_a[c] + sigma_s[c];
        let expected = sigma_s[c] * e * p * (1.0 - (-2.0 * st).exp()) / (2.0 * st);
        let expected = f64::from(expected);
        assert!(
            (mean[c] - expected).abs() < 4.0 * se[c] + 1e-6 && se[c] < 0.03 * expected,
            "channel {c}: {} ± {} vs {expected}",
            mean[c],
            se[c]
        );
        // Energy: with albedo below 1 less than the light's radiance
        // comes back.
        assert!(mean[c] < f64::from(e) * 0.1);
    }
}

/// A purely absorbing slab of emission `Le` seen along its normal:
/// `Le (1 - e^{-σa d})`, in RGB and, per wavelength, in spectral mode.
#[test]
fn emitting_slab_matches_the_analytic_value() {
    let sigma_a = Rgb::new(0.3, 1.0, 2.0);
    let le = Rgb::new(1.0, 0.5, 0.25);
    let medium = homogeneous(sigma_a, Rgb::ZERO, le, 0.0);
    let scene = slab(medium, None);
    let integrator = PathIntegrator::default();
    let ray = Ray::new(Point3::new(0.0, 0.0, 5.0), Vec3::new(0.0, 0.0, -1.0));
    let (mean, se) = estimate::<Rgb>(20_000, 11, |s| {
        integrator.li(&scene, ray, s, 0, &mut PathStats::default())
    });
    for c in 0..3 {
        let expected = f64::from(le[c] * (1.0 - (-sigma_a[c]).exp()));
        assert!(
            (mean[c] - expected).abs() < 4.0 * se[c] + 1e-6,
            "channel {c}: {} ± {} vs {expected}",
            mean[c],
            se[c]
        );
    }
    // Spectral: the ratio to each sample's own expected value averages 1.
    let mut sampler = IndependentSampler::new(1, 5).unwrap();
    let (n, mut sum, mut sq) = (20_000, [0.0f64; 4], [0.0f64; 4]);
    for i in 0..n {
        sampler.start_pixel_sample([0, 0], i, 0);
        let w = SampledWavelengths::sample_visible(sampler.get_1d());
        sampler.get_2d();
        let l: SampledSpectrum =
            integrator.li_for(&scene, ray, &mut sampler, 0, &w, &mut PathStats::default());
        let p = medium.point::<SampledSpectrum>(&w);
        for k in 0..4 {
            let expected = p.le.lane(k) * (1.0 - (-p.sigma_a.lane(k)).exp());
            let r = f64::from(l.lane(k) / expected);
            sum[k] += r;
            sq[k] += r * r;
        }
    }
    for k in 0..4 {
        let m = sum[k] / f64::from(n);
        let se = ((sq[k] / f64::from(n) - m * m) / f64::from(n)).sqrt();
        assert!(
            (m - 1.0).abs() < 4.0 * se + 1e-6 && se < 0.02,
            "lane {k}: {m} ± {se}"
        );
    }
}

#[test]
fn scenes_without_media_do_not_take_the_volumetric_path() {
    let mut b = SceneBuilder::new();
    let m = b.add_material(Material::diffuse(Rgb::splat(0.5)));
    b.add_sphere(
        Sphere::new(Transform::IDENTITY, 1.0, false).unwrap(),
        m,
        None,
    );
    assert!(!b.build().unwrap().has_media());
    // A medium index out of range is an error, not a panic.
    let mut b = SceneBuilder::new();
    b.set_camera_medium(Some(3));
    let e = b.build().unwrap_err().to_string();
    assert!(e.contains("medium index 3"), "{e}");
}
