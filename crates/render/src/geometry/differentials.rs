//! The shading geometry's partial derivatives at a hit, as pbrt-v4 keeps
//! them in `SurfaceInteraction::shading`: the shading normal, `∂p/∂u`,
//! `∂p/∂v`, `∂n/∂u` and `∂n/∂v`. Only bump and normal mapping need them, so
//! they are computed on demand ([`ShapeSet::shading_geometry`]) rather than
//! at every hit.
//!
//! As in pbrt-v4:
//! * a triangle without vertex normals has its geometric derivatives (from
//!   the uv parameterisation; any orthonormal tangents of its plane when that
//!   is degenerate) and `∂n = 0`;
//! * a triangle with vertex normals has the tangent `s = (n × ∂p/∂u) × n` and
//!   the bitangent `t = n × s` (so `|t| = |s|`, not `|∂p/∂v|`), and `∂n/∂u`,
//!   `∂n/∂v` from its vertex normals over the uv parameterisation;
//! * a sphere has `∂n/∂u = (∂p/∂u) / r`, `∂n/∂v = (∂p/∂v) / r` in object
//!   space (the Weingarten equations for a sphere), transformed as normals;
//! * a disk has `∂p/∂v` pointing inwards, of length `radius - innerradius`,
//!   and `∂n = 0`.

use super::{Prim, ShapeSet, SurfaceHit};
use crate::math::{Normal3, Vec3};

/// The shading geometry at a hit (world space).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadingGeometry {
    /// Unit shading normal (the hit's `ns`).
    pub n: Normal3,
    /// Shading `∂p/∂u`.
    pub dpdu: Vec3,
    /// Shading `∂p/∂v`.
    pub dpdv: Vec3,
    /// `∂n/∂u`.
    pub dndu: Vec3,
    /// `∂n/∂v`.
    pub dndv: Vec3,
}

impl ShadingGeometry {
    /// A flat surface: normal `n`, tangents `dpdu` and `dpdv`, no curvature.
    pub fn flat(n: Normal3, dpdu: Vec3, dpdv: Vec3) -> ShadingGeometry {
        ShadingGeometry {
            n,
            dpdu,
            dpdv,
            dndu: Vec3::ZERO,
            dndv: Vec3::ZERO,
        }
    }
}

impl ShapeSet {
    /// The shading geometry of `hit`, a hit on primitive `p` (see the
    /// module documentation).
    pub fn shading_geometry(&self, p: Prim, hit: &SurfaceHit) -> ShadingGeometry {
        match p {
            Prim::Triangle { mesh, tri } => {
                self.meshes[mesh as usize].shading_geometry(tri as usize, hit)
            }
            Prim::Sphere(i) => self.spheres[i as usize].shading_geometry(hit),
            Prim::Disk(i) => self.disks[i as usize].shading_geometry(hit),
        }
    }
}
