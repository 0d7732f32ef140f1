//! The bad-input and fault corpus (tests/corpus/): every case of
//! manifest.json runs against the real binary under an address-space cap and
//! a timeout, and must end as recorded: no panic, no signal death, no hang,
//! the recorded exit class, the recorded files and no temporary file left,
//! and an old output kept whenever the run failed. Mutations of the shared
//! scenes (when present) and a 20 MB token, made at run time, add cases
//! held to the same invariants.
//!
//! Regenerate the fixtures with `python3 crates/cli/tests/corpus/generate.py`;
//! record expectations with `LOWDISC_CORPUS_RECORD=1` (then review the diff).

#[path = "corpus/run.rs"]
mod run;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use run::{Fault, Outcome, case_dir, classify, run};
use serde_json::{Value, json};

const OLD: &[u8] = b"OLD IMAGE";
const EXR_MAGIC: &[u8] = &[0x76, 0x2f, 0x31, 0x01];

fn corpus_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/corpus")
}

/// One case ready to run.
struct Case {
    id: String,
    args: Vec<String>,
    fault: Fault,
    old_output: bool,
    expect: Option<Value>,
}

fn load_cases(fixtures: &Path, tmpfs: Option<&Path>) -> (Vec<Case>, usize) {
    let text = std::fs::read_to_string(corpus_dir().join("manifest.json")).expect("manifest");
    let manifest: Value = serde_json::from_str(&text).expect("manifest is JSON");
    let mut skipped = 0;
    let mut cases = Vec::new();
    for c in manifest["cases"].as_array().expect("cases") {
        let fault = Fault::parse(c["fault"].as_str().expect("fault"));
        if fault == Fault::TmpfsFull && tmpfs.is_none() {
            skipped += 1;
            continue;
        }
        let tmp = tmpfs.map(|p| p.display().to_string()).unwrap_or_default();
        let args = c["args"]
            .as_array()
            .expect("args")
            .iter()
            .map(|a| {
                let a = a.as_str().expect("arg");
                a.replace("{F}", &fixtures.display().to_string())
                    .replace("{TMPFS}", &tmp)
            })
            .collect();
        cases.push(Case {
            id: c["id"].as_str().expect("id").to_string(),
            args,
            fault,
            old_output: c["old_output"].as_bool().unwrap_or(false),
            expect: c.get("expect").cloned(),
        });
    }
    (cases, skipped)
}

/// The invariants every case obeys, whatever it expects.
fn invariants(case: &Case, o: &Outcome, dir: &Path) -> Vec<String> {
    let mut bad = Vec::new();
    if o.hung {
        bad.push("ran past the timeout".to_string());
    }
    if let Some(sig) = o.signal {
        bad.push(format!("killed by signal {sig}"));
    }
    if o.code == Some(101) || o.stderr.contains("panicked") {
        bad.push(format!("panicked: {}", o.stderr.trim()));
    }
    if o.stderr.contains("memory allocation") {
        bad.push("ran out of memory".to_string());
    }
    if o.stderr.lines().any(|l| l.len() > 2000) {
        bad.push("an error line longer than 2000 bytes".to_string());
    }
    if let Some(t) = o.files.iter().find(|f| f.ends_with(".tmp")) {
        bad.push(format!("left the temporary file {t}"));
    }
    if case.old_output {
        let now = std::fs::read(dir.join("out.exr")).unwrap_or_default();
        let kept = now == OLD;
        if o.code != Some(0) && !kept {
            bad.push("destroyed the old output of a failed run".to_string());
        }
        if !kept && !now.starts_with(EXR_MAGIC) {
            bad.push("replaced the old output by an incomplete file".to_string());
        }
    }
    bad
}

fn observed(o: &Outcome) -> Value {
    json!({ "class": classify(o), "files": o.files })
}

/// Checks `o` against the recorded expectation (signal cases: timing decides
/// whether the signal or the end came first, so either is accepted).
fn expectation(case: &Case, o: &Outcome) -> Option<String> {
    let class = classify(o);
    if let Fault::Signal(..) = case.fault {
        let fine = ["ok", "sigint", "sigterm"].contains(&class.as_str());
        return (!fine).then(|| format!("class {class} after a signal"));
    }
    let expect = case.expect.as_ref()?;
    let want = observed(o);
    (expect != &want).then(|| format!("expected {expect}, got {want}; stderr: {}", o.stderr.trim()))
}

fn run_all(cases: &[Case], root: &Path, prlimit: bool) -> Vec<(usize, Outcome, Vec<String>)> {
    let next = AtomicUsize::new(0);
    let results = Mutex::new(Vec::new());
    std::thread::scope(|s| {
        for _ in 0..2 {
            s.spawn(|| {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(case) = cases.get(i) else { break };
                    let dir = case_dir(root, &case.id);
                    if case.old_output {
                        std::fs::write(dir.join("out.exr"), OLD).unwrap();
                    }
                    let o = run(&case.args, &dir, case.fault, prlimit);
                    let mut bad = invariants(case, &o, &dir);
                    bad.extend(expectation(case, &o));
                    results.lock().unwrap().push((i, o, bad));
                }
            });
        }
    });
    let mut results = results.into_inner().unwrap();
    results.sort_by_key(|r| r.0);
    results
}

#[path = "corpus/extra.rs"]
mod extra;

#[test]
fn every_corpus_case_ends_as_recorded_without_panic_hang_or_leftover() {
    let fixtures = corpus_dir().join("files");
    let root = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("corpus");
    let _ = std::fs::remove_dir_all(&root);
    std::fs::create_dir_all(&root).unwrap();
    let prlimit = run::have_prlimit();
    if !prlimit {
        println!("note: prlimit is unavailable; cases run without an address-space cap");
    }
    let tmpfs = extra::mount_tiny_tmpfs(&root);
    let (mut cases, skipped) = load_cases(&fixtures, tmpfs.as_deref());
    if skipped > 0 {
        println!("note: {skipped} full-disk cases skipped: a tmpfs cannot be mounted here");
    }
    let recorded = cases.len();
    cases.extend(extra::generated_cases(&root));
    let results = run_all(&cases, &root, prlimit);
    let mut failures = Vec::new();
    if let Some(t) = &tmpfs {
        let left = run::files_in(t);
        if let Some(f) = left.iter().find(|f| f.ends_with(".tmp")) {
            failures.push(format!("fault/tmpfs-full: left the temporary file {f}"));
        }
        extra::unmount(t);
    }
    let mut classes: BTreeMap<String, usize> = BTreeMap::new();
    let mut record = Vec::new();
    for (i, o, bad) in &results {
        let case = &cases[*i];
        *classes.entry(classify(o)).or_default() += 1;
        if *i < recorded {
            record.push((case.id.clone(), observed(o)));
        }
        let bad: Vec<&String> = if std::env::var_os("LOWDISC_CORPUS_RECORD").is_some() {
            bad.iter().filter(|b| !b.starts_with("expected")).collect()
        } else {
            bad.iter().collect()
        };
        for b in bad {
            failures.push(format!("{}: {b}", case.id));
        }
    }
    println!(
        "{} cases ({recorded} recorded), outcomes: {classes:?}",
        cases.len()
    );
    if std::env::var_os("LOWDISC_CORPUS_RECORD").is_some() {
        extra::write_record(&corpus_dir().join("manifest.json"), &record);
    }
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
    assert!(
        cases.len() >= 300,
        "the corpus has only {} cases",
        cases.len()
    );
}
