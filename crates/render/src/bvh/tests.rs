//! Tests of the 8-wide tree: its structure against the binary tree, and
//! closest-hit / any-hit queries through [`Accel`] against brute force over
//! all primitives, on mixed scenes (triangles, spheres, disks), including
//! rays that start on surfaces, axis-parallel rays and short `t_max`, with
//! every lane set; and of the [`Tri8`] packets [`Accel`] tests leaves with.

use super::{Bvh, ChildRef, EMPTY_SLOT, INTERIOR, LEAF_LANES, Node8, WIDTH};
use crate::Accel;
use crate::geometry::triangle::{RayLanes, Tri8};
use crate::geometry::{
    Disk, MeshData, Prim, PrimHit, ShapeSet, Sphere, TriangleMesh, intersect_triangle,
};
use crate::math::lanes::{LaneSet, Lanes, RunLanes};
use crate::math::{Bounds3, Point2, Point3, Ray, Transform, Vec3};
use lowdisc::hash::mix64;

/// Seeded uniform floats in `[0, 1)` (SplitMix64-style counter hashing).
struct Rng(u64);

impl Rng {
    fn f(&mut self) -> f32 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        (mix64(self.0) >> 40) as f32 / (1u64 << 24) as f32
    }
    fn r(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.f()
    }
    fn v(&mut self, s: f32) -> Vec3 {
        Vec3::new(self.r(-s, s), self.r(-s, s), self.r(-s, s))
    }
    fn dir(&mut self) -> Vec3 {
        loop {
            let v = self.v(1.0);
            if v.length() > 1e-2 && v.length() <= 1.0 {
                return v.normalize();
            }
        }
    }
}

/// Triangles (some tiny, some sliver, some on shared axis-aligned planes),
/// spheres and disks in `[-4, 4]^3`.
fn scene(seed: u64, tris: usize) -> ShapeSet {
    let mut rng = Rng(seed);
    let mut m = MeshData::default();
    for i in 0..tris as u32 {
        let c = rng.v(4.0);
        let s = if i % 5 == 0 { 0.02 } else { 0.6 };
        let mut p = [c + rng.v(s), c + rng.v(s), c + rng.v(s)];
        if i % 7 == 0 {
            // On the plane z = 1 (axis-aligned, shared by many triangles).
            p.iter_mut().for_each(|q| q.z = 1.0);
        }
        m.positions.extend(p);
        m.indices.push([3 * i, 3 * i + 1, 3 * i + 2]);
    }
    let mut set = ShapeSet::new();
    set.add_mesh(TriangleMesh::new(&Transform::IDENTITY, m, false).unwrap());
    for _ in 0..12 {
        let xf = Transform::translate(rng.v(4.0));
        set.add_sphere(Sphere::new(xf, rng.r(0.1, 0.8), false).unwrap());
        let xf = Transform::translate(rng.v(4.0)) * Transform::rotate(rng.r(0.0, 360.0), rng.dir());
        set.add_disk(Disk::new(xf, 0.0, rng.r(0.1, 0.9), 0.0, false).unwrap());
    }
    set
}

/// The smallest (distance, primitive index) over all primitives hit.
fn brute_force(set: &ShapeSet, ray: &Ray, t_max: f32) -> Option<(Prim, f32)> {
    let mut best: Option<(Prim, f32)> = None;
    for p in set.prims() {
        if let Some(h) = set.intersect(p, ray, best.map_or(t_max, |b| b.1)) {
            best = Some((p, h.t));
        }
    }
    best
}

/// Asserts the accelerated queries equal brute force; returns the hit count.
fn check(set: &ShapeSet, accel: &Accel, rays: &[(Ray, f32)]) -> usize {
    let mut hits = 0;
    for (i, (r, t_max)) in rays.iter().enumerate() {
        let want = brute_force(set, r, *t_max);
        let got = accel.intersect(r, *t_max);
        assert_eq!(accel.intersect_p(r, *t_max), want.is_some(), "ray {i}");
        match (want, got) {
            (None, None) => {}
            (Some((wp, wt)), Some(g)) => {
                // At exact ties, the primitive listed first wins.
                assert_eq!((wt, wp), (g.surface.t, g.prim), "ray {i}: {r:?}");
                let h = set.intersect(g.prim, r, f32::INFINITY).unwrap();
                // The surface built from the packed vertices is the usual one.
                assert_eq!(g.surface, set.surface_hit(g.prim, r, &h), "ray {i}");
                hits += 1;
            }
            _ => panic!("ray {i}: brute force {want:?}, accel {got:?}: {r:?}"),
        }
    }
    hits
}

#[test]
fn queries_equal_brute_force_on_mixed_scenes() {
    for (seed, n) in [(1u64, 2000usize), (2, 300), (3, 5), (4, 0)] {
        let set = scene(seed, n);
        let mut rng = Rng(seed + 100);
        let mut rays = Vec::new();
        for k in 0..2000 {
            let o = rng.v(6.0);
            let mut d = (rng.v(4.0) - o).normalize();
            if k % 4 == 0 {
                // Axis-parallel, with signed zeros.
                d = [Vec3::X, -Vec3::Y, Vec3::Z, Vec3::new(-0.0, 0.0, -1.0)][k / 4 % 4];
            }
            let t_max = if k % 3 == 0 {
                rng.r(0.5, 8.0)
            } else {
                f32::INFINITY
            };
            rays.push((Ray::new(o, d), t_max));
        }
        // Rays leaving points on the surfaces, as secondary rays do.
        let prims = set.prims();
        for _ in 0..1000 {
            let p = prims[(rng.f() * prims.len() as f32) as usize % prims.len()];
            if let Some(s) = set.sample(p, Point2::new(rng.f(), rng.f())) {
                rays.push((Ray::new(s.p, rng.dir()), f32::INFINITY));
            }
        }
        let accel = Accel::build(set.clone());
        let hits = check(&set, &accel, &rays);
        assert!(n == 0 || hits > rays.len() / 5, "seed {seed}: {hits} hits");
        // The portable lanes give the same hits, bit for bit.
        let portable = accel.clone().with_lanes(LaneSet::Portable);
        for (r, t_max) in &rays {
            let bits = |h: Option<crate::accel::Hit>| format!("{h:?}");
            assert_eq!(
                bits(portable.intersect(r, *t_max)),
                bits(accel.intersect(r, *t_max))
            );
            assert_eq!(
                portable.intersect_p(r, *t_max),
                accel.intersect_p(r, *t_max)
            );
        }
    }
}

/// Leaf ranges reachable from `r`, checking every child box against the
/// boxes of the primitives below it.
fn walk(
    bvh: &Bvh,
    boxes: &[Bounds3],
    r: ChildRef,
    b: Option<(&Node8, usize)>,
    out: &mut Vec<(u32, u32)>,
) {
    let inside = |q: &Bounds3| {
        b.is_none_or(|(n, s)| (0..3).all(|a| n.lo(a, s) <= q.min[a] && n.hi(a, s) >= q.max[a]))
    };
    if r.count != INTERIOR {
        assert_eq!(r.child as usize % LEAF_LANES, 0, "a leaf starts a packet");
        let slots = &bvh.slots()[r.child as usize..];
        for &id in &slots[..r.count as usize] {
            assert!(inside(&boxes[id as usize]));
        }
        let end = (r.count as usize).next_multiple_of(LEAF_LANES);
        assert!(
            slots[r.count as usize..end]
                .iter()
                .all(|&s| s == EMPTY_SLOT)
        );
        out.push((r.child, r.count));
        return;
    }
    let n = &bvh.nodes8()[r.child as usize];
    assert!(n.used() >= 2, "an 8-wide node has at least two children");
    for s in 0..WIDTH {
        if n.count[s] == 0 {
            assert!((0..3).all(|a| n.lo(a, s) == f32::INFINITY));
            continue;
        }
        if let Some((p, ps)) = b {
            assert!((0..3).all(|a| p.lo(a, ps) <= n.lo(a, s) && p.hi(a, ps) >= n.hi(a, s)));
        }
        let c = ChildRef {
            child: n.child[s],
            count: n.count[s],
        };
        walk(bvh, boxes, c, Some((n, s)), out);
    }
}

#[test]
fn wide_tree_covers_every_binary_leaf_once() {
    for (seed, n) in [(5u64, 3000usize), (6, 7), (7, 1)] {
        let set = scene(seed, n);
        let boxes: Vec<Bounds3> = set.prims().iter().map(|&p| set.bounds(p)).collect();
        let bvh = Bvh::build(&boxes);
        let mut leaves = Vec::new();
        walk(&bvh, &boxes, bvh.root8(), None, &mut leaves);
        // The same leaves as the binary tree, with the same primitives.
        let mut got: Vec<Vec<u32>> = (leaves.iter())
            .map(|&(first, count)| bvh.slots()[first as usize..][..count as usize].to_vec())
            .collect();
        let mut want: Vec<Vec<u32>> = (bvh.nodes().iter())
            .filter(|n| n.is_leaf())
            .map(|n| bvh.prim_order()[n.offset as usize..][..n.count as usize].to_vec())
            .collect();
        got.sort_unstable();
        want.sort_unstable();
        assert_eq!(got, want, "seed {seed}");
        assert_eq!(bvh.stats().nodes8, bvh.nodes8().len());
        assert!(bvh.levels8() <= bvh.stats().max_depth.max(1));
        // Each 8-wide node absorbs at least one of the (nodes - 1) / 2
        // binary interior nodes.
        assert!(bvh.nodes8().len() <= bvh.nodes().len() / 2 + 1);
    }
    let empty = Bvh::build(&[]);
    assert!(empty.nodes8().is_empty() && empty.root8() == ChildRef::default());
    let r = Ray::new(Point3::ZERO, Vec3::X);
    for l in [LaneSet::Portable, LaneSet::detect()] {
        assert!(l.run(EmptyQueries(&empty, r)));
    }
}

/// Queries on an empty tree find nothing (and never call the leaf test).
struct EmptyQueries<'a>(&'a Bvh, Ray);

impl RunLanes for EmptyQueries<'_> {
    type Output = bool;
    fn run<L: Lanes>(self, l: L) -> bool {
        let closest = self.0.closest_hit(l, &self.1, 1.0, |_, _| Some(0.5));
        closest.is_none() && !self.0.any_hit(l, &self.1, 1.0, |_, _| true)
    }
}

/// A packet test with some lane set.
struct PacketTest<'a>(&'a Tri8, Ray, f32);

impl RunLanes for PacketTest<'_> {
    type Output = (crate::geometry::triangle::Hits8, bool);
    fn run<L: Lanes>(self, l: L) -> Self::Output {
        let rl = RayLanes::new(l, &self.1);
        let closed = self.0.intersect::<L, true>(l, &rl, self.2);
        let open = self.0.intersect::<L, false>(l, &rl, self.2);
        assert_eq!(open.mask & !closed.mask, 0, "open hits are closed hits");
        (open, self.0.any(l, &rl, self.2))
    }
}

/// Every lane of a packet gives exactly `intersect_triangle`'s answer with
/// every lane set, including degenerate triangles, edge-on and
/// axis-parallel rays.
#[test]
fn packet_lanes_equal_the_single_triangle_test() {
    let mut s = 7u64;
    let mut f = move || {
        s += 1;
        (mix64(s) >> 40) as f32 / (1u64 << 24) as f32 * 2.0 - 1.0
    };
    let mut hits = 0;
    for k in 0..20_000 {
        let mut tris = [[Point3::ZERO; 3]; LEAF_LANES];
        for (l, t) in tris.iter_mut().enumerate() {
            *t = [0, 1, 2].map(|_| Point3::new(f(), f(), f()));
            match (k + l) % 6 {
                0 => t[2] = t[0] + (t[1] - t[0]) * 0.5,     // collinear
                1 => t.iter_mut().for_each(|p| p.z = 0.25), // axis-aligned
                _ => {}
            }
        }
        let mut packet = Tri8::default();
        for (l, t) in tris.iter().enumerate() {
            packet.set(l, *t);
        }
        let o = Point3::new(f() * 2.0, f() * 2.0, f() * 2.0);
        // Mostly aimed near a triangle's centroid.
        let [a, b, c] = tris[k % LEAF_LANES];
        let aim = (a + b + c) * (1.0 / 3.0) + Vec3::new(f(), f(), f()) * 0.3;
        let d = match k % 5 {
            0 => Vec3::new(0.0, -0.0, 1.0),
            _ => (aim - o).normalize(),
        };
        let (ray, t_max) = (Ray::new(o, d), if k % 3 == 0 { 1.0 } else { f32::INFINITY });
        for set in [LaneSet::Portable, LaneSet::detect()] {
            let (h, any) = set.run(PacketTest(&packet, ray, t_max));
            assert_eq!(any, h.mask != 0);
            for (l, t) in tris.iter().enumerate() {
                let want = intersect_triangle(&ray, t_max, *t);
                let got = (h.mask >> l & 1 == 1).then(|| PrimHit {
                    t: h.t[l],
                    u: h.u[l],
                    v: h.v[l],
                });
                assert_eq!(got, want, "case {k} lane {l} ({})", set.name());
                hits += want.is_some() as usize;
            }
        }
    }
    assert!(hits > 10000, "{hits}");
}
