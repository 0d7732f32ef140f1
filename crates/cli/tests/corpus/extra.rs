//! The corpus's cases made at run time (mutations of the shared scenes, a
//! 20 MB token), the tiny tmpfs of the full-disk cases, and the writing of
//! recorded expectations back into manifest.json.

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

use super::Case;
use super::run::Fault;

/// Mounts a 64 KiB tmpfs under `root` for the full-disk cases, or `None`
/// where mounting is not permitted (no root, no CAP_SYS_ADMIN).
pub fn mount_tiny_tmpfs(root: &Path) -> Option<PathBuf> {
    let dir = root.join("tiny-tmpfs");
    std::fs::create_dir_all(&dir).ok()?;
    let mounted = Command::new("mount")
        .args(["-t", "tmpfs", "-o", "size=64k", "tmpfs"])
        .arg(&dir)
        .stderr(std::process::Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    mounted.then_some(dir)
}

/// Unmounts the tmpfs of [`mount_tiny_tmpfs`].
pub fn unmount(dir: &Path) {
    let _ = Command::new("umount").arg(dir).status();
}

/// The shared scene folder, `None` when absent; with
/// `LOWDISC_REQUIRE_SCENES=1` an absent folder fails the test.
fn shared_scenes() -> Option<PathBuf> {
    let dir = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../shared/scenes"
    ));
    if dir.is_dir() {
        return Some(dir);
    }
    assert!(
        std::env::var("LOWDISC_REQUIRE_SCENES").as_deref() != Ok("1"),
        "LOWDISC_REQUIRE_SCENES=1 but {} is absent",
        dir.display()
    );
    println!(
        "note: {} is absent; its mutations are skipped",
        dir.display()
    );
    None
}

/// Deterministic mutations of a scene's text: cuts, a stray bracket or
/// quote, a dropped line and a repeated one.
fn mutations(text: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let at = |f: usize| {
        let mut k = text.len() * f / 8;
        while !text.is_char_boundary(k) {
            k -= 1;
        }
        k
    };
    for f in 1..8 {
        out.push((format!("cut-{f}of8"), text[..at(f)].to_string()));
    }
    for (name, stray) in [("quote", "\""), ("open", "["), ("close", "]")] {
        for f in [2, 5] {
            let k = at(f);
            out.push((
                format!("{name}-{f}of8"),
                format!("{}{stray}{}", &text[..k], &text[k..]),
            ));
        }
    }
    let lines: Vec<&str> = text.lines().collect();
    for f in [1, 3, 6] {
        let i = lines.len() * f / 8;
        let mut dropped = lines.clone();
        dropped.remove(i);
        out.push((format!("drop-line-{f}of8"), dropped.join("\n")));
        let mut twice = lines.clone();
        twice.insert(i, lines[i]);
        out.push((format!("twice-line-{f}of8"), twice.join("\n")));
    }
    out
}

fn case(id: String, args: Vec<String>) -> Case {
    Case {
        id,
        args,
        fault: Fault::None,
        old_output: false,
        expect: None,
    }
}

/// The run-time cases, held to the invariants only.
pub fn generated_cases(root: &Path) -> Vec<Case> {
    let gen_dir = root.join("generated");
    std::fs::create_dir_all(&gen_dir).unwrap();
    let mut cases = Vec::new();
    let render = |scene: &Path| -> Vec<String> {
        let s = scene.display().to_string();
        [
            "render", &s, "-q", "-o", "out.exr", "--res", "8x8", "--spp", "1",
        ]
        .map(String::from)
        .to_vec()
    };
    let huge = gen_dir.join("huge-token.pbrt");
    let mut text = "WorldBegin\n".to_string();
    text.push_str(&"x".repeat(20 << 20));
    std::fs::write(&huge, text).unwrap();
    cases.push(case("generated/huge-token".into(), render(&huge)));
    if let Some(scenes) = shared_scenes() {
        for name in ["bitterli-cornell-box", "bitterli-veach-mis"] {
            let Ok(text) = std::fs::read_to_string(scenes.join(name).join("scene-v4.pbrt")) else {
                continue;
            };
            for (m, mutated) in mutations(&text) {
                let file = gen_dir.join(format!("{name}-{m}.pbrt"));
                std::fs::write(&file, mutated).unwrap();
                cases.push(case(format!("shared/{name}/{m}"), render(&file)));
            }
        }
    }
    cases
}

/// Writes the observed expectations into the manifest (record mode).
pub fn write_record(path: &Path, record: &[(String, Value)]) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut manifest: Value = serde_json::from_str(&text).unwrap();
    for c in manifest["cases"].as_array_mut().unwrap() {
        let id = c["id"].as_str().unwrap().to_string();
        if let Some((_, v)) = record.iter().find(|(i, _)| *i == id) {
            c["expect"] = v.clone();
        }
    }
    let cases = manifest["cases"].as_array().unwrap();
    let lines: Vec<String> = cases.iter().map(|c| format!("  {c}")).collect();
    std::fs::write(
        path,
        format!("{{\"cases\": [\n{}\n]}}\n", lines.join(",\n")),
    )
    .unwrap();
}
