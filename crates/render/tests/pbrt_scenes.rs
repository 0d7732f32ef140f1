//! Loading every pbrt-v4 scene in `../shared/scenes` (each skipped with a
//! printed message when the data is absent) with pinned counts; the
//! loader's handling of bad input and small synthetic scenes is in
//! `pbrt_loader.rs`.

use lowdisc_render::pbrt::{LoadOptions, LoadedScene, SceneCounts, load_pbrt_scene};
use lowdisc_render::render::{NoProgress, RenderOptions, render};
use lowdisc_render::settings::Settings;
use lowdisc_render::view::View;
use std::path::PathBuf;

fn load(rel: &str, envmap: Option<&str>) -> Option<LoadedScene> {
    load_with(rel, envmap, false)
}

/// A scene using a pbrt-v4 `feature` lowdisc lacks: an error naming it,
/// then loaded with `--approximate`.
fn load_approximate(rel: &str, envmap: Option<&str>, feature: &str) -> Option<LoadedScene> {
    let path = shared_scenes::dir().join(rel);
    let options = LoadOptions {
        envmap_override: envmap.map(|e| shared_scenes::dir().join(e)),
        ..LoadOptions::default()
    };
    if path.is_file() {
        let e = load_pbrt_scene(&path, &options).unwrap_err().to_string();
        assert!(e.contains(feature) && e.contains("--approximate"), "{e}");
    }
    load_with(rel, envmap, true)
}

fn load_with(rel: &str, envmap: Option<&str>, approximate: bool) -> Option<LoadedScene> {
    let path = shared_scenes::dir().join(rel);
    if !path.is_file() {
        shared_scenes::skip(&format!("{} is absent", path.display()));
        return None;
    }
    let options = LoadOptions {
        envmap_override: envmap.map(|e| shared_scenes::dir().join(e)),
        approximate,
    };
    let loaded = load_pbrt_scene(&path, &options).unwrap_or_else(|e| panic!("{rel}: {e}"));
    for w in &loaded.warnings {
        println!("{w}");
    }
    Some(loaded)
}

/// The settings the scene file asks for, resolved over the defaults.
fn settings(l: &LoadedScene) -> Settings {
    Settings::resolve(&[&l.settings.layer]).unwrap()
}

/// Triangles, spheres, disks, materials, non-area lights, emissive shapes;
/// then the scene's total light count and the film resolution.
fn check(l: &LoadedScene, c: [usize; 6], total_lights: usize, res: [u32; 2]) {
    let want = SceneCounts {
        triangles: c[0],
        spheres: c[1],
        disks: c[2],
        materials: c[3],
        lights: c[4],
        area_shapes: c[5],
        instances: 0,
    };
    assert_eq!(l.counts, want);
    assert_eq!(l.scene.lights().len(), total_lights);
    assert_eq!(View::native(&l.view).unwrap().camera().resolution(), res);
    assert_eq!(settings(l).resolution, res);
    assert_eq!(
        l.scene.prim_count(),
        c[0] + c[1] + c[2],
        "every shape reaches the scene"
    );
}

#[test]
fn cornell_box() {
    let Some(l) = load("bitterli-cornell-box/scene-v4.pbrt", None) else {
        return;
    };
    // The light is a two-triangle quad: one area light per triangle.
    check(&l, [36, 0, 0, 8, 0, 1], 2, [1024, 1024]);
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    let s = settings(&l).render;
    assert_eq!((s.sampler.spp, s.integrator.max_depth), (64, 65));
    assert_eq!(l.settings.output.as_deref(), Some("cornell-box.png"));
    // Transform [1 0 0 0  0 1 0 0  0 0 -1 0  0 -1 6.8 1] is camera-from-world:
    // the camera sits at (0, 1, 6.8).
    let p = View::native(&l.view).unwrap().camera().position();
    assert!(
        (p.x).abs() < 1e-5 && (p.y - 1.0).abs() < 1e-5 && (p.z - 6.8).abs() < 1e-4,
        "{p:?}"
    );
}

#[test]
fn veach_mis() {
    let Some(l) = load("bitterli-veach-mis/scene-v4.pbrt", None) else {
        return;
    };
    check(&l, [52, 3, 0, 6, 0, 3], 3, [1280, 720]);
    assert_eq!(settings(&l).render.integrator.max_depth, 3);
}

#[test]
fn material_testball_with_envmap_override() {
    let env = "envmaps/polyhaven-studio_small_03_1k.hdr";
    let Some(l) = load(
        "bitterli-material-testball/material-testball.pbrt",
        Some(env),
    ) else {
        return;
    };
    check(&l, [80770, 0, 0, 4, 1, 0], 1, [1280, 720]);
    assert!(l.warnings.iter().any(|w| w.contains("replaced by")));
}

#[test]
fn material_testball_without_envmap_names_the_missing_file() {
    let Some(path) = shared_scenes::file("bitterli-material-testball/material-testball.pbrt")
    else {
        return;
    };
    if path.with_file_name("textures/envmap.pfm").is_file() {
        println!("SKIPPED: the test ball's own envmap is present");
        return;
    }
    let e = load_pbrt_scene(&path, &LoadOptions::default())
        .unwrap_err()
        .to_string();
    assert!(e.contains("envmap.pfm") && e.contains("--envmap"), "{e}");
}

#[test]
fn classroom_without_its_blackboard_texture_names_the_missing_file() {
    let Some(path) = shared_scenes::file("bitterli-classroom/scene-v4.pbrt") else {
        return;
    };
    if path.with_file_name("textures/blackboard.tga").is_file() {
        println!("SKIPPED: the classroom's blackboard texture is present");
        return;
    }
    // As in pbrt-v4, a missing texture file is an error, located at its
    // `Texture` directive (the shared copy lacks textures/blackboard.tga).
    let e = load_pbrt_scene(&path, &LoadOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("scene-v4.pbrt:26:") && e.contains("blackboard.tga"),
        "{e}"
    );
}

#[test]
fn classroom() {
    let Some(path) = shared_scenes::file("bitterli-classroom/scene-v4.pbrt") else {
        return;
    };
    // A copy whose relative paths point into the scene's folder and whose
    // missing blackboard texture is replaced by the wood texture.
    let dir = path.parent().unwrap().display().to_string();
    let text = std::fs::read_to_string(&path)
        .unwrap()
        .replace("\"models/", &format!("\"{dir}/models/"))
        .replace("\"textures/", &format!("\"{dir}/textures/"))
        .replace("blackboard.tga", "wood1.tga");
    let copy = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("classroom.pbrt");
    std::fs::write(&copy, text).unwrap();
    let l = load_pbrt_scene(&copy, &LoadOptions::default()).unwrap();
    check(&l, [103832, 0, 0, 44, 2, 0], 2, [1280, 720]);
    assert_eq!(settings(&l).render.sampler.spp, 8);
}

#[test]
fn killeroos() {
    if let Some(l) = load("killeroos/killeroo-simple.pbrt", None) {
        check(&l, [66532, 1, 0, 4, 0, 1], 1, [700, 700]);
        assert_eq!(l.settings.sampler_type.as_deref(), Some("halton"));
    }
    for name in ["killeroo-gold", "killeroo-coated-gold"] {
        if let Some(l) = load(&format!("killeroos/{name}.pbrt"), None) {
            check(&l, [532230, 0, 1, 4, 1, 1], 2, [1368, 1026]);
        }
    }
}

#[test]
fn caustic_glass() {
    let bdpt = "Integrator \"bdpt\"";
    let Some(l) = load_approximate("caustic-glass/caustic-glass-v4.pbrt", None, bdpt) else {
        return;
    };
    check(&l, [88066, 0, 0, 2, 1, 0], 1, [700, 1000]);
    assert!(
        l.warnings
            .iter()
            .any(|w| w.contains(bdpt) && w.contains("path tracer"))
    );
}

#[test]
fn bmw_m6() {
    let env = "envmaps/pbrt-v4-ganesha-sky-equiarea.exr";
    let regularize = "Integrator \"regularize\"";
    let Some(l) = load_approximate("bmw-m6/bmw-m6.pbrt", Some(env), regularize) else {
        return;
    };
    check(&l, [792746, 0, 0, 27, 1, 0], 1, [1400, 1000]);
    assert!(l.warnings.iter().any(|w| w.contains(regularize)));
}

#[test]
fn cornell_box_renders_finite_at_16x16() {
    let Some(l) = load("bitterli-cornell-box/scene-v4.pbrt", None) else {
        return;
    };
    let view = View::new(&l.view, [16, 16]).unwrap();
    let mut opts = RenderOptions::default();
    opts.sampler.spp = 1;
    let out = render(&l.scene, &view, &opts, &NoProgress).unwrap();
    let m = out.mean();
    assert!(
        m.iter().all(|v| v.is_finite()) && m.iter().any(|&v| v > 0.0),
        "{m:?}"
    );
}
