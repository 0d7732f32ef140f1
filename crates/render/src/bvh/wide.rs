//! The 8-wide BVH: binary nodes collapsed into [`Node8`]s that hold their
//! (up to) eight children's boxes in structure-of-arrays form, so that
//! traversal tests all eight boxes at once in one register per bound.
//!
//! Collapsing starts from a binary interior node's two children and keeps
//! opening the interior child of largest surface area until there are eight
//! children or only leaves are left (the usual BVH2-to-BVH8 collapse).
//!
//! Leaves address *slots*: each binary leaf's primitives are copied into
//! [`Bvh::slots`](super::Bvh::slots) starting at a multiple of
//! [`LEAF_LANES`], the rest of its last group of `LEAF_LANES` slots left
//! empty, so that a caller can keep one packet per group of slots and test
//! a leaf of up to `LEAF_LANES` primitives with one packet.

use super::Node;

/// Width of the tree: children per [`Node8`].
pub const WIDTH: usize = 8;
/// Primitives a caller tests at once; leaves start at multiples of it in
/// [`Bvh::slots`](super::Bvh::slots).
pub const LEAF_LANES: usize = 8;
/// `count` value of a child slot that is an interior node.
pub const INTERIOR: u32 = u32::MAX;
/// Value of an empty entry of [`Bvh::slots`](super::Bvh::slots).
pub const EMPTY_SLOT: u32 = u32::MAX;

/// An 8-wide node: 256 bytes, four cache lines.
///
/// Child `i` is an interior node when `count[i] == INTERIOR` (then
/// `child[i]` indexes [`Bvh::nodes8`](super::Bvh::nodes8)), else a leaf of
/// `count[i]` primitives in slots `child[i]..child[i] + count[i]` (a
/// multiple of [`LEAF_LANES`] first). Unused children are leaves of zero
/// primitives with an empty box (`lo = +inf`, `hi = -inf`), so no finite
/// ray reaches them and reaching them costs nothing. The corners sit in one
/// array indexed by side (`0` lower, `1` upper), so that the slab test
/// picks a ray's near side by index, without a branch.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub struct Node8 {
    /// Box corners, `bounds[side][axis][child]`: side 0 the lower corner,
    /// side 1 the upper.
    pub bounds: [[[f32; WIDTH]; 3]; 2],
    /// Per child: node index (interior) or first slot (leaf).
    pub child: [u32; WIDTH],
    /// Per child: primitive count of a leaf, or [`INTERIOR`].
    pub count: [u32; WIDTH],
}

impl Node8 {
    const EMPTY: Node8 = Node8 {
        bounds: [[[f32::INFINITY; WIDTH]; 3], [[f32::NEG_INFINITY; WIDTH]; 3]],
        child: [0; WIDTH],
        count: [0; WIDTH],
    };

    /// Lower corner of child `s` on `axis`.
    pub fn lo(&self, axis: usize, s: usize) -> f32 {
        self.bounds[0][axis][s]
    }
    /// Upper corner of child `s` on `axis`.
    pub fn hi(&self, axis: usize, s: usize) -> f32 {
        self.bounds[1][axis][s]
    }

    /// Number of used children (interior or leaves with primitives).
    pub fn used(&self) -> usize {
        self.count.iter().filter(|&&c| c != 0).count()
    }
}

/// A reference to a subtree: an interior [`Node8`] or a leaf's slots.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChildRef {
    /// Node index (interior) or first slot (leaf).
    pub child: u32,
    /// Primitive count of a leaf, or [`INTERIOR`].
    pub count: u32,
}

impl ChildRef {
    /// True for an interior node.
    #[inline]
    pub fn is_interior(self) -> bool {
        self.count == INTERIOR
    }
}

/// The collapsed tree.
pub(super) struct Wide {
    pub nodes: Vec<Node8>,
    pub root: ChildRef,
    /// Levels of [`Node8`]s on the longest path (0 when the root is a leaf).
    pub levels: usize,
    /// Per slot: the primitive's input index, or [`EMPTY_SLOT`].
    pub slots: Vec<u32>,
}

fn area(n: &Node) -> f32 {
    let d = [0, 1, 2].map(|a| (n.max[a] - n.min[a]).max(0.0));
    d[0] * d[1] + d[1] * d[2] + d[2] * d[0]
}

/// Collapses the binary tree `bin` (depth-first, root first) whose leaves
/// index `prim_order`.
pub(super) fn collapse(bin: &[Node], prim_order: &[u32]) -> Wide {
    // Leaves take slots in depth-first order, each from a multiple of LEAF_LANES.
    let mut first_slot = vec![0u32; bin.len()];
    let mut slots = Vec::with_capacity(prim_order.len() * 2);
    for (i, n) in bin.iter().enumerate().filter(|(_, n)| n.is_leaf()) {
        first_slot[i] = slots.len() as u32;
        let prims = &prim_order[n.offset as usize..][..n.count as usize];
        slots.extend_from_slice(prims);
        slots.resize(slots.len().next_multiple_of(LEAF_LANES), EMPTY_SLOT);
    }
    let mut w = Wide {
        nodes: Vec::with_capacity(bin.len() / 4 + 1),
        root: ChildRef::default(),
        levels: 0,
        slots,
    };
    if bin.is_empty() {
        return w;
    }
    if bin[0].is_leaf() {
        w.root = ChildRef {
            child: first_slot[0],
            count: bin[0].count as u32,
        };
        return w;
    }
    let (idx, levels) = collapse_node(bin, &first_slot, 0, &mut w.nodes);
    w.root = ChildRef {
        child: idx,
        count: INTERIOR,
    };
    w.levels = levels;
    w
}

/// Appends the [`Node8`] for binary interior node `i` and its subtree;
/// returns its index and the number of levels below and including it.
fn collapse_node(bin: &[Node], first_slot: &[u32], i: usize, out: &mut Vec<Node8>) -> (u32, usize) {
    let mut kids = [0usize; WIDTH];
    kids[..2].copy_from_slice(&[i + 1, bin[i].offset as usize]);
    let mut n = 2;
    while n < WIDTH {
        let open = (0..n)
            .filter(|&k| !bin[kids[k]].is_leaf())
            .max_by(|&a, &b| area(&bin[kids[a]]).total_cmp(&area(&bin[kids[b]])));
        let Some(k) = open else { break };
        let c = kids[k];
        kids[k] = c + 1;
        kids[n] = bin[c].offset as usize;
        n += 1;
    }
    let idx = out.len();
    out.push(Node8::EMPTY);
    let mut node = Node8::EMPTY;
    let mut levels = 1;
    for (s, &c) in kids[..n].iter().enumerate() {
        let b = &bin[c];
        for a in 0..3 {
            node.bounds[0][a][s] = b.min[a];
            node.bounds[1][a][s] = b.max[a];
        }
        if b.is_leaf() {
            node.child[s] = first_slot[c];
            node.count[s] = b.count as u32;
        } else {
            let (ci, cl) = collapse_node(bin, first_slot, c, out);
            node.child[s] = ci;
            node.count[s] = INTERIOR;
            levels = levels.max(1 + cl);
        }
    }
    out[idx] = node;
    (idx as u32, levels)
}
