//! The [`Formatter`] round trip: parsing its output gives the same calls as
//! parsing the original, for every directive and every shared scene file.

mod common;

use pbrt_format::{Formatter, Recorder, parse_file, parse_str};

/// A scene using every directive, legacy spellings, escapes, long lists and
/// numbers of every magnitude.
const EVERYTHING: &str = r#"
Option "bool disablepixeljitter" true
ColorSpace "srgb"
LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" 45
Film "rgb" "integer xresolution" [ 64 ] "integer yresolution" 48 "string filename" "out.exr"
Sampler "zsobol" "integer pixelsamples" 16
Integrator "path" "integer maxdepth" 5
PixelFilter "gaussian"
Accelerator "bvh"
TransformTimes 0 1
ActiveTransform EndTime
Translate 1e-30 -2.5e20 -0
ActiveTransform All
MakeNamedMedium "fog" "string type" "homogeneous" "rgb sigma_a" [ .1 .2 .3 ]
WorldBegin
Attribute "shape" "float radius" 2
AttributeBegin
  Identity
  Transform [ 1 0 0 0 0 1 0 0 0 0 1 0 4 5 6 1 ]
  ConcatTransform [ 2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 1 ]
  Rotate 33.3 0.1 0.2 0.3
  Scale -1 1 1
  CoordinateSystem "here"
  CoordSysTransform "camera"
  ReverseOrientation
  MediumInterface "fog" ""
  Texture "t" "spectrum" "checkerboard" "color tex1" [ 1 0 0 ] "rgb tex2" [ 0 1 0 ]
  Material "conductor" "spectrum eta" "metal-Cu-eta" "spectrum k" [ 400 1 700 2 ]
  MakeNamedMaterial "m \"quoted\"\\" "string type" "diffuse" "texture reflectance" "t"
  NamedMaterial "m \"quoted\"\\"
  LightSource "spot" "blackbody I" 5500 "point from" [ 0 5 9 ] "point3 to" [ 0 0 0 ]
  AreaLightSource "diffuse" "rgb L" [ 7 7 7 ] "bool twosided" "true"
  TransformBegin
    Shape "trianglemesh" "point P" [ 0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1 ]
      "integer indices" [ 0 1 2 0 2 3 4 5 6 4 6 7 0 1 5 0 5 4 ]
      "normal N" [ 0 0 1 ] "vector2 d" [ 1 2 ] "vector S" [ 1 0 0 ] "point2 uv" [ 0.125 1 ]
  TransformEnd
  ObjectBegin "thing"
    Shape "sphere" "float radius" 0.333333333333333314829616256247 "bool b" [ true false ]
  ObjectEnd
  ObjectInstance "thing"
AttributeEnd
"#;

fn record_text(text: &str) -> Recorder {
    let mut rec = Recorder::new();
    if let Err(e) = parse_str(text, "formatted.pbrt", &mut rec) {
        panic!("formatted text does not parse: {e}\n{text}");
    }
    rec
}

fn format_text(text: &str) -> String {
    let mut f = Formatter::new();
    parse_str(text, "in.pbrt", &mut f).unwrap();
    f.finish()
}

#[test]
fn every_directive_survives_the_round_trip() {
    let original = common::calls(EVERYTHING);
    assert_eq!(original.len(), 40);
    let printed = format_text(EVERYTHING);
    assert_eq!(record_text(&printed).calls_only(), original, "{printed}");
    assert_eq!(
        format_text(&printed),
        printed,
        "formatting is not a fixed point"
    );
}

#[test]
fn formatted_output_is_stable() {
    let printed = format_text(
        "LookAt 0 0 5 0 0 0 0 1 0 WorldBegin AttributeBegin Material \"diffuse\" \
         \"color reflectance\" [ .5 .5 .5 ] Shape \"disk\" \"float radius\" 1e-7 \
         \"integer n\" 3 AttributeEnd",
    );
    let want = "LookAt 0 0 5 0 0 0 0 1 0\n\
                \n\
                WorldBegin\n\
                AttributeBegin\n\
                \x20   Material \"diffuse\"\n\
                \x20       \"rgb reflectance\" [ 0.5 0.5 0.5 ]\n\
                \x20   Shape \"disk\"\n\
                \x20       \"float radius\" [ 1e-7 ]\n\
                \x20       \"integer n\" [ 3 ]\n\
                AttributeEnd\n";
    assert_eq!(printed, want);
}

#[test]
fn every_scene_file_survives_the_round_trip() {
    let Some(dir) = common::scenes_dir() else {
        return;
    };
    for path in common::pbrt_files(&dir) {
        let mut original = Recorder::new();
        parse_file(&path, &mut original).unwrap();
        let mut f = Formatter::new();
        parse_file(&path, &mut f).unwrap();
        let printed = f.finish();
        let again = record_text(&printed);
        assert_eq!(
            again.calls.len(),
            original.calls.len(),
            "{}",
            path.display()
        );
        assert!(
            again.calls_only() == original.calls_only(),
            "{}: calls differ after the round trip",
            path.display()
        );
    }
}
