//! [`Formatter`]: a target that prints a parsed scene back as pbrt-v4 text.
//!
//! The output is one file with `Include`d/`Import`ed text inlined (marked by
//! comments), blocks indented, parameters one per line, legacy type names in
//! canonical form (`point` becomes `point3`) and numbers in their shortest exact
//! form. Parsing the output gives the same directives as parsing the input.

use std::fmt::Write;
use std::path::Path;

use crate::target::TargetResult;
use crate::{Directive, FileKind, Loc, Param, ParamSet, ParamValues, ParserTarget};

/// Values per line in a long parameter list.
const PER_LINE: usize = 12;

/// Pretty-prints the directives it receives; [`Formatter::finish`] returns the text.
///
/// ```
/// let mut f = pbrt_format::Formatter::new();
/// pbrt_format::parse_str("Shape \"sphere\" \"float radius\" 2", "x.pbrt", &mut f).unwrap();
/// assert_eq!(f.finish(), "Shape \"sphere\"\n    \"float radius\" [ 2 ]\n");
/// ```
#[derive(Clone, Debug, Default)]
pub struct Formatter {
    out: String,
    depth: usize,
}

/// Writes a number in the shortest form that parses back to the same `f64`.
pub fn format_number(v: f64, out: &mut String) {
    let a = v.abs();
    if a == 0.0 || (1e-5..1e16).contains(&a) {
        let _ = write!(out, "{v}");
    } else {
        let _ = write!(out, "{v:e}");
    }
}

/// Writes `s` as a quoted pbrt string, escaping `"`, `\` and control characters.
pub fn format_string(s: &str, out: &mut String) {
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            '\u{8}' => out.push_str("\\b"),
            '\u{c}' => out.push_str("\\f"),
            c => out.push(c),
        }
    }
    out.push('"');
}

impl Formatter {
    /// An empty formatter.
    pub fn new() -> Self {
        Self::default()
    }

    /// The text printed so far.
    pub fn as_str(&self) -> &str {
        &self.out
    }

    /// The printed scene.
    pub fn finish(self) -> String {
        self.out
    }

    fn line_start(&mut self) {
        for _ in 0..self.depth {
            self.out.push_str("    ");
        }
    }

    fn numbers(&mut self, v: &[f64]) {
        self.out.push('[');
        for (i, x) in v.iter().enumerate() {
            if i > 0 && i % PER_LINE == 0 {
                self.out.push('\n');
                self.line_start();
                self.out.push_str("       ");
            }
            self.out.push(' ');
            format_number(*x, &mut self.out);
        }
        self.out.push_str(" ]");
    }

    /// `"type name" [ values ]`
    fn param(&mut self, p: &Param) {
        let _ = write!(self.out, "\"{} {}\" ", p.ty, p.name);
        match &p.values {
            ParamValues::Floats(v) => self.numbers(v),
            ParamValues::Ints(v) => {
                self.out.push('[');
                for (i, x) in v.iter().enumerate() {
                    if i > 0 && i % PER_LINE == 0 {
                        self.out.push('\n');
                        self.line_start();
                        self.out.push_str("       ");
                    }
                    let _ = write!(self.out, " {x}");
                }
                self.out.push_str(" ]");
            }
            ParamValues::Bools(v) => {
                self.out.push('[');
                for x in v {
                    let _ = write!(self.out, " {x}");
                }
                self.out.push_str(" ]");
            }
            ParamValues::Strings(v) => {
                self.out.push('[');
                for x in v {
                    self.out.push(' ');
                    format_string(x, &mut self.out);
                }
                self.out.push_str(" ]");
            }
        }
    }

    fn params(&mut self, params: &ParamSet) {
        self.depth += 1;
        for p in params {
            self.out.push('\n');
            self.line_start();
            self.param(p);
        }
        self.depth -= 1;
    }

    /// `Keyword "a" "b" ...` followed by the parameters, one per line.
    fn named(&mut self, keyword: &str, names: &[&str], params: &ParamSet) {
        self.out.push_str(keyword);
        for n in names {
            self.out.push(' ');
            format_string(n, &mut self.out);
        }
        self.params(params);
    }

    fn triples(&mut self, keyword: &str, groups: &[&[f64]]) {
        self.out.push_str(keyword);
        for g in groups {
            for x in *g {
                self.out.push(' ');
                format_number(*x, &mut self.out);
            }
        }
    }

    fn write_directive(&mut self, directive: &Directive) {
        use Directive as D;
        match directive {
            D::AttributeEnd | D::TransformEnd | D::ObjectEnd => {
                self.depth = self.depth.saturating_sub(1)
            }
            D::WorldBegin => self.out.push('\n'),
            _ => {}
        }
        self.line_start();
        let kw = directive.keyword();
        let no_params = ParamSet::new();
        match directive {
            D::Option(p) => {
                self.out.push_str("Option ");
                self.param(p);
            }
            D::Identity
            | D::ReverseOrientation
            | D::WorldBegin
            | D::AttributeBegin
            | D::AttributeEnd
            | D::TransformBegin
            | D::TransformEnd
            | D::ObjectEnd => self.out.push_str(kw),
            D::Translate(v) | D::Scale(v) => self.triples(kw, &[v]),
            D::Rotate(a, axis) => self.triples(kw, &[&[*a], axis]),
            D::LookAt(e, l, u) => self.triples(kw, &[e, l, u]),
            D::TransformTimes(a, b) => self.triples(kw, &[&[*a, *b]]),
            D::ConcatTransform(m) | D::Transform(m) => {
                self.out.push_str(kw);
                self.out.push(' ');
                self.numbers(m);
            }
            D::ActiveTransform(w) => {
                let _ = write!(self.out, "{kw} {}", w.keyword());
            }
            named => {
                let (strings, params) = named.strings_and_params();
                self.named(kw, &strings, params.unwrap_or(&no_params));
            }
        }
        self.out.push('\n');
        if matches!(
            directive,
            D::AttributeBegin | D::TransformBegin | D::ObjectBegin(_)
        ) {
            self.depth += 1;
        }
    }

    fn comment(&mut self, text: &str) {
        self.line_start();
        self.out.push_str("# ");
        // A comment ends at a newline, so keep it on one line.
        self.out.push_str(&text.replace(['\n', '\r'], " "));
        self.out.push('\n');
    }
}

impl ParserTarget for Formatter {
    fn directive(&mut self, directive: Directive, _loc: &Loc) -> TargetResult {
        self.write_directive(&directive);
        Ok(())
    }

    fn warning(&mut self, loc: &Loc, message: &str) {
        self.comment(&format!("warning at {loc}: {message}"));
    }

    fn file_begin(&mut self, path: &Path, kind: FileKind, _loc: Option<&Loc>) -> TargetResult {
        if kind != FileKind::Main {
            self.comment(&format!("begin {kind:?} {}", path.display()));
        }
        Ok(())
    }

    fn file_end(&mut self, path: &Path, kind: FileKind) -> TargetResult {
        if kind != FileKind::Main {
            self.comment(&format!("end {kind:?} {}", path.display()));
        }
        Ok(())
    }
}
