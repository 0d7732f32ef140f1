//! [`ParamSet`]: a directive's parameter list, with typed lookups that remember
//! which parameters were used.
//!
//! A lookup matches a parameter by name *and* type (as pbrt-v4 does): `get_float
//! ("radius")` finds `"float radius"` but not `"integer radius"`. A successful lookup
//! marks the parameter used; after building an object the scene builder calls
//! [`ParamSet::finish`]: a parameter read as one value that holds none or
//! several is an error (as in pbrt-v4), and every parameter the builder did
//! not understand is reported once, with its location.

use crate::{ErrorKind, Loc, Param, ParamType, ParamValues, ParseError, Warnings};

/// A spectrum-valued parameter, as found by [`ParamSet::get_spectrum`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SpectrumValue<'a> {
    /// `"rgb name" [r g b]`.
    Rgb([f64; 3]),
    /// `"blackbody name" [kelvin]`.
    Blackbody(f64),
    /// `"spectrum name" [lambda0 v0 lambda1 v1 ...]`: flattened (wavelength nm, value) pairs.
    Samples(&'a [f64]),
    /// `"spectrum name" "x"`: a spectrum file (relative path) or a built-in named
    /// spectrum such as `metal-Au-eta`.
    Named(&'a str),
}

/// A float parameter or a reference to a float texture, as found by
/// [`ParamSet::get_float_or_texture`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FloatOrTexture<'a> {
    /// `"float name" v`.
    Value(f64),
    /// `"texture name" "texname"`.
    Texture(&'a str),
}

/// A spectrum parameter or a reference to a spectrum texture, as found by
/// [`ParamSet::get_spectrum_or_texture`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SpectrumOrTexture<'a> {
    /// An `rgb`, `blackbody` or `spectrum` parameter.
    Value(SpectrumValue<'a>),
    /// `"texture name" "texname"`.
    Texture(&'a str),
}

/// An ordered list of [`Param`]s with typed lookups.
///
/// Equality compares the parameters in order, ignoring locations and use.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ParamSet {
    params: Vec<Param>,
}

fn chunks<const N: usize>(v: &[f64]) -> Vec<[f64; N]> {
    v.chunks_exact(N)
        .map(|c| std::array::from_fn(|i| c[i]))
        .collect()
}

impl ParamSet {
    /// An empty set.
    pub fn new() -> Self {
        Self::default()
    }

    /// Appends a parameter. Returns it back if one with the same name already exists
    /// (whatever its type), leaving the set unchanged.
    pub fn push(&mut self, param: Param) -> Result<(), Param> {
        if self.params.iter().any(|p| p.name == param.name) {
            return Err(param);
        }
        self.params.push(param);
        Ok(())
    }

    /// Number of parameters.
    pub fn len(&self) -> usize {
        self.params.len()
    }

    /// Whether there are no parameters.
    pub fn is_empty(&self) -> bool {
        self.params.is_empty()
    }

    /// All parameters in order (does not mark them used).
    pub fn iter(&self) -> std::slice::Iter<'_, Param> {
        self.params.iter()
    }

    /// The parameter with this name, whatever its type (does not mark it used).
    pub fn find(&self, name: &str) -> Option<&Param> {
        self.params.iter().find(|p| p.name == name)
    }

    /// The parameter with this name and one of these types, marked used.
    pub fn lookup(&self, name: &str, types: &[ParamType]) -> Option<&Param> {
        let p = self
            .params
            .iter()
            .find(|p| p.name == name && types.contains(&p.ty))?;
        p.mark_used();
        Some(p)
    }

    /// Records a single-value read of `name` as one item of `arity` values
    /// (see [`Param::miscount`]).
    fn single(&self, name: &str, types: &[ParamType], arity: u8) {
        if let Some(p) = self.lookup(name, types) {
            p.mark_read_as_single(arity);
        }
    }

    fn floats_of(&self, name: &str, ty: ParamType) -> Option<&[f64]> {
        self.lookup(name, &[ty]).and_then(Param::floats)
    }

    /// First value of `"float name"`.
    pub fn get_float(&self, name: &str) -> Option<f64> {
        self.single(name, &[ParamType::Float], 1);
        self.get_floats(name)?.first().copied()
    }

    /// First value of `"float name"`, or `default`.
    pub fn float_or(&self, name: &str, default: f64) -> f64 {
        self.get_float(name).unwrap_or(default)
    }

    /// All values of `"float name"`.
    pub fn get_floats(&self, name: &str) -> Option<&[f64]> {
        self.floats_of(name, ParamType::Float)
    }

    /// All values of `"integer name"`.
    pub fn get_ints(&self, name: &str) -> Option<&[i64]> {
        match &self.lookup(name, &[ParamType::Integer])?.values {
            ParamValues::Ints(v) => Some(v),
            _ => None,
        }
    }

    /// First value of `"integer name"`.
    pub fn get_int(&self, name: &str) -> Option<i64> {
        self.single(name, &[ParamType::Integer], 1);
        self.get_ints(name)?.first().copied()
    }

    /// First value of `"integer name"`, or `default`.
    pub fn int_or(&self, name: &str, default: i64) -> i64 {
        self.get_int(name).unwrap_or(default)
    }

    /// First value of `"bool name"`.
    pub fn get_bool(&self, name: &str) -> Option<bool> {
        self.single(name, &[ParamType::Bool], 1);
        match &self.lookup(name, &[ParamType::Bool])?.values {
            ParamValues::Bools(v) => v.first().copied(),
            _ => None,
        }
    }

    /// First value of `"bool name"`, or `default`.
    pub fn bool_or(&self, name: &str, default: bool) -> bool {
        self.get_bool(name).unwrap_or(default)
    }

    /// All values of `"string name"`.
    pub fn get_strings(&self, name: &str) -> Option<&[String]> {
        self.lookup(name, &[ParamType::String])?.strings()
    }

    /// First value of `"string name"`.
    pub fn get_string(&self, name: &str) -> Option<&str> {
        self.single(name, &[ParamType::String], 1);
        self.get_strings(name)?.first().map(String::as_str)
    }

    /// First value of `"string name"`, or `default`.
    pub fn string_or<'a>(&'a self, name: &str, default: &'a str) -> &'a str {
        self.get_string(name).unwrap_or(default)
    }

    /// `"point2 name"` values as pairs.
    pub fn get_point2s(&self, name: &str) -> Option<Vec<[f64; 2]>> {
        self.floats_of(name, ParamType::Point2).map(chunks::<2>)
    }

    /// `"vector2 name"` values as pairs.
    pub fn get_vector2s(&self, name: &str) -> Option<Vec<[f64; 2]>> {
        self.floats_of(name, ParamType::Vector2).map(chunks::<2>)
    }

    /// `"point3 name"` values as triples.
    pub fn get_point3s(&self, name: &str) -> Option<Vec<[f64; 3]>> {
        self.floats_of(name, ParamType::Point3).map(chunks::<3>)
    }

    /// `"vector3 name"` values as triples.
    pub fn get_vector3s(&self, name: &str) -> Option<Vec<[f64; 3]>> {
        self.floats_of(name, ParamType::Vector3).map(chunks::<3>)
    }

    /// `"normal3 name"` (or `"normal name"`) values as triples.
    pub fn get_normals(&self, name: &str) -> Option<Vec<[f64; 3]>> {
        self.floats_of(name, ParamType::Normal3).map(chunks::<3>)
    }

    /// The triple of `"point3 name"`.
    pub fn get_point3(&self, name: &str) -> Option<[f64; 3]> {
        self.single(name, &[ParamType::Point3], 3);
        self.get_point3s(name)?.first().copied()
    }

    /// The triple of `"vector3 name"`.
    pub fn get_vector3(&self, name: &str) -> Option<[f64; 3]> {
        self.single(name, &[ParamType::Vector3], 3);
        self.get_vector3s(name)?.first().copied()
    }

    /// The value of `"rgb name"`.
    pub fn get_rgb(&self, name: &str) -> Option<[f64; 3]> {
        chunks::<3>(self.floats_of(name, ParamType::Rgb)?)
            .first()
            .copied()
    }

    /// An `rgb`, `blackbody` or `spectrum` parameter with this name.
    pub fn get_spectrum(&self, name: &str) -> Option<SpectrumValue<'_>> {
        const TYPES: [ParamType; 3] = [ParamType::Rgb, ParamType::Blackbody, ParamType::Spectrum];
        let p = self.lookup(name, &TYPES)?;
        match (&p.values, p.ty) {
            (ParamValues::Floats(v), ParamType::Rgb) => {
                chunks::<3>(v).first().copied().map(SpectrumValue::Rgb)
            }
            (ParamValues::Floats(v), ParamType::Blackbody) => {
                v.first().copied().map(SpectrumValue::Blackbody)
            }
            (ParamValues::Floats(v), _) => Some(SpectrumValue::Samples(v)),
            (ParamValues::Strings(v), _) => v.first().map(|s| SpectrumValue::Named(s)),
            _ => None,
        }
    }

    /// The texture name of `"texture name"`.
    pub fn get_texture(&self, name: &str) -> Option<&str> {
        self.lookup(name, &[ParamType::Texture])?
            .strings()?
            .first()
            .map(String::as_str)
    }

    /// `"texture name"` if present, else `"float name"` (pbrt-v4's float-texture
    /// parameters such as `roughness` accept either).
    pub fn get_float_or_texture(&self, name: &str) -> Option<FloatOrTexture<'_>> {
        if let Some(t) = self.get_texture(name) {
            return Some(FloatOrTexture::Texture(t));
        }
        self.get_float(name).map(FloatOrTexture::Value)
    }

    /// `"texture name"` if present, else an `rgb`/`blackbody`/`spectrum` parameter.
    pub fn get_spectrum_or_texture(&self, name: &str) -> Option<SpectrumOrTexture<'_>> {
        if let Some(t) = self.get_texture(name) {
            return Some(SpectrumOrTexture::Texture(t));
        }
        self.get_spectrum(name).map(SpectrumOrTexture::Value)
    }

    /// Marks every parameter with this name used (for parameters a builder reads
    /// through [`ParamSet::find`] or deliberately ignores).
    pub fn mark_used(&self, name: &str) {
        self.params
            .iter()
            .filter(|p| p.name == name)
            .for_each(Param::mark_used);
    }

    /// Parameters that no lookup has used, in order.
    pub fn unused(&self) -> impl Iterator<Item = &Param> {
        self.params.iter().filter(|p| !p.is_used())
    }

    /// The end of building an object from this list. A parameter that a
    /// single-value getter read but that holds no value or more than one
    /// (`"float radius" [ ]`, `"float radius" [ 1 2 ]`, two `point3`s; the
    /// parser has already checked `rgb`, `texture` and spectrum counts) is
    /// an error at its location, as in pbrt-v4 ("More than one value
    /// provided for parameter"). Then adds to `warnings`, for each unused
    /// parameter, `{context}: parameter "{type name}" is not used` at the
    /// parameter's location (deduplicated by [`Warnings`], so a parameter is
    /// reported once however often this is called).
    pub fn finish(&self, context: &str, warnings: &mut Warnings) -> Result<(), ParseError> {
        if let Some((p, arity)) = self.params.iter().find_map(|p| Some((p, p.miscount()?))) {
            let n = p.values.len();
            let want = match arity {
                1 => "one value".to_string(),
                a => format!("{a} values (one item)"),
            };
            let message = format!(
                "{context}: parameter \"{}\" takes {want}, got {n}",
                p.declaration()
            );
            return Err(ParseError::new(ErrorKind::WrongValueCount, &p.loc, message));
        }
        for p in self.unused() {
            let message = format!("{context}: parameter \"{}\" is not used", p.declaration());
            warnings.warn(&p.loc, message);
        }
        Ok(())
    }

    /// Location of the first parameter, if any (for messages about the whole list).
    pub fn first_loc(&self) -> Option<&Loc> {
        self.params.first().map(|p| &p.loc)
    }
}

impl<'a> IntoIterator for &'a ParamSet {
    type Item = &'a Param;
    type IntoIter = std::slice::Iter<'a, Param>;
    fn into_iter(self) -> Self::IntoIter {
        self.params.iter()
    }
}
