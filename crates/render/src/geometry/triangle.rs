//! Triangle meshes: storage (world space), ray-triangle intersection
//! (Möller-Trumbore, one triangle or a [`Tri8`] packet of eight at once),
//! surface-hit construction and uniform area sampling.

mod packet;

pub use packet::{Hits8, PACKET_LANES, RayLanes, Tri8};

use super::{PrimHit, ShadingGeometry, ShapeSample, SurfaceHit};
use crate::content_hash::{ContentHash, ContentSink};
use crate::error::Error;
use crate::math::sampling::sample_uniform_triangle;
use crate::math::{Bounds3, Frame, Normal3, Point2, Point3, Ray, Transform, Vec3};

/// A triangle mesh with vertices already in world space (as pbrt does, the
/// object-to-world transform is applied once at construction).
#[derive(Clone, Debug, Default)]
pub struct TriangleMesh {
    /// World-space vertex positions.
    pub positions: Vec<Point3>,
    /// Vertex indices, three per triangle.
    pub indices: Vec<[u32; 3]>,
    /// Optional world-space unit vertex normals (shading normals), negated
    /// under `ReverseOrientation` as pbrt-v4's `TriangleMesh` does.
    pub normals: Option<Vec<Normal3>>,
    /// Optional per-vertex texture coordinates.
    pub uvs: Option<Vec<Point2>>,
    /// pbrt's `ReverseOrientation` state at creation.
    pub reverse_orientation: bool,
    /// Whether the object-to-world transform swapped handedness.
    pub transform_swaps_handedness: bool,
}

/// Input of [`TriangleMesh::new`], in object space.
#[derive(Clone, Debug, Default)]
pub struct MeshData {
    /// Vertex positions.
    pub positions: Vec<Point3>,
    /// Vertex indices, three per triangle.
    pub indices: Vec<[u32; 3]>,
    /// Optional vertex normals (same length as `positions`).
    pub normals: Option<Vec<Normal3>>,
    /// Optional texture coordinates (same length as `positions`).
    pub uvs: Option<Vec<Point2>>,
}

impl TriangleMesh {
    /// Validates `data` (index range, attribute lengths, finite positions) and
    /// transforms it to world space with `object_to_world`. As in pbrt-v4,
    /// `reverse_orientation` negates the vertex normals (whatever the
    /// transform's handedness); a mesh without normals keeps
    /// `reverse_orientation ^ transform_swaps_handedness` for its face
    /// normals instead.
    pub fn new(
        object_to_world: &Transform,
        data: MeshData,
        reverse_orientation: bool,
    ) -> Result<Self, Error> {
        let n = data.positions.len();
        if n > u32::MAX as usize {
            return Err(Error::InvalidShape("too many vertices".into()));
        }
        if let Some(bad) = data.indices.iter().flatten().find(|&&i| i as usize >= n) {
            return Err(Error::InvalidShape(format!(
                "vertex index {bad} out of range (mesh has {n} vertices)"
            )));
        }
        if data.normals.as_ref().is_some_and(|v| v.len() != n) {
            return Err(Error::InvalidShape(
                "number of normals differs from number of vertices".into(),
            ));
        }
        if data.uvs.as_ref().is_some_and(|v| v.len() != n) {
            return Err(Error::InvalidShape(
                "number of uvs differs from number of vertices".into(),
            ));
        }
        if data.positions.iter().any(|p| !p.is_finite()) {
            return Err(Error::InvalidShape("non-finite vertex position".into()));
        }
        let identity = object_to_world.is_identity();
        let positions = if identity {
            data.positions
        } else {
            data.positions
                .into_iter()
                .map(|p| object_to_world.point(p))
                .collect()
        };
        let normals = data.normals.map(|ns| {
            ns.into_iter()
                .map(|nn| {
                    let w = if identity {
                        nn
                    } else {
                        object_to_world.normal(nn)
                    };
                    let l = w.length();
                    if !(l > 0.0 && l.is_finite()) {
                        Vec3::ZERO
                    } else if reverse_orientation {
                        -(w / l)
                    } else {
                        w / l
                    }
                })
                .collect()
        });
        Ok(TriangleMesh {
            positions,
            indices: data.indices,
            normals,
            uvs: data.uvs,
            reverse_orientation,
            transform_swaps_handedness: object_to_world.swaps_handedness(),
        })
    }
    /// Number of triangles.
    pub fn len(&self) -> usize {
        self.indices.len()
    }
    /// True when the mesh has no triangle.
    pub fn is_empty(&self) -> bool {
        self.indices.is_empty()
    }
    /// The three vertices of triangle `i`.
    #[inline]
    pub fn vertices(&self, i: usize) -> [Point3; 3] {
        let [a, b, c] = self.indices[i];
        [
            self.positions[a as usize],
            self.positions[b as usize],
            self.positions[c as usize],
        ]
    }
    /// World-space bounds of triangle `i`.
    pub fn bounds(&self, i: usize) -> Bounds3 {
        Bounds3::from_points(self.vertices(i))
    }
    /// Area of triangle `i`.
    pub fn area(&self, i: usize) -> f32 {
        let [p0, p1, p2] = self.vertices(i);
        0.5 * (p1 - p0).cross(p2 - p0).length()
    }
    /// Intersects triangle `i` (see [`intersect_triangle`]).
    #[inline]
    pub fn intersect(&self, i: usize, ray: &Ray, t_max: f32) -> Option<PrimHit> {
        intersect_triangle(ray, t_max, self.vertices(i))
    }

    /// The unit face normal `ng`, oriented by pbrt's rules: the
    /// face normal `(p0 - p2) × (p1 - p2)`, flipped toward the interpolated
    /// shading normal when the mesh has normals, else flipped when
    /// `reverse_orientation ^ transform_swaps_handedness`.
    fn oriented_normal(&self, ng: Normal3, ns: Option<Normal3>) -> Normal3 {
        match ns {
            Some(ns) => ng.face_forward(ns),
            None if self.reverse_orientation ^ self.transform_swaps_handedness => -ng,
            None => ng,
        }
    }

    fn uv_of(&self, i: usize) -> [Point2; 3] {
        match &self.uvs {
            Some(uv) => self.indices[i].map(|k| uv[k as usize]),
            None => [
                Point2::new(0.0, 0.0),
                Point2::new(1.0, 0.0),
                Point2::new(1.0, 1.0),
            ],
        }
    }

    fn shading_normal(&self, i: usize, b: [f32; 3]) -> Option<Normal3> {
        let ns = self.normals.as_ref()?;
        let [a, c, d] = self.indices[i].map(|k| ns[k as usize]);
        let n = a * b[0] + c * b[1] + d * b[2];
        let l = n.length();
        (l > 0.0 && l.is_finite()).then(|| n / l)
    }

    /// Full surface information for a hit `h` on triangle `i` found by
    /// [`TriangleMesh::intersect`].
    pub fn surface_hit(&self, i: usize, h: &PrimHit) -> SurfaceHit {
        self.surface_hit_at(i, h, self.vertices(i), None)
    }

    /// The normal and tangent of triangle `i` (vertices `p` as returned by
    /// [`TriangleMesh::vertices`]) when they are the same at every point of
    /// it, i.e. when the mesh has no shading normals; `None` otherwise.
    /// Computed as [`TriangleMesh::surface_hit`] computes them, so a caller
    /// may keep them per triangle and pass them to
    /// [`TriangleMesh::surface_hit_at`] with the same result.
    pub fn flat_frame(&self, i: usize, p: [Point3; 3]) -> Option<FlatFrame> {
        if self.normals.is_some() {
            return None;
        }
        let ng = self.oriented_normal(face_normal(p), None);
        let dpdu = tangent(self.uv_of(i), p, ng);
        Some(FlatFrame {
            ng,
            dpdu,
            shading: Frame::shading(ng, dpdu),
        })
    }

    /// [`TriangleMesh::surface_hit`] given the triangle's vertices (as
    /// returned by [`TriangleMesh::vertices`]) and, if the caller keeps it,
    /// its [`TriangleMesh::flat_frame`], saving their computation.
    #[inline]
    pub fn surface_hit_at(
        &self,
        i: usize,
        h: &PrimHit,
        [p0, p1, p2]: [Point3; 3],
        frame: Option<FlatFrame>,
    ) -> SurfaceHit {
        let b = [1.0 - h.u - h.v, h.u, h.v];
        let p = p0 * b[0] + p1 * b[1] + p2 * b[2];
        let uv = self.uv_of(i);
        let uv_hit = uv[0] * b[0] + uv[1] * b[1] + uv[2] * b[2];
        let (ng, ns, dpdu) = match frame {
            Some(f) => (f.ng, None, f.dpdu),
            None => {
                let ns = self.shading_normal(i, b);
                let ng = self.oriented_normal(face_normal([p0, p1, p2]), ns);
                (ng, ns, tangent(uv, [p0, p1, p2], ng))
            }
        };
        SurfaceHit {
            t: h.t,
            p,
            uv: uv_hit,
            bary: b,
            ng,
            ns: ns.unwrap_or(ng),
            dpdu,
        }
    }

    /// The shading geometry of `hit`, a hit on triangle `i` (see
    /// [`super::differentials`]).
    pub fn shading_geometry(&self, i: usize, hit: &SurfaceHit) -> ShadingGeometry {
        let p = self.vertices(i);
        let uv = self.uv_of(i);
        let dpdv = bitangent(uv, p, hit.ng, hit.dpdu);
        let Some(normals) = &self.normals else {
            return ShadingGeometry::flat(hit.ns, hit.dpdu, dpdv);
        };
        let n = hit.ns;
        let t = n.cross(hit.dpdu);
        let (s, t) = if t.length_squared() > 0.0 {
            (t.cross(n), t)
        } else {
            let f = Frame::from_z(n);
            (f.x, f.y)
        };
        let [n0, n1, n2] = self.indices[i].map(|k| normals[k as usize]);
        let (dndu, dndv) = normal_derivatives(uv, [n0, n1, n2]);
        ShadingGeometry {
            n,
            dpdu: s,
            dpdv: t,
            dndu,
            dndv,
        }
    }

    /// Samples a point uniformly by area on triangle `i`; `pdf` is `1 / area`.
    pub fn sample(&self, i: usize, u: Point2) -> Option<ShapeSample> {
        let area = self.area(i);
        if !(area > 0.0) {
            return None;
        }
        let b = sample_uniform_triangle(u);
        let [p0, p1, p2] = self.vertices(i);
        let p = p0 * b[0] + p1 * b[1] + p2 * b[2];
        let n = self.oriented_normal(face_normal([p0, p1, p2]), self.shading_normal(i, b));
        let uv = self.uv_of(i);
        let uv = uv[0] * b[0] + uv[1] * b[1] + uv[2] * b[2];
        Some(ShapeSample {
            p,
            n,
            uv,
            pdf: 1.0 / area,
        })
    }
}

/// The parts of a triangle's [`SurfaceHit`] that do not depend on the hit
/// point when its mesh has no shading normals (see
/// [`TriangleMesh::flat_frame`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlatFrame {
    /// The oriented unit geometric normal (also the shading normal).
    pub ng: Normal3,
    /// The tangent `∂p/∂u`.
    pub dpdu: Vec3,
    /// The BSDF's shading frame there, `Frame::shading(ng, dpdu)`.
    pub shading: Frame,
}

/// The unit face normal `(p0 - p2) × (p1 - p2)`, not yet oriented.
#[inline]
fn face_normal([p0, p1, p2]: [Point3; 3]) -> Normal3 {
    (p0 - p2).cross(p1 - p2).normalize()
}

/// `∂p/∂u` from the uv parameterisation `uv` of the vertices `p`; any
/// tangent of the plane of `ng` when that is degenerate.
#[inline]
fn tangent(uv: [Point2; 3], [p0, p1, p2]: [Point3; 3], ng: Normal3) -> Vec3 {
    let (du02, du12) = (uv[0] - uv[2], uv[1] - uv[2]);
    let (dp02, dp12) = (p0 - p2, p1 - p2);
    let det = du02.x * du12.y - du02.y * du12.x;
    let dpdu = if det.abs() > 1e-9 {
        (dp02 * du12.y - dp12 * du02.y) / det
    } else {
        Vec3::ZERO
    };
    if !(dpdu.cross(ng).length_squared() > 0.0) || !dpdu.is_finite() {
        Frame::from_z(ng).x
    } else {
        dpdu
    }
}

/// `∂p/∂v` from the uv parameterisation `uv` of the vertices `p`, given
/// `∂p/∂u` as [`tangent`] returned it; when the parameterisation is
/// degenerate, the second tangent of the frame about `ng` whose first is
/// that `∂p/∂u`.
fn bitangent(uv: [Point2; 3], [p0, p1, p2]: [Point3; 3], ng: Normal3, dpdu: Vec3) -> Vec3 {
    let (du02, du12) = (uv[0] - uv[2], uv[1] - uv[2]);
    let (dp02, dp12) = (p0 - p2, p1 - p2);
    let det = du02.x * du12.y - du02.y * du12.x;
    let dpdv = if det.abs() > 1e-9 {
        (dp12 * du02.x - dp02 * du12.x) / det
    } else {
        Vec3::ZERO
    };
    if !(dpdu.cross(dpdv).length_squared() > 0.0) || !dpdv.is_finite() {
        ng.cross(dpdu.normalize())
    } else {
        dpdv
    }
}

/// `∂n/∂u` and `∂n/∂v` of the vertex normals `n` over the uv
/// parameterisation `uv`; for a degenerate parameterisation, two tangents
/// of `(n2 - n0) × (n1 - n0)` (zero when that is zero), as pbrt-v4 does.
fn normal_derivatives(uv: [Point2; 3], [n0, n1, n2]: [Normal3; 3]) -> (Vec3, Vec3) {
    let (du02, du12) = (uv[0] - uv[2], uv[1] - uv[2]);
    let (dn1, dn2) = (n0 - n2, n1 - n2);
    let det = du02.x * du12.y - du02.y * du12.x;
    if det.abs() >= 1e-32 {
        let inv = 1.0 / det;
        return (
            (dn1 * du12.y - dn2 * du02.y) * inv,
            (dn2 * du02.x - dn1 * du12.x) * inv,
        );
    }
    let dn = (n2 - n0).cross(n1 - n0);
    if dn.length_squared() == 0.0 {
        return (Vec3::ZERO, Vec3::ZERO);
    }
    let f = Frame::from_z(dn.normalize());
    (f.x, f.y)
}

/// Möller-Trumbore ray-triangle test (two-sided). Returns the hit with
/// `0 < t < t_max` and barycentrics `u = b1`, `v = b2` (weights of the second
/// and third vertex). Degenerate triangles and NaN rays never hit.
#[inline]
pub fn intersect_triangle(ray: &Ray, t_max: f32, [p0, p1, p2]: [Point3; 3]) -> Option<PrimHit> {
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let pvec = ray.d.cross(e2);
    let det = e1.dot(pvec);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let inv = 1.0 / det;
    let tvec = ray.o - p0;
    let u = tvec.dot(pvec) * inv;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let qvec = tvec.cross(e1);
    let v = ray.d.dot(qvec) * inv;
    if !(v >= 0.0 && u + v <= 1.0) {
        return None;
    }
    let t = e2.dot(qvec) * inv;
    if t > 0.0 && t < t_max {
        Some(PrimHit { t, u, v })
    } else {
        None
    }
}

impl ContentHash for TriangleMesh {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let TriangleMesh {
            positions,
            indices,
            normals,
            uvs,
            reverse_orientation,
            transform_swaps_handedness,
        } = self;
        (positions, indices, normals, uvs).feed(sink);
        (reverse_orientation, transform_swaps_handedness).feed(sink);
    }
}
