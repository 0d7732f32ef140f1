//! `lowdisc figure` and `points --plot` write valid PNG and SVG files.

mod common;

use common::{stdout_of, temp_dir};

/// Width and height from a PNG's IHDR chunk, after checking the signature.
fn png_size(bytes: &[u8]) -> [u32; 2] {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "PNG signature");
    assert_eq!(&bytes[12..16], b"IHDR");
    let be = |i: usize| u32::from_be_bytes(bytes[i..i + 4].try_into().unwrap());
    assert_eq!(&bytes[bytes.len() - 8..bytes.len() - 4], b"IEND");
    [be(16), be(20)]
}

#[test]
fn figure_writes_png_and_svg_with_one_panel_per_sampler() {
    let dir = temp_dir("figure");
    let png = dir.join("figure.png");
    let svg = dir.join("figure.svg");
    assert_eq!(stdout_of(&["figure", "-o", png.to_str().unwrap()]), "");
    let [w, h] = png_size(&std::fs::read(&png).unwrap());
    assert!(w > 4 * h, "five panels side by side: {w}x{h}");

    stdout_of(&[
        "figure",
        "-o",
        svg.to_str().unwrap(),
        "--samplers",
        "sobol,paper",
        "--spp",
        "16",
    ]);
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg") && text.trim_end().ends_with("</svg>"));
    assert!(
        text.contains(">sobol</text>") && text.contains(">paper (t = 0.5, all dims)</text>"),
        "panel titles"
    );
    // 2 panels x 4 pixels x 16 samples.
    assert_eq!(text.matches("<circle").count(), 2 * 4 * 16);
    let names: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names.len(), 2, "no temporary files left: {names:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn points_plot_draws_instead_of_printing() {
    let dir = temp_dir("plot");
    let svg = dir.join("p.svg");
    let png = dir.join("p.png");
    assert_eq!(
        stdout_of(&[
            "points",
            "-s",
            "sobol",
            "-n",
            "64",
            "--plot",
            svg.to_str().unwrap()
        ]),
        ""
    );
    assert_eq!(
        std::fs::read_to_string(&svg)
            .unwrap()
            .matches("<circle")
            .count(),
        64
    );
    let out = stdout_of(&[
        "points",
        "-s",
        "zsobol",
        "--pixel",
        "1,1",
        "--spp",
        "16",
        "--plot",
        png.to_str().unwrap(),
    ]);
    assert_eq!(out, "");
    png_size(&std::fs::read(&png).unwrap());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn paper_all_dims_is_the_same_kind_of_option_everywhere() {
    // `--paper-all-dims` alone means true and `--paper-all-dims=BOOL` sets it,
    // in points, figure and render alike.
    let pixel = |extra: &[&str]| {
        let mut args = vec![
            "points",
            "--sampler",
            "paper-repro",
            "--pixel",
            "0,0",
            "--spp",
            "16",
            "--dims",
            "2",
        ];
        args.extend_from_slice(extra);
        stdout_of(&args)
    };
    let default = pixel(&[]);
    let on = pixel(&["--paper-all-dims"]);
    assert_eq!(on, pixel(&["--paper-all-dims=true"]));
    assert_eq!(default, pixel(&["--paper-all-dims=false"]));
    assert_ne!(on, default, "the permutation moves the film positions");

    let dir = temp_dir("paper-all-dims");
    let svg = |name: &str, extra: &[&str]| {
        let file = dir.join(name);
        let mut args = vec![
            "figure",
            "--samplers",
            "paper-repro",
            "-o",
            file.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        stdout_of(&args);
        std::fs::read_to_string(file).unwrap()
    };
    let figure_default = svg("a.svg", &[]);
    assert_eq!(figure_default, svg("b.svg", &["--paper-all-dims"]));
    assert_ne!(figure_default, svg("c.svg", &["--paper-all-dims=false"]));
    let exr = dir.join("r.exr");
    stdout_of(&[
        "render",
        "--res",
        "8x8",
        "--spp",
        "1",
        "--sampler",
        "paper-repro",
        "--paper-all-dims",
        "-q",
        "-o",
        exr.to_str().unwrap(),
    ]);
    assert!(exr.is_file());
    let _ = std::fs::remove_dir_all(&dir);
}
