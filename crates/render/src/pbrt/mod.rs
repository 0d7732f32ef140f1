//! pbrt-v4 scene loading: a [`pbrt_format::ParserTarget`] that keeps pbrt's
//! graphics state and builds a [`Scene`] with a [`SceneBuilder`](crate::scene::SceneBuilder).
//!
//! Entry point: [`load_pbrt_scene`]. It returns the scene, its view (the
//! `Camera`, `Film` and `PixelFilter`, a [`ViewSpec`]), the warnings (one
//! per unsupported directive or parameter, with `file:line:column`) and the
//! rendering settings the scene file asks for ([`SceneSettings`]: sampler,
//! samples per pixel, maximum depth and resolution as a
//! [`SettingsLayer`], each naming its directive; the output file), which
//! the caller may override ([`crate::settings::Settings::resolve`]).
//!
//! **No silent substitutions.** A pbrt-v4 feature that lowdisc lacks and
//! that changes the image (a `curve` shape, the `hair` or `measured`
//! material, alpha on an area light, grid media (`uniformgrid`,
//! `rgbgrid`, `cloud`, `nanovdb`), the `bdpt`, `sppm`, `mlt`, ... integrators, a
//! non-sRGB colour space, ...) is an error naming the feature and its
//! `file:line:column`, unless [`LoadOptions::approximate`] is set: then it
//! is a warning saying what is rendered instead. Features that do not change
//! the pixels (`Accelerator`, a sampler's `seed`, `Option`s that only change
//! speed, ...) are warnings. The full list, directive by directive, is in
//! `docs/guide/pbrt-compatibility.md`.
//!
//! What is always approximated, without a message:
//! * textures are evaluated at each shading point without filtering beyond
//!   bilinear image lookups;
//! * spectra (named, sampled, files, blackbody) are reduced to RGB for RGB
//!   mode; spectral mode evaluates conductors' measured `eta`/`k` and
//!   lights' blackbody, sampled and file spectra as spectra (other spectral
//!   parameters, e.g. a reflectance given as a spectrum, use their RGB,
//!   uplifted), and named glasses keep one index of refraction (no
//!   dispersion).
//!
//! 8-bit image textures are decoded as pbrt-v4 decodes them (see
//! [`crate::texture::ColorEncoding::for_file`]): PNG by the `encoding`
//! parameter (sRGB by default), every other 8-bit format (TGA) as sRGB
//! whatever `encoding` says.
//!
//! Relative file names are resolved against the directory of the main scene
//! file, even inside included files (as pbrt-v4 does).

mod blocks;
mod lights;
mod loader;
mod materials;
mod media;
mod media_table;
mod options;
mod shapes;
mod state;

use crate::error::RenderError;
use crate::scene::Scene;
use crate::settings::SettingsLayer;
use crate::view::{View, ViewSpec};
use std::path::{Path, PathBuf};

pub use loader::PbrtLoader;

/// Options of [`load_pbrt_scene`].
#[derive(Clone, Debug, Default)]
pub struct LoadOptions {
    /// Environment map used instead of every image-based `infinite` light's
    /// file (the command line's `--envmap`).
    pub envmap_override: Option<PathBuf>,
    /// Render pbrt-v4 features that lowdisc lacks approximately, each with a
    /// warning saying how (the command line's `--approximate`), instead of
    /// refusing the scene with an error naming the first one.
    pub approximate: bool,
}

/// The rendering settings a scene file asks for (`Sampler`, `Integrator`,
/// `Film`). `None` means the file does not say.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SceneSettings {
    /// The settings for [`crate::settings::Settings::resolve`]: the
    /// lowdisc sampler the `Sampler` type maps to, its sample count
    /// (`pixelsamples`, or `xsamples * ysamples` of `stratified`), the
    /// `Integrator`'s `maxdepth` and the `Film`'s resolution.
    pub layer: SettingsLayer,
    /// The `Sampler` type as written.
    pub sampler_type: Option<String>,
    /// The `Integrator` type as written.
    pub integrator: Option<String>,
    /// `"string filename"` of the `Film`, if given.
    pub output: Option<String>,
}

/// A loaded scene with its view, warnings and settings.
#[derive(Clone, Debug)]
pub struct LoadedScene {
    /// The scene.
    pub scene: Scene,
    /// How the file sees it: `Camera`, `Film` and `PixelFilter`.
    pub view: ViewSpec,
    /// Warnings, each formatted as `file:line:column: warning: message`.
    pub warnings: Vec<String>,
    /// The settings the file asks for.
    pub settings: SceneSettings,
    /// Counts of what was created.
    pub counts: SceneCounts,
}

/// What the loader created (for reports and tests).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SceneCounts {
    /// Triangles in all meshes.
    pub triangles: usize,
    /// Spheres.
    pub spheres: usize,
    /// Disks.
    pub disks: usize,
    /// Materials added to the scene.
    pub materials: usize,
    /// Lights not attached to shapes (point, spot, distant, infinite).
    pub lights: usize,
    /// Shapes with an area light.
    pub area_shapes: usize,
    /// Object instances expanded.
    pub instances: usize,
}

/// Loads a pbrt-v4 scene file.
///
/// Errors (as [`RenderError::InvalidScene`] whose message starts with
/// `file:line:column` where there is one): unreadable files, syntax errors,
/// unreadable or malformed meshes (the message names the PLY file), invalid
/// shape parameters, undefined named materials or objects, a missing
/// environment map without an override, and, unless
/// [`LoadOptions::approximate`], a pbrt-v4 feature that lowdisc lacks and
/// that changes the image.
pub fn load_pbrt_scene(path: &Path, options: &LoadOptions) -> Result<LoadedScene, RenderError> {
    let mut loader = PbrtLoader::new(path, options.clone());
    pbrt_format::parse_file(path, &mut loader)
        .map_err(|e| RenderError::InvalidScene(e.to_string()))?;
    loader.finish()
}

/// Loads a pbrt-v4 scene file with default [`LoadOptions`] and builds its
/// view at the file's own resolution, dropping its warnings and settings
/// (use [`load_pbrt_scene`] to get them).
pub fn load_scene_file(path: &Path) -> Result<(Scene, View), RenderError> {
    let loaded = load_pbrt_scene(path, &LoadOptions::default())?;
    Ok((loaded.scene, View::native(&loaded.view)?))
}
