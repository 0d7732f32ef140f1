//! Mesh file loading (PLY).

pub mod ply;

pub use ply::{parse_ply, read_ply};
