//! End-to-end test of `lowdisc experiment --preset`: the built-in Cornell
//! box, the masked, blurred and FLIP measures, and the statistics that say
//! which samplers can be told apart.

mod common;

use common::{lowdisc, temp_dir};

#[test]
fn direct_preset_reports_intervals_ratios_and_verdicts() {
    let dir = temp_dir("experiment-preset");
    let out = dir.join("out");
    let o = lowdisc(&[
        "experiment",
        "--preset",
        "direct",
        "--quick",
        "--runs",
        "4",
        "--samplers",
        "sobol,sobol-owen,independent",
        "--out",
        out.to_str().unwrap(),
        "-q",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    assert_eq!(json["settings"]["preset"], "direct");
    assert_eq!(json["settings"]["max_depth"], 1);
    assert_eq!(json["settings"]["baseline"], "sobol");
    // The light and its 3-pixel border are a small part of a 32x32 image.
    let kept = json["kept_fraction"].as_f64().unwrap();
    assert!(kept > 0.7 && kept < 1.0, "{kept}");
    let samplers = json["samplers"].as_array().unwrap();
    let stat = |s: &serde_json::Value, metric: &str| -> serde_json::Value {
        s["statistics"]
            .as_array()
            .unwrap()
            .iter()
            .find(|m| m["metric"] == metric)
            .unwrap_or_else(|| panic!("no {metric}"))
            .clone()
    };
    for s in samplers {
        for metric in [
            "masked_mse",
            "masked_relmse",
            "blurred_mse",
            "flip",
            "mse",
            "relmse",
        ] {
            let m = stat(s, metric);
            let summary = &m["summary"];
            assert_eq!(summary["n"], 4);
            let (mean, lo, hi) = (
                summary["mean"].as_f64().unwrap(),
                summary["ci95"][0].as_f64().unwrap(),
                summary["ci95"][1].as_f64().unwrap(),
            );
            assert!(
                lo <= mean && mean <= hi,
                "{metric} of {}: {summary}",
                s["name"]
            );
            // Every run's value enters the summary: the mean is theirs.
            let runs: Vec<f64> = s["runs"]
                .as_array()
                .unwrap()
                .iter()
                .map(|r| match metric {
                    "masked_mse" => r["quality"]["masked"]["mse"].as_f64().unwrap(),
                    "flip" => r["quality"]["flip"].as_f64().unwrap(),
                    _ => f64::NAN,
                })
                .collect();
            if runs.iter().all(|v| v.is_finite()) {
                let m4 = runs.iter().sum::<f64>() / 4.0;
                assert!((m4 - mean).abs() <= 1e-12 * mean.abs(), "{metric}");
            }
        }
        // The masked MSE leaves out the light's bright outline.
        let masked = stat(s, "masked_mse")["summary"]["mean"].as_f64().unwrap();
        let all = stat(s, "mse")["summary"]["mean"].as_f64().unwrap();
        assert!(masked < all, "{}: masked {masked} vs {all}", s["name"]);
        let flip = stat(s, "flip")["summary"]["mean"].as_f64().unwrap();
        assert!(flip > 0.0 && flip < 1.0);
    }
    assert!(stat(&samplers[0], "masked_mse")["ratio_to_baseline"].is_null());
    // Independent sampling at 4 spp is far worse than Sobol: resolved.
    let indep = stat(&samplers[2], "masked_mse")["ratio_to_baseline"].clone();
    assert!(indep["ratio"].as_f64().unwrap() > 1.5, "{indep}");
    assert_eq!(indep["verdict"], "worse", "{indep}");
    let md = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(md.contains("Can the samplers be told apart?"), "{md}");
    assert!(
        md.contains("| independent |") && md.contains("| worse |"),
        "{md}"
    );
    assert!(md.contains("preset `direct`"), "{md}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_preset_arguments_fail_with_one_line() {
    for args in [
        vec!["experiment", "--preset", "cornell"],
        vec!["experiment", "--preset", "direct", "--blur-sigma", "0"],
        vec!["experiment", "--preset", "gi", "--emitter-border", "100"],
    ] {
        let o = lowdisc(&args);
        assert!(!o.status.success(), "{args:?} succeeded");
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert!(stderr.starts_with("error:"), "{stderr}");
        assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    }
}
