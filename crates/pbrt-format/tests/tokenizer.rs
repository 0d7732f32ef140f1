//! The tokenizer reports exact lines and columns, across comments, escapes,
//! multi-line parameter lists, tabs and CRLF line ends.

use pbrt_format::ErrorKind;
use pbrt_format::token::{Token, TokenKind, Tokenizer};

fn tokens(src: &str) -> Vec<(TokenKind, &str, u32, u32)> {
    Tokenizer::new(src, "t.pbrt")
        .map(|t| {
            let t: Token<'_> = t.unwrap();
            (t.kind, t.text, t.line, t.column)
        })
        .collect()
}

use TokenKind::{CloseBracket as C, Number as N, OpenBracket as O, String as S, Word as W};

#[test]
fn positions_are_exact() {
    let src = "# header comment\n\
               Shape \"trianglemesh\" # trailing \"quoted\" [comment]\n\
               \t\"point3 P\" [ 0 -1.5e-3\n\
               \x20   .5 ]\n\
               \"string s\" \"a \\\"b\\\" c\" Rotate\n";
    let got = tokens(src);
    let want = vec![
        (W, "Shape", 2, 1),
        (S, "trianglemesh", 2, 7),
        (S, "point3 P", 3, 2),
        (O, "[", 3, 13),
        (N, "0", 3, 15),
        (N, "-1.5e-3", 3, 17),
        (N, ".5", 4, 5),
        (C, "]", 4, 8),
        (S, "string s", 5, 1),
        (S, "a \\\"b\\\" c", 5, 12),
        (W, "Rotate", 5, 24),
    ];
    assert_eq!(got, want);
}

#[test]
fn brackets_and_quotes_split_words() {
    let got = tokens("[1 2]\"x\"true[\"y\"]");
    let want = vec![
        (O, "[", 1, 1),
        (N, "1", 1, 2),
        (N, "2", 1, 4),
        (C, "]", 1, 5),
        (S, "x", 1, 6),
        (W, "true", 1, 9),
        (O, "[", 1, 13),
        (S, "y", 1, 14),
        (C, "]", 1, 17),
    ];
    assert_eq!(got, want);
}

#[test]
fn crlf_comments_at_eof_and_empty_input() {
    assert!(tokens("").is_empty());
    assert!(tokens("   \n\t# only a comment").is_empty());
    let got = tokens("A\r\n  B # c\r\nC");
    assert_eq!(got, vec![(W, "A", 1, 1), (W, "B", 2, 3), (W, "C", 3, 1)]);
}

#[test]
fn positions_after_escaped_backslash_and_quote() {
    // "\\" ends after the escaped backslash; the next token is on the same line.
    let got = tokens("\"\\\\\" X\n\"\\\"\" Y");
    assert_eq!(
        got,
        vec![
            (S, "\\\\", 1, 1),
            (W, "X", 1, 6),
            (S, "\\\"", 2, 1),
            (W, "Y", 2, 6),
        ]
    );
}

#[test]
fn unterminated_string_points_at_its_opening_quote() {
    for src in [
        "Shape \"sphere\n\"float radius\" 1",
        "Shape\n   \"sphere",
        "  \"a\\",
    ] {
        let err = Tokenizer::new(src, "t.pbrt")
            .find_map(Result::err)
            .expect("an error");
        assert_eq!(err.kind, ErrorKind::UnterminatedString, "{src:?}");
        let loc = err.loc.clone().unwrap();
        let want = match src {
            s if s.starts_with("Shape \"") => (1, 7),
            s if s.starts_with("Shape\n") => (2, 4),
            _ => (1, 3),
        };
        assert_eq!((loc.line, loc.column), want, "{src:?}");
        assert!(
            err.to_string()
                .starts_with(&format!("t.pbrt:{}:{}: ", want.0, want.1))
        );
    }
}

#[test]
fn position_of_end_of_input() {
    let mut t = Tokenizer::new("A\n  B  \n  ", "t.pbrt");
    while t.next_token().unwrap().is_some() {}
    let end = t.position();
    assert_eq!((end.line, end.column), (3, 3));
}
