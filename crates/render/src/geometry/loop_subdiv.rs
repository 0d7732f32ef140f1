//! Loop subdivision surfaces (pbrt's `loopsubdiv` shape), producing a
//! triangle mesh.
//!
//! Loop's scheme (C. Loop, "Smooth Subdivision Surfaces Based on Triangles",
//! 1987) with the usual boundary rules:
//! * new edge ("odd") vertex: `3/8 (a + b) + 1/8 (c + d)` on an interior edge
//!   with opposite vertices `c, d`; the midpoint on a boundary edge;
//! * old ("even") vertex of valence `n`: `(1 - nβ) v + β Σ neighbours` with
//!   `β = 3/16` for `n = 3` and `3 / (8n)` otherwise (Warren's weights, as
//!   pbrt); on a boundary `3/4 v + 1/8 (b0 + b1)` with its two boundary
//!   neighbours; vertices with another number of boundary edges (corners,
//!   non-manifold) stay put.
//!
//! After the last level every vertex is moved to its limit position, as pbrt
//! does: interior `(1 - nγ) v + γ Σ`, `γ = 1 / (n + 3 / (8β))`; boundary
//! `3/5 v + 1/5 (b0 + b1)`. Edges shared by more than two faces are treated as
//! creases (boundary rules). Vertex normals are the area-weighted averages of
//! the limit mesh's face normals (pbrt instead evaluates limit tangents; the
//! two agree to within the faceting of the final level).

use super::triangle::MeshData;
use crate::error::Error;
use crate::math::{Point3, Vec3};
use std::collections::HashMap;

/// Largest accepted `levels` (each level multiplies the face count by 4).
pub const MAX_LEVELS: u32 = 10;

struct Edge {
    opposite: [u32; 2],
    faces: u32,
    new_vertex: u32,
}

/// Per-vertex neighbourhood sums gathered from the unique edges.
#[derive(Clone, Copy, Default)]
struct Ring {
    valence: u32,
    sum: Vec3,
    boundary: u32,
    boundary_sum: Vec3,
}

fn beta(n: u32) -> f32 {
    if n == 3 {
        3.0 / 16.0
    } else {
        3.0 / (8.0 * n as f32)
    }
}

type EdgeMap = HashMap<(u32, u32), Edge>;

/// The unique edges of `faces` (keyed by sorted endpoints) and their first-seen
/// order, which numbers the new edge vertices from `first_new` on.
fn build_edges(faces: &[[u32; 3]], first_new: u32) -> (EdgeMap, Vec<(u32, u32)>) {
    let mut edges: EdgeMap = HashMap::with_capacity(faces.len() * 2);
    let mut order = Vec::with_capacity(faces.len() * 2);
    for f in faces {
        for k in 0..3 {
            let (a, b, c) = (f[k], f[(k + 1) % 3], f[(k + 2) % 3]);
            let key = (a.min(b), a.max(b));
            let next = first_new + order.len() as u32;
            let e = edges.entry(key).or_insert_with(|| {
                order.push(key);
                Edge {
                    opposite: [c, c],
                    faces: 0,
                    new_vertex: next,
                }
            });
            if e.faces == 1 {
                e.opposite[1] = c;
            }
            e.faces += 1;
        }
    }
    (edges, order)
}

fn rings(n: usize, positions: &[Point3], edges: &EdgeMap, order: &[(u32, u32)]) -> Vec<Ring> {
    let mut rings = vec![Ring::default(); n];
    for key in order {
        let boundary = edges[key].faces != 2;
        for (v, o) in [(key.0, key.1), (key.1, key.0)] {
            let r = &mut rings[v as usize];
            r.valence += 1;
            r.sum += positions[o as usize];
            if boundary {
                r.boundary += 1;
                r.boundary_sum += positions[o as usize];
            }
        }
    }
    rings
}

fn subdivide_once(positions: &[Point3], faces: &[[u32; 3]]) -> (Vec<Point3>, Vec<[u32; 3]>) {
    let n = positions.len();
    let (edges, order) = build_edges(faces, n as u32);
    let rings = rings(n, positions, &edges, &order);
    let mut out: Vec<Point3> = positions
        .iter()
        .zip(&rings)
        .map(|(&v, r)| match r.boundary {
            0 if r.valence > 0 => {
                let b = beta(r.valence);
                v * (1.0 - r.valence as f32 * b) + r.sum * b
            }
            2 => v * 0.75 + r.boundary_sum * 0.125,
            _ => v,
        })
        .collect();
    out.extend(order.iter().map(|key| {
        let e = &edges[key];
        let (a, b) = (positions[key.0 as usize], positions[key.1 as usize]);
        if e.faces == 2 {
            (a + b) * 0.375
                + (positions[e.opposite[0] as usize] + positions[e.opposite[1] as usize]) * 0.125
        } else {
            (a + b) * 0.5
        }
    }));
    let mid = |a: u32, b: u32| edges[&(a.min(b), a.max(b))].new_vertex;
    let mut new_faces = Vec::with_capacity(faces.len() * 4);
    for &[v0, v1, v2] in faces {
        let (e01, e12, e20) = (mid(v0, v1), mid(v1, v2), mid(v2, v0));
        new_faces.extend_from_slice(&[
            [v0, e01, e20],
            [v1, e12, e01],
            [v2, e20, e12],
            [e01, e12, e20],
        ]);
    }
    (out, new_faces)
}

/// Subdivides the control mesh `levels` times, moves vertices to the limit
/// surface and returns the triangle mesh with vertex normals.
pub fn loop_subdivide(
    positions: &[Point3],
    indices: &[u32],
    levels: u32,
) -> Result<MeshData, Error> {
    if indices.len() % 3 != 0 {
        return Err(Error::InvalidShape(
            "loopsubdiv: index count is not a multiple of 3".into(),
        ));
    }
    if levels > MAX_LEVELS {
        return Err(Error::InvalidShape(format!(
            "loopsubdiv: levels {levels} exceeds {MAX_LEVELS}"
        )));
    }
    let n = positions.len();
    if let Some(bad) = indices.iter().find(|&&i| i as usize >= n) {
        return Err(Error::InvalidShape(format!(
            "loopsubdiv: index {bad} out of range ({n} vertices)"
        )));
    }
    if positions.iter().any(|p| !p.is_finite()) {
        return Err(Error::InvalidShape("loopsubdiv: non-finite vertex".into()));
    }
    let mut faces: Vec<[u32; 3]> = indices
        .chunks_exact(3)
        .map(|c| [c[0], c[1], c[2]])
        .collect();
    faces.retain(|f| f[0] != f[1] && f[1] != f[2] && f[2] != f[0]);
    let mut pos = positions.to_vec();
    for _ in 0..levels {
        let (p, f) = subdivide_once(&pos, &faces);
        pos = p;
        faces = f;
    }
    // Push to the limit surface.
    let (edges, order) = build_edges(&faces, pos.len() as u32);
    let rings = rings(pos.len(), &pos, &edges, &order);
    let limit: Vec<Point3> = pos
        .iter()
        .zip(&rings)
        .map(|(&v, r)| match r.boundary {
            0 if r.valence > 0 => {
                let g = 1.0 / (r.valence as f32 + 3.0 / (8.0 * beta(r.valence)));
                v * (1.0 - r.valence as f32 * g) + r.sum * g
            }
            2 => v * 0.6 + r.boundary_sum * 0.2,
            _ => v,
        })
        .collect();
    let mut normals = vec![Vec3::ZERO; limit.len()];
    for f in &faces {
        let [a, b, c] = f.map(|i| limit[i as usize]);
        let fnrm = (b - a).cross(c - a); // length = 2 * area: area weighting
        for &i in f {
            normals[i as usize] += fnrm;
        }
    }
    for nn in &mut normals {
        let l = nn.length();
        *nn = if l > 0.0 { *nn / l } else { Vec3::ZERO };
    }
    Ok(MeshData {
        positions: limit,
        indices: faces,
        normals: Some(normals),
        uvs: None,
    })
}
