//! `Include` and `Import`: relative paths, order of calls, locations inside included
//! files, and errors that name the including file and line.

mod common;

use std::fs;
use std::path::Path;

use pbrt_format::{Directive, ErrorKind, FileKind, Recorder, parse_file, parse_str};

fn write(dir: &Path, name: &str, text: &str) {
    let path = dir.join(name);
    fs::create_dir_all(path.parent().unwrap()).unwrap();
    fs::write(path, text).unwrap();
}

fn named(rec: &Recorder) -> Vec<(String, String, u32)> {
    rec.calls
        .iter()
        .filter_map(|(c, loc)| match c {
            Directive::NamedMaterial(n) => {
                let file = Path::new(&*loc.file).file_name().unwrap();
                Some((n.clone(), file.to_string_lossy().into_owned(), loc.line))
            }
            _ => None,
        })
        .collect()
}

#[test]
fn include_is_textual_and_relative_to_the_including_file() {
    let dir = common::scratch_dir("relative");
    write(
        &dir,
        "main.pbrt",
        "NamedMaterial \"m0\"\nInclude \"sub/a.pbrt\"\nNamedMaterial \"m3\"\n",
    );
    // b.pbrt sits next to a.pbrt; sub/c.pbrt is named relative to the main file
    // (as pbrt-v4 resolves it).
    write(
        &dir,
        "sub/a.pbrt",
        "\n  NamedMaterial \"m1\"\nInclude \"b.pbrt\" Include \"sub/c.pbrt\"\n",
    );
    write(&dir, "sub/b.pbrt", "NamedMaterial \"m2\"");
    write(&dir, "sub/c.pbrt", "\n\nNamedMaterial \"m2c\"");
    let mut rec = Recorder::new();
    parse_file(dir.join("main.pbrt"), &mut rec).unwrap();
    assert_eq!(
        named(&rec),
        [
            ("m0".into(), "main.pbrt".into(), 1),
            ("m1".into(), "a.pbrt".into(), 2),
            ("m2".into(), "b.pbrt".into(), 1),
            ("m2c".into(), "c.pbrt".into(), 3),
            ("m3".into(), "main.pbrt".into(), 3),
        ]
    );
    let kinds: Vec<(FileKind, bool)> = rec.files.iter().map(|f| (f.1, f.2)).collect();
    use FileKind::{Include as I, Main as M};
    let want = [
        (M, true),
        (I, true),
        (I, true),
        (I, false),
        (I, true),
        (I, false),
        (I, false),
    ];
    assert_eq!(kinds, [&want[..], &[(M, false)]].concat());
    // The column of an included call is in its own file.
    let m1 = rec
        .calls
        .iter()
        .find(|(c, _)| *c == Directive::NamedMaterial("m1".into()))
        .unwrap();
    assert_eq!(m1.1.column, 3);
}

#[test]
fn parse_str_resolves_includes_against_its_name() {
    let dir = common::scratch_dir("named");
    write(&dir, "geo.pbrt", "Shape \"sphere\"");
    let name = dir.join("virtual.pbrt");
    let mut rec = Recorder::new();
    parse_str("Import \"geo.pbrt\"", &name.to_string_lossy(), &mut rec).unwrap();
    assert_eq!(rec.calls.len(), 1);
    assert_eq!(rec.files[1].1, FileKind::Import);
}

#[test]
fn missing_include_names_the_including_file_and_line() {
    let dir = common::scratch_dir("missing");
    write(
        &dir,
        "main.pbrt",
        "WorldBegin\nAttributeBegin\n  Include \"nothere.pbrt\"\n",
    );
    let main = dir.join("main.pbrt");
    let e = parse_file(&main, &mut Recorder::new()).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Io);
    let loc = e.loc.clone().unwrap();
    assert_eq!(
        (&*loc.file, loc.line, loc.column),
        (&*main.to_string_lossy(), 3, 3)
    );
    assert!(e.message.contains("\"nothere.pbrt\""), "{e}");
    assert!(
        e.to_string()
            .starts_with(&format!("{}:3:3: ", main.display())),
        "{e}"
    );
}

#[test]
fn errors_inside_an_included_file_are_located_there() {
    let dir = common::scratch_dir("inner-error");
    write(&dir, "main.pbrt", "Include \"inner.pbrt\"\n");
    write(
        &dir,
        "inner.pbrt",
        "Shape \"x\"\n    \"rgb c\" [ 1 2 oops ]\n",
    );
    let e = parse_file(dir.join("main.pbrt"), &mut Recorder::new()).unwrap_err();
    assert_eq!(e.kind, ErrorKind::WrongValueType);
    let loc = e.loc.unwrap();
    assert!(loc.file.ends_with("inner.pbrt"));
    assert_eq!((loc.line, loc.column), (2, 19));
}

#[test]
fn a_file_including_itself_is_an_error_not_a_hang() {
    let dir = common::scratch_dir("cycle");
    write(&dir, "a.pbrt", "Include \"b.pbrt\"\n");
    write(&dir, "b.pbrt", "\nInclude \"a.pbrt\"\n");
    let e = parse_file(dir.join("a.pbrt"), &mut Recorder::new()).unwrap_err();
    assert_eq!(e.kind, ErrorKind::IncludeDepth);
    assert!(e.loc.is_some());
}

#[test]
fn a_directive_cannot_continue_past_the_end_of_an_included_file() {
    let dir = common::scratch_dir("boundary");
    write(
        &dir,
        "main.pbrt",
        "Include \"part.pbrt\" \"float radius\" 1\n",
    );
    write(&dir, "part.pbrt", "Shape \"sphere\"\n");
    let e = parse_file(dir.join("main.pbrt"), &mut Recorder::new()).unwrap_err();
    assert_eq!(e.kind, ErrorKind::UnexpectedToken);
    let loc = e.loc.unwrap();
    assert!(loc.file.ends_with("main.pbrt"));
    assert_eq!((loc.line, loc.column), (1, 21));
}
