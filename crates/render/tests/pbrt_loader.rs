//! The pbrt-v4 loader on small synthetic scenes: bad input (located errors,
//! missing files, wrong parameter counts and texture kinds) and the scene
//! state it tracks (instances, attribute blocks, includes, materials).

use lowdisc_render::pbrt::{LoadOptions, LoadedScene, load_pbrt_scene};
use std::path::{Path, PathBuf};

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("lowdisc-pbrt-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn load_text(name: &str, text: &str) -> Result<LoadedScene, String> {
    load_text_with(name, text, &LoadOptions::default())
}

/// [`load_text`] with `--approximate`: missing features become warnings.
fn load_approximate(name: &str, text: &str) -> Result<LoadedScene, String> {
    let options = LoadOptions {
        approximate: true,
        ..LoadOptions::default()
    };
    load_text_with(name, text, &options)
}

fn load_text_with(name: &str, text: &str, options: &LoadOptions) -> Result<LoadedScene, String> {
    let d = temp_dir(name);
    let p = d.join("scene.pbrt");
    std::fs::write(&p, text).unwrap();
    load_pbrt_scene(&p, options).map_err(|e| e.to_string())
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
fn unknown_material_is_an_error_and_unused_parameters_warn_with_location() {
    let scene = format!(
        "{CAMERA}Material \"velvet\"\nShape \"sphere\" \"float radius\" 1 \"float bogus\" 2\nLightSource \"point\"\n"
    );
    let e = load_text("unknown", &scene).unwrap_err();
    assert!(
        e.contains("scene.pbrt:5:1: material \"velvet\" is not supported")
            && e.contains("--approximate"),
        "{e}"
    );
    let l = load_approximate("warn", &scene).unwrap();
    assert!(
        l.warnings.iter().any(|w| w.contains(":5:")
            && w.contains("material \"velvet\" is not supported; a diffuse material is used")),
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
    let e = load_text("mats", &scene).unwrap_err();
    assert!(e.contains("scene.pbrt:11:1: material \"measured\""), "{e}");
    let l = load_approximate("mats", &scene).unwrap();
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
    for what in [
        "material \"measured\" (\"x.bsdf\") is not supported",
        "interface",
    ] {
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

#[test]
fn a_texture_of_the_wrong_kind_is_an_error_at_the_parameter() {
    // pbrt-v4 looks spectrum parameters up among spectrum textures only
    // ("Couldn't find spectrum texture named ..."), and floats among floats.
    let float_tex = "Texture \"t\" \"float\" \"constant\" \"float value\" 0.5\n";
    let e = load_text(
        "float-as-rgb",
        &format!("{CAMERA}{float_tex}Material \"diffuse\"\n  \"texture reflectance\" \"t\"\n"),
    )
    .unwrap_err();
    assert!(
        e.ends_with(
            "scene.pbrt:7:3: parameter \"reflectance\": texture \"t\" is a float texture; \
             a spectrum texture is needed"
        ),
        "{e}"
    );
    let rgb_tex = "Texture \"c\" \"spectrum\" \"constant\" \"rgb value\" [0.5 0.5 0.5]\n";
    let e = load_text(
        "rgb-as-float",
        &format!("{CAMERA}{rgb_tex}Material \"conductor\" \"texture roughness\" \"c\"\n"),
    )
    .unwrap_err();
    assert!(
        e.contains("parameter \"roughness\": texture \"c\" is a spectrum texture"),
        "{e}"
    );
    let e = load_text(
        "undefined-tex",
        &format!("{CAMERA}Material \"diffuse\" \"texture reflectance\" \"nowhere\"\n"),
    )
    .unwrap_err();
    assert!(e.contains("texture \"nowhere\" is not defined"), "{e}");
}

#[test]
fn a_missing_texture_file_is_an_error_naming_it() {
    let e = load_text(
        "missing-texture",
        &format!(
            "{CAMERA}Texture \"t\" \"spectrum\" \"imagemap\" \"string filename\" \"gone.png\"\n"
        ),
    )
    .unwrap_err();
    assert!(
        e.contains("scene.pbrt:5:1: imagemap: ") && e.contains("gone.png"),
        "{e}"
    );
}

#[test]
fn single_value_parameters_with_no_or_several_values_are_errors() {
    for (list, n) in [("[ ]", 0), ("[ 1 2 ]", 2)] {
        let scene = format!("{CAMERA}Shape \"sphere\" \"float radius\" {list}\n");
        let e = load_text("radius-count", &scene).unwrap_err();
        assert!(
            e.ends_with(&format!(
                "scene.pbrt:5:16: Shape \"sphere\": parameter \"float radius\" takes one value, got {n}"
            )),
            "{e}"
        );
    }
}

#[test]
fn transforms_that_overflow_f32_are_errors_at_the_directive() {
    for (directive, line, what) in [
        ("Translate 1e39 0 0", 5, "Translate needs finite offsets"),
        ("Scale 1e39 1 1", 5, "Scale needs finite, non-zero factors"),
        ("Scale 0 1 1", 5, "Scale needs finite, non-zero factors"),
        (
            "Scale 1e30 1e30 1e30\nScale 1e30 1e30 1e30",
            6,
            "the current transform overflows",
        ),
    ] {
        let scene = format!("{CAMERA}{directive}\nShape \"sphere\"\n");
        let e = load_text("transform-overflow", &scene).unwrap_err();
        assert!(
            e.contains(&format!("scene.pbrt:{line}:1: ")) && e.contains(what),
            "{directive}: {e}"
        );
    }
    // Large but finite transforms stay accepted.
    let scene = format!("{CAMERA}Scale 1e18 1e18 1e18\nShape \"sphere\" \"float radius\" 1e-18\n");
    load_text("transform-large", &scene).unwrap();
}

#[test]
fn an_emissive_mesh_with_a_degenerate_triangle_loads_and_that_triangle_emits_nothing() {
    // Triangle 1 repeats a vertex: no area. pbrt-v4 renders such meshes.
    let scene = format!(
        "{CAMERA}AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [ 2 2 2 ]\n\
         Shape \"trianglemesh\" \"integer indices\" [ 0 1 2 0 0 1 ] \
         \"point3 P\" [ 0 0 0 1 0 0 0 1 0 ]\nAttributeEnd\n"
    );
    let loaded = load_text("degenerate-emitter", &scene).unwrap();
    let powers: Vec<f32> = loaded
        .scene
        .lights()
        .iter()
        .map(|l| l.phi().average())
        .collect();
    assert_eq!(powers.len(), 2, "{powers:?}");
    // The unit right triangle: area 1/2, power L * pi * area.
    let expected = 2.0 * std::f32::consts::PI * 0.5;
    assert!((powers[0] - expected).abs() < 1e-5 * expected, "{powers:?}");
    assert_eq!(powers[1], 0.0);
}

/// Directives and parameters whose effect lowdisc lacks: errors at their
/// location naming them, warnings with `--approximate`; their harmless
/// forms load without a word.
#[test]
fn missing_features_are_errors_and_their_harmless_forms_are_not() {
    let light = "LightSource \"point\"\n";
    // (text after the camera, the error's place and feature)
    let missing = [
        (
            "AreaLightSource \"diffuse\"\nShape \"sphere\" \"float alpha\" 0.5\n",
            ":6:16:",
            "alpha cut-out on an area light",
        ),
        ("Shape \"cylinder\"\n", ":5:1:", "Shape \"cylinder\""),
        (
            "ActiveTransform EndTime\nTranslate 1 0 0\n",
            ":5:1:",
            "motion blur",
        ),
        (
            "Attribute \"shape\" \"float radius\" 2\n",
            ":5:1:",
            "Attribute \"shape\"",
        ),
        (
            "LightSource \"goniometric\"\n",
            ":5:1:",
            "LightSource \"goniometric\"",
        ),
        (
            "Texture \"t\" \"float\" \"fbm\"\n",
            ":5:1:",
            "texture class \"fbm\"",
        ),
    ];
    for (text, place, feature) in missing {
        let scene = format!("{CAMERA}{text}{light}");
        let e = load_text("missing", &scene).unwrap_err();
        assert!(e.contains(place) && e.contains(feature), "{text}: {e}");
        let l = load_approximate("missing", &scene).unwrap();
        assert!(
            l.warnings.iter().any(|w| w.contains(place)
                && w.contains(feature)
                && w.ends_with("(--approximate)")),
            "{text}: {:?}",
            l.warnings
        );
    }
    let harmless = "Shape \"sphere\" \"float alpha\" 1\nActiveTransform All\nTranslate 1 0 0\n";
    let l = load_text("harmless", &format!("{CAMERA}{harmless}{light}")).unwrap();
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    // Before WorldBegin: a colour space and an option that change the image.
    for (before, feature) in [
        ("ColorSpace \"aces2065-1\"\n", "ColorSpace \"aces2065-1\""),
        (
            "Option \"bool forcediffuse\" true\n",
            "Option \"forcediffuse\"",
        ),
    ] {
        let e = load_text("before", &format!("{before}{CAMERA}{light}")).unwrap_err();
        assert!(e.contains("scene.pbrt:1:1:") && e.contains(feature), "{e}");
    }
    let off = load_text(
        "off",
        &format!("Option \"bool forcediffuse\" false\n{CAMERA}{light}"),
    )
    .unwrap();
    assert!(
        off.warnings
            .iter()
            .any(|w| w.contains("Option \"forcediffuse\" is not supported; ignored")),
        "{:?}",
        off.warnings
    );
}
