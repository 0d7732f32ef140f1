//! Participating media in pbrt-v4 files: `MakeNamedMedium`,
//! `MediumInterface` on shapes and the camera, the `interface` material,
//! and one-line errors naming `file:line:column` for bad media.

use lowdisc_render::medium::{HomogeneousMedium, Medium};
use lowdisc_render::pbrt::{LoadOptions, LoadedScene, load_pbrt_scene};
use lowdisc_render::spectrum::Rgb;

fn load(name: &str, text: &str) -> Result<LoadedScene, String> {
    let d = std::env::temp_dir().join(format!("lowdisc-media-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    let p = d.join("scene.pbrt");
    std::fs::write(&p, text).unwrap();
    let r = load_pbrt_scene(&p, &LoadOptions::default()).map_err(|e| e.to_string());
    std::fs::remove_dir_all(&d).ok();
    r
}

const HEAD: &str = "LookAt 0 0 5  0 0 0  0 1 0\n";

#[test]
fn media_on_shapes_and_the_camera_are_loaded() {
    let text = format!(
        "{HEAD}MediumInterface \"\" \"fog\"\nCamera \"perspective\"\nWorldBegin\n\
         MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0.1 0.2 0.3]\n\
         \"rgb sigma_s\" [1 1 1] \"float scale\" 2 \"float g\" 0.5\n\
         MakeNamedMedium \"milk\" \"string type\" \"homogeneous\" \"string preset\" \"Wholemilk\"\n\
         LightSource \"point\" \"rgb I\" [1 1 1]\n\
         AttributeBegin\nMediumInterface \"milk\" \"fog\"\nMaterial \"interface\"\nShape \"sphere\"\nAttributeEnd\n\
         Shape \"disk\" \"float height\" -3\n"
    );
    let loaded = load("ok", &text).unwrap();
    let scene = &loaded.scene;
    assert!(scene.has_media());
    assert_eq!(scene.media().len(), 2);
    assert_eq!(scene.camera_medium(), Some(0));
    let Medium::Homogeneous(fog) = scene.media()[0];
    assert_eq!(
        fog,
        HomogeneousMedium {
            sigma_a: Rgb::new(0.1, 0.2, 0.3) * 2.0,
            sigma_s: Rgb::splat(2.0),
            le: Rgb::ZERO,
            g: 0.5
        }
    );
    // pbrt-v4's measured whole milk (Jensen et al. 2001), in mm⁻¹.
    let Medium::Homogeneous(milk) = scene.media()[1];
    assert_eq!(milk.sigma_s, Rgb::new(2.55, 3.21, 3.77));
    assert_eq!(milk.sigma_a, Rgb::new(0.0011, 0.0024, 0.014));
    // The interface sphere is kept (it separates milk from fog), as is the
    // disk: two primitives.
    assert_eq!(scene.prim_count(), 2);
}

#[test]
fn scenes_without_media_have_none() {
    let text = format!("{HEAD}Camera \"perspective\"\nWorldBegin\nShape \"sphere\"\n");
    assert!(!load("none", &text).unwrap().scene.has_media());
    // An interface shape without a medium transition is skipped.
    let text = format!(
        "{HEAD}Camera \"perspective\"\nWorldBegin\nMaterial \"interface\"\nShape \"sphere\"\n"
    );
    let loaded = load("skip", &text).unwrap();
    assert!(!loaded.scene.has_media());
    assert_eq!(loaded.scene.prim_count(), 0);
}

#[test]
fn bad_media_are_one_line_errors_naming_the_place() {
    let world = |s: &str| format!("{HEAD}Camera \"perspective\"\nWorldBegin\n{s}");
    let medium = |params: &str| {
        world(&format!(
            "MakeNamedMedium \"m\" \"string type\" \"homogeneous\"\n  {params}\n"
        ))
    };
    let cases = [
        (
            medium("\"float g\" 1"),
            "scene.pbrt:5:3:",
            "\"g\" must be between -1 and 1",
        ),
        (
            medium("\"rgb sigma_a\" [-1 0 0]"),
            "scene.pbrt:5:3:",
            "\"sigma_a\" must be finite and not negative",
        ),
        (medium("\"float scale\" -2"), "scene.pbrt:5:3:", "\"scale\""),
        (
            world("MakeNamedMedium \"m\" \"string type\" \"smoke\"\n"),
            "scene.pbrt:4:1:",
            "unknown medium type \"smoke\"",
        ),
        (
            world("MakeNamedMedium \"m\" \"string type\" \"nanovdb\"\n"),
            "scene.pbrt:4:1:",
            "medium type \"nanovdb\" is not supported",
        ),
        (
            world("MediumInterface \"nowhere\" \"\"\nShape \"sphere\"\n"),
            "scene.pbrt:4:1:",
            "medium \"nowhere\" is not defined",
        ),
    ];
    for (i, (text, place, what)) in cases.iter().enumerate() {
        let e = load(&format!("bad{i}"), text).unwrap_err();
        assert_eq!(e.lines().count(), 1, "{e}");
        assert!(e.contains(place) && e.contains(what), "case {i}: {e}");
    }
}
