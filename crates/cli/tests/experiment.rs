//! End-to-end tests of `lowdisc experiment` on tiny settings: the report
//! folder is complete, `results.json` has the documented schema, and the
//! reference cache is reused by a second run.

mod common;

use std::path::Path;

use common::{lowdisc, temp_dir};

fn run_quick(out: &Path) -> String {
    let o = lowdisc(&[
        "experiment",
        "--quick",
        "--res",
        "32x24",
        "--samplers",
        "sobol,paper-repro,independent",
        "--out",
        out.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(o.status.success(), "experiment failed: {stderr}");
    stderr
}

#[test]
fn tiny_experiment_writes_a_complete_report_and_reuses_the_reference() {
    let dir = temp_dir("experiment");
    let out = dir.join("out");
    let log1 = run_quick(&out);
    assert!(log1.contains("rendering reference"), "{log1}");
    for f in [
        "report.md",
        "report.html",
        "results.json",
        "reference.exr",
        "reference.png",
        "reference_crop.png",
        "convergence.png",
        "threshold_sweep.png",
        "figure.png",
    ] {
        assert!(out.join(f).is_file(), "missing {f}");
    }
    for s in ["sobol", "paper-repro", "independent"] {
        for suffix in ["", "_crop", "_relse"] {
            let f = out.join(format!("{s}{suffix}.png"));
            assert!(f.is_file(), "missing {}", f.display());
        }
    }
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(md.contains("| paper-repro"), "{md}");
    // The report answers the paper's question first.
    assert!(
        md.starts_with("# Does the paper's permuted Sobol beat Sobol?\n\n## Answer\n\n"),
        "{md}"
    );
    assert!(!md.contains("busy machine"), "{md}");
    // The linear EXR of seed 0 against the reference EXR gives the relMSE
    // that results.json reports for that run.
    let reference = lowdisc_image::read_image(out.join("reference.exr")).unwrap();
    let seed0 = lowdisc_image::read_image(out.join("independent.exr")).unwrap();
    let relmse = lowdisc_image::error_metrics(&seed0, &reference)
        .unwrap()
        .linear
        .relmse;
    assert!(md.contains("relMSE / sobol"), "{md}");
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(html.contains("<img src=\"convergence.png\""), "{html}");
    assert!(html.contains("<table>"));

    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    assert_eq!(json["settings"]["width"], 32);
    assert_eq!(json["settings"]["height"], 24);
    assert_eq!(json["settings"]["spp"], 4);
    assert!(json["command"].as_array().unwrap().len() > 2);
    assert!(json["version"].is_string());
    assert!(json["machine"]["cores"].as_u64().unwrap() >= 1);
    let samplers = json["samplers"].as_array().unwrap();
    assert_eq!(samplers.len(), 3);
    for s in samplers {
        for key in ["time_s", "mse", "relmse", "rmse", "mae"] {
            assert!(
                s[key]["mean"].as_f64().unwrap() >= 0.0,
                "{key} of {}",
                s["name"]
            );
            assert!(
                s[key]["sd"].as_f64().unwrap() >= 0.0,
                "{key} of {}",
                s["name"]
            );
        }
        assert_eq!(s["runs"].as_array().unwrap().len(), 2);
        // The mean in the summary is the mean of the runs.
        let runs: Vec<f64> = s["runs"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| r["linear"]["relmse"].as_f64().unwrap())
            .collect();
        let mean = (runs[0] + runs[1]) / 2.0;
        assert!((s["relmse"]["mean"].as_f64().unwrap() - mean).abs() <= 1e-12 * mean.abs());
        // RMSE is the square root of MSE in every run.
        for r in s["runs"].as_array().unwrap() {
            let mse = r["linear"]["mse"].as_f64().unwrap();
            let rmse = r["linear"]["rmse"].as_f64().unwrap();
            assert!((rmse - mse.sqrt()).abs() <= 1e-9 * rmse.max(1e-300));
        }
        assert_eq!(s["convergence"].as_array().unwrap().len(), 4); // 1, 2, 4, 8 spp
        // --quick's 2 seeds: each point is their mean, with an interval
        // around it, and the slope is the mean of the seeds' fits.
        for c in s["convergence"].as_array().unwrap() {
            let seeds: Vec<f64> = c["relmse_seeds"]
                .as_array()
                .unwrap()
                .iter()
                .map(|v| v.as_f64().unwrap())
                .collect();
            assert_eq!(seeds.len(), 2);
            let mean = c["relmse"].as_f64().unwrap();
            assert!((mean - (seeds[0] + seeds[1]) / 2.0).abs() <= 1e-12 * mean);
            let ci = &c["relmse_ci95"];
            assert!(ci[0].as_f64().unwrap() <= mean && mean <= ci[1].as_f64().unwrap());
        }
        let slopes = s["convergence_slopes"].as_array().unwrap();
        assert_eq!(slopes.len(), 2);
        let slope = s["convergence_slope"].as_f64().unwrap();
        let mean = (slopes[0].as_f64().unwrap() + slopes[1].as_f64().unwrap()) / 2.0;
        assert!((slope - mean).abs() < 1e-12, "{slope} vs {mean}");
        assert!(s["convergence_slope_ci95"][0].as_f64().unwrap() <= slope);
    }
    let sobol = &samplers[0];
    assert_eq!(sobol["name"], "sobol");
    assert_eq!(sobol["relmse_ratio_to_sobol"], 1.0);
    let indep = &samplers[2];
    let run0 = indep["runs"][0]["linear"]["relmse"].as_f64().unwrap();
    assert!((relmse - run0).abs() <= 1e-12 * run0, "{relmse} vs {run0}");
    let expected =
        indep["relmse"]["mean"].as_f64().unwrap() / sobol["relmse"]["mean"].as_f64().unwrap();
    assert!((indep["relmse_ratio_to_sobol"].as_f64().unwrap() - expected).abs() < 1e-12 * expected);
    let sweep = json["threshold_sweep"].as_array().unwrap();
    assert_eq!(sweep.len(), 7);
    for p in sweep {
        assert!(p["relmse"]["mean"].as_f64().unwrap() > 0.0, "{p}");
        assert!(p["srgb8_relmse"]["mean"].as_f64().unwrap() > 0.0, "{p}");
        let d = p["star_discrepancy"].as_f64().unwrap();
        assert!(d > 0.0 && d <= 1.0, "{p}");
    }
    // Threshold 1 flips no column: its renders are plain Sobol's, the same
    // images as the `sobol` runs with the same seeds.
    assert_eq!(sweep[6]["threshold"], 1.0);
    assert_eq!(sweep[6]["relmse"], sobol["relmse"]);
    assert_eq!(json["reference"]["cached"], false);

    // Second run: the cached reference is reused, its file untouched.
    let cache = Path::new(json["reference"]["file"].as_str().unwrap()).to_path_buf();
    let mtime = std::fs::metadata(&cache).unwrap().modified().unwrap();
    let log2 = run_quick(&out);
    assert!(log2.contains("reusing cached reference"), "{log2}");
    assert!(!log2.contains("rendering reference"), "{log2}");
    assert_eq!(
        std::fs::metadata(&cache).unwrap().modified().unwrap(),
        mtime
    );
    let json2: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    assert_eq!(json2["reference"]["cached"], true);
    // Same seeds, same reference: the same errors.
    assert_eq!(
        json2["samplers"][1]["relmse"],
        json["samplers"][1]["relmse"]
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_arguments_fail_with_one_line() {
    for args in [
        vec!["experiment", "--samplers", "sobel"],
        vec!["experiment", "--runs", "0"],
        vec!["experiment", "--conv-max", "12"],
        vec!["experiment", "--conv-res", "0x0"],
        vec!["experiment", "--conv-res", "99999x2"],
        vec!["experiment", "--conv-ref-spp", "0"],
        vec!["experiment", "--conv-seeds", "0"],
        vec!["experiment", "/nonexistent/scene.pbrt"],
    ] {
        let o = lowdisc(&args);
        assert!(!o.status.success(), "{args:?} succeeded");
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert!(stderr.starts_with("error:"), "{stderr}");
        assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    }
}

#[test]
fn scene_file_with_a_substituted_environment_map() {
    let (Some(scene), Some(sky)) = (
        shared_scenes::file("bitterli-material-testball/material-testball.pbrt"),
        shared_scenes::file("envmaps/polyhaven-venice_sunset_1k.hdr"),
    ) else {
        return;
    };
    let dir = temp_dir("experiment-scene");
    let out = dir.join("out");
    let o = lowdisc(&[
        "experiment",
        scene.to_str().unwrap(),
        "--envmap",
        sky.to_str().unwrap(),
        "--samplers",
        "sobol,zsobol",
        "--runs",
        "1",
        "--spp",
        "2",
        "--res",
        "24x16",
        "--ref-spp",
        "8",
        "--conv-max",
        "2",
        "--conv-res",
        "12x8",
        "--out",
        out.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "experiment failed: {stderr}");
    assert!(stderr.contains("replaced by"), "{stderr}");
    // The convergence series has its own reference: 12x8 at 8 x 2 spp.
    assert!(
        stderr.contains("rendering reference: 24x16, 8 spp"),
        "{stderr}"
    );
    assert!(
        stderr.contains("rendering reference: 12x8, 16 spp"),
        "{stderr}"
    );
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(md.contains("substituted for the scene's own sky"), "{md}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    // The environment map lights the scene: the reference is not black.
    let relmse = json["samplers"][0]["relmse"]["mean"].as_f64().unwrap();
    assert!(relmse.is_finite() && relmse > 0.0, "{relmse}");
    assert_eq!(json["settings"]["conv_res"], serde_json::json!([12, 8]));
    assert_eq!(json["settings"]["conv_ref_spp"], 16);
    assert_ne!(
        json["convergence_reference"]["file"],
        json["reference"]["file"]
    );
    let conv = json["samplers"][1]["convergence"].as_array().unwrap();
    assert_eq!(conv.len(), 2); // 1 and 2 spp
    assert!(conv.iter().all(|c| c["relmse"].as_f64().unwrap() > 0.0));
    let reference = lowdisc_image::read_image(out.join("reference.exr")).unwrap();
    let mean: f64 = reference
        .pixels()
        .iter()
        .map(|p| f64::from(p[0] + p[1] + p[2]))
        .sum::<f64>()
        / reference.pixels().len() as f64;
    assert!(mean > 0.01, "reference mean {mean}");
    let _ = std::fs::remove_dir_all(&dir);
}
