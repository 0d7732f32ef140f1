//! Small `f32` vectors: [`Vec3`] (also used for points and normals) and [`Vec2`].
//!
//! Points, directions and normals share one type ([`Point3`] and [`Normal3`]
//! are aliases of [`Vec3`]); the difference matters only under a transform,
//! where [`crate::math::Transform`] has a separate method for each.

use crate::content_hash::{ContentHash, ContentSink};
use std::ops::{Add, AddAssign, Div, Index, Mul, MulAssign, Neg, Sub, SubAssign};

/// A 3-component `f32` vector.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vec3 {
    /// x component.
    pub x: f32,
    /// y component.
    pub y: f32,
    /// z component.
    pub z: f32,
}

/// A position in space (same representation as [`Vec3`]).
pub type Point3 = Vec3;
/// A surface normal (same representation as [`Vec3`]; transform with
/// [`crate::math::Transform::normal`]).
pub type Normal3 = Vec3;

impl Vec3 {
    /// The zero vector.
    pub const ZERO: Vec3 = Vec3::new(0.0, 0.0, 0.0);
    /// Unit x.
    pub const X: Vec3 = Vec3::new(1.0, 0.0, 0.0);
    /// Unit y.
    pub const Y: Vec3 = Vec3::new(0.0, 1.0, 0.0);
    /// Unit z.
    pub const Z: Vec3 = Vec3::new(0.0, 0.0, 1.0);

    /// Builds a vector from its components.
    #[inline]
    pub const fn new(x: f32, y: f32, z: f32) -> Self {
        Vec3 { x, y, z }
    }
    /// All three components equal to `v`.
    #[inline]
    pub const fn splat(v: f32) -> Self {
        Vec3 { x: v, y: v, z: v }
    }
    /// Builds a vector from an array.
    #[inline]
    pub const fn from_array(a: [f32; 3]) -> Self {
        Vec3::new(a[0], a[1], a[2])
    }
    /// The components as an array.
    #[inline]
    pub const fn to_array(self) -> [f32; 3] {
        [self.x, self.y, self.z]
    }
    /// Dot product.
    #[inline]
    pub fn dot(self, o: Vec3) -> f32 {
        self.x * o.x + self.y * o.y + self.z * o.z
    }
    /// Absolute value of the dot product.
    #[inline]
    pub fn abs_dot(self, o: Vec3) -> f32 {
        self.dot(o).abs()
    }
    /// Cross product (right-handed).
    #[inline]
    pub fn cross(self, o: Vec3) -> Vec3 {
        Vec3::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }
    /// Squared Euclidean length.
    #[inline]
    pub fn length_squared(self) -> f32 {
        self.dot(self)
    }
    /// Euclidean length.
    #[inline]
    pub fn length(self) -> f32 {
        self.length_squared().sqrt()
    }
    /// The vector scaled to unit length (NaN components for the zero vector).
    #[inline]
    pub fn normalize(self) -> Vec3 {
        self / self.length()
    }
    /// Component-wise absolute value.
    #[inline]
    pub fn abs(self) -> Vec3 {
        Vec3::new(self.x.abs(), self.y.abs(), self.z.abs())
    }
    /// Component-wise minimum.
    #[inline]
    pub fn min(self, o: Vec3) -> Vec3 {
        Vec3::new(self.x.min(o.x), self.y.min(o.y), self.z.min(o.z))
    }
    /// Component-wise maximum.
    #[inline]
    pub fn max(self, o: Vec3) -> Vec3 {
        Vec3::new(self.x.max(o.x), self.y.max(o.y), self.z.max(o.z))
    }
    /// Largest component.
    #[inline]
    pub fn max_component(self) -> f32 {
        self.x.max(self.y).max(self.z)
    }
    /// Smallest component.
    #[inline]
    pub fn min_component(self) -> f32 {
        self.x.min(self.y).min(self.z)
    }
    /// Index (0, 1, 2) of the largest component.
    #[inline]
    pub fn max_dimension(self) -> usize {
        if self.x > self.y {
            if self.x > self.z { 0 } else { 2 }
        } else if self.y > self.z {
            1
        } else {
            2
        }
    }
    /// Linear interpolation `(1 - t) a + t b`.
    #[inline]
    pub fn lerp(t: f32, a: Vec3, b: Vec3) -> Vec3 {
        a * (1.0 - t) + b * t
    }
    /// `self` flipped, if needed, to lie in the hemisphere of `v`.
    #[inline]
    pub fn face_forward(self, v: Vec3) -> Vec3 {
        if self.dot(v) < 0.0 { -self } else { self }
    }
    /// True when every component is finite.
    #[inline]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }
    /// Euclidean distance between two points.
    #[inline]
    pub fn distance(self, o: Vec3) -> f32 {
        (self - o).length()
    }
}

impl Index<usize> for Vec3 {
    type Output = f32;
    #[inline]
    fn index(&self, i: usize) -> &f32 {
        match i {
            0 => &self.x,
            1 => &self.y,
            _ => &self.z,
        }
    }
}

macro_rules! vec_binop {
    ($t:ident, $tr:ident, $f:ident, $op:tt, $($c:ident),+) => {
        impl $tr for $t {
            type Output = $t;
            #[inline]
            fn $f(self, o: $t) -> $t { $t { $($c: self.$c $op o.$c),+ } }
        }
    };
}
macro_rules! vec_scalar {
    ($t:ident, $($c:ident),+) => {
        impl Mul<f32> for $t {
            type Output = $t;
            #[inline]
            fn mul(self, s: f32) -> $t { $t { $($c: self.$c * s),+ } }
        }
        impl Mul<$t> for f32 {
            type Output = $t;
            #[inline]
            fn mul(self, v: $t) -> $t { v * self }
        }
        impl Div<f32> for $t {
            type Output = $t;
            #[inline]
            fn div(self, s: f32) -> $t { let inv = 1.0 / s; self * inv }
        }
        impl Neg for $t {
            type Output = $t;
            #[inline]
            fn neg(self) -> $t { $t { $($c: -self.$c),+ } }
        }
        impl AddAssign for $t {
            #[inline]
            fn add_assign(&mut self, o: $t) { $(self.$c += o.$c;)+ }
        }
        impl SubAssign for $t {
            #[inline]
            fn sub_assign(&mut self, o: $t) { $(self.$c -= o.$c;)+ }
        }
        impl MulAssign<f32> for $t {
            #[inline]
            fn mul_assign(&mut self, s: f32) { $(self.$c *= s;)+ }
        }
    };
}
vec_binop!(Vec3, Add, add, +, x, y, z);
vec_binop!(Vec3, Sub, sub, -, x, y, z);
vec_binop!(Vec3, Mul, mul, *, x, y, z);
vec_scalar!(Vec3, x, y, z);
vec_binop!(Vec2, Add, add, +, x, y);
vec_binop!(Vec2, Sub, sub, -, x, y);
vec_binop!(Vec2, Mul, mul, *, x, y);
vec_scalar!(Vec2, x, y);

/// A 2-component `f32` vector (texture coordinates, sample pairs).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vec2 {
    /// x (or u) component.
    pub x: f32,
    /// y (or v) component.
    pub y: f32,
}

/// A 2D point (same representation as [`Vec2`]).
pub type Point2 = Vec2;

impl Vec2 {
    /// Builds a vector from its components.
    #[inline]
    pub const fn new(x: f32, y: f32) -> Self {
        Vec2 { x, y }
    }
    /// Dot product.
    #[inline]
    pub fn dot(self, o: Vec2) -> f32 {
        self.x * o.x + self.y * o.y
    }
    /// Euclidean length.
    #[inline]
    pub fn length(self) -> f32 {
        self.dot(self).sqrt()
    }
}

impl ContentHash for Vec3 {
    #[inline]
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let Vec3 { x, y, z } = self;
        [x, y, z].feed(sink);
    }
}

impl ContentHash for Vec2 {
    #[inline]
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let Vec2 { x, y } = self;
        [x, y].feed(sink);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cross_is_right_handed_and_orthogonal() {
        assert_eq!(Vec3::X.cross(Vec3::Y), Vec3::Z);
        let a = Vec3::new(1.0, 2.0, 3.0);
        let b = Vec3::new(-4.0, 0.5, 2.0);
        let c = a.cross(b);
        assert!(c.dot(a).abs() < 1e-5 && c.dot(b).abs() < 1e-5);
    }

    #[test]
    fn ops_and_reductions() {
        let a = Vec3::new(1.0, -5.0, 3.0);
        assert_eq!(a.max_dimension(), 2);
        assert_eq!(a.abs().max_dimension(), 1);
        assert_eq!(a * 2.0 - a, a);
        assert_eq!((a / 2.0)[1], -2.5);
        assert!((Vec3::new(3.0, 4.0, 0.0).length() - 5.0).abs() < 1e-6);
        assert_eq!(Vec3::Z.face_forward(-Vec3::Z), -Vec3::Z);
    }
}
