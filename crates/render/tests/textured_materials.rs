//! Materials with textured parameters: a checkerboard-textured diffuse plane
//! under uniform light shows its two albedos, an image texture's texel comes
//! back through the BSDF at its uv, constant materials do not depend on the
//! shading point, `mix` follows a textured amount, and the pbrt loader builds
//! textured materials (keeping untextured ones constant).

mod common;

use lowdisc::catalog::SamplerName;
use lowdisc_image::RgbImage;
use lowdisc_render::bsdf::{
    BsdfContext, ConductorSpec, Material, MixMaterial, Roughness, TransportMode,
};
use lowdisc_render::camera::PerspectiveParams;
use lowdisc_render::filter::Filter;
use lowdisc_render::geometry::{MeshData, TriangleMesh};
use lowdisc_render::integrator::{LightStrategy, PathIntegrator};
use lowdisc_render::light::{Light, UniformInfiniteLight};
use lowdisc_render::math::{Point2, Point3, Transform, Vec3};
use lowdisc_render::pbrt::{LoadOptions, load_pbrt_scene};
use lowdisc_render::render::{NoProgress, RenderOptions, render};
use lowdisc_render::scene::SceneBuilder;
use lowdisc_render::spectrum::Rgb;
use lowdisc_render::texture::{
    Checker, FloatTexture, ImageTexture, SpectrumTexture, TexImage, TextureMapping,
};
use lowdisc_render::view::{CameraSpec, View, ViewSpec};
use std::f32::consts::PI;
use std::sync::Arc;

const RHO1: Rgb = Rgb::new(0.8, 0.2, 0.5);
const RHO2: Rgb = Rgb::new(0.1, 0.6, 0.3);

/// A 2x2 checkerboard over uv (`uscale = vscale = 2`).
fn checker_2x2(tex1: Rgb, tex2: Rgb) -> SpectrumTexture {
    SpectrumTexture::Checkerboard {
        checker: Arc::new(Checker::TwoD(TextureMapping::Uv {
            su: 2.0,
            sv: 2.0,
            du: 0.0,
            dv: 0.0,
        })),
        tex1: Arc::new(tex1.into()),
        tex2: Arc::new(tex2.into()),
    }
}

fn ctx_at(uv: Point2) -> BsdfContext {
    BsdfContext {
        ns: Vec3::Z,
        dpdus: Vec3::X,
        seed: 0,
        p: Point3::ZERO,
        uv,
        wo: Vec3::Z,
    }
}

/// `f(wo, wi) * π` of a diffuse material at `uv` (its reflectance).
fn diffuse_albedo(m: &Material, uv: Point2) -> Rgb {
    let w = Vec3::new(0.3, 0.2, 0.9).normalize();
    m.bsdf(&ctx_at(uv)).f(w, Vec3::Z, TransportMode::Radiance) * PI
}

fn close(a: Rgb, b: Rgb, tol: f32) -> bool {
    (a - b).map(f32::abs).max_component() <= tol
}

#[test]
fn checkerboard_plane_in_a_furnace_shows_both_albedos() {
    // The square [-1,1]^2 in z = 0 with uv = ((x+1)/2, (y+1)/2): the checker
    // makes four quadrants. Under a uniform environment L = 1 a Lambertian
    // plane (nothing else in the scene) reflects exactly rho * L.
    let mut b = SceneBuilder::new();
    let m = b.add_material(Material::Diffuse {
        reflectance: checker_2x2(RHO1, RHO2),
    });
    let data = MeshData {
        positions: vec![
            Point3::new(-1.0, -1.0, 0.0),
            Point3::new(1.0, -1.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(-1.0, 1.0, 0.0),
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
    b.add_mesh(
        TriangleMesh::new(&Transform::IDENTITY, data, false).unwrap(),
        m,
        None,
    );
    b.add_light(Light::UniformInfinite(
        UniformInfiniteLight::new(Rgb::ONE, 1.0, None).unwrap(),
    ));
    let look = Transform::look_at(Point3::new(0.0, 0.0, 5.0), Point3::ZERO, Vec3::Y).unwrap();
    let camera = CameraSpec {
        world_from_camera: look.inverse(),
        // Half-width 5 tan(10°) = 0.88 < 1: the plane fills the image.
        params: PerspectiveParams {
            fov: 20.0,
            ..PerspectiveParams::default()
        },
    };
    let filter = Filter::box_filter([0.5, 0.5]).unwrap();
    let view = View::native(&ViewSpec::new(camera, [8, 8], filter)).unwrap();
    let scene = b.build().unwrap();
    let opts = RenderOptions {
        integrator: PathIntegrator {
            max_depth: 1,
            strategy: LightStrategy::Mis,
            ..PathIntegrator::default()
        },
        threads: Some(2),
        ..RenderOptions::new(SamplerName::ZSobol, 11, 64)
    };
    let out = render(&scene, &view, &opts, &NoProgress).unwrap();
    let px = |x: usize, y: usize| Rgb::from_array(out.image.get(x, y).unwrap());
    // Each 4x4 quadrant of pixels lies inside one checker square; whatever
    // the camera's handedness, opposite quadrants share an albedo and
    // neighbouring ones differ.
    let (mut n1, mut n2) = (0, 0);
    for y in 0..8 {
        for x in 0..8 {
            let v = px(x, y);
            let is1 = close(v, RHO1, 0.02);
            let is2 = close(v, RHO2, 0.02);
            assert!(is1 ^ is2, "pixel ({x},{y}) = {v:?}");
            n1 += usize::from(is1);
            n2 += usize::from(is2);
            let same_as_opposite = close(px(7 - x, 7 - y), v, 0.04);
            let same_as_mirror = close(px(7 - x, y), v, 0.04);
            assert!(same_as_opposite && !same_as_mirror, "pixel ({x},{y})");
        }
    }
    assert_eq!((n1, n2), (32, 32));
}

#[test]
fn image_texture_texel_comes_back_through_the_bsdf() {
    const T: [[f32; 3]; 4] = [
        [0.9, 0.1, 0.2],
        [0.3, 0.7, 0.1],
        [0.05, 0.25, 0.85],
        [0.5, 0.5, 0.5],
    ];
    // Row 0 (the top of the image) is T[0] T[1]; the texture flips t.
    let img = TexImage::new(RgbImage::from_pixels(2, 2, T.to_vec()).unwrap());
    let reflectance = SpectrumTexture::Image(Arc::new(ImageTexture::new(Arc::new(img))));
    let m = Material::Diffuse { reflectance };
    assert!(!m.is_constant());
    let centres = [(0.25, 0.75), (0.75, 0.75), (0.25, 0.25), (0.75, 0.25)];
    for (texel, (u, v)) in T.iter().zip(centres) {
        let got = diffuse_albedo(&m, Point2::new(u, v));
        assert!(
            close(got, Rgb::from_array(*texel), 1e-6),
            "{got:?} {texel:?}"
        );
    }
    // Between the two top texels: their bilinear average.
    let mid = diffuse_albedo(&m, Point2::new(0.5, 0.75));
    let want = (Rgb::from_array(T[0]) + Rgb::from_array(T[1])) * 0.5;
    assert!(close(mid, want, 1e-6), "{mid:?}");
}

fn constant_materials() -> Vec<Material> {
    let gold = ConductorSpec::named("Au").unwrap();
    vec![
        Material::diffuse(Rgb::new(0.7, 0.4, 0.2)),
        Material::Conductor {
            spec: gold.into(),
            roughness: Roughness {
                u: 0.3,
                v: 0.1,
                remap: true,
            }
            .into(),
        },
        Material::Conductor {
            spec: ConductorSpec::Reflectance(Rgb::new(0.9, 0.5, 0.3)).into(),
            roughness: Roughness::isotropic(0.2, false).into(),
        },
        Material::Dielectric {
            eta: 1.33,
            roughness: Roughness::isotropic(0.25, false).into(),
        },
        Material::DiffuseTransmission {
            reflectance: Rgb::splat(0.3).into(),
            transmittance: Rgb::new(0.5, 0.2, 0.1).into(),
            scale: 1.5,
        },
        Material::CoatedDiffuse {
            reflectance: Rgb::new(0.6, 0.1, 0.1).into(),
            roughness: Roughness::isotropic(0.1, true).into(),
            thickness: 0.02.into(),
            eta: 1.5,
            max_depth: 10,
            n_samples: 1,
        },
        Material::CoatedConductor {
            interface_roughness: Roughness::isotropic(0.05, true).into(),
            interface_eta: 1.4,
            thickness: 0.01.into(),
            conductor: gold.into(),
            conductor_roughness: Roughness::isotropic(0.2, true).into(),
            max_depth: 10,
            n_samples: 2,
        },
    ]
}

#[test]
fn constant_materials_do_not_depend_on_the_shading_point() {
    let mut rng = common::Rng::new(21);
    for m in constant_materials() {
        assert!(m.is_constant(), "{m:?}");
        for _ in 0..50 {
            let ctx = BsdfContext {
                ns: Vec3::new(0.1, 0.2, 0.97).normalize(),
                dpdus: Vec3::new(1.0, 0.0, -0.1),
                seed: 5,
                p: rng.vec(-1.0, 1.0),
                uv: Point2::new(rng.f32(), rng.f32()),
                wo: Vec3::Z,
            };
            let origin = BsdfContext {
                p: Point3::ZERO,
                uv: Point2::default(),
                ..ctx
            };
            let (a, b) = (m.bsdf(&ctx), m.bsdf(&origin));
            let wo = rng.vec(-1.0, 1.0).normalize();
            let wi = rng.vec(-1.0, 1.0).normalize();
            let mode = TransportMode::Radiance;
            assert_eq!(a.f(wo, wi, mode), b.f(wo, wi, mode), "{m:?}");
            assert_eq!(a.pdf(wo, wi, mode).to_bits(), b.pdf(wo, wi, mode).to_bits());
            let (uc, u2) = (rng.f32(), [rng.f32(), rng.f32()]);
            assert_eq!(a.sample_f(wo, uc, u2, mode), b.sample_f(wo, uc, u2, mode));
        }
    }
}

#[test]
fn textured_roughness_and_thickness_follow_the_texture() {
    // Roughness 0 (specular) in one checker square, 0.5 in the other.
    let rough = FloatTexture::Checkerboard {
        checker: Arc::new(Checker::TwoD(TextureMapping::default())),
        tex1: Arc::new(0.0.into()),
        tex2: Arc::new(0.5.into()),
    };
    let m = Material::Conductor {
        spec: ConductorSpec::named("Ag").unwrap().into(),
        roughness: Roughness {
            u: rough.clone(),
            v: rough,
            remap: false,
        },
    };
    assert!(!m.is_specular_only(), "the roughness varies");
    let flags = |u: f32| m.bsdf(&ctx_at(Point2::new(u, 0.5))).flags();
    // floor(0.5) + floor(0.5) = 0: tex1 (smooth); floor(1.5) = 1: tex2.
    assert!(flags(0.5).is_specular() && !flags(0.5).is_non_specular());
    assert!(!flags(1.5).is_specular() && flags(1.5).is_non_specular());
}

#[test]
fn mix_follows_a_textured_amount() {
    let a = Material::diffuse(RHO1);
    let b = Material::diffuse(RHO2);
    // amount 0 where the checker shows tex1, 0.25 where it shows tex2.
    let amount = FloatTexture::Checkerboard {
        checker: Arc::new(Checker::TwoD(TextureMapping::default())),
        tex1: Arc::new(0.0.into()),
        tex2: Arc::new(0.25.into()),
    };
    let mix = Material::Mix(Arc::new(MixMaterial {
        materials: [a, b],
        amount,
    }));
    let mut rng = common::Rng::new(3);
    let (mut seconds, n) = (0usize, 4000);
    for _ in 0..n {
        let mut ctx = ctx_at(Point2::new(0.5, 0.5));
        ctx.p = rng.vec(-1.0, 1.0);
        let f = mix.bsdf(&ctx).f(Vec3::Z, Vec3::Z, TransportMode::Radiance) * PI;
        assert!(close(f, RHO1, 1e-6));
        ctx.uv = Point2::new(1.5, 0.5);
        let f = mix.bsdf(&ctx).f(Vec3::Z, Vec3::Z, TransportMode::Radiance) * PI;
        if close(f, RHO2, 1e-6) {
            seconds += 1;
        } else {
            assert!(close(f, RHO1, 1e-6));
        }
    }
    // Binomial(4000, 0.25): mean 1000, standard deviation 27.
    assert!((seconds as i64 - 1000).abs() < 140, "{seconds}");
}

fn load_text(tag: &str, text: &str) -> lowdisc_render::pbrt::LoadedScene {
    let dir = std::env::temp_dir().join(format!("lowdisc-textured-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("scene.pbrt");
    std::fs::write(&path, text).unwrap();
    let l = load_pbrt_scene(&path, &LoadOptions::default()).unwrap();
    std::fs::remove_dir_all(&dir).ok();
    l
}

#[test]
fn loader_builds_textured_and_constant_materials() {
    let scene = "LookAt 0 0 5 0 0 0 0 1 0\nCamera \"perspective\"\nWorldBegin\n\
        LightSource \"point\"\n\
        Texture \"checks\" \"spectrum\" \"checkerboard\" \"rgb tex1\" [0.8 0.2 0.5] \
            \"rgb tex2\" [0.1 0.6 0.3] \"float uscale\" 2 \"float vscale\" 2\n\
        Texture \"half\" \"spectrum\" \"scale\" \"rgb tex\" [0.4 0.4 0.4] \"float scale\" 0.5\n\
        Texture \"r\" \"float\" \"checkerboard\" \"float tex1\" 0.1 \"float tex2\" 0.3\n\
        Material \"diffuse\" \"texture reflectance\" \"checks\"\nShape \"sphere\"\n\
        Material \"diffuse\" \"texture reflectance\" \"half\"\nShape \"sphere\"\n\
        Material \"conductor\" \"texture roughness\" \"r\"\nShape \"sphere\"\n\
        MakeNamedMaterial \"a\" \"string type\" \"diffuse\"\n\
        MakeNamedMaterial \"b\" \"string type\" \"conductor\"\n\
        MakeNamedMaterial \"m\" \"string type\" \"mix\" \"string materials\" [\"a\" \"b\"] \
            \"float amount\" 0.3\n\
        NamedMaterial \"m\"\nShape \"sphere\"\n";
    let l = load_text("mats", scene);
    assert!(
        !l.warnings
            .iter()
            .any(|w| w.contains("texture") || w.contains("mix")),
        "{:?}",
        l.warnings
    );
    let mats = l.scene.materials();
    let uv = |u, v| lowdisc_render::texture::TextureEvalContext {
        p: Point3::ZERO,
        uv: Point2::new(u, v),
    };
    let refl = |m: &Material| match m {
        Material::Diffuse { reflectance } => reflectance.clone(),
        other => panic!("{other:?}"),
    };
    assert!(!mats[0].is_constant());
    assert_eq!(refl(&mats[0]).evaluate(&uv(0.25, 0.25)), RHO1);
    assert_eq!(refl(&mats[0]).evaluate(&uv(0.75, 0.25)), RHO2);
    // A scale of constants folds to a constant: the fast path.
    assert_eq!(refl(&mats[1]).as_constant(), Some(Rgb::splat(0.2)));
    assert!(!mats[2].is_constant());
    // a, b, then the mix (not counted as a material of its own).
    assert!(matches!(&mats[5], Material::Mix(m) if m.amount.as_constant() == Some(0.3)));
    assert_eq!(l.counts.materials, 5);
}

#[test]
fn shared_scenes_with_textures_get_textured_materials() {
    let Some(path) = shared_scenes::file("killeroos/killeroo-gold.pbrt") else {
        return;
    };
    let l = load_pbrt_scene(&path, &LoadOptions::default()).unwrap();
    assert!(
        l.scene.materials().iter().any(|m| !m.is_constant()),
        "the floor's reflectance is an image texture"
    );
    assert!(!l.warnings.iter().any(|w| w.contains("average")));
}

/// A 24-bit uncompressed TGA (top-left origin), one row of `pixels`.
fn tga_row(pixels: &[[u8; 3]]) -> Vec<u8> {
    let w = u16::try_from(pixels.len()).unwrap().to_le_bytes();
    let mut bytes = vec![
        0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, w[0], w[1], 1, 0, 24, 0x20,
    ];
    for [r, g, b] in pixels {
        bytes.extend([*b, *g, *r]);
    }
    bytes
}

/// The sRGB curve (IEC 61966-2-1), written out here independently of the
/// image crate's table.
fn srgb_curve(code: u8) -> f32 {
    let c = f64::from(code) / 255.0;
    let v = if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    };
    v as f32
}

/// pbrt-v4 reads 8-bit files other than PNG through stb_image and decodes
/// them as sRGB whatever the texture's `encoding` says: a TGA declared
/// `linear` and one declared `sRGB` hold the same texels, every code on the
/// sRGB curve, and the ignored declaration is a warning.
#[test]
fn eight_bit_tga_textures_are_srgb_whatever_encoding_says() {
    let pixels: Vec<[u8; 3]> = (0..=255u8).map(|k| [k, 255 - k, k / 2]).collect();
    let dir = std::env::temp_dir().join(format!("lowdisc-tga-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("ramp.tga"), tga_row(&pixels)).unwrap();
    let scene = "LookAt 0 0 5 0 0 0 0 1 0\nCamera \"perspective\"\nWorldBegin\n\
        LightSource \"point\"\n\
        Texture \"lin\" \"spectrum\" \"imagemap\" \"string filename\" \"ramp.tga\" \
            \"string encoding\" \"linear\"\n\
        Texture \"srgb\" \"spectrum\" \"imagemap\" \"string filename\" \"ramp.tga\" \
            \"string encoding\" \"sRGB\"\n\
        Texture \"default\" \"spectrum\" \"imagemap\" \"string filename\" \"ramp.tga\"\n\
        Material \"diffuse\" \"texture reflectance\" \"lin\"\nShape \"sphere\"\n\
        Material \"diffuse\" \"texture reflectance\" \"srgb\"\nShape \"sphere\"\n\
        Material \"diffuse\" \"texture reflectance\" \"default\"\nShape \"sphere\"\n";
    let path = dir.join("scene.pbrt");
    std::fs::write(&path, scene).unwrap();
    let l = load_pbrt_scene(&path, &LoadOptions::default()).unwrap();
    std::fs::remove_dir_all(&dir).ok();
    let ignored: Vec<_> = l
        .warnings
        .iter()
        .filter(|w| w.contains("\"encoding\" is ignored"))
        .collect();
    assert_eq!(ignored.len(), 1, "{:?}", l.warnings);
    assert!(ignored[0].contains("scene.pbrt:5:"), "{}", ignored[0]);
    let mats = l.scene.materials();
    for m in &mats[..3] {
        let Material::Diffuse { reflectance } = m else {
            panic!("{m:?}")
        };
        for (k, [r, g, b]) in pixels.iter().enumerate() {
            let ctx = lowdisc_render::texture::TextureEvalContext {
                p: Point3::ZERO,
                uv: Point2::new((k as f32 + 0.5) / 256.0, 0.5),
            };
            let got = reflectance.evaluate(&ctx);
            let want = Rgb::new(srgb_curve(*r), srgb_curve(*g), srgb_curve(*b));
            assert!(close(got, want, 1e-6), "code {k}: {got:?} vs {want:?}");
        }
    }
}
