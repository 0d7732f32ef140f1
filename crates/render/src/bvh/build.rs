//! Binned-SAH construction of the binary tree (parallel), which the BVH
//! then flattens depth first (module `flatten`).

use super::{LEAF_LANES, MAX_DEPTH, Node};
use crate::math::{Bounds3, Vec3};
use rayon::prelude::*;

/// Options for [`Bvh::build_with`](super::Bvh::build_with).
///
/// The SAH cost model counts packets: a leaf of `n` primitives costs
/// `ceil(n / LEAF_LANES)` (its caller tests [`LEAF_LANES`] primitives at
/// once), a binary interior node `traversal_cost`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BuildOptions {
    /// SAH bins per split (clamped to 2..=16; fewer for small sets).
    pub bins: usize,
    /// Largest leaf; larger sets are always split (clamped to 1..=255).
    pub max_leaf_prims: usize,
    /// Cost of a binary interior node relative to a leaf packet's test.
    pub traversal_cost: f32,
    /// Subtrees with more primitives than this are built in parallel.
    pub parallel_threshold: usize,
}

impl Default for BuildOptions {
    fn default() -> Self {
        BuildOptions {
            bins: 16,
            max_leaf_prims: LEAF_LANES,
            traversal_cost: TRAVERSAL_COST,
            parallel_threshold: 4096,
        }
    }
}

/// Depth from which only median splits are made, bounding the tree depth by
/// `MEDIAN_DEPTH + 32 < MAX_DEPTH` for up to 2^32 primitives.
const MEDIAN_DEPTH: usize = 56;
/// Default relative cost of a binary interior node: about an eighth of an
/// 8-wide node's visit, which costs about as much as a packet test (chosen
/// by callgrind counts on Mitsuba's Cornell box and bmw-m6; 0.1 and 0.2 tie
/// on bmw-m6, 0.1 is 4 % fewer instructions in the Cornell box's queries).
const TRAVERSAL_COST: f32 = 0.1;

/// Largest number of SAH bins.
const MAX_BINS: usize = 16;

/// SAH cost of a leaf of `n` primitives: its number of packets.
#[inline]
pub(super) fn leaf_cost(n: u32) -> f32 {
    n.div_ceil(LEAF_LANES as u32) as f32
}

#[derive(Clone, Copy)]
struct BuildPrim {
    bounds: Bounds3,
    index: u32,
}

impl BuildPrim {
    /// Twice the centroid along `axis` (the factor 2 cancels in all uses).
    #[inline]
    fn c2(&self, axis: usize) -> f32 {
        self.bounds.min[axis] + self.bounds.max[axis]
    }
    #[inline]
    fn centroid2(&self) -> Vec3 {
        self.bounds.min + self.bounds.max
    }
}

/// Box of the primitives and box of their (doubled) centroids.
#[derive(Clone, Copy)]
struct Boxes {
    bounds: Bounds3,
    cent: Bounds3,
}

impl Boxes {
    const EMPTY: Boxes = Boxes {
        bounds: Bounds3::EMPTY,
        cent: Bounds3::EMPTY,
    };
    #[inline]
    fn add(&mut self, p: &BuildPrim) {
        self.bounds = self.bounds.union(&p.bounds);
        self.cent = self.cent.union_point(p.centroid2());
    }
    fn merge(a: Boxes, b: Boxes) -> Boxes {
        Boxes {
            bounds: a.bounds.union(&b.bounds),
            cent: a.cent.union(&b.cent),
        }
    }
    fn of(prims: &[BuildPrim], par: bool) -> Boxes {
        let fold = |mut acc: Boxes, p: &BuildPrim| {
            acc.add(p);
            acc
        };
        if par {
            prims
                .par_chunks(8192)
                .map(|ch| ch.iter().fold(Boxes::EMPTY, fold))
                .reduce(|| Boxes::EMPTY, Boxes::merge)
        } else {
            prims.iter().fold(Boxes::EMPTY, fold)
        }
    }
}

/// A subtree: interior nodes above the parallel threshold, flattened
/// depth-first below it (child indices relative to the vector's start).
pub(super) enum BuildNode {
    Interior {
        bounds: Bounds3,
        axis: u8,
        children: Box<[BuildNode; 2]>,
    },
    Flat(Vec<Node>),
}

enum Split {
    Leaf,
    /// Partitioned at `mid` along `axis`, with the two sides' boxes.
    At {
        mid: usize,
        axis: usize,
        left: Boxes,
        right: Boxes,
    },
}

/// Node, leaf and depth counts of a binary (sub)tree.
#[derive(Clone, Copy, Default)]
pub(super) struct Summary {
    pub nodes: usize,
    pub leaves: usize,
    pub max_depth: usize,
}

struct Builder {
    bins: usize,
    max_leaf: usize,
    traversal_cost: f32,
    par: usize,
}

#[derive(Clone, Copy)]
struct Bins {
    count: [u32; MAX_BINS],
    bounds: [Bounds3; MAX_BINS],
}

impl Builder {
    /// Chooses how to split `prims` (whose boxes are `b`), partitioning them.
    fn split(&self, prims: &mut [BuildPrim], b: &Boxes, depth: usize) -> Split {
        let n = prims.len();
        if n == 1 {
            return Split::Leaf;
        }
        let axis = b.cent.max_extent();
        let (cmin, cext) = (b.cent.min[axis], b.cent.max[axis] - b.cent.min[axis]);
        if !(cext > 0.0) {
            // All centroids coincide: a leaf if allowed, else halve.
            return if n <= self.max_leaf {
                Split::Leaf
            } else {
                self.median(prims, axis)
            };
        }
        if depth >= MEDIAN_DEPTH {
            return self.median(prims, axis);
        }
        let nb = self.bins.min(n.max(2));
        let scale = nb as f32 / cext;
        let bin = |p: &BuildPrim| (((p.c2(axis) - cmin) * scale) as usize).min(nb - 1);
        let fill = |ch: &[BuildPrim]| {
            let mut acc = Bins {
                count: [0; MAX_BINS],
                bounds: [Bounds3::EMPTY; MAX_BINS],
            };
            for p in ch {
                let k = bin(p);
                acc.count[k] += 1;
                acc.bounds[k] = acc.bounds[k].union(&p.bounds);
            }
            acc
        };
        let bins = if n > self.par {
            prims
                .par_chunks(8192)
                .map(fill)
                .reduce_with(|mut a, o| {
                    for k in 0..nb {
                        a.count[k] += o.count[k];
                        a.bounds[k] = a.bounds[k].union(&o.bounds[k]);
                    }
                    a
                })
                .unwrap_or_else(|| fill(&[]))
        } else {
            fill(prims)
        };
        // Sweep: cost of splitting after bin i.
        let mut right_area = [0.0f32; MAX_BINS];
        let mut acc = Bounds3::EMPTY;
        for i in (1..nb).rev() {
            acc = acc.union(&bins.bounds[i]);
            right_area[i] = acc.surface_area();
        }
        let (mut best, mut best_cost) = (usize::MAX, f32::INFINITY);
        let (mut left_box, mut left_n, mut right_n) = (Bounds3::EMPTY, 0u32, n as u32);
        for i in 0..nb - 1 {
            left_box = left_box.union(&bins.bounds[i]);
            left_n += bins.count[i];
            right_n -= bins.count[i];
            if left_n == 0 || right_n == 0 {
                continue;
            }
            let cost = leaf_cost(left_n) * left_box.surface_area()
                + leaf_cost(right_n) * right_area[i + 1];
            if cost < best_cost {
                best_cost = cost;
                best = i;
            }
        }
        if best == usize::MAX {
            return if n <= self.max_leaf {
                Split::Leaf
            } else {
                self.median(prims, axis)
            };
        }
        let area = b.bounds.surface_area();
        let split_cost = self.traversal_cost + if area > 0.0 { best_cost / area } else { 0.0 };
        if n <= self.max_leaf && leaf_cost(n as u32) <= split_cost {
            return Split::Leaf;
        }
        // Partition, gathering both sides' boxes on the way.
        let (mut left, mut right) = (Boxes::EMPTY, Boxes::EMPTY);
        let mut mid = 0;
        for i in 0..n {
            let p = prims[i];
            if bin(&p) <= best {
                left.add(&p);
                prims.swap(mid, i);
                mid += 1;
            } else {
                right.add(&p);
            }
        }
        Split::At {
            mid,
            axis,
            left,
            right,
        }
    }

    fn median(&self, prims: &mut [BuildPrim], axis: usize) -> Split {
        let mid = prims.len() / 2;
        prims.select_nth_unstable_by(mid, |a, b| a.c2(axis).total_cmp(&b.c2(axis)));
        let par = prims.len() > self.par;
        Split::At {
            mid,
            axis,
            left: Boxes::of(&prims[..mid], par),
            right: Boxes::of(&prims[mid..], par),
        }
    }

    fn leaf_node(b: &Bounds3, offset: usize, n: usize) -> Node {
        Node {
            min: b.min.to_array(),
            max: b.max.to_array(),
            offset: offset as u32,
            count: n as u16,
            axis: 0,
            pad: 0,
        }
    }

    /// Sequential build appending depth-first nodes to `out` (indices
    /// relative to `out`'s start); returns the subtree depth.
    fn build_flat(
        &self,
        prims: &mut [BuildPrim],
        b: &Boxes,
        offset: usize,
        depth: usize,
        out: &mut Vec<Node>,
    ) -> usize {
        let idx = out.len();
        out.push(Self::leaf_node(&b.bounds, offset, prims.len()));
        match self.split(prims, b, depth) {
            Split::Leaf => 0,
            Split::At {
                mid,
                axis,
                left,
                right,
            } => {
                out[idx].count = 0;
                out[idx].axis = axis as u8;
                let (lp, rp) = prims.split_at_mut(mid);
                let dl = self.build_flat(lp, &left, offset, depth + 1, out);
                out[idx].offset = out.len() as u32;
                let dr = self.build_flat(rp, &right, offset + mid, depth + 1, out);
                1 + dl.max(dr)
            }
        }
    }

    fn build(
        &self,
        prims: &mut [BuildPrim],
        b: &Boxes,
        offset: usize,
        depth: usize,
    ) -> (BuildNode, Summary) {
        if prims.len() <= self.par {
            let mut out = Vec::with_capacity(prims.len());
            let d = self.build_flat(prims, b, offset, depth, &mut out);
            let summary = Summary {
                nodes: out.len(),
                leaves: out.iter().filter(|n| n.is_leaf()).count(),
                max_depth: d,
            };
            return (BuildNode::Flat(out), summary);
        }
        match self.split(prims, b, depth) {
            Split::Leaf => {
                let node = Self::leaf_node(&b.bounds, offset, prims.len());
                (
                    BuildNode::Flat(vec![node]),
                    Summary {
                        nodes: 1,
                        leaves: 1,
                        max_depth: 0,
                    },
                )
            }
            Split::At {
                mid,
                axis,
                left,
                right,
            } => {
                let (lp, rp) = prims.split_at_mut(mid);
                let ((l, ls), (r, rs)) = rayon::join(
                    || self.build(lp, &left, offset, depth + 1),
                    || self.build(rp, &right, offset + mid, depth + 1),
                );
                let summary = Summary {
                    nodes: 1 + ls.nodes + rs.nodes,
                    leaves: ls.leaves + rs.leaves,
                    max_depth: 1 + ls.max_depth.max(rs.max_depth),
                };
                (
                    BuildNode::Interior {
                        bounds: b.bounds,
                        axis: axis as u8,
                        children: Box::new([l, r]),
                    },
                    summary,
                )
            }
        }
    }
}

/// Builds the binary tree over primitives given by their boxes, leaving out
/// those with an empty or non-finite box: the tree (which the caller
/// flattens depth first), the leaf order and the tree's summary; `None` when
/// no primitive is left.
pub(super) fn build_binary(
    prim_bounds: &[Bounds3],
    opts: BuildOptions,
) -> Option<(BuildNode, Vec<u32>, Summary)> {
    let mut prims: Vec<BuildPrim> = prim_bounds
        .par_iter()
        .enumerate()
        .filter(|(_, b)| !b.is_empty() && b.min.is_finite() && b.max.is_finite())
        .map(|(i, b)| BuildPrim {
            bounds: *b,
            index: i as u32,
        })
        .collect();
    if prims.is_empty() {
        return None;
    }
    let builder = Builder {
        bins: opts.bins.clamp(2, MAX_BINS),
        max_leaf: opts.max_leaf_prims.clamp(1, 255),
        traversal_cost: opts.traversal_cost.max(0.0),
        par: opts.parallel_threshold.max(2),
    };
    let boxes = Boxes::of(&prims, true);
    let (root, summary) = builder.build(&mut prims, &boxes, 0, 0);
    debug_assert!(summary.max_depth < MAX_DEPTH);
    Some((root, prims.iter().map(|p| p.index).collect(), summary))
}
