//! 4x4 matrices and affine/projective transforms with cached inverses.
//!
//! Conventions follow pbrt: column vectors (`p' = M p`), row-major storage,
//! left-handed rotations are *not* used (rotation is right-handed about the
//! axis, as in pbrt's `Rotate`), and normals transform by the inverse
//! transpose.

use super::bounds::Bounds3;
use super::ray::Ray;
use super::vector::{Normal3, Point3, Vec3};
use crate::content_hash::{ContentHash, ContentSink};
use std::ops::Mul;

/// A row-major 4x4 matrix.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Matrix4 {
    /// Rows of the matrix: `m[row][col]`.
    pub m: [[f32; 4]; 4],
}

impl Matrix4 {
    /// The identity matrix.
    pub const IDENTITY: Matrix4 = Matrix4 {
        m: [
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
    };

    /// The transpose.
    pub fn transpose(&self) -> Matrix4 {
        let mut r = [[0.0; 4]; 4];
        for (i, row) in r.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                *v = self.m[j][i];
            }
        }
        Matrix4 { m: r }
    }

    /// The inverse, computed in `f64` by Gauss-Jordan elimination with partial
    /// pivoting; `None` when the matrix is singular (or has non-finite entries).
    #[allow(clippy::needless_range_loop)] // index form mirrors the algebra
    pub fn inverse(&self) -> Option<Matrix4> {
        let mut a = [[0.0f64; 8]; 4];
        for i in 0..4 {
            for j in 0..4 {
                a[i][j] = self.m[i][j] as f64;
            }
            a[i][4 + i] = 1.0;
        }
        let scale = a
            .iter()
            .flat_map(|r| r[..4].iter())
            .fold(0.0f64, |s, v| s.max(v.abs()));
        if !(scale.is_finite() && scale > 0.0) {
            return None;
        }
        for c in 0..4 {
            let p = (c..4).max_by(|&x, &y| a[x][c].abs().total_cmp(&a[y][c].abs()))?;
            if a[p][c].abs() <= 1e-12 * scale {
                return None;
            }
            a.swap(c, p);
            let inv = 1.0 / a[c][c];
            for v in a[c].iter_mut() {
                *v *= inv;
            }
            for r in 0..4 {
                if r != c {
                    let f = a[r][c];
                    if f != 0.0 {
                        for k in 0..8 {
                            a[r][k] -= f * a[c][k];
                        }
                    }
                }
            }
        }
        let mut m = [[0.0f32; 4]; 4];
        for i in 0..4 {
            for j in 0..4 {
                m[i][j] = a[i][4 + j] as f32;
            }
        }
        Some(Matrix4 { m })
    }

    /// Determinant of the upper-left 3x3 block.
    pub fn det3(&self) -> f32 {
        let m = &self.m;
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    }
}

impl Mul for Matrix4 {
    type Output = Matrix4;
    fn mul(self, o: Matrix4) -> Matrix4 {
        let mut r = [[0.0f32; 4]; 4];
        for (i, row) in r.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                *v = (0..4).map(|k| self.m[i][k] * o.m[k][j]).sum();
            }
        }
        Matrix4 { m: r }
    }
}

/// Error for a transform that cannot be inverted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SingularMatrix;

impl std::fmt::Display for SingularMatrix {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("transform matrix is singular or not finite")
    }
}
impl std::error::Error for SingularMatrix {}

/// A transform with its inverse.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    m: Matrix4,
    m_inv: Matrix4,
}

impl Default for Transform {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Transform {
    /// The identity.
    pub const IDENTITY: Transform = Transform {
        m: Matrix4::IDENTITY,
        m_inv: Matrix4::IDENTITY,
    };

    /// A transform from a matrix, inverting it; errors if it is singular.
    pub fn from_matrix(m: Matrix4) -> Result<Transform, SingularMatrix> {
        let m_inv = m.inverse().ok_or(SingularMatrix)?;
        Ok(Transform { m, m_inv })
    }
    /// A transform from a matrix and its known inverse (not checked).
    pub fn from_parts(m: Matrix4, m_inv: Matrix4) -> Transform {
        Transform { m, m_inv }
    }
    /// The matrix.
    pub fn matrix(&self) -> &Matrix4 {
        &self.m
    }
    /// The inverse matrix.
    pub fn inverse_matrix(&self) -> &Matrix4 {
        &self.m_inv
    }
    /// The inverse transform.
    pub fn inverse(&self) -> Transform {
        Transform {
            m: self.m_inv,
            m_inv: self.m,
        }
    }
    /// Translation by `d`.
    pub fn translate(d: Vec3) -> Transform {
        let mut m = Matrix4::IDENTITY;
        let mut mi = Matrix4::IDENTITY;
        for a in 0..3 {
            m.m[a][3] = d[a];
            mi.m[a][3] = -d[a];
        }
        Transform { m, m_inv: mi }
    }
    /// Non-uniform scale; errors if a factor is zero.
    pub fn scale(s: Vec3) -> Result<Transform, SingularMatrix> {
        if s.x == 0.0 || s.y == 0.0 || s.z == 0.0 || !s.is_finite() {
            return Err(SingularMatrix);
        }
        let mut m = Matrix4::IDENTITY;
        let mut mi = Matrix4::IDENTITY;
        for a in 0..3 {
            m.m[a][a] = s[a];
            mi.m[a][a] = 1.0 / s[a];
        }
        Ok(Transform { m, m_inv: mi })
    }
    /// Rotation by `degrees` about `axis` (right-handed, as pbrt's `Rotate`).
    pub fn rotate(degrees: f32, axis: Vec3) -> Transform {
        let a = axis.normalize();
        let (s, c) = degrees.to_radians().sin_cos();
        let mut m = Matrix4::IDENTITY;
        m.m[0][0] = a.x * a.x + (1.0 - a.x * a.x) * c;
        m.m[0][1] = a.x * a.y * (1.0 - c) - a.z * s;
        m.m[0][2] = a.x * a.z * (1.0 - c) + a.y * s;
        m.m[1][0] = a.x * a.y * (1.0 - c) + a.z * s;
        m.m[1][1] = a.y * a.y + (1.0 - a.y * a.y) * c;
        m.m[1][2] = a.y * a.z * (1.0 - c) - a.x * s;
        m.m[2][0] = a.x * a.z * (1.0 - c) - a.y * s;
        m.m[2][1] = a.y * a.z * (1.0 - c) + a.x * s;
        m.m[2][2] = a.z * a.z + (1.0 - a.z * a.z) * c;
        Transform {
            m,
            m_inv: m.transpose(),
        }
    }
    /// pbrt's `LookAt`: the world-to-camera transform of a camera at `eye`
    /// looking at `look` with `up` roughly up; errors when degenerate.
    pub fn look_at(eye: Point3, look: Point3, up: Vec3) -> Result<Transform, SingularMatrix> {
        let dir = (look - eye).normalize();
        let right = up.normalize().cross(dir);
        if !(right.length() > 0.0) {
            return Err(SingularMatrix);
        }
        let right = right.normalize();
        let new_up = dir.cross(right);
        let mut cam_to_world = Matrix4::IDENTITY;
        for a in 0..3 {
            cam_to_world.m[a][0] = right[a];
            cam_to_world.m[a][1] = new_up[a];
            cam_to_world.m[a][2] = dir[a];
            cam_to_world.m[a][3] = eye[a];
        }
        let world_to_cam = cam_to_world.inverse().ok_or(SingularMatrix)?;
        Ok(Transform {
            m: world_to_cam,
            m_inv: cam_to_world,
        })
    }
    /// pbrt's perspective projection (`fov` in degrees, near/far clip planes).
    pub fn perspective(fov: f32, near: f32, far: f32) -> Result<Transform, SingularMatrix> {
        let persp = Matrix4 {
            m: [
                [1.0, 0.0, 0.0, 0.0],
                [0.0, 1.0, 0.0, 0.0],
                [0.0, 0.0, far / (far - near), -far * near / (far - near)],
                [0.0, 0.0, 1.0, 0.0],
            ],
        };
        let inv_tan = 1.0 / (fov.to_radians() / 2.0).tan();
        let s = Transform::scale(Vec3::new(inv_tan, inv_tan, 1.0))?;
        Ok(s * Transform::from_matrix(persp)?)
    }

    /// Applies the transform to a point (with the homogeneous divide).
    #[inline]
    pub fn point(&self, p: Point3) -> Point3 {
        let m = &self.m.m;
        let x = m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3];
        let y = m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3];
        let z = m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3];
        let w = m[3][0] * p.x + m[3][1] * p.y + m[3][2] * p.z + m[3][3];
        if w == 1.0 {
            Vec3::new(x, y, z)
        } else {
            Vec3::new(x, y, z) / w
        }
    }
    /// Applies the transform to a direction (ignores translation).
    #[inline]
    pub fn vector(&self, v: Vec3) -> Vec3 {
        let m = &self.m.m;
        Vec3::new(
            m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z,
        )
    }
    /// Applies the transform to a normal: multiplies by the inverse transpose
    /// (the result is not renormalised).
    #[inline]
    pub fn normal(&self, n: Normal3) -> Normal3 {
        let mi = &self.m_inv.m;
        Vec3::new(
            mi[0][0] * n.x + mi[1][0] * n.y + mi[2][0] * n.z,
            mi[0][1] * n.x + mi[1][1] * n.y + mi[2][1] * n.z,
            mi[0][2] * n.x + mi[1][2] * n.y + mi[2][2] * n.z,
        )
    }
    /// Applies the transform to a ray (origin as a point, direction as a vector;
    /// ray parameters `t` are preserved by an affine transform).
    #[inline]
    pub fn ray(&self, r: &Ray) -> Ray {
        Ray::new(self.point(r.o), self.vector(r.d))
    }
    /// The box holding the eight transformed corners of `b`.
    pub fn bounds(&self, b: &Bounds3) -> Bounds3 {
        if b.is_empty() {
            return *b;
        }
        Bounds3::from_points((0..8).map(|i| {
            let pick = |bit: usize, a: usize| if i & bit != 0 { b.max[a] } else { b.min[a] };
            self.point(Vec3::new(pick(1, 0), pick(2, 1), pick(4, 2)))
        }))
    }
    /// True when the transform changes a right-handed frame into a left-handed one.
    pub fn swaps_handedness(&self) -> bool {
        self.m.det3() < 0.0
    }
    /// True for the identity.
    pub fn is_identity(&self) -> bool {
        self.m == Matrix4::IDENTITY
    }
}

impl Mul for Transform {
    type Output = Transform;
    /// Composition: `(a * b).point(p) == a.point(b.point(p))`.
    fn mul(self, o: Transform) -> Transform {
        Transform {
            m: self.m * o.m,
            m_inv: o.m_inv * self.m_inv,
        }
    }
}

impl ContentHash for Matrix4 {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let Matrix4 { m } = self;
        m.feed(sink);
    }
}

/// Both matrices: an inverse given with [`Transform::from_parts`] need not
/// be the one [`Matrix4::inverse`] computes.
impl ContentHash for Transform {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let Transform { m, m_inv } = self;
        m.feed(sink);
        m_inv.feed(sink);
    }
}
