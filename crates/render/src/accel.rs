//! The scene's shapes with their BVH: ray queries returning full hits.
//!
//! Triangle vertices are stored as [`Tri8`] packets, one per group of
//! [`LEAF_LANES`] slots of the 8-wide tree ([`Bvh::slots`]: each leaf
//! starts a new group), so a leaf of up to eight triangles is tested with
//! one packet, without looking up the primitive kind; other shapes
//! (spheres, disks) in a packet's lanes are tested one by one. Queries run
//! with the lanes [`LaneSet::detect`] chose when the accelerator was built
//! (AVX2 or portable), with bit-identical results either way.
//!
//! Primitives with an alpha cut-out ([`crate::geometry::alpha`]) are
//! marked per packet lane, so that only their hits pay for the alpha test.

use crate::bvh::{BuildOptions, Bvh, BvhStats, EMPTY_SLOT, LEAF_LANES};
use crate::geometry::triangle::{FlatFrame, PACKET_LANES, RayLanes, Tri8};
use crate::geometry::{Prim, PrimHit, ShapeSet, SurfaceHit};
use crate::math::lanes::{LaneSet, Lanes, RunLanes};
use crate::math::{Bounds3, Frame, Ray};
use rayon::prelude::*;

const _: () = assert!(PACKET_LANES == LEAF_LANES, "one packet per leaf group");

/// A ray hit: which primitive, and the surface there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// The primitive hit.
    pub prim: Prim,
    /// Surface information at the hit.
    pub surface: SurfaceHit,
    /// The shading frame of a BSDF at the hit,
    /// `Frame::shading(surface.ns, surface.dpdu)`, when it is kept per
    /// primitive (triangles without shading normals); see
    /// [`crate::bsdf::material::Material::bsdf_in_frame`].
    pub shading: Option<Frame>,
}

/// Shapes plus a BVH over all their primitives.
#[derive(Clone, Debug)]
pub struct Accel {
    shapes: ShapeSet,
    bvh: Bvh,
    /// Every primitive, in [`ShapeSet::prims`] order (the BVH's input order).
    prims: Vec<Prim>,
    /// Per group of [`LEAF_LANES`] slots: its triangles (zero in other lanes).
    tris: Vec<Tri8>,
    /// Per group of slots: bit `l` set when lane `l` is another shape.
    others: Vec<u8>,
    /// Per group of slots: bit `l` set when lane `l` has an alpha cut-out
    /// (empty when no shape has one).
    cut: Vec<u8>,
    /// Per primitive (input order): the triangle's [`FlatFrame`], if it has one.
    frames: Vec<Option<FlatFrame>>,
    bounds: Bounds3,
    lanes: LaneSet,
}

/// The closest hit found so far in a closest-hit query, with its tie-break
/// rule: a hit wins if it is nearer, or exactly as near and its primitive
/// comes first in [`ShapeSet::prims`]. The result is thus the smallest
/// (distance, primitive index) over all primitives hit, whatever the order
/// in which the BVH visits them (and so whatever its shape or width).
struct Closest {
    /// Distance of the hit, or the query's `t_max` before the first one.
    t: f32,
    /// Index in [`ShapeSet::prims`] of the hit primitive; 0 before the first
    /// hit, so that nothing at exactly `t_max` is taken (`(0, t_max)` is open).
    id: u32,
    /// The hit on primitive `id`.
    hit: Option<PrimHit>,
}

impl Closest {
    #[inline(always)]
    fn new(t_max: f32) -> Self {
        Closest {
            t: t_max,
            id: 0,
            hit: None,
        }
    }
    /// True if a hit at `t` on primitive `id` replaces the current one.
    #[inline(always)]
    fn beats(&self, t: f32, id: u32) -> bool {
        t < self.t || (t == self.t && id < self.id)
    }
    #[inline(always)]
    fn set(&mut self, id: u32, hit: PrimHit) {
        (self.t, self.id, self.hit) = (hit.t, id, Some(hit));
    }
    /// The exclusive bound for a shape's own test that still admits a tie:
    /// the next float above the current hit's distance (`t_max` itself
    /// before the first hit).
    #[inline(always)]
    fn bound(&self) -> f32 {
        if self.hit.is_some() && self.t.is_finite() {
            f32::from_bits(self.t.to_bits() + 1)
        } else {
            self.t
        }
    }
}

/// A closest-hit query, run with some [`Lanes`].
struct ClosestQuery<'a> {
    accel: &'a Accel,
    ray: &'a Ray,
    t_max: f32,
}

impl RunLanes for ClosestQuery<'_> {
    type Output = Option<(u32, PrimHit)>;
    #[inline(always)]
    fn run<L: Lanes>(self, l: L) -> Self::Output {
        let (accel, ray) = (self.accel, self.ray);
        let rl = RayLanes::new(l, ray);
        let mut best = Closest::new(self.t_max);
        // Closures are inlined by force: compiled on their own, they would
        // lack the lane set's target features (see `Tri8::intersect`).
        accel.bvh.closest_hit(
            l,
            ray,
            self.t_max,
            #[inline(always)]
            |first, count| accel.leaf_closest(l, &rl, ray, first, count, &mut best),
        );
        best.hit.map(|h| (best.id, h))
    }
}

/// An any-hit query, run with some [`Lanes`].
struct AnyQuery<'a> {
    accel: &'a Accel,
    ray: &'a Ray,
    t_max: f32,
}

impl RunLanes for AnyQuery<'_> {
    type Output = bool;
    #[inline(always)]
    fn run<L: Lanes>(self, l: L) -> bool {
        let (accel, ray, t_max) = (self.accel, self.ray, self.t_max);
        let rl = RayLanes::new(l, ray);
        accel.bvh.any_hit(
            l,
            ray,
            t_max,
            #[inline(always)]
            |first, count| accel.leaf_any(l, &rl, ray, first, count, t_max),
        )
    }
}

/// The packets of the slots `first..first + count` (`first` a multiple of
/// [`LEAF_LANES`]).
#[inline(always)]
fn packets(first: u32, count: u32) -> std::ops::Range<usize> {
    first as usize / LEAF_LANES..(first + count).div_ceil(LEAF_LANES as u32) as usize
}

impl Accel {
    /// Builds the BVH over every primitive of `shapes` (default options).
    pub fn build(shapes: ShapeSet) -> Accel {
        Self::build_with(shapes, BuildOptions::default())
    }

    /// Builds the BVH over every primitive of `shapes`.
    pub fn build_with(shapes: ShapeSet, opts: BuildOptions) -> Accel {
        let prims = shapes.prims();
        let boxes: Vec<Bounds3> = prims.par_iter().map(|&p| shapes.bounds(p)).collect();
        let bounds = boxes.iter().fold(Bounds3::EMPTY, |a, b| a.union(b));
        let bvh = Bvh::build_with(&boxes, opts);
        let (tris, others) = bvh
            .slots()
            .par_chunks(LEAF_LANES)
            .map(|group| {
                let (mut packet, mut others) = (Tri8::default(), 0u8);
                for (lane, &id) in group.iter().enumerate() {
                    match prims.get(id as usize) {
                        Some(&Prim::Triangle { mesh, tri }) => {
                            packet.set(lane, shapes.meshes[mesh as usize].vertices(tri as usize));
                        }
                        Some(_) => others |= 1 << lane,
                        None => debug_assert_eq!(id, EMPTY_SLOT),
                    }
                }
                (packet, others)
            })
            .unzip();
        let cut = if shapes.has_alpha() {
            (bvh.slots().chunks(LEAF_LANES))
                .map(|group| {
                    (group.iter().enumerate())
                        .filter(|(_, id)| {
                            prims
                                .get(**id as usize)
                                .is_some_and(|&p| shapes.alpha(p).is_some())
                        })
                        .fold(0u8, |m, (lane, _)| m | 1 << lane)
                })
                .collect()
        } else {
            Vec::new()
        };
        let frames = (prims.par_iter())
            .map(|&p| match p {
                Prim::Triangle { mesh, tri } => {
                    let m = &shapes.meshes[mesh as usize];
                    m.flat_frame(tri as usize, m.vertices(tri as usize))
                }
                _ => None,
            })
            .collect();
        Accel {
            shapes,
            bvh,
            prims,
            tris,
            others,
            cut,
            frames,
            bounds,
            lanes: LaneSet::detect(),
        }
    }

    /// The same accelerator running its queries with `lanes` (tests compare
    /// lane sets; [`Accel::build`] takes the widest the CPU has).
    pub fn with_lanes(mut self, lanes: LaneSet) -> Accel {
        self.lanes = lanes;
        self
    }
    /// The lanes queries run with.
    pub fn lanes(&self) -> LaneSet {
        self.lanes
    }
    /// The shapes.
    pub fn shapes(&self) -> &ShapeSet {
        &self.shapes
    }
    /// The BVH.
    pub fn bvh(&self) -> &Bvh {
        &self.bvh
    }
    /// BVH statistics.
    pub fn stats(&self) -> &BvhStats {
        self.bvh.stats()
    }
    /// World bounds of all primitives.
    pub fn bounds(&self) -> Bounds3 {
        self.bounds
    }

    /// The lanes of packet `p` that have an alpha cut-out.
    #[inline(always)]
    fn cut(&self, p: usize) -> u8 {
        self.cut.get(p).copied().unwrap_or(0)
    }

    /// Tests the primitives in slots `first..first + count`, recording in
    /// `best` the hit that [`Closest::beats`] the one found so far; returns
    /// its distance when it changed.
    #[inline(always)]
    fn leaf_closest<L: Lanes>(
        &self,
        l: L,
        rl: &RayLanes<L>,
        ray: &Ray,
        first: u32,
        count: u32,
        best: &mut Closest,
    ) -> Option<f32> {
        let slots = self.bvh.slots();
        let mut found = None;
        for p in packets(first, count) {
            let ids = &slots[LEAF_LANES * p..][..LEAF_LANES];
            let h = self.tris[p].intersect::<L, true>(l, rl, best.t);
            let cut = self.cut(p);
            let mut m = h.mask;
            while m != 0 {
                let lane = m.trailing_zeros() as usize;
                m &= m - 1;
                if best.beats(h.t[lane], ids[lane]) {
                    let hit = PrimHit {
                        t: h.t[lane],
                        u: h.u[lane],
                        v: h.v[lane],
                    };
                    if cut & (1 << lane) != 0 && !self.keeps(ids[lane], ray, &hit) {
                        continue;
                    }
                    best.set(ids[lane], hit);
                    found = Some(best.t);
                }
            }
            let mut other = self.others[p] as u32;
            while other != 0 {
                let lane = other.trailing_zeros() as usize;
                let id = ids[lane];
                other &= other - 1;
                let prim = self.prims[id as usize];
                let h = if cut & (1 << lane) != 0 {
                    self.shapes.intersect_alpha(prim, ray, best.bound())
                } else {
                    self.shapes.intersect(prim, ray, best.bound())
                };
                if let Some(h) = h.filter(|h| best.beats(h.t, id)) {
                    best.set(id, h);
                    found = Some(best.t);
                }
            }
        }
        found
    }

    /// True if any primitive in slots `first..first + count` is hit in
    /// `(0, t_max)`.
    #[inline(always)]
    fn leaf_any<L: Lanes>(
        &self,
        l: L,
        rl: &RayLanes<L>,
        ray: &Ray,
        first: u32,
        count: u32,
        t_max: f32,
    ) -> bool {
        let slots = self.bvh.slots();
        for p in packets(first, count) {
            let cut = self.cut(p);
            if cut == 0 {
                if self.tris[p].any(l, rl, t_max) {
                    return true;
                }
            } else if self.any_cut_triangle(l, rl, ray, p, t_max) {
                return true;
            }
            let mut other = self.others[p] as u32;
            while other != 0 {
                let lane = other.trailing_zeros() as usize;
                let prim = self.prims[slots[LEAF_LANES * p + lane] as usize];
                other &= other - 1;
                let h = if cut & (1 << lane) != 0 {
                    self.shapes.intersect_alpha(prim, ray, t_max)
                } else {
                    self.shapes.intersect(prim, ray, t_max)
                };
                if h.is_some() {
                    return true;
                }
            }
        }
        false
    }

    /// True if a triangle of packet `p` (which has alpha cut-outs) is hit
    /// in `(0, t_max)` where its alpha keeps the hit.
    #[inline(always)]
    fn any_cut_triangle<L: Lanes>(
        &self,
        l: L,
        rl: &RayLanes<L>,
        ray: &Ray,
        p: usize,
        t_max: f32,
    ) -> bool {
        let (cut, ids) = (
            self.cut(p),
            &self.bvh.slots()[LEAF_LANES * p..][..LEAF_LANES],
        );
        let h = self.tris[p].intersect::<L, false>(l, rl, t_max);
        let mut m = h.mask;
        while m != 0 {
            let lane = m.trailing_zeros() as usize;
            m &= m - 1;
            let hit = PrimHit {
                t: h.t[lane],
                u: h.u[lane],
                v: h.v[lane],
            };
            if cut & (1 << lane) == 0 || self.keeps(ids[lane], ray, &hit) {
                return true;
            }
        }
        false
    }

    /// True when the hit `h` on primitive `id` (input order) along `ray`
    /// counts under its alpha cut-out.
    #[inline(never)]
    fn keeps(&self, id: u32, ray: &Ray, h: &PrimHit) -> bool {
        self.shapes.alpha_keeps_hit(self.prims[id as usize], ray, h)
    }

    /// Closest hit in `(0, t_max)` as (primitive index, primitive hit).
    #[inline]
    fn closest(&self, ray: &Ray, t_max: f32) -> Option<(u32, PrimHit)> {
        let accel = self;
        self.lanes.run(ClosestQuery { accel, ray, t_max })
    }

    /// Closest primitive hit in `(0, t_max)` without building the surface data.
    pub fn intersect_prim(&self, ray: &Ray, t_max: f32) -> Option<(Prim, PrimHit)> {
        let (id, h) = self.closest(ray, t_max)?;
        Some((self.prims[id as usize], h))
    }

    /// Closest hit in `(0, t_max)` with full surface information.
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        let (id, h) = self.closest(ray, t_max)?;
        let (prim, frame) = (self.prims[id as usize], self.frames[id as usize]);
        let surface = match prim {
            Prim::Triangle { mesh, tri } => {
                let (m, tri) = (&self.shapes.meshes[mesh as usize], tri as usize);
                m.surface_hit_at(tri, &h, m.vertices(tri), frame)
            }
            p => self.shapes.surface_hit(p, ray, &h),
        };
        Some(Hit {
            prim,
            surface,
            shading: frame.map(|f| f.shading),
        })
    }

    /// True if anything is hit in `(0, t_max)` (shadow rays).
    pub fn intersect_p(&self, ray: &Ray, t_max: f32) -> bool {
        let accel = self;
        self.lanes.run(AnyQuery { accel, ray, t_max })
    }
}
