//! Transforms: inverses, composition, normals by the inverse transpose.

mod common;

use common::Rng;
use lowdisc_render::math::{Bounds3, Matrix4, Point3, Transform, Vec3};

fn random_transform(rng: &mut Rng) -> Transform {
    let t = Transform::translate(rng.vec(-10.0, 10.0));
    let r = Transform::rotate(rng.range(-180.0, 180.0), rng.dir());
    let s = Transform::scale(Vec3::new(
        rng.range(0.2, 3.0),
        rng.range(0.2, 3.0),
        rng.range(-3.0, -0.2),
    ))
    .unwrap();
    let r2 = Transform::rotate(rng.range(-180.0, 180.0), rng.dir());
    t * r * s * r2
}

fn max_abs_diff(a: &Matrix4, b: &Matrix4) -> f32 {
    (0..16)
        .map(|k| (a.m[k / 4][k % 4] - b.m[k / 4][k % 4]).abs())
        .fold(0.0, f32::max)
}

#[test]
fn inverse_times_transform_is_identity() {
    let mut rng = Rng::new(11);
    for _ in 0..200 {
        let t = random_transform(&mut rng);
        let id = *t.inverse_matrix() * *t.matrix();
        assert!(max_abs_diff(&id, &Matrix4::IDENTITY) < 1e-4, "{id:?}");
        // The general inverse agrees with the cached, constructed one.
        let inv = t.matrix().inverse().unwrap();
        assert!(max_abs_diff(&inv, t.inverse_matrix()) < 1e-4);
        let p = rng.vec(-5.0, 5.0);
        assert!((t.inverse().point(t.point(p)) - p).length() < 1e-4);
    }
    assert!(
        Matrix4 {
            m: [
                [1.0, 2.0, 3.0, 0.0],
                [2.0, 4.0, 6.0, 0.0],
                [0.0, 0.0, 1.0, 0.0],
                [0.0, 0.0, 0.0, 1.0]
            ]
        }
        .inverse()
        .is_none()
    );
    assert!(Transform::scale(Vec3::new(1.0, 0.0, 1.0)).is_err());
}

#[test]
fn composition_applies_right_to_left() {
    let t = Transform::translate(Vec3::new(1.0, 0.0, 0.0));
    let r = Transform::rotate(90.0, Vec3::Z);
    // Rotate first (x -> y), then translate.
    let p = (t * r).point(Point3::new(1.0, 0.0, 0.0));
    assert!((p - Point3::new(1.0, 1.0, 0.0)).length() < 1e-6);
    assert!(
        (r.vector(Vec3::X) - Vec3::Y).length() < 1e-6,
        "right-handed rotation"
    );
    assert!(!r.swaps_handedness());
    assert!(
        Transform::scale(Vec3::new(-1.0, 1.0, 1.0))
            .unwrap()
            .swaps_handedness()
    );
}

#[test]
fn normals_transform_by_inverse_transpose() {
    let mut rng = Rng::new(12);
    for _ in 0..200 {
        let t = random_transform(&mut rng);
        let n = rng.dir();
        let frame = lowdisc_render::math::Frame::from_z(n);
        let tn = t.normal(n);
        // Tangents stay perpendicular to the transformed normal.
        for tangent in [frame.x, frame.y] {
            let tt = t.vector(tangent);
            assert!(tn.normalize().dot(tt.normalize()).abs() < 1e-4);
        }
    }
    // A non-uniform scale: the plane x + y = 0's normal (1,1,0) under
    // scale (2,1,1) becomes (1/2, 1, 0).
    let s = Transform::scale(Vec3::new(2.0, 1.0, 1.0)).unwrap();
    assert!((s.normal(Vec3::new(1.0, 1.0, 0.0)) - Vec3::new(0.5, 1.0, 0.0)).length() < 1e-6);
}

#[test]
fn look_at_and_bounds() {
    let w2c = Transform::look_at(Point3::new(0.0, 0.0, -5.0), Point3::ZERO, Vec3::Y).unwrap();
    assert!((w2c.point(Point3::ZERO) - Point3::new(0.0, 0.0, 5.0)).length() < 1e-6);
    assert!(Transform::look_at(Point3::ZERO, Point3::new(0.0, 1.0, 0.0), Vec3::Y).is_err());
    let b = Bounds3::new(Point3::new(-1.0, -1.0, -1.0), Point3::new(1.0, 1.0, 1.0));
    let rb = Transform::rotate(45.0, Vec3::Z).bounds(&b);
    assert!((rb.max.x - 2f32.sqrt()).abs() < 1e-5 && (rb.max.z - 1.0).abs() < 1e-6);
}
