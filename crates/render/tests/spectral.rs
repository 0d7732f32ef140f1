//! Spectral mode against analytic truths: a white furnace stays white, a
//! saturated reflectance inside an emitting sphere gives the finite sum its
//! uplifted spectrum predicts (and not the RGB one), renders do not depend on
//! the thread count, and RGB mode draws no wavelength dimension.

use lowdisc::catalog::SamplerName;
use lowdisc_colour::cie::spectrum_to_xyz;
use lowdisc_colour::{CIE_Y_INTEGRAL, srgb};
use lowdisc_render::bsdf::Material;
use lowdisc_render::camera::PerspectiveParams;
use lowdisc_render::filter::Filter;
use lowdisc_render::geometry::Sphere;
use lowdisc_render::integrator::PathIntegrator;
use lowdisc_render::light::{Light, UniformInfiniteLight};
use lowdisc_render::math::{Point3, Transform, Vec3};
use lowdisc_render::render::{NoProgress, RenderOptions, RenderOutput, render};
use lowdisc_render::scene::{Emission, Scene, SceneBuilder};
use lowdisc_render::spectrum::Rgb;
use lowdisc_render::spectrum::uplift::{albedo, illuminant_d65};
use lowdisc_render::view::{CameraSpec, View, ViewSpec};

fn camera(from: Point3, at: Point3, fov: f32) -> CameraSpec {
    let look = Transform::look_at(from, at, Vec3::Y).unwrap();
    CameraSpec {
        world_from_camera: look.inverse(),
        params: PerspectiveParams {
            fov,
            ..PerspectiveParams::default()
        },
    }
}

/// `camera` on a `res x res` film with a box filter of radius 0.5.
fn view(camera: CameraSpec, res: u32) -> View {
    let filter = Filter::box_filter([0.5, 0.5]).unwrap();
    View::native(&ViewSpec::new(camera, [res, res], filter)).unwrap()
}

fn run(
    (scene, view): &(Scene, View),
    spp: u32,
    max_depth: u32,
    spectral: bool,
    threads: usize,
) -> RenderOutput {
    let opts = RenderOptions {
        integrator: PathIntegrator {
            max_depth,
            ..PathIntegrator::default()
        },
        threads: Some(threads),
        spectral,
        ..RenderOptions::new(SamplerName::ZSobol, 5, spp)
    };
    let out = render(scene, view, &opts, &NoProgress).unwrap();
    assert_eq!(out.stats.nonfinite_samples, 0);
    out
}

/// A sphere of reflectance `rgb` filling the view in a uniform white
/// environment (a furnace: every ray leaving the convex sphere escapes).
fn furnace(rgb: Rgb) -> (Scene, View) {
    let mut b = SceneBuilder::new();
    let m = b.add_material(Material::diffuse(rgb));
    b.add_sphere(
        Sphere::new(Transform::IDENTITY, 1.0, false).unwrap(),
        m,
        None,
    );
    b.add_light(Light::UniformInfinite(
        UniformInfiniteLight::new(Rgb::ONE, 1.0, None).unwrap(),
    ));
    let view = view(camera(Point3::new(0.0, 0.0, -5.0), Point3::ZERO, 8.0), 16);
    (b.build().unwrap(), view)
}

#[test]
fn white_furnace_stays_white() {
    // Albedo (1, 1, 1) uplifts to the constant 1 and white light to D65 of
    // luminance 1, which the sensor maps to sRGB (1, 1, 1): every channel's
    // mean is 1 within the wavelength sampling's noise.
    let out = run(&furnace(Rgb::ONE), 64, 3, true, 2);
    for (c, m) in out.mean().iter().enumerate() {
        assert!((m - 1.0).abs() < 3e-3, "channel {c}: {m}");
    }
}

/// The sRGB (Y of the white 1) of the spectrum `s` seen under unit D65.
fn srgb_of(s: impl Fn(f32) -> f32) -> [f64; 3] {
    let xyz = spectrum_to_xyz(|l| s(l) * illuminant_d65(l) * CIE_Y_INTEGRAL);
    srgb().rgb_from_xyz.apply(xyz.map(f64::from))
}

#[test]
fn saturated_reflectance_follows_its_uplifted_spectrum() {
    // Inside a closed sphere of reflectance ρ emitting white light Le
    // inwards, the radiance after at most D bounces is Le Σ_{k≤D} ρ^k,
    // wavelength by wavelength. For the coffee maker's orange plastic,
    // ρ = (1, 0.378, 0.013), the uplifted ρ(λ) is below 1 over part of the
    // red band, so the spectral red is well below RGB's Σ 1^k = D + 1.
    let rho = Rgb::new(1.0, 0.378, 0.013);
    let mut b = SceneBuilder::new();
    let m = b.add_material(Material::diffuse(rho));
    let e = Emission {
        l: Rgb::ONE,
        two_sided: false,
    };
    b.add_sphere(
        Sphere::new(Transform::IDENTITY, 1.0, true).unwrap(),
        m,
        Some(e),
    );
    let view = view(camera(Point3::ZERO, Point3::new(0.0, 0.0, 1.0), 60.0), 8);
    let scene = (b.build().unwrap(), view);
    let depth = 4u32;
    let s = albedo(rho);
    let predicted = srgb_of(|l| (0..=depth).map(|k| s.eval(l).powi(k as i32)).sum());
    let out = run(&scene, 256, depth, true, 2);
    let got = out.mean();
    for c in 0..3 {
        let tol = 0.01 * predicted[c].abs() + 2e-3;
        assert!(
            (got[c] - predicted[c]).abs() < tol,
            "channel {c}: rendered {} vs predicted {}",
            got[c],
            predicted[c]
        );
    }
    let rgb = run(&scene, 64, depth, false, 2).mean();
    assert!((rgb[0] - 5.0).abs() < 0.05, "RGB red {}", rgb[0]);
    assert!(
        got[0] < 0.95 * rgb[0],
        "spectral red {} vs RGB {}",
        got[0],
        rgb[0]
    );
}

#[test]
fn spectral_renders_are_bit_identical_across_thread_counts() {
    let scene = furnace(Rgb::new(0.8, 0.3, 0.1));
    let a = run(&scene, 4, 2, true, 1);
    let b = run(&scene, 4, 2, true, 2);
    assert_eq!(a.image.pixels(), b.image.pixels());
    // Spectral and RGB renders differ (the wavelength dimension and the
    // sensor), while agreeing on average for this single-bounce scene.
    let c = run(&scene, 4, 2, false, 2);
    assert_ne!(a.image.pixels(), c.image.pixels());
}
