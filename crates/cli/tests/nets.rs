//! `--net`: generator matrices from a file or by name. Joe & Kuo's own
//! direction numbers given as a file render the built-in samplers' images
//! bit for bit, the built-in `onetwo` net changes the samplers that read
//! its later dimensions, parts record the net, and bad files or samplers
//! that read no net are one-line errors naming the file and line.

mod common;

use common::{lowdisc, rows, stdout_of, temp_dir};

/// Joe & Kuo's first 64 dimensions, as a user's file.
const JOE_KUO_64: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../lowdisc/tests/data/new-joe-kuo-6.64"
);

/// Renders the Cornell box at 16x16, 4 spp, and returns the image's pixels.
fn render(dir: &std::path::Path, name: &str, extra: &[&str]) -> Vec<[f32; 3]> {
    let exr = dir.join(format!("{name}.exr"));
    let args = ["render", "--res", "16x16", "--spp", "4", "--quiet", "-o"];
    let out = lowdisc(&[&args[..], &[exr.to_str().unwrap()], extra].concat());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{extra:?}: {stderr}");
    lowdisc_image::read_image(&exr).unwrap().pixels().to_vec()
}

#[test]
fn a_joe_kuo_file_renders_the_built_in_images_and_onetwo_differs() {
    let dir = temp_dir("nets-render");
    for sampler in ["zsobol", "sobol-owen", "zsobol-4d"] {
        let built_in = render(&dir, sampler, &["-s", sampler]);
        let file = render(
            &dir,
            &format!("{sampler}-file"),
            &["-s", sampler, "--net", JOE_KUO_64],
        );
        assert!(built_in == file, "{sampler}: the file's image differs");
        let onetwo = render(
            &dir,
            &format!("{sampler}-onetwo"),
            &["-s", sampler, "--net", "onetwo"],
        );
        // onetwo's dimensions 0-1 are Joe & Kuo's: zsobol reads no other.
        assert_eq!(built_in == onetwo, sampler == "zsobol", "{sampler}");
    }
}

#[test]
fn points_read_the_net() {
    let text = stdout_of(&[
        "points", "-s", "sobol", "-n", "8", "--dims", "4", "--net", "onetwo",
    ]);
    let points: Vec<Vec<f64>> = rows(&text);
    let built_in: Vec<Vec<f64>> = rows(&stdout_of(&[
        "points", "-s", "sobol", "-n", "8", "--dims", "4",
    ]));
    assert_eq!(points.len(), 8);
    // The first two dimensions agree, the next two differ.
    assert!(points.iter().zip(&built_in).all(|(a, b)| a[..2] == b[..2]));
    assert!(points.iter().zip(&built_in).any(|(a, b)| a[2..] != b[2..]));
}

#[test]
fn parts_record_the_net_and_refuse_to_merge_across_nets() {
    let dir = temp_dir("nets-parts");
    let part = |name: &str, bounds: &str, net: &[&str]| {
        let path = dir.join(name);
        let args = [
            "render",
            "--res",
            "8x8",
            "--spp",
            "2",
            "--quiet",
            "-s",
            "zsobol-4d",
        ];
        let more = ["--pixel-bounds", bounds, "-o", path.to_str().unwrap()];
        let out = lowdisc(&[&args[..], &more, net].concat());
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        path.to_str().unwrap().to_string()
    };
    let a = part("a.exr", "0,8,0,4", &["--net", "onetwo"]);
    let b = part("b.exr", "0,8,4,8", &[]);
    let merged = dir.join("m.exr");
    let out = lowdisc(&["merge", merged.to_str().unwrap(), &a, &b]);
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("net"), "{stderr}");
    let b = part("b.exr", "0,8,4,8", &["--net", "onetwo"]);
    let out = lowdisc(&["merge", merged.to_str().unwrap(), &a, &b]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Fails with one `error:` line containing `needle`.
fn fails_with(args: &[&str], needle: &str) {
    let out = lowdisc(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{args:?} should fail");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    assert!(
        stderr.starts_with("error: ") && stderr.contains(needle),
        "{needle}: {stderr}"
    );
}

#[test]
fn bad_nets_are_one_line_errors_naming_the_file_and_line() {
    let dir = temp_dir("nets-bad");
    let file = dir.join("even.txt");
    std::fs::write(&file, "d s a m_i\n2 1 0 1\n3 2 1 1 2\n").unwrap();
    let f = file.to_str().unwrap();
    let o = dir.join("x.exr");
    let o = o.to_str().unwrap();
    fails_with(
        &["render", "--net", f, "-o", o],
        &format!("{f}:3: m_2 = 2 is even"),
    );
    fails_with(&["points", "-s", "sobol", "--net", f], &format!("{f}:3:"));
    fails_with(
        &["render", "--net", "nope", "-o", o],
        "not a built-in net (sobol, onetwo)",
    );
    fails_with(
        &["render", "-s", "halton", "--net", "onetwo", "-o", o],
        "--net: sampler `halton` does not take generator matrices",
    );
    fails_with(
        &["points", "-s", "pmj02", "--net", "onetwo"],
        "does not take",
    );
    let matrices = dir.join("m.txt");
    std::fs::write(&matrices, "# one dimension\n0x80000000 1 2\n").unwrap();
    let m = matrices.to_str().unwrap();
    fails_with(
        &["points", "-s", "sobol", "--net", m],
        &format!("{m}:2: 3 columns; a dimension has 32"),
    );
    assert!(!o.is_empty() && !std::path::Path::new(o).exists());
}
