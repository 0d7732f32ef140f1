//! Syntax errors have the right kind and file:line:column; a target's error stops
//! the parse.

use pbrt_format::{
    Directive, ErrorKind, Loc, ParseError, ParserTarget, Recorder, TargetResult, parse_str,
};

fn error(text: &str) -> ParseError {
    match parse_str(text, "e.pbrt", &mut Recorder::new()) {
        Ok(()) => panic!("expected an error for {text:?}"),
        Err(e) => e,
    }
}

/// (input, kind, line, column, a word the message must contain)
const CASES: &[(&str, ErrorKind, u32, u32, &str)] = &[
    (
        "Shape \"sphere\n",
        ErrorKind::UnterminatedString,
        1,
        7,
        "unterminated",
    ),
    (
        "Shape \"x\" \"string s\" \"bad\\q\"",
        ErrorKind::BadEscape,
        1,
        22,
        "\\q",
    ),
    ("Translate 1 2.3.4 5", ErrorKind::BadNumber, 1, 13, "2.3.4"),
    (
        "Shape \"x\" \"float f\" [ 1 -e ]",
        ErrorKind::BadNumber,
        1,
        25,
        "-e",
    ),
    (
        "Shape \"x\" \"float f\" 1e400",
        ErrorKind::BadNumber,
        1,
        21,
        "1e400",
    ),
    (
        "WorldBegin\n  Shpae \"sphere\"",
        ErrorKind::UnknownDirective,
        2,
        3,
        "Shpae",
    ),
    (
        "Shape \"x\" \"float f\" [ 1 2\nShape \"y\"",
        ErrorKind::MissingBracket,
        2,
        1,
        "1:21",
    ),
    (
        "Shape \"x\" \"float f\" [ 1 2",
        ErrorKind::MissingBracket,
        1,
        21,
        "never closed",
    ),
    (
        "Shape \"x\" \"float f\" [ 1\n \"float g\" [ 2 ]",
        ErrorKind::MissingBracket,
        2,
        2,
        "']'",
    ),
    (
        "Transform [ 1 0 0 0\nWorldBegin",
        ErrorKind::MissingBracket,
        2,
        1,
        "']'",
    ),
    (
        "Shape \"x\" \"float f\" ] 1",
        ErrorKind::MissingBracket,
        1,
        21,
        "']'",
    ),
    ("WorldBegin ]", ErrorKind::MissingBracket, 1, 12, "']'"),
    (
        "Shape \"x\" \"float f\" [ 1 [ 2 ] ]",
        ErrorKind::MissingBracket,
        1,
        25,
        "'['",
    ),
    (
        "Translate 1 \"2\" 3",
        ErrorKind::UnexpectedToken,
        1,
        13,
        "number",
    ),
    (
        "Shape sphere",
        ErrorKind::UnexpectedToken,
        1,
        7,
        "shape type",
    ),
    (
        "\"float x\" 1",
        ErrorKind::UnexpectedToken,
        1,
        1,
        "directive",
    ),
    (
        "ActiveTransform Sometimes",
        ErrorKind::UnexpectedToken,
        1,
        17,
        "Sometimes",
    ),
    (
        "Shape \"x\" \"float f\" Shape",
        ErrorKind::UnexpectedToken,
        1,
        21,
        "value",
    ),
    (
        "Transform 1 0 0 0",
        ErrorKind::UnexpectedToken,
        1,
        11,
        "'['",
    ),
    (
        "Translate 1 2",
        ErrorKind::UnexpectedEof,
        1,
        1,
        "end of the file",
    ),
    ("\n\nShape", ErrorKind::UnexpectedEof, 3, 1, "shape type"),
    (
        "Shape \"x\" \"float f\"",
        ErrorKind::UnexpectedEof,
        1,
        11,
        "value",
    ),
    (
        "Shape \"x\" \"floatf\" 1",
        ErrorKind::BadParameter,
        1,
        11,
        "type name",
    ),
    (
        "Shape \"x\" \"double f\" 1",
        ErrorKind::BadParameter,
        1,
        11,
        "double",
    ),
    (
        "Shape \"x\" \"float f\" 1\n \"integer f\" 2",
        ErrorKind::BadParameter,
        2,
        2,
        "1:11",
    ),
    (
        "Shape \"x\" \"float f\" [ \"one\" ]",
        ErrorKind::WrongValueType,
        1,
        23,
        "numbers",
    ),
    (
        "Shape \"x\" \"integer n\" [ 1 2.5 ]",
        ErrorKind::WrongValueType,
        1,
        27,
        "whole",
    ),
    (
        "Shape \"x\" \"integer n\" 1e3",
        ErrorKind::WrongValueType,
        1,
        23,
        "whole",
    ),
    (
        "Shape \"x\" \"bool b\" \"yes\"",
        ErrorKind::WrongValueType,
        1,
        20,
        "true or false",
    ),
    (
        "Shape \"x\" \"bool b\" 1",
        ErrorKind::WrongValueType,
        1,
        20,
        "true or false",
    ),
    (
        "Shape \"x\" \"string s\" 1",
        ErrorKind::WrongValueType,
        1,
        22,
        "strings",
    ),
    (
        "Shape \"x\" \"float f\" true",
        ErrorKind::WrongValueType,
        1,
        21,
        "numbers",
    ),
    (
        "Shape \"x\" \"spectrum s\" [ 1 \"a\" ]",
        ErrorKind::WrongValueType,
        1,
        28,
        "one string",
    ),
    (
        "Shape \"x\" \"spectrum s\" [ \"a\" 1 ]",
        ErrorKind::WrongValueType,
        1,
        30,
        "one string",
    ),
    (
        "Shape \"x\" \"rgb c\" [ 1 2 ]",
        ErrorKind::WrongValueCount,
        1,
        11,
        "3",
    ),
    (
        "Shape \"x\" \"point3 P\" [ 1 2 3 4 ]",
        ErrorKind::WrongValueCount,
        1,
        11,
        "3",
    ),
    (
        "Shape \"x\" \"point2 uv\" [ 1 ]",
        ErrorKind::WrongValueCount,
        1,
        11,
        "2",
    ),
    (
        "Shape \"x\" \"spectrum s\" [ 400 1 500 ]",
        ErrorKind::WrongValueCount,
        1,
        11,
        "pairs",
    ),
    (
        "Shape \"x\" \"spectrum s\" [ \"a\" \"b\" ]",
        ErrorKind::WrongValueCount,
        1,
        11,
        "pairs",
    ),
    (
        "Shape \"x\" \"texture t\" [ ]",
        ErrorKind::WrongValueCount,
        1,
        11,
        "texture",
    ),
    (
        "Shape \"x\" \"blackbody b\" [ ]",
        ErrorKind::WrongValueCount,
        1,
        11,
        "temperature",
    ),
    (
        "\n ConcatTransform [ 1 2 3 ]",
        ErrorKind::WrongValueCount,
        2,
        2,
        "16",
    ),
];

#[test]
fn syntax_errors_have_kind_and_location() {
    for &(text, kind, line, column, word) in CASES {
        let e = error(text);
        assert_eq!(e.kind, kind, "{text:?}: {e}");
        let loc = e.loc.clone().expect("a location");
        assert_eq!(
            (&*loc.file, loc.line, loc.column),
            ("e.pbrt", line, column),
            "{text:?}: {e}"
        );
        assert!(
            e.message.contains(word),
            "{text:?}: message {:?} lacks {word:?}",
            e.message
        );
        assert_eq!(
            e.to_string(),
            format!("e.pbrt:{line}:{column}: {}", e.message)
        );
    }
}

#[test]
fn unreadable_main_file_has_no_location() {
    let e =
        pbrt_format::parse_file("/nonexistent/dir/scene.pbrt", &mut Recorder::new()).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Io);
    assert!(e.loc.is_none());
    assert!(e.to_string().contains("/nonexistent/dir/scene.pbrt"));
}

/// A target that rejects `NamedMaterial` for undefined names.
#[derive(Default)]
struct Strict {
    defined: Vec<String>,
    seen: usize,
}

impl ParserTarget for Strict {
    fn directive(&mut self, directive: Directive, loc: &Loc) -> TargetResult {
        self.seen += 1;
        match directive {
            Directive::MakeNamedMaterial(n, _) => self.defined.push(n),
            Directive::NamedMaterial(n) if !self.defined.contains(&n) => {
                return Err(ParseError::scene(
                    loc,
                    format!("{n}: named material not defined"),
                ));
            }
            _ => {}
        }
        Ok(())
    }
    fn warning(&mut self, _loc: &Loc, _message: &str) {}
}

#[test]
fn target_errors_stop_the_parse_and_keep_their_location() {
    let mut t = Strict::default();
    let text = "MakeNamedMaterial \"a\"\nNamedMaterial \"a\"\n  NamedMaterial \"b\"\nShape \"s\"";
    let e = parse_str(text, "e.pbrt", &mut t).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Scene);
    assert_eq!(e.to_string(), "e.pbrt:3:3: b: named material not defined");
    assert_eq!(t.seen, 3, "no call after the failing one");
}
