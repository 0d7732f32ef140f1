//! Geometric math: vectors, rays, boxes, transforms, frames, spherical
//! helpers and the sample warps used by shapes.

pub mod bounds;
pub mod frame;
pub mod lanes;
pub mod ray;
pub mod sampling;
pub mod spherical;
pub mod transform;
pub mod vector;

pub use bounds::Bounds3;
pub use frame::Frame;
pub use ray::{Ray, SHADOW_EPSILON, offset_ray_origin, spawn_ray, spawn_ray_to};
pub use transform::{Matrix4, SingularMatrix, Transform};
pub use vector::{Normal3, Point2, Point3, Vec2, Vec3};

/// pbrt's conservative rounding-error bound `n ε / (1 - n ε)` for `n`
/// floating-point operations (`ε` = half an ULP of 1).
#[inline]
pub const fn gamma(n: i32) -> f32 {
    let e = f32::EPSILON * 0.5;
    (n as f32 * e) / (1.0 - n as f32 * e)
}
