//! The tokenizer: splits pbrt-v4 scene text into words, numbers, strings and
//! brackets, skipping whitespace and `#` comments, with the line and column of
//! every token.
//!
//! Tokens borrow their text from the source, so tokenizing allocates nothing.
//! Like pbrt-v4, a string may not contain a raw newline (it is reported as
//! unterminated at its opening quote); escapes (`\"`, `\n`, ...) are kept raw in
//! [`Token::text`] and decoded by [`unescape`].

use std::borrow::Cow;
use std::sync::Arc;

use crate::{ErrorKind, Loc, ParseError};

/// The kind of a [`Token`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TokenKind {
    /// A bare word that does not start like a number: a directive name, `true`, `false`.
    Word,
    /// A bare word starting with a digit, `+`, `-` or `.` (not yet checked to be a
    /// valid number; see [`Token::number`]).
    Number,
    /// A double-quoted string; [`Token::text`] is the raw text between the quotes.
    String,
    /// `[`
    OpenBracket,
    /// `]`
    CloseBracket,
}

/// One token, borrowing its text from the source.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Token<'a> {
    /// What kind of token this is.
    pub kind: TokenKind,
    /// The token's text; for strings, the raw text between the quotes.
    pub text: &'a str,
    /// 1-based line of the token's first character (the opening quote of a string).
    pub line: u32,
    /// 1-based column of the token's first character.
    pub column: u32,
}

impl Token<'_> {
    /// The token's location in `file`.
    pub fn loc(&self, file: &Arc<str>) -> Loc {
        Loc {
            file: Arc::clone(file),
            line: self.line,
            column: self.column,
        }
    }

    /// The value of a number token, if its text is a finite decimal number
    /// (`12`, `-4.37114e-8`, `.5`, `+3.`). `inf`/`nan` spellings are not numbers.
    pub fn number(&self) -> Option<f64> {
        let valid = self
            .text
            .bytes()
            .all(|b| b.is_ascii_digit() || matches!(b, b'+' | b'-' | b'.' | b'e' | b'E'));
        if !valid {
            return None;
        }
        self.text.parse::<f64>().ok().filter(|v| v.is_finite())
    }

    /// A short description for error messages: `"text"` for strings, `'text'` else.
    pub fn describe(&self) -> String {
        match self.kind {
            TokenKind::String => format!("string \"{}\"", self.text),
            _ => format!("'{}'", self.text),
        }
    }
}

/// Decodes the escapes of a raw string token (`\b \f \n \r \t \\ \' \"`).
///
/// Returns the text borrowed when it has no escapes, or the offending character
/// after a backslash.
pub fn unescape(raw: &str) -> Result<Cow<'_, str>, char> {
    if !raw.contains('\\') {
        return Ok(Cow::Borrowed(raw));
    }
    let mut out = String::with_capacity(raw.len());
    let mut chars = raw.chars();
    while let Some(c) = chars.next() {
        if c != '\\' {
            out.push(c);
            continue;
        }
        let e = chars.next().unwrap_or('\\');
        out.push(match e {
            'b' => '\u{8}',
            'f' => '\u{c}',
            'n' => '\n',
            'r' => '\r',
            't' => '\t',
            '\\' | '\'' | '"' => e,
            other => return Err(other),
        });
    }
    Ok(Cow::Owned(out))
}

/// Splits scene text into [`Token`]s; an iterator of `Result<Token, ParseError>`.
#[derive(Clone, Debug)]
pub struct Tokenizer<'a> {
    src: &'a str,
    pos: usize,
    line: u32,
    column: u32,
    file: Arc<str>,
}

impl<'a> Tokenizer<'a> {
    /// A tokenizer over `src`, whose locations name `file`.
    pub fn new(src: &'a str, file: impl Into<Arc<str>>) -> Self {
        Tokenizer {
            src,
            pos: 0,
            line: 1,
            column: 1,
            file: file.into(),
        }
    }

    /// The file name used in locations.
    pub fn file(&self) -> &Arc<str> {
        &self.file
    }

    /// The location of the next character not yet consumed (the end of input at EOF).
    pub fn position(&self) -> Loc {
        Loc::new(Arc::clone(&self.file), self.line, self.column)
    }

    /// Moves `pos` to `end` (which must not cross a newline), counting columns.
    fn advance_in_line(&mut self, end: usize) {
        let span = &self.src.as_bytes()[self.pos..end];
        self.column += span.iter().filter(|&&b| (b & 0xC0) != 0x80).count() as u32;
        self.pos = end;
    }

    /// Skips whitespace and comments.
    fn skip_blank(&mut self) {
        let bytes = self.src.as_bytes();
        while self.pos < bytes.len() {
            match bytes[self.pos] {
                b'\n' => {
                    self.pos += 1;
                    self.line += 1;
                    self.column = 1;
                }
                b' ' | b'\t' | b'\r' | 0x0b | 0x0c => {
                    self.pos += 1;
                    self.column += 1;
                }
                b'#' => {
                    let end = bytes[self.pos..]
                        .iter()
                        .position(|&b| b == b'\n')
                        .map_or(bytes.len(), |n| self.pos + n);
                    self.advance_in_line(end);
                }
                _ => return,
            }
        }
    }

    /// The next token, `Ok(None)` at the end of input.
    pub fn next_token(&mut self) -> Result<Option<Token<'a>>, ParseError> {
        self.skip_blank();
        let bytes = self.src.as_bytes();
        if self.pos >= bytes.len() {
            return Ok(None);
        }
        let (line, column, start) = (self.line, self.column, self.pos);
        let first = bytes[start];
        let (kind, text_start, text_end, end) = match first {
            b'[' => (TokenKind::OpenBracket, start, start + 1, start + 1),
            b']' => (TokenKind::CloseBracket, start, start + 1, start + 1),
            b'"' => {
                let mut i = start + 1;
                loop {
                    match bytes.get(i) {
                        Some(b'"') => break,
                        Some(b'\\') if !matches!(bytes.get(i + 1), None | Some(b'\n')) => i += 2,
                        Some(b'\n') | Some(b'\\') | None => {
                            let loc = Loc::new(Arc::clone(&self.file), line, column);
                            return Err(ParseError::new(
                                ErrorKind::UnterminatedString,
                                &loc,
                                "unterminated string (no closing '\"' on this line)",
                            ));
                        }
                        Some(_) => i += 1,
                    }
                }
                (TokenKind::String, start + 1, i, i + 1)
            }
            _ => {
                let end = bytes[start..]
                    .iter()
                    .position(|&b| b.is_ascii_whitespace() || matches!(b, b'"' | b'[' | b']'))
                    .map_or(bytes.len(), |n| start + n);
                let kind = if first.is_ascii_digit() || matches!(first, b'+' | b'-' | b'.') {
                    TokenKind::Number
                } else {
                    TokenKind::Word
                };
                (kind, start, end, end)
            }
        };
        self.advance_in_line(end);
        Ok(Some(Token {
            kind,
            text: &self.src[text_start..text_end],
            line,
            column,
        }))
    }
}

impl<'a> Iterator for Tokenizer<'a> {
    type Item = Result<Token<'a>, ParseError>;
    fn next(&mut self) -> Option<Self::Item> {
        self.next_token().transpose()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tok(kind: TokenKind, text: &str, line: u32, column: u32) -> Token<'_> {
        Token {
            kind,
            text,
            line,
            column,
        }
    }

    #[test]
    fn numbers_are_validated() {
        let t = |s| tok(TokenKind::Number, s, 1, 1);
        assert_eq!(t("-4.37114e-8").number(), Some(-4.37114e-8));
        assert_eq!(t(".7").number(), Some(0.7));
        assert_eq!(t("+3.").number(), Some(3.0));
        assert_eq!(t("1.2.3").number(), None);
        assert_eq!(t("-inf").number(), None);
        assert_eq!(t("1e999").number(), None);
        assert_eq!(t("-").number(), None);
    }

    #[test]
    fn unescape_decodes_and_rejects() {
        assert!(matches!(unescape("plain"), Ok(Cow::Borrowed("plain"))));
        assert_eq!(unescape(r#"a\"b\\c\nd\te"#).unwrap(), "a\"b\\c\nd\te");
        assert_eq!(unescape(r"bad\q"), Err('q'));
    }

    #[test]
    fn multibyte_characters_count_as_one_column() {
        let toks: Vec<_> = Tokenizer::new("\"é\" x # ü\n  ü y", "f")
            .map(Result::unwrap)
            .collect();
        assert_eq!(toks[0], tok(TokenKind::String, "é", 1, 1));
        assert_eq!(toks[1], tok(TokenKind::Word, "x", 1, 5));
        assert_eq!(toks[2], tok(TokenKind::Word, "ü", 2, 3));
        assert_eq!(toks[3], tok(TokenKind::Word, "y", 2, 5));
    }
}
