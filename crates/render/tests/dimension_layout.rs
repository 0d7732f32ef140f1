//! The integrator's documented sampler-dimension layout, pinned with a
//! counting mock sampler: every camera sample draws the film position, then
//! the lens (dimensions 0-1), then exactly `DIMS_PER_BOUNCE` dimensions per
//! scattering vertex in the order light choice (1), light position (2), BSDF
//! lobe (1), BSDF direction (2), Russian roulette (1) - so bounce `k` starts
//! at dimension `2 + 7k`. In spectral mode the wavelength sample comes
//! first (dimension 0), the lens takes 1-2 and bounce `k` starts at `3 + 7k`.
//! In a scene with media the hero lane follows the lens (dimension 2) and
//! every bounce draws `DIMS_PER_MEDIA_BOUNCE` dimensions from `3 + 10k`.
//! Also: the BSDF seed given to the path reaches the layered BSDFs.

use lowdisc::pixel::PixelSampler;
use lowdisc_render::bsdf::{Material, Roughness};
use lowdisc_render::camera::PerspectiveParams;
use lowdisc_render::filter::Filter;
use lowdisc_render::geometry::Sphere;
use lowdisc_render::integrator::{
    DIMS_PER_BOUNCE, DIMS_PER_MEDIA_BOUNCE, PathIntegrator, PathStats,
};
use lowdisc_render::light::{Light, PointLight};
use lowdisc_render::math::{Point3, Transform, Vec3};
use lowdisc_render::medium::{HomogeneousMedium, Medium, MediumInterface};
use lowdisc_render::render::{Shot, trace_sample};
use lowdisc_render::scene::{Scene, SceneBuilder};
use lowdisc_render::spectrum::{Rgb, SampledSpectrum};
use lowdisc_render::view::{CameraSpec, View, ViewSpec};

/// One request made of the sampler.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Draw {
    /// `start_pixel_sample` with its dimension.
    Start(u32),
    /// `get_pixel_2d`.
    Pixel2d,
    /// `get_1d` at this dimension.
    OneD(u32),
    /// `get_2d` at this first dimension.
    TwoD(u32),
}

/// Records every request and returns fixed values: 0.5 for 2-D draws (BSDF
/// directions near the normal) and 0.99 for 1-D draws (Russian roulette
/// never ends a path of albedo 0.8).
#[derive(Default)]
struct CountingSampler {
    dimension: u32,
    log: Vec<Draw>,
}

impl PixelSampler for CountingSampler {
    fn samples_per_pixel(&self) -> u32 {
        1
    }
    fn start_pixel_sample(&mut self, _pixel: [u32; 2], _index: u32, dimension: u32) {
        self.dimension = dimension;
        self.log.push(Draw::Start(dimension));
    }
    fn get_1d(&mut self) -> f32 {
        self.log.push(Draw::OneD(self.dimension));
        self.dimension += 1;
        0.99
    }
    fn get_2d(&mut self) -> [f32; 2] {
        self.log.push(Draw::TwoD(self.dimension));
        self.dimension += 2;
        [0.5, 0.5]
    }
    fn get_pixel_2d(&mut self) -> [f32; 2] {
        self.log.push(Draw::Pixel2d);
        [0.5, 0.5]
    }
}

/// The camera at the centre of a closed sphere of `material`, lit by a point
/// light inside it: every path scatters until its depth runs out.
fn inside_a_sphere(material: Material) -> (Scene, View) {
    let mut b = SceneBuilder::new();
    let m = b.add_material(material);
    b.add_sphere(
        Sphere::new(Transform::IDENTITY, 1.0, true).unwrap(),
        m,
        None,
    );
    let light = PointLight::new(
        &Transform::IDENTITY,
        Point3::new(0.2, 0.3, 0.1),
        Rgb::ONE,
        1.0,
        None,
    );
    b.add_light(Light::Point(light.unwrap()));
    let look = Transform::look_at(Point3::ZERO, Point3::new(0.0, 0.0, 1.0), Vec3::Y).unwrap();
    let camera = CameraSpec {
        world_from_camera: look.inverse(),
        params: PerspectiveParams::default(),
    };
    let view = View::native(&ViewSpec::new(camera, [4, 4], Filter::default())).unwrap();
    (b.build().unwrap(), view)
}

/// The draws the documentation promises for a path with `bounces` vertices.
fn documented(bounces: u32) -> Vec<Draw> {
    let mut v = vec![Draw::Start(0), Draw::Pixel2d, Draw::TwoD(0)];
    for k in 0..bounces {
        let d = 2 + DIMS_PER_BOUNCE * k;
        v.extend([
            Draw::OneD(d),
            Draw::TwoD(d + 1),
            Draw::OneD(d + 3),
            Draw::TwoD(d + 4),
            Draw::OneD(d + 6),
        ]);
    }
    v
}

fn trace((scene, view): &(Scene, View), max_depth: u32, seed: u64) -> (Rgb, Vec<Draw>) {
    let integrator = PathIntegrator {
        max_depth,
        ..PathIntegrator::default()
    };
    let mut sampler = CountingSampler::default();
    let mut stats = PathStats::default();
    let shot = Shot {
        scene,
        view,
        integrator: &integrator,
        seed,
    };
    let (l, _) = trace_sample::<Rgb, _>(&shot, &mut sampler, [1, 2], 0, &mut stats);
    (l, sampler.log)
}

#[test]
fn every_bounce_draws_seven_dimensions_in_the_documented_order() {
    assert_eq!(DIMS_PER_BOUNCE, 7);
    let scene = inside_a_sphere(Material::diffuse(Rgb::splat(0.8)));
    for max_depth in [0, 1, 2, 5, 9] {
        let (l, log) = trace(&scene, max_depth, 0);
        assert_eq!(log, documented(max_depth), "max depth {max_depth}");
        assert!(max_depth == 0 || l.max_component() > 0.0, "lit: {l:?}");
    }
}

#[test]
fn specular_vertices_draw_the_same_dimensions() {
    // A mirror: no light sample is taken, yet all seven dimensions are drawn.
    let mirror = Material::Conductor {
        spec: lowdisc_render::bsdf::ConductorSpec::Reflectance(Rgb::splat(0.9)).into(),
        roughness: Roughness::SMOOTH.into(),
    };
    let scene = inside_a_sphere(mirror);
    let (_, log) = trace(&scene, 4, 0);
    assert_eq!(log, documented(4));
}

#[test]
fn the_bsdf_seed_reaches_the_layered_bsdfs() {
    // A coated diffuse sphere: its random walks depend on the seed, the
    // sampler's values do not.
    let scene = inside_a_sphere(Material::pbrt_default("coateddiffuse").unwrap());
    let (a, log_a) = trace(&scene, 3, 1);
    let (b, log_b) = trace(&scene, 3, 2);
    let (a_again, _) = trace(&scene, 3, 1);
    assert_eq!(log_a, log_b);
    assert_eq!(a, a_again, "deterministic for one seed");
    assert_ne!(a, b, "the seed changes the layered BSDF's walks");
}

#[test]
fn spectral_samples_draw_the_wavelength_first_then_the_rgb_layout_shifted_by_one() {
    let scene = inside_a_sphere(Material::diffuse(Rgb::splat(0.8)));
    let integrator = PathIntegrator {
        max_depth: 3,
        ..PathIntegrator::default()
    };
    let mut sampler = CountingSampler::default();
    let mut stats = PathStats::default();
    let shot = Shot {
        scene: &scene.0,
        view: &scene.1,
        integrator: &integrator,
        seed: 0,
    };
    let (xyz, _) = trace_sample::<SampledSpectrum, _>(&shot, &mut sampler, [1, 2], 0, &mut stats);
    assert!(xyz.g > 0.0, "lit: {xyz:?}");
    let mut want = vec![Draw::Start(0), Draw::OneD(0), Draw::Pixel2d, Draw::TwoD(1)];
    for k in 0..3 {
        let d = 3 + DIMS_PER_BOUNCE * k;
        want.extend([
            Draw::OneD(d),
            Draw::TwoD(d + 1),
            Draw::OneD(d + 3),
            Draw::TwoD(d + 4),
            Draw::OneD(d + 6),
        ]);
    }
    assert_eq!(sampler.log, want);
}

/// [`inside_a_sphere`] filled with a thin medium (the camera in it too):
/// rendered by the volumetric path tracer.
fn inside_a_foggy_sphere(material: Material) -> (Scene, View) {
    let (_, view) = inside_a_sphere(material.clone());
    let mut b = SceneBuilder::new();
    let fog = b.add_medium(Medium::Homogeneous(HomogeneousMedium {
        sigma_a: Rgb::splat(0.01),
        sigma_s: Rgb::splat(0.01),
        le: Rgb::ZERO,
        g: 0.0,
    }));
    b.set_medium_interface(MediumInterface {
        inside: Some(fog),
        outside: None,
    });
    b.set_camera_medium(Some(fog));
    let m = b.add_material(material);
    b.add_sphere(
        Sphere::new(Transform::IDENTITY, 1.0, true).unwrap(),
        m,
        None,
    );
    let light = PointLight::new(
        &Transform::IDENTITY,
        Point3::new(0.2, 0.3, 0.1),
        Rgb::ONE,
        1.0,
        None,
    );
    b.add_light(Light::Point(light.unwrap()));
    (b.build().unwrap(), view)
}

#[test]
fn media_scenes_draw_the_hero_lane_then_ten_dimensions_per_bounce() {
    assert_eq!(DIMS_PER_MEDIA_BOUNCE, 10);
    let scene = inside_a_foggy_sphere(Material::diffuse(Rgb::splat(0.8)));
    assert!(scene.0.has_media());
    for max_depth in [0, 1, 4] {
        let (l, log) = trace(&scene, max_depth, 0);
        // The 1-D values (0.99) send every free flight through the fog to
        // the sphere: a surface vertex ends every bounce, and one more
        // bounce is drawn for the ray that reaches the depth limit.
        let mut want = vec![Draw::Start(0), Draw::Pixel2d, Draw::TwoD(0), Draw::OneD(2)];
        for k in 0..=max_depth {
            let d = 3 + DIMS_PER_MEDIA_BOUNCE * k;
            want.extend([
                Draw::OneD(d),
                Draw::OneD(d + 1),
                Draw::OneD(d + 2),
                Draw::OneD(d + 3),
                Draw::TwoD(d + 4),
                Draw::OneD(d + 6),
                Draw::TwoD(d + 7),
                Draw::OneD(d + 9),
            ]);
        }
        assert_eq!(log, want, "max depth {max_depth}");
        assert!(max_depth == 0 || l.max_component() > 0.0, "lit: {l:?}");
    }
}
