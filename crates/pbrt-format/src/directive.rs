//! Directives as values: their keywords ([`DIRECTIVES`], [`is_directive`]),
//! [`Directive`] (what the parser hands a [`ParserTarget`]) and the
//! [`Recorder`] target that keeps every directive.
//!
//! The [`Recorder`] is what the tests compare against, and what the
//! [`crate::Formatter`] round trip (parse, print, parse again) is checked with.

use std::path::{Path, PathBuf};

use crate::target::TargetResult;
use crate::{ActiveTransform, FileKind, Loc, Param, ParamSet, ParserTarget};

/// Every directive keyword the parser accepts.
pub const DIRECTIVES: &[&str] = &[
    "Accelerator",
    "ActiveTransform",
    "AreaLightSource",
    "Attribute",
    "AttributeBegin",
    "AttributeEnd",
    "Camera",
    "ColorSpace",
    "ConcatTransform",
    "CoordinateSystem",
    "CoordSysTransform",
    "Film",
    "Identity",
    "Import",
    "Include",
    "Integrator",
    "LightSource",
    "LookAt",
    "MakeNamedMaterial",
    "MakeNamedMedium",
    "Material",
    "MediumInterface",
    "NamedMaterial",
    "ObjectBegin",
    "ObjectEnd",
    "ObjectInstance",
    "Option",
    "PixelFilter",
    "ReverseOrientation",
    "Rotate",
    "Sampler",
    "Scale",
    "Shape",
    "Texture",
    "Transform",
    "TransformBegin",
    "TransformEnd",
    "TransformTimes",
    "Translate",
    "WorldBegin",
    "WorldEnd",
];

/// Whether `word` is a directive keyword.
pub fn is_directive(word: &str) -> bool {
    DIRECTIVES.contains(&word)
}

/// One directive with its typed arguments, as [`ParserTarget::directive`]
/// receives it (the location comes separately).
///
/// All numbers are `f64` exactly as written (the parser does not round to
/// `f32`). Methods taking a [`ParamSet`] own it: it remembers which parameters
/// lookups used (see [`ParamSet::finish`]).
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)] // each variant is the directive of the same name
pub enum Directive {
    Option(Param),
    ColorSpace(String),
    Identity,
    Translate([f64; 3]),
    Scale([f64; 3]),
    /// Angle in degrees, axis.
    Rotate(f64, [f64; 3]),
    /// Eye, look-at point, up.
    LookAt([f64; 3], [f64; 3], [f64; 3]),
    ConcatTransform([f64; 16]),
    Transform([f64; 16]),
    CoordinateSystem(String),
    CoordSysTransform(String),
    ActiveTransform(ActiveTransform),
    TransformTimes(f64, f64),
    ReverseOrientation,
    Camera(String, ParamSet),
    Film(String, ParamSet),
    Sampler(String, ParamSet),
    Integrator(String, ParamSet),
    PixelFilter(String, ParamSet),
    Accelerator(String, ParamSet),
    MakeNamedMedium(String, ParamSet),
    /// Inside, outside.
    MediumInterface(String, String),
    WorldBegin,
    AttributeBegin,
    AttributeEnd,
    TransformBegin,
    TransformEnd,
    Attribute(String, ParamSet),
    Shape(String, ParamSet),
    Material(String, ParamSet),
    MakeNamedMaterial(String, ParamSet),
    NamedMaterial(String),
    /// Name, type (`float`/`spectrum`), class (`imagemap`, ...), parameters.
    Texture(String, String, String, ParamSet),
    LightSource(String, ParamSet),
    AreaLightSource(String, ParamSet),
    ObjectBegin(String),
    ObjectEnd,
    ObjectInstance(String),
}

impl Directive {
    /// The directive's parameter list, for the directives that have one.
    pub fn params(&self) -> Option<&ParamSet> {
        self.strings_and_params().1
    }

    /// The directive's quoted string arguments, in file order, and its
    /// parameter list (empty and `None` for directives whose arguments are
    /// numbers, a keyword or a single parameter).
    pub fn strings_and_params(&self) -> (Vec<&str>, Option<&ParamSet>) {
        use Directive as D;
        match self {
            D::ColorSpace(n)
            | D::CoordinateSystem(n)
            | D::CoordSysTransform(n)
            | D::NamedMaterial(n)
            | D::ObjectBegin(n)
            | D::ObjectInstance(n) => (vec![n], None),
            D::MediumInterface(i, o) => (vec![i, o], None),
            D::Texture(n, t, c, p) => (vec![n, t, c], Some(p)),
            D::Camera(n, p)
            | D::Film(n, p)
            | D::Sampler(n, p)
            | D::Integrator(n, p)
            | D::PixelFilter(n, p)
            | D::Accelerator(n, p)
            | D::MakeNamedMedium(n, p)
            | D::Attribute(n, p)
            | D::Shape(n, p)
            | D::Material(n, p)
            | D::MakeNamedMaterial(n, p)
            | D::LightSource(n, p)
            | D::AreaLightSource(n, p) => (vec![n], Some(p)),
            _ => (Vec::new(), None),
        }
    }

    /// The directive's keyword as written in scene files (for messages).
    pub fn keyword(&self) -> &'static str {
        match self {
            Directive::Option(..) => "Option",
            Directive::ColorSpace(..) => "ColorSpace",
            Directive::Identity => "Identity",
            Directive::Translate(..) => "Translate",
            Directive::Scale(..) => "Scale",
            Directive::Rotate(..) => "Rotate",
            Directive::LookAt(..) => "LookAt",
            Directive::ConcatTransform(..) => "ConcatTransform",
            Directive::Transform(..) => "Transform",
            Directive::CoordinateSystem(..) => "CoordinateSystem",
            Directive::CoordSysTransform(..) => "CoordSysTransform",
            Directive::ActiveTransform(..) => "ActiveTransform",
            Directive::TransformTimes(..) => "TransformTimes",
            Directive::ReverseOrientation => "ReverseOrientation",
            Directive::Camera(..) => "Camera",
            Directive::Film(..) => "Film",
            Directive::Sampler(..) => "Sampler",
            Directive::Integrator(..) => "Integrator",
            Directive::PixelFilter(..) => "PixelFilter",
            Directive::Accelerator(..) => "Accelerator",
            Directive::MakeNamedMedium(..) => "MakeNamedMedium",
            Directive::MediumInterface(..) => "MediumInterface",
            Directive::WorldBegin => "WorldBegin",
            Directive::AttributeBegin => "AttributeBegin",
            Directive::AttributeEnd => "AttributeEnd",
            Directive::TransformBegin => "TransformBegin",
            Directive::TransformEnd => "TransformEnd",
            Directive::Attribute(..) => "Attribute",
            Directive::Shape(..) => "Shape",
            Directive::Material(..) => "Material",
            Directive::MakeNamedMaterial(..) => "MakeNamedMaterial",
            Directive::NamedMaterial(..) => "NamedMaterial",
            Directive::Texture(..) => "Texture",
            Directive::LightSource(..) => "LightSource",
            Directive::AreaLightSource(..) => "AreaLightSource",
            Directive::ObjectBegin(..) => "ObjectBegin",
            Directive::ObjectEnd => "ObjectEnd",
            Directive::ObjectInstance(..) => "ObjectInstance",
        }
    }
}

/// A target that records every directive, warning and file event.
#[derive(Clone, Debug, Default)]
pub struct Recorder {
    /// The directives in order, with their locations.
    pub calls: Vec<(Directive, Loc)>,
    /// Parser warnings in order.
    pub warnings: Vec<(Loc, String)>,
    /// `(path, kind, begin)` for every `file_begin` (`begin = true`) and `file_end`.
    pub files: Vec<(PathBuf, FileKind, bool)>,
}

impl Recorder {
    /// An empty recorder.
    pub fn new() -> Self {
        Self::default()
    }

    /// The directives without their locations.
    pub fn calls_only(&self) -> Vec<Directive> {
        self.calls.iter().map(|(c, _)| c.clone()).collect()
    }

    /// How many recorded directives satisfy `pred`.
    pub fn count(&self, pred: impl Fn(&Directive) -> bool) -> usize {
        self.calls.iter().filter(|(c, _)| pred(c)).count()
    }
}

impl ParserTarget for Recorder {
    fn directive(&mut self, directive: Directive, loc: &Loc) -> TargetResult {
        self.calls.push((directive, loc.clone()));
        Ok(())
    }
    fn warning(&mut self, loc: &Loc, message: &str) {
        self.warnings.push((loc.clone(), message.to_string()));
    }
    fn file_begin(&mut self, path: &Path, kind: FileKind, _loc: Option<&Loc>) -> TargetResult {
        self.files.push((path.to_path_buf(), kind, true));
        Ok(())
    }
    fn file_end(&mut self, path: &Path, kind: FileKind) -> TargetResult {
        self.files.push((path.to_path_buf(), kind, false));
        Ok(())
    }
}
