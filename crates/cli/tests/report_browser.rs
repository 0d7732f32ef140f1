//! The experiment's report.html in a real browser (headless Chromium): the
//! page opens with the answer to the paper's question, renders to a
//! screenshot, shows no raw Markdown, and every image loads in the browser
//! and is a file that decodes.
//!
//! Without Chromium (`chromium` on the PATH, or the program named by
//! `LOWDISC_CHROMIUM`) the test prints a note and passes, unless
//! `LOWDISC_REQUIRE_BROWSER=1` (set by `.ci/run`), where it fails.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

use common::{lowdisc, temp_dir};

/// The Chromium program, if one runs.
fn chromium() -> Option<PathBuf> {
    let program = std::env::var_os("LOWDISC_CHROMIUM").unwrap_or_else(|| "chromium".into());
    let runs = Command::new(&program)
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    runs.then(|| PathBuf::from(program))
}

/// Runs headless Chromium on `page` with `args` and a fresh profile; returns stdout.
fn headless(program: &Path, profile: &Path, args: &[&str], page: &Path) -> String {
    let out = Command::new(program)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--no-first-run",
            "--allow-file-access-from-files",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(args)
        .arg(format!("file://{}", page.display()))
        .output()
        .expect("chromium runs");
    assert!(
        out.status.success(),
        "chromium failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The `src` of every `<img>` in `html`.
fn image_sources(html: &str) -> Vec<String> {
    html.split("<img")
        .skip(1)
        .filter_map(|tag| {
            let rest = &tag[tag.find("src=\"")? + 5..];
            Some(rest[..rest.find('"')?].to_string())
        })
        .collect()
}

/// The HTML from the page's title to its second `<h2>`: the title and the
/// first section.
fn first_section(html: &str) -> String {
    let start = html.find("<h1>").expect("a title");
    let rest = &html[start..];
    let first = rest.find("<h2>").expect("a first section");
    let end = rest[first + 4..]
        .find("<h2>")
        .map_or(rest.len(), |e| first + 4 + e);
    rest[..end].to_string()
}

/// The text of `html` without its tags.
fn text_of(html: &str) -> String {
    let mut text = String::new();
    let mut in_tag = false;
    for c in html.chars() {
        match c {
            '<' => in_tag = true,
            '>' => in_tag = false,
            c if !in_tag => text.push(c),
            _ => {}
        }
    }
    text
}

#[test]
fn report_renders_in_chromium_with_every_image_and_no_raw_markdown() {
    let Some(program) = chromium() else {
        assert!(
            std::env::var("LOWDISC_REQUIRE_BROWSER").as_deref() != Ok("1"),
            "LOWDISC_REQUIRE_BROWSER=1 but chromium does not run (apt-get install chromium)"
        );
        println!("skipped: chromium is not installed (apt-get install chromium to run this test)");
        return;
    };
    let dir = temp_dir("report-browser");
    let out = dir.join("out");
    let o = lowdisc(&[
        "experiment",
        "--quick",
        "--quiet",
        "--samplers",
        "sobol,paper-repro",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // With --quiet the answer is still printed: the command's only line.
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        stdout.starts_with("answer: the paper's claim (0.92x Sobol's error at 16 spp) is ")
            && stdout.contains(": paper-repro has ")
            && stdout.lines().count() == 1,
        "{stdout}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    assert_eq!(json["answer"]["line"].as_str(), Some(stdout.trim_end()));
    assert_eq!(json["answer"]["paper"]["sampler"], "paper-repro");
    let report = out.join("report.html");

    // The page as the browser built it: no Markdown left over.
    let dom = headless(&program, &dir.join("profile-dom"), &["--dump-dom"], &report);
    assert!(dom.contains("<table>"), "{dom}");
    let text = text_of(&dom);
    for raw in ["`", "|---", "![", "](", "## "] {
        assert!(
            !text.contains(raw),
            "raw Markdown `{raw}` in the page: {text}"
        );
    }

    // The page opens with the answer: the first section after the title,
    // naming the paper, its claim, the verdict and the measured ratio with
    // its interval, before the settings and the tables.
    let answer = first_section(&dom);
    for needed in [
        "<h2>Answer</h2>",
        "Song &amp; Ro 2019",
        "92.0 % of Sobol's error at 16 spp",
        "The claim is ",
        "<code>paper-repro</code> has ",
        "x [",
    ] {
        assert!(
            answer.contains(needed),
            "no `{needed}` in the first section: {answer}"
        );
    }
    let claim = ["reproduced", "not reproduced", "not shown"]
        .iter()
        .any(|v| answer.contains(&format!("The claim is {v} by this run.")));
    assert!(claim, "no verdict in the first section: {answer}");
    assert!(!answer.contains("<table>"), "{answer}");
    let order = |s: &str| dom.find(s).unwrap_or_else(|| panic!("no {s}"));
    assert!(order("<h2>Answer</h2>") < order("<h2>Settings</h2>"));
    assert!(order("<h2>Settings</h2>") < order("<h2>Summary</h2>"));

    // Every image: a file that decodes, and loaded by the browser (a copy
    // of the page with a script that lists the images that did not load).
    let sources = image_sources(&dom);
    assert!(sources.len() >= 8, "{sources:?}");
    for src in &sources {
        let file = out.join(src);
        let image = lowdisc_image::read_image(&file)
            .unwrap_or_else(|e| panic!("{} does not decode: {e}", file.display()));
        assert!(image.width() > 0 && image.height() > 0);
    }
    let probe = out.join("probe.html");
    let script = "<script>addEventListener('load', () => { const bad = [...document.images]\
        .filter(i => !i.complete || i.naturalWidth === 0).map(i => i.getAttribute('src'));\
        document.body.setAttribute('data-images', document.images.length);\
        document.body.setAttribute('data-broken', bad.join(' ') || 'none'); });</script>";
    let page = std::fs::read_to_string(&report).unwrap();
    std::fs::write(&probe, page.replace("</body>", &format!("{script}</body>"))).unwrap();
    let probed = headless(
        &program,
        &dir.join("profile-probe"),
        &["--virtual-time-budget=10000", "--dump-dom"],
        &probe,
    );
    assert!(
        probed.contains(&format!("data-images=\"{}\"", sources.len())),
        "{probed}"
    );
    assert!(probed.contains("data-broken=\"none\""), "{probed}");

    // A screenshot of the page: a PNG of the window's size, not blank.
    let shot = dir.join("shot.png");
    headless(
        &program,
        &dir.join("profile-shot"),
        &[
            "--window-size=1280,2400",
            &format!("--screenshot={}", shot.display()),
        ],
        &report,
    );
    let shot = lowdisc_image::read_image(&shot).expect("the screenshot decodes");
    assert_eq!((shot.width(), shot.height()), (1280, 2400));
    let first = shot.pixels()[0];
    assert!(
        shot.pixels().iter().any(|p| p != &first),
        "blank screenshot"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
