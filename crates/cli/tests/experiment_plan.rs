//! End-to-end tests of the experiment cut into units (`lowdisc experiment
//! plan|unit|merge|status`) on tiny settings: the planned and merged run
//! gives the one-machine run's `results.json` bit for bit (times aside) and
//! the same images; units are idempotent, survive a failure and a stale
//! lock, and the merge refuses missing and foreign units.

mod common;

use std::path::{Path, PathBuf};
use std::process::Output;

use common::{lowdisc, temp_dir};

/// The tiny experiment: 32x24, 4 spp, 2 runs of 2 samplers, a 64-spp
/// reference, and convergence to 8 spp at 32x24 with 2 seeds against its
/// own 32-spp reference, in units of at most 4096 camera samples: the references are
/// cut into bands and sample ranges, the 8-spp convergence points into bands.
const SETTINGS: [&str; 13] = [
    "--quick",
    "--res",
    "32x24",
    "--samplers",
    "sobol,paper-repro",
    "--conv-max",
    "8",
    "--conv-res",
    "32x24",
    "--conv-ref-spp",
    "32",
    "--unit-samples",
    "4096",
];
/// 2 bands x 8 ranges of the reference + 2 x 2 runs + 7 x 2 sweep renders +
/// 2 bands x 4 ranges of the convergence reference + 2 samplers x 2 seeds x
/// (3 whole points + 2 bands of the 8-spp point).
const UNITS: usize = 62;
/// The first run's unit.
const FIRST_RUN: usize = 16;

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn ok(o: &Output) -> String {
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "lowdisc failed: {stderr}");
    String::from_utf8_lossy(&o.stdout).to_string()
}

/// The one-line error of a failed command.
fn error_of(o: &Output) -> String {
    assert_eq!(o.status.code(), Some(1), "{o:?}");
    let stderr = String::from_utf8_lossy(&o.stderr).to_string();
    assert!(stderr.starts_with("error: "), "{stderr}");
    assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    stderr
}

fn plan(out: &Path, extra: &[&str]) -> String {
    let mut args = vec!["experiment", "plan", "--quiet", "--out", s(out)];
    args.extend(SETTINGS);
    args.extend(extra);
    ok(&lowdisc(&args))
}

fn unit(out: &Path, index: usize) -> Output {
    lowdisc(&[
        "experiment",
        "unit",
        s(out),
        "--index",
        &index.to_string(),
        "--quiet",
    ])
}

fn status(out: &Path) -> String {
    ok(&lowdisc(&["experiment", "status", s(out)]))
}

fn merge(out: &Path) -> Output {
    lowdisc(&["experiment", "merge", "--quiet", s(out)])
}

/// `results.json` without what may differ between two runs of the same
/// experiment: times, the command line, the commit, and the folder of the
/// reference cache.
fn comparable(out: &Path) -> serde_json::Value {
    fn strip(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Object(m) => {
                for k in ["time_s", "wall_time_s", "command", "git_hash"] {
                    m.remove(k);
                }
                m.values_mut().for_each(strip);
            }
            serde_json::Value::Array(a) => a.iter_mut().for_each(strip),
            serde_json::Value::String(t) => {
                if let Some(i) = t.find("lowdisc-ref-cache") {
                    *t = t[i..].to_string();
                }
            }
            _ => {}
        }
    }
    let text = std::fs::read_to_string(out.join("results.json")).unwrap();
    let mut v = serde_json::from_str(&text).unwrap();
    strip(&mut v);
    v
}

fn unit_file(out: &Path, index: usize, ext: &str) -> PathBuf {
    out.join("units").join(format!("{index:04}.{ext}"))
}

#[test]
fn planned_and_merged_equals_the_one_machine_run() {
    let dir = temp_dir("plan-equal");
    let single = dir.join("single").join("out");
    let planned = dir.join("planned").join("out");
    let mut args = vec!["experiment", "--quiet", "--out", s(&single)];
    args.extend(SETTINGS);
    ok(&lowdisc(&args));

    let printed = plan(&planned, &[]);
    // The plan cuts both references in bands and sample ranges, and the
    // last convergence points in bands.
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(planned.join("plan.json")).unwrap()).unwrap();
    let units = doc["units"].as_array().unwrap();
    let cut_of = |i: usize| {
        let u = &units[i];
        (
            u["kind"].as_str().unwrap(),
            u["bands"].clone(),
            u["ranges"].clone(),
        )
    };
    assert_eq!(cut_of(0), ("reference", 2.into(), 8.into()));
    assert_eq!(cut_of(FIRST_RUN).0, "run");
    assert_eq!(cut_of(34), ("reference", 2.into(), 4.into()));
    assert_eq!(cut_of(UNITS - 1).0, "convergence");
    assert_eq!(cut_of(UNITS - 1).1, 2);
    assert!(
        printed.contains(&format!("{UNITS} units (indices 0 to 61)")),
        "{printed}"
    );
    // The same plan again is kept; a different one is refused.
    plan(&planned, &[]);
    let mut other = vec!["experiment", "plan", "--out", s(&planned)];
    other.extend(SETTINGS);
    other.extend(["--spp", "2"]);
    let err = error_of(&lowdisc(&other));
    assert!(err.contains("holds another plan"), "{err}");
    let mut tiny = vec!["experiment", "plan", "--out", s(&planned)];
    tiny.extend(&SETTINGS[..11]);
    tiny.extend(["--unit-samples", "1000"]);
    let err = error_of(&lowdisc(&tiny));
    assert!(
        err.contains("--unit-samples must be at least 1024, got 1000"),
        "{err}"
    );
    assert!(status(&planned).contains(&format!(
        "0 done, 0 running, 0 stale, 0 failed, {UNITS} pending"
    )));
    // Before every unit is done the merge refuses, naming what is missing.
    ok(&unit(&planned, 0));
    let err = error_of(&merge(&planned));
    assert!(
        err.contains("61 of the plan's 62 units are not done (units 1, 2,"),
        "{err}"
    );
    // In reverse order: any order gives the same result.
    for i in (1..UNITS).rev() {
        ok(&unit(&planned, i));
    }
    let st = status(&planned);
    assert!(st.contains(&format!("{UNITS} done")), "{st}");
    assert!(st.contains("all units done"), "{st}");
    ok(&merge(&planned));

    assert_eq!(comparable(&planned), comparable(&single));
    for f in [
        "reference.exr",
        "sobol.exr",
        "paper-repro.exr",
        "sobol.png",
        "sobol_relse.png",
    ] {
        let a = std::fs::read(single.join(f)).unwrap();
        let b = std::fs::read(planned.join(f)).unwrap();
        assert!(a == b, "{f} differs");
    }
    // Both references went to the planned folder's cache.
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(planned.join("results.json")).unwrap())
            .unwrap();
    for key in ["reference", "convergence_reference"] {
        assert_eq!(json[key]["cached"], false);
        assert!(Path::new(json[key]["file"].as_str().unwrap()).is_file());
    }
    // Merging again gives the same results.
    ok(&merge(&planned));
    assert_eq!(comparable(&planned), comparable(&single));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn units_are_idempotent_and_survive_failures() {
    let dir = temp_dir("plan-units");
    let out = dir.join("out");
    // A uniform grey sky, 8x4 lat-long, whose change makes units fail.
    let sky = dir.join("sky.pfm");
    let grey = lowdisc_image::RgbImage::filled(8, 4, [0.5; 3]).unwrap();
    lowdisc_image::write_pfm(&sky, &grey).unwrap();
    plan(&out, &["--envmap", s(&sky)]);

    // Index out of range.
    let err = error_of(&unit(&out, UNITS));
    assert!(
        err.contains("unit index 62 is out of range: the plan has 62 units (0 to 61)"),
        "{err}"
    );

    // A second run of a done unit changes nothing.
    let (sobol_1, paper_0, paper_1) = (FIRST_RUN + 1, FIRST_RUN + 2, FIRST_RUN + 3);
    let first = ok(&unit(&out, sobol_1));
    assert!(
        first.contains(&format!("unit {sobol_1} (run sobol seed 1): done in")),
        "{first}"
    );
    let record = std::fs::read(unit_file(&out, sobol_1, "json")).unwrap();
    let again = ok(&unit(&out, sobol_1));
    assert!(again.contains("already done"), "{again}");
    assert_eq!(
        std::fs::read(unit_file(&out, sobol_1, "json")).unwrap(),
        record
    );

    // The sky changes: the unit fails, says why, keeps no lock.
    let bright = lowdisc_image::RgbImage::filled(8, 4, [0.7; 3]).unwrap();
    lowdisc_image::write_pfm(&sky, &bright).unwrap();
    let err = error_of(&unit(&out, paper_0));
    assert!(err.contains("changed since the plan was made"), "{err}");
    assert!(unit_file(&out, paper_0, "failed").is_file());
    assert!(!unit_file(&out, paper_0, "lock").exists());
    assert!(!unit_file(&out, paper_0, "json").exists());
    let st = status(&out);
    assert!(
        st.contains("1 done, 0 running, 0 stale, 1 failed, 60 pending"),
        "{st}"
    );
    assert!(
        st.contains(&format!(
            "failed: unit {paper_0} (run paper-repro seed 0): the scene"
        )),
        "{st}"
    );
    assert!(st.contains("ETA: "), "{st}");
    // Restored, the rerun succeeds and clears the failure.
    lowdisc_image::write_pfm(&sky, &grey).unwrap();
    ok(&unit(&out, paper_0));
    assert!(!unit_file(&out, paper_0, "failed").exists());

    // A live lock (this test's process) is running and refused; a dead
    // process's lock is stale and taken over.
    let host = std::fs::read_to_string("/proc/sys/kernel/hostname").unwrap();
    let lock = |pid: u32| {
        let text = format!(
            "{{\"pid\":{pid},\"host\":\"{}\",\"start_unix_s\":0}}",
            host.trim()
        );
        std::fs::write(unit_file(&out, paper_1, "lock"), text).unwrap();
    };
    lock(std::process::id());
    let st = status(&out);
    assert!(
        st.contains(&format!(
            "running: unit {paper_1} (run paper-repro seed 1): pid {}",
            std::process::id()
        )),
        "{st}"
    );
    let err = error_of(&unit(&out, paper_1));
    assert!(err.contains("is being run by pid"), "{err}");
    let mut child = std::process::Command::new("true").spawn().unwrap();
    let dead = child.id();
    child.wait().unwrap();
    lock(dead);
    let st = status(&out);
    assert!(
        st.contains(&format!(
            "stale: unit {paper_1} (run paper-repro seed 1): pid {dead} on"
        )),
        "{st}"
    );
    ok(&unit(&out, paper_1));
    assert!(!unit_file(&out, paper_1, "lock").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_merge_refuses_foreign_and_broken_units() {
    let dir = temp_dir("plan-foreign");
    let (a, b) = (dir.join("a"), dir.join("b"));
    plan(&a, &[]);
    plan(&b, &["--spp", "2"]);
    for i in 0..UNITS {
        ok(&unit(&a, i));
    }
    ok(&unit(&b, 1));
    // Unit 1 (a piece of the reference) of another plan in place of this
    // plan's.
    for ext in ["json", "exr"] {
        std::fs::copy(unit_file(&b, 1, ext), unit_file(&a, 1, ext)).unwrap();
    }
    let err = error_of(&merge(&a));
    assert!(err.contains("0001.json` is unit 1 of plan"), "{err}");
    assert!(err.contains("not unit 1 of this plan"), "{err}");
    // The unit command redoes it.
    ok(&unit(&a, 1));
    // Files that do not match their records: a piece's sums, a run's image.
    for (i, ext) in [(2, "exr"), (FIRST_RUN, "pfm")] {
        let file = unit_file(&a, i, ext);
        let mut bytes = std::fs::read(&file).unwrap();
        let last = bytes.len() - 1;
        bytes[last] ^= 1;
        std::fs::write(&file, bytes).unwrap();
        let err = error_of(&merge(&a));
        assert!(err.contains("does not match its record"), "{err}");
        ok(&unit(&a, i));
    }
    // A missing unit.
    std::fs::remove_file(unit_file(&a, 7, "json")).unwrap();
    let err = error_of(&merge(&a));
    assert!(
        err.contains("1 of the plan's 62 units are not done (units 7)"),
        "{err}"
    );
    ok(&unit(&a, 7));
    ok(&merge(&a));
    // No plan at all.
    let err = error_of(&lowdisc(&["experiment", "status", s(&dir.join("none"))]));
    assert!(err.contains("cannot read the plan"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
