//! Closest-hit and any-hit traversal of the 8-wide tree.
//!
//! Each [`Node8`] visit tests its eight child boxes at once (one register of
//! [`Lanes`] per slab bound), then continues with the nearest hit child and
//! pushes the others far to near with their entry distances, so that
//! closest-hit queries skip stacked subtrees that start beyond the closest
//! hit found since. Any-hit queries take the children in slot order.

use super::wide::{ChildRef, INTERIOR, Node8, WIDTH};
use super::{Bvh, MAX_DEPTH};
use crate::math::lanes::Lanes;
use crate::math::{Ray, gamma};
use arrayvec::ArrayVec;

/// Stack capacity: a visit pushes at most `WIDTH - 1` subtrees, so a tree
/// of at most `MAX_DEPTH` levels never stacks more.
const STACK: usize = (WIDTH - 1) * MAX_DEPTH;

/// Widening of slab and query distances against rounding (pbrt's `1 + 2γ(3)`).
const WIDEN: f32 = 1.0 + 2.0 * gamma(3);

/// Per-ray constants of the slab test, splatted across the lanes.
struct RayInv<L: Lanes> {
    o: [L::F; 3],
    inv: [L::F; 3],
    widen: L::F,
    /// Per axis, the side of a box the ray enters by (1 for the upper
    /// corner when the direction is negative).
    near: [usize; 3],
}

impl<L: Lanes> RayInv<L> {
    #[inline(always)]
    fn new(l: L, ray: &Ray) -> Self {
        let inv = [1.0 / ray.d.x, 1.0 / ray.d.y, 1.0 / ray.d.z];
        // Sign of the inverse, so that -0.0 directions count as negative.
        let near = inv.map(|i| usize::from(i.is_sign_negative()));
        // (No closures: see `Tri8::intersect`.)
        RayInv {
            o: [l.splat(ray.o.x), l.splat(ray.o.y), l.splat(ray.o.z)],
            inv: [l.splat(inv[0]), l.splat(inv[1]), l.splat(inv[2])],
            widen: l.splat(WIDEN),
            near,
        }
    }

    /// Slab test of the child boxes of `n` over `[0, t_max]`: returns each
    /// box's entry distance and a bit mask of the boxes hit. `far` is
    /// widened by `1 + 2γ(3)` (pbrt) so rounding never culls a box the ray
    /// touches; a NaN slab bound (`0 * inf` for a ray in a slab plane) is
    /// ignored, i.e. the ray counts as inside that slab. Every lane does the
    /// scalar test's operations in the scalar test's order.
    #[inline(always)]
    fn hits(&self, l: L, n: &Node8, t_max: f32) -> ([f32; WIDTH], u32) {
        let mut t0 = l.splat(0.0);
        let mut t1 = l.splat(t_max);
        for a in 0..3 {
            // `& 1` lets the compiler drop the bounds checks of both indices.
            let side = self.near[a] & 1;
            let (lo, hi) = (&n.bounds[side][a], &n.bounds[side ^ 1][a]);
            let near = l.mul(l.sub(l.load(lo), self.o[a]), self.inv[a]);
            let far = l.mul(l.mul(l.sub(l.load(hi), self.o[a]), self.inv[a]), self.widen);
            t0 = l.max_gt(near, t0);
            t1 = l.min_lt(far, t1);
        }
        let mask = l.bits(l.le(t0, t1));
        (l.store(t0), mask)
    }
}

/// A fixed-capacity stack of subtrees with their entry distances. It lives
/// on the call stack and is never zeroed: only the entries pushed are
/// written.
struct Stack(ArrayVec<(ChildRef, f32), STACK>);

impl Stack {
    #[inline(always)]
    fn new() -> Self {
        Stack(ArrayVec::new())
    }
    #[inline(always)]
    fn push(&mut self, r: ChildRef, t: f32) {
        self.0.push((r, t));
    }
    #[inline(always)]
    fn pop(&mut self) -> Option<(ChildRef, f32)> {
        self.0.pop()
    }
}

#[inline(always)]
fn slot(n: &Node8, s: usize) -> ChildRef {
    ChildRef {
        child: n.child[s],
        count: n.count[s],
    }
}

impl Bvh {
    /// Finds the closest hit along `ray` in `(0, t_max)`, testing boxes
    /// with lanes `l`.
    ///
    /// `leaf(first, count)` tests the `count` primitives in slots
    /// `first..first + count` (see [`Bvh::slots`]) and returns the distance
    /// of the closest hit so far if it found a new one; the caller keeps
    /// that hit and whatever else it needs. Leaves are visited roughly
    /// near to far, and not at all when their box starts beyond the
    /// closest hit. Returns the closest distance found.
    #[inline(always)]
    pub fn closest_hit<L: Lanes>(
        &self,
        l: L,
        ray: &Ray,
        t_max: f32,
        mut leaf: impl FnMut(u32, u32) -> Option<f32>,
    ) -> Option<f32> {
        let r = RayInv::new(l, ray);
        // Boxes are tested against a widened `t_max`: a primitive's
        // computed distance may fall a few ulps short of its box's computed
        // entry (coplanar, axis-aligned geometry), and it must not be culled
        // once a hit that is only slightly farther has shrunk `t_max`.
        let mut t_box = t_max * WIDEN;
        let mut found = None;
        let mut stack = Stack::new();
        let mut cur = self.root8;
        loop {
            if cur.count == INTERIOR {
                let node = &self.nodes8[cur.child as usize];
                let (tn, mut mask) = r.hits(l, node, t_box);
                if mask != 0 {
                    // Hit children in order of entry distance, nearest last.
                    let mut order = [0usize; WIDTH];
                    let mut k = 0;
                    while mask != 0 {
                        let s = mask.trailing_zeros() as usize;
                        mask &= mask - 1;
                        let mut j = k;
                        while j > 0 && tn[order[j - 1]] < tn[s] {
                            order[j] = order[j - 1];
                            j -= 1;
                        }
                        order[j] = s;
                        k += 1;
                    }
                    for &s in &order[..k - 1] {
                        stack.push(slot(node, s), tn[s]);
                    }
                    cur = slot(node, order[k - 1]);
                    continue;
                }
            } else if cur.count > 0 {
                if let Some(t) = leaf(cur.child, cur.count) {
                    t_box = t * WIDEN;
                    found = Some(t);
                }
            }
            // Next stacked subtree whose box starts within the closest hit.
            loop {
                let Some((next, t)) = stack.pop() else {
                    return found;
                };
                if t <= t_box {
                    cur = next;
                    break;
                }
            }
        }
    }

    /// True if any primitive is hit in `(0, t_max)` (shadow rays), testing
    /// boxes with lanes `l`.
    ///
    /// `leaf(first, count)` tests the primitives in slots
    /// `first..first + count`; traversal stops at the first leaf for which
    /// it returns `true`.
    #[inline(always)]
    pub fn any_hit<L: Lanes>(
        &self,
        l: L,
        ray: &Ray,
        t_max: f32,
        mut leaf: impl FnMut(u32, u32) -> bool,
    ) -> bool {
        let r = RayInv::new(l, ray);
        let t_box = t_max * WIDEN;
        let mut stack = Stack::new();
        let mut cur = self.root8;
        loop {
            if cur.count == INTERIOR {
                let node = &self.nodes8[cur.child as usize];
                let (_, mut mask) = r.hits(l, node, t_box);
                if mask != 0 {
                    let first = mask.trailing_zeros() as usize;
                    mask &= mask - 1;
                    while mask != 0 {
                        let s = mask.trailing_zeros() as usize;
                        mask &= mask - 1;
                        stack.push(slot(node, s), 0.0);
                    }
                    cur = slot(node, first);
                    continue;
                }
            } else if cur.count > 0 && leaf(cur.child, cur.count) {
                return true;
            }
            match stack.pop() {
                Some((next, _)) => cur = next,
                None => return false,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::math::lanes::{LaneSet, Lanes, RunLanes};

    struct MinMax([f32; 8], [f32; 8]);
    impl RunLanes for MinMax {
        type Output = ([f32; 8], [f32; 8]);
        fn run<L: Lanes>(self, l: L) -> Self::Output {
            let (a, b) = (l.load(&self.0), l.load(&self.1));
            (l.store(l.max_gt(a, b)), l.store(l.min_lt(a, b)))
        }
    }

    /// The slab test relies on a NaN bound leaving `t0`/`t1` alone, with
    /// every lane set.
    #[test]
    fn lane_min_max_keep_the_second_operand_for_nan() {
        let nan = f32::NAN;
        let a = [nan, 2.0, -1.0, f32::INFINITY, 1.0, nan, -0.0, 0.0];
        let b = [1.0, 1.0, 0.0, 5.0, nan, nan, 0.0, -0.0];
        for set in [LaneSet::Portable, LaneSet::detect()] {
            let (max, min) = set.run(MinMax(a, b));
            let want_max = [1.0, 2.0, 0.0, f32::INFINITY, nan, nan, 0.0, -0.0];
            let want_min = [1.0, 1.0, -1.0, 5.0, nan, nan, 0.0, -0.0];
            let bits = |v: [f32; 8]| v.map(f32::to_bits);
            assert_eq!(bits(max), bits(want_max), "{}", set.name());
            assert_eq!(bits(min), bits(want_min), "{}", set.name());
        }
    }
}
