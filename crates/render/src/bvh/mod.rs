//! Bounding volume hierarchy over abstract primitives given by their boxes.
//!
//! * [`Bvh::build`]: binned SAH along the centroid box's longest axis,
//!   with a cost model for packets (a leaf costs one unit per
//!   [`LEAF_LANES`] primitives, i.e. per packet its caller tests, and a
//!   binary interior node [`BuildOptions`]'s traversal cost), forking with
//!   rayon on subtrees of more than [`BuildOptions::parallel_threshold`]
//!   primitives; median split as fallback and below the depth where SAH
//!   could degenerate.
//! * Layout: compact 32-byte [`Node`]s in depth-first order (first child
//!   follows its parent; the node stores the second child's index), then
//!   collapsed into an 8-wide tree of [`Node8`]s (`wide`) for traversal,
//!   whose leaves address [`Bvh::slots`]: each leaf's primitives from a
//!   multiple of [`LEAF_LANES`], so one packet per leaf.
//! * [`Bvh::closest_hit`] and [`Bvh::any_hit`] traverse the 8-wide tree,
//!   testing eight boxes at once ([`crate::math::lanes`]) with a robust
//!   slab test (infinite inverse directions, NaN from `0 * inf` treated as
//!   inside), near child first, and leave primitive tests to a caller
//!   closure called per leaf, so the BVH knows nothing about shapes.

mod build;
mod flatten;
#[cfg(test)]
mod tests;
mod traverse;
mod wide;

pub use build::BuildOptions;
pub use wide::{ChildRef, EMPTY_SLOT, INTERIOR, LEAF_LANES, Node8, WIDTH};

use crate::math::Bounds3;
use std::time::{Duration, Instant};

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
    /// Total nodes of the binary tree.
    pub nodes: usize,
    /// Nodes of the 8-wide tree used for traversal.
    pub nodes8: usize,
    /// Leaf nodes.
    pub leaves: usize,
    /// Depth of the deepest leaf (the root has depth 0).
    pub max_depth: usize,
    /// Average primitives per leaf.
    pub avg_leaf_size: f64,
    /// SAH cost of the tree relative to the root box (the build's cost
    /// model: see [`BuildOptions`]).
    pub sah_cost: f64,
    /// Wall-clock build time (excluding computing primitive boxes).
    pub build_time: Duration,
}

impl std::fmt::Display for BvhStats {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "BVH: {} prims, {} nodes ({} 8-wide), {} leaves, max depth {}, {:.2} prims/leaf, SAH cost {:.2}, built in {:.1} ms",
            self.prims,
            self.nodes,
            self.nodes8,
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
    nodes8: Vec<Node8>,
    root8: ChildRef,
    /// Levels of `nodes8` on the longest root-to-leaf path.
    levels8: usize,
    prim_order: Vec<u32>,
    slots: Vec<u32>,
    stats: BvhStats,
}

/// Deepest tree the traversal stack supports (the builder guarantees it).
pub const MAX_DEPTH: usize = 96;

impl Bvh {
    /// The nodes, root first (empty for no primitives).
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }
    /// The 8-wide nodes (empty when the root is a leaf).
    pub fn nodes8(&self) -> &[Node8] {
        &self.nodes8
    }
    /// The root of the 8-wide tree: node 0 of [`Bvh::nodes8`], or a leaf.
    pub fn root8(&self) -> ChildRef {
        self.root8
    }
    /// Levels of [`Node8`]s on the longest root-to-leaf path (0 when the
    /// root is a leaf).
    pub fn levels8(&self) -> usize {
        self.levels8
    }
    /// `prim_order()[k]` is the input index of the `k`-th primitive in leaf
    /// order (the binary [`Bvh::nodes`]' leaves index it).
    pub fn prim_order(&self) -> &[u32] {
        &self.prim_order
    }
    /// The leaves of the 8-wide tree, each from a multiple of
    /// [`LEAF_LANES`]: per slot the input index of a primitive, or
    /// [`EMPTY_SLOT`] after a leaf's last one.
    pub fn slots(&self) -> &[u32] {
        &self.slots
    }
    /// Build statistics.
    pub fn stats(&self) -> &BvhStats {
        &self.stats
    }
}

impl Bvh {
    /// Builds over primitives given by their boxes with default options.
    pub fn build(prim_bounds: &[Bounds3]) -> Bvh {
        Self::build_with(prim_bounds, BuildOptions::default())
    }

    /// Builds over primitives given by their boxes. Primitives with an empty
    /// or non-finite box are left out (no ray can hit them).
    pub fn build_with(prim_bounds: &[Bounds3], opts: BuildOptions) -> Bvh {
        let start = Instant::now();
        let Some((root, prim_order, summary)) = build::build_binary(prim_bounds, opts) else {
            return Bvh::default();
        };
        let mut nodes = Vec::with_capacity(summary.nodes);
        flatten::flatten(&root, &mut nodes);
        drop(root);
        let wide = wide::collapse(&nodes, &prim_order);
        let build_time = start.elapsed();
        let stats = BvhStats {
            prims: prim_order.len(),
            nodes: summary.nodes,
            nodes8: wide.nodes.len(),
            leaves: summary.leaves,
            max_depth: summary.max_depth,
            avg_leaf_size: prim_order.len() as f64 / summary.leaves as f64,
            sah_cost: flatten::sah_cost(&nodes, opts),
            build_time,
        };
        Bvh {
            nodes,
            nodes8: wide.nodes,
            root8: wide.root,
            levels8: wide.levels,
            prim_order,
            slots: wide.slots,
            stats,
        }
    }
}
