//! A target as a scene builder writes one (in another crate): a tiny
//! graphics-state tracker that matches on the [`Directive`], checks block
//! nesting, keeps the current material, and warns about unused parameters.

use pbrt_format::{Directive, ErrorKind, Loc, ParseError, ParserTarget, TargetResult};
use pbrt_format::{Warnings, parse_str};

#[derive(Default)]
struct Tracker {
    stack: Vec<String>,
    material: String,
    translated: [f64; 3],
    spheres: Vec<(f64, String)>,
    warnings: Warnings,
}

impl Tracker {
    fn ignore(&mut self, loc: &Loc, what: &str) {
        self.warnings
            .warn_once(loc, format!("{what} is not supported"));
    }
}

impl ParserTarget for Tracker {
    fn directive(&mut self, directive: Directive, loc: &Loc) -> TargetResult {
        use Directive as D;
        let keyword = directive.keyword();
        match directive {
            D::Identity => self.translated = [0.0; 3],
            D::Translate(d) => (0..3).for_each(|i| self.translated[i] += d[i]),
            D::WorldBegin => {}
            D::AttributeBegin | D::TransformBegin => self.stack.push(self.material.clone()),
            D::AttributeEnd | D::TransformEnd => match self.stack.pop() {
                Some(m) => self.material = m,
                None => {
                    let msg = "AttributeEnd without AttributeBegin";
                    return Err(ParseError::scene(loc, msg));
                }
            },
            D::Shape(ty, p) if ty == "sphere" => {
                self.spheres
                    .push((p.float_or("radius", 1.0), self.material.clone()));
                p.finish("Shape \"sphere\"", &mut self.warnings)?;
            }
            D::Shape(ty, p) => {
                let what = format!("Shape \"{ty}\"");
                p.finish(&what, &mut self.warnings)?;
                self.ignore(loc, &what)
            }
            D::Material(ty, p) => {
                p.finish(&format!("Material \"{ty}\""), &mut self.warnings)?;
                self.material = ty;
            }
            other => {
                if let Some(p) = other.params() {
                    p.finish(keyword, &mut self.warnings)?;
                }
                self.ignore(loc, keyword)
            }
        }
        Ok(())
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
