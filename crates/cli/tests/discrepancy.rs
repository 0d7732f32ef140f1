//! `lowdisc discrepancy`: exact values on small files (the paper's 1-D facts,
//! a 2-D set against a brute-force evaluation here), JSON output, and every
//! bad input failing cleanly with the line number.

mod common;

use std::path::{Path, PathBuf};

use common::{lowdisc, stdout_of, temp_dir};
use serde_json::Value;

/// Writes `text` to `name` in `dir`.
fn file(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// The JSON report of `discrepancy` with `args`.
fn report(args: &[&str]) -> Value {
    let mut all = vec!["discrepancy", "--json"];
    all.extend_from_slice(args);
    serde_json::from_str(&stdout_of(&all)).expect("valid JSON")
}

/// The `value` of metric `name` in a report.
fn value(report: &Value, name: &str) -> f64 {
    report["results"]
        .as_array()
        .unwrap()
        .iter()
        .find(|r| r["metric"] == name)
        .unwrap_or_else(|| panic!("no {name} in {report}"))["value"]
        .as_f64()
        .unwrap()
}

/// Brute-force star discrepancy over the critical grid (coordinates and 1),
/// open boxes for the volume excess and closed boxes for the count excess.
fn brute_force_star(points: &[[f64; 2]]) -> f64 {
    let n = points.len() as f64;
    let grid = |j: usize| {
        let mut g: Vec<f64> = points.iter().map(|p| p[j]).collect();
        g.push(1.0);
        g
    };
    let mut worst: f64 = 0.0;
    for &a in &grid(0) {
        for &b in &grid(1) {
            let open = points.iter().filter(|p| p[0] < a && p[1] < b).count() as f64;
            let closed = points.iter().filter(|p| p[0] <= a && p[1] <= b).count() as f64;
            worst = worst.max(a * b - open / n).max(closed / n - a * b);
        }
    }
    worst
}

#[test]
fn one_dimensional_closed_forms_of_the_paper() {
    let dir = temp_dir("disc-1d");
    let n = 10;
    let ends: String = (1..=n)
        .map(|i| format!("{}\n", i as f64 / n as f64))
        .collect();
    let mids: String = (1..=n)
        .map(|i| format!("{}\n", (i as f64 - 0.5) / n as f64))
        .collect();
    let ends = file(&dir, "ends.txt", &ends);
    let mids = file(&dir, "mids.txt", &mids);
    let r = report(&["-i", ends.to_str().unwrap(), "--metric", "star"]);
    assert!((value(&r, "star") - 0.1).abs() < 1e-12, "{r}");
    let r = report(&["-i", mids.to_str().unwrap(), "--metric", "star"]);
    assert!((value(&r, "star") - 0.05).abs() < 1e-12, "{r}");
    assert_eq!(r["points"], 10);
    assert_eq!(r["dims"], 1);
}

#[test]
fn two_dimensional_exact_value_equals_brute_force() {
    let dir = temp_dir("disc-2d");
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let points: Vec<[f64; 2]> = (0..40).map(|_| [next(), next()]).collect();
    let mut text = String::from("# x, y\n");
    for p in &points {
        text.push_str(&format!("{}, {}\n", p[0], p[1]));
    }
    let path = file(&dir, "pts.csv", &text);
    let r = report(&["-i", path.to_str().unwrap(), "--metric", "star"]);
    let expected = brute_force_star(&points);
    assert!(
        (value(&r, "star") - expected).abs() < 1e-12,
        "{r} vs {expected}"
    );
    // The bounds bracket it.
    let r = report(&["-i", path.to_str().unwrap(), "--metric", "star-bounds"]);
    let row = &r["results"][0];
    assert!(row["lower"].as_f64().unwrap() <= expected + 1e-12, "{r}");
    assert!(row["upper"].as_f64().unwrap() >= expected - 1e-12, "{r}");
}

#[test]
fn all_metrics_of_a_sampler_as_json_and_table() {
    let r = report(&["-s", "sobol", "-n", "64", "--metric", "all"]);
    for name in [
        "star",
        "star-lower",
        "l2-star",
        "cd",
        "wd",
        "md",
        "mindist-euclidean",
        "mindist-toroidal",
        "mean-nn-euclidean",
        "mean-nn-toroidal",
    ] {
        let v = value(&r, name);
        assert!(v.is_finite() && v >= 0.0, "{name}: {v}");
    }
    // A (0,6,2)-net of 64 points: exact D* at most the lower bound's target.
    assert!(value(&r, "star-lower") <= value(&r, "star") + 1e-12);
    assert!(value(&r, "mindist-toroidal") <= value(&r, "mindist-euclidean") + 1e-15);
    let table = stdout_of(&["discrepancy", "-s", "sobol", "-n", "64", "-m", "cd"]);
    assert!(table.contains("64 points in 2 dimensions"), "{table}");
    assert!(table.lines().any(|l| l.starts_with("cd ")), "{table}");
}

#[test]
fn unaffordable_exact_star_points_to_the_bounds() {
    let args = [
        "discrepancy",
        "-s",
        "sobol",
        "-n",
        "4096",
        "--dims",
        "6",
        "-m",
        "star",
    ];
    let out = lowdisc(&args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(stderr.contains("star-bounds"), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
}

/// Expects failure without a panic; returns stderr.
fn fails(args: &[&str]) -> String {
    let out = lowdisc(args);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(!out.status.success(), "{args:?} should fail");
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    assert!(stderr.starts_with("error"), "{args:?}: {stderr}");
    stderr
}

#[test]
fn bad_files_fail_with_the_line_number() {
    let dir = temp_dir("disc-bad");
    for (name, text, needle) in [
        (
            "outside.txt",
            "0.1 0.2\n0.3 1.5\n",
            ":2: coordinate 2 = 1.5 is outside [0, 1]",
        ),
        (
            "negative.txt",
            "# c\n-0.1 0.2\n",
            ":2: coordinate 1 = -0.1 is outside",
        ),
        ("nan.txt", "0.1 0.2\n\n0.3 NaN\n", ":3: coordinate 2 is NaN"),
        (
            "ragged.txt",
            "0.1 0.2\n0.3\n",
            ":2: 1 coordinates, but line 1 has 2",
        ),
        (
            "word.txt",
            "0.1 zero\n",
            ":1: coordinate 2 `zero` is not a number",
        ),
        ("empty.txt", "", "no points"),
        ("comments.txt", "# nothing\n\n", "no points"),
    ] {
        let path = file(&dir, name, text);
        let stderr = fails(&["discrepancy", "-i", path.to_str().unwrap()]);
        assert!(stderr.contains(needle), "{name}: {stderr}");
        assert!(stderr.contains(name), "{name}: {stderr}");
        assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    }
    let missing = dir.join("missing.txt");
    let stderr = fails(&["discrepancy", "-i", missing.to_str().unwrap()]);
    assert!(
        stderr.contains("cannot read") && stderr.contains("missing.txt"),
        "{stderr}"
    );
    let binary = dir.join("binary.txt");
    std::fs::write(&binary, [b'0', b'\n', 0xff, 0xfe]).unwrap();
    let stderr = fails(&["discrepancy", "-i", binary.to_str().unwrap()]);
    assert!(stderr.contains(":2: the file is not UTF-8"), "{stderr}");
}

#[test]
fn bad_options_fail_cleanly() {
    fails(&["discrepancy", "-s", "sobol", "--metric", "nonsense"]);
    fails(&["discrepancy", "-s", "sobel"]);
    fails(&["discrepancy"]);
    fails(&["discrepancy", "-s", "sobol", "-n", "0"]);
    fails(&["discrepancy", "-s", "sobol", "-n", "1", "-m", "mindist"]);
    fails(&["discrepancy", "-s", "paper", "--threshold", "1.5"]);
}
