//! Typed lookups of [`ParamSet`] match by name and type, remember what was used,
//! and report each unused parameter once with its location.

mod common;

use common::record;
use pbrt_format::{
    Directive, FloatOrTexture, ParamSet, SpectrumOrTexture, SpectrumValue, Warnings,
};

fn params_of(text: &str) -> ParamSet {
    match record(text).calls.remove(0).0 {
        Directive::Shape(_, p) => p,
        other => panic!("expected a shape, got {other:?}"),
    }
}

#[test]
fn typed_lookups() {
    let p = params_of(
        "Shape \"x\" \"float a\" [ 1 2 ] \"integer n\" 7 \"bool b\" false \"string s\" [\"u\" \"v\"]\n\
         \"point2 uv\" [ 0 1 2 3 ] \"point3 P\" [ 1 2 3 4 5 6 ] \"vector3 v\" [ 0 0 1 ]\n\
         \"normal N\" [ 0 1 0 ] \"rgb c\" [ .1 .2 .3 ] \"blackbody bb\" 6500\n\
         \"spectrum sp\" [ 300 1 800 2 ] \"spectrum named\" \"metal-Au-k\" \"texture t\" \"tex\"",
    );
    assert_eq!(p.get_float("a"), Some(1.0));
    assert_eq!(p.get_floats("a"), Some(&[1.0, 2.0][..]));
    assert_eq!(p.float_or("missing", 0.25), 0.25);
    assert_eq!((p.get_int("n"), p.int_or("m", -1)), (Some(7), -1));
    assert_eq!((p.get_bool("b"), p.bool_or("c", true)), (Some(false), true));
    assert_eq!(p.get_string("s"), Some("u"));
    assert_eq!(p.get_strings("s").unwrap().len(), 2);
    assert_eq!(p.string_or("none", "dflt"), "dflt");
    assert_eq!(p.get_point2s("uv"), Some(vec![[0.0, 1.0], [2.0, 3.0]]));
    assert_eq!(
        p.get_point3s("P"),
        Some(vec![[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]])
    );
    assert_eq!(p.get_point3("P"), Some([1.0, 2.0, 3.0]));
    assert_eq!(p.get_vector3("v"), Some([0.0, 0.0, 1.0]));
    assert_eq!(p.get_normals("N"), Some(vec![[0.0, 1.0, 0.0]]));
    assert_eq!(p.get_rgb("c"), Some([0.1, 0.2, 0.3]));
    assert_eq!(
        p.get_spectrum("c"),
        Some(SpectrumValue::Rgb([0.1, 0.2, 0.3]))
    );
    assert_eq!(p.get_spectrum("bb"), Some(SpectrumValue::Blackbody(6500.0)));
    assert_eq!(
        p.get_spectrum("sp"),
        Some(SpectrumValue::Samples(&[300.0, 1.0, 800.0, 2.0]))
    );
    assert_eq!(
        p.get_spectrum("named"),
        Some(SpectrumValue::Named("metal-Au-k"))
    );
    assert_eq!(p.get_texture("t"), Some("tex"));
    assert_eq!(p.unused().count(), 0);
}

#[test]
fn lookups_match_type_as_well_as_name() {
    let p = params_of("Shape \"x\" \"integer radius\" 2 \"float fov\" 30");
    assert_eq!(p.get_float("radius"), None);
    assert_eq!(p.get_int("fov"), None);
    assert_eq!(p.get_rgb("fov"), None);
    let unused: Vec<&str> = p.unused().map(|q| q.name.as_str()).collect();
    assert_eq!(
        unused,
        ["radius", "fov"],
        "failed lookups must not mark parameters used"
    );
    assert_eq!(p.find("radius").map(|q| q.is_used()), Some(false));
    p.mark_used("radius");
    assert_eq!(p.unused().count(), 1);
}

#[test]
fn float_or_texture_and_spectrum_or_texture() {
    let p = params_of("Shape \"x\" \"float roughness\" .1 \"texture reflectance\" \"checks\"");
    assert_eq!(
        p.get_float_or_texture("roughness"),
        Some(FloatOrTexture::Value(0.1))
    );
    assert_eq!(
        p.get_spectrum_or_texture("reflectance"),
        Some(SpectrumOrTexture::Texture("checks"))
    );
    assert_eq!(
        p.get_float_or_texture("reflectance"),
        Some(FloatOrTexture::Texture("checks"))
    );
    assert_eq!(p.get_spectrum_or_texture("missing"), None);
    let q = params_of("Shape \"x\" \"rgb reflectance\" [ 1 0 0 ]");
    assert_eq!(
        q.get_spectrum_or_texture("reflectance"),
        Some(SpectrumOrTexture::Value(SpectrumValue::Rgb([
            1.0, 0.0, 0.0
        ])))
    );
}

#[test]
fn unused_parameters_are_warned_once_with_their_location() {
    let p = params_of(
        "Shape \"sphere\"\n  \"float radius\" 1\n  \"float zmin\" -1\n  \"string bogus\" \"x\"",
    );
    let mut w = Warnings::new();
    assert_eq!(p.get_float("radius"), Some(1.0));
    p.finish("Shape \"sphere\"", &mut w).unwrap();
    p.finish("Shape \"sphere\"", &mut w).unwrap(); // a second use of the same list
    let shown: Vec<String> = w.iter().map(ToString::to_string).collect();
    assert_eq!(
        shown,
        [
            "test.pbrt:3:3: warning: Shape \"sphere\": parameter \"float zmin\" is not used",
            "test.pbrt:4:3: warning: Shape \"sphere\": parameter \"string bogus\" is not used",
        ]
    );
}

#[test]
fn a_single_value_parameter_with_none_or_several_is_an_error_at_its_location() {
    // pbrt-v4's ParameterDictionary refuses these ("No values provided",
    // "More than one value provided for parameter").
    let cases = [
        (
            "\"float radius\" [ ]",
            "\"float radius\" takes one value, got 0",
        ),
        (
            "\"float radius\" [ 1 2 ]",
            "\"float radius\" takes one value, got 2",
        ),
        (
            "\"string radius\" [ \"a\" \"b\" ]",
            "\"string radius\" takes one value, got 2",
        ),
        (
            "\"integer radius\" [ ]",
            "\"integer radius\" takes one value, got 0",
        ),
        (
            "\"bool radius\" [ true false ]",
            "\"bool radius\" takes one value, got 2",
        ),
        (
            "\"point3 radius\" [ 0 0 0 1 1 1 ]",
            "\"point3 radius\" takes 3 values (one item), got 6",
        ),
    ];
    for (param, message) in cases {
        let p = params_of(&format!("Shape \"sphere\"\n  {param}"));
        let _ = p.get_float("radius");
        let _ = p.get_string("radius");
        let _ = p.get_int("radius");
        let _ = p.get_bool("radius");
        let _ = p.get_point3("radius");
        let mut w = Warnings::new();
        let e = p
            .finish("Shape \"sphere\"", &mut w)
            .unwrap_err()
            .to_string();
        assert_eq!(
            e,
            format!("test.pbrt:2:3: Shape \"sphere\": parameter {message}")
        );
    }
    // Array reads take any count, and one value is right for a single read.
    let p = params_of("Shape \"sphere\" \"float radius\" [ 1 2 ] \"float zmin\" 1");
    assert_eq!(p.get_floats("radius"), Some(&[1.0, 2.0][..]));
    assert_eq!(p.get_float("zmin"), Some(1.0));
    assert!(p.finish("Shape \"sphere\"", &mut Warnings::new()).is_ok());
}

#[test]
fn clones_keep_use_and_push_rejects_duplicates() {
    let p = params_of("Shape \"x\" \"float a\" 1 \"float b\" 2");
    p.get_float("a");
    let mut q = p.clone();
    assert_eq!(q.unused().count(), 1);
    let dup = p.find("a").unwrap().clone();
    assert!(q.push(dup).is_err());
    assert_eq!(q.len(), 2);
}
