//! pbrt-v4's bump and normal mapping: a material's `displacement` texture or
//! `normalmap` image perturbs the shading geometry
//! ([`ShadingGeometry`]) before the BSDF is built there.
//!
//! * **Bump mapping** (pbrt-v4's `BumpMap`): the displacement `d` is
//!   evaluated at the hit and at offsets `du` in `u` and `dv` in `v`, and
//!   `∂p/∂u' = ∂p/∂u + (d(u + du) - d) / du · n + d · ∂n/∂u` (likewise in
//!   `v`). pbrt-v4 takes `du = (|∂u/∂x| + |∂u/∂y|) / 2` from the ray
//!   differentials, or `0.0005` when that is zero; lowdisc has no ray
//!   differentials, so `du = dv =` [`BUMP_DELTA`] = 0.0005 always.
//! * **Normal mapping** (pbrt-v4's `NormalMap`): the image's RGB at
//!   `(u, 1 - v)` (bilinear, repeat) maps `[0, 1]` to `[-1, 1]`, a normal in
//!   the tangent frame whose `z` is the shading normal and `x` follows
//!   `∂p/∂u`; `∂p/∂u` and `∂p/∂v` are then turned about it, keeping their
//!   lengths.
//!
//! Either way the new shading normal is `∂p/∂u' × ∂p/∂v'`, normalised and
//! flipped to the geometric normal's side.

use super::Material;
use crate::geometry::ShadingGeometry;
use crate::math::{Frame, Normal3, Vec3};
use crate::texture::{FloatTexture, TexImage, TextureEvalContext, WrapMode};
use std::sync::Arc;

/// The offset in `u` and `v` at which bump mapping evaluates the
/// displacement (pbrt-v4's value when there are no ray differentials).
pub const BUMP_DELTA: f32 = 0.0005;

/// How a material perturbs its shading normal.
#[derive(Clone, Debug, PartialEq)]
pub enum Bump {
    /// pbrt-v4's `"float displacement"`: a bump map.
    Displacement(FloatTexture),
    /// pbrt-v4's `"string normalmap"`: a tangent-space normal map
    /// (linear RGB).
    NormalMap(Arc<TexImage>),
}

/// A material with a bump or normal map.
#[derive(Clone, Debug, PartialEq)]
pub struct BumpedMaterial {
    /// The material whose BSDF is built in the perturbed frame.
    pub material: Material,
    /// The perturbation.
    pub bump: Bump,
}

impl Bump {
    /// The shading geometry `g` (of a surface with geometric normal `ng`)
    /// perturbed by this map, evaluated at `tc`.
    ///
    /// ```
    /// use lowdisc_render::bsdf::material::Bump;
    /// use lowdisc_render::geometry::ShadingGeometry;
    /// use lowdisc_render::math::Vec3;
    /// use lowdisc_render::texture::TextureEvalContext;
    ///
    /// let g = ShadingGeometry::flat(Vec3::Z, Vec3::X, Vec3::Y);
    /// let flat = Bump::Displacement(0.3.into()); // a constant displacement
    /// let b = flat.apply(&TextureEvalContext::default(), Vec3::Z, &g);
    /// assert!((b.n - Vec3::Z).length() < 1e-6);
    /// ```
    pub fn apply(
        &self,
        tc: &TextureEvalContext,
        ng: Normal3,
        g: &ShadingGeometry,
    ) -> ShadingGeometry {
        let (dpdu, dpdv) = match self {
            Bump::Displacement(d) => displaced(d, tc, g),
            Bump::NormalMap(image) => normal_mapped(image, tc, g),
        };
        let n = dpdu.cross(dpdv).normalize();
        if !n.is_finite() || !dpdu.is_finite() || !dpdv.is_finite() {
            return *g;
        }
        ShadingGeometry {
            n: n.face_forward(ng),
            dpdu,
            dpdv,
            dndu: g.dndu,
            dndv: g.dndv,
        }
    }

    /// True when the perturbation is the same everywhere (a constant
    /// displacement, which leaves the normal as it is).
    pub fn is_constant(&self) -> bool {
        matches!(self, Bump::Displacement(d) if d.as_constant().is_some())
    }
}

/// `∂p/∂u` and `∂p/∂v` displaced by the bump map `d` (pbrt-v4's `BumpMap`).
fn displaced(d: &FloatTexture, tc: &TextureEvalContext, g: &ShadingGeometry) -> (Vec3, Vec3) {
    let (du, dv) = (BUMP_DELTA, BUMP_DELTA);
    let mut shifted = *tc;
    shifted.p = tc.p + g.dpdu * du;
    shifted.uv.x = tc.uv.x + du;
    let u_displace = d.evaluate(&shifted);
    shifted.p = tc.p + g.dpdv * dv;
    shifted.uv = tc.uv;
    shifted.uv.y = tc.uv.y + dv;
    let v_displace = d.evaluate(&shifted);
    let displace = d.evaluate(tc);
    let dpdu = g.dpdu + g.n * ((u_displace - displace) / du) + g.dndu * displace;
    let dpdv = g.dpdv + g.n * ((v_displace - displace) / dv) + g.dndv * displace;
    (dpdu, dpdv)
}

/// `∂p/∂u` and `∂p/∂v` turned to the normal map's normal (pbrt-v4's
/// `NormalMap`).
fn normal_mapped(image: &TexImage, tc: &TextureEvalContext, g: &ShadingGeometry) -> (Vec3, Vec3) {
    let c = image.bilerp([tc.uv.x, 1.0 - tc.uv.y], WrapMode::Repeat);
    let local = Vec3::from_array(c.map(|v| 2.0 * v - 1.0)).normalize();
    let ns = Frame::from_zx(g.n, g.dpdu).from_local(local);
    let (ulen, vlen) = (g.dpdu.length(), g.dpdv.length());
    let dpdu = (g.dpdu - ns * g.dpdu.dot(ns)).normalize() * ulen;
    let dpdv = ns.cross(dpdu).normalize() * vlen;
    (dpdu, dpdv)
}
