//! Physically based path tracer driven by lowdisc's pixel samplers.
//!
//! This crate currently holds the geometric foundations:
//! * [`math`]: `f32` vectors, rays, boxes, transforms, frames, spherical helpers;
//! * [`geometry`]: shapes (triangle meshes, spheres, disks, bilinear patch
//!   meshes, Loop subdivision surfaces) with intersection and area sampling;
//! * [`bvh`]: a binned-SAH bounding volume hierarchy (parallel build, compact
//!   32-byte nodes, closest-hit and any-hit traversal);
//! * [`accel`]: the scene's shapes plus their BVH, answering ray queries with
//!   full surface hits;
//! * [`mesh`]: PLY loading.
// `!(x > 0.0)` is used on purpose throughout: unlike `x <= 0.0` it is also
// true for NaN, which is how bad input is rejected without panicking.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod accel;
pub mod bsdf;
pub mod bvh;
pub mod camera;
pub mod cornell;
pub mod error;
pub mod film;
pub mod filter;
pub mod first_hit;
pub mod geometry;
pub mod integrator;
pub mod light;
pub mod math;
pub mod mesh;
pub mod pbrt;
pub mod preset;
pub mod render;
pub mod sampling;
pub mod scene;
pub mod spectrum;
pub mod texture;

pub use accel::Accel;
pub use error::Error;
