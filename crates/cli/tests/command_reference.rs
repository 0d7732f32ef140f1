//! The book's command reference (`docs/reference/commands.md` and one page
//! per command under `docs/reference/commands/`) is the `--help` of the
//! real binary: this test regenerates every page in memory and fails when
//! a committed page differs, is missing, is left over from a command that
//! is gone, or is not listed in `docs/SUMMARY.md`. With
//! `LOWDISC_DOCS_UPDATE=1` it writes the pages instead.

mod common;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use common::stdout_of;

const REGENERATE: &str = "LOWDISC_DOCS_UPDATE=1 cargo test -p lowdisc-cli --test command_reference";

/// The repository's `docs/` folder.
fn docs() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs")
}

/// The subcommands listed under `Commands:` in `help`, without `help`.
fn commands(help: &str) -> Vec<(String, String)> {
    help.lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| {
            let l = l.trim_start();
            let (name, about) = l.split_once(' ').unwrap_or((l, ""));
            (name != "help").then(|| (name.to_string(), about.trim().to_string()))
        })
        .collect()
}

fn note(args: &str) -> String {
    let command = if args.is_empty() {
        "lowdisc".to_string()
    } else {
        format!("lowdisc {args}")
    };
    format!(
        "<!-- Generated from `{command} --help` by crates/cli/tests/command_reference.rs; \
do not edit. Regenerate with `{REGENERATE}`. -->\n"
    )
}

fn help_block(help: &str) -> String {
    format!("```text\n{}\n```\n", help.trim_end())
}

/// The page of `command` (with a section per subcommand, if it has any).
fn command_page(command: &str) -> String {
    let help = stdout_of(&[command, "--help"]);
    let mut page = format!(
        "# lowdisc {command}\n\n{}\n{}",
        note(command),
        help_block(&help)
    );
    for (sub, about) in commands(&help) {
        let sub_help = stdout_of(&[command, &sub, "--help"]);
        page.push_str(&format!(
            "\n## lowdisc {command} {sub}\n\n{about}\n\n{}",
            help_block(&sub_help)
        ));
    }
    page
}

/// Every generated page, by its path under `docs/reference/`.
fn pages() -> BTreeMap<String, String> {
    let help = stdout_of(&["--help"]);
    let list = commands(&help);
    assert!(
        list.len() >= 5,
        "no command list in `lowdisc --help`: {help}"
    );
    let mut index = format!(
        "# Command reference\n\n{}\n\
`lowdisc` is one binary with one subcommand per task; `lowdisc <command> --help` prints the \
page of that command. Build it with `cargo build --release -p lowdisc-cli` (it is then \
`target/release/lowdisc`). Output files go through a temporary file and a rename; bad input \
gives a one-line `error:` and a non-zero exit.\n\n{}\n| command | what it does |\n|---|---|\n",
        note(""),
        help_block(&help)
    );
    let mut pages = BTreeMap::new();
    for (name, about) in &list {
        index.push_str(&format!("| [`{name}`](commands/{name}.md) | {about} |\n"));
        pages.insert(format!("commands/{name}.md"), command_page(name));
    }
    pages.insert("commands.md".to_string(), index);
    pages
}

#[test]
fn the_command_reference_is_the_binarys_help() {
    let reference = docs().join("reference");
    let pages = pages();
    let update = std::env::var("LOWDISC_DOCS_UPDATE").as_deref() == Ok("1");
    let generated_dir = reference.join("commands");
    if update {
        std::fs::create_dir_all(&generated_dir).unwrap();
        for entry in std::fs::read_dir(&generated_dir).unwrap() {
            let path = entry.unwrap().path();
            let key = format!("commands/{}", path.file_name().unwrap().to_string_lossy());
            if !pages.contains_key(&key) {
                std::fs::remove_file(&path).unwrap();
            }
        }
        for (path, text) in &pages {
            std::fs::write(reference.join(path), text).unwrap();
        }
    }
    let mut problems = Vec::new();
    for (path, text) in &pages {
        match std::fs::read_to_string(reference.join(path)) {
            Ok(committed) if &committed == text => {}
            Ok(_) => problems.push(format!("docs/reference/{path} is stale")),
            Err(_) => problems.push(format!("docs/reference/{path} is missing")),
        }
    }
    for entry in std::fs::read_dir(&generated_dir).into_iter().flatten() {
        let name = entry.unwrap().file_name().to_string_lossy().into_owned();
        if !pages.contains_key(&format!("commands/{name}")) {
            problems.push(format!(
                "docs/reference/commands/{name} documents no command"
            ));
        }
    }
    let summary = std::fs::read_to_string(docs().join("SUMMARY.md")).unwrap();
    for path in pages.keys() {
        if !summary.contains(&format!("(reference/{path})")) {
            problems.push(format!("docs/SUMMARY.md does not list reference/{path}"));
        }
    }
    assert!(
        problems.is_empty(),
        "{}\nregenerate with `{REGENERATE}` (and list new pages in docs/SUMMARY.md)",
        problems.join("\n")
    );
}

#[test]
fn the_command_list_is_read_from_the_help() {
    let help = "Usage: x\n\nCommands:\n  points  Print points\n  render  Path-trace\n  help    Print this\n\nOptions:\n  -h\n";
    assert_eq!(
        commands(help),
        vec![
            ("points".to_string(), "Print points".to_string()),
            ("render".to_string(), "Path-trace".to_string())
        ]
    );
}
