//! Robustness: random byte strings, random token soups, truncations and mutations
//! of the real scene files all give `Ok` or `Err`, never a panic; whatever parses
//! also survives the Formatter round trip.

mod common;

use pbrt_format::{Formatter, Recorder, parse_str};

/// xorshift64*: a small deterministic generator (explicit seeds below).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

/// Parses `text` as if it were the file `name`; if it parses, checks the round trip
/// and returns `true`.
fn check(text: &str, name: &str) -> bool {
    let mut rec = Recorder::new();
    if parse_str(text, name, &mut rec).is_err() {
        return false;
    }
    let mut f = Formatter::new();
    parse_str(text, name, &mut f).expect("parsed once, must parse again");
    let printed = f.finish();
    let mut again = Recorder::new();
    match parse_str(&printed, "printed.pbrt", &mut again) {
        Ok(()) => assert!(
            again.calls_only() == rec.calls_only(),
            "round trip changed the calls of {text:?}"
        ),
        Err(e) => panic!("formatter output does not parse ({e}) for input {text:?}"),
    }
    true
}

#[test]
fn random_bytes_never_panic() {
    let mut rng = Rng(0x5eed_0001);
    for _ in 0..3000 {
        let len = rng.below(120);
        let bytes: Vec<u8> = (0..len).map(|_| rng.next() as u8).collect();
        check(&String::from_utf8_lossy(&bytes), "random.pbrt");
    }
}

#[test]
fn random_token_soups_never_panic() {
    const PIECES: &[&str] = &[
        "Shape",
        "\"sphere\"",
        "\"float radius\"",
        "\"integer n\"",
        "\"rgb L\"",
        "\"bool b\"",
        "\"string s\"",
        "\"spectrum k\"",
        "\"texture t\"",
        "\"point3 P\"",
        "[",
        "]",
        "1",
        "-2.5",
        ".5e3",
        "1.2.3",
        "true",
        "false",
        "\"x\"",
        "#c\n",
        "\n",
        " ",
        "\"",
        "\\",
        "AttributeBegin",
        "AttributeEnd",
        "Translate",
        "Transform",
        "LookAt",
        "WorldBegin",
        "WorldEnd",
        "Texture",
        "MediumInterface",
        "ActiveTransform",
        "All",
        "Option",
        "Include",
        "Import",
        "\"no.pbrt\"",
        "Rotate",
        "Material",
        "MakeNamedMaterial",
        "NamedMaterial",
        "ObjectBegin",
        "ObjectEnd",
        "é",
        "\"a\\\"b\"",
        "\"bad\\q\"",
        "99999999999999999999",
        "1e999",
        "nan",
        "-inf",
    ];
    let mut rng = Rng(0x5eed_0002);
    let mut parsed = 0;
    for _ in 0..4000 {
        let n = rng.below(24);
        let mut text = String::new();
        for _ in 0..n {
            text.push_str(PIECES[rng.below(PIECES.len())]);
            if rng.below(3) > 0 {
                text.push(' ');
            }
        }
        parsed += usize::from(check(&text, "soup.pbrt"));
    }
    println!("{parsed} of 4000 token soups parsed");
    assert!(
        parsed >= 100,
        "too few soups parse ({parsed}) to exercise the round trip"
    );
}

#[test]
fn truncated_and_mutated_scene_files_never_panic() {
    let Some(dir) = common::scenes_dir() else {
        return;
    };
    let mut rng = Rng(0x5eed_0003);
    let mut parsed = 0;
    for path in common::pbrt_files(&dir) {
        let bytes = std::fs::read(&path).unwrap();
        let name = path.to_string_lossy().into_owned();
        // Big geometry files get fewer cuts; their structure is repetitive.
        let cuts = if bytes.len() > 100_000 { 12 } else { 60 };
        for _ in 0..cuts {
            let cut = rng.below(bytes.len() + 1);
            parsed += usize::from(check(&String::from_utf8_lossy(&bytes[..cut]), &name));
        }
        for _ in 0..cuts {
            let mut m = bytes.clone();
            for _ in 0..1 + rng.below(4) {
                let i = rng.below(m.len());
                m[i] = b"[]\"#\n 0.-eAz\\"[rng.below(13)];
            }
            parsed += usize::from(check(&String::from_utf8_lossy(&m), &name));
        }
    }
    println!("{parsed} truncated or mutated scene files parsed");
    assert!(
        parsed >= 50,
        "too few variants parse ({parsed}) to exercise the round trip"
    );
}
