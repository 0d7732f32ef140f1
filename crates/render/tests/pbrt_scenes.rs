//! Loading every pbrt-v4 scene in `../shared/scenes` (each skipped with a
//! printed message when the data is absent) with pinned counts, and the
//! loader's handling of bad input.

use lowdisc_render::pbrt::{LoadOptions, LoadedScene, SceneCounts, load_pbrt_scene};
use lowdisc_render::render::{NoProgress, RenderOptions, render};
use std::path::{Path, PathBuf};

fn load(rel: &str, envmap: Option<&str>) -> Option<LoadedScene> {
    let path = shared_scenes::dir().join(rel);
    if !path.is_file() {
        shared_scenes::skip(&format!("{} is absent", path.display()));
        return None;
    }
    let options = LoadOptions {
        envmap_override: envmap.map(|e| shared_scenes::dir().join(e)),
    };
    let loaded = load_pbrt_scene(&path, &options).unwrap_or_else(|e| panic!("{rel}: {e}"));
    for w in &loaded.warnings {
        println!("{w}");
    }
    Some(loaded)
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
    assert_eq!(l.scene.camera().resolution(), res);
    assert_eq!(l.settings.resolution, res);
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
    assert_eq!((l.settings.spp, l.settings.max_depth), (Some(64), Some(65)));
    assert_eq!(l.settings.output.as_deref(), Some("cornell-box.png"));
    // Transform [1 0 0 0  0 1 0 0  0 0 -1 0  0 -1 6.8 1] is camera-from-world:
    // the camera sits at (0, 1, 6.8).
    let p = l.scene.camera().position();
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
    assert_eq!(l.settings.max_depth, Some(3));
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
fn classroom() {
    let Some(l) = load("bitterli-classroom/scene-v4.pbrt", None) else {
        return;
    };
    check(&l, [103832, 0, 0, 44, 2, 0], 2, [1280, 720]);
    assert_eq!(l.settings.spp, Some(8));
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
    let Some(l) = load("caustic-glass/caustic-glass-v4.pbrt", None) else {
        return;
    };
    check(&l, [88066, 0, 0, 2, 1, 0], 1, [700, 1000]);
    assert!(l.warnings.iter().any(|w| w.contains("\"bdpt\"")));
}

#[test]
fn bmw_m6() {
    let env = "envmaps/pbrt-v4-ganesha-sky-equiarea.exr";
    let Some(l) = load("bmw-m6/bmw-m6.pbrt", Some(env)) else {
        return;
    };
    check(&l, [792746, 0, 0, 27, 1, 0], 1, [1400, 1000]);
    assert!(l.warnings.iter().any(|w| w.contains("volpath")));
}

#[test]
fn cornell_box_renders_finite_at_16x16() {
    let Some(mut l) = load("bitterli-cornell-box/scene-v4.pbrt", None) else {
        return;
    };
    l.scene.set_resolution([16, 16]).unwrap();
    let mut opts = RenderOptions::default();
    opts.sampler.spp = 1;
    let out = render(&l.scene, &opts, &NoProgress).unwrap();
    let m = out.mean();
    assert!(
        m.iter().all(|v| v.is_finite()) && m.iter().any(|&v| v > 0.0),
        "{m:?}"
    );
}

// ---- bad input and small synthetic scenes ------------------------------------

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("lowdisc-pbrt-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn load_text(name: &str, text: &str) -> Result<LoadedScene, String> {
    let d = temp_dir(name);
    let p = d.join("scene.pbrt");
    std::fs::write(&p, text).unwrap();
    load_pbrt_scene(&p, &LoadOptions::default()).map_err(|e| e.to_string())
}

const CAMERA: &str = "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\"\nFilm \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\nWorldBegin\n";

#[test]
fn missing_scene_file_is_an_error_naming_it() {
    let e = load_pbrt_scene(
        Path::new("/nonexistent/nothing.pbrt"),
        &LoadOptions::default(),
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("nothing.pbrt"), "{e}");
}

#[test]
fn syntax_error_names_file_line_and_column() {
    let e = load_text("syntax", "WorldBegin\nTranslate 1 2 \"x\"\n").unwrap_err();
    assert!(e.contains("scene.pbrt:2:"), "{e}");
}

#[test]
fn missing_and_truncated_ply_are_errors_naming_the_ply() {
    let scene = format!("{CAMERA}Shape \"plymesh\" \"string filename\" \"gone.ply\"\n");
    let e = load_text("noply", &scene).unwrap_err();
    assert!(e.contains("gone.ply") && e.contains("scene.pbrt:5:"), "{e}");
    let d = temp_dir("truncply");
    let header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    let mut bytes = header.as_bytes().to_vec();
    bytes.extend_from_slice(&[0u8; 10]);
    std::fs::write(d.join("cut.ply"), bytes).unwrap();
    let p = d.join("scene.pbrt");
    std::fs::write(
        &p,
        format!("{CAMERA}Shape \"plymesh\" \"string filename\" \"cut.ply\"\n"),
    )
    .unwrap();
    let e = load_pbrt_scene(&p, &LoadOptions::default())
        .unwrap_err()
        .to_string();
    assert!(e.contains("cut.ply"), "{e}");
}

#[test]
fn bad_radius_is_an_error() {
    for r in ["-1", "0"] {
        let scene = format!("{CAMERA}Shape \"sphere\" \"float radius\" {r}\n");
        let e = load_text("radius", &scene).unwrap_err();
        assert!(e.contains("radius") && e.contains(":5:"), "{e}");
    }
}

#[test]
fn unknown_material_and_parameter_warn_with_location() {
    let scene = format!(
        "{CAMERA}Material \"velvet\"\nShape \"sphere\" \"float radius\" 1 \"float bogus\" 2\nLightSource \"point\"\n"
    );
    let l = load_text("warn", &scene).unwrap();
    assert!(
        l.warnings
            .iter()
            .any(|w| w.contains(":5:") && w.contains("unknown material type \"velvet\"")),
        "{:?}",
        l.warnings
    );
    assert!(
        l.warnings
            .iter()
            .any(|w| w.contains(":6:") && w.contains("bogus")),
        "{:?}",
        l.warnings
    );
    assert_eq!(l.counts.spheres, 1);
}

#[test]
fn scene_without_lights_warns() {
    let l = load_text("dark", &format!("{CAMERA}Shape \"sphere\"\n")).unwrap();
    assert!(l.warnings.iter().any(|w| w.contains("no lights")));
}

#[test]
fn undefined_named_material_is_an_error() {
    let e = load_text("named", &format!("{CAMERA}NamedMaterial \"nope\"\n")).unwrap_err();
    assert!(e.contains("\"nope\"") && e.contains(":5:"), "{e}");
}

#[test]
fn object_instances_are_flattened_into_world_space() {
    let scene = format!(
        "{CAMERA}ObjectBegin \"tri\"\nShape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2]\nObjectEnd\nAttributeBegin\nTranslate 10 0 0\nObjectInstance \"tri\"\nAttributeEnd\nObjectInstance \"tri\"\nLightSource \"point\"\n"
    );
    let l = load_text("inst", &scene).unwrap();
    assert_eq!((l.counts.triangles, l.counts.instances), (2, 2));
    let b = l.scene.bounds();
    assert!(
        (b.max.x - 11.0).abs() < 1e-5 && b.min.x.abs() < 1e-5,
        "{b:?}"
    );
}

#[test]
fn attribute_blocks_scope_material_and_area_light() {
    let scene = format!(
        "{CAMERA}AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\nShape \"sphere\"\nAttributeEnd\nShape \"sphere\"\n"
    );
    let l = load_text("scope", &scene).unwrap();
    assert_eq!((l.counts.spheres, l.counts.area_shapes), (2, 1));
    assert_eq!(l.scene.lights().len(), 1);
}

#[test]
fn plymesh_in_included_file_resolves_against_main_directory() {
    let d = temp_dir("include");
    std::fs::create_dir_all(d.join("sub")).unwrap();
    let ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    std::fs::write(d.join("tri.ply"), ply).unwrap();
    std::fs::write(
        d.join("sub/geo.pbrt"),
        "Shape \"plymesh\" \"string filename\" \"tri.ply\"\n",
    )
    .unwrap();
    let p = d.join("scene.pbrt");
    std::fs::write(
        &p,
        format!("{CAMERA}Include \"sub/geo.pbrt\"\nLightSource \"point\"\n"),
    )
    .unwrap();
    let l = load_pbrt_scene(&p, &LoadOptions::default()).unwrap();
    assert_eq!(l.counts.triangles, 1);
}

#[test]
fn nan_radius_is_an_error() {
    let e = load_text(
        "nan",
        &format!("{CAMERA}Shape \"sphere\" \"float radius\" nan\n"),
    )
    .unwrap_err();
    assert!(e.contains("scene.pbrt:5:"), "{e}");
}

#[test]
fn interface_mix_and_measured_materials() {
    let scene = format!(
        "{CAMERA}LightSource \"point\"\n\
         MakeNamedMaterial \"a\" \"string type\" \"diffuse\"\n\
         MakeNamedMaterial \"b\" \"string type\" \"dielectric\" \"spectrum eta\" \"glass-BK7\"\n\
         MakeNamedMaterial \"m\" \"string type\" \"mix\" \"string materials\" [\"a\" \"b\"] \"float amount\" 0.8\n\
         NamedMaterial \"m\"\nShape \"sphere\"\n\
         Material \"measured\" \"string filename\" \"x.bsdf\"\nShape \"sphere\"\n\
         Material \"interface\"\nShape \"sphere\"\n"
    );
    let l = load_text("mats", &scene).unwrap();
    // The interface sphere is skipped; the mix is not counted as a material.
    assert_eq!((l.counts.spheres, l.counts.materials), (2, 3));
    let mats = l.scene.materials();
    assert!(
        matches!(mats[1], lowdisc_render::bsdf::Material::Dielectric { eta, .. } if (eta - 1.5168).abs() < 1e-4),
        "{:?}",
        mats[1]
    );
    // The mix is kept as a material choosing per shading point (no warning).
    assert!(
        matches!(&mats[2], lowdisc_render::bsdf::Material::Mix(m) if m.amount.as_constant() == Some(0.8)),
        "{:?}",
        mats[2]
    );
    for what in ["measured material", "interface"] {
        assert!(
            l.warnings.iter().any(|w| w.contains(what)),
            "{what}: {:?}",
            l.warnings
        );
    }
}

#[test]
fn camera_coordinate_system_is_world_from_camera() {
    let scene = format!(
        "{CAMERA}LightSource \"point\"\nAttributeBegin\nCoordSysTransform \"camera\"\nShape \"sphere\" \"float radius\" 0.5\nAttributeEnd\n"
    );
    let l = load_text("camsys", &scene).unwrap();
    let b = l.scene.bounds();
    let c = [
        (b.min.x + b.max.x) / 2.0,
        (b.min.y + b.max.y) / 2.0,
        (b.min.z + b.max.z) / 2.0,
    ];
    assert!(
        c[0].abs() < 1e-4 && c[1].abs() < 1e-4 && (c[2] + 5.0).abs() < 1e-4,
        "{c:?}"
    );
}
