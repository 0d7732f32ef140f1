//! A token stream with one token of lookahead, and the parsing of directive
//! arguments and parameter lists (`"type name" [values]`) into a [`ParamSet`].

use std::borrow::Cow;
use std::sync::Arc;

use crate::directive::is_directive;
use crate::token::{Token, TokenKind, Tokenizer, unescape};
use crate::{ErrorKind, Loc, Param, ParamSet, ParamType, ParamValues, ParseError};

/// Tokens of one file with one token of lookahead.
pub(crate) struct Stream<'a> {
    tokens: Tokenizer<'a>,
    peeked: Option<Token<'a>>,
}

fn err(kind: ErrorKind, loc: &Loc, message: impl Into<String>) -> ParseError {
    ParseError::new(kind, loc, message)
}

impl<'a> Stream<'a> {
    pub(crate) fn new(src: &'a str, file: Arc<str>) -> Self {
        Stream {
            tokens: Tokenizer::new(src, file),
            peeked: None,
        }
    }

    pub(crate) fn loc(&self, tok: &Token<'_>) -> Loc {
        tok.loc(self.tokens.file())
    }

    pub(crate) fn next(&mut self) -> Result<Option<Token<'a>>, ParseError> {
        match self.peeked.take() {
            Some(t) => Ok(Some(t)),
            None => self.tokens.next_token(),
        }
    }

    pub(crate) fn peek(&mut self) -> Result<Option<Token<'a>>, ParseError> {
        if self.peeked.is_none() {
            self.peeked = self.tokens.next_token()?;
        }
        Ok(self.peeked)
    }

    /// The next token, or an `UnexpectedEof` error saying `what` was expected by the
    /// directive at `at`.
    fn required(&mut self, at: &Loc, what: &str) -> Result<Token<'a>, ParseError> {
        self.next()?.ok_or_else(|| {
            err(
                ErrorKind::UnexpectedEof,
                at,
                format!("expected {what}, found the end of the file"),
            )
        })
    }

    /// Decodes a string token's escapes.
    fn decode(&self, tok: &Token<'a>) -> Result<Cow<'a, str>, ParseError> {
        unescape(tok.text).map_err(|c| {
            err(
                ErrorKind::BadEscape,
                &self.loc(tok),
                format!("unknown escape sequence '\\{c}' in string"),
            )
        })
    }

    /// A string argument of the directive at `at`.
    pub(crate) fn string_arg(&mut self, at: &Loc, what: &str) -> Result<Cow<'a, str>, ParseError> {
        let tok = self.required(at, what)?;
        if tok.kind != TokenKind::String {
            let msg = format!("expected {what}, found {}", tok.describe());
            return Err(err(ErrorKind::UnexpectedToken, &self.loc(&tok), msg));
        }
        self.decode(&tok)
    }

    /// A bare-word argument (e.g. `ActiveTransform All`).
    pub(crate) fn word_arg(&mut self, at: &Loc, what: &str) -> Result<Token<'a>, ParseError> {
        let tok = self.required(at, what)?;
        if tok.kind != TokenKind::Word {
            let msg = format!("expected {what}, found {}", tok.describe());
            return Err(err(ErrorKind::UnexpectedToken, &self.loc(&tok), msg));
        }
        Ok(tok)
    }

    /// A number token's value, or the appropriate error.
    fn number_value(&self, tok: &Token<'a>, what: &str) -> Result<f64, ParseError> {
        match tok.kind {
            TokenKind::Number => tok.number().ok_or_else(|| {
                let msg = format!("invalid number '{}'", tok.text);
                err(ErrorKind::BadNumber, &self.loc(tok), msg)
            }),
            _ => {
                let msg = format!("expected {what}, found {}", tok.describe());
                Err(err(ErrorKind::UnexpectedToken, &self.loc(tok), msg))
            }
        }
    }

    /// `N` numeric arguments of the directive at `at` (e.g. `Translate 1 2 3`).
    pub(crate) fn numbers<const N: usize>(
        &mut self,
        at: &Loc,
        directive: &str,
    ) -> Result<[f64; N], ParseError> {
        let mut out = [0.0; N];
        let what = format!("{N} numbers after {directive}");
        for v in &mut out {
            let tok = self.required(at, &what)?;
            *v = self.number_value(&tok, &what)?;
        }
        Ok(out)
    }

    /// `[ 16 numbers ]` for `Transform`/`ConcatTransform`.
    pub(crate) fn matrix(&mut self, at: &Loc, directive: &str) -> Result<[f64; 16], ParseError> {
        let what = format!("'[' and 16 numbers after {directive}");
        let open = self.required(at, &what)?;
        if open.kind != TokenKind::OpenBracket {
            let msg = format!("expected {what}, found {}", open.describe());
            return Err(err(ErrorKind::UnexpectedToken, &self.loc(&open), msg));
        }
        let open_loc = self.loc(&open);
        let mut values = Vec::with_capacity(16);
        loop {
            let tok = self.list_token(&open_loc)?;
            if tok.kind == TokenKind::CloseBracket {
                break;
            }
            values.push(self.number_value(&tok, "a number")?);
        }
        values.try_into().map_err(|v: Vec<f64>| {
            let msg = format!("{directive} needs 16 numbers, found {}", v.len());
            err(ErrorKind::WrongValueCount, at, msg)
        })
    }

    /// The next token inside a `[ ... ]` list opened at `open`: reports a missing
    /// `]` at the end of the file, before a directive, or before a nested `[`.
    fn list_token(&mut self, open: &Loc) -> Result<Token<'a>, ParseError> {
        let Some(tok) = self.next()? else {
            let msg = "'[' is never closed (expected ']' before the end of the file)";
            return Err(err(ErrorKind::MissingBracket, open, msg));
        };
        let unclosed = match tok.kind {
            TokenKind::Word => is_directive(tok.text),
            TokenKind::OpenBracket => true,
            TokenKind::String => looks_like_declaration(tok.text),
            _ => false,
        };
        if unclosed {
            let msg = format!(
                "expected ']' to close the '[' at {}:{}, found {}",
                open.line,
                open.column,
                tok.describe()
            );
            return Err(err(ErrorKind::MissingBracket, &self.loc(&tok), msg));
        }
        Ok(tok)
    }

    /// Parameters `"type name" value(s)` for as long as the next token is a string.
    pub(crate) fn params(&mut self) -> Result<ParamSet, ParseError> {
        let mut set = ParamSet::new();
        while let Some(tok) = self.peek()? {
            if tok.kind != TokenKind::String {
                break;
            }
            let param = self.param()?;
            if let Err(p) = set.push(param) {
                let first = set.find(&p.name).map(|q| q.loc.clone());
                let msg = match first {
                    Some(f) => format!(
                        "parameter \"{}\" given twice (first at {}:{})",
                        p.name, f.line, f.column
                    ),
                    None => format!("parameter \"{}\" given twice", p.name),
                };
                return Err(err(ErrorKind::BadParameter, &p.loc, msg));
            }
        }
        Ok(set)
    }

    /// One parameter: a `"type name"` string then one value or a bracketed list.
    pub(crate) fn param(&mut self) -> Result<Param, ParseError> {
        let Some(decl) = self.next()? else {
            let loc = self.tokens.position();
            let msg = "expected a parameter, found the end of the file";
            return Err(err(ErrorKind::UnexpectedEof, &loc, msg));
        };
        let loc = self.loc(&decl);
        if decl.kind != TokenKind::String {
            let msg = format!(
                "expected a \"type name\" parameter, found {}",
                decl.describe()
            );
            return Err(err(ErrorKind::UnexpectedToken, &loc, msg));
        }
        let mut words = decl.text.split_ascii_whitespace();
        let (Some(ty_word), Some(name), None) = (words.next(), words.next(), words.next()) else {
            let msg = format!(
                "bad parameter declaration \"{}\" (expected \"type name\")",
                decl.text
            );
            return Err(err(ErrorKind::BadParameter, &loc, msg));
        };
        let Some(ty) = ParamType::from_name(ty_word) else {
            let msg = format!("unknown parameter type \"{ty_word}\" in \"{}\"", decl.text);
            return Err(err(ErrorKind::BadParameter, &loc, msg));
        };
        let mut values = Values::new(ty);
        let what = format!("a value for \"{}\"", decl.text);
        let first = self.required(&loc, &what)?;
        match first.kind {
            TokenKind::OpenBracket => {
                let open = self.loc(&first);
                loop {
                    let tok = self.list_token(&open)?;
                    if tok.kind == TokenKind::CloseBracket {
                        break;
                    }
                    self.push_value(&mut values, &tok, decl.text)?;
                }
            }
            TokenKind::CloseBracket => {
                let msg = format!("']' without '[' after \"{}\"", decl.text);
                return Err(err(ErrorKind::MissingBracket, &self.loc(&first), msg));
            }
            TokenKind::Word if !matches!(first.text, "true" | "false") => {
                let msg = format!("expected {what}, found {}", first.describe());
                return Err(err(ErrorKind::UnexpectedToken, &self.loc(&first), msg));
            }
            _ => self.push_value(&mut values, &first, decl.text)?,
        }
        let values = values.finish(ty, decl.text, &loc)?;
        Ok(Param::new(ty, name, values, loc))
    }

    /// Converts one value token for a parameter of type `values.ty`.
    fn push_value(
        &self,
        values: &mut Values,
        tok: &Token<'a>,
        decl: &str,
    ) -> Result<(), ParseError> {
        let wrong = |expected: &str| {
            let msg = format!("\"{decl}\" needs {expected}, found {}", tok.describe());
            Err(err(ErrorKind::WrongValueType, &self.loc(tok), msg))
        };
        if values.ty == ParamType::Spectrum && !values.started && tok.kind == TokenKind::String {
            values.data = ParamValues::Strings(Vec::new());
        }
        match (&mut values.data, tok.kind) {
            (ParamValues::Floats(v), TokenKind::Number) => v.push(self.number_value(tok, "")?),
            (ParamValues::Floats(_), _) if values.ty == ParamType::Spectrum => {
                return wrong("all numbers or one string");
            }
            (ParamValues::Floats(_), _) => return wrong("numbers"),
            (ParamValues::Ints(v), TokenKind::Number) => match tok.text.parse::<i64>() {
                Ok(i) => v.push(i),
                Err(_) if tok.number().is_some() => return wrong("whole numbers"),
                Err(_) => {
                    self.number_value(tok, "")?;
                    return wrong("whole numbers in range");
                }
            },
            (ParamValues::Ints(_), _) => return wrong("whole numbers"),
            (ParamValues::Bools(v), TokenKind::Word | TokenKind::String) => match tok.text {
                "true" => v.push(true),
                "false" => v.push(false),
                _ => return wrong("true or false"),
            },
            (ParamValues::Bools(_), _) => return wrong("true or false"),
            (ParamValues::Strings(v), TokenKind::String) => v.push(self.decode(tok)?.into_owned()),
            (ParamValues::Strings(_), _) if values.ty == ParamType::Spectrum => {
                return wrong("all numbers or one string");
            }
            (ParamValues::Strings(_), _) => return wrong("strings"),
        }
        values.started = true;
        Ok(())
    }
}

/// Whether a string token looks like a parameter declaration (`"float radius"`).
fn looks_like_declaration(text: &str) -> bool {
    let mut words = text.split_ascii_whitespace();
    matches!(
        (
            words.next().and_then(ParamType::from_name),
            words.next(),
            words.next()
        ),
        (Some(_), Some(_), None)
    )
}

/// Values being collected for one parameter.
struct Values {
    ty: ParamType,
    data: ParamValues,
    started: bool,
}

impl Values {
    fn new(ty: ParamType) -> Self {
        let data = match ty {
            ParamType::Integer => ParamValues::Ints(Vec::new()),
            ParamType::Bool => ParamValues::Bools(Vec::new()),
            ParamType::String | ParamType::Texture => ParamValues::Strings(Vec::new()),
            _ => ParamValues::Floats(Vec::new()),
        };
        Values {
            ty,
            data,
            started: false,
        }
    }

    /// Checks the number of values for the type.
    fn finish(self, ty: ParamType, decl: &str, loc: &Loc) -> Result<ParamValues, ParseError> {
        let n = self.data.len();
        let ok = match (ty, &self.data) {
            (ParamType::Rgb, _) => n == 3,
            (ParamType::Blackbody, _) => n == 1 || n == 2,
            (ParamType::Texture, _) => n == 1,
            (ParamType::Spectrum, ParamValues::Strings(_)) => n == 1,
            (ParamType::Spectrum, _) => n >= 2 && n % 2 == 0,
            _ => n % ty.arity() == 0,
        };
        if ok {
            return Ok(self.data);
        }
        let need = match ty {
            ParamType::Rgb => "exactly 3 values".to_string(),
            ParamType::Blackbody => "1 value (a temperature)".to_string(),
            ParamType::Texture => "exactly 1 texture name".to_string(),
            ParamType::Spectrum => {
                "(wavelength, value) pairs or exactly 1 spectrum name".to_string()
            }
            _ => format!("a multiple of {} values", ty.arity()),
        };
        let msg = format!("\"{decl}\" needs {need}, found {n}");
        Err(err(ErrorKind::WrongValueCount, loc, msg))
    }
}
