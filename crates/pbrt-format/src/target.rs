//! [`ParserTarget`]: the interface between the parser and whoever consumes a scene.
//!
//! As in pbrt-v4, the parser knows only syntax: it calls one method per directive,
//! in file order, with the directive's arguments, its [`ParamSet`] and the
//! [`Loc`] of the directive's keyword. Graphics state, named objects and
//! scene-building errors belong to the target. A target method returning an error
//! stops the parse, and the error is returned from [`crate::parse_file`].
//!
//! All numbers are `f64` exactly as written (the parser does not round to `f32`).

use std::path::Path;

use crate::{Loc, Param, ParamSet, ParseError};

/// Result type of every target method.
pub type TargetResult = Result<(), ParseError>;

/// The argument of `ActiveTransform`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ActiveTransform {
    /// `ActiveTransform StartTime`
    StartTime,
    /// `ActiveTransform EndTime`
    EndTime,
    /// `ActiveTransform All`
    All,
}

impl ActiveTransform {
    /// The keyword as written in scene files.
    pub fn keyword(self) -> &'static str {
        match self {
            ActiveTransform::StartTime => "StartTime",
            ActiveTransform::EndTime => "EndTime",
            ActiveTransform::All => "All",
        }
    }
}

/// How a file came to be parsed (see [`ParserTarget::file_begin`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FileKind {
    /// The top-level file given to [`crate::parse_file`] or [`crate::parse_str`].
    Main,
    /// A file named by `Include`: its text is parsed as if it stood in place of the
    /// directive.
    Include,
    /// A file named by `Import`. The parser treats it like `Include`; pbrt-v4 gives
    /// it a copy of the graphics state whose changes do not flow back (only named
    /// materials, textures, media and object definitions do), so a builder should
    /// save its graphics state in `file_begin` and restore it in `file_end`.
    Import,
}

/// Receives the directives of a scene, one method per directive.
///
/// Every method gets the location of the directive keyword. Methods taking a
/// [`ParamSet`] receive it by value (it remembers which parameters lookups used;
/// see [`ParamSet::warn_unused`]). Only `file_begin`, `file_end` and
/// `end_of_files` have default (empty) implementations.
///
/// Implementing [`crate::CallSink`] instead gives a type this trait through a
/// blanket impl, receiving every directive as one [`crate::Call`] value.
pub trait ParserTarget {
    /// `Option "type name" value`: a global rendering option (e.g. `"bool
    /// disablepixeljitter" true`), as a single parameter.
    fn option(&mut self, param: Param, loc: &Loc) -> TargetResult;
    /// `ColorSpace "name"`.
    fn color_space(&mut self, name: &str, loc: &Loc) -> TargetResult;
    /// `Identity`.
    fn identity(&mut self, loc: &Loc) -> TargetResult;
    /// `Translate dx dy dz`.
    fn translate(&mut self, d: [f64; 3], loc: &Loc) -> TargetResult;
    /// `Scale sx sy sz`.
    fn scale(&mut self, s: [f64; 3], loc: &Loc) -> TargetResult;
    /// `Rotate angle_degrees ax ay az`.
    fn rotate(&mut self, angle_deg: f64, axis: [f64; 3], loc: &Loc) -> TargetResult;
    /// `LookAt ex ey ez  lx ly lz  ux uy uz`.
    fn look_at(&mut self, eye: [f64; 3], look: [f64; 3], up: [f64; 3], loc: &Loc) -> TargetResult;
    /// `ConcatTransform [16 numbers]`, in file order (pbrt's column-major layout:
    /// elements 12..15 hold the translation).
    fn concat_transform(&mut self, m: [f64; 16], loc: &Loc) -> TargetResult;
    /// `Transform [16 numbers]`, in file order (as for `concat_transform`).
    fn transform(&mut self, m: [f64; 16], loc: &Loc) -> TargetResult;
    /// `CoordinateSystem "name"`.
    fn coordinate_system(&mut self, name: &str, loc: &Loc) -> TargetResult;
    /// `CoordSysTransform "name"` (`"camera"` and `"world"` are predefined by pbrt).
    fn coord_sys_transform(&mut self, name: &str, loc: &Loc) -> TargetResult;
    /// `ActiveTransform StartTime|EndTime|All`.
    fn active_transform(&mut self, which: ActiveTransform, loc: &Loc) -> TargetResult;
    /// `TransformTimes start end`.
    fn transform_times(&mut self, start: f64, end: f64, loc: &Loc) -> TargetResult;
    /// `ReverseOrientation`.
    fn reverse_orientation(&mut self, loc: &Loc) -> TargetResult;
    /// `Camera "type" params`.
    fn camera(&mut self, ty: &str, params: ParamSet, loc: &Loc) -> TargetResult;
    /// `Film "type" params`.
    fn film(&mut self, ty: &str, params: ParamSet, loc: &Loc) -> TargetResult;
    /// `Sampler "type" params`.
    fn sampler(&mut self, ty: &str, params: ParamSet, loc: &Loc) -> TargetResult;
    /// `Integrator "type" params`.
    fn integrator(&mut self, ty: &str, params: ParamSet, loc: &Loc) -> TargetResult;
    /// `PixelFilter "type" params`.
    fn pixel_filter(&mut self, ty: &str, params: ParamSet, loc: &Loc) -> TargetResult;
    /// `Accelerator "type" params`.
    fn accelerator(&mut self, ty: &str, params: ParamSet, loc: &Loc) -> TargetResult;
    /// `MakeNamedMedium "name" params` (the medium type is `"string type"`).
    fn make_named_medium(&mut self, name: &str, params: ParamSet, loc: &Loc) -> TargetResult;
    /// `MediumInterface "inside" "outside"`; a single name sets both.
    fn medium_interface(&mut self, inside: &str, outside: &str, loc: &Loc) -> TargetResult;
    /// `WorldBegin`.
    fn world_begin(&mut self, loc: &Loc) -> TargetResult;
    /// `AttributeBegin`.
    fn attribute_begin(&mut self, loc: &Loc) -> TargetResult;
    /// `AttributeEnd`.
    fn attribute_end(&mut self, loc: &Loc) -> TargetResult;
    /// `TransformBegin` (deprecated in pbrt-v4, which parses it as `AttributeBegin`;
    /// strictly it saves only the transformation).
    fn transform_begin(&mut self, loc: &Loc) -> TargetResult;
    /// `TransformEnd` (see [`ParserTarget::transform_begin`]).
    fn transform_end(&mut self, loc: &Loc) -> TargetResult;
    /// `Attribute "shape"|"light"|"material"|"medium"|"texture" params`: default
    /// parameters for later directives of that kind.
    fn attribute(&mut self, target: &str, params: ParamSet, loc: &Loc) -> TargetResult;
    /// `Shape "type" params`.
    fn shape(&mut self, ty: &str, params: ParamSet, loc: &Loc) -> TargetResult;
    /// `Material "type" params`.
    fn material(&mut self, ty: &str, params: ParamSet, loc: &Loc) -> TargetResult;
    /// `MakeNamedMaterial "name" params` (the material type is `"string type"`).
    fn make_named_material(&mut self, name: &str, params: ParamSet, loc: &Loc) -> TargetResult;
    /// `NamedMaterial "name"`.
    fn named_material(&mut self, name: &str, loc: &Loc) -> TargetResult;
    /// `Texture "name" "type" "class" params`; `ty` is `"float"` or `"spectrum"`
    /// (pbrt-v3 files may say `"color"`), `class` is e.g. `"imagemap"`.
    fn texture(
        &mut self,
        name: &str,
        ty: &str,
        class: &str,
        params: ParamSet,
        loc: &Loc,
    ) -> TargetResult;
    /// `LightSource "type" params`.
    fn light_source(&mut self, ty: &str, params: ParamSet, loc: &Loc) -> TargetResult;
    /// `AreaLightSource "type" params`.
    fn area_light_source(&mut self, ty: &str, params: ParamSet, loc: &Loc) -> TargetResult;
    /// `ObjectBegin "name"`.
    fn object_begin(&mut self, name: &str, loc: &Loc) -> TargetResult;
    /// `ObjectEnd`.
    fn object_end(&mut self, loc: &Loc) -> TargetResult;
    /// `ObjectInstance "name"`.
    fn object_instance(&mut self, name: &str, loc: &Loc) -> TargetResult;
    /// A non-fatal problem the parser noticed (e.g. the pbrt-v3 `WorldEnd`, which is
    /// ignored). The target decides whether and how to report it.
    fn warning(&mut self, loc: &Loc, message: &str);

    /// A file starts: the main file (`loc` is `None`), or an included/imported one
    /// (`loc` is the `Include`/`Import` directive). `path` is the path opened (for
    /// [`crate::parse_str`], the name given).
    fn file_begin(&mut self, path: &Path, kind: FileKind, loc: Option<&Loc>) -> TargetResult {
        let _ = (path, kind, loc);
        Ok(())
    }
    /// The file begun by the matching `file_begin` has ended.
    fn file_end(&mut self, path: &Path, kind: FileKind) -> TargetResult {
        let _ = (path, kind);
        Ok(())
    }
    /// The whole scene has been parsed without error (called last, once).
    fn end_of_files(&mut self) -> TargetResult {
        Ok(())
    }
}
