//! Closest-hit and any-hit traversal.

use super::{Bvh, MAX_DEPTH, Node};
use crate::math::{Ray, Vec3, gamma};

/// Per-ray constants of the slab test.
struct RayInv {
    o: Vec3,
    inv: Vec3,
    neg: [bool; 3],
}

impl RayInv {
    #[inline]
    fn new(ray: &Ray) -> Self {
        let inv = Vec3::new(1.0 / ray.d.x, 1.0 / ray.d.y, 1.0 / ray.d.z);
        // Sign of the inverse, so that -0.0 directions count as negative.
        let neg = [
            inv.x.is_sign_negative(),
            inv.y.is_sign_negative(),
            inv.z.is_sign_negative(),
        ];
        RayInv { o: ray.o, inv, neg }
    }

    /// Slab test against a node box over `[0, t_max]`. `far` is widened by
    /// `1 + 2γ(3)` (pbrt) so rounding never culls a box the ray touches; a NaN
    /// slab bound (`0 * inf` for a ray in a slab plane) is ignored, i.e. the
    /// ray counts as inside that slab.
    #[inline(always)]
    fn hits(&self, n: &Node, t_max: f32) -> bool {
        const WIDEN: f32 = 1.0 + 2.0 * gamma(3);
        let mut t0 = 0.0f32;
        let mut t1 = t_max;
        macro_rules! axis {
            ($a:tt, $c:ident) => {
                let (lo, hi) = if self.neg[$a] {
                    (n.max[$a], n.min[$a])
                } else {
                    (n.min[$a], n.max[$a])
                };
                let near = (lo - self.o.$c) * self.inv.$c;
                let far = (hi - self.o.$c) * self.inv.$c * WIDEN;
                if near > t0 {
                    t0 = near;
                }
                if far < t1 {
                    t1 = far;
                }
            };
        }
        axis!(0, x);
        axis!(1, y);
        axis!(2, z);
        t0 <= t1
    }
}

impl Bvh {
    /// Finds the closest hit along `ray` in `(0, t_max)`.
    ///
    /// `hit(k, t_max)` tests the primitive at leaf-order position `k` (see
    /// [`Bvh::prim_order`]) and returns its hit distance if it is hit closer
    /// than the given `t_max`; the caller records whatever else it needs.
    /// Returns the closest distance found.
    #[inline]
    pub fn closest_hit(
        &self,
        ray: &Ray,
        t_max: f32,
        mut hit: impl FnMut(u32, f32) -> Option<f32>,
    ) -> Option<f32> {
        if self.nodes.is_empty() {
            return None;
        }
        let r = RayInv::new(ray);
        let mut t_max = t_max;
        let mut found = None;
        let mut stack = [0u32; MAX_DEPTH];
        let mut sp = 0usize;
        let mut cur = 0usize;
        loop {
            let node = &self.nodes[cur];
            if r.hits(node, t_max) {
                if node.is_leaf() {
                    let first = node.offset;
                    for k in first..first + node.count as u32 {
                        if let Some(t) = hit(k, t_max) {
                            if t < t_max {
                                t_max = t;
                                found = Some(t);
                            }
                        }
                    }
                } else {
                    // Visit the child on the near side of the split first.
                    let (near, far) = if r.neg[node.axis as usize] {
                        (node.offset as usize, cur + 1)
                    } else {
                        (cur + 1, node.offset as usize)
                    };
                    stack[sp] = far as u32;
                    sp += 1;
                    cur = near;
                    continue;
                }
            }
            if sp == 0 {
                return found;
            }
            sp -= 1;
            cur = stack[sp] as usize;
        }
    }

    /// True if any primitive is hit in `(0, t_max)` (shadow rays): stops at the
    /// first `hit(k, t_max)` that returns `true`.
    #[inline]
    pub fn any_hit(&self, ray: &Ray, t_max: f32, mut hit: impl FnMut(u32, f32) -> bool) -> bool {
        if self.nodes.is_empty() {
            return false;
        }
        let r = RayInv::new(ray);
        let mut stack = [0u32; MAX_DEPTH];
        let mut sp = 0usize;
        let mut cur = 0usize;
        loop {
            let node = &self.nodes[cur];
            if r.hits(node, t_max) {
                if node.is_leaf() {
                    let first = node.offset;
                    if (first..first + node.count as u32).any(|k| hit(k, t_max)) {
                        return true;
                    }
                } else {
                    let (near, far) = if r.neg[node.axis as usize] {
                        (node.offset as usize, cur + 1)
                    } else {
                        (cur + 1, node.offset as usize)
                    };
                    stack[sp] = far as u32;
                    sp += 1;
                    cur = near;
                    continue;
                }
            }
            if sp == 0 {
                return false;
            }
            sp -= 1;
            cur = stack[sp] as usize;
        }
    }
}
