//! A target implementing [`ParserTarget`] directly (as a scene builder will, in
//! another crate): a tiny graphics-state tracker that checks block nesting, keeps
//! the current material, and warns about unused parameters.

use pbrt_format::{
    ActiveTransform, ErrorKind, Loc, Param, ParamSet, ParseError, ParserTarget, TargetResult,
    Warnings, parse_str,
};

#[derive(Default)]
struct Tracker {
    stack: Vec<String>,
    material: String,
    translated: [f64; 3],
    spheres: Vec<(f64, String)>,
    warnings: Warnings,
}

impl Tracker {
    fn ignore(&mut self, loc: &Loc, what: &str) -> TargetResult {
        self.warnings
            .warn_once(loc, format!("{what} is not supported"));
        Ok(())
    }
    fn ignore_params(&mut self, loc: &Loc, what: &str, params: ParamSet) -> TargetResult {
        params.warn_unused(what, &mut self.warnings);
        self.ignore(loc, what)
    }
}

impl ParserTarget for Tracker {
    fn option(&mut self, _p: Param, loc: &Loc) -> TargetResult {
        self.ignore(loc, "Option")
    }
    fn color_space(&mut self, _n: &str, loc: &Loc) -> TargetResult {
        self.ignore(loc, "ColorSpace")
    }
    fn identity(&mut self, _loc: &Loc) -> TargetResult {
        self.translated = [0.0; 3];
        Ok(())
    }
    fn translate(&mut self, d: [f64; 3], _loc: &Loc) -> TargetResult {
        (0..3).for_each(|i| self.translated[i] += d[i]);
        Ok(())
    }
    fn scale(&mut self, _s: [f64; 3], loc: &Loc) -> TargetResult {
        self.ignore(loc, "Scale")
    }
    fn rotate(&mut self, _a: f64, _axis: [f64; 3], loc: &Loc) -> TargetResult {
        self.ignore(loc, "Rotate")
    }
    fn look_at(&mut self, _e: [f64; 3], _l: [f64; 3], _u: [f64; 3], loc: &Loc) -> TargetResult {
        self.ignore(loc, "LookAt")
    }
    fn concat_transform(&mut self, _m: [f64; 16], loc: &Loc) -> TargetResult {
        self.ignore(loc, "ConcatTransform")
    }
    fn transform(&mut self, _m: [f64; 16], loc: &Loc) -> TargetResult {
        self.ignore(loc, "Transform")
    }
    fn coordinate_system(&mut self, _n: &str, loc: &Loc) -> TargetResult {
        self.ignore(loc, "CoordinateSystem")
    }
    fn coord_sys_transform(&mut self, _n: &str, loc: &Loc) -> TargetResult {
        self.ignore(loc, "CoordSysTransform")
    }
    fn active_transform(&mut self, _w: ActiveTransform, loc: &Loc) -> TargetResult {
        self.ignore(loc, "ActiveTransform")
    }
    fn transform_times(&mut self, _s: f64, _e: f64, loc: &Loc) -> TargetResult {
        self.ignore(loc, "TransformTimes")
    }
    fn reverse_orientation(&mut self, loc: &Loc) -> TargetResult {
        self.ignore(loc, "ReverseOrientation")
    }
    fn camera(&mut self, _t: &str, p: ParamSet, loc: &Loc) -> TargetResult {
        self.ignore_params(loc, "Camera", p)
    }
    fn film(&mut self, _t: &str, p: ParamSet, loc: &Loc) -> TargetResult {
        self.ignore_params(loc, "Film", p)
    }
    fn sampler(&mut self, _t: &str, p: ParamSet, loc: &Loc) -> TargetResult {
        self.ignore_params(loc, "Sampler", p)
    }
    fn integrator(&mut self, _t: &str, p: ParamSet, loc: &Loc) -> TargetResult {
        self.ignore_params(loc, "Integrator", p)
    }
    fn pixel_filter(&mut self, _t: &str, p: ParamSet, loc: &Loc) -> TargetResult {
        self.ignore_params(loc, "PixelFilter", p)
    }
    fn accelerator(&mut self, _t: &str, p: ParamSet, loc: &Loc) -> TargetResult {
        self.ignore_params(loc, "Accelerator", p)
    }
    fn make_named_medium(&mut self, _n: &str, p: ParamSet, loc: &Loc) -> TargetResult {
        self.ignore_params(loc, "MakeNamedMedium", p)
    }
    fn medium_interface(&mut self, _i: &str, _o: &str, loc: &Loc) -> TargetResult {
        self.ignore(loc, "MediumInterface")
    }
    fn world_begin(&mut self, _loc: &Loc) -> TargetResult {
        Ok(())
    }
    fn attribute_begin(&mut self, _loc: &Loc) -> TargetResult {
        self.stack.push(self.material.clone());
        Ok(())
    }
    fn attribute_end(&mut self, loc: &Loc) -> TargetResult {
        match self.stack.pop() {
            Some(m) => {
                self.material = m;
                Ok(())
            }
            None => Err(ParseError::scene(
                loc,
                "AttributeEnd without AttributeBegin",
            )),
        }
    }
    fn transform_begin(&mut self, loc: &Loc) -> TargetResult {
        self.attribute_begin(loc)
    }
    fn transform_end(&mut self, loc: &Loc) -> TargetResult {
        self.attribute_end(loc)
    }
    fn attribute(&mut self, _t: &str, p: ParamSet, loc: &Loc) -> TargetResult {
        self.ignore_params(loc, "Attribute", p)
    }
    fn shape(&mut self, ty: &str, p: ParamSet, loc: &Loc) -> TargetResult {
        if ty != "sphere" {
            return self.ignore_params(loc, &format!("Shape \"{ty}\""), p);
        }
        self.spheres
            .push((p.float_or("radius", 1.0), self.material.clone()));
        p.warn_unused("Shape \"sphere\"", &mut self.warnings);
        Ok(())
    }
    fn material(&mut self, ty: &str, p: ParamSet, _loc: &Loc) -> TargetResult {
        self.material = ty.to_string();
        p.warn_unused(&format!("Material \"{ty}\""), &mut self.warnings);
        Ok(())
    }
    fn make_named_material(&mut self, _n: &str, p: ParamSet, loc: &Loc) -> TargetResult {
        self.ignore_params(loc, "MakeNamedMaterial", p)
    }
    fn named_material(&mut self, _n: &str, loc: &Loc) -> TargetResult {
        self.ignore(loc, "NamedMaterial")
    }
    fn texture(&mut self, _n: &str, _t: &str, _c: &str, p: ParamSet, loc: &Loc) -> TargetResult {
        self.ignore_params(loc, "Texture", p)
    }
    fn light_source(&mut self, _t: &str, p: ParamSet, loc: &Loc) -> TargetResult {
        self.ignore_params(loc, "LightSource", p)
    }
    fn area_light_source(&mut self, _t: &str, p: ParamSet, loc: &Loc) -> TargetResult {
        self.ignore_params(loc, "AreaLightSource", p)
    }
    fn object_begin(&mut self, _n: &str, loc: &Loc) -> TargetResult {
        self.ignore(loc, "ObjectBegin")
    }
    fn object_end(&mut self, loc: &Loc) -> TargetResult {
        self.ignore(loc, "ObjectEnd")
    }
    fn object_instance(&mut self, _n: &str, loc: &Loc) -> TargetResult {
        self.ignore(loc, "ObjectInstance")
    }
    fn warning(&mut self, loc: &Loc, message: &str) {
        self.warnings.warn(loc, message);
    }
}

#[test]
fn a_direct_target_tracks_state_and_warns_once() {
    let text = "WorldBegin\n\
                Material \"diffuse\"\n\
                AttributeBegin\n\
                \x20 Material \"conductor\" \"float roughness\" 0.1\n\
                \x20 Translate 1 2 3\n\
                \x20 Shape \"sphere\" \"float radius\" 2 \"float zmax\" 1\n\
                AttributeEnd\n\
                Shape \"sphere\"\n\
                Scale 1 1 1\nScale 2 2 2\nWorldEnd\n";
    let mut t = Tracker::default();
    parse_str(text, "s.pbrt", &mut t).unwrap();
    assert_eq!(
        t.spheres,
        [(2.0, "conductor".into()), (1.0, "diffuse".into())]
    );
    assert_eq!(t.translated, [1.0, 2.0, 3.0]);
    let shown: Vec<String> = t.warnings.iter().map(ToString::to_string).collect();
    assert_eq!(
        shown,
        [
            "s.pbrt:4:24: warning: Material \"conductor\": parameter \"float roughness\" is not used",
            "s.pbrt:6:35: warning: Shape \"sphere\": parameter \"float zmax\" is not used",
            "s.pbrt:9:1: warning: Scale is not supported",
            "s.pbrt:11:1: warning: WorldEnd (pbrt-v3) is ignored",
        ]
    );
}

#[test]
fn a_direct_target_error_has_the_directive_location() {
    let e = parse_str(
        "AttributeBegin\nAttributeEnd\n  AttributeEnd",
        "s.pbrt",
        &mut Tracker::default(),
    )
    .unwrap_err();
    assert_eq!(e.kind, ErrorKind::Scene);
    assert_eq!(
        e.to_string(),
        "s.pbrt:3:3: AttributeEnd without AttributeBegin"
    );
}
