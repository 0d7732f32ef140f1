//! Loop subdivision: counts, convex-hull property, boundaries, bad input.

use lowdisc_render::geometry::loop_subdivide;
use lowdisc_render::math::{Point3, Vec3};
use std::collections::HashSet;

fn tetrahedron() -> (Vec<Point3>, Vec<u32>) {
    let p = vec![
        Point3::new(1.0, 1.0, 1.0),
        Point3::new(1.0, -1.0, -1.0),
        Point3::new(-1.0, 1.0, -1.0),
        Point3::new(-1.0, -1.0, 1.0),
    ];
    (p, vec![0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2])
}

fn cube() -> (Vec<Point3>, Vec<u32>) {
    let p = (0..8)
        .map(|i| Point3::new((i & 1) as f32, ((i >> 1) & 1) as f32, ((i >> 2) & 1) as f32))
        .collect();
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let idx = quads
        .iter()
        .flat_map(|q| [q[0], q[1], q[2], q[0], q[2], q[3]])
        .collect();
    (p, idx)
}

fn edge_count(faces: &[[u32; 3]]) -> usize {
    let mut e = HashSet::new();
    for f in faces {
        for k in 0..3 {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            e.insert((a.min(b), a.max(b)));
        }
    }
    e.len()
}

/// Outward face planes of a closed convex control mesh.
fn planes(p: &[Point3], idx: &[u32]) -> Vec<(Vec3, f32)> {
    idx.chunks(3)
        .map(|t| {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| p[i as usize]);
            let n = (b - a).cross(c - a).normalize();
            (n, n.dot(a))
        })
        .collect()
}

#[test]
fn counts_follow_the_scheme_for_closed_meshes() {
    for (p, idx) in [tetrahedron(), cube()] {
        let (mut v, mut e, mut f) = (
            p.len(),
            edge_count(
                &idx.chunks(3)
                    .map(|c| [c[0], c[1], c[2]])
                    .collect::<Vec<_>>(),
            ),
            idx.len() / 3,
        );
        for k in 0..=4u32 {
            let m = loop_subdivide(&p, &idx, k).unwrap();
            assert_eq!(m.indices.len(), (idx.len() / 3) * 4usize.pow(k));
            assert_eq!(
                (m.positions.len(), m.indices.len(), edge_count(&m.indices)),
                (v, f, e),
                "level {k}"
            );
            assert_eq!(
                v as i64 - e as i64 + f as i64,
                2,
                "Euler characteristic of a sphere"
            );
            // Next level: V' = V + E, E' = 2E + 3F, F' = 4F.
            (v, e, f) = (v + e, 2 * e + 3 * f, 4 * f);
        }
    }
}

#[test]
fn limit_surface_stays_inside_the_convex_hull_and_normals_point_out() {
    for (p, idx) in [tetrahedron(), cube()] {
        let pl = planes(&p, &idx);
        let centre = p.iter().fold(Vec3::ZERO, |a, &b| a + b) / p.len() as f32;
        for k in 0..=3 {
            let m = loop_subdivide(&p, &idx, k).unwrap();
            let normals = m.normals.as_ref().unwrap();
            for (q, n) in m.positions.iter().zip(normals) {
                for (pn, d) in &pl {
                    assert!(pn.dot(*q) <= d + 1e-5, "level {k}: {q:?} outside");
                }
                assert!((*q - centre).dot(*n) > 0.0, "normal points outward");
                assert!((n.length() - 1.0).abs() < 1e-5);
            }
            // Smoothing shrinks the shape strictly inside for k >= 0.
            let max_r = m
                .positions
                .iter()
                .map(|q| (*q - centre).length())
                .fold(0.0, f32::max);
            let hull_r = p.iter().map(|q| (*q - centre).length()).fold(0.0, f32::max);
            assert!(max_r < hull_r);
        }
    }
}

#[test]
fn tetrahedron_limit_of_a_vertex_is_exact() {
    // Level 0: vertex v of valence 3 has beta = 3/16, gamma = 1/(3 + 2) = 1/5,
    // limit = (1 - 3/5) v + 1/5 (sum of the other three).
    let (p, idx) = tetrahedron();
    let m = loop_subdivide(&p, &idx, 0).unwrap();
    let want = p[0] * 0.4 + (p[1] + p[2] + p[3]) * 0.2;
    assert!((m.positions[0] - want).length() < 1e-6);
}

#[test]
fn open_planar_mesh_keeps_its_boundary_and_plane() {
    // A unit square of two triangles: everything stays in z = 0 and inside
    // the square, and corners (boundary valence 2) follow the boundary rules.
    let p = vec![
        Point3::new(0.0, 0.0, 0.0),
        Point3::new(1.0, 0.0, 0.0),
        Point3::new(1.0, 1.0, 0.0),
        Point3::new(0.0, 1.0, 0.0),
    ];
    let idx = vec![0, 1, 2, 0, 2, 3];
    let m = loop_subdivide(&p, &idx, 3).unwrap();
    assert_eq!(m.indices.len(), 2 * 64);
    for q in &m.positions {
        assert_eq!(q.z, 0.0);
        assert!(
            (0.0..=1.0).contains(&q.x) && (0.0..=1.0).contains(&q.y),
            "{q:?}"
        );
    }
    for n in m.normals.unwrap() {
        assert!((n - Vec3::Z).length() < 1e-6);
    }
}

#[test]
fn bad_input_is_an_error() {
    let (p, idx) = tetrahedron();
    assert!(loop_subdivide(&p, &idx[..11], 1).is_err());
    assert!(loop_subdivide(&p, &[0, 1, 9], 1).is_err());
    assert!(loop_subdivide(&p, &idx, 99).is_err());
    assert!(loop_subdivide(&[Point3::new(f32::NAN, 0.0, 0.0)], &[0, 0, 0], 1).is_err());
}
