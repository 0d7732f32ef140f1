//! End-to-end test of `lowdisc study --quick`: two preset scenes, three
//! samplers, the three output files and their agreement; bad input.

mod common;

use common::{lowdisc, temp_dir};

fn run_quick(out: &std::path::Path, extra: &[&str]) -> std::process::Output {
    let mut args = vec![
        "study",
        "--quick",
        "--samplers",
        "independent,sobol,sobol-fast-owen",
        "--threads",
        "2",
        "--out",
        out.to_str().unwrap(),
        "-q",
    ];
    args.extend_from_slice(extra);
    lowdisc(&args)
}

#[test]
fn quick_study_writes_consistent_tables() {
    let dir = temp_dir("study-quick");
    let out = dir.join("out");
    let baselines = ["--baseline", "sobol,independent"];
    let o = run_quick(&out, &baselines);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("study.json")).unwrap()).unwrap();
    assert_eq!(json["settings"]["baselines"][0], "sobol");
    let scenes = json["results"]["scenes"].as_array().unwrap();
    let names: Vec<&str> = scenes.iter().map(|s| s["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["direct", "gi"]);
    let samplers = json["results"]["samplers"].as_array().unwrap();
    assert_eq!(samplers.len(), 3);
    for s in samplers {
        let masked = &s["ratios"][0]["metrics"][0];
        assert_eq!(masked["metric"], "masked_mse");
        let pooled = &masked["pooled"];
        let ratio = pooled["ratio"].as_f64().unwrap();
        let [lo, hi] = [0, 1].map(|i| pooled["ci95"][i].as_f64().unwrap());
        assert!(lo <= ratio && ratio <= hi, "{s}");
        // The pooled ratio is the geometric mean of the scene ratios.
        let scene_ratios: Vec<f64> = masked["scenes"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| r["ratio"].as_f64().unwrap())
            .collect();
        let geo = (scene_ratios.iter().map(|r| r.ln()).sum::<f64>() / 2.0).exp();
        assert!((geo / ratio - 1.0).abs() < 1e-12, "{geo} vs {ratio}");
        let structure = s["structure"]["mean"].as_f64().unwrap();
        assert!(structure > 0.0 && structure < 100.0, "{structure}");
    }
    // Unscrambled Sobol is deterministic: its ratio to itself is exactly 1.
    assert_eq!(
        samplers[1]["ratios"][0]["metrics"][0]["pooled"]["ratio"],
        1.0
    );
    let md = std::fs::read_to_string(out.join("study.md")).unwrap();
    assert!(md.contains("| `sobol-fast-owen` |"), "{md}");
    let csv = std::fs::read_to_string(out.join("study.csv")).unwrap();
    let header = csv.lines().next().unwrap();
    assert!(
        header.starts_with("scope,sampler,baseline,metric,value"),
        "{header}"
    );
    // Per sampler: 2 baselines x 4 metrics x (2 scenes + pooled), structure
    // x 3 and the spectral peak.
    assert_eq!(csv.lines().count(), 1 + 3 * (2 * 4 * 3 + 3 + 1));
    // The second baseline: independent against itself is 1, and sobol's
    // ratio to independent is the inverse of independent's to sobol.
    let to = |s: usize, b: usize| {
        samplers[s]["ratios"][b]["metrics"][0]["pooled"]["ratio"]
            .as_f64()
            .unwrap()
    };
    assert_eq!(samplers[0]["ratios"][1]["baseline"], "independent");
    assert_eq!(to(0, 1), 1.0);
    assert!((to(1, 1) * to(0, 0) - 1.0).abs() < 1e-12);
    assert!(md.contains("## Masked MSE ratio to `independent`"), "{md}");
    assert!(md.contains("| spectral peak |"), "{md}");
    // A second run reuses the cached references and gives the same numbers.
    let again = dir.join("again");
    let o = run_quick(&again, &baselines);
    assert!(o.status.success());
    let second: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(again.join("study.json")).unwrap()).unwrap();
    assert_eq!(second["results"]["scenes"][0]["reference"]["cached"], true);
    assert_eq!(
        second["results"]["samplers"], json["results"]["samplers"],
        "the study is not deterministic"
    );
}

#[test]
fn bad_input_is_one_line_and_non_zero() {
    let dir = temp_dir("study-bad");
    let out = dir.join("out");
    for (extra, needle) in [
        (&["--scenes", "nowhere"][..], "unknown scene `nowhere`"),
        (&["--baseline", "zsobol"][..], "baseline `zsobol`"),
        (&["--runs", "1"][..], "--runs"),
        (&["--samplers", "bogus"][..], "unknown sampler `bogus`"),
        (&["no-such-file.pbrt"][..], "no-such-file.pbrt"),
    ] {
        let o = run_quick(&out, extra);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{extra:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(
            err.starts_with("error: ") && err.contains(needle),
            "{extra:?}: {err}"
        );
    }
}
