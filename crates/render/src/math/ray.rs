//! Rays, and the robust origin offset used to spawn rays from a surface.

use super::vector::{Normal3, Point3, Vec3};
use bytemuck::cast;
use wide::{CmpEq, CmpLt, f32x4, i32x4};

/// A ray `o + t d` (the direction need not be normalised).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Origin.
    pub o: Point3,
    /// Direction.
    pub d: Vec3,
}

impl Ray {
    /// Builds a ray.
    #[inline]
    pub const fn new(o: Point3, d: Vec3) -> Self {
        Ray { o, d }
    }
    /// The point at parameter `t`.
    #[inline]
    pub fn at(&self, t: f32) -> Point3 {
        self.o + self.d * t
    }
}

/// Moves a surface point `p` off the surface along the geometric normal `ng`,
/// to the side `w` points to, so that a ray spawned there does not hit the same
/// surface again.
///
/// This is the integer-ULP offset of Wächter & Binder, "A Fast and Robust
/// Method for Avoiding Self-Intersection" (Ray Tracing Gems, ch. 6, 2019):
/// the offset scales with the magnitude of `p`, and near the origin a small
/// absolute offset is used instead. `ng` should be unit length.
pub fn offset_ray_origin(p: Point3, ng: Normal3, w: Vec3) -> Point3 {
    // `n` is `-ng` when `ng · w < 0`, else `ng`: negation flips the sign
    // bit, so one XOR of every lane does it, without a branch.
    let flip = if ng.dot(w) < 0.0 { i32::MIN } else { 0 };
    // The three coordinates at once (lane 3 unused); per lane this is
    // `offset_coordinate` below, operation for operation.
    let pv = f32x4::from([p.x, p.y, p.z, 0.0]);
    let ngv = cast::<f32x4, i32x4>(f32x4::from([ng.x, ng.y, ng.z, 0.0]));
    let nv: f32x4 = cast(ngv ^ i32x4::splat(flip));
    let scaled = nv * f32x4::splat(INT_SCALE);
    // `as i32` maps NaN to 0 (`fast_trunc_int` does not); |scaled| <= 256
    // for a unit normal, so no lane saturates.
    let oi = scaled.fast_trunc_int() & cast::<f32x4, i32x4>(scaled.cmp_eq(scaled));
    let negative = cast::<f32x4, i32x4>(pv.cmp_lt(f32x4::ZERO));
    let moved: f32x4 = cast(cast::<f32x4, i32x4>(pv) + negative.blend(-oi, oi));
    let near_origin = pv.abs().cmp_lt(f32x4::splat(ORIGIN));
    let out = near_origin
        .blend(pv + f32x4::splat(FLOAT_SCALE) * nv, moved)
        .to_array();
    Vec3::new(out[0], out[1], out[2])
}

// Constants from the chapter: 1/32 switch point, 1/65536 float scale, 256
// integer scale.
const ORIGIN: f32 = 1.0 / 32.0;
const FLOAT_SCALE: f32 = 1.0 / 65536.0;
const INT_SCALE: f32 = 256.0;

/// One coordinate of [`offset_ray_origin`]: `pc` moved by `INT_SCALE * nc`
/// units in the last place, or by `FLOAT_SCALE * nc` near the origin (the
/// scalar definition the SIMD version is tested against).
#[cfg(test)]
fn offset_coordinate(pc: f32, nc: f32) -> f32 {
    let oi = (INT_SCALE * nc) as i32;
    let bits = pc.to_bits() as i32;
    let moved = f32::from_bits(bits.wrapping_add(if pc < 0.0 { -oi } else { oi }) as u32);
    if pc.abs() < ORIGIN {
        pc + FLOAT_SCALE * nc
    } else {
        moved
    }
}

/// A ray from surface point `p` (geometric normal `ng`) in direction `d`,
/// with its origin offset by [`offset_ray_origin`].
pub fn spawn_ray(p: Point3, ng: Normal3, d: Vec3) -> Ray {
    Ray::new(offset_ray_origin(p, ng, d), d)
}

/// A ray from surface point `p` towards point `target`, with the direction
/// scaled so that `t = 1` reaches `target` (use `t_max` slightly below 1 for
/// shadow rays, e.g. [`SHADOW_EPSILON`] below).
pub fn spawn_ray_to(p: Point3, ng: Normal3, target: Point3) -> Ray {
    let o = offset_ray_origin(p, ng, target - p);
    Ray::new(o, target - o)
}

/// `1 - SHADOW_EPSILON` is the usual `t_max` for a shadow ray built with
/// [`spawn_ray_to`], so that the target surface itself is not hit.
pub const SHADOW_EPSILON: f32 = 1e-4;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offset_moves_to_the_side_of_w() {
        for &p in &[Vec3::new(0.0, 0.0, 0.0), Vec3::new(100.0, -3.0, 1e4)] {
            let n = Vec3::Z;
            let up = offset_ray_origin(p, n, Vec3::new(0.3, 0.0, 1.0));
            let down = offset_ray_origin(p, n, Vec3::new(0.3, 0.0, -1.0));
            assert!(up.z > p.z && down.z < p.z, "{p:?} {up:?} {down:?}");
            assert_eq!(up.x, p.x);
        }
    }

    /// The SIMD offset equals the scalar definition bit for bit, on points
    /// near and far from the origin, of both signs, and on exact zeros.
    #[test]
    fn offset_matches_the_scalar_definition() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state = lowdisc::hash::mix64(state.wrapping_add(0x9e37_79b9_7f4a_7c15));
            state
        };
        for _ in 0..20_000 {
            let r = next();
            let coord = |k: u32| {
                let u = ((r >> (16 * k)) & 0xffff) as f32 / 65536.0 - 0.5;
                let scale = [0.0, 0.01, 1.0, 1e4][((r >> (60 - 2 * k)) & 3) as usize];
                u * scale
            };
            let p = Vec3::new(coord(0), coord(1), coord(2));
            let n = Vec3::new(coord(1) + 0.1, coord(2) - 0.2, coord(0) + 0.3).normalize();
            let w = Vec3::new(coord(2), coord(0), coord(1));
            let got = offset_ray_origin(p, n, w);
            let m = if n.dot(w) < 0.0 { -n } else { n };
            let want = Vec3::new(
                offset_coordinate(p.x, m.x),
                offset_coordinate(p.y, m.y),
                offset_coordinate(p.z, m.z),
            );
            assert_eq!(
                [got.x, got.y, got.z].map(f32::to_bits),
                [want.x, want.y, want.z].map(f32::to_bits),
                "p {p:?} n {n:?} w {w:?}"
            );
        }
    }

    #[test]
    fn ray_at() {
        let r = Ray::new(Vec3::new(1.0, 2.0, 3.0), Vec3::new(0.0, 0.0, -2.0));
        assert_eq!(r.at(1.5), Vec3::new(1.0, 2.0, 0.0));
    }
}
