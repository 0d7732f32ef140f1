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
    /// recording the closest hit closer than `t_max` in `best`.
    #[inline(always)]
    fn leaf_closest(
        &self,
        first: u32,
        count: u32,
        ray: &Ray,
        t_max: f32,
        best: &mut Option<(u32, PrimHit)>,
    ) -> Option<f32> {
        let (first, end) = (first as usize, (first + count) as usize);
        let mut t_max = t_max;
        let mut found = None;
        for p in first / 4..end.div_ceil(4) {
            let range = lanes(p, first, end);
            let tri = range & self.tri_lanes[p] as u32;
            if tri != 0 {
                let h = self.tris[p].intersect(ray, t_max);
                let mut m = h.mask & tri;
                while m != 0 {
                    let l = m.trailing_zeros() as usize;
                    m &= m - 1;
                    if h.t[l] < t_max {
                        t_max = h.t[l];
                        found = Some(t_max);
                        let hit = PrimHit {
                            t: h.t[l],
                            u: h.u[l],
                            v: h.v[l],
                        };
                        *best = Some(((4 * p + l) as u32, hit));
                    }
                }
            }
            let mut other = range & !tri;
            while other != 0 {
                let k = 4 * p + other.trailing_zeros() as usize;
                other &= other - 1;
                if let Some(h) = self.shapes.intersect(self.prims[k], ray, t_max) {
                    t_max = h.t;
                    found = Some(t_max);
                    *best = Some((k as u32, h));
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
            if tri != 0 && self.tris[p].intersect(ray, t_max).mask & tri != 0 {
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
        let mut best = None;
        self.bvh.closest_hit(ray, t_max, |first, count, tm| {
            self.leaf_closest(first, count, ray, tm, &mut best)
        });
        best
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
