//! The render loop and the built-in Cornell box: determinism across thread
//! counts, non-finite samples, scenes without lights, colour tendencies,
//! cancellation.

use lowdisc::catalog::SamplerName;
use lowdisc_render::bsdf::Material;
use lowdisc_render::camera::PerspectiveParams;
use lowdisc_render::cornell::cornell_box;
use lowdisc_render::film::PixelBounds;
use lowdisc_render::filter::Filter;
use lowdisc_render::geometry::Sphere;
use lowdisc_render::integrator::PathIntegrator;
use lowdisc_render::light::{Light, PointLight};
use lowdisc_render::math::{Point3, Transform, Vec3};
use lowdisc_render::render::{
    MAX_SPP, NoProgress, Progress, RenderError, RenderOptions, render, render_cancellable,
};
use lowdisc_render::scene::{Emission, Scene, SceneBuilder};
use lowdisc_render::settings::ranges::MAX_DEPTH_LIMIT;
use lowdisc_render::spectrum::Rgb;
use lowdisc_render::view::{CameraSpec, View, ViewSpec};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering};

fn opts(sampler: SamplerName, spp: u32, threads: usize) -> RenderOptions {
    RenderOptions {
        integrator: PathIntegrator {
            max_depth: 5,
            ..PathIntegrator::default()
        },
        threads: Some(threads),
        ..RenderOptions::new(sampler, 7, spp)
    }
}

fn bits(p: &[[f32; 3]]) -> Vec<u32> {
    p.iter().flat_map(|c| c.map(f32::to_bits)).collect()
}

#[test]
fn output_is_bit_identical_with_one_and_two_threads() {
    let (scene, view) = cornell_box([40, 24]).unwrap();
    for name in [
        SamplerName::ZSobol,
        SamplerName::ZSobolJoint,
        SamplerName::ZOrderSz,
        SamplerName::CascadedSobol,
        SamplerName::Paper,
        SamplerName::Independent,
        SamplerName::Halton,
    ] {
        let a = render(&scene, &view, &opts(name, 4, 1), &NoProgress).unwrap();
        let b = render(&scene, &view, &opts(name, 4, 2), &NoProgress).unwrap();
        assert_eq!(bits(a.image.pixels()), bits(b.image.pixels()), "{name}");
        assert_eq!(a.stats.rays, b.stats.rays, "{name}");
        assert_eq!(a.stats.samples, 40 * 24 * 4);
        // A different seed changes the image (the test can fail).
        let mut o = opts(name, 4, 2);
        o.sampler.seed = 8;
        let c = render(&scene, &view, &o, &NoProgress).unwrap();
        assert_ne!(
            bits(a.image.pixels()),
            bits(c.image.pixels()),
            "{name}: seed ignored"
        );
    }
}

#[test]
fn paper_threshold_reaches_the_sampler() {
    // Threshold 1 leaves every column unflipped: the reproducible paper
    // sampler then renders exactly what plain Sobol renders; threshold 0.5
    // does not.
    let (scene, view) = cornell_box([16, 16]).unwrap();
    let sobol = render(&scene, &view, &opts(SamplerName::Sobol, 4, 2), &NoProgress).unwrap();
    let paper = |t: f64| {
        let mut o = opts(SamplerName::PaperRepro, 4, 2);
        o.sampler.threshold = t;
        render(&scene, &view, &o, &NoProgress).unwrap()
    };
    assert_eq!(bits(paper(1.0).image.pixels()), bits(sobol.image.pixels()));
    assert_ne!(bits(paper(0.5).image.pixels()), bits(sobol.image.pixels()));
}

#[test]
fn cornell_box_has_finite_positive_mean_red_left_green_right() {
    let (scene, view) = cornell_box([32, 32]).unwrap();
    let out = render(
        &scene,
        &view,
        &opts(SamplerName::ZSobol, 16, 2),
        &NoProgress,
    )
    .unwrap();
    assert!(out.warnings.is_empty(), "{:?}", out.warnings);
    assert_eq!(out.stats.nonfinite_samples, 0);
    let m = out.mean();
    assert!(
        m.iter().all(|v| v.is_finite() && *v > 0.01 && *v < 5.0),
        "mean {m:?}"
    );
    // Warm light: red > green > blue on average.
    assert!(m[0] > m[1] && m[1] > m[2], "mean {m:?}");
    // Average the left and right eighths of the image, middle rows.
    let region = |x0: u32, x1: u32| {
        let mut s = [0.0f64; 3];
        for y in 8..24u32 {
            for x in x0..x1 {
                let p = out.image.pixels()[(y * 32 + x) as usize];
                for c in 0..3 {
                    s[c] += f64::from(p[c]);
                }
            }
        }
        s
    };
    let left = region(0, 4);
    let right = region(28, 32);
    assert!(left[0] > 2.0 * left[1], "left wall not red: {left:?}");
    assert!(right[1] > 1.5 * right[0], "right wall not green: {right:?}");
    // The light (radiance 17, 11.8, 4) is seen near the top centre (rows
    // 4-5 at this resolution), and it is the brightest thing in the image.
    let px = |x: u32, y: u32| out.image.pixels()[(y * 32 + x) as usize];
    let light = (3..7)
        .flat_map(|y| (14..18).map(move |x| (x, y)))
        .map(|(x, y)| px(x, y)[0]);
    let brightest = light.fold(0.0f32, f32::max);
    assert!(
        brightest > 5.0,
        "light not visible at the top centre: {brightest}"
    );
    let max_red = out
        .image
        .pixels()
        .iter()
        .map(|p| p[0])
        .fold(0.0f32, f32::max);
    assert_eq!(brightest, max_red);
}

/// A diffuse sphere seen by a camera, lit by a point light.
fn sphere_scene(reflectance: Rgb, with_light: bool) -> (Scene, View) {
    let mut b = SceneBuilder::new();
    let m = b.add_material(Material::diffuse(reflectance));
    b.add_sphere(
        Sphere::new(Transform::IDENTITY, 1.0, false).unwrap(),
        m,
        None,
    );
    if with_light {
        let l = PointLight::new(
            &Transform::IDENTITY,
            Point3::new(0.0, 0.0, -4.0),
            Rgb::splat(10.0),
            1.0,
            None,
        );
        b.add_light(Light::Point(l.unwrap()));
    }
    let look = Transform::look_at(Point3::new(0.0, 0.0, -5.0), Point3::ZERO, Vec3::Y).unwrap();
    let camera = CameraSpec {
        world_from_camera: look.inverse(),
        params: PerspectiveParams {
            fov: 30.0,
            ..PerspectiveParams::default()
        },
    };
    let filter = Filter::box_filter([0.5, 0.5]).unwrap();
    let view = View::native(&ViewSpec::new(camera, [16, 16], filter)).unwrap();
    (b.build().unwrap(), view)
}

#[test]
fn scene_without_lights_renders_black_with_a_warning() {
    let (scene, view) = sphere_scene(Rgb::splat(0.5), false);
    let out = render(&scene, &view, &opts(SamplerName::ZSobol, 2, 1), &NoProgress).unwrap();
    assert!(out.image.pixels().iter().all(|p| *p == [0.0; 3]));
    assert_eq!(out.warnings.len(), 1);
    assert!(out.warnings[0].contains("no lights"), "{:?}", out.warnings);
    // The same scene with a light is not black.
    let (lit_scene, view) = sphere_scene(Rgb::splat(0.5), true);
    let lit = render(
        &lit_scene,
        &view,
        &opts(SamplerName::ZSobol, 2, 1),
        &NoProgress,
    )
    .unwrap();
    assert!(lit.mean()[0] > 0.0 && lit.warnings.is_empty());
}

#[test]
fn nonfinite_samples_are_counted_and_never_written() {
    // Inside a sphere emitting close to f32::MAX, the emitted radiance plus
    // one bounce overflows to infinity: those samples must be counted and
    // dropped (the film treats NaN the same way).
    let mut b = SceneBuilder::new();
    let m = b.add_material(Material::diffuse(Rgb::splat(0.9)));
    let e = Emission {
        l: Rgb::splat(0.8 * f32::MAX),
        two_sided: false,
    };
    b.add_sphere(
        Sphere::new(Transform::IDENTITY, 1.0, true).unwrap(),
        m,
        Some(e),
    );
    let look = Transform::look_at(Point3::ZERO, Point3::new(0.0, 0.0, 1.0), Vec3::Y).unwrap();
    let camera = CameraSpec {
        world_from_camera: look.inverse(),
        params: PerspectiveParams::default(),
    };
    let filter = Filter::box_filter([0.5, 0.5]).unwrap();
    let view = View::native(&ViewSpec::new(camera, [8, 8], filter)).unwrap();
    let scene = b.build().unwrap();
    let out = render(&scene, &view, &opts(SamplerName::ZSobol, 2, 2), &NoProgress).unwrap();
    assert!(out.stats.nonfinite_samples > 0);
    assert!(out.image.pixels().iter().flatten().all(|v| v.is_finite()));
    assert!(
        out.warnings.iter().any(|w| w.contains("NaN or infinite")),
        "{:?}",
        out.warnings
    );
    // With maxdepth 0 nothing overflows.
    let mut o = opts(SamplerName::ZSobol, 2, 2);
    o.integrator.max_depth = 0;
    let out = render(&scene, &view, &o, &NoProgress).unwrap();
    assert_eq!(out.stats.nonfinite_samples, 0);
}

#[test]
fn progress_reports_every_tile_and_bad_options_are_errors() {
    let (scene, view) = cornell_box([40, 20]).unwrap();
    let seen = Mutex::new(Vec::new());
    let sink = |p: Progress| seen.lock().unwrap().push(p);
    let out = render(&scene, &view, &opts(SamplerName::Independent, 1, 2), &sink).unwrap();
    let seen = seen.into_inner().unwrap();
    assert_eq!(seen.len(), 6, "3x2 tiles of 16x16");
    let last = seen.iter().max_by_key(|p| p.tiles_done).unwrap();
    assert_eq!((last.tiles_done, last.tiles_total), (6, 6));
    assert_eq!(last.samples_done, 800);
    assert_eq!(last.rays, out.stats.rays);
    let with_threshold = |name, t| {
        let mut o = opts(name, 1, 1);
        o.sampler.threshold = t;
        o
    };
    for bad in [
        opts(SamplerName::ZSobol, 0, 1),
        opts(SamplerName::ZSobol, MAX_SPP + 1, 1),
        RenderOptions {
            integrator: PathIntegrator {
                max_depth: MAX_DEPTH_LIMIT + 1,
                ..PathIntegrator::default()
            },
            ..opts(SamplerName::ZSobol, 1, 1)
        },
        RenderOptions {
            threads: Some(0),
            ..opts(SamplerName::ZSobol, 1, 1)
        },
        with_threshold(SamplerName::PaperRepro, f64::NAN),
        with_threshold(SamplerName::Paper, 1.5),
    ] {
        assert!(bad.validate().is_err(), "{bad:?}");
        assert!(render(&scene, &view, &bad, &NoProgress).is_err());
    }
}

#[test]
fn the_image_of_a_renders_sums_is_its_image() {
    use lowdisc_render::render::image_of_sums;
    let (scene, view) = cornell_box([24, 16]).unwrap();
    for spectral in [false, true] {
        let o = RenderOptions {
            spectral,
            window: Some(PixelBounds::new([3, 2], [19, 13])),
            ..opts(SamplerName::ZSobol, 4, 2)
        };
        let out = render(&scene, &view, &o, &NoProgress).unwrap();
        let window = out.film.pixel_bounds();
        let sums = out.film.sums();
        let image = image_of_sums(&view, window, spectral, sums).unwrap();
        assert_eq!(bits(image.pixels()), bits(out.image.pixels()), "{spectral}");
        // The other mode's output gives another image.
        let other = image_of_sums(&view, window, !spectral, sums).unwrap();
        assert_ne!(bits(other.pixels()), bits(out.image.pixels()), "{spectral}");
        // The film's white balance reaches the output in either mode.
        let mut warm = view.spec().clone();
        warm.film.white_balance = 4000.0;
        let warm = View::native(&warm).unwrap();
        let balanced = image_of_sums(&warm, window, spectral, sums).unwrap();
        assert_ne!(bits(balanced.pixels()), bits(image.pixels()), "{spectral}");
        // Sums of another window's size are refused.
        let small = PixelBounds::new([3, 2], [19, 12]);
        assert!(image_of_sums(&view, small, spectral, sums).is_err());
    }
}

/// A flag set by the progress sink after the first finished tile stops the
/// render: the later tiles stop before their first sample, and the result
/// is the cancellation error, not an image.
#[test]
fn a_flag_set_during_the_render_stops_it() {
    let (scene, view) = cornell_box([64, 64]).unwrap();
    let stop = AtomicBool::new(false);
    let samples = Mutex::new(0u64);
    let sink = |p: Progress| {
        stop.store(true, Ordering::Relaxed);
        *samples.lock().unwrap() = p.samples_done;
    };
    let o = opts(SamplerName::ZSobol, 4, 1);
    let out = render_cancellable(&scene, &view, &o, &sink, &stop);
    assert!(matches!(out, Err(RenderError::Cancelled)), "{out:?}");
    // One thread: the first tile (16x16 pixels, 4 spp) was whole, every
    // later one stopped at once; far fewer than the 64x64x4 samples.
    assert_eq!(*samples.lock().unwrap(), 16 * 16 * 4);
    let go = AtomicBool::new(false);
    let whole = render_cancellable(&scene, &view, &o, &NoProgress, &go).unwrap();
    let plain = render(&scene, &view, &o, &NoProgress).unwrap();
    assert_eq!(bits(whole.image.pixels()), bits(plain.image.pixels()));
}
