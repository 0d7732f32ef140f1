//! Bounding volume hierarchy over abstract primitives given by their boxes.
//!
//! * [`Bvh::build`]: binned SAH (16 bins along the centroid box's longest
//!   axis, pbrt's cost model: traversal 1/2, intersection 1 per primitive),
//!   forking with rayon on subtrees of more than [`BuildOptions::parallel_threshold`]
//!   primitives; median split as fallback and below the depth where SAH
//!   could degenerate.
//! * Layout: compact 32-byte [`Node`]s in depth-first order (first child
//!   follows its parent; the node stores the second child's index).
//! * [`Bvh::closest_hit`] and [`Bvh::any_hit`] traverse near child first,
//!   with a robust slab test (infinite inverse directions, NaN from `0 * inf`
//!   treated as inside) and leave primitive tests to a caller closure, so the
//!   BVH knows nothing about shapes. Primitives are addressed by their
//!   position in [`Bvh::prim_order`] (leaf order), so callers can store
//!   primitive data in that order for locality.

mod build;
mod flatten;
mod traverse;

pub use build::BuildOptions;

use std::time::Duration;

/// A flattened BVH node: 32 bytes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C)]
pub struct Node {
    /// Lower corner of the node's box.
    pub min: [f32; 3],
    /// Upper corner of the node's box.
    pub max: [f32; 3],
    /// Leaf: position of its first primitive in leaf order.
    /// Interior: index of the second child (the first is the next node).
    pub offset: u32,
    /// Number of primitives (0 for an interior node).
    pub count: u16,
    /// Interior: split axis (0, 1, 2), used for near-first traversal.
    pub axis: u8,
    /// Padding to 32 bytes.
    pub pad: u8,
}

impl Node {
    /// True for a leaf.
    #[inline]
    pub fn is_leaf(&self) -> bool {
        self.count > 0
    }
}

/// Statistics of a built hierarchy.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BvhStats {
    /// Number of primitives.
    pub prims: usize,
    /// Total nodes.
    pub nodes: usize,
    /// Leaf nodes.
    pub leaves: usize,
    /// Depth of the deepest leaf (the root has depth 0).
    pub max_depth: usize,
    /// Average primitives per leaf.
    pub avg_leaf_size: f64,
    /// SAH cost of the tree relative to the root box (pbrt's cost model).
    pub sah_cost: f64,
    /// Wall-clock build time (excluding computing primitive boxes).
    pub build_time: Duration,
}

impl std::fmt::Display for BvhStats {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "BVH: {} prims, {} nodes, {} leaves, max depth {}, {:.2} prims/leaf, SAH cost {:.2}, built in {:.1} ms",
            self.prims,
            self.nodes,
            self.leaves,
            self.max_depth,
            self.avg_leaf_size,
            self.sah_cost,
            self.build_time.as_secs_f64() * 1e3
        )
    }
}

/// A built BVH.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    prim_order: Vec<u32>,
    stats: BvhStats,
}

/// Deepest tree the traversal stack supports (the builder guarantees it).
pub const MAX_DEPTH: usize = 96;

impl Bvh {
    /// The nodes, root first (empty for no primitives).
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }
    /// `prim_order()[k]` is the input index of the `k`-th primitive in leaf order.
    pub fn prim_order(&self) -> &[u32] {
        &self.prim_order
    }
    /// Build statistics.
    pub fn stats(&self) -> &BvhStats {
        &self.stats
    }
}
