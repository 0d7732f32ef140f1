//! Closest-hit and any-hit traversal of the 4-wide tree.
//!
//! Each [`Node4`] visit tests its four child boxes at once (one `wide::f32x4`
//! register per slab bound), then continues with the nearest hit child and
//! pushes the others far to near with their entry distances, so that
//! closest-hit queries skip stacked subtrees that start beyond the closest
//! hit found since.

use super::wide::{ChildRef, INTERIOR, Node4};
use super::{Bvh, MAX_DEPTH};
use crate::math::{Ray, gamma};
use arrayvec::ArrayVec;
use wide::{CmpLe, f32x4};

/// Stack capacity: a visit pushes at most three subtrees, so a tree of at
/// most `MAX_DEPTH` levels never stacks more.
const STACK: usize = 3 * MAX_DEPTH;

/// Widening of slab and query distances against rounding (pbrt's `1 + 2γ(3)`).
const WIDEN: f32 = 1.0 + 2.0 * gamma(3);

/// Per-ray constants of the slab test, splatted across the four slots.
struct RayInv {
    o: [f32x4; 3],
    inv: [f32x4; 3],
    /// Per axis, the side of a box the ray enters by (1 for the upper
    /// corner when the direction is negative).
    near: [usize; 3],
}

/// `if a > b { a } else { b }` per lane: a NaN in `a` keeps `b`.
#[inline(always)]
fn max_gt(a: f32x4, b: f32x4) -> f32x4 {
    // MAXPS returns its second operand unless the first is greater.
    #[cfg(target_feature = "sse")]
    {
        a.fast_max(b)
    }
    #[cfg(not(target_feature = "sse"))]
    {
        use wide::CmpGt;
        a.cmp_gt(b).blend(a, b)
    }
}

/// `if a < b { a } else { b }` per lane: a NaN in `a` keeps `b`.
#[inline(always)]
fn min_lt(a: f32x4, b: f32x4) -> f32x4 {
    // MINPS returns its second operand unless the first is smaller.
    #[cfg(target_feature = "sse")]
    {
        a.fast_min(b)
    }
    #[cfg(not(target_feature = "sse"))]
    {
        use wide::CmpLt;
        a.cmp_lt(b).blend(a, b)
    }
}

impl RayInv {
    #[inline(always)]
    fn new(ray: &Ray) -> Self {
        let inv = [1.0 / ray.d.x, 1.0 / ray.d.y, 1.0 / ray.d.z];
        // Sign of the inverse, so that -0.0 directions count as negative.
        let near = inv.map(|i| usize::from(i.is_sign_negative()));
        RayInv {
            o: [ray.o.x, ray.o.y, ray.o.z].map(f32x4::splat),
            inv: inv.map(f32x4::splat),
            near,
        }
    }

    /// Slab test of the four child boxes of `n` over `[0, t_max]`: returns
    /// each box's entry distance and a bit mask of the boxes hit. `far` is
    /// widened by `1 + 2γ(3)` (pbrt) so rounding never culls a box the ray
    /// touches; a NaN slab bound (`0 * inf` for a ray in a slab plane) is
    /// ignored, i.e. the ray counts as inside that slab. The four slots are
    /// tested in one SIMD register; every lane does the scalar test's
    /// operations in the scalar test's order.
    #[inline(always)]
    fn hits4(&self, n: &Node4, t_max: f32) -> ([f32; 4], u32) {
        let mut t0 = f32x4::ZERO;
        let mut t1 = f32x4::splat(t_max);
        let widen = f32x4::splat(WIDEN);
        for a in 0..3 {
            // `& 1` lets the compiler drop the bounds checks of both indices.
            let side = self.near[a] & 1;
            let (lo, hi) = (n.bounds[side][a], n.bounds[side ^ 1][a]);
            let near = (f32x4::from(lo) - self.o[a]) * self.inv[a];
            let far = (f32x4::from(hi) - self.o[a]) * self.inv[a] * widen;
            t0 = max_gt(near, t0);
            t1 = min_lt(far, t1);
        }
        let mask = t0.cmp_le(t1).move_mask() as u32;
        (t0.to_array(), mask)
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
fn slot(n: &Node4, s: usize) -> ChildRef {
    ChildRef {
        child: n.child[s],
        count: n.count[s],
    }
}

impl Bvh {
    /// Finds the closest hit along `ray` in `(0, t_max)`.
    ///
    /// `leaf(first, count, t_max)` tests the `count` primitives at leaf-order
    /// positions `first..first + count` (see [`Bvh::prim_order`]) and returns
    /// the distance of the closest one hit closer than the given `t_max`, if
    /// any; the caller records whatever else it needs. Leaves are visited
    /// roughly near to far. Returns the closest distance found.
    #[inline]
    pub fn closest_hit(
        &self,
        ray: &Ray,
        t_max: f32,
        mut leaf: impl FnMut(u32, u32, f32) -> Option<f32>,
    ) -> Option<f32> {
        let r = RayInv::new(ray);
        let mut t_max = t_max;
        // Boxes are tested against a widened `t_max` too: a primitive's
        // computed distance may fall a few ulps short of its box's computed
        // entry (coplanar, axis-aligned geometry), and it must not be culled
        // once a hit that is only slightly farther has shrunk `t_max`.
        let mut t_box = t_max * WIDEN;
        let mut found = None;
        let mut stack = Stack::new();
        let mut cur = self.root4;
        loop {
            if cur.count == INTERIOR {
                let node = &self.nodes4[cur.child as usize];
                let (tn, mut mask) = r.hits4(node, t_box);
                if mask != 0 {
                    // Hit slots in order of entry distance, nearest last.
                    let mut order = [0usize; 4];
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
                if let Some(t) = leaf(cur.child, cur.count, t_max) {
                    if t < t_max {
                        t_max = t;
                        t_box = t * WIDEN;
                        found = Some(t);
                    }
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

    /// True if any primitive is hit in `(0, t_max)` (shadow rays).
    ///
    /// `leaf(first, count, t_max)` tests the primitives at leaf-order
    /// positions `first..first + count`; traversal stops at the first leaf
    /// for which it returns `true`.
    #[inline]
    pub fn any_hit(
        &self,
        ray: &Ray,
        t_max: f32,
        mut leaf: impl FnMut(u32, u32, f32) -> bool,
    ) -> bool {
        let r = RayInv::new(ray);
        let t_box = t_max * WIDEN;
        let mut stack = Stack::new();
        let mut cur = self.root4;
        loop {
            if cur.count == INTERIOR {
                let node = &self.nodes4[cur.child as usize];
                let (_, mut mask) = r.hits4(node, t_box);
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
            } else if cur.count > 0 && leaf(cur.child, cur.count, t_max) {
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
    use super::*;

    /// The slab test relies on a NaN bound leaving `t0`/`t1` alone.
    #[test]
    fn lane_min_max_keep_the_second_operand_for_nan() {
        let a = f32x4::from([f32::NAN, 2.0, -1.0, f32::INFINITY]);
        let b = f32x4::from([1.0, 1.0, 0.0, 5.0]);
        assert_eq!(max_gt(a, b).to_array(), [1.0, 2.0, 0.0, f32::INFINITY]);
        assert_eq!(min_lt(a, b).to_array(), [1.0, 1.0, -1.0, 5.0]);
    }
}
