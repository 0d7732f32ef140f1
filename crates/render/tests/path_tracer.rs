//! Analytic checks of the path tracer (after pbrt-v4's integrator tests):
//! furnaces whose answer is a known finite sum, a point light inside a
//! sphere, and agreement of BSDF-only, light-only and MIS direct lighting.

use lowdisc::catalog::SamplerName;
use lowdisc_render::bsdf::Material;
use lowdisc_render::camera::PerspectiveParams;
use lowdisc_render::filter::Filter;
use lowdisc_render::geometry::{MeshData, Sphere, TriangleMesh};
use lowdisc_render::integrator::{LightStrategy, PathIntegrator};
use lowdisc_render::light::{Light, PointLight, UniformInfiniteLight};
use lowdisc_render::math::{Point3, Transform, Vec3};
use lowdisc_render::render::{NoProgress, RenderOptions, render};
use lowdisc_render::scene::{Emission, Scene, SceneBuilder};
use lowdisc_render::spectrum::Rgb;
use lowdisc_render::view::{CameraSpec, View, ViewSpec};
use std::f64::consts::PI;

fn camera(from: Point3, at: Point3, fov: f32) -> CameraSpec {
    let up = if (at - from).cross(Vec3::Y).length() > 1e-3 {
        Vec3::Y
    } else {
        Vec3::Z
    };
    let look = Transform::look_at(from, at, up).unwrap();
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

/// Mean image value (channel average) of `scene` at `spp` and `max_depth`.
fn mean(scene: &Scene, view: &View, spp: u32, max_depth: u32, strategy: LightStrategy) -> f64 {
    let opts = RenderOptions {
        integrator: PathIntegrator {
            max_depth,
            strategy,
            ..PathIntegrator::default()
        },
        threads: Some(2),
        ..RenderOptions::new(SamplerName::ZSobol, 3, spp)
    };
    let out = render(scene, view, &opts, &NoProgress).unwrap();
    assert_eq!(out.stats.nonfinite_samples, 0);
    let m = out.mean();
    (m[0] + m[1] + m[2]) / 3.0
}

fn grey(v: f32) -> Material {
    Material::diffuse(Rgb::splat(v))
}

#[test]
fn furnace_convex_sphere_in_uniform_light() {
    // A diffuse sphere (albedo 0.5) filling the view, inside a uniform
    // environment L = 1. Every ray leaving the convex sphere escapes, so the
    // finite sum stops after one bounce: 0 for maxdepth 0, then 0.5 * L.
    let mut b = SceneBuilder::new();
    let m = b.add_material(grey(0.5));
    b.add_sphere(
        Sphere::new(Transform::IDENTITY, 1.0, false).unwrap(),
        m,
        None,
    );
    b.add_light(Light::UniformInfinite(
        UniformInfiniteLight::new(Rgb::ONE, 1.0, None).unwrap(),
    ));
    let view = view(camera(Point3::new(0.0, 0.0, -5.0), Point3::ZERO, 8.0), 8);
    let scene = b.build().unwrap();
    assert_eq!(mean(&scene, &view, 16, 0, LightStrategy::Mis), 0.0);
    for depth in [1, 4] {
        for strategy in [
            LightStrategy::Mis,
            LightStrategy::BsdfOnly,
            LightStrategy::LightOnly,
        ] {
            let v = mean(&scene, &view, 256, depth, strategy);
            assert!((v - 0.5).abs() < 0.01, "depth {depth} {strategy:?}: {v}");
        }
    }
}

#[test]
fn furnace_inside_emitting_sphere_follows_the_finite_sum() {
    // Inside a closed sphere of albedo r = 0.5 emitting Le = 1 inwards, the
    // radiance after at most D bounces is Le * sum_{k=0}^{D} r^k.
    let mut b = SceneBuilder::new();
    let m = b.add_material(grey(0.5));
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
    let scene = b.build().unwrap();
    for depth in [0u32, 1, 2, 5] {
        let expected: f64 = (0..=depth).map(|k| 0.5f64.powi(k as i32)).sum();
        let v = mean(&scene, &view, 256, depth, LightStrategy::Mis);
        assert!(
            (v - expected).abs() < 0.015 * expected,
            "depth {depth}: {v} vs {expected}"
        );
    }
}

#[test]
fn point_light_inside_a_unit_sphere() {
    // pbrt-v4's test: intensity I at the centre of a unit sphere of albedo r
    // gives L = (r I / pi) * sum_{k=0}^{D-1} r^k after at most D bounces.
    let mut b = SceneBuilder::new();
    let m = b.add_material(grey(0.5));
    b.add_sphere(
        Sphere::new(Transform::IDENTITY, 1.0, false).unwrap(),
        m,
        None,
    );
    let pl = PointLight::new(
        &Transform::IDENTITY,
        Point3::ZERO,
        Rgb::splat(2.0),
        1.0,
        None,
    )
    .unwrap();
    b.add_light(Light::Point(pl));
    let view = view(
        camera(Point3::new(0.0, 0.1, 0.0), Point3::new(0.3, 0.1, 1.0), 60.0),
        8,
    );
    let scene = b.build().unwrap();
    for depth in [1u32, 2, 5] {
        let sum: f64 = (0..depth).map(|k| 0.5f64.powi(k as i32)).sum();
        let expected = 0.5 * 2.0 / PI * sum;
        let v = mean(&scene, &view, 128, depth, LightStrategy::Mis);
        assert!(
            (v - expected).abs() < 0.015 * expected,
            "depth {depth}: {v} vs {expected}"
        );
    }
    // BSDF sampling alone can never reach a point light.
    assert_eq!(mean(&scene, &view, 4, 3, LightStrategy::BsdfOnly), 0.0);
}

fn quad(corners: [[f32; 3]; 4]) -> TriangleMesh {
    let data = MeshData {
        positions: corners.iter().map(|&c| Point3::from_array(c)).collect(),
        indices: vec![[0, 1, 2], [0, 2, 3]],
        normals: None,
        uvs: None,
    };
    TriangleMesh::new(&Transform::IDENTITY, data, false).unwrap()
}

#[test]
fn bsdf_light_and_mis_sampling_agree_in_the_mean() {
    // A floor and a back wall lit by a square area light facing down.
    let mut b = SceneBuilder::new();
    let m = b.add_material(grey(0.6));
    let black = b.add_material(grey(0.0));
    b.add_mesh(
        quad([
            [-2.0, 0.0, -2.0],
            [-2.0, 0.0, 2.0],
            [2.0, 0.0, 2.0],
            [2.0, 0.0, -2.0],
        ]),
        m,
        None,
    );
    b.add_mesh(
        quad([
            [-2.0, 0.0, 1.0],
            [-2.0, 2.0, 1.0],
            [2.0, 2.0, 1.0],
            [2.0, 0.0, 1.0],
        ]),
        m,
        None,
    );
    // A 1.6 x 1.6 light at height 1.2 split into 4 x 4 quads (32 triangles,
    // so each is chosen with probability 1/32: MIS weights that forget the
    // choice probability are far off), face normals pointing down (-y).
    let mut light = MeshData::default();
    for i in 0..4 {
        for j in 0..4 {
            let (x, z) = (-0.8 + 0.4 * i as f32, -0.8 + 0.4 * j as f32);
            let k = light.positions.len() as u32;
            for (dx, dz) in [(0.0, 0.0), (0.4, 0.0), (0.4, 0.4), (0.0, 0.4)] {
                light.positions.push(Point3::new(x + dx, 1.2, z + dz));
            }
            light.indices.extend([[k, k + 1, k + 2], [k, k + 2, k + 3]]);
        }
    }
    let light = TriangleMesh::new(&Transform::IDENTITY, light, false).unwrap();
    let emission = Emission {
        l: Rgb::splat(2.0),
        two_sided: false,
    };
    b.add_mesh(light, black, Some(emission));
    let view = view(
        camera(
            Point3::new(0.0, 0.6, -3.0),
            Point3::new(0.0, 0.3, 0.0),
            50.0,
        ),
        16,
    );
    let scene = b.build().unwrap();
    for depth in [1u32, 3] {
        let mis = mean(&scene, &view, 256, depth, LightStrategy::Mis);
        let bsdf = mean(&scene, &view, 256, depth, LightStrategy::BsdfOnly);
        let light = mean(&scene, &view, 256, depth, LightStrategy::LightOnly);
        assert!(mis > 0.05, "{mis}");
        for (name, v) in [("bsdf", bsdf), ("light", light)] {
            assert!(
                (v - mis).abs() < 0.02 * mis,
                "depth {depth}: {name} {v} vs mis {mis}"
            );
        }
    }
    // More depth adds light (indirect bounces between floor and wall).
    assert!(
        mean(&scene, &view, 64, 3, LightStrategy::Mis)
            > 1.02 * mean(&scene, &view, 64, 1, LightStrategy::Mis)
    );
}
