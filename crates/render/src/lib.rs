//! Physically based path tracer driven by lowdisc's pixel samplers, with
//! pbrt-v4 scene loading.
//!
//! **Entry points.** [`pbrt::load_pbrt_scene`] (a scene file) or
//! [`cornell::cornell_scene`] (the built-in scene) give a [`scene::Scene`]
//! (geometry, materials, lights) and a [`view::ViewSpec`] (camera, film,
//! filter) with the settings the description asks for;
//! [`settings::Settings::resolve`] combines those with the caller's own
//! into one validated [`settings::Settings`]; [`view::View::new`] builds the
//! view at its resolution, and [`render::render`] renders the scene through
//! the view with [`render::RenderOptions`] (which hold the sampler's
//! [`lowdisc::catalog::SamplerConfig`]), returning the film, the image and
//! counters. Every failure is an [`error::RenderError`].
//!
//! **Modules**, from the scene description down to the numbers:
//!
//! | layer | modules |
//! |---|---|
//! | scenes | [`pbrt`] (pbrt-v4 loader: graphics state, shapes, materials, textures, lights, options), [`cornell`] (built-in scene), [`scene`] (builder and the renderable scene) |
//! | settings and view | [`settings`] (every render setting: layers, defaults, ranges, resolution), [`view`] (camera, film and filter, built once per render) |
//! | rendering | [`render`] (tiles, threads, progress; one camera sample), [`integrator`] (path tracer, sampler-dimension layout), [`camera`] (perspective camera), [`film`] (pixel sums, tiles, output), [`filter`] (pixel filters and their sampling) |
//! | appearance | [`bsdf`] (BxDFs, materials, `mix`), [`texture`] (one generic texture, image maps, registry), [`light`] (point, spot, distant, area, infinite and image lights; light selection), [`medium`] (participating media, phase function), [`spectrum`] (the `Colour` trait: RGB, or four sampled wavelengths with uplift, named spectra and the film's sensor) |
//! | geometry | [`geometry`] (triangles, spheres, disks, bilinear patches, Loop subdivision), [`accel`] (shapes plus BVH, full hits), [`bvh`] (binned-SAH build, traversal), [`mesh`] (PLY files) |
//! | foundations | [`math`] (vectors, rays, boxes, transforms, frames), [`sampling`] (tabulated 1-D/2-D distributions), [`content_hash`] (the explicit serialisation content hashes are taken over), [`error`] (the crate's errors) |
//!
//! **Determinism.** Every random decision comes from the pixel sampler (or a
//! seeded hash), tiles get their own sampler streams and are merged in order,
//! so an image is bit-identical whatever the thread count.
// `!(x > 0.0)` is used on purpose throughout: unlike `x <= 0.0` it is also
// true for NaN, which is how bad input is rejected without panicking.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod accel;
pub mod bsdf;
pub mod bvh;
pub mod camera;
pub mod content_hash;
pub mod cornell;
pub mod error;
pub mod film;
pub mod filter;
pub mod first_hit;
pub mod geometry;
pub mod integrator;
pub mod light;
pub mod math;
pub mod medium;
pub mod mesh;
pub mod pbrt;
pub mod preset;
pub mod render;
pub mod sampling;
pub mod scene;
pub mod settings;
pub mod spectrum;
pub mod texture;
pub mod view;

pub use accel::Accel;
pub use error::{Error, RenderError};
