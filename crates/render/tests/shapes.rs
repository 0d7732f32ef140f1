//! Ray-shape intersections against analytic answers, and area sampling.

mod common;

use common::Rng;
use lowdisc_render::geometry::{Disk, MeshData, Sphere, TriangleMesh, intersect_triangle};
use lowdisc_render::math::{Point2, Point3, Ray, Transform, Vec3};
use std::f32::consts::PI;

fn close(a: f32, b: f32, tol: f32) -> bool {
    (a - b).abs() <= tol * (1.0 + b.abs())
}

#[test]
fn triangle_hit_matches_analytic_plane_intersection() {
    let tri = [
        Point3::new(0.0, 0.0, 2.0),
        Point3::new(4.0, 0.0, 2.0),
        Point3::new(0.0, 4.0, 2.0),
    ];
    let ray = Ray::new(Point3::new(1.0, 1.0, 0.0), Vec3::new(0.0, 0.0, 1.0));
    let h = intersect_triangle(&ray, f32::INFINITY, tri).unwrap();
    assert!(close(h.t, 2.0, 1e-6));
    // p = p0 + u (p1 - p0) + v (p2 - p0) => u = 1/4, v = 1/4.
    assert!(close(h.u, 0.25, 1e-6) && close(h.v, 0.25, 1e-6));
    // Oblique ray: hits (3, 0.5, 2) at t = |(2, -0.5, 2) |.
    let o = Point3::new(1.0, 1.0, 0.0);
    let target = Point3::new(3.0, 0.5, 2.0);
    let d = (target - o).normalize();
    let h = intersect_triangle(&Ray::new(o, d), f32::INFINITY, tri).unwrap();
    assert!(close(h.t, (target - o).length(), 1e-5));
    // Misses: outside the edge, behind the origin, beyond t_max, parallel.
    let miss = Ray::new(Point3::new(3.0, 3.0, 0.0), Vec3::Z);
    assert!(intersect_triangle(&miss, f32::INFINITY, tri).is_none());
    assert!(
        intersect_triangle(
            &Ray::new(Point3::new(1.0, 1.0, 3.0), Vec3::Z),
            f32::INFINITY,
            tri
        )
        .is_none()
    );
    assert!(intersect_triangle(&ray, 1.99, tri).is_none());
    assert!(intersect_triangle(&Ray::new(o, Vec3::X), f32::INFINITY, tri).is_none());
    // NaN rays never hit.
    let nan = Ray::new(o, Vec3::new(f32::NAN, 0.0, 1.0));
    assert!(intersect_triangle(&nan, f32::INFINITY, tri).is_none());
}

#[test]
fn triangle_surface_hit_normals_and_uv() {
    let data = MeshData {
        positions: vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
        ],
        indices: vec![[0, 1, 2]],
        normals: None,
        uvs: Some(vec![
            Point2::new(0.0, 0.0),
            Point2::new(2.0, 0.0),
            Point2::new(0.0, 2.0),
        ]),
    };
    let m = TriangleMesh::new(&Transform::IDENTITY, data.clone(), false).unwrap();
    let ray = Ray::new(Point3::new(0.25, 0.5, 1.0), -Vec3::Z);
    let h = m.intersect(0, &ray, f32::INFINITY).unwrap();
    let s = m.surface_hit(0, &h);
    assert!((s.p - Point3::new(0.25, 0.5, 0.0)).length() < 1e-6);
    assert!(
        (s.ng - Vec3::Z).length() < 1e-6,
        "counter-clockwise face normal is +z"
    );
    assert!((s.uv - Point2::new(0.5, 1.0)).length() < 1e-6);
    assert!((s.dpdu - Vec3::new(0.5, 0.0, 0.0)).length() < 1e-6);
    // ReverseOrientation flips; a mirroring transform flips; both cancel.
    let rev = TriangleMesh::new(&Transform::IDENTITY, data.clone(), true).unwrap();
    assert!((rev.surface_hit(0, &h).ng + Vec3::Z).length() < 1e-6);
    let mirror = Transform::scale(Vec3::new(1.0, 1.0, -1.0)).unwrap();
    let m2 = TriangleMesh::new(&mirror, data.clone(), false).unwrap();
    assert!((m2.surface_hit(0, &h).ng + Vec3::Z).length() < 1e-6);
    let m3 = TriangleMesh::new(&mirror, data.clone(), true).unwrap();
    assert!((m3.surface_hit(0, &h).ng - Vec3::Z).length() < 1e-6);
    // With shading normals, ng follows them.
    let mut d2 = data;
    d2.normals = Some(vec![-Vec3::Z; 3]);
    let m4 = TriangleMesh::new(&Transform::IDENTITY, d2, false).unwrap();
    let s4 = m4.surface_hit(0, &h);
    assert!((s4.ng + Vec3::Z).length() < 1e-6 && (s4.ns + Vec3::Z).length() < 1e-6);
}

#[test]
fn sphere_hits_match_analytic_roots() {
    // Sphere of radius 1 scaled by 2 and moved to (1, 2, 3): radius 2 there.
    let xf = Transform::translate(Vec3::new(1.0, 2.0, 3.0))
        * Transform::scale(Vec3::splat(2.0)).unwrap();
    let s = Sphere::new(xf, 1.0, false).unwrap();
    let ray = Ray::new(Point3::new(1.0, 2.0, -7.0), Vec3::Z);
    let h = s.intersect(&ray, f32::INFINITY).unwrap();
    assert!(close(h.t, 8.0, 1e-6), "{}", h.t);
    let sh = s.surface_hit(&ray, &h);
    assert!((sh.p - Point3::new(1.0, 2.0, 1.0)).length() < 1e-5);
    assert!(
        (sh.ng + Vec3::Z).length() < 1e-5,
        "outward normal at the south pole"
    );
    assert!(
        close(sh.uv.y, 0.0, 1e-5),
        "v = 1 - theta/pi is 0 at the south pole"
    );
    // From inside: the far root.
    let inside = Ray::new(Point3::new(1.0, 2.0, 3.0), Vec3::X);
    assert!(close(
        s.intersect(&inside, f32::INFINITY).unwrap().t,
        2.0,
        1e-6
    ));
    // Grazing offset ray: |offset| = 1.2 => half chord sqrt(4 - 1.44) = 1.6.
    let off = Ray::new(Point3::new(2.2, 2.0, -7.0), Vec3::Z);
    assert!(close(
        s.intersect(&off, f32::INFINITY).unwrap().t,
        10.0 - 1.6,
        1e-5
    ));
    assert!(s.intersect(&off, 8.0).is_none());
    assert!(
        s.intersect(
            &Ray::new(Point3::new(3.5, 2.0, -7.0), Vec3::Z),
            f32::INFINITY
        )
        .is_none()
    );
    assert!(
        s.intersect(
            &Ray::new(Point3::new(1.0, 2.0, 6.0), Vec3::Z),
            f32::INFINITY
        )
        .is_none()
    );
    assert!(close(s.area(), 16.0 * PI, 1e-6));
    assert!(Sphere::new(Transform::IDENTITY, -1.0, false).is_err());
    assert!(Sphere::new(Transform::IDENTITY, f32::NAN, false).is_err());
}

#[test]
fn disk_hits_match_analytic_answers() {
    let xf = Transform::translate(Vec3::new(0.0, 0.0, 5.0)) * Transform::rotate(90.0, Vec3::X);
    // Object z=1 plane, after Rotate 90 about x, is world y = -1; normal -y.
    let d = Disk::new(xf, 1.0, 2.0, 0.5, false).unwrap();
    let ray = Ray::new(Point3::new(1.0, 3.0, 5.0), -Vec3::Y);
    let h = d.intersect(&ray, f32::INFINITY).unwrap();
    assert!(close(h.t, 4.0, 1e-5));
    let s = d.surface_hit(&ray, &h);
    assert!((s.ng + Vec3::Y).length() < 1e-5, "{:?}", s.ng);
    assert!((s.p - Point3::new(1.0, -1.0, 5.0)).length() < 1e-5);
    assert!(close(s.uv.y, (2.0 - 1.0) / 1.5, 1e-5));
    // Through the hole, outside the rim, parallel: misses.
    assert!(
        d.intersect(
            &Ray::new(Point3::new(0.2, 3.0, 5.0), -Vec3::Y),
            f32::INFINITY
        )
        .is_none()
    );
    assert!(
        d.intersect(
            &Ray::new(Point3::new(2.1, 3.0, 5.0), -Vec3::Y),
            f32::INFINITY
        )
        .is_none()
    );
    assert!(
        d.intersect(
            &Ray::new(Point3::new(1.0, -0.5, 0.0), Vec3::Z),
            f32::INFINITY
        )
        .is_none()
    );
    assert!(close(d.area(), PI * (4.0 - 0.25), 1e-6));
    assert!(Disk::new(Transform::IDENTITY, 0.0, 1.0, 2.0, false).is_err());
}

/// Monte Carlo estimate of the projected area (along `axis`) of a shape,
/// by parallel rays through a square window of half-size `s`.
fn projected_area(hit: impl Fn(&Ray) -> bool, axis: Vec3, s: f32, n: usize, seed: u64) -> f64 {
    let frame = lowdisc_render::math::Frame::from_z(axis);
    let mut rng = Rng::new(seed);
    let hits = (0..n)
        .filter(|_| {
            let (a, b) = (rng.range(-s, s), rng.range(-s, s));
            let o = frame.x * a + frame.y * b - axis * 100.0;
            hit(&Ray::new(o, axis))
        })
        .count();
    hits as f64 / n as f64 * (2.0 * s as f64).powi(2)
}

#[test]
fn area_sampling_pdfs_integrate_to_one() {
    let n = 200_000;
    // Disk (annulus) under rotation and uniform scale: seen along its normal,
    // its projected area is its area, so pdf * MC area must be 1.
    let xf = Transform::rotate(30.0, Vec3::new(1.0, 1.0, 0.0))
        * Transform::scale(Vec3::splat(1.5)).unwrap();
    let d = Disk::new(xf, 0.3, 1.0, 0.4, false).unwrap();
    let s = d.sample(Point2::new(0.3, 0.7)).unwrap();
    let mc = projected_area(|r| d.intersect(r, f32::INFINITY).is_some(), s.n, 1.6, n, 1);
    assert!(
        (s.pdf as f64 * mc - 1.0).abs() < 0.01,
        "disk: {}",
        s.pdf as f64 * mc
    );
    // Sphere: surface area = 4 x projected area (Cauchy).
    let xf = Transform::translate(Vec3::new(0.5, 0.0, 0.0))
        * Transform::scale(Vec3::splat(0.7)).unwrap();
    let sp = Sphere::new(xf, 1.0, false).unwrap();
    let s = sp.sample(Point2::new(0.1, 0.9)).unwrap();
    let mc = 4.0
        * projected_area(
            |r| sp.intersect(r, f32::INFINITY).is_some(),
            Vec3::Z,
            1.3,
            n,
            2,
        );
    assert!(
        (s.pdf as f64 * mc - 1.0).abs() < 0.01,
        "sphere: {}",
        s.pdf as f64 * mc
    );
    // Triangle, transformed.
    let data = MeshData {
        positions: vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.2, 0.0),
            Point3::new(0.3, 0.9, 0.0),
        ],
        indices: vec![[0, 1, 2]],
        ..Default::default()
    };
    let m = TriangleMesh::new(
        &Transform::rotate(50.0, Vec3::new(0.2, 1.0, 0.3)),
        data,
        false,
    )
    .unwrap();
    let s = m.sample(0, Point2::new(0.5, 0.5)).unwrap();
    let mc = projected_area(
        |r| m.intersect(0, r, f32::INFINITY).is_some(),
        s.n,
        1.2,
        n,
        3,
    );
    assert!(
        (s.pdf as f64 * mc - 1.0).abs() < 0.01,
        "triangle: {}",
        s.pdf as f64 * mc
    );
}

#[test]
fn area_samples_lie_on_the_surface_and_are_uniform() {
    let mut rng = Rng::new(7);
    let xf = Transform::translate(Vec3::new(0.0, 1.0, 0.0));
    let sp = Sphere::new(xf, 2.0, false).unwrap();
    let d = Disk::new(Transform::IDENTITY, 0.5, 1.0, 0.5, false).unwrap();
    let n = 100_000;
    let (mut zsum, mut inner) = (0.0f64, 0usize);
    for _ in 0..n {
        let s = sp.sample(rng.p2()).unwrap();
        assert!(((s.p - Point3::new(0.0, 1.0, 0.0)).length() - 2.0).abs() < 1e-5);
        assert!((s.n - (s.p - Point3::new(0.0, 1.0, 0.0)) / 2.0).length() < 1e-5);
        zsum += s.p.z as f64;
        let t = d.sample(rng.p2()).unwrap();
        let r = (t.p.x * t.p.x + t.p.y * t.p.y).sqrt();
        assert!((0.5 - 1e-5..=1.0 + 1e-5).contains(&r) && t.p.z == 0.5);
        inner += (r < 0.75) as usize;
    }
    // Archimedes: z is uniform on [-2, 2], mean 0 (sd of mean ~ 0.0037).
    assert!((zsum / n as f64).abs() < 0.02);
    // Annulus 0.5..1: fraction with r < 0.75 is (0.75^2-0.25)/(1-0.25).
    let want = (0.5625 - 0.25) / 0.75;
    assert!((inner as f64 / n as f64 - want).abs() < 0.006);
}

/// pbrt-v4's `TriangleMesh` negates the per-vertex normals under
/// `ReverseOrientation`, whatever the transform's handedness, and the face
/// normal follows the shading normal: a reversed mesh with normals faces
/// the other way (a one-sided emitter or a dielectric's inside flips).
#[test]
fn reverse_orientation_negates_vertex_normals() {
    let data = MeshData {
        positions: vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
        ],
        indices: vec![[0, 1, 2]],
        normals: Some(vec![Vec3::new(0.0, 0.0, 2.0); 3]),
        uvs: None,
    };
    let mirror_x = Transform::scale(Vec3::new(-1.0, 1.0, 1.0)).unwrap();
    // Straight down onto the (transformed) point (0.25, 0.5, 0).
    let ray = |t: &Transform| Ray::new(t.point(Point3::new(0.25, 0.5, 1.0)), -Vec3::Z);
    // (transform, reverse) -> expected world normal (normals transform
    // with the mirror: z stays +z under a flip of x).
    for (t, reverse, want) in [
        (Transform::IDENTITY, false, Vec3::Z),
        (Transform::IDENTITY, true, -Vec3::Z),
        (mirror_x, false, Vec3::Z),
        (mirror_x, true, -Vec3::Z),
    ] {
        let m = TriangleMesh::new(&t, data.clone(), reverse).unwrap();
        let stored = m.normals.as_ref().unwrap();
        assert!(
            stored.iter().all(|n| (*n - want).length() < 1e-6),
            "{stored:?}"
        );
        let h = m.intersect(0, &ray(&t), f32::INFINITY).unwrap();
        let s = m.surface_hit(0, &h);
        assert!((s.ns - want).length() < 1e-6, "ns {:?} want {want:?}", s.ns);
        assert!((s.ng - want).length() < 1e-6, "ng {:?} want {want:?}", s.ng);
    }
}
