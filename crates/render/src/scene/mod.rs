//! The renderable scene: shapes in a BVH with a material (and optionally an
//! area light) per shape, and the lights with their power-proportional
//! sampler. How the scene is seen (camera, film, filter) is apart, in
//! [`crate::view`].
//!
//! Scenes are put together with a [`SceneBuilder`] (the built-in Cornell box
//! in [`crate::cornell`], and the pbrt-v4 scene loader) and are immutable
//! afterwards, so one `&Scene` is shared by every render thread.
//!
//! Area lights: every primitive of an emissive shape (each triangle of a
//! mesh, as in pbrt) becomes one [`DiffuseAreaLight`] in [`Scene::lights`];
//! lights at infinity are preprocessed with the scene bounds.
//!
//! Participating media: [`SceneBuilder::add_medium`] adds a [`Medium`];
//! shapes added after [`SceneBuilder::set_medium_interface`] separate the
//! media it names, and [`SceneBuilder::set_camera_medium`] says where the
//! camera is. A shape whose material is [`INTERFACE`] has no surface: it
//! only marks where the medium changes. A scene with media or interface
//! shapes ([`Scene::has_media`]) is rendered by the volumetric path tracer.
//!
//! Scene files are loaded by [`crate::pbrt`] (`load_pbrt_scene`, `load_scene_file`).
//! A scene's content, for content hashes, is fed by its
//! [`crate::content_hash::ContentHash`] implementation (`content_hash.rs`).

mod content_hash;

use crate::accel::{Accel, Hit};
use crate::bsdf::Material;
use crate::bvh::BvhStats;
use crate::error::RenderError;
use crate::geometry::{Disk, Prim, ShapeId, ShapeSet, Sphere, TriangleMesh};
use crate::light::{DiffuseAreaLight, Light, LightSampler, LightType};
use crate::math::{Bounds3, Ray};
use crate::medium::{Medium, MediumInterface};
use crate::spectrum::Rgb;
use crate::spectrum::named::EmissionSpectrum;
use crate::texture::FloatTexture;

/// Diffuse emission of a shape (pbrt's `AreaLightSource "diffuse"`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emission {
    /// Emitted radiance, `scale` already applied.
    pub l: Rgb,
    /// Emit from both sides of the surface.
    pub two_sided: bool,
}

/// The material index of a shape without a surface (pbrt-v4's `interface`
/// material): rays pass through it, changing medium when its
/// [`MediumInterface`] is a transition.
pub const INTERFACE: u32 = u32::MAX;

/// Per-shape data: material index and the index of its first area light.
#[derive(Clone, Copy, Debug, PartialEq)]
struct ShapeInfo {
    material: u32,
    /// For emissive shapes, the light of primitive `k` is `first_light + k`.
    first_light: Option<u32>,
}

/// Collects shapes, materials and lights, then builds a [`Scene`].
#[derive(Clone, Debug, Default)]
pub struct SceneBuilder {
    shapes: ShapeSet,
    mesh_info: Vec<(u32, Option<Emission>, Option<EmissionSpectrum>)>,
    sphere_info: Vec<(u32, Option<Emission>, Option<EmissionSpectrum>)>,
    disk_info: Vec<(u32, Option<Emission>, Option<EmissionSpectrum>)>,
    materials: Vec<Material>,
    lights: Vec<(Light, Option<EmissionSpectrum>)>,
    emission_spectrum: Option<EmissionSpectrum>,
    alpha: Option<FloatTexture>,
    media: Vec<Medium>,
    medium_interface: MediumInterface,
    /// The medium interface of every shape (by kind, as `mesh_info`...).
    shape_media: [Vec<MediumInterface>; 3],
    camera_medium: Option<u32>,
}

impl SceneBuilder {
    /// An empty scene.
    pub fn new() -> Self {
        Self::default()
    }
    /// Adds a material; returns its index.
    pub fn add_material(&mut self, m: Material) -> u32 {
        self.materials.push(m);
        (self.materials.len() - 1) as u32
    }
    /// Adds a triangle mesh with a material and optional emission.
    pub fn add_mesh(&mut self, mesh: TriangleMesh, material: u32, emission: Option<Emission>) {
        let i = self.shapes.add_mesh(mesh);
        self.apply_alpha(ShapeId::Mesh(i));
        let s = self.emission_spectrum.clone();
        self.mesh_info.push((material, emission, s));
        self.shape_media[0].push(self.medium_interface);
    }
    /// Adds a sphere with a material and optional emission.
    pub fn add_sphere(&mut self, s: Sphere, material: u32, emission: Option<Emission>) {
        let p = self.shapes.add_sphere(s);
        self.apply_alpha(p.shape());
        let s = self.emission_spectrum.clone();
        self.sphere_info.push((material, emission, s));
        self.shape_media[1].push(self.medium_interface);
    }
    /// Adds a disk with a material and optional emission.
    pub fn add_disk(&mut self, d: Disk, material: u32, emission: Option<Emission>) {
        let p = self.shapes.add_disk(d);
        self.apply_alpha(p.shape());
        let s = self.emission_spectrum.clone();
        self.disk_info.push((material, emission, s));
        self.shape_media[2].push(self.medium_interface);
    }
    /// Adds a light that is not attached to a shape (point, infinite...).
    pub fn add_light(&mut self, l: Light) {
        self.lights.push((l, self.emission_spectrum.clone()));
    }
    /// The emission spectrum (spectral mode) of the shapes' emission and the
    /// lights added after this call: `Some` for a light given as a spectrum
    /// (blackbody, sampled, file), `None` (the default) to uplift its RGB.
    pub fn set_emission_spectrum(&mut self, s: Option<EmissionSpectrum>) {
        self.emission_spectrum = s;
    }

    /// The alpha cut-out (pbrt-v4's shape `"alpha"`, see
    /// [`crate::geometry::alpha`]) of the shapes added after this call;
    /// `None` (the default) for opaque shapes.
    pub fn set_shape_alpha(&mut self, alpha: Option<FloatTexture>) {
        self.alpha = alpha;
    }
    /// Adds a participating medium; returns its index.
    pub fn add_medium(&mut self, m: Medium) -> u32 {
        self.media.push(m);
        (self.media.len() - 1) as u32
    }
    /// The media inside and outside the shapes added after this call (the
    /// default: vacuum on both sides).
    pub fn set_medium_interface(&mut self, mi: MediumInterface) {
        self.medium_interface = mi;
    }
    /// The medium the camera is in (`None`, the default: vacuum).
    pub fn set_camera_medium(&mut self, m: Option<u32>) {
        self.camera_medium = m;
    }
    fn apply_alpha(&mut self, shape: ShapeId) {
        if let Some(a) = &self.alpha {
            self.shapes.set_alpha(shape, a.clone());
        }
    }

    /// Validates indices and emission, builds the BVH, the area lights and
    /// the light sampler.
    pub fn build(self) -> Result<Scene, RenderError> {
        let nmat = self.materials.len() as u32;
        let accel = Accel::build(self.shapes);
        let shapes = accel.shapes();
        let mut lights = Vec::new();
        let mut light_spectra = Vec::new();
        let mut infos = [Vec::new(), Vec::new(), Vec::new()];
        let groups = [&self.mesh_info, &self.sphere_info, &self.disk_info];
        for (kind, group) in groups.into_iter().enumerate() {
            for (i, (material, emission, spectrum)) in group.iter().enumerate() {
                let (material, emission) = (*material, *emission);
                if material >= nmat && material != INTERFACE {
                    return Err(RenderError::InvalidScene(format!(
                        "material index {material} out of range ({nmat} materials)"
                    )));
                }
                let prims: Vec<Prim> = match kind {
                    0 => shapes.mesh_prims(i as u32).collect(),
                    1 => vec![Prim::Sphere(i as u32)],
                    _ => vec![Prim::Disk(i as u32)],
                };
                let first_light = match emission {
                    Some(e) if !e.l.is_black() => {
                        let first = lights.len() as u32;
                        for p in prims {
                            let light =
                                DiffuseAreaLight::from_prim(shapes, p, e.l, 1.0, e.two_sided)
                                    .map_err(|err| RenderError::InvalidScene(err.to_string()))?;
                            lights.push(Light::Area(light));
                            light_spectra.push(spectrum.clone());
                        }
                        Some(first)
                    }
                    _ => None,
                };
                infos[kind].push(ShapeInfo {
                    material,
                    first_light,
                });
            }
        }
        for (l, s) in self.lights {
            lights.push(l);
            light_spectra.push(s);
        }
        let bounds = accel.bounds();
        for l in &mut lights {
            l.preprocess(&bounds);
        }
        let light_sampler = LightSampler::new(&lights);
        let infinite_lights = (0..lights.len())
            .filter(|&i| lights[i].light_type() == LightType::Infinite)
            .collect();
        let [mesh_info, sphere_info, disk_info] = infos;
        let media = MediaOfScene::new(
            self.media,
            self.shape_media,
            self.camera_medium,
            [&mesh_info, &sphere_info, &disk_info],
        )?;
        Ok(Scene {
            accel,
            materials: self.materials,
            mesh_info,
            sphere_info,
            disk_info,
            lights,
            light_spectra,
            infinite_lights,
            light_sampler,
            media,
        })
    }
}

/// A scene's media: the media, each shape's interface (kept only where it
/// is a transition) and the camera's medium.
#[derive(Clone, Debug, Default)]
struct MediaOfScene {
    media: Vec<Medium>,
    shape_media: [Vec<MediumInterface>; 3],
    camera_medium: Option<u32>,
    /// Media or shapes without a surface exist.
    active: bool,
}

impl MediaOfScene {
    fn new(
        media: Vec<Medium>,
        mut shape_media: [Vec<MediumInterface>; 3],
        camera_medium: Option<u32>,
        infos: [&[ShapeInfo]; 3],
    ) -> Result<MediaOfScene, RenderError> {
        let n = media.len() as u32;
        let named = shape_media
            .iter()
            .flatten()
            .flat_map(|mi| [mi.inside, mi.outside]);
        if let Some(m) = named.chain([camera_medium]).flatten().find(|&m| m >= n) {
            return Err(RenderError::InvalidScene(format!(
                "medium index {m} out of range ({n} media)"
            )));
        }
        let interfaces = infos
            .iter()
            .flat_map(|i| i.iter())
            .any(|i| i.material == INTERFACE);
        let active = n > 0 || interfaces;
        if !active || shape_media.iter().flatten().all(|mi| !mi.is_transition()) {
            shape_media = Default::default();
        }
        Ok(MediaOfScene {
            media,
            shape_media,
            camera_medium,
            active,
        })
    }
}

/// A ray hit with the data the integrator needs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneHit {
    /// Primitive and surface.
    pub hit: Hit,
    /// Material index into [`Scene::materials`].
    pub material: u32,
    /// Index of the area light of the hit primitive, if it emits.
    pub light: Option<u32>,
}

/// A built scene, ready to render.
#[derive(Clone, Debug)]
pub struct Scene {
    accel: Accel,
    materials: Vec<Material>,
    mesh_info: Vec<ShapeInfo>,
    sphere_info: Vec<ShapeInfo>,
    disk_info: Vec<ShapeInfo>,
    lights: Vec<Light>,
    light_spectra: Vec<Option<EmissionSpectrum>>,
    infinite_lights: Vec<usize>,
    light_sampler: LightSampler,
    media: MediaOfScene,
}

impl Scene {
    /// The same scene with its ray queries run with `lanes` (tests compare
    /// lane sets; the default is the widest the CPU has).
    pub fn with_lanes(mut self, lanes: crate::math::lanes::LaneSet) -> Scene {
        self.accel = self.accel.with_lanes(lanes);
        self
    }

    /// Closest hit along `ray` (any `t > 0`).
    #[inline]
    pub fn intersect(&self, ray: &Ray) -> Option<SceneHit> {
        let hit = self.intersect_hit(ray)?;
        let (material, light) = self.material_and_light(hit.prim);
        Some(SceneHit {
            hit,
            material,
            light,
        })
    }
    /// [`Scene::intersect`] without the lookups of
    /// [`Scene::material_and_light`] (the path tracer makes them itself, so
    /// that the hit is not copied into a [`SceneHit`]).
    #[inline]
    pub fn intersect_hit(&self, ray: &Ray) -> Option<Hit> {
        self.accel.intersect(ray, f32::INFINITY)
    }
    /// The closest hit along `ray` with `t < t_max`.
    #[inline]
    pub fn intersect_hit_before(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        self.accel.intersect(ray, t_max)
    }
    /// The material index of primitive `prim` and the index of its area
    /// light, if it emits ([`SceneHit::material`], [`SceneHit::light`]).
    #[inline]
    pub fn material_and_light(&self, prim: Prim) -> (u32, Option<u32>) {
        let (info, k) = match prim {
            Prim::Triangle { mesh, tri } => (self.mesh_info[mesh as usize], tri),
            Prim::Sphere(i) => (self.sphere_info[i as usize], 0),
            Prim::Disk(i) => (self.disk_info[i as usize], 0),
        };
        (info.material, info.first_light.map(|f| f + k))
    }
    /// True when anything is hit in `(0, t_max)` (shadow rays).
    #[inline]
    pub fn intersect_p(&self, ray: &Ray, t_max: f32) -> bool {
        self.accel.intersect_p(ray, t_max)
    }
    /// The shapes.
    pub fn shapes(&self) -> &ShapeSet {
        self.accel.shapes()
    }
    /// The materials.
    pub fn materials(&self) -> &[Material] {
        &self.materials
    }
    /// Every light (area lights first, one per emissive primitive).
    pub fn lights(&self) -> &[Light] {
        &self.lights
    }
    /// The emission spectrum of light `i` (spectral mode), when it was given
    /// as a spectrum rather than RGB.
    #[inline]
    pub fn light_spectrum(&self, i: usize) -> Option<&lowdisc_colour::cie::Tabulated> {
        self.light_spectra.get(i).and_then(|s| s.as_deref())
    }
    /// Indices of the infinite lights (seen by escaping rays).
    pub fn infinite_lights(&self) -> &[usize] {
        &self.infinite_lights
    }
    /// The power-proportional light chooser.
    pub fn light_sampler(&self) -> &LightSampler {
        &self.light_sampler
    }
    /// True when the scene has participating media or shapes without a
    /// surface ([`INTERFACE`]): it is then rendered by the volumetric path
    /// tracer. Scenes without are rendered as before media existed.
    #[inline]
    pub fn has_media(&self) -> bool {
        self.media.active
    }
    /// The participating media.
    pub fn media(&self) -> &[Medium] {
        &self.media.media
    }
    /// The medium the camera is in.
    pub fn camera_medium(&self) -> Option<u32> {
        self.media.camera_medium
    }
    /// The media on the two sides of primitive `prim`'s surface when they
    /// differ (`None` when crossing it keeps the ray's medium).
    #[inline]
    pub fn medium_interface(&self, prim: Prim) -> Option<MediumInterface> {
        let (kind, i) = match prim {
            Prim::Triangle { mesh, .. } => (0, mesh),
            Prim::Sphere(i) => (1, i),
            Prim::Disk(i) => (2, i),
        };
        let mi = *self.media.shape_media[kind].get(i as usize)?;
        mi.is_transition().then_some(mi)
    }
    /// World bounds of the geometry.
    pub fn bounds(&self) -> Bounds3 {
        self.accel.bounds()
    }
    /// BVH statistics.
    pub fn bvh_stats(&self) -> &BvhStats {
        self.accel.stats()
    }
    /// Total number of primitives.
    pub fn prim_count(&self) -> usize {
        self.accel.shapes().prim_count()
    }
}
