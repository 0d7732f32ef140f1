//! The scene's shapes with their BVH: ray queries returning full hits.

use crate::bvh::{BuildOptions, Bvh, BvhStats};
use crate::geometry::{Prim, PrimHit, ShapeSet, SurfaceHit, intersect_triangle};
use crate::math::{Bounds3, Point3, Ray, Vec3};
use rayon::prelude::*;

/// A ray hit: which primitive, and the surface there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// The primitive hit.
    pub prim: Prim,
    /// Surface information at the hit.
    pub surface: SurfaceHit,
}

/// Shapes plus a BVH over all their primitives. Triangle vertices are copied
/// in BVH leaf order so the inner loop reads them contiguously.
#[derive(Clone, Debug)]
pub struct Accel {
    shapes: ShapeSet,
    bvh: Bvh,
    /// Primitives in leaf order.
    prims: Vec<Prim>,
    /// Triangle vertices in leaf order (unused entries for other shapes).
    tris: Vec<[Point3; 3]>,
    bounds: Bounds3,
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
        let tris = prims
            .par_iter()
            .map(|p| match *p {
                Prim::Triangle { mesh, tri } => shapes.meshes[mesh as usize].vertices(tri as usize),
                _ => [Vec3::ZERO; 3],
            })
            .collect();
        Accel {
            shapes,
            bvh,
            prims,
            tris,
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

    #[inline]
    fn test(&self, k: u32, ray: &Ray, t_max: f32) -> Option<PrimHit> {
        let k = k as usize;
        match self.prims[k] {
            Prim::Triangle { .. } => intersect_triangle(ray, t_max, self.tris[k]),
            p => self.shapes.intersect(p, ray, t_max),
        }
    }

    /// Closest primitive hit in `(0, t_max)` without building the surface data.
    pub fn intersect_prim(&self, ray: &Ray, t_max: f32) -> Option<(Prim, PrimHit)> {
        let mut best: Option<(u32, PrimHit)> = None;
        self.bvh.closest_hit(ray, t_max, |k, tm| {
            let h = self.test(k, ray, tm)?;
            best = Some((k, h));
            Some(h.t)
        });
        best.map(|(k, h)| (self.prims[k as usize], h))
    }

    /// Closest hit in `(0, t_max)` with full surface information.
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        let (prim, h) = self.intersect_prim(ray, t_max)?;
        Some(Hit {
            prim,
            surface: self.shapes.surface_hit(prim, ray, &h),
        })
    }

    /// True if anything is hit in `(0, t_max)` (shadow rays).
    pub fn intersect_p(&self, ray: &Ray, t_max: f32) -> bool {
        self.bvh
            .any_hit(ray, t_max, |k, tm| self.test(k, ray, tm).is_some())
    }
}
