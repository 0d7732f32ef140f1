//! Prints a pbrt-v4 scene file (with its includes inlined) in canonical form, or
//! its first error: `cargo run -p pbrt-format --example pbrt-fmt -- scene.pbrt`.
//! With `--check`, only parses and prints the number of directives, parameter
//! values and warnings and the time taken.

use std::process::ExitCode;
use std::time::Instant;

use pbrt_format::{Formatter, Recorder, parse_file};

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let check = args.iter().any(|a| a == "--check");
    let Some(path) = args.iter().find(|a| !a.starts_with("--")) else {
        eprintln!("usage: pbrt-fmt [--check] SCENE.pbrt");
        return ExitCode::from(2);
    };
    let result = if check {
        let start = Instant::now();
        let mut rec = Recorder::new();
        parse_file(path, &mut rec).map(|()| {
            let secs = start.elapsed().as_secs_f64();
            println!(
                "{path}: {} directives, {} files, {} warnings, parsed in {:.2} ms",
                rec.calls.len(),
                rec.files.iter().filter(|f| f.2).count(),
                rec.warnings.len(),
                secs * 1e3
            );
        })
    } else {
        let mut f = Formatter::new();
        parse_file(path, &mut f).map(|()| print!("{}", f.finish()))
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
