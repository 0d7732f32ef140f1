//! The scene's shapes with their BVH: ray queries returning full hits.
//!
//! Triangle vertices are stored in BVH leaf order as [`Tri4`] packets
//! (packet `k / 4`, lane `k % 4` holds the primitive at leaf-order position
//! `k`), so a leaf's triangles are tested four at a time without looking up
//! the primitive kind; other shapes (spheres, disks) are tested one by one.

use crate::bvh::{BuildOptions, Bvh, BvhStats};
use crate::geometry::triangle::{FlatFrame, Tri4};
use crate::geometry::{Prim, PrimHit, ShapeSet, SurfaceHit};
use crate::math::{Bounds3, Frame, Ray};
use rayon::prelude::*;

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
    /// Primitives in leaf order.
    prims: Vec<Prim>,
    /// Triangle vertices in leaf order, four per packet (zero for other shapes).
    tris: Vec<Tri4>,
    /// Per packet: bit `l` set when lane `l` is a triangle.
    tri_lanes: Vec<u8>,
    /// In leaf order: the triangle's [`FlatFrame`], if it has one.
    frames: Vec<Option<FlatFrame>>,
    bounds: Bounds3,
}

/// Bit mask of the lanes of packet `p` inside the leaf-order range `first..end`.
#[inline(always)]
fn lanes(p: usize, first: usize, end: usize) -> u32 {
    let base = 4 * p;
    let lo = first.saturating_sub(base);
    let hi = (end - base).min(4);
    ((1u32 << hi) - 1) & !((1u32 << lo) - 1)
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
    /// Leaf-order position and primitive hit.
    hit: Option<(u32, PrimHit)>,
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
    fn set(&mut self, k: u32, id: u32, hit: PrimHit) {
        (self.t, self.id, self.hit) = (hit.t, id, Some((k, hit)));
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

impl Accel {
    /// Builds the BVH over every primitive of `shapes` (default options).
    pub fn build(shapes: ShapeSet) -> Accel {
        Self::build_with(shapes, BuildOptions::default())
    }

    /// Builds the BVH over every primitive of `shapes`.
    pub fn build_with(shapes: ShapeSet, opts: BuildOptions) -> Accel {
        let all = shapes.prims();
        let boxes: Vec<Bounds3> = all.par_iter().map(|&p| shapes.bounds(p)).collect();
        let bounds = boxes.iter().fold(Bounds3::EMPTY, |a, b| a.union(b));
        let bvh = Bvh::build_with(&boxes, opts);
        let prims: Vec<Prim> = bvh.prim_order().iter().map(|&i| all[i as usize]).collect();
        let (tris, tri_lanes) = prims
            .par_chunks(4)
            .map(|chunk| {
                let (mut packet, mut mask) = (Tri4::default(), 0u8);
                for (lane, p) in chunk.iter().enumerate() {
                    if let Prim::Triangle { mesh, tri } = *p {
                        packet.set(lane, shapes.meshes[mesh as usize].vertices(tri as usize));
                        mask |= 1 << lane;
                    }
                }
                (packet, mask)
            })
            .unzip();
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
            tri_lanes,
            frames,
            bounds,
        }
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

    /// Tests the primitives at leaf-order positions `first..first + count`,
    /// recording in `best` the hit that [`Closest::beats`] the one found so
    /// far; returns its distance when it changed.
    #[inline(always)]
    fn leaf_closest(&self, first: u32, count: u32, ray: &Ray, best: &mut Closest) -> Option<f32> {
        let (first, end) = (first as usize, (first + count) as usize);
        let order = self.bvh.prim_order();
        let mut found = None;
        for p in first / 4..end.div_ceil(4) {
            let range = lanes(p, first, end);
            let tri = range & self.tri_lanes[p] as u32;
            if tri != 0 {
                let h = self.tris[p].intersect::<true>(ray, best.t);
                let mut m = h.mask & tri;
                while m != 0 {
                    let l = m.trailing_zeros() as usize;
                    m &= m - 1;
                    let k = 4 * p + l;
                    if best.beats(h.t[l], order[k]) {
                        let hit = PrimHit {
                            t: h.t[l],
                            u: h.u[l],
                            v: h.v[l],
                        };
                        best.set(k as u32, order[k], hit);
                        found = Some(best.t);
                    }
                }
            }
            let mut other = range & !tri;
            while other != 0 {
                let k = 4 * p + other.trailing_zeros() as usize;
                other &= other - 1;
                let h = self.shapes.intersect(self.prims[k], ray, best.bound());
                if let Some(h) = h.filter(|h| best.beats(h.t, order[k])) {
                    best.set(k as u32, order[k], h);
                    found = Some(best.t);
                }
            }
        }
        found
    }

    /// True if any primitive at leaf-order positions `first..first + count`
    /// is hit in `(0, t_max)`.
    #[inline(always)]
    fn leaf_any(&self, first: u32, count: u32, ray: &Ray, t_max: f32) -> bool {
        let (first, end) = (first as usize, (first + count) as usize);
        (first / 4..end.div_ceil(4)).any(|p| {
            let range = lanes(p, first, end);
            let tri = range & self.tri_lanes[p] as u32;
            if tri != 0 && self.tris[p].intersect::<false>(ray, t_max).mask & tri != 0 {
                return true;
            }
            let mut other = range & !tri;
            while other != 0 {
                let k = 4 * p + other.trailing_zeros() as usize;
                other &= other - 1;
                if self.shapes.intersect(self.prims[k], ray, t_max).is_some() {
                    return true;
                }
            }
            false
        })
    }

    /// Closest hit in `(0, t_max)` as (leaf-order position, primitive hit).
    #[inline]
    fn closest(&self, ray: &Ray, t_max: f32) -> Option<(u32, PrimHit)> {
        let mut best = Closest::new(t_max);
        self.bvh.closest_hit(ray, t_max, |first, count, _| {
            self.leaf_closest(first, count, ray, &mut best)
        });
        best.hit
    }

    /// Closest primitive hit in `(0, t_max)` without building the surface data.
    pub fn intersect_prim(&self, ray: &Ray, t_max: f32) -> Option<(Prim, PrimHit)> {
        let (k, h) = self.closest(ray, t_max)?;
        Some((self.prims[k as usize], h))
    }

    /// Closest hit in `(0, t_max)` with full surface information.
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        let (k, h) = self.closest(ray, t_max)?;
        let k = k as usize;
        let prim = self.prims[k];
        let frame = self.frames[k];
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
        self.bvh.any_hit(ray, t_max, |first, count, tm| {
            self.leaf_any(first, count, ray, tm)
        })
    }
}
