//! `lowdisc spectrum` and `lowdisc paper-claim` on tiny settings write their
//! files with the expected contents.

mod common;

use common::{lowdisc, stdout_of, temp_dir};
use serde_json::Value;

#[test]
fn spectrum_writes_the_picture_the_csv_and_json() {
    let dir = temp_dir("spectrum");
    let png = dir.join("spec.png");
    let out = stdout_of(&[
        "spectrum",
        "--samplers",
        "independent,sobol",
        "-n",
        "64",
        "--max-frequency",
        "8",
        "-o",
        png.to_str().unwrap(),
        "--json",
    ]);
    let entries: Value = serde_json::from_str(&out).expect("valid JSON");
    let entries = entries.as_array().unwrap();
    assert_eq!(entries.len(), 2);
    assert_eq!(entries[1]["sampler"], "sobol");
    assert_eq!(entries[1]["spectrum"]["power"].as_array().unwrap().len(), 8);
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[1..4], b"PNG");
    let csv = std::fs::read_to_string(dir.join("spec.csv")).unwrap();
    assert!(csv.starts_with("sampler,radius,power,count\n"), "{csv}");
    assert_eq!(csv.lines().count(), 1 + 2 * 8);
    let svg = dir.join("spec.svg");
    stdout_of(&[
        "spectrum",
        "-n",
        "16",
        "--max-frequency",
        "4",
        "-o",
        svg.to_str().unwrap(),
    ]);
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
}

#[test]
fn spectrum_rejects_bad_options() {
    for args in [
        &["spectrum", "--samplers", "sobel", "-o", "x.png"][..],
        &["spectrum", "--dim-range", "0..3", "-o", "x.png"],
        &["spectrum", "-o", "x.gif"],
        &["spectrum", "-n", "1", "-o", "x.png"],
    ] {
        let out = lowdisc(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}

#[test]
fn paper_claim_writes_tables_json_and_plots() {
    let dir = temp_dir("claim");
    let out = stdout_of(&[
        "paper-claim",
        "--out",
        dir.to_str().unwrap(),
        "--seeds",
        "2",
        "--ns",
        "16,64",
        "--pairs",
        "0..2,2..4",
        "--thresholds",
        "0.5",
        "--plot-format",
        "svg",
    ]);
    assert!(out.contains("claim.md"), "{out}");
    let md = std::fs::read_to_string(dir.join("claim.md")).unwrap();
    for needle in [
        "## Dimensions 2, 3",
        "| paper (t = 0.5) |",
        "| paper-repro (t = 0.5) |",
        "| sobol-fast-owen |",
        "Minimum toroidal distance",
    ] {
        assert!(md.contains(needle), "{needle} not in {md}");
    }
    let json: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("claim.json")).unwrap()).unwrap();
    let rows = json["rows"].as_array().unwrap();
    // 8 samplers (sobol, 2 paper, xor, owen, fast owen, halton, independent) x 2 pairs x 2 ns.
    assert_eq!(rows.len(), 8 * 2 * 2);
    let sobol16 = rows
        .iter()
        .find(|r| r["sampler"] == "sobol" && r["n"] == 16 && r["dims"][0] == 0)
        .unwrap();
    assert_eq!(sobol16["runs"], 1);
    // The first 16 Sobol points in dims 0,1: the exact D* of this (0,4,2)-net.
    let star = sobol16["star"]["mean"].as_f64().unwrap();
    assert!(star > 1.0 / 16.0 - 1e-12 && star < 0.25, "{star}");
    for stem in ["dstar", "mindist", "mindist_toroidal"] {
        for pair in ["0-1", "2-3"] {
            let path = dir.join(format!("{stem}_dims{pair}.svg"));
            assert!(
                std::fs::read_to_string(&path).unwrap().contains("<svg"),
                "{path:?}"
            );
        }
    }
}
