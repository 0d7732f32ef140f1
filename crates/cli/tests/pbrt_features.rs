//! pbrt-v4 features lowdisc lacks and that change the image: without
//! `--approximate` the real binary refuses the scene with one `error:` line
//! naming the feature and its `file:line:column`; with it, the scene renders
//! and a warning says what was rendered instead.

mod common;

use common::{lowdisc, temp_dir};
use std::path::Path;

/// A scene with a point light and a sphere; `before_world` goes before
/// `WorldBegin`, `world` after it (the light and sphere come first, on
/// lines 4 to 6 of the world block).
fn scene(dir: &Path, name: &str, before_world: &str, world: &str) -> String {
    let text = format!(
        "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 30\n{before_world}\
         WorldBegin\nLightSource \"point\" \"rgb I\" [10 10 10] \"point3 from\" [0 0 5]\n\
         {world}Shape \"sphere\"\n"
    );
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

fn render(scene: &str, out: &Path, approximate: bool) -> (bool, String) {
    let o = out.to_str().unwrap();
    let mut args = vec!["render", scene, "--res", "8x6", "--spp", "1", "-o", o];
    if approximate {
        args.push("--approximate");
    }
    let r = lowdisc(&args);
    (
        r.status.success(),
        String::from_utf8_lossy(&r.stderr).into_owned(),
    )
}

/// Each case: file name, text before and after `WorldBegin`, where the
/// error must point (`file:line:column`) and the feature it must name.
const CASES: &[(&str, &str, &str, &str, &str)] = &[
    (
        "medium.pbrt",
        "",
        "MakeNamedMedium \"fog\" \"string type\" \"uniformgrid\"\n\
         MediumInterface \"fog\" \"\"\n",
        "medium.pbrt:5:1:",
        "medium type \"uniformgrid\"",
    ),
    (
        "curve.pbrt",
        "",
        "Shape \"curve\" \"point3 P\" [0 0 0  0 1 0  1 1 0  1 0 0] \"float width\" 0.1\n",
        "curve.pbrt:5:1:",
        "Shape \"curve\"",
    ),
    (
        "hair.pbrt",
        "",
        "Material \"hair\"\n",
        "hair.pbrt:5:1:",
        "material \"hair\"",
    ),
    (
        "bdpt.pbrt",
        "Integrator \"bdpt\"\n",
        "",
        "bdpt.pbrt:3:1:",
        "Integrator \"bdpt\"",
    ),
];

#[test]
fn missing_features_are_errors_naming_the_place_unless_approximate() {
    let dir = temp_dir("features");
    for &(name, before, world, place, feature) in CASES {
        let file = scene(&dir, name, before, world);
        let out = dir.join(format!("{name}.exr"));
        let (ok, stderr) = render(&file, &out, false);
        assert!(!ok, "{name} rendered: {stderr}");
        assert!(!out.exists(), "{name}: no image after an error");
        let lines: Vec<&str> = stderr.trim_end().lines().collect();
        assert_eq!(lines.len(), 1, "{name}: {stderr}");
        assert!(lines[0].starts_with("error: "), "{name}: {stderr}");
        assert!(
            lines[0].contains(place) && lines[0].contains(feature),
            "{name}: `{place}` and `{feature}` not in {stderr}"
        );
        assert!(lines[0].contains("--approximate"), "{name}: {stderr}");

        let (ok, stderr) = render(&file, &out, true);
        assert!(ok, "{name} with --approximate failed: {stderr}");
        assert!(out.is_file(), "{name}: no image with --approximate");
        let warning = stderr
            .lines()
            .find(|l| l.contains("warning:") && l.contains(feature))
            .unwrap_or_else(|| panic!("{name}: no warning naming `{feature}` in {stderr}"));
        assert!(
            warning.contains(place) && warning.contains("(--approximate)"),
            "{name}: {warning}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// pbrt-v4's `path` integrator ignores media, as lowdisc does: no error.
#[test]
fn media_under_the_path_integrator_are_a_warning() {
    let dir = temp_dir("features-path");
    let file = scene(
        &dir,
        "path.pbrt",
        "Integrator \"path\"\n",
        "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n\
         MediumInterface \"fog\" \"\"\n",
    );
    let out = dir.join("path.exr");
    let (ok, stderr) = render(&file, &out, false);
    assert!(ok, "{stderr}");
    assert!(
        stderr.contains("path.pbrt:7:1: warning: participating media are ignored"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// Features that do not change the pixels stay warnings.
#[test]
fn features_without_effect_on_the_pixels_are_warnings() {
    let dir = temp_dir("features-harmless");
    let file = scene(
        &dir,
        "harmless.pbrt",
        "Accelerator \"kdtree\"\nOption \"bool wavefront\" true\n",
        "",
    );
    let out = dir.join("harmless.exr");
    let (ok, stderr) = render(&file, &out, false);
    assert!(ok, "{stderr}");
    assert!(
        stderr.contains("harmless.pbrt:3:1: warning: Accelerator"),
        "{stderr}"
    );
    assert!(
        stderr.contains("harmless.pbrt:4:1: warning: Option"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// `lowdisc experiment` loads scene files the same way and takes
/// `--approximate` too.
#[test]
fn experiment_refuses_missing_features_unless_approximate() {
    let dir = temp_dir("features-experiment");
    let file = scene(&dir, "bdpt.pbrt", "Integrator \"bdpt\"\n", "");
    let run = |approximate: bool, out: &str| {
        let out = dir.join(out).display().to_string();
        let mut args = vec![
            "experiment",
            file.as_str(),
            "--samplers",
            "sobol",
            "--runs",
            "1",
            "--spp",
            "1",
            "--res",
            "8x6",
            "--ref-spp",
            "4",
            "--conv-max",
            "1",
            "--conv-res",
            "8x6",
            "--conv-ref-spp",
            "4",
            "--quiet",
            "--out",
        ];
        args.push(&out);
        if approximate {
            args.push("--approximate");
        }
        let r = lowdisc(&args);
        (
            r.status.success(),
            String::from_utf8_lossy(&r.stderr).into_owned(),
        )
    };
    let (ok, stderr) = run(false, "refused");
    assert!(!ok, "{stderr}");
    assert!(
        stderr.starts_with("error: ")
            && stderr.contains("bdpt.pbrt:3:1:")
            && stderr.contains("Integrator \"bdpt\""),
        "{stderr}"
    );
    let (ok, stderr) = run(true, "approximated");
    assert!(ok, "{stderr}");
    assert!(dir.join("approximated/results.json").is_file());
    std::fs::remove_dir_all(&dir).ok();
}
