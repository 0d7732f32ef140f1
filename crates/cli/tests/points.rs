//! `lowdisc points`: exact values, the output formats, pixel mode and a
//! closed output pipe, run through the real binary.

mod common;

use std::io::Read;
use std::process::{Command, Stdio};

use common::{lowdisc, rows, stdout_of};

/// The first 8 points of Sobol dimensions 0 and 1 in Gray-code order, as
/// `floor(x * 2^32)` of `scipy.stats.qmc.Sobol(2, scramble=False, bits=32)`.
const SCIPY_FIRST_8: [[u32; 2]; 8] = [
    [0, 0],
    [2147483648, 2147483648],
    [3221225472, 1073741824],
    [1073741824, 3221225472],
    [1610612736, 1610612736],
    [3758096384, 3758096384],
    [2684354560, 536870912],
    [536870912, 2684354560],
];

#[test]
fn sobol_u32_matches_scipy_in_gray_order() {
    let got: Vec<Vec<u32>> = rows(&stdout_of(&[
        "points",
        "--sampler",
        "sobol",
        "--n",
        "8",
        "--format",
        "u32",
    ]));
    let want: Vec<Vec<u32>> = SCIPY_FIRST_8.iter().map(|p| p.to_vec()).collect();
    assert_eq!(got, want);
    let explicit = stdout_of(&[
        "points", "-s", "sobol", "-n", "8", "-f", "u32", "--order", "gray",
    ]);
    assert_eq!(rows::<u32>(&explicit), want);
}

#[test]
fn natural_order_is_the_index_order() {
    let got: Vec<Vec<u32>> = rows(&stdout_of(&[
        "points", "-s", "sobol", "-n", "4", "-f", "u32", "--order", "natural",
    ]));
    let half = 1u32 << 31;
    assert_eq!(
        got,
        vec![
            vec![0, 0],
            vec![half, half],
            vec![half / 2, 3 * (half / 2)],
            vec![3 * (half / 2), half / 2]
        ]
    );
}

#[test]
fn dim_range_selects_columns_of_the_full_point() {
    let full: Vec<Vec<u32>> = rows(&stdout_of(&[
        "points", "-s", "sobol", "-n", "32", "--dims", "6", "-f", "u32",
    ]));
    let part: Vec<Vec<u32>> = rows(&stdout_of(&[
        "points",
        "-s",
        "sobol",
        "-n",
        "32",
        "--dim-range",
        "3..5",
        "-f",
        "u32",
    ]));
    assert_eq!(part.len(), 32);
    for (p, f) in part.iter().zip(&full) {
        assert_eq!(p[..], f[3..5]);
    }
}

/// Every decimal format parses back to exactly the u32 words (value = word * 2^-32).
#[test]
fn text_csv_and_json_parse_back_to_the_words() {
    let args = |f: &'static str| {
        [
            "points",
            "-s",
            "sobol-owen",
            "--seed",
            "7",
            "-n",
            "64",
            "--dims",
            "3",
            "-f",
            f,
        ]
    };
    let words: Vec<Vec<u32>> = rows(&stdout_of(&args("u32")));
    let back = |v: f64| (v * 4_294_967_296.0) as u32;
    let text: Vec<Vec<f64>> = rows(&stdout_of(&args("text")));
    assert_eq!(
        text.iter()
            .map(|r| r.iter().map(|&v| back(v)).collect::<Vec<_>>())
            .collect::<Vec<_>>(),
        words
    );

    let csv = stdout_of(&args("csv"));
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("x0,x1,x2"));
    let csv_words: Vec<Vec<u32>> = lines
        .map(|l| l.split(',').map(|v| back(v.parse().unwrap())).collect())
        .collect();
    assert_eq!(csv_words, words);

    let json = stdout_of(&args("json"));
    let body = json
        .trim()
        .strip_prefix('[')
        .and_then(|s| s.strip_suffix(']'))
        .expect("an outer array");
    let json_words: Vec<Vec<u32>> = body
        .split("],")
        .map(|row| {
            let row = row.trim().trim_start_matches('[').trim_end_matches(']');
            row.split(',')
                .map(|v| back(v.trim().parse().unwrap()))
                .collect()
        })
        .collect();
    assert_eq!(json_words, words);
}

#[test]
fn pixel_mode_samples_lie_in_the_pixel() {
    for sampler in [
        "independent",
        "stratified",
        "halton",
        "halton-owen",
        "sobol",
        "sobol-xor",
        "sobol-owen",
        "sobol-fast-owen",
        "paper",
        "paper-repro",
        "padded-sobol",
        "zsobol",
    ] {
        for extra in ["--paper-all-dims", "--seed=3"] {
            let out = stdout_of(&[
                "points", "-s", sampler, "--pixel", "5,2", "--spp", "16", "--res", "8x4", "--dims",
                "5", extra,
            ]);
            let samples: Vec<Vec<f64>> = rows(&out);
            assert_eq!(samples.len(), 16, "{sampler}");
            for s in &samples {
                assert_eq!(s.len(), 2 + 5, "{sampler}");
                assert!(
                    (5.0..6.0).contains(&s[0]) && (2.0..3.0).contains(&s[1]),
                    "{sampler}: {s:?}"
                );
                assert!(
                    s[2..].iter().all(|v| (0.0..1.0).contains(v)),
                    "{sampler}: {s:?}"
                );
            }
        }
    }
}

#[test]
fn pixel_mode_csv_names_the_columns() {
    let out = stdout_of(&[
        "points", "-s", "sobol", "--pixel", "0,0", "--spp", "4", "--dims", "3", "-f", "csv",
    ]);
    let mut lines = out.lines();
    assert_eq!(lines.next(), Some("film_x,film_y,v0,v1,v2"));
    assert_eq!(lines.count(), 4);
}

/// pbrt-v3's global Sobol sampler puts the first 2x2x4 indices in a 2x2 image,
/// so pixel (0,0)'s four film positions are the Sobol points that fall there.
#[test]
fn unscrambled_pixel_positions_are_sobol_points() {
    let out = stdout_of(&[
        "points", "-s", "sobol", "--pixel", "0,0", "--spp", "4", "--res", "2x2",
    ]);
    let mut got: Vec<Vec<f64>> = rows(&out);
    got.sort_by(|a, b| a.partial_cmp(b).unwrap());
    let all: Vec<Vec<f64>> = rows(&stdout_of(&["points", "-s", "sobol", "-n", "16"]));
    let mut want: Vec<Vec<f64>> = all
        .into_iter()
        .filter(|p| p[0] < 0.5 && p[1] < 0.5)
        .map(|p| vec![2.0 * p[0], 2.0 * p[1]])
        .collect();
    want.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(got, want);
}

#[test]
fn a_closed_pipe_ends_quietly_with_success() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_lowdisc"))
        .args([
            "points", "-s", "sobol", "-n", "65536", "--dims", "256", "-f", "u32",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 100];
    child
        .stdout
        .as_mut()
        .unwrap()
        .read_exact(&mut first)
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "status {:?}, stderr {stderr}",
        out.status
    );
    assert!(stderr.is_empty(), "{stderr}");
}

#[test]
fn help_documents_the_scipy_order() {
    let out = lowdisc(&["points", "--help"]);
    let help = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success());
    assert!(
        help.contains("scipy.stats.qmc.Sobol") && help.contains("--pixel"),
        "{help}"
    );
}

#[test]
fn help_lists_every_catalog_name_with_its_description() {
    let out = lowdisc(&["points", "--help"]);
    let help = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success());
    for name in lowdisc::catalog::SamplerName::ALL {
        let line = help
            .lines()
            .find(|l| l.split_whitespace().next() == Some(name.as_str()));
        let line = line.unwrap_or_else(|| panic!("{name} missing from:\n{help}"));
        assert!(line.contains(name.description()), "{line}");
    }
}
