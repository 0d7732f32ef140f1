//! The scene hash of split parts: pinned for a fixed scene, changed by every
//! kind of content change, blind to the folder a scene is read from and to
//! the resolution, and refused by the merge when taken by another version.

use lowdisc::catalog::SamplerName;
use lowdisc_render::cornell::{cornell_box, cornell_box_with_camera, cornell_camera_with_lens};
use lowdisc_render::pbrt::{LoadOptions, load_pbrt_scene};
use lowdisc_render::render::{NoProgress, RenderOptions, render};
use lowdisc_render::scene::Scene;
use lowdisc_render::view::View;
use lowdisc_split::{NamedPart, RenderPart, content_digest, merge, scene_hash};
use std::path::{Path, PathBuf};

/// A scene with a PLY mesh, an image texture, a point light, an emissive
/// sphere, a camera and a filter; `edit` replaces one piece of its text.
const SCENE: &str = r#"LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" [ 45 ]
Film "rgb" "integer xresolution" [ 8 ] "integer yresolution" [ 6 ]
PixelFilter "gaussian" "float xradius" [ 1.5 ] "float yradius" [ 1.5 ]
WorldBegin
LightSource "point" "point3 from" [ 0 4 0 ] "rgb I" [ 10 10 10 ]
Texture "tex" "spectrum" "imagemap" "string filename" "tex.pfm"
Material "coateddiffuse" "texture reflectance" "tex" "float roughness" [ 0.2 ]
Shape "plymesh" "string filename" "mesh.ply"
Material "diffuse" "rgb reflectance" [ 0.5 0.5 0.5 ]
Shape "trianglemesh" "point3 P" [ -1 -1 0  1 -1 0  0 1 0 ] "integer indices" [ 0 1 2 ]
AttributeBegin
  AreaLightSource "diffuse" "rgb L" [ 1 1 1 ]
  Translate 0 2 0
  Shape "sphere" "float radius" [ 0.5 ]
AttributeEnd
"#;

const PLY: &str = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n\
property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n\
end_header\n0 0 -1\n1 0 -1\n0 1 -1\n3 0 1 2\n";

/// A 2x2 little-endian PFM image.
fn texture() -> Vec<u8> {
    let mut bytes = b"PF\n2 2\n-1.0\n".to_vec();
    for v in [
        0.1f32, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 0.5, 0.25,
    ] {
        bytes.extend_from_slice(&v.to_le_bytes());
    }
    bytes
}

/// Writes the scene (with `SCENE`'s `from` replaced by `to`) into a fresh
/// folder named `name` and returns the scene file.
fn write_scene(name: &str, from: &str, to: &str) -> PathBuf {
    assert!(SCENE.contains(from), "{from}");
    let dir = std::env::temp_dir().join(format!("lowdisc-hash-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("tex.pfm"), texture()).unwrap();
    std::fs::write(dir.join("mesh.ply"), PLY).unwrap();
    let file = dir.join("scene.pbrt");
    std::fs::write(&file, SCENE.replace(from, to)).unwrap();
    file
}

fn load(file: &Path) -> (Scene, View) {
    let loaded = load_pbrt_scene(file, &LoadOptions::default()).unwrap();
    let view = View::native(&loaded.view).unwrap();
    (loaded.scene, view)
}

/// The hash of the scene with `from` replaced by `to`.
fn hash_of(name: &str, from: &str, to: &str) -> String {
    let file = write_scene(name, from, to);
    let (scene, view) = load(&file);
    let _ = std::fs::remove_dir_all(file.parent().unwrap());
    scene_hash(&scene, &view)
}

#[test]
fn the_hash_of_a_fixed_scene_is_pinned() {
    assert_eq!(
        hash_of("pinned", "", ""),
        "e127c9a72b26758afad3149e2f36000d859196fdb09f99863872a08595c34b2c"
    );
    let (scene, view) = cornell_box([24, 16]).unwrap();
    assert_eq!(
        scene_hash(&scene, &view),
        "dc39e46698ee51ac4bd0896a22c2bc536e1220a9ac8b9a4fa5467172ba8330f4"
    );
}

/// The scene's text before its `AttributeBegin` when the sphere holds a
/// homogeneous medium of absorption `sigma_a`.
fn with_fog(sigma_a: &str) -> String {
    format!(
        "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \
         \"rgb sigma_a\" [ {sigma_a} {sigma_a} {sigma_a} ]\n\
         AttributeBegin\n  MediumInterface \"fog\" \"\"\n"
    )
}

#[test]
fn every_kind_of_change_changes_the_hash() {
    let (fog, denser_fog) = (with_fog("0.1"), with_fog("0.2"));
    let changes = [
        ("material parameter", "[ 0.5 0.5 0.5 ]", "[ 0.5 0.6 0.5 ]"),
        ("textured material", "[ 0.2 ]", "[ 0.3 ]"),
        ("light power", "[ 10 10 10 ]", "[ 11 10 10 ]"),
        ("area light", "[ 1 1 1 ]", "[ 1 1 2 ]"),
        ("camera fov", "[ 45 ]", "[ 46 ]"),
        (
            "filter radius",
            "\"float xradius\" [ 1.5 ]",
            "\"float xradius\" [ 1 ]",
        ),
        ("mesh vertex", "0 1 0 ]", "0 1.001 0 ]"),
        ("sphere", "Translate 0 2 0", "Translate 0 2.5 0"),
        ("medium", "AttributeBegin\n", &fog),
        ("medium density", "AttributeBegin\n", &denser_fog),
    ];
    let base = hash_of("base", "", "");
    let mut seen = vec![base.clone()];
    for (what, from, to) in changes {
        let h = hash_of(what, from, to);
        assert!(!seen.contains(&h), "{what}: the hash did not change");
        seen.push(h);
    }
    // The texture's texels and the PLY file's vertices are content too.
    let file = write_scene("texels", "", "");
    let mut texels = texture();
    texels[12] ^= 1;
    std::fs::write(file.with_file_name("tex.pfm"), texels).unwrap();
    let texel = scene_hash(&load(&file).0, &load(&file).1);
    std::fs::write(
        file.with_file_name("mesh.ply"),
        PLY.replace("0 1 -1", "0 2 -1"),
    )
    .unwrap();
    let ply = scene_hash(&load(&file).0, &load(&file).1);
    let _ = std::fs::remove_dir_all(file.parent().unwrap());
    assert!(texel != base && ply != base && ply != texel);
}

#[test]
fn the_same_scene_in_two_folders_hashes_equal_and_the_resolution_is_not_content() {
    let (a, b) = (write_scene("here", "", ""), write_scene("there", "", ""));
    let (scene_a, view_a) = load(&a);
    let (scene_b, view_b) = load(&b);
    for f in [&a, &b] {
        let _ = std::fs::remove_dir_all(f.parent().unwrap());
    }
    let h = scene_hash(&scene_a, &view_a);
    assert_eq!(h, scene_hash(&scene_b, &view_b));
    assert_eq!(h.len(), 64);
    // The resolution is recorded by the part, not hashed.
    let wider = View::new(&view_a.spec().clone(), [16, 6]).unwrap();
    assert_eq!(h, scene_hash(&scene_a, &wider));
    // Another camera is another view of the scene, and another hash.
    let (scene, view) = cornell_box([24, 16]).unwrap();
    let lens = cornell_camera_with_lens(40.0, 1000.0).unwrap();
    let (with_lens, lens_view) = cornell_box_with_camera([24, 16], lens).unwrap();
    assert_ne!(
        scene_hash(&scene, &view),
        scene_hash(&with_lens, &lens_view)
    );
}

#[test]
fn merge_refuses_parts_hashed_by_another_version() {
    let (scene, view) = cornell_box([8, 4]).unwrap();
    let o = RenderOptions {
        threads: Some(1),
        ..RenderOptions::new(SamplerName::ZSobol, 0, 1)
    };
    let out = render(&scene, &view, &o, &NoProgress).unwrap();
    let part = RenderPart::new(&scene, &view, &o, &out);
    let mut old = part.clone();
    old.info.scene = content_digest("lowdisc scene hash 2", &(&scene, view.spec()));
    assert_ne!(old.info.scene, part.info.scene);
    let named = |name: &str, part: &RenderPart| NamedPart {
        name: name.into(),
        part: part.clone(),
    };
    let e = merge(&[named("new", &part), named("old", &old)]).unwrap_err();
    assert!(e.to_string().starts_with("old: scene hash "), "{e}");
    assert!(merge(&[named("new", &part)]).is_ok());
}
