//! Closest-hit and any-hit traversal of the 4-wide tree.
//!
//! Each [`Node4`] visit tests its four child boxes at once (fixed-size
//! arrays in straight-line code, which the compiler turns into SIMD), then
//! continues with the nearest hit child and pushes the others far to near
//! with their entry distances, so that closest-hit queries skip stacked
//! subtrees that start beyond the closest hit found since.

use super::wide::{ChildRef, INTERIOR, Node4};
use super::{Bvh, MAX_DEPTH};
use crate::math::{Ray, gamma};

/// Stack size for trees of at most `MICRO_STACK / 3` levels (small scenes:
/// zeroing it per ray costs a few stores instead of a `memset` call).
const MICRO_STACK: usize = 9;
/// Stack size for trees of at most `TINY_STACK / 3` levels.
const TINY_STACK: usize = 24;
/// Stack size for trees of at most `SMALL_STACK / 3` levels.
const SMALL_STACK: usize = 66;
/// Stack size for any tree the builder makes (at most `MAX_DEPTH` levels).
const LARGE_STACK: usize = 3 * MAX_DEPTH;

/// Widening of slab and query distances against rounding (pbrt's `1 + 2γ(3)`).
const WIDEN: f32 = 1.0 + 2.0 * gamma(3);

/// Per-ray constants of the slab test.
struct RayInv {
    o: [f32; 3],
    inv: [f32; 3],
    neg: [bool; 3],
}

impl RayInv {
    #[inline(always)]
    fn new(ray: &Ray) -> Self {
        let inv = [1.0 / ray.d.x, 1.0 / ray.d.y, 1.0 / ray.d.z];
        // Sign of the inverse, so that -0.0 directions count as negative.
        let neg = inv.map(f32::is_sign_negative);
        RayInv {
            o: [ray.o.x, ray.o.y, ray.o.z],
            inv,
            neg,
        }
    }

    /// Slab test of the four child boxes of `n` over `[0, t_max]`: returns
    /// each box's entry distance and a bit mask of the boxes hit. `far` is
    /// widened by `1 + 2γ(3)` (pbrt) so rounding never culls a box the ray
    /// touches; a NaN slab bound (`0 * inf` for a ray in a slab plane) is
    /// ignored, i.e. the ray counts as inside that slab.
    #[inline(always)]
    fn hits4(&self, n: &Node4, t_max: f32) -> ([f32; 4], u32) {
        let mut t0 = [0.0f32; 4];
        let mut t1 = [t_max; 4];
        for a in 0..3 {
            let (lo, hi) = if self.neg[a] {
                (&n.hi[a], &n.lo[a])
            } else {
                (&n.lo[a], &n.hi[a])
            };
            let (o, inv) = (self.o[a], self.inv[a]);
            for s in 0..4 {
                let near = (lo[s] - o) * inv;
                let far = (hi[s] - o) * inv * WIDEN;
                // `x > y` is false for NaN: NaN bounds leave t0, t1 alone.
                t0[s] = if near > t0[s] { near } else { t0[s] };
                t1[s] = if far < t1[s] { far } else { t1[s] };
            }
        }
        let mut mask = 0;
        for s in 0..4 {
            mask |= ((t0[s] <= t1[s]) as u32) << s;
        }
        (t0, mask)
    }
}

/// A fixed-capacity stack of subtrees with their entry distances.
struct Stack<const N: usize> {
    refs: [ChildRef; N],
    t: [f32; N],
    len: usize,
}

impl<const N: usize> Stack<N> {
    #[inline(always)]
    fn new() -> Self {
        Stack {
            refs: [ChildRef::default(); N],
            t: [0.0; N],
            len: 0,
        }
    }
    #[inline(always)]
    fn push(&mut self, r: ChildRef, t: f32) {
        self.refs[self.len] = r;
        self.t[self.len] = t;
        self.len += 1;
    }
    #[inline(always)]
    fn pop(&mut self) -> Option<(ChildRef, f32)> {
        self.len = self.len.checked_sub(1)?;
        Some((self.refs[self.len], self.t[self.len]))
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
        leaf: impl FnMut(u32, u32, f32) -> Option<f32>,
    ) -> Option<f32> {
        // The stack is zeroed per ray: size it to the tree.
        let need = self.levels4 * 3;
        if need <= MICRO_STACK {
            self.closest_hit_n::<MICRO_STACK>(ray, t_max, leaf)
        } else if need <= TINY_STACK {
            self.closest_hit_n::<TINY_STACK>(ray, t_max, leaf)
        } else if need <= SMALL_STACK {
            self.closest_hit_n::<SMALL_STACK>(ray, t_max, leaf)
        } else {
            self.closest_hit_n::<LARGE_STACK>(ray, t_max, leaf)
        }
    }

    /// True if any primitive is hit in `(0, t_max)` (shadow rays).
    ///
    /// `leaf(first, count, t_max)` tests the primitives at leaf-order
    /// positions `first..first + count`; traversal stops at the first leaf
    /// for which it returns `true`.
    #[inline]
    pub fn any_hit(&self, ray: &Ray, t_max: f32, leaf: impl FnMut(u32, u32, f32) -> bool) -> bool {
        let need = self.levels4 * 3;
        if need <= MICRO_STACK {
            self.any_hit_n::<MICRO_STACK>(ray, t_max, leaf)
        } else if need <= TINY_STACK {
            self.any_hit_n::<TINY_STACK>(ray, t_max, leaf)
        } else if need <= SMALL_STACK {
            self.any_hit_n::<SMALL_STACK>(ray, t_max, leaf)
        } else {
            self.any_hit_n::<LARGE_STACK>(ray, t_max, leaf)
        }
    }

    #[inline(always)]
    fn closest_hit_n<const N: usize>(
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
        let mut stack = Stack::<N>::new();
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

    #[inline(always)]
    fn any_hit_n<const N: usize>(
        &self,
        ray: &Ray,
        t_max: f32,
        mut leaf: impl FnMut(u32, u32, f32) -> bool,
    ) -> bool {
        let r = RayInv::new(ray);
        let t_box = t_max * WIDEN;
        let mut stack = Stack::<N>::new();
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
