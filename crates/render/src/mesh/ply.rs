//! A small, strict PLY reader (ASCII, binary little- and big-endian).
//!
//! Reads the `vertex` element's `x y z`, optional `nx ny nz` and optional
//! texture coordinates (`u v`, `s t`, `texture_u texture_v` or
//! `texture_s texture_t`), and the `face` element's `vertex_indices` (or
//! `vertex_index`) lists: triangles as is, quads split along `v0-v2`, larger
//! polygons fanned from `v0`. Other elements and properties are skipped.
//! Every defect (truncation, bad header, index out of range, a face of fewer
//! than three vertices) is an [`Error::Ply`] naming the file; nothing panics.
//!
//! Written for this crate rather than using `ply-rs`-style generic readers:
//! it decodes straight into flat arrays (no per-element maps), which keeps
//! loading the ~800k-triangle bmw-m6 scene to tens of milliseconds, and it
//! controls every error path.

use crate::error::Error;
use crate::geometry::MeshData;
use crate::math::{Point2, Vec3};
use std::path::{Path, PathBuf};

#[derive(Clone, Copy, Debug, PartialEq)]
enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn parse(s: &str) -> Option<Scalar> {
        Some(match s {
            "char" | "int8" => Scalar::I8,
            "uchar" | "uint8" => Scalar::U8,
            "short" | "int16" => Scalar::I16,
            "ushort" | "uint16" => Scalar::U16,
            "int" | "int32" => Scalar::I32,
            "uint" | "uint32" => Scalar::U32,
            "float" | "float32" => Scalar::F32,
            "double" | "float64" => Scalar::F64,
            _ => return None,
        })
    }
    fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }
}

#[derive(Debug)]
enum Kind {
    Scalar(Scalar),
    List(Scalar, Scalar),
}

#[derive(Debug)]
struct Property {
    name: String,
    kind: Kind,
}

#[derive(Debug)]
struct Element {
    name: String,
    count: usize,
    props: Vec<Property>,
}

#[derive(Clone, Copy, PartialEq, Debug)]
enum Format {
    Ascii,
    Le,
    Be,
}

/// Source of property values: binary cursor or ASCII tokens.
enum Body<'a> {
    Binary {
        data: &'a [u8],
        pos: usize,
        big: bool,
    },
    Ascii(std::str::SplitAsciiWhitespace<'a>),
}

impl Body<'_> {
    #[inline]
    fn read(&mut self, t: Scalar) -> Option<f64> {
        match self {
            Body::Binary { data, pos, big } => {
                let n = t.size();
                let bytes = data.get(*pos..*pos + n)?;
                *pos += n;
                let mut b = [0u8; 8];
                b[..n].copy_from_slice(bytes);
                if *big {
                    b[..n].reverse();
                }
                Some(match t {
                    Scalar::I8 => b[0] as i8 as f64,
                    Scalar::U8 => b[0] as f64,
                    Scalar::I16 => i16::from_le_bytes([b[0], b[1]]) as f64,
                    Scalar::U16 => u16::from_le_bytes([b[0], b[1]]) as f64,
                    Scalar::I32 => i32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
                    Scalar::U32 => u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
                    Scalar::F32 => f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
                    Scalar::F64 => f64::from_le_bytes(b),
                })
            }
            Body::Ascii(it) => it.next()?.parse::<f64>().ok(),
        }
    }
    fn remaining_hint(&self) -> usize {
        match self {
            Body::Binary { data, pos, .. } => data.len().saturating_sub(*pos),
            Body::Ascii(_) => usize::MAX,
        }
    }
}

fn err(path: &Path, message: impl Into<String>) -> Error {
    Error::Ply {
        path: path.to_path_buf(),
        message: message.into(),
    }
}

/// Reads a PLY file into object-space mesh data.
pub fn read_ply(path: impl AsRef<Path>) -> Result<MeshData, Error> {
    let path = path.as_ref();
    let bytes = lowdisc_files::read_input(path).map_err(|e| Error::Io {
        path: PathBuf::from(path),
        source: std::io::Error::new(e.io_error().kind(), e.io_error().to_string()),
    })?;
    parse_ply(&bytes, path)
}

fn parse_header(bytes: &[u8], path: &Path) -> Result<(Format, Vec<Element>, usize), Error> {
    if !bytes.starts_with(b"ply\n") && !bytes.starts_with(b"ply\r\n") {
        return Err(err(path, "missing 'ply' magic line"));
    }
    const END: &[u8] = b"end_header";
    let end = bytes
        .windows(END.len())
        .position(|w| w == END)
        .ok_or_else(|| err(path, "header has no 'end_header' (truncated?)"))?;
    let mut body = end + END.len();
    while body < bytes.len() && bytes[body] != b'\n' {
        body += 1;
    }
    body += 1; // past '\n' (may equal len + 1 when truncated; checked below)
    if body > bytes.len() {
        return Err(err(path, "file ends right after 'end_header'"));
    }
    let header = String::from_utf8_lossy(&bytes[..end]);
    let mut format = None;
    let mut elements: Vec<Element> = Vec::new();
    for (ln, line) in header.lines().enumerate().skip(1) {
        let w: Vec<&str> = line.split_ascii_whitespace().collect();
        let bad = |m: &str| {
            err(
                path,
                format!("header line {}: {m}: '{}'", ln + 1, line.trim()),
            )
        };
        match w.first().copied() {
            None | Some("comment") | Some("obj_info") => {}
            Some("format") => {
                format = Some(match w.get(1).copied() {
                    Some("ascii") => Format::Ascii,
                    Some("binary_little_endian") => Format::Le,
                    Some("binary_big_endian") => Format::Be,
                    _ => return Err(bad("unknown format")),
                })
            }
            Some("element") => {
                let (Some(name), Some(count)) =
                    (w.get(1), w.get(2).and_then(|c| c.parse::<usize>().ok()))
                else {
                    return Err(bad("malformed element"));
                };
                elements.push(Element {
                    name: name.to_string(),
                    count,
                    props: Vec::new(),
                });
            }
            Some("property") => {
                let el = elements
                    .last_mut()
                    .ok_or_else(|| bad("property before any element"))?;
                let prop = match w.as_slice() {
                    [_, "list", c, i, name] => {
                        let (Some(c), Some(i)) = (Scalar::parse(c), Scalar::parse(i)) else {
                            return Err(bad("unknown list type"));
                        };
                        Property {
                            name: name.to_string(),
                            kind: Kind::List(c, i),
                        }
                    }
                    [_, t, name] => {
                        let t = Scalar::parse(t).ok_or_else(|| bad("unknown property type"))?;
                        Property {
                            name: name.to_string(),
                            kind: Kind::Scalar(t),
                        }
                    }
                    _ => return Err(bad("malformed property")),
                };
                el.props.push(prop);
            }
            Some(_) => return Err(bad("unknown header keyword")),
        }
    }
    let format = format.ok_or_else(|| err(path, "header has no 'format' line"))?;
    Ok((format, elements, body))
}

/// What a vertex property feeds.
#[derive(Clone, Copy, PartialEq)]
enum Role {
    Pos(usize),
    Normal(usize),
    Uv(usize),
    Skip,
}

fn vertex_roles(el: &Element) -> Vec<Role> {
    let find = |names: &[&str]| {
        el.props
            .iter()
            .position(|p| names.contains(&p.name.as_str()))
    };
    let mut roles = vec![Role::Skip; el.props.len()];
    let mut assign = |groups: &[&[&str]], make: fn(usize) -> Role| {
        let found: Vec<Option<usize>> = groups.iter().map(|g| find(g)).collect();
        if found.iter().all(Option::is_some) {
            for (k, i) in found.into_iter().enumerate() {
                roles[i.unwrap_or_default()] = make(k);
            }
        }
    };
    assign(&[&["x"], &["y"], &["z"]], Role::Pos);
    assign(&[&["nx"], &["ny"], &["nz"]], Role::Normal);
    assign(
        &[
            &["u", "s", "texture_u", "texture_s"],
            &["v", "t", "texture_v", "texture_t"],
        ],
        Role::Uv,
    );
    roles
}

fn skip_prop(body: &mut Body, kind: &Kind) -> Option<()> {
    match *kind {
        Kind::Scalar(t) => {
            body.read(t)?;
        }
        Kind::List(c, t) => {
            let n = body.read(c)?;
            if !(n >= 0.0 && n.fract() == 0.0) {
                return None;
            }
            for _ in 0..n as usize {
                body.read(t)?;
            }
        }
    }
    Some(())
}

/// Parses PLY data (`path` is only used in error messages).
pub fn parse_ply(bytes: &[u8], path: &Path) -> Result<MeshData, Error> {
    let (format, elements, start) = parse_header(bytes, path)?;
    let mut body = match format {
        Format::Ascii => {
            let text = std::str::from_utf8(&bytes[start..])
                .map_err(|_| err(path, "ASCII body is not text"))?;
            Body::Ascii(text.split_ascii_whitespace())
        }
        _ => Body::Binary {
            data: &bytes[start..],
            pos: 0,
            big: format == Format::Be,
        },
    };
    let mut mesh = MeshData::default();
    let mut have_vertices = false;
    for el in &elements {
        // Never trust the count for allocation beyond what the data can hold.
        let cap = el.count.min(body.remaining_hint() / 4 + 1).min(1 << 24);
        let eof = |i: usize| {
            err(
                path,
                format!(
                    "unexpected end of data in element '{}' (item {i} of {})",
                    el.name, el.count
                ),
            )
        };
        match el.name.as_str() {
            "vertex" => {
                let roles = vertex_roles(el);
                if !roles.iter().any(|r| matches!(r, Role::Pos(_))) {
                    return Err(err(path, "vertex element lacks x, y, z"));
                }
                let has_n = roles.iter().any(|r| matches!(r, Role::Normal(_)));
                let has_uv = roles.iter().any(|r| matches!(r, Role::Uv(_)));
                let mut normals = Vec::with_capacity(if has_n { cap } else { 0 });
                let mut uvs = Vec::with_capacity(if has_uv { cap } else { 0 });
                mesh.positions.reserve(cap);
                for i in 0..el.count {
                    let (mut p, mut n, mut uv) = ([0f32; 3], [0f32; 3], [0f32; 2]);
                    for (prop, role) in el.props.iter().zip(&roles) {
                        match (role, &prop.kind) {
                            (Role::Skip, k) | (_, k @ Kind::List(..)) => {
                                skip_prop(&mut body, k).ok_or_else(|| eof(i))?
                            }
                            (r, Kind::Scalar(t)) => {
                                let v = body.read(*t).ok_or_else(|| eof(i))? as f32;
                                match *r {
                                    Role::Pos(a) => p[a] = v,
                                    Role::Normal(a) => n[a] = v,
                                    Role::Uv(a) => uv[a] = v,
                                    Role::Skip => {}
                                }
                            }
                        }
                    }
                    mesh.positions.push(Vec3::from_array(p));
                    if has_n {
                        normals.push(Vec3::from_array(n));
                    }
                    if has_uv {
                        uvs.push(Point2::new(uv[0], uv[1]));
                    }
                }
                mesh.normals = has_n.then_some(normals);
                mesh.uvs = has_uv.then_some(uvs);
                have_vertices = true;
            }
            "face" => {
                let idx_prop = el.props.iter().position(|p| {
                    matches!(p.kind, Kind::List(..))
                        && (p.name == "vertex_indices" || p.name == "vertex_index")
                });
                let idx_prop = idx_prop
                    .ok_or_else(|| err(path, "face element lacks a vertex_indices list"))?;
                mesh.indices.reserve(cap);
                let mut poly: Vec<u32> = Vec::with_capacity(8);
                for i in 0..el.count {
                    for (k, prop) in el.props.iter().enumerate() {
                        if k != idx_prop {
                            skip_prop(&mut body, &prop.kind).ok_or_else(|| eof(i))?;
                            continue;
                        }
                        let Kind::List(ct, it) = prop.kind else {
                            unreachable!("checked above")
                        };
                        let n = body.read(ct).ok_or_else(|| eof(i))?;
                        if !(n >= 3.0 && n.fract() == 0.0 && n <= 65536.0) {
                            return Err(err(
                                path,
                                format!("face {i} has {n} vertices (need at least 3)"),
                            ));
                        }
                        poly.clear();
                        for _ in 0..n as usize {
                            let v = body.read(it).ok_or_else(|| eof(i))?;
                            if !(v >= 0.0 && v.fract() == 0.0 && v <= u32::MAX as f64) {
                                return Err(err(
                                    path,
                                    format!("face {i} has invalid vertex index {v}"),
                                ));
                            }
                            poly.push(v as u32);
                        }
                        for j in 1..poly.len() - 1 {
                            mesh.indices.push([poly[0], poly[j], poly[j + 1]]);
                        }
                    }
                }
            }
            _ => {
                for i in 0..el.count {
                    for prop in &el.props {
                        skip_prop(&mut body, &prop.kind).ok_or_else(|| eof(i))?;
                    }
                }
            }
        }
    }
    if !have_vertices {
        return Err(err(path, "no vertex element"));
    }
    let nv = mesh.positions.len();
    if let Some(bad) = mesh.indices.iter().flatten().find(|&&v| v as usize >= nv) {
        return Err(err(
            path,
            format!("vertex index {bad} out of range ({nv} vertices)"),
        ));
    }
    if mesh.positions.iter().any(|p| !p.is_finite()) {
        return Err(err(path, "non-finite vertex position"));
    }
    Ok(mesh)
}
