//! pbrt's graphics state: the current transformation matrix (CTM), reverse
//! orientation, the current material and area light, the attribute stack and
//! named coordinate systems.

use crate::math::{Matrix4, Point3, Transform, Vec3};
use crate::spectrum::Rgb;
use pbrt_format::{Loc, ParseError};
use std::collections::HashMap;

/// Which material a shape gets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum MatRef {
    /// pbrt's default (diffuse, reflectance 0.5), created on first use.
    Default,
    /// An index into the scene builder's materials.
    Index(u32),
    /// pbrt's `interface` material: the shape has no surface.
    Interface,
}

/// An `AreaLightSource "diffuse"` in effect.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct AreaSpec {
    /// `L * scale`.
    pub l: Rgb,
    /// `twosided`.
    pub two_sided: bool,
    /// `power`, if given.
    pub power: Option<f32>,
    /// The emission spectrum when `L` is not RGB (spectral mode).
    pub spectrum: Option<crate::spectrum::named::EmissionSpectrum>,
}

/// The attributes saved by `AttributeBegin`.
#[derive(Clone, Debug)]
pub(crate) struct GraphicsState {
    /// Object-to-world (after `WorldBegin`) or camera-from-world (before).
    pub ctm: Transform,
    /// `ReverseOrientation` in effect.
    pub reverse_orientation: bool,
    /// The current material.
    pub material: MatRef,
    /// The current area light.
    pub area: Option<AreaSpec>,
    /// The current `MediumInterface` (scene medium indices).
    pub media: crate::medium::MediumInterface,
}

impl Default for GraphicsState {
    fn default() -> Self {
        GraphicsState {
            ctm: Transform::IDENTITY,
            reverse_orientation: false,
            material: MatRef::Default,
            area: None,
            media: crate::medium::MediumInterface::default(),
        }
    }
}

/// The graphics state with its stack and named coordinate systems.
#[derive(Clone, Debug, Default)]
pub(crate) struct StateStack {
    /// The current state.
    pub cur: GraphicsState,
    /// Saved states; `true` marks a `TransformBegin` (only the CTM is restored).
    stack: Vec<(GraphicsState, bool)>,
    /// `CoordinateSystem` names (and `camera`).
    pub named: HashMap<String, Transform>,
}

fn v3(a: [f64; 3]) -> Vec3 {
    Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32)
}

/// pbrt's 16 numbers (column-major, translation in 12..15) as a transform.
pub(crate) fn pbrt_matrix(m: [f64; 16], loc: &Loc) -> Result<Transform, ParseError> {
    let mut r = Matrix4::IDENTITY;
    for (i, row) in r.m.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = m[j * 4 + i] as f32;
        }
    }
    if r.m.iter().flatten().any(|v| !v.is_finite()) {
        return Err(ParseError::scene(loc, "transform has non-finite entries"));
    }
    Transform::from_matrix(r).map_err(|_| ParseError::scene(loc, "transform matrix is singular"))
}

impl StateStack {
    /// `ctm = ctm * t`, refused (and the transform left as it was) when the
    /// product or its inverse is no longer finite in `f32`: a transform that
    /// overflows would place the geometry after it at infinity or NaN.
    pub fn concat(&mut self, t: Transform, loc: &Loc) -> Result<(), ParseError> {
        let ctm = self.cur.ctm * t;
        let finite = |m: &Matrix4| m.m.iter().flatten().all(|v| v.is_finite());
        if !(finite(ctm.matrix()) && finite(ctm.inverse_matrix())) {
            return Err(ParseError::scene(
                loc,
                "the current transform overflows (entries beyond f32's range)",
            ));
        }
        self.cur.ctm = ctm;
        Ok(())
    }

    /// `Translate`.
    pub fn translate(&mut self, d: [f64; 3], loc: &Loc) -> Result<(), ParseError> {
        let d = v3(d);
        if !d.is_finite() {
            return Err(ParseError::scene(
                loc,
                "Translate needs finite offsets (within f32's range)",
            ));
        }
        self.concat(Transform::translate(d), loc)
    }
    /// `Scale`.
    pub fn scale(&mut self, s: [f64; 3], loc: &Loc) -> Result<(), ParseError> {
        let t = Transform::scale(v3(s)).map_err(|_| {
            ParseError::scene(
                loc,
                "Scale needs finite, non-zero factors (within f32's range)",
            )
        })?;
        self.concat(t, loc)
    }
    /// `Rotate`.
    pub fn rotate(&mut self, angle: f64, axis: [f64; 3], loc: &Loc) -> Result<(), ParseError> {
        let a = v3(axis);
        if !(a.length() > 0.0) || !angle.is_finite() {
            return Err(ParseError::scene(
                loc,
                "Rotate needs a finite angle and a non-zero axis",
            ));
        }
        self.concat(Transform::rotate(angle as f32, a), loc)
    }
    /// `LookAt`.
    pub fn look_at(
        &mut self,
        e: [f64; 3],
        l: [f64; 3],
        u: [f64; 3],
        loc: &Loc,
    ) -> Result<(), ParseError> {
        let t = Transform::look_at(v3(e) as Point3, v3(l), v3(u))
            .map_err(|_| ParseError::scene(loc, "LookAt: degenerate eye, look and up"))?;
        self.concat(t, loc)
    }

    /// `AttributeBegin` (`transform_only = false`) or `TransformBegin`.
    pub fn push(&mut self, transform_only: bool) {
        self.stack.push((self.cur.clone(), transform_only));
    }
    /// `AttributeEnd` / `TransformEnd`; `false` when the stack is empty.
    pub fn pop(&mut self) -> bool {
        match self.stack.pop() {
            Some((s, true)) => {
                self.cur.ctm = s.ctm;
                true
            }
            Some((s, false)) => {
                self.cur = s;
                true
            }
            None => false,
        }
    }
}
