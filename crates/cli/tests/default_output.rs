//! Where commands write without `-o`, and what they say about it: `render`
//! and `figure` write into `out/` (created) under the current directory,
//! `points --plot` names the file it wrote, and an I/O error is named once.

mod common;

use std::path::Path;
use std::process::{Command, Output};

use common::temp_dir;

/// Runs `lowdisc args` in `cwd`.
fn lowdisc_in(cwd: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_lowdisc"))
        .args(args)
        .current_dir(cwd)
        .output()
        .expect("the lowdisc binary runs")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn render_and_figure_write_into_out_without_o() {
    let dir = temp_dir("default-output");
    let o = lowdisc_in(&dir, &["render", "--res", "8x8", "--spp", "1"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(dir.join("out/render.exr").is_file());
    assert!(
        stderr(&o).contains("wrote out/render.exr"),
        "{}",
        stderr(&o)
    );
    assert!(!dir.join("render.exr").exists());

    let o = lowdisc_in(&dir, &["figure", "--spp", "4"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(dir.join("out/figure.png").is_file());
    assert!(
        stderr(&o).contains("wrote out/figure.png"),
        "{}",
        stderr(&o)
    );

    // A bad option creates nothing.
    let fresh = dir.join("fresh");
    std::fs::create_dir(&fresh).unwrap();
    let o = lowdisc_in(&fresh, &["figure", "--spp", "0"]);
    assert!(!o.status.success());
    assert!(!fresh.join("out").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn points_plot_names_its_file_and_errors_name_the_cause_once() {
    let dir = temp_dir("points-plot");
    let o = lowdisc_in(
        &dir,
        &[
            "points",
            "--sampler",
            "sobol",
            "--n",
            "16",
            "--plot",
            "p.png",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(dir.join("p.png").is_file());
    assert_eq!(stderr(&o).trim(), "wrote p.png");
    assert!(o.stdout.is_empty());

    let o = lowdisc_in(
        &dir,
        &[
            "points",
            "--sampler",
            "sobol",
            "--n",
            "16",
            "--plot",
            "nowhere/p.png",
        ],
    );
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.starts_with("error: cannot write `nowhere/p.png`"),
        "{err}"
    );
    assert_eq!(err.matches("(os error").count(), 1, "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
