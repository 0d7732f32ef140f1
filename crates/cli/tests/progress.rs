//! Progress on stderr, from the real binary: off a terminal, lines with the
//! percentage, elapsed time, ETA and throughput, an estimate at the start
//! and a summary of the time and files at the end; under a pseudo-terminal
//! (`script` from util-linux), an indicatif bar; nothing with `--quiet`.

mod common;

use std::path::Path;
use std::process::{Command, Output};

use common::temp_dir;

/// The quick experiment with one sampler, writing to `out`, with `extra` arguments.
fn experiment_args(out: &Path, extra: &[&str]) -> Vec<String> {
    let mut args: Vec<String> = [
        "experiment",
        "--quick",
        "--samplers",
        "sobol",
        "--ref-spp",
        "256",
        "--out",
    ]
    .map(String::from)
    .into();
    args.push(out.display().to_string());
    args.extend(extra.iter().map(|s| s.to_string()));
    args
}

fn run(args: &[String]) -> Output {
    let o = Command::new(env!("CARGO_BIN_EXE_lowdisc"))
        .args(args)
        // Every 10 % gets its line, however fast the stage.
        .env("LOWDISC_PROGRESS_INTERVAL", "0")
        .output()
        .expect("the lowdisc binary runs");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    o
}

#[test]
fn off_a_terminal_progress_is_lines_with_eta_and_a_summary() {
    let dir = temp_dir("progress-lines");
    let out = dir.join("out");
    let o = run(&experiment_args(&out, &[]));
    let log = String::from_utf8_lossy(&o.stderr);
    let lines: Vec<&str> = log.lines().collect();
    assert!(
        lines[0].starts_with("estimated run time: ") && lines[0].contains("samples/s"),
        "{log}"
    );
    let reference = lines
        .iter()
        .position(|l| l.starts_with("rendering reference: 32x32, 256 spp"))
        .unwrap_or_else(|| panic!("{log}"));
    // Lines at the tenths of the reference render: percentage, elapsed, ETA,
    // and the whole run's percentage and time left.
    let figures: Vec<&&str> = lines[reference + 1..]
        .iter()
        .take_while(|l| l.contains("ETA"))
        .collect();
    assert!(!figures.is_empty(), "{log}");
    for l in &figures {
        assert!(
            l.contains("%, ")
                && l.contains(" elapsed, ETA ")
                && l.contains("; run ")
                && l.ends_with(" left"),
            "{l}"
        );
    }
    let pct = |l: &str| -> u32 { l.trim().split('%').next().unwrap().trim().parse().unwrap() };
    assert!(figures.windows(2).all(|w| pct(w[0]) < pct(w[1])), "{log}");
    assert!(
        lines[reference + 1 + figures.len()].starts_with("  done in "),
        "{log}"
    );
    for stage in [
        "[1/1] sobol: 2 runs at 4 spp",
        "threshold sweep: paper-repro at 7 thresholds",
        "convergence of sobol: 1 to 8 spp at 32x32, 2 seeds",
    ] {
        assert!(lines.iter().any(|l| l.starts_with(stage)), "{stage}: {log}");
    }
    // The summary: every stage's time, then every file.
    let summary = lines
        .iter()
        .position(|l| l.starts_with("time: "))
        .unwrap_or_else(|| panic!("{log}"));
    assert!(
        lines[summary].contains(" in all (estimated ") && lines[summary].ends_with(" %)"),
        "{log}"
    );
    assert!(
        lines[summary..]
            .iter()
            .any(|l| l.ends_with("other (loading, calibration, statistics, writing)"))
    );
    let files = &lines[lines.iter().position(|l| *l == "files:").unwrap()..];
    for f in ["report.html", "report.md", "results.json"] {
        let path = out.join(f);
        assert!(
            files.contains(&format!("  {}", path.display()).as_str()),
            "{f}: {log}"
        );
        assert!(path.is_file());
    }
    assert!(
        files.iter().any(|l| l.contains("lowdisc-ref-cache")),
        "{log}"
    );
    assert!(
        files.iter().any(|l| l.ends_with("images (.png, .exr)")),
        "{log}"
    );

    // --quiet: nothing at all.
    let quiet = run(&experiment_args(&out, &["--quiet"]));
    assert!(
        quiet.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&quiet.stderr)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn render_off_a_terminal_says_where_the_image_went() {
    let dir = temp_dir("progress-render");
    let file = dir.join("cornell.png");
    let args: Vec<String> = ["render", "--res", "16x16", "--spp", "2", "-o"]
        .map(String::from)
        .into_iter()
        .chain([file.display().to_string()])
        .collect();
    let log = String::from_utf8_lossy(&run(&args).stderr).into_owned();
    assert!(log.starts_with("rendering 16x16, 2 spp"), "{log}");
    assert!(log.contains("  done in "), "{log}");
    assert!(
        log.trim_end()
            .ends_with(&format!("wrote {}", file.display())),
        "{log}"
    );
    assert!(file.is_file());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn on_a_terminal_progress_is_a_bar() {
    let has_script = Command::new("script")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !has_script {
        println!("skipped: `script` (util-linux) is not installed");
        return;
    }
    let dir = temp_dir("progress-pty");
    let out = dir.join("out");
    let command = std::iter::once(env!("CARGO_BIN_EXE_lowdisc").to_string())
        .chain(experiment_args(&out, &[]))
        .collect::<Vec<_>>()
        .join(" ");
    let o = Command::new("script")
        .args(["-qec", &command, "/dev/null"])
        .env("TERM", "xterm")
        .output()
        .expect("script runs");
    let screen = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{screen}");
    // The bar: redrawn in place (carriage returns or cursor escapes), with
    // the percentage, ETA and the whole run's progress and time left.
    assert!(
        screen.contains('\r') || screen.contains("\x1b["),
        "{screen:?}"
    );
    assert!(
        screen.contains("rendering reference: 32x32, 256 spp with sobol-owen"),
        "{screen}"
    );
    assert!(screen.contains("% ") && screen.contains("ETA"), "{screen}");
    assert!(
        screen.contains("; run ") && screen.contains(" left"),
        "{screen}"
    );
    assert!(
        screen.contains("rendering reference: 32x32, 256 spp with sobol-owen done in "),
        "{screen}"
    );
    // No lines of the non-terminal form.
    assert!(!screen.contains(" elapsed, ETA "), "{screen}");
    assert!(screen.contains("estimated run time: "), "{screen}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn paper_claim_off_a_terminal_reports_its_cells() {
    let dir = temp_dir("progress-claim");
    let args: Vec<String> = [
        "paper-claim",
        "--seeds",
        "2",
        "--ns",
        "16,256",
        "--pairs",
        "0..2",
        "-o",
    ]
    .map(String::from)
    .into_iter()
    .chain([dir.join("claim").display().to_string()])
    .collect();
    let log = String::from_utf8_lossy(&run(&args).stderr).into_owned();
    let lines: Vec<&str> = log.lines().collect();
    // 14 samplers x 1 pair x 2 point counts.
    assert_eq!(lines[0], "paper-claim: 28 cells", "{log}");
    assert!(
        lines[1..lines.len() - 1]
            .iter()
            .all(|l| l.contains(" elapsed, ETA ") && l.ends_with("points/s")),
        "{log}"
    );
    assert!(
        lines.len() >= 3 && lines[lines.len() - 1].starts_with("  done in "),
        "{log}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
