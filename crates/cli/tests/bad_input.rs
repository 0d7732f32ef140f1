//! Bad input: every case exits non-zero with one `error: ...` line that
//! names the problem, never a panic, and leaves no output file behind.

mod common;

use common::{lowdisc, temp_dir};

/// Runs `lowdisc`, expects failure, returns stderr.
fn fails(args: &[&str]) -> String {
    let out = lowdisc(args);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(!out.status.success(), "lowdisc {args:?} should fail");
    assert!(
        !stderr.contains("panicked"),
        "lowdisc {args:?} panicked: {stderr}"
    );
    assert!(stderr.starts_with("error: "), "lowdisc {args:?}: {stderr}");
    stderr
}

/// Fails with exactly one line mentioning `needle`.
fn fails_with(args: &[&str], needle: &str) {
    let stderr = fails(args);
    assert_eq!(
        stderr.trim_end().lines().count(),
        1,
        "lowdisc {args:?}: {stderr}"
    );
    assert!(
        stderr.contains(needle),
        "lowdisc {args:?}: `{needle}` not in {stderr}"
    );
}

#[test]
fn dimensions_beyond_the_table_are_rejected() {
    fails_with(
        &["points", "-s", "sobol", "--dims", "30000"],
        "out of range",
    );
    fails_with(
        &["points", "-s", "sobol", "--dim-range", "21200..21202"],
        "21201",
    );
    fails_with(
        &["points", "-s", "paper", "--dims", "21202"],
        "out of range",
    );
    fails_with(&["points", "-s", "sobol", "--dims", "0"], "--dims");
}

#[test]
fn counts_of_zero_are_rejected() {
    fails_with(&["points", "-s", "sobol", "--n", "0"], "--n");
    fails_with(
        &["points", "-s", "sobol", "--pixel", "0,0", "--spp", "0"],
        "--spp",
    );
    fails_with(&["figure", "--spp", "0", "-o", "never.png"], "--spp");
}

#[test]
fn unknown_samplers_list_the_known_ones() {
    fails_with(
        &["points", "-s", "sobel"],
        "known samplers: independent, stratified, halton",
    );
    fails_with(
        &["figure", "--samplers", "sobol,nope", "-o", "never.svg"],
        "unknown sampler `nope`",
    );
}

#[test]
fn thresholds_outside_the_unit_interval_are_rejected() {
    for t in ["1.5", "-0.1", "NaN", "inf"] {
        fails_with(&["points", "-s", "paper", "--threshold", t], "[0, 1]");
        fails_with(&["figure", "--threshold", t, "-o", "never.png"], "[0, 1]");
    }
}

#[test]
fn malformed_pixel_and_resolution_are_rejected() {
    for pixel in ["3", "a,b", "1;2", "-1,0", ",", "1,2,3"] {
        fails_with(&["points", "-s", "sobol", "--pixel", pixel], "--pixel");
    }
    fails_with(
        &["points", "-s", "sobol", "--pixel", "4,0", "--res", "4x4"],
        "outside the 4x4 image",
    );
    for res in ["4", "0x4", "4x", "x4", "4*4"] {
        fails_with(
            &["points", "-s", "sobol", "--pixel", "0,0", "--res", res],
            "--res",
        );
    }
    fails_with(
        &["points", "-s", "sobol", "--pixel", "0,0", "-f", "u32"],
        "u32",
    );
}

#[test]
fn empty_or_reversed_dimension_ranges_are_rejected() {
    for range in ["4..2", "3..3", "2-4", "..4", "a..b"] {
        fails_with(
            &["points", "-s", "sobol", "--dim-range", range],
            "--dim-range",
        );
    }
}

#[test]
fn too_much_output_at_once_is_rejected() {
    fails_with(
        &[
            "points",
            "-s",
            "sobol",
            "--n",
            "2000000",
            "--plot",
            "never.png",
        ],
        "--plot draws at most",
    );
    fails_with(
        &[
            "points",
            "-s",
            "sobol",
            "--pixel",
            "0,0",
            "--spp",
            "4000000",
            "--plot",
            "never.svg",
        ],
        "--plot draws at most",
    );
    fails_with(
        &[
            "points",
            "-s",
            "sobol",
            "--pixel",
            "0,0",
            "--dims",
            "4000000000",
        ],
        "--dims must be at most",
    );
    fails_with(
        &["points", "-s", "sobol", "--n", "4294967295", "--dims", "2"],
        "sample count",
    );
}

#[test]
fn failed_runs_leave_no_file() {
    let dir = temp_dir("bad");
    let png = dir.join("fig.png");
    fails_with(
        &[
            "figure",
            "--samplers",
            "sobol,bogus",
            "-o",
            png.to_str().unwrap(),
        ],
        "bogus",
    );
    fails_with(
        &["figure", "-o", dir.join("fig.gif").to_str().unwrap()],
        ".png or .svg",
    );
    let missing = dir.join("no/such/dir/fig.png");
    fails_with(&["figure", "-o", missing.to_str().unwrap()], "cannot write");
    fails_with(
        &[
            "points",
            "-s",
            "sobol",
            "--dims",
            "1",
            "--plot",
            png.to_str().unwrap(),
        ],
        "2 dimensions",
    );
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert!(left.is_empty(), "files left behind: {left:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn syntax_errors_fail_without_panicking() {
    let out = lowdisc(&["points", "-s", "sobol", "--n", "many"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(!String::from_utf8_lossy(&out.stderr).contains("panicked"));
    let out = lowdisc(&["points"]);
    assert_eq!(out.status.code(), Some(2));
}
