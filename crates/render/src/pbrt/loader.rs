//! [`PbrtLoader`]: the [`ParserTarget`] that receives every directive and keeps
//! the loader's state; shapes, materials, lights and rendering options are
//! handled in sibling modules.

use super::media_table::MediaTable;
use super::state::{MatRef, StateStack, pbrt_matrix};
use super::{LoadOptions, LoadedScene, SceneCounts, SceneSettings};
use crate::bsdf::Material;
use crate::error::RenderError;
use crate::film::FilmParams;
use crate::filter::Filter;
use crate::math::Transform;
use crate::medium::MediumInterface;
use crate::scene::SceneBuilder;
use crate::settings::Given;
use crate::texture::TextureRegistry;
use crate::view::{CameraSpec, ViewSpec};
use pbrt_format::{
    ActiveTransform, Directive, FileKind, Loc, Param, ParamSet, ParamValues, ParseError,
    ParserTarget, TargetResult, Warnings,
};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// A shape recorded inside `ObjectBegin`/`ObjectEnd`, created per instance.
#[derive(Clone, Debug)]
pub(super) struct ShapeDef {
    pub ty: String,
    pub params: ParamSet,
    pub ctm: Transform,
    pub reverse: bool,
    pub material: MatRef,
    pub media: MediumInterface,
    pub loc: Loc,
}

/// Builds a scene from pbrt-v4 directives (see [`super::load_pbrt_scene`]).
#[derive(Debug)]
pub struct PbrtLoader {
    pub(super) base_dir: PathBuf,
    pub(super) options: LoadOptions,
    pub(super) builder: SceneBuilder,
    pub(super) warnings: Warnings,
    pub(super) state: StateStack,
    pub(super) settings: SceneSettings,
    pub(super) counts: SceneCounts,
    pub(super) camera: Option<CameraSpec>,
    pub(super) film: FilmParams,
    pub(super) filter: Filter,
    pub(super) named_materials: HashMap<String, MatRef>,
    pub(super) default_material: Option<u32>,
    pub(super) textures: TextureRegistry,
    /// The named participating media.
    pub(super) media: MediaTable,
    /// Every material added by a directive, by scene index (for `mix`).
    pub(super) material_values: HashMap<u32, Material>,
    objects: HashMap<String, Vec<ShapeDef>>,
    current_object: Option<(String, Vec<ShapeDef>)>,
    imports: Vec<StateStack>,
    /// The main scene file (named in errors without a location).
    pub(super) main_file: PathBuf,
    /// Where `WorldBegin` was, once it was seen.
    pub(super) world_begin: Option<Loc>,
    /// The `AttributeBegin`/`TransformBegin` blocks still open.
    pub(super) open_blocks: Vec<(&'static str, Loc)>,
    /// Whether an infinite light took the `--envmap` override.
    pub(super) envmap_used: bool,
    /// Where the `Camera` and `Film` directives were (for their errors).
    pub(super) camera_loc: Option<Loc>,
    pub(super) film_loc: Option<Loc>,
}

impl PbrtLoader {
    /// A loader for the scene file `path` (relative file names in the scene
    /// are resolved against its directory).
    pub fn new(path: &Path, options: LoadOptions) -> PbrtLoader {
        let base_dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        PbrtLoader {
            base_dir,
            options,
            builder: SceneBuilder::new(),
            warnings: Warnings::new(),
            state: StateStack::default(),
            settings: SceneSettings::default(),
            counts: SceneCounts::default(),
            camera: None,
            film: FilmParams::default(),
            filter: Filter::default(),
            named_materials: HashMap::new(),
            default_material: None,
            textures: TextureRegistry::new(),
            media: MediaTable::default(),
            material_values: HashMap::new(),
            objects: HashMap::new(),
            current_object: None,
            imports: Vec::new(),
            main_file: path.to_path_buf(),
            world_begin: None,
            open_blocks: Vec::new(),
            envmap_used: false,
            camera_loc: None,
            film_loc: None,
        }
    }

    /// A file name from the scene, resolved against the main file's directory.
    pub(super) fn resolve(&self, name: &str) -> PathBuf {
        let p = Path::new(name);
        if p.is_absolute() {
            p.to_path_buf()
        } else {
            self.base_dir.join(p)
        }
    }

    /// Adds a warning at `loc`.
    pub(super) fn warn(&mut self, loc: &Loc, message: impl Into<String>) {
        self.warnings.warn(loc, message);
    }

    /// Warns once per message (for "X is not supported" where X does not
    /// change the image).
    pub(super) fn unsupported(&mut self, loc: &Loc, what: &str) {
        self.warnings
            .warn_once(loc, format!("{what} is not supported; ignored"));
    }

    /// A pbrt-v4 `feature` that lowdisc lacks and that changes the image:
    /// an error at `loc` naming it, or, with [`LoadOptions::approximate`],
    /// a warning (once per message) saying that `instead` is rendered.
    pub(super) fn approximated(
        &mut self,
        loc: &Loc,
        feature: &str,
        instead: &str,
    ) -> Result<(), ParseError> {
        if self.options.approximate {
            let message = format!("{feature} is not supported; {instead} (--approximate)");
            self.warnings.warn_once(loc, message);
            Ok(())
        } else {
            let message = format!("{feature} is not supported (with --approximate: {instead})");
            Err(ParseError::scene(loc, message))
        }
    }

    /// Builds the scene after the last directive.
    pub fn finish(mut self) -> Result<LoadedScene, RenderError> {
        if self.current_object.is_some() {
            self.warnings
                .warn_global("ObjectBegin without ObjectEnd at end of file");
        }
        let mut view = ViewSpec::pbrt_default();
        match self.camera.take() {
            Some(c) => view.camera = c,
            None => {
                let w = "the scene has no Camera; using pbrt's default camera";
                self.warnings.warn_global(w);
            }
        }
        if let Some(env) = &self.options.envmap_override
            && !self.envmap_used
        {
            let msg = format!(
                "the scene has no infinite light; the environment map {} is not used",
                env.display()
            );
            self.warnings.warn_global(&msg);
        }
        if self.counts.lights == 0 && self.counts.area_shapes == 0 {
            self.warnings
                .warn_global("the scene has no lights; it will render black");
        }
        // The view's errors (built at the resolved resolution) name the
        // directive's file:line:column.
        view.film = self.film;
        view.filter = self.filter;
        view.camera_at = self.camera_loc.as_ref().map(ToString::to_string);
        view.film_at = self.film_loc.as_ref().map(ToString::to_string);
        if let Some(at) = &view.film_at {
            let resolution = Given::new(view.film.resolution, format!("{at}: Film"));
            self.settings.layer.resolution = Some(resolution);
        }
        let media = std::mem::take(&mut self.media).into_media();
        for m in media.map_err(|e| RenderError::InvalidScene(e.to_string()))? {
            self.builder.add_medium(m);
        }
        let scene = self.builder.build()?;
        Ok(LoadedScene {
            scene,
            view,
            warnings: self.warnings.iter().map(ToString::to_string).collect(),
            settings: self.settings,
            counts: self.counts,
        })
    }

    fn shape_directive(&mut self, ty: String, params: ParamSet, loc: &Loc) -> TargetResult {
        let def = ShapeDef {
            ty,
            params,
            ctm: self.state.cur.ctm,
            reverse: self.state.cur.reverse_orientation,
            material: self.state.cur.material,
            media: self.state.cur.media,
            loc: loc.clone(),
        };
        if let Some((_, defs)) = &mut self.current_object {
            if self.state.cur.area.is_some() {
                self.warnings
                    .warn_once(loc, "area lights inside object definitions are ignored");
            }
            defs.push(def);
            return Ok(());
        }
        let area = self.state.cur.area.clone();
        self.create_shape(&def, def.ctm, area.as_ref())
    }

    fn object_instance(&mut self, name: &str, loc: &Loc) -> TargetResult {
        if self.current_object.is_some() {
            return Err(ParseError::scene(loc, "ObjectInstance inside ObjectBegin"));
        }
        let defs =
            self.objects.get(name).cloned().ok_or_else(|| {
                ParseError::scene(loc, format!("object \"{name}\" is not defined"))
            })?;
        let inst = self.state.cur.ctm;
        for def in &defs {
            self.create_shape(def, inst * def.ctm, None)?;
        }
        self.counts.instances += 1;
        Ok(())
    }

    /// `Option "type name" value`: pbrt-v4's options that change the image
    /// when enabled are errors (see [`PbrtLoader::approximated`]); the others
    /// (speed, statistics, the seed, `rendercoordsys`) are ignored with a
    /// warning.
    fn option_directive(&mut self, p: &Param, loc: &Loc) -> Result<(), ParseError> {
        let enabled = matches!(&p.values, ParamValues::Bools(b) if b.first() == Some(&true));
        let changes_image = matches!(
            p.name.as_str(),
            "forcediffuse" | "disablepixeljitter" | "disablewavelengthjitter"
        );
        let what = format!("Option \"{}\"", p.name);
        if changes_image && enabled {
            self.approximated(loc, &what, "the option is ignored")
        } else {
            self.unsupported(loc, &what);
            Ok(())
        }
    }

    fn attribute_end(&mut self, loc: &Loc) {
        if !self.state.pop() {
            self.warn(loc, "unmatched AttributeEnd; ignored");
        }
    }
}

impl ParserTarget for PbrtLoader {
    fn directive(&mut self, directive: Directive, loc: &Loc) -> TargetResult {
        self.check_block(&directive, loc)?;
        match directive {
            Directive::Option(p) => self.option_directive(&p, loc)?,
            Directive::ColorSpace(name) => {
                if name != "srgb" {
                    let what = format!("ColorSpace \"{name}\"");
                    self.approximated(loc, &what, "rendering in sRGB primaries")?;
                }
            }
            Directive::Identity => self.state.cur.ctm = Transform::IDENTITY,
            Directive::Translate(d) => self.state.translate(d, loc)?,
            Directive::Scale(s) => self.state.scale(s, loc)?,
            Directive::Rotate(a, axis) => self.state.rotate(a, axis, loc)?,
            Directive::LookAt(e, l, u) => self.state.look_at(e, l, u, loc)?,
            Directive::ConcatTransform(m) => {
                let t = pbrt_matrix(m, loc)?;
                self.state.concat(t, loc)?;
            }
            Directive::Transform(m) => self.state.cur.ctm = pbrt_matrix(m, loc)?,
            Directive::CoordinateSystem(name) => {
                self.state.named.insert(name, self.state.cur.ctm);
            }
            Directive::CoordSysTransform(name) => match self.state.named.get(&name) {
                Some(t) => self.state.cur.ctm = *t,
                None => {
                    self.warn(
                        loc,
                        format!("coordinate system \"{name}\" is not defined; ignored"),
                    );
                }
            },
            Directive::ActiveTransform(ActiveTransform::All) => {}
            Directive::ActiveTransform(_) => self.approximated(
                loc,
                "motion blur (ActiveTransform StartTime/EndTime)",
                "every transform applies at all times",
            )?,
            Directive::TransformTimes(..) => {
                self.unsupported(loc, "TransformTimes (without motion blur)")
            }
            Directive::ReverseOrientation => {
                self.state.cur.reverse_orientation = !self.state.cur.reverse_orientation
            }
            Directive::Camera(ty, params) => self.camera_directive(&ty, &params, loc)?,
            Directive::Film(ty, params) => self.film_directive(&ty, &params, loc)?,
            Directive::Sampler(ty, params) => self.sampler_directive(&ty, &params, loc)?,
            Directive::Integrator(ty, params) => self.integrator_directive(&ty, &params, loc)?,
            Directive::PixelFilter(ty, params) => self.filter_directive(&ty, &params, loc)?,
            Directive::Accelerator(..) => {
                self.unsupported(loc, "Accelerator (the renderer always uses its SAH BVH)")
            }
            Directive::MakeNamedMedium(name, params) => {
                self.make_named_medium(&name, &params, loc)?
            }
            Directive::MediumInterface(inside, outside) => {
                self.medium_interface(&inside, &outside, loc)?
            }
            Directive::WorldBegin => {
                self.state.cur.ctm = Transform::IDENTITY;
                self.state.named.insert("world".into(), Transform::IDENTITY);
            }
            Directive::AttributeBegin => self.state.push(false),
            Directive::TransformBegin => self.state.push(true),
            Directive::AttributeEnd | Directive::TransformEnd => self.attribute_end(loc),
            Directive::Attribute(target, _) => {
                let what = format!("Attribute \"{target}\" (default parameters)");
                self.approximated(loc, &what, "the defaults are ignored")?;
            }
            Directive::Shape(ty, params) => self.shape_directive(ty, params, loc)?,
            Directive::Material(ty, params) => {
                let m = self.create_material(&ty, &params, loc)?;
                self.state.cur.material = m;
            }
            Directive::MakeNamedMaterial(name, params) => {
                params.mark_used("type");
                let ty = params.get_string("type").unwrap_or("").to_string();
                let m = self.create_material(&ty, &params, loc)?;
                if self.named_materials.insert(name.clone(), m).is_some() {
                    self.warn(loc, format!("named material \"{name}\" redefined"));
                }
            }
            Directive::NamedMaterial(name) => {
                let m = *self.named_materials.get(&name).ok_or_else(|| {
                    ParseError::scene(loc, format!("named material \"{name}\" is not defined"))
                })?;
                self.state.cur.material = m;
            }
            Directive::Texture(name, ty, class, params) => {
                self.texture_directive(&name, &ty, &class, &params, loc)?
            }
            Directive::LightSource(ty, params) => self.light_directive(&ty, &params, loc)?,
            Directive::AreaLightSource(ty, params) => {
                self.area_light_directive(&ty, &params, loc)?
            }
            Directive::ObjectBegin(name) => {
                if self.current_object.is_some() {
                    return Err(ParseError::scene(loc, "ObjectBegin inside ObjectBegin"));
                }
                self.state.push(false);
                self.current_object = Some((name, Vec::new()));
            }
            Directive::ObjectEnd => match self.current_object.take() {
                Some((name, defs)) => {
                    self.objects.insert(name, defs);
                    self.attribute_end(loc);
                }
                None => self.warn(loc, "ObjectEnd without ObjectBegin; ignored"),
            },
            Directive::ObjectInstance(name) => self.object_instance(&name, loc)?,
        }
        Ok(())
    }

    fn warning(&mut self, loc: &Loc, message: &str) {
        self.warn(loc, message);
    }

    fn file_begin(&mut self, _path: &Path, kind: FileKind, _loc: Option<&Loc>) -> TargetResult {
        if kind == FileKind::Import {
            self.imports.push(self.state.clone());
        }
        Ok(())
    }

    fn end_of_files(&mut self) -> TargetResult {
        self.check_end_of_files()
    }

    fn file_end(&mut self, _path: &Path, kind: FileKind) -> TargetResult {
        if kind == FileKind::Import
            && let Some(s) = self.imports.pop()
        {
            self.state = s;
        }
        Ok(())
    }
}
