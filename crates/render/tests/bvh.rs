//! BVH closest hit equals brute force; any-hit agrees; structure invariants.

mod common;

use common::{Rng, random_ray};
use lowdisc::catalog::SamplerName;
use lowdisc_render::Accel;
use lowdisc_render::bvh::{BuildOptions, Bvh, MAX_DEPTH, Node};
use lowdisc_render::cornell::cornell_box;
use lowdisc_render::geometry::{Disk, MeshData, Prim, ShapeSet, Sphere, TriangleMesh};
use lowdisc_render::math::lanes::LaneSet;
use lowdisc_render::math::{Bounds3, Point3, Ray, Transform, Vec3};
use lowdisc_render::mesh::read_ply;
use lowdisc_render::render::{NoProgress, RenderOptions, render};

fn soup(rng: &mut Rng, n: usize, size: f32, spread: f32) -> MeshData {
    let mut m = MeshData::default();
    for i in 0..n as u32 {
        let c = rng.vec(-spread, spread);
        for _ in 0..3 {
            m.positions.push(c + rng.vec(-size, size));
        }
        m.indices.push([3 * i, 3 * i + 1, 3 * i + 2]);
    }
    m
}

/// The smallest (distance, primitive index) over all primitives hit.
fn brute_force(set: &ShapeSet, ray: &Ray, t_max: f32) -> Option<(Prim, f32)> {
    let mut best: Option<(Prim, f32)> = None;
    for p in set.prims() {
        let tm = best.map_or(t_max, |b| b.1);
        if let Some(h) = set.intersect(p, ray, tm) {
            best = Some((p, h.t));
        }
    }
    best
}

/// Compares BVH queries with brute force on `rays`; returns the number of hits.
fn check(set: &ShapeSet, accel: &Accel, rays: &[Ray], t_max: f32) -> usize {
    let mut hits = 0;
    for (i, r) in rays.iter().enumerate() {
        let want = brute_force(set, r, t_max);
        let got = accel.intersect_prim(r, t_max);
        match (want, got) {
            (None, None) => {}
            (Some((wp, wt)), Some((gp, gh))) => {
                // Same distance and, at exact ties, the primitive listed
                // first (the tie-break rule).
                assert_eq!((wt, wp), (gh.t, gp), "ray {i}: {r:?}");
                hits += 1;
            }
            _ => panic!("ray {i}: brute force {want:?} vs bvh {got:?} ({r:?})"),
        }
        assert_eq!(
            accel.intersect_p(r, t_max),
            want.is_some(),
            "any-hit, ray {i}"
        );
    }
    hits
}

fn check_structure(bvh: &Bvh, boxes: &[Bounds3]) {
    assert_eq!(std::mem::size_of::<Node>(), 32);
    let nodes = bvh.nodes();
    let mut seen = vec![false; boxes.len()];
    for &i in bvh.prim_order() {
        assert!(
            !std::mem::replace(&mut seen[i as usize], true),
            "prim {i} twice"
        );
    }
    assert!(seen.iter().all(|&s| s), "every primitive is in a leaf");
    let contains =
        |n: &Node, b: &Bounds3| (0..3).all(|a| n.min[a] <= b.min[a] && n.max[a] >= b.max[a]);
    let mut stack = vec![(0usize, 0usize)];
    let (mut leaves, mut in_leaves, mut max_depth) = (0, 0, 0);
    while let Some((i, depth)) = stack.pop() {
        let n = &nodes[i];
        max_depth = max_depth.max(depth);
        if n.is_leaf() {
            leaves += 1;
            for k in n.offset..n.offset + n.count as u32 {
                in_leaves += 1;
                assert!(contains(n, &boxes[bvh.prim_order()[k as usize] as usize]));
            }
        } else {
            for c in [i + 1, n.offset as usize] {
                let cb = &nodes[c];
                let b = Bounds3 {
                    min: Vec3::from_array(cb.min),
                    max: Vec3::from_array(cb.max),
                };
                assert!(contains(n, &b), "child box inside parent");
                stack.push((c, depth + 1));
            }
        }
    }
    let st = bvh.stats();
    assert_eq!(
        (st.leaves, st.nodes, st.max_depth, in_leaves),
        (leaves, nodes.len(), max_depth, boxes.len())
    );
    assert!(max_depth < MAX_DEPTH);
}

fn boxes_of(set: &ShapeSet) -> Vec<Bounds3> {
    set.prims().iter().map(|&p| set.bounds(p)).collect()
}

#[test]
fn closest_hit_equals_brute_force_on_random_soups() {
    for (seed, n, size) in [
        (1u64, 3000usize, 0.3f32),
        (2, 1000, 2.0),
        (3, 20, 0.5),
        (4, 1, 1.0),
    ] {
        let mut rng = Rng::new(seed);
        let mut set = ShapeSet::new();
        set.add_mesh(
            TriangleMesh::new(&Transform::IDENTITY, soup(&mut rng, n, size, 4.0), false).unwrap(),
        );
        for _ in 0..20 {
            let xf = Transform::translate(rng.vec(-4.0, 4.0));
            set.add_sphere(Sphere::new(xf, rng.range(0.05, 0.6), false).unwrap());
            let xf = Transform::translate(rng.vec(-4.0, 4.0))
                * Transform::rotate(rng.range(0.0, 360.0), rng.dir());
            set.add_disk(Disk::new(xf, 0.0, rng.range(0.1, 0.8), 0.0, false).unwrap());
        }
        let opts = BuildOptions {
            parallel_threshold: 256,
            ..Default::default()
        };
        let accel = Accel::build_with(set.clone(), opts);
        check_structure(accel.bvh(), &boxes_of(&set));
        let rays: Vec<Ray> = (0..3000).map(|_| random_ray(&mut rng, 4.5)).collect();
        let hits = check(&set, &accel, &rays, f32::INFINITY);
        assert!(hits > 300, "seed {seed}: only {hits} hits: test too weak");
        let short = check(&set, &accel, &rays[..500], 3.0);
        assert!(short < hits);
    }
}

#[test]
fn exact_ties_go_to_the_primitive_listed_first() {
    // Every triangle and sphere twice: the copies are hit at bit-identical
    // distances, and the copy listed first in `ShapeSet::prims` must win
    // whichever the BVH visits first. The second mesh lists the copies in
    // reverse order, so that leaf order and listing order disagree.
    let mut rng = Rng::new(11);
    let data = soup(&mut rng, 400, 0.5, 3.0);
    let mut reversed = data.clone();
    reversed.indices.reverse();
    let mut set = ShapeSet::new();
    for d in [reversed, data] {
        set.add_mesh(TriangleMesh::new(&Transform::IDENTITY, d, false).unwrap());
    }
    for _ in 0..10 {
        let s = Sphere::new(Transform::translate(rng.vec(-3.0, 3.0)), 0.4, false).unwrap();
        set.add_sphere(s.clone());
        set.add_sphere(s);
    }
    for max_leaf_prims in [1, 4, 8, 20] {
        let opts = BuildOptions {
            max_leaf_prims,
            ..Default::default()
        };
        let accel = Accel::build_with(set.clone(), opts);
        let rays: Vec<Ray> = (0..3000).map(|_| random_ray(&mut rng, 4.0)).collect();
        let hits = check(&set, &accel, &rays, f32::INFINITY);
        assert!(hits > 1000, "{hits}");
    }
}

#[test]
fn axis_aligned_and_degenerate_rays() {
    // A grid of unit-cube-aligned triangles: rays with zero direction
    // components, rays in slab planes, and NaN rays.
    let mut rng = Rng::new(5);
    let mut m = MeshData::default();
    for k in 0..400u32 {
        let c = Point3::new((k % 20) as f32, (k / 20) as f32, (k % 7) as f32);
        m.positions.extend([c, c + Vec3::X, c + Vec3::Y]);
        m.indices.push([3 * k, 3 * k + 1, 3 * k + 2]);
    }
    let mut set = ShapeSet::new();
    set.add_mesh(TriangleMesh::new(&Transform::IDENTITY, m, false).unwrap());
    let accel = Accel::build(set.clone());
    let mut rays = Vec::new();
    for _ in 0..2000 {
        let o = Point3::new(rng.range(-1.0, 21.0), rng.range(-1.0, 21.0), -3.0);
        rays.push(Ray::new(o, Vec3::Z));
        rays.push(Ray::new(
            Point3::new(o.x.floor(), o.y, -3.0),
            Vec3::new(0.0, -0.0, 1.0),
        ));
        rays.push(Ray::new(
            Point3::new(o.x, o.y, 10.0),
            Vec3::new(-0.0, 0.0, -1.0),
        ));
    }
    let hits = check(&set, &accel, &rays, f32::INFINITY);
    assert!(hits > 1000, "{hits}");
    for bad in [
        Vec3::new(f32::NAN, 0.0, 1.0),
        Vec3::ZERO,
        Vec3::new(f32::INFINITY, 1.0, 0.0),
    ] {
        let r = Ray::new(Point3::new(5.2, 5.2, -3.0), bad);
        assert!(accel.intersect(&r, f32::INFINITY).is_none());
        assert!(!accel.intersect_p(&r, f32::INFINITY));
    }
}

#[test]
fn degenerate_inputs_build() {
    // Many identical triangles (all centroids equal), plus empty input.
    let mut m = MeshData::default();
    for k in 0..5000u32 {
        m.positions.extend([Point3::ZERO, Vec3::X, Vec3::Y]);
        m.indices.push([3 * k, 3 * k + 1, 3 * k + 2]);
    }
    let mut set = ShapeSet::new();
    set.add_mesh(TriangleMesh::new(&Transform::IDENTITY, m, false).unwrap());
    let accel = Accel::build(set.clone());
    check_structure(accel.bvh(), &boxes_of(&set));
    let r = Ray::new(Point3::new(0.2, 0.2, -1.0), Vec3::Z);
    assert!((accel.intersect(&r, f32::INFINITY).unwrap().surface.t - 1.0).abs() < 1e-6);
    let empty = Accel::build(ShapeSet::new());
    assert!(empty.intersect(&r, f32::INFINITY).is_none() && !empty.intersect_p(&r, f32::INFINITY));
    assert_eq!(empty.stats().nodes, 0);
}

#[test]
fn closest_hit_equals_brute_force_on_a_real_ply() {
    let path = shared_scenes::dir().join("bmw-m6/geometry/mesh_00004.ply");
    if !path.exists() {
        shared_scenes::skip(&format!("{} is absent", path.display()));
        return;
    }
    let data = read_ply(&path).unwrap();
    let mut set = ShapeSet::new();
    set.add_mesh(TriangleMesh::new(&Transform::IDENTITY, data, false).unwrap());
    let accel = Accel::build(set.clone());
    check_structure(accel.bvh(), &boxes_of(&set));
    let (c, r) = accel.bounds().bounding_sphere();
    let mut rng = Rng::new(9);
    let rays: Vec<Ray> = (0..2000)
        .map(|_| {
            // Aim at a random point of a random triangle, from outside.
            let o = c + rng.dir() * (1.2 * r);
            let mesh = &set.meshes[0];
            let tri = (rng.next_u64() % mesh.len() as u64) as usize;
            let target = mesh.sample(tri, rng.p2()).map_or(c, |s| s.p);
            Ray::new(o, (target - o).normalize())
        })
        .collect();
    let hits = check(&set, &accel, &rays, f32::INFINITY);
    assert!(hits > 1500, "{hits}");
}

#[test]
fn images_are_bit_identical_with_every_lane_set() {
    // The widest lanes this CPU has (AVX2 on x86-64-v3) against the
    // portable ones: the same image, bit for bit. (On a CPU without AVX2
    // both are portable and the test only checks determinism.)
    let (scene, view) = cornell_box([48, 32]).unwrap();
    let opts = RenderOptions {
        threads: Some(2),
        ..RenderOptions::new(SamplerName::ZSobol, 3, 8)
    };
    let bits = |scene| {
        let out = render(scene, &view, &opts, &NoProgress).unwrap();
        (out.image.pixels().iter())
            .flat_map(|c| c.map(f32::to_bits))
            .collect::<Vec<u32>>()
    };
    let widest = bits(&scene);
    let portable = bits(&scene.clone().with_lanes(LaneSet::Portable));
    assert_eq!(widest, portable, "lanes {}", LaneSet::detect().name());
    assert!(widest.iter().any(|&b| b != 0));
}
