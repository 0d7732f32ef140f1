//! Bounding volume hierarchy over abstract primitives given by their boxes.
//!
//! * [`Bvh::build`]: binned SAH (16 bins along the centroid box's longest
//!   axis, pbrt's cost model: traversal 1/2, intersection 1 per primitive),
//!   forking with rayon on subtrees of more than [`BuildOptions::parallel_threshold`]
//!   primitives; median split as fallback and below the depth where SAH
//!   could degenerate.
//! * Layout: compact 32-byte [`Node`]s in depth-first order (first child
//!   follows its parent; the node stores the second child's index), then
//!   collapsed into a 4-wide tree of [`Node4`]s (`wide`) for traversal.
//! * [`Bvh::closest_hit`] and [`Bvh::any_hit`] traverse the 4-wide tree,
//!   testing four boxes at once with a robust slab test (infinite inverse
//!   directions, NaN from `0 * inf` treated as inside), near child first,
//!   and leave primitive tests to a caller closure called per leaf, so the
//!   BVH knows nothing about shapes. Primitives are addressed by their
//!   position in [`Bvh::prim_order`] (leaf order), so callers can store
//!   primitive data in that order for locality.

mod build;
mod flatten;
#[cfg(test)]
mod tests;
mod traverse;
mod wide;

pub use build::BuildOptions;
pub use wide::{ChildRef, INTERIOR, Node4};

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
    /// Nodes of the 4-wide tree used for traversal.
    pub nodes4: usize,
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
            "BVH: {} prims, {} nodes ({} 4-wide), {} leaves, max depth {}, {:.2} prims/leaf, SAH cost {:.2}, built in {:.1} ms",
            self.prims,
            self.nodes,
            self.nodes4,
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
    nodes4: Vec<Node4>,
    root4: ChildRef,
    /// Levels of `nodes4` on the longest root-to-leaf path.
    levels4: usize,
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
    /// The 4-wide nodes (empty when the root is a leaf).
    pub fn nodes4(&self) -> &[Node4] {
        &self.nodes4
    }
    /// The root of the 4-wide tree: node 0 of [`Bvh::nodes4`], or a leaf.
    pub fn root4(&self) -> ChildRef {
        self.root4
    }
    /// Levels of [`Node4`]s on the longest root-to-leaf path (0 when the
    /// root is a leaf).
    pub fn levels4(&self) -> usize {
        self.levels4
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

impl Bvh {
    /// Builds over primitives given by their boxes with default options.
    pub fn build(prim_bounds: &[Bounds3]) -> Bvh {
        Self::build_with(prim_bounds, BuildOptions::default())
    }

    /// Builds over primitives given by their boxes. Primitives with an empty
    /// or non-finite box are left out (no ray can hit them).
    pub fn build_with(prim_bounds: &[Bounds3], opts: BuildOptions) -> Bvh {
        let start = Instant::now();
        let Some((nodes, prim_order, summary)) = build::build_binary(prim_bounds, opts) else {
            return Bvh::default();
        };
        let wide = wide::collapse(&nodes);
        let build_time = start.elapsed();
        let stats = BvhStats {
            prims: prim_order.len(),
            nodes: summary.nodes,
            nodes4: wide.nodes.len(),
            leaves: summary.leaves,
            max_depth: summary.max_depth,
            avg_leaf_size: prim_order.len() as f64 / summary.leaves as f64,
            sah_cost: flatten::sah_cost(&nodes),
            build_time,
        };
        Bvh {
            nodes,
            nodes4: wide.nodes,
            root4: wide.root,
            levels4: wide.levels,
            prim_order,
            stats,
        }
    }
}
