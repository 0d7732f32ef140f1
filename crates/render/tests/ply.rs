//! PLY reading: known values from hand-written files; errors, never panics.

mod common;

use lowdisc_render::Error;
use lowdisc_render::geometry::MeshData;
use lowdisc_render::math::{Point2, Point3, Vec3};
use lowdisc_render::mesh::{parse_ply, read_ply};
use std::path::Path;

const ASCII: &str = "ply
format ascii 1.0
comment a quad and a triangle
element vertex 5
property float x
property float y
property float z
property float nx
property float ny
property float nz
property float s
property float t
element material 1
property list uchar float rgb
element face 2
property list uchar int vertex_indices
property int face_indices
end_header
0 0 0 0 0 1 0 0
1 0 0 0 0 1 1 0
1 1 0 0 0 1 1 1
0 1 0 0 0 1 0 1
0.5 0.5 2.5 1 0 0 0.5 0.5
3 0.1 0.2 0.3
4 0 1 2 3 7
3 0 1 4 8
";

fn expected() -> MeshData {
    MeshData {
        positions: vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::new(0.5, 0.5, 2.5),
        ],
        indices: vec![[0, 1, 2], [0, 2, 3], [0, 1, 4]],
        normals: Some(vec![Vec3::Z, Vec3::Z, Vec3::Z, Vec3::Z, Vec3::X]),
        uvs: Some(vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 0.0),
            Point2::new(1.0, 1.0),
            Point2::new(0.0, 1.0),
            Point2::new(0.5, 0.5),
        ]),
    }
}

fn assert_mesh_eq(a: &MeshData, b: &MeshData) {
    assert_eq!(a.positions, b.positions);
    assert_eq!(a.indices, b.indices);
    assert_eq!(a.normals, b.normals);
    assert_eq!(a.uvs, b.uvs);
}

/// The same mesh as `ASCII`, in binary (vertex props: float xyz, double
/// normals, float uv; list counts uchar, indices uint; face_indices short).
fn binary(big: bool) -> Vec<u8> {
    let fmt = if big {
        "binary_big_endian"
    } else {
        "binary_little_endian"
    };
    let mut v = format!(
        "ply\nformat {fmt} 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n\
         property double nx\nproperty double ny\nproperty double nz\nproperty float u\nproperty float v\n\
         element face 2\nproperty list uchar uint vertex_indices\nproperty short face_indices\nend_header\n"
    )
    .into_bytes();
    let e = expected();
    macro_rules! put {
        ($x:expr) => {
            if big {
                v.extend_from_slice(&$x.to_be_bytes())
            } else {
                v.extend_from_slice(&$x.to_le_bytes())
            }
        };
    }
    for i in 0..5 {
        let (p, n, uv) = (
            e.positions[i],
            e.normals.as_ref().unwrap()[i],
            e.uvs.as_ref().unwrap()[i],
        );
        for c in [p.x, p.y, p.z] {
            put!(c);
        }
        for c in [n.x, n.y, n.z] {
            put!(c as f64);
        }
        put!(uv.x);
        put!(uv.y);
    }
    for (face, id) in [(&[0u32, 1, 2, 3][..], 7i16), (&[0, 1, 4][..], 8)] {
        v.push(face.len() as u8);
        for &k in face {
            put!(k);
        }
        put!(id);
    }
    v
}

#[test]
fn ascii_and_binary_parse_to_known_values() {
    let p = Path::new("tiny.ply");
    assert_mesh_eq(&parse_ply(ASCII.as_bytes(), p).unwrap(), &expected());
    assert_mesh_eq(&parse_ply(&binary(false), p).unwrap(), &expected());
    assert_mesh_eq(&parse_ply(&binary(true), p).unwrap(), &expected());
    // CRLF line ends in the header are accepted.
    let crlf = ASCII.replace('\n', "\r\n");
    assert_mesh_eq(&parse_ply(crlf.as_bytes(), p).unwrap(), &expected());
}

#[test]
fn every_truncation_is_an_error_naming_the_file() {
    let p = Path::new("cut.ply");
    for big in [false, true] {
        let full = binary(big);
        for len in 0..full.len() {
            match parse_ply(&full[..len], p) {
                Err(e @ Error::Ply { .. }) => assert!(e.to_string().contains("cut.ply"), "{e}"),
                other => panic!("prefix {len}: expected a PLY error, got {other:?}"),
            }
        }
    }
    // ASCII truncated inside the face list.
    let cut = &ASCII[..ASCII.len() - 6];
    assert!(parse_ply(cut.as_bytes(), p).is_err());
}

#[test]
fn malformed_files_are_errors() {
    let p = Path::new("bad.ply");
    let bad = [
        ASCII.replace("ply\n", "plx\n"),
        ASCII.replace("ascii", "utf8"),
        ASCII.replace("end_header", "end_headr"),
        ASCII.replace("property float x\n", "property quad x\n"),
        ASCII.replace("element vertex 5\n", "property float w\nelement vertex 5\n"),
        ASCII.replace("3 0 1 4 8", "3 0 1 5 8"),
        ASCII.replace("3 0 1 4 8", "2 0 1 8"),
        ASCII.replace("3 0 1 4 8", "3 0 -1 4 8"),
        ASCII.replace("0.5 0.5 2.5", "0.5 nan 2.5"),
        ASCII.replace("0.5 0.5 2.5", "0.5 abc 2.5"),
        ASCII.replace("property float y\n", ""),
        ASCII.replace("element vertex 5", "element vertex 99999999999"),
    ];
    for (i, text) in bad.iter().enumerate() {
        let r = parse_ply(text.as_bytes(), p);
        assert!(matches!(r, Err(Error::Ply { .. })), "case {i}: {r:?}");
    }
    let e = read_ply("/nonexistent/dir/x.ply").unwrap_err();
    assert!(matches!(e, Error::Io { .. }) && e.to_string().contains("/nonexistent/dir/x.ply"));
}

#[test]
fn truncated_copies_of_a_real_ply_give_errors() {
    let src = shared_scenes::dir().join("bmw-m6/geometry/mesh_00001.ply");
    if !src.exists() {
        shared_scenes::skip(&format!("{} is absent", src.display()));
        return;
    }
    let full = std::fs::read(&src).unwrap();
    let m = read_ply(&src).unwrap();
    assert!(!m.positions.is_empty() && !m.indices.is_empty());
    assert!(m.normals.is_some());
    let dir = std::env::temp_dir().join(format!("lowdisc-render-ply-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (k, len) in [
        0,
        10,
        100,
        250,
        full.len() / 3,
        full.len() / 2,
        full.len() - 1,
    ]
    .into_iter()
    .enumerate()
    {
        let path = dir.join(format!("truncated-{k}.ply"));
        std::fs::write(&path, &full[..len]).unwrap();
        let e = read_ply(&path).unwrap_err();
        assert!(e.to_string().contains(&format!("truncated-{k}.ply")), "{e}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bmw_m6_loads_with_pinned_counts() {
    let dir = shared_scenes::dir().join("bmw-m6/geometry");
    let Ok(rd) = std::fs::read_dir(&dir) else {
        shared_scenes::skip(&format!("{} is absent", dir.display()));
        return;
    };
    let mut files: Vec<_> = rd.filter_map(|e| e.ok().map(|e| e.path())).collect();
    files.retain(|p| p.extension().is_some_and(|e| e == "ply"));
    let (mut tris, mut with_normals, mut with_uvs) = (0usize, 0usize, 0usize);
    for f in &files {
        let m = read_ply(f).unwrap();
        tris += m.indices.len();
        with_normals += m.normals.is_some() as usize;
        with_uvs += m.uvs.is_some() as usize;
    }
    // Pinned from the scene as shipped: a change means the loader changed.
    assert_eq!((files.len(), tris), (114, 792_746));
    assert!(with_normals > 0 && with_uvs > 0);
}
