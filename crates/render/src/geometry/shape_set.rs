//! A set of shapes addressed by primitive ([`Prim`]): the unit the BVH
//! stores, intersects and (for area lights) samples.

use super::alpha::ShapeId;
use super::{Disk, PrimHit, ShapeSample, Sphere, SurfaceHit, TriangleMesh};
use crate::content_hash::{ContentHash, ContentSink};
use crate::math::{Bounds3, Point2, Ray};
use crate::texture::FloatTexture;
use std::collections::BTreeMap;

/// One intersectable primitive: a triangle of a mesh, a sphere or a disk.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Prim {
    /// Triangle `tri` of mesh `mesh` in [`ShapeSet::meshes`].
    Triangle {
        /// Mesh index.
        mesh: u32,
        /// Triangle index in the mesh.
        tri: u32,
    },
    /// Sphere index in [`ShapeSet::spheres`].
    Sphere(u32),
    /// Disk index in [`ShapeSet::disks`].
    Disk(u32),
}

/// The scene's shapes, in world space.
#[derive(Clone, Debug, Default)]
pub struct ShapeSet {
    /// Triangle meshes.
    pub meshes: Vec<TriangleMesh>,
    /// Spheres.
    pub spheres: Vec<Sphere>,
    /// Disks.
    pub disks: Vec<Disk>,
    /// Alpha cut-outs of the shapes that have one (see [`super::alpha`]).
    pub(super) alpha: BTreeMap<ShapeId, FloatTexture>,
}

impl ShapeSet {
    /// An empty set.
    pub fn new() -> Self {
        Self::default()
    }
    /// Adds a mesh and returns its index.
    pub fn add_mesh(&mut self, m: TriangleMesh) -> u32 {
        self.meshes.push(m);
        (self.meshes.len() - 1) as u32
    }
    /// Adds a sphere and returns its primitive.
    pub fn add_sphere(&mut self, s: Sphere) -> Prim {
        self.spheres.push(s);
        Prim::Sphere((self.spheres.len() - 1) as u32)
    }
    /// Adds a disk and returns its primitive.
    pub fn add_disk(&mut self, d: Disk) -> Prim {
        self.disks.push(d);
        Prim::Disk((self.disks.len() - 1) as u32)
    }
    /// The primitives of mesh `mesh`, one per triangle.
    pub fn mesh_prims(&self, mesh: u32) -> impl Iterator<Item = Prim> + '_ {
        (0..self.meshes[mesh as usize].len() as u32).map(move |tri| Prim::Triangle { mesh, tri })
    }
    /// Every primitive: all triangles of all meshes, then spheres, then disks.
    pub fn prims(&self) -> Vec<Prim> {
        let mut v = Vec::with_capacity(self.prim_count());
        for m in 0..self.meshes.len() as u32 {
            v.extend(self.mesh_prims(m));
        }
        v.extend((0..self.spheres.len() as u32).map(Prim::Sphere));
        v.extend((0..self.disks.len() as u32).map(Prim::Disk));
        v
    }
    /// Total number of primitives.
    pub fn prim_count(&self) -> usize {
        self.meshes.iter().map(TriangleMesh::len).sum::<usize>()
            + self.spheres.len()
            + self.disks.len()
    }
    /// World-space bounds of a primitive.
    pub fn bounds(&self, p: Prim) -> Bounds3 {
        match p {
            Prim::Triangle { mesh, tri } => self.meshes[mesh as usize].bounds(tri as usize),
            Prim::Sphere(i) => self.spheres[i as usize].bounds(),
            Prim::Disk(i) => self.disks[i as usize].bounds(),
        }
    }
    /// Intersects one primitive (`0 < t < t_max`).
    #[inline]
    pub fn intersect(&self, p: Prim, ray: &Ray, t_max: f32) -> Option<PrimHit> {
        match p {
            Prim::Triangle { mesh, tri } => {
                self.meshes[mesh as usize].intersect(tri as usize, ray, t_max)
            }
            Prim::Sphere(i) => self.spheres[i as usize].intersect(ray, t_max),
            Prim::Disk(i) => self.disks[i as usize].intersect(ray, t_max),
        }
    }
    /// Expands a hit on `p` into full surface information.
    pub fn surface_hit(&self, p: Prim, ray: &Ray, h: &PrimHit) -> SurfaceHit {
        match p {
            Prim::Triangle { mesh, tri } => self.meshes[mesh as usize].surface_hit(tri as usize, h),
            Prim::Sphere(i) => self.spheres[i as usize].surface_hit(ray, h),
            Prim::Disk(i) => self.disks[i as usize].surface_hit(ray, h),
        }
    }
    /// Surface area of a primitive.
    pub fn area(&self, p: Prim) -> f32 {
        match p {
            Prim::Triangle { mesh, tri } => self.meshes[mesh as usize].area(tri as usize),
            Prim::Sphere(i) => self.spheres[i as usize].area(),
            Prim::Disk(i) => self.disks[i as usize].area(),
        }
    }
    /// Samples a point uniformly by area on a primitive (`None` if it has no
    /// area).
    pub fn sample(&self, p: Prim, u: Point2) -> Option<ShapeSample> {
        match p {
            Prim::Triangle { mesh, tri } => self.meshes[mesh as usize].sample(tri as usize, u),
            Prim::Sphere(i) => self.spheres[i as usize].sample(u),
            Prim::Disk(i) => self.disks[i as usize].sample(u),
        }
    }
}

impl ContentHash for ShapeSet {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let ShapeSet {
            meshes,
            spheres,
            disks,
            alpha,
        } = self;
        (meshes, spheres, disks, alpha).feed(sink);
    }
}

impl ContentHash for Prim {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        match self {
            Prim::Triangle { mesh, tri } => (0u8, mesh, tri).feed(sink),
            Prim::Sphere(i) => (1u8, i).feed(sink),
            Prim::Disk(i) => (2u8, i).feed(sink),
        }
    }
}
