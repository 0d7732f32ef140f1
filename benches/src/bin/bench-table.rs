//! Prints the README's benchmark tables from criterion's saved results.
//!
//! Usage: `cargo run -p lowdisc-benches --bin bench-table [CRITERION_DIR]`
//! after `cargo bench -p lowdisc-benches`. `CRITERION_DIR` defaults to
//! `$CARGO_TARGET_DIR/criterion`, else `target/criterion`.

use std::path::PathBuf;
use std::process::ExitCode;

use lowdisc_benches::report::{batch_table, sample_table};

fn main() -> ExitCode {
    let dir = std::env::args_os()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            std::env::var_os("CARGO_TARGET_DIR")
                .map(PathBuf::from)
                .unwrap_or_else(|| PathBuf::from("target"))
                .join("criterion")
        });
    let tables = sample_table(&dir).and_then(|s| Ok((s, batch_table(&dir)?)));
    match tables {
        Ok((samples, batch)) => {
            println!("{samples}\n{batch}");
            if let Some(name) = cpu_model() {
                println!("Machine: {name}, {} logical CPUs.", cpu_count());
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("bench-table: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The CPU model name from `/proc/cpuinfo` (Linux), if any.
fn cpu_model() -> Option<String> {
    let info = std::fs::read_to_string("/proc/cpuinfo").ok()?;
    let line = info.lines().find(|l| l.starts_with("model name"))?;
    Some(line.split(':').nth(1)?.trim().to_string())
}

/// Logical CPUs available to this process.
fn cpu_count() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}
