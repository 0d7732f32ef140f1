//! [`Tri4`]: four triangles tested against one ray at once, one SIMD lane
//! each, with [`intersect_triangle`](super::intersect_triangle)'s
//! arithmetic (bit-identical results).

use crate::math::{Point3, Ray, Vec3};
use wide::{CmpGe, CmpGt, CmpLe, CmpLt, CmpNe, f32x4};

/// Four triangles in structure-of-arrays form (`[axis][lane]`), for
/// [`Tri4::intersect`]: the first vertex and the two edges from it, which
/// the test would otherwise subtract on every ray (the same subtractions,
/// so the same bits). Unused lanes hold degenerate (all-zero) triangles,
/// which never hit.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C, align(16))]
pub struct Tri4 {
    /// The first vertex `p0`.
    pub p0: [[f32; 4]; 3],
    /// `p1 - p0`.
    pub e1: [[f32; 4]; 3],
    /// `p2 - p0`.
    pub e2: [[f32; 4]; 3],
}

/// Per-lane results of [`Tri4::intersect`]: `mask` bit `l` is set when lane
/// `l` is hit; then `t[l]`, `u[l]`, `v[l]` are as in [`PrimHit`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hits4 {
    /// Hit distances.
    pub t: [f32; 4],
    /// Barycentric weights of the second vertex.
    pub u: [f32; 4],
    /// Barycentric weights of the third vertex.
    pub v: [f32; 4],
    /// Lanes hit.
    pub mask: u32,
}

impl Tri4 {
    /// Stores triangle `[p0, p1, p2]` in `lane`.
    pub fn set(&mut self, lane: usize, [p0, p1, p2]: [Point3; 3]) {
        let parts = [
            (&mut self.p0, p0),
            (&mut self.e1, p1 - p0),
            (&mut self.e2, p2 - p0),
        ];
        for (dst, q) in parts {
            [dst[0][lane], dst[1][lane], dst[2][lane]] = [q.x, q.y, q.z];
        }
    }

    /// [`intersect_triangle`](super::intersect_triangle) on all four lanes at once, one `wide::f32x4`
    /// register per coordinate, with the same arithmetic in the same order
    /// per lane (no fused multiply-adds), so the results are bit-identical
    /// to it. With `CLOSED`, hits at exactly `t_max` count too (closest-hit
    /// queries break ties at equal distances by primitive).
    #[inline(always)]
    pub fn intersect<const CLOSED: bool>(&self, ray: &Ray, t_max: f32) -> Hits4 {
        let splat = |v: Vec3| [v.x, v.y, v.z].map(f32x4::splat);
        let (o, d) = (splat(ray.o), splat(ray.d));
        let [p0, e1, e2] = [self.p0, self.e1, self.e2].map(|v| v.map(f32x4::from));
        let sub = |a: [f32x4; 3], b: [f32x4; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
        let pvec = cross4(d, e2);
        let det = dot4(e1, pvec);
        let inv = f32x4::ONE / det;
        let tvec = sub(o, p0);
        let u = dot4(tvec, pvec) * inv;
        let qvec = cross4(tvec, e1);
        let v = dot4(d, qvec) * inv;
        let t = dot4(e2, qvec) * inv;
        let zero = f32x4::ZERO;
        let hit = det.cmp_ne(zero)
            & det.abs().cmp_lt(f32x4::splat(f32::INFINITY))
            & u.cmp_ge(zero)
            & u.cmp_le(f32x4::ONE)
            & v.cmp_ge(zero)
            & (u + v).cmp_le(f32x4::ONE)
            & t.cmp_gt(zero)
            & if CLOSED {
                t.cmp_le(f32x4::splat(t_max))
            } else {
                t.cmp_lt(f32x4::splat(t_max))
            };
        Hits4 {
            t: t.to_array(),
            u: u.to_array(),
            v: v.to_array(),
            mask: hit.move_mask() as u32,
        }
    }
}

/// [`Vec3::cross`] per lane, in its operation order.
#[inline(always)]
fn cross4(a: [f32x4; 3], b: [f32x4; 3]) -> [f32x4; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// [`Vec3::dot`] per lane, in its operation order.
#[inline(always)]
fn dot4(a: [f32x4; 3], b: [f32x4; 3]) -> f32x4 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
