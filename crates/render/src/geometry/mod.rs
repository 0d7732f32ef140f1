//! Shapes: triangle meshes, spheres, disks, bilinear patch meshes (as
//! triangles) and Loop subdivision surfaces (as triangles), with ray
//! intersection, surface-hit construction and uniform area sampling.
//!
//! Intersection is two-phase: a cheap test returns a [`PrimHit`] (distance
//! and barycentrics), and only the closest hit is expanded into a
//! [`SurfaceHit`] with points, normals and texture coordinates.

pub mod alpha;
pub mod bilinear;
pub mod differentials;
pub mod disk;
pub mod loop_subdiv;
pub mod shape_set;
pub mod sphere;
pub mod triangle;

pub use alpha::ShapeId;
pub use bilinear::bilinear_to_triangles;
pub use differentials::ShadingGeometry;
pub use disk::Disk;
pub use loop_subdiv::loop_subdivide;
pub use shape_set::{Prim, ShapeSet};
pub use sphere::Sphere;
pub use triangle::{MeshData, TriangleMesh, intersect_triangle};

use crate::math::{Normal3, Point2, Point3, Vec3};

/// The minimal result of a ray-primitive test.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PrimHit {
    /// Ray parameter of the hit.
    pub t: f32,
    /// Triangles: barycentric weight of the second vertex (0 for other shapes).
    pub u: f32,
    /// Triangles: barycentric weight of the third vertex (0 for other shapes).
    pub v: f32,
}

/// Everything a shader needs about a ray-surface hit (world space).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceHit {
    /// Ray parameter of the hit.
    pub t: f32,
    /// Hit point.
    pub p: Point3,
    /// Surface texture coordinates.
    pub uv: Point2,
    /// Triangle barycentrics `(b0, b1, b2)`; zero for other shapes.
    pub bary: [f32; 3],
    /// Unit geometric normal, oriented by pbrt's rules (not towards the ray).
    pub ng: Normal3,
    /// Unit shading normal (interpolated vertex normal, or `ng`), in the
    /// hemisphere of `ng`.
    pub ns: Normal3,
    /// Surface tangent `∂p/∂u` (not normalised; never zero or parallel to `ng`
    /// for a non-degenerate shape).
    pub dpdu: Vec3,
}

/// A point sampled on a shape's surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapeSample {
    /// The point.
    pub p: Point3,
    /// Unit geometric normal there, oriented as at a ray hit.
    pub n: Normal3,
    /// Texture coordinates there.
    pub uv: Point2,
    /// Density with respect to surface area (`1 / area` for uniform sampling).
    pub pdf: f32,
}
