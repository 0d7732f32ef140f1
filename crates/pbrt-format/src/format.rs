//! [`Formatter`]: a target that prints a parsed scene back as pbrt-v4 text.
//!
//! The output is one file with `Include`d/`Import`ed text inlined (marked by
//! comments), blocks indented, parameters one per line, legacy type names in
//! canonical form (`point` becomes `point3`) and numbers in their shortest exact
//! form. Parsing the output gives the same directives as parsing the input.

use std::fmt::Write;
use std::path::Path;

use crate::call::{Call, CallSink};
use crate::target::TargetResult;
use crate::{FileKind, Loc, Param, ParamSet, ParamValues};

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

    fn write_call(&mut self, call: &Call) {
        match call {
            Call::AttributeEnd | Call::TransformEnd | Call::ObjectEnd => {
                self.depth = self.depth.saturating_sub(1)
            }
            Call::WorldBegin => self.out.push('\n'),
            _ => {}
        }
        self.line_start();
        match call {
            Call::Option(p) => {
                self.out.push_str("Option ");
                self.param(p);
            }
            Call::ColorSpace(n) => self.named("ColorSpace", &[n], &ParamSet::new()),
            Call::Identity => self.out.push_str("Identity"),
            Call::Translate(d) => self.triples("Translate", &[d]),
            Call::Scale(s) => self.triples("Scale", &[s]),
            Call::Rotate(a, axis) => self.triples("Rotate", &[&[*a], axis]),
            Call::LookAt(e, l, u) => self.triples("LookAt", &[e, l, u]),
            Call::ConcatTransform(m) => {
                self.out.push_str("ConcatTransform ");
                self.numbers(m);
            }
            Call::Transform(m) => {
                self.out.push_str("Transform ");
                self.numbers(m);
            }
            Call::CoordinateSystem(n) => self.named("CoordinateSystem", &[n], &ParamSet::new()),
            Call::CoordSysTransform(n) => self.named("CoordSysTransform", &[n], &ParamSet::new()),
            Call::ActiveTransform(w) => {
                let _ = write!(self.out, "ActiveTransform {}", w.keyword());
            }
            Call::TransformTimes(a, b) => self.triples("TransformTimes", &[&[*a, *b]]),
            Call::ReverseOrientation => self.out.push_str("ReverseOrientation"),
            Call::Camera(n, p) => self.named("Camera", &[n], p),
            Call::Film(n, p) => self.named("Film", &[n], p),
            Call::Sampler(n, p) => self.named("Sampler", &[n], p),
            Call::Integrator(n, p) => self.named("Integrator", &[n], p),
            Call::PixelFilter(n, p) => self.named("PixelFilter", &[n], p),
            Call::Accelerator(n, p) => self.named("Accelerator", &[n], p),
            Call::MakeNamedMedium(n, p) => self.named("MakeNamedMedium", &[n], p),
            Call::MediumInterface(i, o) => self.named("MediumInterface", &[i, o], &ParamSet::new()),
            Call::WorldBegin => self.out.push_str("WorldBegin"),
            Call::AttributeBegin => self.out.push_str("AttributeBegin"),
            Call::AttributeEnd => self.out.push_str("AttributeEnd"),
            Call::TransformBegin => self.out.push_str("TransformBegin"),
            Call::TransformEnd => self.out.push_str("TransformEnd"),
            Call::Attribute(n, p) => self.named("Attribute", &[n], p),
            Call::Shape(n, p) => self.named("Shape", &[n], p),
            Call::Material(n, p) => self.named("Material", &[n], p),
            Call::MakeNamedMaterial(n, p) => self.named("MakeNamedMaterial", &[n], p),
            Call::NamedMaterial(n) => self.named("NamedMaterial", &[n], &ParamSet::new()),
            Call::Texture(n, t, c, p) => self.named("Texture", &[n, t, c], p),
            Call::LightSource(n, p) => self.named("LightSource", &[n], p),
            Call::AreaLightSource(n, p) => self.named("AreaLightSource", &[n], p),
            Call::ObjectBegin(n) => self.named("ObjectBegin", &[n], &ParamSet::new()),
            Call::ObjectEnd => self.out.push_str("ObjectEnd"),
            Call::ObjectInstance(n) => self.named("ObjectInstance", &[n], &ParamSet::new()),
        }
        self.out.push('\n');
        if matches!(
            call,
            Call::AttributeBegin | Call::TransformBegin | Call::ObjectBegin(_)
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

impl CallSink for Formatter {
    fn call(&mut self, call: Call, _loc: &Loc) -> TargetResult {
        self.write_call(&call);
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
