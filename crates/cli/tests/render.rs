//! `lowdisc render` end to end: the built-in Cornell box and the shared
//! pbrt-v4 Cornell box file render to PNG and EXR (read back: size, and the
//! EXR's mean equals the library's render of the same options); bad input
//! (including bad scene files) exits non-zero with one `error:` line and no
//! panic.

mod common;

use common::{lowdisc, temp_dir};
use lowdisc::catalog::SamplerName;
use lowdisc_render::cornell::cornell_box;
use lowdisc_render::render::{NoProgress, RenderOptions, render};

/// `path` is a PNG of `size` whose mean is that of a lit box, neither black
/// nor white.
fn assert_lit_png(path: &std::path::Path, size: (usize, usize)) {
    let bytes = std::fs::read(path).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    let image = lowdisc_image::read_image(path).unwrap();
    assert_eq!((image.width(), image.height()), size);
    let m = mean(&image);
    assert!(m > 0.05 && m < 0.95, "{}: mean {m}", path.display());
}

/// Mean of every channel of every pixel.
fn mean(image: &lowdisc_image::RgbImage) -> f64 {
    let sum: f64 = image.pixels().iter().flatten().map(|&v| f64::from(v)).sum();
    sum / (3 * image.pixels().len()) as f64
}

#[test]
fn renders_the_cornell_box_to_png_and_exr() {
    let dir = temp_dir("render-ok");
    let png = dir.join("tmp.png");
    let out = lowdisc(&[
        "render",
        "--res",
        "32x32",
        "--spp",
        "4",
        "-o",
        png.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert_lit_png(&png, (32, 32));
    let exr = dir.join("tmp.exr");
    let out = lowdisc(&[
        "render",
        "--res",
        "16x8",
        "--spp",
        "2",
        "--threads",
        "1",
        "--stats",
        "--quiet",
        "-o",
        exr.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("rays traced") && stdout.contains("rays/s"),
        "{stdout}"
    );
    assert!(stdout.contains("BVH"), "{stdout}");
    let bytes = std::fs::read(&exr).unwrap();
    assert_eq!(&bytes[..4], &[0x76, 0x2f, 0x31, 0x01], "EXR magic");
    let image = lowdisc_image::read_image(&exr).unwrap();
    assert_eq!((image.width(), image.height()), (16, 8));
    // The command's defaults (zsobol, seed 0, maxdepth 5) in the library.
    let (scene, view) = cornell_box([16, 8]).unwrap();
    let expected = render(
        &scene,
        &view,
        &RenderOptions::new(SamplerName::ZSobol, 0, 2),
        &NoProgress,
    )
    .unwrap();
    let want = expected.mean().iter().sum::<f64>() / 3.0;
    assert!(want > 0.01, "{want}");
    assert!(
        (mean(&image) - want).abs() < 1e-3 * want,
        "{} vs {want}",
        mean(&image)
    );
    // No temporary files are left next to the output.
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names.len(), 2, "{names:?}");
}

#[test]
fn spectral_flag_renders_what_the_library_renders_spectrally() {
    let dir = temp_dir("render-spectral");
    let exr = dir.join("s.exr");
    let args = [
        "render",
        "--res",
        "16x8",
        "--spp",
        "4",
        "--quiet",
        "--spectral",
    ];
    let out = lowdisc(&[&args[..], &["-o", exr.to_str().unwrap()]].concat());
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let image = lowdisc_image::read_image(&exr).unwrap();
    let (scene, view) = cornell_box([16, 8]).unwrap();
    let opts = |spectral| RenderOptions {
        spectral,
        ..RenderOptions::new(SamplerName::ZSobol, 0, 4)
    };
    let spectral = render(&scene, &view, &opts(true), &NoProgress).unwrap();
    assert_eq!(image.pixels(), spectral.image.pixels());
    let rgb = render(&scene, &view, &opts(false), &NoProgress).unwrap();
    assert_ne!(image.pixels(), rgb.image.pixels());
}

/// A coated gold sphere (the coated killeroo's material) lit by a sphere
/// light: the layered BSDF's exit weight decides its brightness.
const COATED_SPHERE: &str = r#"LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" [ 30 ]
Film "rgb" "integer xresolution" [ 16 ] "integer yresolution" [ 16 ]
Sampler "zsobol" "integer pixelsamples" [ 16 ]
WorldBegin
LightSource "infinite" "rgb L" [ 0.5 0.5 0.5 ]
AttributeBegin
  Translate 2 2 4
  AreaLightSource "diffuse" "rgb L" [ 20 20 20 ]
  Shape "sphere" "float radius" [ 0.5 ]
AttributeEnd
Material "coatedconductor" "spectrum conductor.eta" "metal-Au-eta"
  "spectrum conductor.k" "metal-Au-k"
  "float interface.roughness" [ 0.02 ] "float conductor.roughness" [ 0.002 ]
Shape "sphere" "float radius" [ 1.2 ]
"#;

#[test]
fn layered_weight_flag_selects_pbrt_v4s_brighter_weight() {
    let dir = temp_dir("render-layered");
    let scene = dir.join("coated.pbrt");
    std::fs::write(&scene, COATED_SPHERE).unwrap();
    let render_mean = |weight: &str| {
        let exr = dir.join(format!("{weight}.exr"));
        let out = lowdisc(&[
            "render",
            scene.to_str().unwrap(),
            "--quiet",
            "--layered-weight",
            weight,
            "-o",
            exr.to_str().unwrap(),
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        mean(&lowdisc_image::read_image(&exr).unwrap())
    };
    let (unbiased, pbrt_v4) = (render_mean("unbiased"), render_mean("pbrt-v4"));
    // pbrt-v4's weights sum to more than 1 (tests/layered_exit_weight.rs in
    // the render crate measures by how much). Both renders draw the same
    // samples, so the difference is the weight's alone: 0.9 % here, where
    // BSDF sampling carries most of the near-specular coat's light.
    assert!(
        unbiased > 0.05,
        "unbiased mean {unbiased}, pbrt-v4 {pbrt_v4}"
    );
    assert!(
        pbrt_v4 > unbiased * 1.005,
        "pbrt-v4 {pbrt_v4}, unbiased {unbiased}"
    );
    fails(&["--layered-weight", "other"], "other");
}

/// Runs `lowdisc render ARGS`, expects a one-line error and no panic.
fn fails(args: &[&str], needle: &str) {
    let mut all = vec!["render"];
    all.extend_from_slice(args);
    let out = lowdisc(&all);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{all:?} should fail");
    assert!(!stderr.contains("panicked"), "{all:?} panicked: {stderr}");
    assert!(
        stderr.contains(needle),
        "{all:?}: `{needle}` not in {stderr}"
    );
}

#[test]
fn bad_input_is_a_clean_error() {
    let dir = temp_dir("render-bad");
    let o = dir.join("x.png");
    let o = o.to_str().unwrap();
    fails(&["--res", "0x0", "-o", o], "at least 1");
    fails(&["--res", "100000x100000", "-o", o], "too large");
    fails(&["--res", "axb", "-o", o], "--res");
    fails(&["--spp", "0", "-o", o], "--spp");
    fails(&["--spp", "NaN", "-o", o], "spp");
    fails(&["--sampler", "nope", "-o", o], "unknown sampler");
    fails(&["--threads", "0", "-o", o], "--threads");
    fails(&["--maxdepth", "99999999", "-o", o], "--maxdepth");
    fails(&["--threshold", "1.5", "-o", o], "--threshold");
    fails(&["--threshold", "NaN", "-o", o], "--threshold");
    fails(&["-o", dir.join("x.jpg").to_str().unwrap()], ".exr");
    fails(
        &["-o", dir.join("missing/x.png").to_str().unwrap()],
        "does not exist",
    );
    fails(&["scene.pbrt", "-o", o], "scene.pbrt");
    fails(&["--envmap", "sky.exr", "-o", o], "--envmap");
    assert!(
        std::fs::read_dir(&dir).unwrap().next().is_none(),
        "no output left behind"
    );
}

/// The shared scene directory, or `None` (with a printed message) when absent.
fn shared_scenes() -> Option<std::path::PathBuf> {
    shared_scenes::existing(shared_scenes::dir())
}

#[test]
fn renders_the_shared_cornell_box_scene_file() {
    let Some(scenes) = shared_scenes() else {
        return;
    };
    let scene = scenes.join("bitterli-cornell-box/scene-v4.pbrt");
    let dir = temp_dir("render-scene");
    let png = dir.join("cbox.png");
    let out = lowdisc(&[
        "render",
        scene.to_str().unwrap(),
        "--res",
        "32x32",
        "--spp",
        "1",
        "--stats",
        "-o",
        png.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    let stdout = String::from_utf8_lossy(&out.stdout);
    // 32x32 pixels at 1 spp: 1024 samples.
    assert!(stdout.contains("samples           1024"), "{stdout}");
    assert_lit_png(&png, (32, 32));
}

#[test]
fn bad_scene_files_are_clean_errors_naming_the_place() {
    let dir = temp_dir("render-bad-scene");
    let o = dir.join("x.png");
    let o = o.to_str().unwrap();
    let bad = dir.join("syntax.pbrt");
    std::fs::write(&bad, "WorldBegin\nShape \"sphere\" \"float radius\" [ 1\n").unwrap();
    fails(&[bad.to_str().unwrap(), "-o", o], "syntax.pbrt:2:");
    let ply = dir.join("ply.pbrt");
    std::fs::write(
        &ply,
        "WorldBegin\nShape \"plymesh\" \"string filename\" \"missing-mesh.ply\"\n",
    )
    .unwrap();
    fails(&[ply.to_str().unwrap(), "-o", o], "missing-mesh.ply");
    fails(&[ply.to_str().unwrap(), "-o", o], "ply.pbrt:2:");
    assert!(!dir.join("x.png").exists(), "no output left behind");
}
