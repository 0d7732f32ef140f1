//! Orthonormal frames (local shading coordinates).

use super::vector::Vec3;

/// A right-handed orthonormal basis `x, y, z`; `z` is usually the normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// First tangent.
    pub x: Vec3,
    /// Second tangent (`z × x`).
    pub y: Vec3,
    /// Normal direction.
    pub z: Vec3,
}

impl Frame {
    /// A frame whose `z` is the unit vector `n`, with tangents from the
    /// branchless construction of Duff et al., "Building an Orthonormal Basis,
    /// Revisited" (JCGT 2017).
    pub fn from_z(n: Vec3) -> Frame {
        let sign = 1.0f32.copysign(n.z);
        let a = -1.0 / (sign + n.z);
        let b = n.x * n.y * a;
        let x = Vec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
        let y = Vec3::new(b, sign + n.y * n.y * a, -n.y);
        Frame { x, y, z: n }
    }
    /// The shading frame of a surface point with shading normal `ns` (need
    /// not be unit) and tangent `dpdus` (pbrt-v4's `BSDF` constructor): `z`
    /// is `ns` normalised and `x` follows `dpdus` ([`Frame::from_zx`]); the
    /// `+z` frame when `ns` does not normalise.
    #[inline]
    pub fn shading(ns: Vec3, dpdus: Vec3) -> Frame {
        let n = ns.normalize();
        if n.is_finite() {
            Frame::from_zx(n, dpdus)
        } else {
            Frame::from_z(Vec3::Z)
        }
    }
    /// A frame with `z = n` (unit) and `x` the part of `t` orthogonal to `n`;
    /// falls back to [`Frame::from_z`] when `t` is (nearly) parallel to `n`.
    pub fn from_zx(n: Vec3, t: Vec3) -> Frame {
        let x = t - n * n.dot(t);
        let l = x.length();
        if !(l > 1e-6 * t.length()) || !l.is_finite() {
            return Frame::from_z(n);
        }
        let x = x / l;
        Frame {
            x,
            y: n.cross(x),
            z: n,
        }
    }
    /// World direction to local coordinates.
    #[inline(always)]
    pub fn to_local(&self, v: Vec3) -> Vec3 {
        Vec3::new(v.dot(self.x), v.dot(self.y), v.dot(self.z))
    }
    /// Local coordinates to a world direction.
    #[inline(always)]
    pub fn from_local(&self, v: Vec3) -> Vec3 {
        self.x * v.x + self.y * v.y + self.z * v.z
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_are_orthonormal_and_right_handed() {
        let dirs = [
            Vec3::Z,
            -Vec3::Z,
            Vec3::X,
            Vec3::new(0.3, -0.4, 0.1).normalize(),
            Vec3::new(1e-4, 2e-4, -1.0).normalize(),
        ];
        for n in dirs {
            for f in [
                Frame::from_z(n),
                Frame::from_zx(n, Vec3::new(1.0, 1.0, 0.0)),
            ] {
                for (a, b) in [(f.x, f.y), (f.y, f.z), (f.z, f.x)] {
                    assert!(a.dot(b).abs() < 1e-5, "{n:?}");
                }
                assert!((f.x.cross(f.y) - f.z).length() < 1e-5, "{n:?}");
                let v = Vec3::new(0.2, -0.7, 0.5);
                assert!((f.from_local(f.to_local(v)) - v).length() < 1e-5);
            }
        }
    }
}
