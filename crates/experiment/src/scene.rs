//! The built-in experiment scene, "what sportscar has" without downloads:
//! glossy metal and coated (car-paint-like) shapes on a diffuse ground, lit
//! by a procedural sky.
//!
//! World space is z-up. The ground is a grey diffuse disk of radius 50 at
//! `z = 0`. On it stand: a rough gold sphere (GGX roughness 0.1), a rough
//! aluminium sphere (0.3), a red car-paint sphere (`coateddiffuse`, smooth
//! clear coat over red), a metallic-paint sphere (`coatedconductor`: smooth
//! coat over a rough conductor with eta (1.2, 1.0, 0.5), k (3.0, 3.5, 5.0)),
//! and a flat box of the same metallic paint. The camera looks slightly down at them.
//!
//! **Sky** ([`procedural_sky`]): a lat-long image (2:1, the light's z axis is
//! up, `v = θ/π`, `u = φ/2π`) holding a gradient from a pale horizon
//! `(0.9, 0.95, 1.0)` to a blue zenith `(0.25, 0.45, 0.9)` (linear RGB,
//! interpolated in `sqrt(cos θ)`), a dark ground colour `(0.12, 0.11, 0.10)`
//! below the horizon, and a sun: a disk of angular radius 2° at elevation
//! 35° and azimuth 60° with radiance `(1500, 1400, 1250)`. The sun is a few
//! texels wide, so the light's importance sampling finds it.
//!
//! **Film**: a box filter and, as in the pbrt-v4 sportscar scene, a
//! `maxcomponentvalue` of 10 ([`MAX_COMPONENT_VALUE`]). Without it the
//! sun's mirror image in the smooth clear coats (a spot far smaller than a
//! pixel, 1,500 times brighter than the sky) makes single samples carry
//! whole-pixel errors of ~100, and the linear relMSE of a 16-spp render is
//! decided by whether such a sample happens to fall in a pixel (its sd over
//! seeds exceeded its mean). The clamp applies to the reference too, so
//! every sampler is measured against the same, clamped, image.

use anyhow::{Context, Result};
use lowdisc_image::RgbImage;
use lowdisc_render::bsdf::{ConductorSpec, Material, Roughness};
use lowdisc_render::camera::PerspectiveParams;
use lowdisc_render::filter::Filter;
use lowdisc_render::geometry::{Disk, MeshData, Sphere, TriangleMesh};
use lowdisc_render::light::{EnvLayout, EnvLookup, ImageInfiniteLight, Light};
use lowdisc_render::math::{Point3, Transform, Vec3};
use lowdisc_render::scene::{Scene, SceneBuilder};
use lowdisc_render::spectrum::Rgb;
use lowdisc_render::view::{CameraSpec, ViewSpec};

/// A name and version of the built-in scene, part of the reference cache key.
pub const SCENE_ID: &str = "builtin-showroom-v2";
/// Width of the procedural sky (height is half).
pub const SKY_WIDTH: usize = 512;
/// Sun angular radius in degrees.
pub const SUN_RADIUS_DEG: f64 = 2.0;
/// Sun elevation above the horizon in degrees.
pub const SUN_ELEVATION_DEG: f64 = 35.0;
/// Sun azimuth in degrees.
pub const SUN_AZIMUTH_DEG: f64 = 60.0;
/// Sun radiance (linear RGB).
pub const SUN_RADIANCE: [f32; 3] = [1500.0, 1400.0, 1250.0];
/// The film's `maxcomponentvalue`: each camera sample's RGB is scaled down
/// so that its largest component is at most this (pbrt-v4's `RGBFilm`), as
/// the pbrt-v4 sportscar scene's own film does (`"float maxcomponentvalue" 10`).
pub const MAX_COMPONENT_VALUE: f32 = 10.0;

fn dir(theta: f64, phi: f64) -> [f64; 3] {
    [
        theta.sin() * phi.cos(),
        theta.sin() * phi.sin(),
        theta.cos(),
    ]
}

/// The procedural sky as a `width x width/2` lat-long image (see the module doc).
pub fn procedural_sky(width: usize) -> Result<RgbImage> {
    let height = (width / 2).max(1);
    let sun = dir(
        (90.0 - SUN_ELEVATION_DEG).to_radians(),
        SUN_AZIMUTH_DEG.to_radians(),
    );
    let cos_sun = SUN_RADIUS_DEG.to_radians().cos();
    let horizon = [0.9f32, 0.95, 1.0];
    let zenith = [0.25f32, 0.45, 0.9];
    let ground = [0.12f32, 0.11, 0.10];
    let image = RgbImage::from_fn(width, height, |x, y| {
        let theta = (y as f64 + 0.5) / height as f64 * std::f64::consts::PI;
        let phi = (x as f64 + 0.5) / width as f64 * 2.0 * std::f64::consts::PI;
        let d = dir(theta, phi);
        let cos_angle = d[0] * sun[0] + d[1] * sun[1] + d[2] * sun[2];
        if cos_angle >= cos_sun {
            return SUN_RADIANCE;
        }
        if d[2] <= 0.0 {
            return ground;
        }
        let t = d[2].sqrt() as f32;
        [0, 1, 2].map(|c| horizon[c] + (zenith[c] - horizon[c]) * t)
    })?;
    Ok(image)
}

/// An axis-aligned box mesh from `lo` to `hi`, 12 outward-facing triangles.
fn box_mesh(lo: [f32; 3], hi: [f32; 3]) -> Result<TriangleMesh> {
    let mut data = MeshData::default();
    for i in 0..8u32 {
        let p = [0, 1, 2].map(|a| if i >> a & 1 == 1 { hi[a] } else { lo[a] });
        data.positions.push(Point3::from_array(p));
    }
    // Faces as corner indices (bit a of an index = upper side on axis a).
    let faces: [[u32; 4]; 6] = [
        [0, 2, 6, 4],
        [1, 5, 7, 3],
        [0, 4, 5, 1],
        [2, 3, 7, 6],
        [0, 1, 3, 2],
        [4, 6, 7, 5],
    ];
    for f in faces {
        data.indices.push([f[0], f[1], f[2]]);
        data.indices.push([f[0], f[2], f[3]]);
    }
    Ok(TriangleMesh::new(&Transform::IDENTITY, data, false)?)
}

fn sphere(b: &mut SceneBuilder, center: [f32; 3], r: f32, material: u32) -> Result<()> {
    let xf = Transform::translate(Vec3::new(center[0], center[1], center[2]));
    b.add_sphere(Sphere::new(xf, r, false)?, material, None);
    Ok(())
}

/// Builds the built-in scene, lit by `sky` (a lat-long or equal-area image;
/// `None` uses [`procedural_sky`]), and its view on a `resolution` film.
pub fn showroom(resolution: [u32; 2], sky: Option<&RgbImage>) -> Result<(Scene, ViewSpec)> {
    let mut b = SceneBuilder::new();
    let ground = b.add_material(Material::diffuse(Rgb::splat(0.4)));
    let gold = b.add_material(Material::Conductor {
        spec: ConductorSpec::named("Au")?.into(),
        roughness: Roughness::isotropic(0.1, true).into(),
    });
    let alu = b.add_material(Material::Conductor {
        spec: ConductorSpec::named("Al")?.into(),
        roughness: Roughness::isotropic(0.3, true).into(),
    });
    let paint = b.add_material(Material::CoatedDiffuse {
        reflectance: Rgb::new(0.6, 0.05, 0.04).into(),
        roughness: Roughness::SMOOTH.into(),
        thickness: 0.01.into(),
        eta: 1.5,
        max_depth: 10,
        n_samples: 1,
    });
    let metallic = b.add_material(Material::CoatedConductor {
        interface_roughness: Roughness::SMOOTH.into(),
        interface_eta: 1.5,
        thickness: 0.01.into(),
        conductor: ConductorSpec::EtaK {
            eta: Rgb::new(1.2, 1.0, 0.5),
            k: Rgb::new(3.0, 3.5, 5.0),
        }
        .into(),
        conductor_roughness: Roughness::isotropic(0.2, true).into(),
        max_depth: 10,
        n_samples: 1,
    });
    b.add_disk(
        Disk::new(Transform::IDENTITY, 0.0, 50.0, 0.0, false)?,
        ground,
        None,
    );
    sphere(&mut b, [0.0, 0.0, 1.0], 1.0, gold)?;
    sphere(&mut b, [2.3, 0.8, 0.8], 0.8, alu)?;
    sphere(&mut b, [-2.2, 0.6, 0.9], 0.9, paint)?;
    sphere(&mut b, [1.0, -1.9, 0.6], 0.6, metallic)?;
    b.add_mesh(
        box_mesh([-3.5, -2.5, 0.0], [-1.5, -1.5, 0.6])?,
        metallic,
        None,
    );

    let generated;
    let sky = match sky {
        Some(s) => s,
        None => {
            generated = procedural_sky(SKY_WIDTH)?;
            &generated
        }
    };
    let light = ImageInfiniteLight::from_image(
        &Transform::IDENTITY,
        sky,
        Some(EnvLayout::detect(sky.width(), sky.height())?),
        EnvLookup::Bilinear,
        1.0,
        None,
    )?;
    b.add_light(Light::ImageInfinite(Box::new(light)));

    let look = Transform::look_at(
        Point3::new(-1.0, -9.0, 3.2),
        Point3::new(0.0, 0.0, 0.7),
        Vec3::new(0.0, 0.0, 1.0),
    )
    .context("singular camera")?;
    let camera = CameraSpec {
        world_from_camera: look.inverse(),
        params: PerspectiveParams {
            fov: 32.0,
            ..PerspectiveParams::default()
        },
    };
    let filter = Filter::box_filter([0.5, 0.5]).map_err(|e| anyhow::anyhow!("{e}"))?;
    let mut view = ViewSpec::new(camera, resolution, filter);
    view.film.max_component_value = MAX_COMPONENT_VALUE;
    Ok((b.build()?, view))
}
