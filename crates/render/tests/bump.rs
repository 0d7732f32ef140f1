//! Bump and normal mapping (pbrt-v4's `BumpMap` and `NormalMap`): analytic
//! checks of the perturbed shading normal, the loader's parameters, and a
//! render of a bumped plane.

use lowdisc::catalog::SamplerName;
use lowdisc_image::RgbImage;
use lowdisc_render::bsdf::{Bump, Material};
use lowdisc_render::geometry::{MeshData, Prim, ShadingGeometry, ShapeSet, TriangleMesh};
use lowdisc_render::math::{Point2, Point3, Ray, Transform, Vec3};
use lowdisc_render::pbrt::{LoadOptions, LoadedScene, load_pbrt_scene};
use lowdisc_render::render::{NoProgress, RenderOptions, render};
use lowdisc_render::texture::{ImageTexture, TexImage, Texture, TextureEvalContext};
use lowdisc_render::view::View;
use std::path::{Path, PathBuf};
use std::sync::Arc;

fn close(a: Vec3, b: Vec3, tol: f32) -> bool {
    (a - b).length() < tol
}

/// The rectangle `[0, width] x [0, 1]` in `z = 0` with `uv = (x / width, y)`,
/// so `∂p/∂u = (width, 0, 0)` and `∂p/∂v = (0, 1, 0)`.
fn quad(width: f32) -> ShapeSet {
    let data = MeshData {
        positions: vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(width, 0.0, 0.0),
            Point3::new(width, 1.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
        ],
        indices: vec![[0, 1, 2], [0, 2, 3]],
        normals: None,
        uvs: Some(vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(0.0, 1.0),
        ]),
    };
    let mut shapes = ShapeSet::new();
    shapes.add_mesh(TriangleMesh::new(&Transform::IDENTITY, data, false).unwrap());
    shapes
}

/// The shading geometry where the ray straight down at `(x, y)` hits `shapes`.
fn geometry_at(shapes: &ShapeSet, x: f32, y: f32) -> (ShadingGeometry, TextureEvalContext, Vec3) {
    let ray = Ray::new(Point3::new(x, y, 1.0), Vec3::new(0.0, 0.0, -1.0));
    for prim in shapes.prims() {
        if let Some(h) = shapes.intersect(prim, &ray, f32::INFINITY) {
            let hit = shapes.surface_hit(prim, &ray, &h);
            let tc = TextureEvalContext {
                p: hit.p,
                uv: hit.uv,
            };
            return (shapes.shading_geometry(prim, &hit), tc, hit.ng);
        }
    }
    panic!("no hit at ({x}, {y})");
}

/// A float image texture of one row of `values` times `scale`.
fn row_texture(values: &[f32], scale: f32) -> Texture<f32> {
    let pixels = values.iter().map(|&v| [v; 3]).collect();
    let image = RgbImage::from_pixels(values.len(), 1, pixels).unwrap();
    let mut t = ImageTexture::new(Arc::new(TexImage::new(image)));
    t.scale = scale;
    Texture::Image(Arc::new(t))
}

#[test]
fn quad_shading_geometry_is_its_parameterisation() {
    let (g, tc, ng) = geometry_at(&quad(3.0), 1.5, 0.25);
    assert!(close(g.dpdu, Vec3::new(3.0, 0.0, 0.0), 1e-5), "{g:?}");
    assert!(close(g.dpdv, Vec3::new(0.0, 1.0, 0.0), 1e-5), "{g:?}");
    assert!(close(g.n.cross(ng), Vec3::ZERO, 1e-6));
    assert!((tc.uv.x - 0.5).abs() < 1e-5 && (tc.uv.y - 0.25).abs() < 1e-5);
}

#[test]
fn a_constant_displacement_leaves_the_normal_unchanged() {
    let (g, tc, ng) = geometry_at(&quad(2.0), 0.7, 0.6);
    for d in [0.0, 0.25, -3.0] {
        let b = Bump::Displacement(d.into()).apply(&tc, ng, &g);
        assert!(close(b.n, g.n, 1e-6), "d = {d}: {b:?}");
    }
    // A curved surface (a sphere of radius 2: ∂n = ∂p / r): a constant
    // displacement scales the tangents, and the normal stays.
    let curved = ShadingGeometry {
        dndu: g.dpdu / 2.0,
        dndv: g.dpdv / 2.0,
        ..g
    };
    let b = Bump::Displacement(0.5.into()).apply(&tc, ng, &curved);
    assert!(close(b.n, g.n, 1e-6), "{b:?}");
    assert!(close(b.dpdu, g.dpdu * 1.25, 1e-5), "{b:?}");
}

#[test]
fn a_linear_displacement_tilts_the_normal_by_the_analytic_angle() {
    // Two texels 0 and 1: between their centres (s in [0.25, 0.75]) the
    // bilinear lookup is 2 s - 0.5, so d(u) = a (2 u - 0.5), slope 2a.
    for (width, a) in [(1.0f32, 0.1f32), (3.0, 0.5), (0.5, -0.2)] {
        let (g, tc, ng) = geometry_at(&quad(width), 0.45 * width, 0.5);
        let d = row_texture(&[0.0, 1.0], a);
        let b = Bump::Displacement(d).apply(&tc, ng, &g);
        // ∂p/∂u' = (width, 0, 2a): the normal turns from +z towards -x by
        // atan(2a / width).
        let angle = (2.0 * a / width).atan();
        let want = Vec3::new(-angle.sin(), 0.0, angle.cos());
        assert!(
            close(b.n, want, 2e-3),
            "width {width}, a {a}: {:?} vs {want:?}",
            b.n
        );
        assert!(b.n.dot(ng) > 0.0);
    }
}

#[test]
fn the_bumped_normal_stays_on_the_geometric_side() {
    // A steep ramp on a quad seen from below (its normal flipped by
    // ReverseOrientation) still gives a normal on the geometric side.
    let (g, tc, _) = geometry_at(&quad(1.0), 0.5, 0.5);
    let ng = -g.n;
    let flipped = ShadingGeometry { n: ng, ..g };
    let b = Bump::Displacement(row_texture(&[0.0, 1.0], 5.0)).apply(&tc, ng, &flipped);
    assert!(b.n.dot(ng) > 0.0, "{b:?}");
}

fn temp_dir(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lowdisc-bump-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn load(dir: &Path, text: &str) -> LoadedScene {
    let path = dir.join("scene.pbrt");
    std::fs::write(&path, text).unwrap();
    load_pbrt_scene(&path, &LoadOptions::default()).unwrap()
}

/// A unit square facing the camera, lit by a distant light at an angle,
/// with `material`; `textures` come before it.
fn plane_scene(textures: &str, material: &str) -> String {
    format!(
        "LookAt 0 0 3 0 0 0 0 1 0\nCamera \"perspective\" \"float fov\" 30\n\
         Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n\
         WorldBegin\n\
         LightSource \"distant\" \"point3 from\" [1 0.5 1] \"point3 to\" [0 0 0]\n\
         {textures}\n{material}\n\
         Shape \"bilinearmesh\" \"point3 P\" [-1 -1 0 1 -1 0 -1 1 0 1 1 0] \
         \"point2 uv\" [0 0 1 0 0 1 1 1]\n"
    )
}

fn render_pixels(l: &LoadedScene) -> Vec<[f32; 3]> {
    let view = View::native(&l.view).unwrap();
    let opts = RenderOptions {
        threads: Some(2),
        ..RenderOptions::new(SamplerName::ZSobol, 3, 4)
    };
    render(&l.scene, &view, &opts, &NoProgress)
        .unwrap()
        .image
        .into_pixels()
}

#[test]
fn a_bumped_plane_renders_differently_from_the_flat_one_and_stays_finite() {
    let dir = temp_dir("render");
    // Eight texels of a sawtooth: a ridged displacement across u.
    let ramp: Vec<[f32; 3]> = (0..8).map(|i| [(i % 4) as f32 / 3.0; 3]).collect();
    let image = RgbImage::from_pixels(8, 1, ramp).unwrap();
    lowdisc_image::write_pfm(dir.join("ridges.pfm"), &image).unwrap();
    let texture = "Texture \"ridges\" \"float\" \"imagemap\" \"string filename\" \"ridges.pfm\" \
                   \"float scale\" 0.05";
    let flat = load(&dir, &plane_scene(texture, "Material \"diffuse\""));
    let bumped = load(
        &dir,
        &plane_scene(
            texture,
            "Material \"diffuse\" \"texture displacement\" \"ridges\"",
        ),
    );
    std::fs::remove_dir_all(&dir).ok();
    assert!(matches!(bumped.scene.materials()[0], Material::Bumped(_)));
    assert!(bumped.warnings.is_empty(), "{:?}", bumped.warnings);
    let (a, b) = (render_pixels(&flat), render_pixels(&bumped));
    assert!(b.iter().flatten().all(|v| v.is_finite() && *v >= 0.0));
    let differing = a
        .iter()
        .zip(&b)
        .filter(|(p, q)| !close(Vec3::from_array(**p), Vec3::from_array(**q), 1e-3))
        .count();
    assert!(
        differing > a.len() / 2,
        "{differing} of {} pixels differ",
        a.len()
    );
}

#[test]
fn the_loader_reads_a_constant_displacement_as_a_bump_map() {
    let dir = temp_dir("constant");
    let l = load(
        &dir,
        &plane_scene("", "Material \"conductor\" \"float displacement\" 0.1"),
    );
    std::fs::remove_dir_all(&dir).ok();
    match &l.scene.materials()[0] {
        Material::Bumped(b) => {
            assert_eq!(b.bump, Bump::Displacement(0.1.into()));
            assert!(matches!(b.material, Material::Conductor { .. }));
        }
        m => panic!("{m:?}"),
    }
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
}

#[test]
fn a_normal_map_image_tilts_the_shading_normal() {
    // A constant tangent-space normal (sin 30°, 0, cos 30°), stored in
    // [0, 1] as pbrt-v4 reads it.
    let (s, c) = (30f32.to_radians().sin(), 30f32.to_radians().cos());
    let texel = [(s + 1.0) / 2.0, 0.5, (c + 1.0) / 2.0];
    let image = RgbImage::filled(4, 4, texel).unwrap();
    let dir = temp_dir("normalmap");
    lowdisc_image::write_pfm(dir.join("tilt.pfm"), &image).unwrap();
    let l = load(
        &dir,
        &plane_scene("", "Material \"diffuse\" \"string normalmap\" \"tilt.pfm\""),
    );
    std::fs::remove_dir_all(&dir).ok();
    let Material::Bumped(b) = &l.scene.materials()[0] else {
        panic!("{:?}", l.scene.materials()[0]);
    };
    assert!(matches!(b.bump, Bump::NormalMap(_)));
    // On the quad, x follows ∂p/∂u = (3, 0, 0): the normal tilts 30° to +x
    // and the tangents keep their lengths.
    let (g, tc, ng) = geometry_at(&quad(3.0), 1.0, 0.3);
    let n = b.bump.apply(&tc, ng, &g);
    assert!(close(n.n, Vec3::new(s, 0.0, c), 1e-4), "{n:?}");
    assert!((n.dpdu.length() - 3.0).abs() < 1e-4 && (n.dpdv.length() - 1.0).abs() < 1e-5);
    assert!(n.dpdu.dot(n.n).abs() < 1e-4 && n.dpdv.dot(n.n).abs() < 1e-4);
}

#[test]
fn a_missing_normal_map_is_an_error_at_the_parameter() {
    let dir = temp_dir("missing");
    let path = dir.join("scene.pbrt");
    std::fs::write(
        &path,
        plane_scene(
            "",
            "Material \"diffuse\" \"string normalmap\" \"nothere.png\"",
        ),
    )
    .unwrap();
    let e = load_pbrt_scene(&path, &LoadOptions::default())
        .unwrap_err()
        .to_string();
    std::fs::remove_dir_all(&dir).ok();
    assert!(
        e.contains("scene.pbrt:7:20:") && e.contains("nothere.png"),
        "{e}"
    );
}

#[test]
fn prims_of_the_quad_are_triangles() {
    assert!(
        quad(1.0)
            .prims()
            .iter()
            .all(|p| matches!(p, Prim::Triangle { .. }))
    );
}

#[test]
fn a_mix_applies_the_bump_map_of_the_material_it_chooses() {
    let dir = temp_dir("mix");
    let ramp: Vec<[f32; 3]> = (0..8).map(|i| [(i % 4) as f32 / 3.0; 3]).collect();
    let image = RgbImage::from_pixels(8, 1, ramp).unwrap();
    lowdisc_image::write_pfm(dir.join("ridges.pfm"), &image).unwrap();
    // An amount of 0 from an image, so that the loader keeps the mix (a
    // constant 0 would be the first material itself).
    let zeros = RgbImage::from_pixels(2, 1, vec![[0.0; 3]; 2]).unwrap();
    lowdisc_image::write_pfm(dir.join("zeros.pfm"), &zeros).unwrap();
    let flat_only = "Texture \"zero\" \"float\" \"imagemap\" \"string filename\" \"zeros.pfm\"\n\
                     MakeNamedMaterial \"flat\" \"string type\" \"diffuse\"";
    let with_bumped = format!(
        "Texture \"ridges\" \"float\" \"imagemap\" \"string filename\" \"ridges.pfm\" \
         \"float scale\" 0.05\n\
         MakeNamedMaterial \"bumped\" \"string type\" \"diffuse\" \
         \"texture displacement\" \"ridges\"\n{flat_only}"
    );
    let bumped = load(&dir, &plane_scene(&with_bumped, "NamedMaterial \"bumped\""));
    // Amount 0 always chooses the first material, the bumped one.
    let mix =
        "Material \"mix\" \"string materials\" [\"bumped\" \"flat\"] \"texture amount\" \"zero\"";
    let mixed = load(&dir, &plane_scene(&with_bumped, mix));
    let plain =
        "Material \"mix\" \"string materials\" [\"flat\" \"flat\"] \"texture amount\" \"zero\"";
    let unbumped = load(&dir, &plane_scene(flat_only, plain));
    let flat = load(&dir, &plane_scene(flat_only, "NamedMaterial \"flat\""));
    std::fs::remove_dir_all(&dir).ok();
    let is_mix = |l: &LoadedScene| {
        l.scene
            .materials()
            .iter()
            .any(|m| matches!(m, Material::Mix(_)))
    };
    assert!(is_mix(&mixed) && is_mix(&unbumped));
    assert!(mixed.scene.materials().iter().any(Material::has_bump));
    assert!(!unbumped.scene.materials().iter().any(Material::has_bump));
    assert_eq!(render_pixels(&mixed), render_pixels(&bumped));
    assert_eq!(render_pixels(&unbumped), render_pixels(&flat));
    assert_ne!(render_pixels(&mixed), render_pixels(&flat));
}
