//! One typed parameter of a directive: `"type name" [values]`.
//!
//! pbrt-v4's parameter types are [`ParamType`]; the legacy spellings `point`,
//! `vector`, `normal` and `color` are accepted as `point3`, `vector3`, `normal3` and
//! `rgb`. Values are stored by representation in [`ParamValues`].

use std::fmt;
use std::sync::atomic::{AtomicBool, AtomicU8, Ordering};

use crate::Loc;

/// The declared type of a parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ParamType {
    /// `float`: numbers.
    Float,
    /// `integer`: whole numbers (a number with `.` or an exponent is an error).
    Integer,
    /// `bool`: `true`/`false`, bare or quoted.
    Bool,
    /// `string`: strings.
    String,
    /// `point2`: numbers, a multiple of 2.
    Point2,
    /// `vector2`: numbers, a multiple of 2.
    Vector2,
    /// `point3` (legacy `point`): numbers, a multiple of 3.
    Point3,
    /// `vector3` (legacy `vector`): numbers, a multiple of 3.
    Vector3,
    /// `normal3` (also `normal`): numbers, a multiple of 3.
    Normal3,
    /// `rgb` (legacy `color`): exactly 3 numbers.
    Rgb,
    /// `blackbody`: a temperature in kelvin (pbrt-v3 files may add a second number).
    Blackbody,
    /// `spectrum`: (wavelength, value) number pairs, or one string naming a spectrum
    /// file or a built-in named spectrum such as `metal-Al-eta`.
    Spectrum,
    /// `texture`: one string naming a texture.
    Texture,
}

impl ParamType {
    /// The type for a declaration's type word, accepting legacy spellings.
    pub fn from_name(name: &str) -> Option<ParamType> {
        Some(match name {
            "float" => ParamType::Float,
            "integer" => ParamType::Integer,
            "bool" => ParamType::Bool,
            "string" => ParamType::String,
            "point2" => ParamType::Point2,
            "vector2" => ParamType::Vector2,
            "point3" | "point" => ParamType::Point3,
            "vector3" | "vector" => ParamType::Vector3,
            "normal3" | "normal" => ParamType::Normal3,
            "rgb" | "color" => ParamType::Rgb,
            "blackbody" => ParamType::Blackbody,
            "spectrum" => ParamType::Spectrum,
            "texture" => ParamType::Texture,
            _ => return None,
        })
    }

    /// The canonical pbrt-v4 name (`point3`, not `point`).
    pub fn name(self) -> &'static str {
        match self {
            ParamType::Float => "float",
            ParamType::Integer => "integer",
            ParamType::Bool => "bool",
            ParamType::String => "string",
            ParamType::Point2 => "point2",
            ParamType::Vector2 => "vector2",
            ParamType::Point3 => "point3",
            ParamType::Vector3 => "vector3",
            ParamType::Normal3 => "normal3",
            ParamType::Rgb => "rgb",
            ParamType::Blackbody => "blackbody",
            ParamType::Spectrum => "spectrum",
            ParamType::Texture => "texture",
        }
    }

    /// How many numbers make one element (2 for `point2`, 3 for `point3`/`rgb`, else 1).
    pub fn arity(self) -> usize {
        match self {
            ParamType::Point2 | ParamType::Vector2 => 2,
            ParamType::Point3 | ParamType::Vector3 | ParamType::Normal3 | ParamType::Rgb => 3,
            _ => 1,
        }
    }
}

impl fmt::Display for ParamType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A parameter's values, by representation.
///
/// `float`, `point*`, `vector*`, `normal3`, `rgb`, `blackbody` and numeric
/// `spectrum` values are `Floats`; `integer` is `Ints`; `bool` is `Bools`;
/// `string`, `texture` and named/file `spectrum` values are `Strings`.
#[derive(Clone, Debug, PartialEq)]
pub enum ParamValues {
    /// Numbers, flattened (`point3` values are x0 y0 z0 x1 y1 z1 ...).
    Floats(Vec<f64>),
    /// Integers.
    Ints(Vec<i64>),
    /// Booleans.
    Bools(Vec<bool>),
    /// Strings (escapes already decoded).
    Strings(Vec<String>),
}

impl ParamValues {
    /// The number of values (numbers, not points).
    pub fn len(&self) -> usize {
        match self {
            ParamValues::Floats(v) => v.len(),
            ParamValues::Ints(v) => v.len(),
            ParamValues::Bools(v) => v.len(),
            ParamValues::Strings(v) => v.len(),
        }
    }

    /// Whether there are no values.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// One parameter: type, name, values, the location of its declaration, and whether a
/// lookup has used it (see [`crate::ParamSet`]).
///
/// Equality compares type, name and values only (not location or use), so the
/// parameters of two parses of equivalent text compare equal.
#[derive(Debug)]
pub struct Param {
    /// The declared type.
    pub ty: ParamType,
    /// The parameter's name (`fov`, `reflectance`, `conductor.eta`, ...).
    pub name: String,
    /// The values.
    pub values: ParamValues,
    /// Location of the `"type name"` declaration string.
    pub loc: Loc,
    used: AtomicBool,
    /// The number of values a single-value getter (`get_float`,
    /// `get_point3`, ...) expects; 0 when none has read it.
    single_arity: AtomicU8,
}

impl Param {
    /// A new, not yet used parameter.
    pub fn new(ty: ParamType, name: impl Into<String>, values: ParamValues, loc: Loc) -> Self {
        Param {
            ty,
            name: name.into(),
            values,
            loc,
            used: AtomicBool::new(false),
            single_arity: AtomicU8::new(0),
        }
    }

    /// Whether a lookup has used this parameter (or [`Param::mark_used`] was called).
    pub fn is_used(&self) -> bool {
        self.used.load(Ordering::Relaxed)
    }

    /// Records that a single-value getter read the parameter as one item of
    /// `arity` numbers or strings (1 for a float, 3 for a point3 or rgb).
    pub fn mark_read_as_single(&self, arity: u8) {
        self.single_arity.store(arity, Ordering::Relaxed);
    }

    /// The number of values a single-value getter expected, if it holds a
    /// different number (none, or several items): pbrt-v4 refuses that, and
    /// [`crate::ParamSet::finish`] makes it an error.
    pub fn miscount(&self) -> Option<usize> {
        let arity = usize::from(self.single_arity.load(Ordering::Relaxed));
        (arity > 0 && self.values.len() != arity).then_some(arity)
    }

    /// Marks the parameter used.
    pub fn mark_used(&self) {
        self.used.store(true, Ordering::Relaxed);
    }

    /// The declaration as written in canonical form, e.g. `float fov`.
    pub fn declaration(&self) -> String {
        format!("{} {}", self.ty, self.name)
    }

    /// The numbers, if stored as floats.
    pub fn floats(&self) -> Option<&[f64]> {
        match &self.values {
            ParamValues::Floats(v) => Some(v),
            _ => None,
        }
    }

    /// The strings, if stored as strings.
    pub fn strings(&self) -> Option<&[String]> {
        match &self.values {
            ParamValues::Strings(v) => Some(v),
            _ => None,
        }
    }
}

impl Clone for Param {
    fn clone(&self) -> Self {
        Param {
            ty: self.ty,
            name: self.name.clone(),
            values: self.values.clone(),
            loc: self.loc.clone(),
            used: AtomicBool::new(self.is_used()),
            single_arity: AtomicU8::new(self.single_arity.load(Ordering::Relaxed)),
        }
    }
}

impl PartialEq for Param {
    fn eq(&self, other: &Self) -> bool {
        self.ty == other.ty && self.name == other.name && self.values == other.values
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn type_names_round_trip_and_legacy_aliases() {
        for ty in [
            ParamType::Float,
            ParamType::Integer,
            ParamType::Bool,
            ParamType::String,
            ParamType::Point2,
            ParamType::Vector2,
            ParamType::Point3,
            ParamType::Vector3,
            ParamType::Normal3,
            ParamType::Rgb,
            ParamType::Blackbody,
            ParamType::Spectrum,
            ParamType::Texture,
        ] {
            assert_eq!(ParamType::from_name(ty.name()), Some(ty));
        }
        assert_eq!(ParamType::from_name("point"), Some(ParamType::Point3));
        assert_eq!(ParamType::from_name("normal"), Some(ParamType::Normal3));
        assert_eq!(ParamType::from_name("vector"), Some(ParamType::Vector3));
        assert_eq!(ParamType::from_name("color"), Some(ParamType::Rgb));
        assert_eq!(ParamType::from_name("double"), None);
    }

    #[test]
    fn equality_ignores_location_and_use() {
        let a = Param::new(
            ParamType::Float,
            "fov",
            ParamValues::Floats(vec![30.0]),
            Loc::new("a", 1, 1),
        );
        let b = Param::new(
            ParamType::Float,
            "fov",
            ParamValues::Floats(vec![30.0]),
            Loc::new("b", 9, 9),
        );
        b.mark_used();
        assert_eq!(a, b);
        assert!(b.clone().is_used() && !a.clone().is_used());
        assert_eq!(b.declaration(), "float fov");
    }
}
