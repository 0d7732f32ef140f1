//! pbrt's `bilinearmesh`, converted to triangles.
//!
//! Each patch `(p00, p10, p01, p11)` becomes the two triangles
//! `(p00, p10, p01)` and `(p10, p11, p01)`, whose face normals agree with the
//! patch normal `∂p/∂u × ∂p/∂v`. This is exact for planar patches (every
//! bilinear mesh in the reference scenes is planar: area-light quads) and an
//! approximation for twisted ones. Without given uvs, each patch gets its own
//! four vertices with uvs `(0,0) (1,0) (0,1) (1,1)`, so texture lookups see
//! pbrt's per-patch parameterisation.

use super::triangle::MeshData;
use crate::error::Error;
use crate::math::{Normal3, Point2, Point3};

/// Converts a bilinear patch mesh (`indices`: four per patch, in pbrt's order
/// `p00 p10 p01 p11`) to triangle-mesh data.
pub fn bilinear_to_triangles(
    positions: &[Point3],
    indices: &[u32],
    normals: Option<&[Normal3]>,
    uvs: Option<&[Point2]>,
) -> Result<MeshData, Error> {
    if indices.len() % 4 != 0 {
        return Err(Error::InvalidShape(format!(
            "bilinearmesh: {} indices is not a multiple of 4",
            indices.len()
        )));
    }
    let n = positions.len();
    if let Some(bad) = indices.iter().find(|&&i| i as usize >= n) {
        return Err(Error::InvalidShape(format!(
            "bilinearmesh: index {bad} out of range ({n} vertices)"
        )));
    }
    if normals.is_some_and(|v| v.len() != n) || uvs.is_some_and(|v| v.len() != n) {
        return Err(Error::InvalidShape(
            "bilinearmesh: attribute count differs from vertex count".into(),
        ));
    }
    let patches = indices.chunks_exact(4);
    if uvs.is_some() {
        let tris = patches
            .flat_map(|q| [[q[0], q[1], q[2]], [q[1], q[3], q[2]]])
            .collect();
        return Ok(MeshData {
            positions: positions.to_vec(),
            indices: tris,
            normals: normals.map(<[_]>::to_vec),
            uvs: uvs.map(<[_]>::to_vec),
        });
    }
    let corner_uv = [
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 0.0),
        Point2::new(0.0, 1.0),
        Point2::new(1.0, 1.0),
    ];
    let mut out = MeshData {
        normals: normals.map(|_| Vec::with_capacity(indices.len())),
        uvs: Some(Vec::with_capacity(indices.len())),
        ..Default::default()
    };
    for (k, q) in patches.enumerate() {
        let base = (4 * k) as u32;
        for (c, &vi) in q.iter().enumerate() {
            out.positions.push(positions[vi as usize]);
            if let (Some(dst), Some(src)) = (out.normals.as_mut(), normals) {
                dst.push(src[vi as usize]);
            }
            if let Some(dst) = out.uvs.as_mut() {
                dst.push(corner_uv[c]);
            }
        }
        out.indices.push([base, base + 1, base + 2]);
        out.indices.push([base + 1, base + 3, base + 2]);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quad_becomes_two_triangles_with_patch_normal() {
        let p = [
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(2.0, 0.0, 0.0),
            Point3::new(0.0, 3.0, 0.0),
            Point3::new(2.0, 3.0, 0.0),
        ];
        let m = bilinear_to_triangles(&p, &[0, 1, 2, 3], None, None).unwrap();
        assert_eq!(m.indices.len(), 2);
        let mut area = 0.0;
        for t in &m.indices {
            let [a, b, c] = t.map(|i| m.positions[i as usize]);
            let n = (a - c).cross(b - c);
            assert!(n.z > 0.0, "patch normal is +z");
            area += 0.5 * n.length();
        }
        assert_eq!(area, 6.0);
        assert_eq!(m.uvs.unwrap()[3], Point2::new(1.0, 1.0));
        assert!(bilinear_to_triangles(&p, &[0, 1, 2], None, None).is_err());
        assert!(bilinear_to_triangles(&p, &[0, 1, 2, 4], None, None).is_err());
    }
}
