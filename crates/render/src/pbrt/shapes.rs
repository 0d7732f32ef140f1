//! `Shape` directives: triangle meshes, PLY meshes, spheres, disks, bilinear
//! patch meshes and Loop subdivision surfaces, with their material and area
//! light.

use super::loader::{PbrtLoader, ShapeDef};
use super::state::{AreaSpec, MatRef};
use crate::bsdf::Material;
use crate::geometry::{
    Disk, MeshData, Sphere, TriangleMesh, bilinear_to_triangles, loop_subdivide,
};
use crate::light::diffuse_power_scale;
use crate::math::{Normal3, Point2, Point3, Transform, Vec3};
use crate::medium::MediumInterface;
use crate::scene::{Emission, INTERFACE};
use crate::spectrum::Rgb;
use crate::texture::FloatTexture;
use pbrt_format::{FloatOrTexture, Loc, ParamSet, ParseError, TargetResult};

/// A built shape before it goes to the scene builder.
enum Built {
    Mesh(TriangleMesh),
    Sphere(Sphere),
    Disk(Disk),
}

fn p3s(v: Vec<[f64; 3]>) -> Vec<Point3> {
    v.into_iter()
        .map(|a| Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32))
        .collect()
}

fn indices(ps: &ParamSet, loc: &Loc, ty: &str) -> Result<Option<Vec<u32>>, ParseError> {
    let Some(ix) = ps.get_ints("indices") else {
        return Ok(None);
    };
    ix.iter()
        .map(|&i| {
            u32::try_from(i)
                .map_err(|_| ParseError::scene(loc, format!("{ty}: vertex index {i} out of range")))
        })
        .collect::<Result<Vec<_>, _>>()
        .map(Some)
}

fn positions(ps: &ParamSet, loc: &Loc, ty: &str) -> Result<Vec<Point3>, ParseError> {
    ps.get_point3s("P")
        .map(p3s)
        .filter(|p| !p.is_empty())
        .ok_or_else(|| ParseError::scene(loc, format!("{ty}: \"point3 P\" is required")))
}

fn normals(ps: &ParamSet) -> Option<Vec<Normal3>> {
    ps.get_normals("N").map(p3s).filter(|n| !n.is_empty())
}

fn uvs(ps: &ParamSet) -> Option<Vec<Point2>> {
    ps.get_point2s("uv")
        .map(|v| {
            v.into_iter()
                .map(|a| Point2::new(a[0] as f32, a[1] as f32))
                .collect()
        })
        .filter(|v: &Vec<Point2>| !v.is_empty())
}

fn triangles(ix: Vec<u32>, loc: &Loc, ty: &str) -> Result<Vec<[u32; 3]>, ParseError> {
    if ix.len() % 3 != 0 {
        return Err(ParseError::scene(
            loc,
            format!("{ty}: {} indices is not a multiple of 3", ix.len()),
        ));
    }
    Ok(ix.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect())
}

impl PbrtLoader {
    fn mesh_data(&mut self, def: &ShapeDef) -> Result<Option<MeshData>, ParseError> {
        let (ps, loc, ty) = (&def.params, &def.loc, def.ty.as_str());
        let geo = |e: crate::Error| ParseError::scene(loc, format!("{ty}: {e}"));
        Ok(Some(match ty {
            "trianglemesh" => {
                let positions = positions(ps, loc, ty)?;
                let ix = match indices(ps, loc, ty)? {
                    Some(ix) => ix,
                    None if positions.len() == 3 => vec![0, 1, 2],
                    None => {
                        return Err(ParseError::scene(
                            loc,
                            "trianglemesh: \"integer indices\" is required",
                        ));
                    }
                };
                MeshData {
                    positions,
                    indices: triangles(ix, loc, ty)?,
                    normals: normals(ps),
                    uvs: uvs(ps),
                }
            }
            "plymesh" => {
                let name = ps.get_string("filename").ok_or_else(|| {
                    ParseError::scene(loc, "plymesh: \"string filename\" is required")
                })?;
                let path = self.resolve(name);
                crate::mesh::read_ply(&path).map_err(geo)?
            }
            "bilinearmesh" => {
                let positions = positions(ps, loc, ty)?;
                let ix = match indices(ps, loc, ty)? {
                    Some(ix) => ix,
                    None if positions.len() == 4 => vec![0, 1, 2, 3],
                    None => {
                        return Err(ParseError::scene(
                            loc,
                            "bilinearmesh: \"integer indices\" is required",
                        ));
                    }
                };
                let n = normals(ps);
                let uv = uvs(ps);
                bilinear_to_triangles(&positions, &ix, n.as_deref(), uv.as_deref()).map_err(geo)?
            }
            "loopsubdiv" => {
                let levels = ps.int_or("levels", 3);
                let levels = u32::try_from(levels).map_err(|_| {
                    ParseError::scene(loc, format!("loopsubdiv: levels {levels} < 0"))
                })?;
                let positions = positions(ps, loc, ty)?;
                let ix = indices(ps, loc, ty)?.ok_or_else(|| {
                    ParseError::scene(loc, "loopsubdiv: \"integer indices\" is required")
                })?;
                loop_subdivide(&positions, &ix, levels).map_err(geo)?
            }
            _ => return Ok(None),
        }))
    }

    fn build_shape(&mut self, def: &ShapeDef, ctm: Transform) -> Result<Option<Built>, ParseError> {
        let (ps, loc) = (&def.params, &def.loc);
        let bad = |what: &str, e: crate::Error| ParseError::scene(loc, format!("{what}: {e}"));
        match def.ty.as_str() {
            "sphere" => {
                let r = ps.float_or("radius", 1.0) as f32;
                Sphere::new(ctm, r, def.reverse)
                    .map(|s| Some(Built::Sphere(s)))
                    .map_err(|e| bad("sphere", e))
            }
            "disk" => {
                let h = ps.float_or("height", 0.0) as f32;
                let r = ps.float_or("radius", 1.0) as f32;
                let ri = ps.float_or("innerradius", 0.0) as f32;
                Disk::new(ctm, h, r, ri, def.reverse)
                    .map(|d| Some(Built::Disk(d)))
                    .map_err(|e| bad("disk", e))
            }
            _ => match self.mesh_data(def)? {
                Some(data) => TriangleMesh::new(&ctm, data, def.reverse)
                    .map(|m| Some(Built::Mesh(m)))
                    .map_err(|e| bad(&def.ty, e)),
                None => Ok(None),
            },
        }
    }

    /// The scene material index for `m`, or `None` for `interface`.
    fn material_index(&mut self, m: MatRef) -> Option<u32> {
        match m {
            MatRef::Index(i) => Some(i),
            MatRef::Interface => None,
            MatRef::Default => Some(*self.default_material.get_or_insert_with(|| {
                self.counts.materials += 1;
                self.builder
                    .add_material(Material::diffuse(Rgb::splat(0.5)))
            })),
        }
    }

    /// The shape's alpha cut-out (`"alpha"`: a float texture, or a
    /// constant below 1; `None` when opaque). On an area light it is not
    /// supported: light sampling would ignore it.
    fn shape_alpha(
        &mut self,
        def: &ShapeDef,
        emissive: bool,
    ) -> Result<Option<FloatTexture>, ParseError> {
        let ps = &def.params;
        let alpha = match ps.get_float_or_texture("alpha") {
            None => return Ok(None),
            Some(FloatOrTexture::Value(v)) if v >= 1.0 => return Ok(None),
            Some(_) => self.float_tex(ps, "alpha", 1.0.into(), &def.loc)?,
        };
        if emissive {
            let what = format!(
                "alpha cut-out on an area light ({} parameter \"alpha\")",
                def.ty
            );
            let at = ps.find("alpha").map_or(&def.loc, |p| &p.loc).clone();
            self.approximated(&at, &what, "the light emits from the whole shape")?;
        }
        Ok(Some(alpha))
    }

    /// Shape parameters lowdisc lacks: image area lights
    /// (`emissionfilename`) and displacement (`loopsubdiv`).
    fn unsupported_shape_params(&mut self, def: &ShapeDef) -> Result<(), ParseError> {
        let ps = &def.params;
        let missing = [
            (
                "emissionfilename",
                "image area light",
                "the light's \"L\" is used",
            ),
            (
                "displacement",
                "displacement",
                "the surface is not displaced",
            ),
        ];
        for (name, feature, instead) in missing {
            let Some(p) = ps.find(name) else { continue };
            ps.mark_used(name);
            let what = format!("{feature} ({} parameter \"{name}\")", def.ty);
            let at = p.loc.clone();
            self.approximated(&at, &what, instead)?;
        }
        Ok(())
    }

    /// Creates the shape of `def` with object-to-world `ctm` and adds it to
    /// the scene with its material and (optional) area light.
    pub(super) fn create_shape(
        &mut self,
        def: &ShapeDef,
        ctm: Transform,
        area: Option<&AreaSpec>,
    ) -> TargetResult {
        let loc = def.loc.clone();
        let Some(built) = self.build_shape(def, ctm)? else {
            let what = format!("Shape \"{}\"", def.ty);
            self.approximated(&loc, &what, "the shape is left out")?;
            def.params
                .into_iter()
                .for_each(pbrt_format::Param::mark_used);
            return Ok(());
        };
        self.unsupported_shape_params(def)?;
        let alpha = self.shape_alpha(def, area.is_some())?;
        def.params
            .finish(&format!("Shape \"{}\"", def.ty), &mut self.warnings)?;
        let material = match self.material_index(def.material) {
            Some(m) => m,
            // A medium boundary: kept where the medium changes across it.
            None if def.media.is_transition() => INTERFACE,
            None => {
                self.warnings.warn_once(
                    &loc,
                    "shapes with the \"interface\" material and no medium transition are skipped",
                );
                return Ok(());
            }
        };
        let emission = area.map(|a| {
            let mut l = a.l;
            if let Some(p) = a.power {
                let total = match &built {
                    Built::Mesh(m) => (0..m.len()).map(|i| m.area(i)).sum(),
                    Built::Sphere(s) => s.area(),
                    Built::Disk(d) => d.area(),
                };
                l *= diffuse_power_scale(a.l, p, total, a.two_sided);
            }
            Emission {
                l,
                two_sided: a.two_sided,
            }
        });
        if emission.is_some() {
            self.counts.area_shapes += 1;
        }
        self.builder
            .set_emission_spectrum(area.and_then(|a| a.spectrum.clone()));
        self.builder.set_shape_alpha(alpha);
        self.builder.set_medium_interface(def.media);
        match built {
            Built::Mesh(m) => {
                self.counts.triangles += m.len();
                self.builder.add_mesh(m, material, emission);
            }
            Built::Sphere(s) => {
                self.counts.spheres += 1;
                self.builder.add_sphere(s, material, emission);
            }
            Built::Disk(d) => {
                self.counts.disks += 1;
                self.builder.add_disk(d, material, emission);
            }
        }
        self.builder.set_emission_spectrum(None);
        self.builder.set_shape_alpha(None);
        self.builder
            .set_medium_interface(MediumInterface::default());
        Ok(())
    }
}
