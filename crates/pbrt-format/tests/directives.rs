//! Every directive becomes the right call, with the right arguments, parameters
//! and location.

mod common;

use common::{calls, record};
use pbrt_format::{ActiveTransform, Directive, Loc, Param, ParamSet, ParamType, ParamValues};

fn param(ty: ParamType, name: &str, values: ParamValues) -> Param {
    Param::new(ty, name, values, Loc::new("expected", 0, 0))
}

fn set(params: Vec<Param>) -> ParamSet {
    let mut s = ParamSet::new();
    for p in params {
        s.push(p).unwrap();
    }
    s
}

fn floats(ty: ParamType, name: &str, v: &[f64]) -> Param {
    param(ty, name, ParamValues::Floats(v.to_vec()))
}

fn strings(ty: ParamType, name: &str, v: &[&str]) -> Param {
    let v = v.iter().map(|s| s.to_string()).collect();
    param(ty, name, ParamValues::Strings(v))
}

#[test]
fn transform_directives() {
    let got = calls(
        "Identity Translate 1 2 3 Scale -1 1 .5 Rotate 90 0 0 1\n\
         LookAt 0 0 5  0 0 0  0 1 0\n\
         Transform [ 1 0 0 0 0 1 0 0 0 0 1 0 4 5 6 1 ]\n\
         ConcatTransform [ 2 0 0 0 0 2 0 0 0 0 2 0 0 0 0 1 ]\n\
         CoordinateSystem \"mine\" CoordSysTransform \"camera\"\n\
         ActiveTransform StartTime ActiveTransform EndTime ActiveTransform All\n\
         TransformTimes 0 1.5 ReverseOrientation TransformBegin TransformEnd",
    );
    let mut m = [0.0; 16];
    for i in 0..4 {
        m[i * 5] = 1.0;
    }
    let mut t = m;
    t[12..15].copy_from_slice(&[4.0, 5.0, 6.0]);
    let mut c = m;
    for i in 0..3 {
        c[i * 5] = 2.0;
    }
    let want = vec![
        Directive::Identity,
        Directive::Translate([1.0, 2.0, 3.0]),
        Directive::Scale([-1.0, 1.0, 0.5]),
        Directive::Rotate(90.0, [0.0, 0.0, 1.0]),
        Directive::LookAt([0.0, 0.0, 5.0], [0.0; 3], [0.0, 1.0, 0.0]),
        Directive::Transform(t),
        Directive::ConcatTransform(c),
        Directive::CoordinateSystem("mine".into()),
        Directive::CoordSysTransform("camera".into()),
        Directive::ActiveTransform(ActiveTransform::StartTime),
        Directive::ActiveTransform(ActiveTransform::EndTime),
        Directive::ActiveTransform(ActiveTransform::All),
        Directive::TransformTimes(0.0, 1.5),
        Directive::ReverseOrientation,
        Directive::TransformBegin,
        Directive::TransformEnd,
    ];
    assert_eq!(got, want);
}

#[test]
fn rendering_options_and_world_block() {
    let got = calls(
        "Option \"bool disablepixeljitter\" true\n\
         ColorSpace \"aces2065-1\"\n\
         Camera \"perspective\" \"float fov\" [ 45 ] \"float lensradius\" .1\n\
         Film \"rgb\" \"integer xresolution\" [ 640 ] \"string filename\" \"a.exr\"\n\
         Sampler \"zsobol\" \"integer pixelsamples\" 16\n\
         Integrator \"volpath\" \"integer maxdepth\" [ 8 ] \"bool regularize\" true\n\
         PixelFilter \"gaussian\" \"float sigma\" 0.5\n\
         Accelerator \"bvh\"\n\
         WorldBegin WorldEnd",
    );
    use ParamType as T;
    let want = vec![
        Directive::Option(param(
            T::Bool,
            "disablepixeljitter",
            ParamValues::Bools(vec![true]),
        )),
        Directive::ColorSpace("aces2065-1".into()),
        Directive::Camera(
            "perspective".into(),
            set(vec![
                floats(T::Float, "fov", &[45.0]),
                floats(T::Float, "lensradius", &[0.1]),
            ]),
        ),
        Directive::Film(
            "rgb".into(),
            set(vec![
                param(T::Integer, "xresolution", ParamValues::Ints(vec![640])),
                strings(T::String, "filename", &["a.exr"]),
            ]),
        ),
        Directive::Sampler(
            "zsobol".into(),
            set(vec![param(
                T::Integer,
                "pixelsamples",
                ParamValues::Ints(vec![16]),
            )]),
        ),
        Directive::Integrator(
            "volpath".into(),
            set(vec![
                param(T::Integer, "maxdepth", ParamValues::Ints(vec![8])),
                param(T::Bool, "regularize", ParamValues::Bools(vec![true])),
            ]),
        ),
        Directive::PixelFilter(
            "gaussian".into(),
            set(vec![floats(T::Float, "sigma", &[0.5])]),
        ),
        Directive::Accelerator("bvh".into(), ParamSet::new()),
        Directive::WorldBegin,
    ];
    assert_eq!(got, want);
}

#[test]
fn scene_directives() {
    let got = calls(
        "AttributeBegin Attribute \"shape\" \"float radius\" 2 AttributeEnd\n\
         Material \"conductor\" \"spectrum eta\" \"metal-Cu-eta\" \"spectrum k\" [ 400 1 700 2 ]\n\
         MakeNamedMaterial \"m\" \"string type\" \"diffuse\" \"texture reflectance\" \"t\"\n\
         NamedMaterial \"m\"\n\
         Texture \"t\" \"spectrum\" \"checkerboard\" \"rgb tex1\" [ 1 0 0 ] \"color tex2\" [0 1 0]\n\
         LightSource \"spot\" \"blackbody I\" 5500 \"point from\" [ 0 5 9 ] \"point3 to\" [0 0 0]\n\
         AreaLightSource \"diffuse\" \"rgb L\" [ 7 7 7 ] \"bool twosided\" \"true\"\n\
         MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n\
         MediumInterface \"fog\" \"\" MediumInterface \"fog\"\n\
         ObjectBegin \"o\" Shape \"sphere\" ObjectEnd ObjectInstance \"o\"\n\
         Shape \"trianglemesh\" \"point2 uv\" [0 0 1 0 1 1] \"normal N\" [0 0 1]\n\
         \"vector3 S\" [1 0 0] \"vector2 d\" [1 2] \"integer indices\" [0 1 2]",
    );
    use ParamType as T;
    let want = vec![
        Directive::AttributeBegin,
        Directive::Attribute(
            "shape".into(),
            set(vec![floats(T::Float, "radius", &[2.0])]),
        ),
        Directive::AttributeEnd,
        Directive::Material(
            "conductor".into(),
            set(vec![
                strings(T::Spectrum, "eta", &["metal-Cu-eta"]),
                floats(T::Spectrum, "k", &[400.0, 1.0, 700.0, 2.0]),
            ]),
        ),
        Directive::MakeNamedMaterial(
            "m".into(),
            set(vec![
                strings(T::String, "type", &["diffuse"]),
                strings(T::Texture, "reflectance", &["t"]),
            ]),
        ),
        Directive::NamedMaterial("m".into()),
        Directive::Texture(
            "t".into(),
            "spectrum".into(),
            "checkerboard".into(),
            set(vec![
                floats(T::Rgb, "tex1", &[1.0, 0.0, 0.0]),
                floats(T::Rgb, "tex2", &[0.0, 1.0, 0.0]),
            ]),
        ),
        Directive::LightSource(
            "spot".into(),
            set(vec![
                floats(T::Blackbody, "I", &[5500.0]),
                floats(T::Point3, "from", &[0.0, 5.0, 9.0]),
                floats(T::Point3, "to", &[0.0; 3]),
            ]),
        ),
        Directive::AreaLightSource(
            "diffuse".into(),
            set(vec![
                floats(T::Rgb, "L", &[7.0; 3]),
                param(T::Bool, "twosided", ParamValues::Bools(vec![true])),
            ]),
        ),
        Directive::MakeNamedMedium(
            "fog".into(),
            set(vec![strings(T::String, "type", &["homogeneous"])]),
        ),
        Directive::MediumInterface("fog".into(), "".into()),
        Directive::MediumInterface("fog".into(), "fog".into()),
        Directive::ObjectBegin("o".into()),
        Directive::Shape("sphere".into(), ParamSet::new()),
        Directive::ObjectEnd,
        Directive::ObjectInstance("o".into()),
        Directive::Shape(
            "trianglemesh".into(),
            set(vec![
                floats(T::Point2, "uv", &[0.0, 0.0, 1.0, 0.0, 1.0, 1.0]),
                floats(T::Normal3, "N", &[0.0, 0.0, 1.0]),
                floats(T::Vector3, "S", &[1.0, 0.0, 0.0]),
                floats(T::Vector2, "d", &[1.0, 2.0]),
                param(T::Integer, "indices", ParamValues::Ints(vec![0, 1, 2])),
            ]),
        ),
    ];
    assert_eq!(got, want);
}

#[test]
fn every_call_has_its_keyword_location() {
    let rec = record(
        "Camera \"perspective\"\n  \"float fov\" 30\n\n\tWorldBegin # x\n   Shape \"sphere\"",
    );
    let locs: Vec<(u32, u32)> = rec.calls.iter().map(|(_, l)| (l.line, l.column)).collect();
    assert_eq!(locs, [(1, 1), (4, 2), (5, 4)]);
    assert!(rec.calls.iter().all(|(_, l)| &*l.file == "test.pbrt"));
    let Directive::Camera(_, params) = &rec.calls[0].0 else {
        panic!()
    };
    let fov = params.find("fov").unwrap();
    assert_eq!((fov.loc.line, fov.loc.column), (2, 3));
}

#[test]
fn escapes_are_decoded_in_values_and_names() {
    let got = calls("Shape \"a\\\"b\" \"string s\" [ \"tab\\there\" \"back\\\\slash\" ]");
    let want = vec![Directive::Shape(
        "a\"b".into(),
        set(vec![strings(
            ParamType::String,
            "s",
            &["tab\there", "back\\slash"],
        )]),
    )];
    assert_eq!(got, want);
}

#[test]
fn world_end_is_ignored_with_a_warning() {
    let rec = record("WorldBegin\nWorldEnd\n");
    assert_eq!(rec.calls_only(), vec![Directive::WorldBegin]);
    assert_eq!(rec.warnings.len(), 1);
    assert_eq!((rec.warnings[0].0.line, rec.warnings[0].0.column), (2, 1));
}

#[test]
fn empty_lists_and_integer_signs() {
    let got = calls("Shape \"x\" \"integer i\" [ ] \"integer j\" [ -3 +4 ] \"float f\" []");
    let want = vec![Directive::Shape(
        "x".into(),
        set(vec![
            param(ParamType::Integer, "i", ParamValues::Ints(vec![])),
            param(ParamType::Integer, "j", ParamValues::Ints(vec![-3, 4])),
            floats(ParamType::Float, "f", &[]),
        ]),
    )];
    assert_eq!(got, want);
}

#[test]
fn every_directive_knows_its_keyword() {
    let text = "Option \"bool b\" true ColorSpace \"srgb\" Identity Translate 1 2 3\n\
                Scale 1 1 1 Rotate 1 0 0 1 LookAt 0 0 1 0 0 0 0 1 0\n\
                ConcatTransform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1]\n\
                Transform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1]\n\
                CoordinateSystem \"c\" CoordSysTransform \"c\" ActiveTransform All\n\
                TransformTimes 0 1 ReverseOrientation Camera \"perspective\"\n\
                Film \"rgb\" Sampler \"zsobol\" Integrator \"path\" PixelFilter \"box\"\n\
                Accelerator \"bvh\" MakeNamedMedium \"m\" MediumInterface \"m\"\n\
                WorldBegin AttributeBegin AttributeEnd TransformBegin TransformEnd\n\
                Attribute \"shape\" Shape \"sphere\" Material \"diffuse\"\n\
                MakeNamedMaterial \"n\" NamedMaterial \"n\"\n\
                Texture \"t\" \"float\" \"constant\" LightSource \"point\"\n\
                AreaLightSource \"diffuse\" ObjectBegin \"o\" ObjectEnd ObjectInstance \"o\"";
    let rec = record(text);
    let keywords: Vec<&str> = rec.calls.iter().map(|(d, _)| d.keyword()).collect();
    let expected: Vec<&str> = pbrt_format::DIRECTIVES
        .iter()
        .copied()
        .filter(|w| !matches!(*w, "Include" | "Import" | "WorldEnd"))
        .collect();
    let mut sorted = keywords.clone();
    sorted.sort_unstable();
    let mut expected_sorted = expected.clone();
    expected_sorted.sort_unstable();
    assert_eq!(sorted, expected_sorted, "each directive once");
    // The keyword is the word at the directive's location.
    for ((d, loc), word) in rec.calls.iter().zip(&keywords) {
        let line = text.lines().nth(loc.line as usize - 1).unwrap();
        let at = &line[loc.column as usize - 1..];
        assert!(at.starts_with(word), "{} at {loc}", d.keyword());
    }
}
