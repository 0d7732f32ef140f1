//! Helpers shared by the integration tests: run the real `lowdisc` binary.

#![allow(dead_code)]

use std::process::{Command, Output};

/// Runs `lowdisc` with `args` and returns its output.
pub fn lowdisc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_lowdisc"))
        .args(args)
        .output()
        .expect("the lowdisc binary runs")
}

/// Runs `lowdisc`, asserts success, returns stdout.
pub fn stdout_of(args: &[&str]) -> String {
    let out = lowdisc(args);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "lowdisc {args:?} failed: {stderr}");
    String::from_utf8(out.stdout).expect("output is UTF-8")
}

/// Parses whitespace-separated rows of numbers.
pub fn rows<T: std::str::FromStr>(text: &str) -> Vec<Vec<T>>
where
    T::Err: std::fmt::Debug,
{
    text.lines()
        .map(|l| {
            l.split_whitespace()
                .map(|v| v.parse().expect("a number"))
                .collect()
        })
        .collect()
}

/// A fresh empty directory for a test's files.
pub fn temp_dir(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("lowdisc-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
