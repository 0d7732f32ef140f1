//! Source locations ([`Loc`]) and the parse error type ([`ParseError`]).
//!
//! Every token, directive and parameter carries a [`Loc`]; every error names one
//! (except a failure to read the top-level file, which has no position to name).

use std::fmt;
use std::sync::Arc;

/// A position in a scene file: file name, 1-based line and 1-based column.
///
/// Columns count Unicode scalar values (characters), so a tab counts as one column.
/// The file name is shared (`Arc<str>`), so cloning a `Loc` never copies it.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Loc {
    /// The file name as it was given to the parser or resolved for an `Include`.
    pub file: Arc<str>,
    /// 1-based line number.
    pub line: u32,
    /// 1-based column number (in characters).
    pub column: u32,
}

impl Loc {
    /// Builds a location.
    pub fn new(file: impl Into<Arc<str>>, line: u32, column: u32) -> Self {
        Loc {
            file: file.into(),
            line,
            column,
        }
    }
}

impl fmt::Display for Loc {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", self.file, self.line, self.column)
    }
}

/// What went wrong; see [`ParseError`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A file (the scene file or an included/imported one) could not be read.
    Io,
    /// A string has no closing `"` on its line (pbrt-v4 does not allow newlines in strings).
    UnterminatedString,
    /// An escape sequence in a string other than `\b \f \n \r \t \\ \' \"`.
    BadEscape,
    /// A token that starts like a number but is not one (or overflows to infinity).
    BadNumber,
    /// A bare word where a directive is expected that is not a pbrt-v4 directive.
    UnknownDirective,
    /// A `[` without its `]`, or a `]` without its `[`.
    MissingBracket,
    /// A token of the wrong kind, e.g. a string where `Translate` expects a number.
    UnexpectedToken,
    /// The file ended in the middle of a directive.
    UnexpectedEof,
    /// A malformed parameter declaration: not `"type name"`, an unknown type, or a
    /// parameter given twice in one list.
    BadParameter,
    /// A value of the wrong type for the declared parameter type (a string for a
    /// `float`, `1.5` for an `integer`, `yes` for a `bool`, ...).
    WrongValueType,
    /// The wrong number of values (e.g. `rgb` with 2 values, `point3` with 4, a
    /// `Transform` without 16 numbers).
    WrongValueCount,
    /// `Include`/`Import` nested too deeply (most likely a file including itself).
    IncludeDepth,
    /// An error raised by a [`crate::ParserTarget`] (scene-building errors such as an
    /// undefined named material, or an unreadable mesh).
    Scene,
}

/// A parse (or scene) error: a kind, where it happened, and a message.
///
/// Displays as `file:line:column: message`, or just `message` when there is no
/// location (the top-level file could not be read).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParseError {
    /// What went wrong.
    pub kind: ErrorKind,
    /// Where it went wrong.
    pub loc: Option<Loc>,
    /// A human-readable description (without the location).
    pub message: String,
}

impl ParseError {
    /// An error at `loc`.
    pub fn new(kind: ErrorKind, loc: &Loc, message: impl Into<String>) -> Self {
        ParseError {
            kind,
            loc: Some(loc.clone()),
            message: bounded(message.into()),
        }
    }

    /// An error without a location.
    pub fn without_loc(kind: ErrorKind, message: impl Into<String>) -> Self {
        ParseError {
            kind,
            loc: None,
            message: bounded(message.into()),
        }
    }

    /// A [`ErrorKind::Scene`] error at `loc`, for use by [`crate::ParserTarget`]s.
    pub fn scene(loc: &Loc, message: impl Into<String>) -> Self {
        Self::new(ErrorKind::Scene, loc, message)
    }
}

/// The longest message kept whole, in bytes.
const MAX_MESSAGE: usize = 600;

/// `message`, cut after about [`MAX_MESSAGE`] bytes when longer (a huge
/// token echoed from a hostile file must not make a huge error line).
fn bounded(mut message: String) -> String {
    if message.len() <= MAX_MESSAGE {
        return message;
    }
    let total = message.len();
    let mut cut = MAX_MESSAGE;
    while !message.is_char_boundary(cut) {
        cut -= 1;
    }
    message.truncate(cut);
    message.push_str(&format!("... [{} more bytes]", total - cut));
    message
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.loc {
            Some(loc) => write!(f, "{loc}: {}", self.message),
            None => f.write_str(&self.message),
        }
    }
}

impl std::error::Error for ParseError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display_has_file_line_column() {
        let loc = Loc::new("scenes/a.pbrt", 12, 7);
        let e = ParseError::new(ErrorKind::BadNumber, &loc, "bad number \"1.2.3\"");
        assert_eq!(e.to_string(), "scenes/a.pbrt:12:7: bad number \"1.2.3\"");
        let e = ParseError::without_loc(ErrorKind::Io, "cannot read x");
        assert_eq!(e.to_string(), "cannot read x");
        assert_eq!(ParseError::scene(&loc, "m").kind, ErrorKind::Scene);
    }
}
