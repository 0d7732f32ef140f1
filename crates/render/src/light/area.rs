//! Diffuse area lights on triangles, spheres and disks, sampled uniformly by
//! area and converted to solid angle; a sphere seen from outside is instead
//! sampled uniformly over the cone of directions it subtends (pbrt-v4's
//! `Sphere::Sample(ctx, u)`), falling back to area sampling inside.

use super::error::{check_rgb, check_scalar};
use super::{LightError, LightLiSample, LightSampleContext, luminance_normaliser};
use crate::content_hash::{ContentHash, ContentSink};
use crate::geometry::{Disk, Prim, ShapeSample, ShapeSet, Sphere, intersect_triangle};
use crate::math::sampling::sample_uniform_triangle;
use crate::math::{Normal3, Point2, Point3, Ray, Vec3};
use crate::spectrum::Rgb;
use std::f32::consts::PI;

/// The emitting shape of a [`DiffuseAreaLight`] (a copy of its geometry).
#[derive(Clone, Debug)]
pub enum AreaShape {
    /// One triangle with its oriented unit geometric normal.
    Triangle {
        /// World-space vertices.
        p: [Point3; 3],
        /// Unit geometric normal, oriented as at a ray hit.
        n: Normal3,
    },
    /// A sphere.
    Sphere(Sphere),
    /// A disk (or annulus).
    Disk(Disk),
}

impl AreaShape {
    /// Copies primitive `prim` of `shapes`; errors for a primitive it lacks.
    pub fn from_prim(shapes: &ShapeSet, prim: Prim) -> Result<Self, LightError> {
        Ok(match prim {
            Prim::Triangle { mesh, tri } => {
                let m = shapes
                    .meshes
                    .get(mesh as usize)
                    .filter(|m| (tri as usize) < m.len());
                let m = m.ok_or_else(|| {
                    LightError::InvalidParameter(format!("no primitive {prim:?}"))
                })?;
                // The normal at the centroid carries the mesh's orientation
                // rules. A degenerate triangle (no area: exported meshes
                // have them) keeps a zero normal; it emits no power, so the
                // light sampler never picks it, and no ray can hit it.
                let s = m.sample(tri as usize, Point2::new(4.0 / 9.0, 0.5));
                AreaShape::Triangle {
                    p: m.vertices(tri as usize),
                    n: s.map_or(Normal3::new(0.0, 0.0, 0.0), |s| s.n),
                }
            }
            Prim::Sphere(i) => AreaShape::Sphere(Self::get(&shapes.spheres, i, prim)?),
            Prim::Disk(i) => AreaShape::Disk(Self::get(&shapes.disks, i, prim)?),
        })
    }

    fn get<T: Clone>(v: &[T], i: u32, prim: Prim) -> Result<T, LightError> {
        v.get(i as usize)
            .cloned()
            .ok_or_else(|| LightError::InvalidParameter(format!("no primitive {prim:?}")))
    }

    /// Surface area.
    pub fn area(&self) -> f32 {
        match self {
            AreaShape::Triangle { p, .. } => 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).length(),
            AreaShape::Sphere(s) => s.area(),
            AreaShape::Disk(d) => d.area(),
        }
    }

    /// A point uniformly distributed by area.
    pub fn sample(&self, u: Point2) -> Option<ShapeSample> {
        self.sample_with_area(u, self.area())
    }

    /// [`AreaShape::sample`] given `area = self.area()` (a light keeps it).
    #[inline]
    fn sample_with_area(&self, u: Point2, area: f32) -> Option<ShapeSample> {
        match self {
            AreaShape::Triangle { p, n } => {
                if !(area > 0.0) {
                    return None;
                }
                let b = sample_uniform_triangle(u);
                let q = p[0] * b[0] + p[1] * b[1] + p[2] * b[2];
                Some(ShapeSample {
                    p: q,
                    n: *n,
                    uv: Point2::new(b[1], b[2]),
                    pdf: 1.0 / area,
                })
            }
            AreaShape::Sphere(s) => s.sample(u),
            AreaShape::Disk(d) => d.sample(u),
        }
    }

    /// The nearest intersection of `ray` (`t > 0`) as (point, unit normal).
    pub fn intersect(&self, ray: &Ray) -> Option<(Point3, Normal3)> {
        match self {
            AreaShape::Triangle { p, n } => {
                let h = intersect_triangle(ray, f32::INFINITY, *p)?;
                Some((p[0] * (1.0 - h.u - h.v) + p[1] * h.u + p[2] * h.v, *n))
            }
            AreaShape::Sphere(s) => {
                let h = s.intersect(ray, f32::INFINITY)?;
                let sh = s.surface_hit(ray, &h);
                Some((sh.p, sh.ng))
            }
            AreaShape::Disk(d) => {
                let h = d.intersect(ray, f32::INFINITY)?;
                let sh = d.surface_hit(ray, &h);
                Some((sh.p, sh.ng))
            }
        }
    }
}

/// pbrt-v4's `AreaLightSource "diffuse"`: radiance `L * scale` leaving the
/// front side of a shape (both sides when `two_sided`).
#[derive(Clone, Debug)]
pub struct DiffuseAreaLight {
    shape: AreaShape,
    prim: Option<Prim>,
    l: Rgb,
    two_sided: bool,
    area: f32,
}

impl DiffuseAreaLight {
    /// An area light on `shape`; errors for negative or non-finite `l` or
    /// `scale` or a shape whose area is not finite. A shape of area 0 (a
    /// degenerate triangle) makes a light of no power: [`Self::phi`] is 0,
    /// its samples are `None` and its densities 0, as in pbrt-v4, which
    /// renders such meshes.
    pub fn new(shape: AreaShape, l: Rgb, scale: f32, two_sided: bool) -> Result<Self, LightError> {
        check_rgb("L", l)?;
        check_scalar("scale", scale)?;
        let area = shape.area();
        if !(area >= 0.0 && area.is_finite()) {
            return Err(LightError::InvalidParameter(format!(
                "area light shape has area {area}"
            )));
        }
        Ok(DiffuseAreaLight {
            shape,
            prim: None,
            l: l * scale,
            two_sided,
            area,
        })
    }

    /// An area light on primitive `prim` of `shapes` (remembered in
    /// [`DiffuseAreaLight::prim`] so a scene can map hits to lights).
    pub fn from_prim(
        shapes: &ShapeSet,
        prim: Prim,
        l: Rgb,
        scale: f32,
        two_sided: bool,
    ) -> Result<Self, LightError> {
        let mut light = Self::new(AreaShape::from_prim(shapes, prim)?, l, scale, two_sided)?;
        light.prim = Some(prim);
        Ok(light)
    }

    /// The primitive this light was built from, if any.
    pub fn prim(&self) -> Option<Prim> {
        self.prim
    }
    /// The emitting shape.
    pub fn shape(&self) -> &AreaShape {
        &self.shape
    }
    /// Surface area of the shape.
    pub fn area(&self) -> f32 {
        self.area
    }
    /// True when both sides emit.
    pub fn two_sided(&self) -> bool {
        self.two_sided
    }

    #[inline]
    pub(crate) fn l(&self, _p: Point3, n: Normal3, _uv: Point2, w: Vec3) -> Rgb {
        if !self.two_sided && n.dot(w) < 0.0 {
            Rgb::ZERO
        } else {
            self.l
        }
    }

    /// [`super::Light::sample_li`] of this light (`u` already clamped to
    /// `[0, 1)`), `None` unless the sample
    /// [carries light](LightLiSample::carries_light).
    #[inline(always)]
    pub(crate) fn sample_li(&self, ctx: &LightSampleContext, u: [f32; 2]) -> Option<LightLiSample> {
        match &self.shape {
            AreaShape::Triangle { p, n } => self.sample_triangle(p, *n, ctx, u),
            _ => self.sample_li_curved(ctx, u),
        }
    }

    /// [`Self::sample_li`] on a triangle: a point uniform by area (as
    /// [`AreaShape::sample`]), its density converted to solid angle.
    #[inline(always)]
    fn sample_triangle(
        &self,
        p: &[Point3; 3],
        n: Normal3,
        ctx: &LightSampleContext,
        u: [f32; 2],
    ) -> Option<LightLiSample> {
        if !(self.area > 0.0) {
            return None;
        }
        let b = sample_uniform_triangle(Point2::new(u[0], u[1]));
        let q = p[0] * b[0] + p[1] * b[1] + p[2] * b[2];
        let d = q - ctx.p;
        let d2 = d.length_squared();
        if !(d2 > 0.0) {
            return None;
        }
        let wi = d / d2.sqrt();
        let cos_l = n.abs_dot(wi);
        if !(cos_l > 0.0) {
            return None;
        }
        let s = LightLiSample {
            l: self.l(q, n, Point2::new(b[1], b[2]), -wi),
            wi,
            pdf: (1.0 / self.area) * d2 / cos_l,
            p_light: q,
            n_light: n,
            is_delta: false,
        };
        s.carries_light().then_some(s)
    }

    /// [`Self::sample_li`] on a sphere (by solid angle from outside) or a disk.
    #[inline(never)]
    fn sample_li_curved(&self, ctx: &LightSampleContext, u: [f32; 2]) -> Option<LightLiSample> {
        let u = Point2::new(u[0], u[1]);
        let cone = match &self.shape {
            AreaShape::Sphere(s) => s.sample_solid_angle(ctx.p, u),
            _ => None,
        };
        let solid_angle = cone.is_some();
        let ss = match cone {
            Some(ss) => ss,
            None => self.shape.sample_with_area(u, self.area)?,
        };
        let d = ss.p - ctx.p;
        let d2 = d.length_squared();
        if !(d2 > 0.0) {
            return None;
        }
        let wi = d / d2.sqrt();
        let cos_l = ss.n.abs_dot(wi);
        if !(cos_l > 0.0) {
            return None;
        }
        let s = LightLiSample {
            l: self.l(ss.p, ss.n, ss.uv, -wi),
            wi,
            pdf: if solid_angle {
                ss.pdf
            } else {
                ss.pdf * d2 / cos_l
            },
            p_light: ss.p,
            n_light: ss.n,
            is_delta: false,
        };
        s.carries_light().then_some(s)
    }

    pub(crate) fn pdf_li_hit(
        &self,
        ctx: &LightSampleContext,
        p_light: Point3,
        n_light: Normal3,
    ) -> f32 {
        if let AreaShape::Sphere(s) = &self.shape
            && let Some(pdf) = s.pdf_solid_angle(ctx.p)
        {
            return pdf;
        }
        let d = p_light - ctx.p;
        let d2 = d.length_squared();
        let cos_l = n_light.abs_dot(d) / d2.sqrt();
        if !(d2 > 0.0 && cos_l > 0.0) {
            return 0.0;
        }
        let pdf = d2 / (cos_l * self.area);
        if pdf.is_finite() { pdf } else { 0.0 }
    }

    pub(crate) fn pdf_li(&self, ctx: &LightSampleContext, wi: Vec3) -> f32 {
        match self.shape.intersect(&Ray::new(ctx.p, wi)) {
            Some((p, n)) => self.pdf_li_hit(ctx, p, n),
            None => 0.0,
        }
    }

    pub(crate) fn phi(&self) -> Rgb {
        self.l * (PI * self.area * if self.two_sided { 2.0 } else { 1.0 })
    }
}

/// The factor to multiply a diffuse area light's `scale` by so that the
/// luminance of its total power is `power`, for radiance `l` on shapes of
/// `total_area` (pbrt-v4's `"float power"`; apply it to every primitive of
/// the shape). Returns 1 when `power` is not positive.
pub fn diffuse_power_scale(l: Rgb, power: f32, total_area: f32, two_sided: bool) -> f32 {
    let k_e = PI * total_area * if two_sided { 2.0 } else { 1.0 };
    luminance_normaliser(l, k_e, Some(power))
}

impl ContentHash for AreaShape {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        match self {
            AreaShape::Triangle { p, n } => (0u8, p, n).feed(sink),
            AreaShape::Sphere(sphere) => (1u8, sphere).feed(sink),
            AreaShape::Disk(disk) => (2u8, disk).feed(sink),
        }
    }
}

/// The area is derived from the shape.
impl ContentHash for DiffuseAreaLight {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let DiffuseAreaLight {
            shape,
            prim,
            l,
            two_sided,
            area: _,
        } = self;
        (shape, prim, l, two_sided).feed(sink);
    }
}
