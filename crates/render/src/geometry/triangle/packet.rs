//! [`Tri8`]: eight triangles tested against one ray at once, one lane each
//! ([`crate::math::lanes`]), with
//! [`intersect_triangle`](super::intersect_triangle)'s arithmetic
//! (bit-identical results, whatever the lane set).

use crate::math::lanes::Lanes;
use crate::math::{Point3, Ray, Vec3};

/// Lanes of a packet.
pub const PACKET_LANES: usize = 8;

/// Eight triangles in structure-of-arrays form (`[axis][lane]`), for
/// [`Tri8::intersect`]: the first vertex and the two edges from it, which
/// the test would otherwise subtract on every ray (the same subtractions,
/// so the same bits). Unused lanes hold degenerate (all-zero) triangles,
/// which never hit.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C, align(32))]
pub struct Tri8 {
    /// The first vertex `p0`.
    pub p0: [[f32; PACKET_LANES]; 3],
    /// `p1 - p0`.
    pub e1: [[f32; PACKET_LANES]; 3],
    /// `p2 - p0`.
    pub e2: [[f32; PACKET_LANES]; 3],
}

/// Per-lane results of [`Tri8::intersect`]: `mask` bit `l` is set when lane
/// `l` is hit; then `t[l]`, `u[l]`, `v[l]` are as in
/// [`PrimHit`](crate::geometry::PrimHit).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hits8 {
    /// Hit distances.
    pub t: [f32; PACKET_LANES],
    /// Barycentric weights of the second vertex.
    pub u: [f32; PACKET_LANES],
    /// Barycentric weights of the third vertex.
    pub v: [f32; PACKET_LANES],
    /// Lanes hit.
    pub mask: u32,
}

/// A ray's origin and direction splatted across the lanes, made once per
/// query for all its packets.
pub struct RayLanes<L: Lanes> {
    o: [L::F; 3],
    d: [L::F; 3],
}

impl<L: Lanes> RayLanes<L> {
    /// Splats `ray`.
    #[inline(always)]
    pub fn new(l: L, ray: &Ray) -> Self {
        RayLanes {
            o: splat3(l, ray.o),
            d: splat3(l, ray.d),
        }
    }
}

impl Tri8 {
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

    /// [`intersect_triangle`](super::intersect_triangle) on all lanes at
    /// once, one register per coordinate, with the same arithmetic in the
    /// same order per lane (no fused multiply-adds), so the results are
    /// bit-identical to it. With `CLOSED`, hits at exactly `t_max` count
    /// too (closest-hit queries break ties at equal distances by primitive).
    ///
    /// (No closures here: a closure would be compiled without the lane
    /// set's target features and keep its intrinsics as calls.)
    #[inline(always)]
    pub fn intersect<L: Lanes, const CLOSED: bool>(
        &self,
        l: L,
        ray: &RayLanes<L>,
        t_max: f32,
    ) -> Hits8 {
        let (o, d) = (&ray.o, &ray.d);
        let p0 = load3(l, &self.p0);
        let e1 = load3(l, &self.e1);
        let e2 = load3(l, &self.e2);
        let pvec = cross(l, d, &e2);
        let det = dot(l, &e1, &pvec);
        let (zero, one) = (l.splat(0.0), l.splat(1.0));
        let inv = l.div(one, det);
        let tvec = [l.sub(o[0], p0[0]), l.sub(o[1], p0[1]), l.sub(o[2], p0[2])];
        let u = l.mul(dot(l, &tvec, &pvec), inv);
        let qvec = cross(l, &tvec, &e1);
        let v = l.mul(dot(l, d, &qvec), inv);
        let t = l.mul(dot(l, &e2, &qvec), inv);
        let in_range = if CLOSED {
            l.le(t, l.splat(t_max))
        } else {
            l.lt(t, l.splat(t_max))
        };
        let mut hit = l.and(l.ne(det, zero), l.lt(l.abs(det), l.splat(f32::INFINITY)));
        hit = l.and(hit, l.and(l.ge(u, zero), l.le(u, one)));
        hit = l.and(hit, l.and(l.ge(v, zero), l.le(l.add(u, v), one)));
        hit = l.and(hit, l.and(l.gt(t, zero), in_range));
        Hits8 {
            t: l.store(t),
            u: l.store(u),
            v: l.store(v),
            mask: l.bits(hit),
        }
    }

    /// True if any lane is hit in `(0, t_max)` (no distances kept).
    #[inline(always)]
    pub fn any<L: Lanes>(&self, l: L, ray: &RayLanes<L>, t_max: f32) -> bool {
        self.intersect::<L, false>(l, ray, t_max).mask != 0
    }
}

/// Three rows of lanes.
#[inline(always)]
fn load3<L: Lanes>(l: L, v: &[[f32; PACKET_LANES]; 3]) -> [L::F; 3] {
    [l.load(&v[0]), l.load(&v[1]), l.load(&v[2])]
}

/// [`Vec3::cross`] per lane, in its operation order.
#[inline(always)]
fn cross<L: Lanes>(l: L, a: &[L::F; 3], b: &[L::F; 3]) -> [L::F; 3] {
    [
        l.sub(l.mul(a[1], b[2]), l.mul(a[2], b[1])),
        l.sub(l.mul(a[2], b[0]), l.mul(a[0], b[2])),
        l.sub(l.mul(a[0], b[1]), l.mul(a[1], b[0])),
    ]
}

/// [`Vec3::dot`] per lane, in its operation order.
#[inline(always)]
fn dot<L: Lanes>(l: L, a: &[L::F; 3], b: &[L::F; 3]) -> L::F {
    l.add(
        l.add(l.mul(a[0], b[0]), l.mul(a[1], b[1])),
        l.mul(a[2], b[2]),
    )
}

/// A vector's coordinates splatted.
#[inline(always)]
pub(crate) fn splat3<L: Lanes>(l: L, v: Vec3) -> [L::F; 3] {
    [l.splat(v.x), l.splat(v.y), l.splat(v.z)]
}
