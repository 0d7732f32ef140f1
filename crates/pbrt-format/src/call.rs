//! Directives as values: [`Call`], the [`CallSink`] shortcut for writing a
//! [`ParserTarget`], [`replay`], and the [`Recorder`] target that keeps every call.
//!
//! The [`Recorder`] is what the tests compare against, and what the
//! [`crate::Formatter`] round trip (parse, print, parse again) is checked with.

use std::path::{Path, PathBuf};

use crate::target::TargetResult;
use crate::{ActiveTransform, FileKind, Loc, Param, ParamSet, ParserTarget};

/// One directive with its arguments (everything a [`ParserTarget`] method receives
/// except the location).
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)] // each variant is the directive of the same name
pub enum Call {
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

/// A simpler way to write a [`ParserTarget`]: one method receiving every directive
/// as a [`Call`]. Every `CallSink` is a `ParserTarget` (blanket impl).
pub trait CallSink {
    /// One directive.
    fn call(&mut self, call: Call, loc: &Loc) -> TargetResult;
    /// A parser warning (see [`ParserTarget::warning`]).
    fn warning(&mut self, loc: &Loc, message: &str);
    /// See [`ParserTarget::file_begin`].
    fn file_begin(&mut self, path: &Path, kind: FileKind, loc: Option<&Loc>) -> TargetResult {
        let _ = (path, kind, loc);
        Ok(())
    }
    /// See [`ParserTarget::file_end`].
    fn file_end(&mut self, path: &Path, kind: FileKind) -> TargetResult {
        let _ = (path, kind);
        Ok(())
    }
}

macro_rules! sink_methods {
    ($( $method:ident ( $($arg:ident : $ty:ty),* ) => $call:expr ;)*) => {
        $(
            fn $method(&mut self, $($arg: $ty,)* loc: &Loc) -> TargetResult {
                self.call($call, loc)
            }
        )*
    };
}

impl<S: CallSink> ParserTarget for S {
    sink_methods! {
        option(p: Param) => Call::Option(p);
        color_space(n: &str) => Call::ColorSpace(n.into());
        identity() => Call::Identity;
        translate(d: [f64; 3]) => Call::Translate(d);
        scale(s: [f64; 3]) => Call::Scale(s);
        rotate(a: f64, axis: [f64; 3]) => Call::Rotate(a, axis);
        look_at(e: [f64; 3], l: [f64; 3], u: [f64; 3]) => Call::LookAt(e, l, u);
        concat_transform(m: [f64; 16]) => Call::ConcatTransform(m);
        transform(m: [f64; 16]) => Call::Transform(m);
        coordinate_system(n: &str) => Call::CoordinateSystem(n.into());
        coord_sys_transform(n: &str) => Call::CoordSysTransform(n.into());
        active_transform(w: ActiveTransform) => Call::ActiveTransform(w);
        transform_times(s: f64, e: f64) => Call::TransformTimes(s, e);
        reverse_orientation() => Call::ReverseOrientation;
        camera(t: &str, p: ParamSet) => Call::Camera(t.into(), p);
        film(t: &str, p: ParamSet) => Call::Film(t.into(), p);
        sampler(t: &str, p: ParamSet) => Call::Sampler(t.into(), p);
        integrator(t: &str, p: ParamSet) => Call::Integrator(t.into(), p);
        pixel_filter(t: &str, p: ParamSet) => Call::PixelFilter(t.into(), p);
        accelerator(t: &str, p: ParamSet) => Call::Accelerator(t.into(), p);
        make_named_medium(n: &str, p: ParamSet) => Call::MakeNamedMedium(n.into(), p);
        medium_interface(i: &str, o: &str) => Call::MediumInterface(i.into(), o.into());
        world_begin() => Call::WorldBegin;
        attribute_begin() => Call::AttributeBegin;
        attribute_end() => Call::AttributeEnd;
        transform_begin() => Call::TransformBegin;
        transform_end() => Call::TransformEnd;
        attribute(t: &str, p: ParamSet) => Call::Attribute(t.into(), p);
        shape(t: &str, p: ParamSet) => Call::Shape(t.into(), p);
        material(t: &str, p: ParamSet) => Call::Material(t.into(), p);
        make_named_material(n: &str, p: ParamSet) => Call::MakeNamedMaterial(n.into(), p);
        named_material(n: &str) => Call::NamedMaterial(n.into());
        texture(n: &str, t: &str, c: &str, p: ParamSet) =>
            Call::Texture(n.into(), t.into(), c.into(), p);
        light_source(t: &str, p: ParamSet) => Call::LightSource(t.into(), p);
        area_light_source(t: &str, p: ParamSet) => Call::AreaLightSource(t.into(), p);
        object_begin(n: &str) => Call::ObjectBegin(n.into());
        object_end() => Call::ObjectEnd;
        object_instance(n: &str) => Call::ObjectInstance(n.into());
    }

    fn warning(&mut self, loc: &Loc, message: &str) {
        CallSink::warning(self, loc, message)
    }
    fn file_begin(&mut self, path: &Path, kind: FileKind, loc: Option<&Loc>) -> TargetResult {
        CallSink::file_begin(self, path, kind, loc)
    }
    fn file_end(&mut self, path: &Path, kind: FileKind) -> TargetResult {
        CallSink::file_end(self, path, kind)
    }
}

/// Sends one [`Call`] to the matching method of `target`.
pub fn replay<T: ParserTarget + ?Sized>(call: Call, loc: &Loc, target: &mut T) -> TargetResult {
    let t = target;
    match call {
        Call::Option(p) => t.option(p, loc),
        Call::ColorSpace(n) => t.color_space(&n, loc),
        Call::Identity => t.identity(loc),
        Call::Translate(d) => t.translate(d, loc),
        Call::Scale(s) => t.scale(s, loc),
        Call::Rotate(a, axis) => t.rotate(a, axis, loc),
        Call::LookAt(e, l, u) => t.look_at(e, l, u, loc),
        Call::ConcatTransform(m) => t.concat_transform(m, loc),
        Call::Transform(m) => t.transform(m, loc),
        Call::CoordinateSystem(n) => t.coordinate_system(&n, loc),
        Call::CoordSysTransform(n) => t.coord_sys_transform(&n, loc),
        Call::ActiveTransform(w) => t.active_transform(w, loc),
        Call::TransformTimes(s, e) => t.transform_times(s, e, loc),
        Call::ReverseOrientation => t.reverse_orientation(loc),
        Call::Camera(n, p) => t.camera(&n, p, loc),
        Call::Film(n, p) => t.film(&n, p, loc),
        Call::Sampler(n, p) => t.sampler(&n, p, loc),
        Call::Integrator(n, p) => t.integrator(&n, p, loc),
        Call::PixelFilter(n, p) => t.pixel_filter(&n, p, loc),
        Call::Accelerator(n, p) => t.accelerator(&n, p, loc),
        Call::MakeNamedMedium(n, p) => t.make_named_medium(&n, p, loc),
        Call::MediumInterface(i, o) => t.medium_interface(&i, &o, loc),
        Call::WorldBegin => t.world_begin(loc),
        Call::AttributeBegin => t.attribute_begin(loc),
        Call::AttributeEnd => t.attribute_end(loc),
        Call::TransformBegin => t.transform_begin(loc),
        Call::TransformEnd => t.transform_end(loc),
        Call::Attribute(n, p) => t.attribute(&n, p, loc),
        Call::Shape(n, p) => t.shape(&n, p, loc),
        Call::Material(n, p) => t.material(&n, p, loc),
        Call::MakeNamedMaterial(n, p) => t.make_named_material(&n, p, loc),
        Call::NamedMaterial(n) => t.named_material(&n, loc),
        Call::Texture(n, ty, c, p) => t.texture(&n, &ty, &c, p, loc),
        Call::LightSource(n, p) => t.light_source(&n, p, loc),
        Call::AreaLightSource(n, p) => t.area_light_source(&n, p, loc),
        Call::ObjectBegin(n) => t.object_begin(&n, loc),
        Call::ObjectEnd => t.object_end(loc),
        Call::ObjectInstance(n) => t.object_instance(&n, loc),
    }
}

/// A target that records every call, warning and file event.
#[derive(Clone, Debug, Default)]
pub struct Recorder {
    /// The directives in order, with their locations.
    pub calls: Vec<(Call, Loc)>,
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

    /// The calls without their locations.
    pub fn calls_only(&self) -> Vec<Call> {
        self.calls.iter().map(|(c, _)| c.clone()).collect()
    }

    /// How many recorded calls satisfy `pred`.
    pub fn count(&self, pred: impl Fn(&Call) -> bool) -> usize {
        self.calls.iter().filter(|(c, _)| pred(c)).count()
    }
}

impl CallSink for Recorder {
    fn call(&mut self, call: Call, loc: &Loc) -> TargetResult {
        self.calls.push((call, loc.clone()));
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
