//! The 4-wide BVH: binary nodes collapsed into [`Node4`]s that hold their
//! (up to) four children's boxes in structure-of-arrays form, so that
//! traversal tests all four boxes in straight-line code the compiler
//! vectorises.
//!
//! Collapsing starts from a binary interior node's two children and keeps
//! opening the interior child of largest surface area until there are four
//! children or only leaves are left (the usual BVH2-to-BVH4 collapse).

use super::Node;

/// `count` value of a child slot that is an interior node.
pub const INTERIOR: u32 = u32::MAX;

/// A 4-wide node: 128 bytes, two cache lines.
///
/// Child slot `i` is an interior node when `count[i] == INTERIOR` (then
/// `child[i]` indexes [`Bvh::nodes4`](super::Bvh::nodes4)), else a leaf of
/// `count[i]` primitives starting at leaf-order position `child[i]`. Unused
/// slots are leaves of zero primitives with an empty box (`lo = +inf`,
/// `hi = -inf`), so no finite ray reaches them and reaching them costs nothing.
/// The corners sit in one array indexed by side (`0` lower, `1` upper), so
/// that the slab test picks a ray's near side by index, without a branch.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub struct Node4 {
    /// Box corners, `bounds[side][axis][slot]`: side 0 the lower corner,
    /// side 1 the upper.
    pub bounds: [[[f32; 4]; 3]; 2],
    /// Per slot: node index (interior) or first primitive (leaf).
    pub child: [u32; 4],
    /// Per slot: primitive count of a leaf, or [`INTERIOR`].
    pub count: [u32; 4],
}

impl Node4 {
    const EMPTY: Node4 = Node4 {
        bounds: [[[f32::INFINITY; 4]; 3], [[f32::NEG_INFINITY; 4]; 3]],
        child: [0; 4],
        count: [0; 4],
    };

    /// Lower corner of slot `s` on `axis`.
    pub fn lo(&self, axis: usize, s: usize) -> f32 {
        self.bounds[0][axis][s]
    }
    /// Upper corner of slot `s` on `axis`.
    pub fn hi(&self, axis: usize, s: usize) -> f32 {
        self.bounds[1][axis][s]
    }

    /// Number of used slots (interior or leaves with primitives).
    pub fn used(&self) -> usize {
        self.count.iter().filter(|&&c| c != 0).count()
    }
}

/// A reference to a subtree: an interior [`Node4`] or a leaf range.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChildRef {
    /// Node index (interior) or first primitive (leaf).
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
    pub nodes: Vec<Node4>,
    pub root: ChildRef,
    /// Levels of [`Node4`]s on the longest path (0 when the root is a leaf).
    pub levels: usize,
}

fn area(n: &Node) -> f32 {
    let d = [0, 1, 2].map(|a| (n.max[a] - n.min[a]).max(0.0));
    d[0] * d[1] + d[1] * d[2] + d[2] * d[0]
}

/// Collapses the binary tree `bin` (depth-first, root first).
pub(super) fn collapse(bin: &[Node]) -> Wide {
    let mut w = Wide {
        nodes: Vec::with_capacity(bin.len() / 2 + 1),
        root: ChildRef::default(),
        levels: 0,
    };
    if bin.is_empty() {
        return w;
    }
    if bin[0].is_leaf() {
        w.root = ChildRef {
            child: bin[0].offset,
            count: bin[0].count as u32,
        };
        return w;
    }
    let (idx, levels) = collapse_node(bin, 0, &mut w.nodes);
    w.root = ChildRef {
        child: idx,
        count: INTERIOR,
    };
    w.levels = levels;
    w
}

/// Appends the [`Node4`] for binary interior node `i` and its subtree;
/// returns its index and the number of levels below and including it.
fn collapse_node(bin: &[Node], i: usize, out: &mut Vec<Node4>) -> (u32, usize) {
    let mut kids = [i + 1, bin[i].offset as usize, 0, 0];
    let mut n = 2;
    while n < 4 {
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
    out.push(Node4::EMPTY);
    let mut node = Node4::EMPTY;
    let mut levels = 1;
    for (s, &c) in kids[..n].iter().enumerate() {
        let b = &bin[c];
        for a in 0..3 {
            node.bounds[0][a][s] = b.min[a];
            node.bounds[1][a][s] = b.max[a];
        }
        if b.is_leaf() {
            node.child[s] = b.offset;
            node.count[s] = b.count as u32;
        } else {
            let (ci, cl) = collapse_node(bin, c, out);
            node.child[s] = ci;
            node.count[s] = INTERIOR;
            levels = levels.max(1 + cl);
        }
    }
    out[idx] = node;
    (idx as u32, levels)
}
