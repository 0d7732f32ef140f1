//! The view of a scene, apart from the scene itself (geometry, materials,
//! lights): where the camera is and how it projects, the film and the pixel
//! filter.
//!
//! A scene description gives a [`ViewSpec`] (a pbrt-v4 file's `Camera`,
//! `Film` and `PixelFilter`; a built-in scene's own); a render builds one
//! [`View`] from it at the resolved resolution
//! ([`crate::settings::Settings::resolution`]), once: the camera is built
//! for that resolution and the film's pixel bounds (crop window, pixel
//! bounds, sensor settings) are checked there and nowhere else. Two renders
//! of one scene at two resolutions are two views of the same `Scene`.
//!
//! ```
//! use lowdisc_render::cornell::cornell_scene;
//! use lowdisc_render::view::View;
//! let (_scene, spec) = cornell_scene().unwrap();
//! let view = View::new(&spec, [64, 32]).unwrap();
//! assert_eq!(view.resolution(), [64, 32]);
//! assert_eq!(view.pixel_bounds().area(), 64 * 32);
//! ```

use crate::camera::{PerspectiveCamera, PerspectiveParams};
use crate::content_hash::{ContentHash, ContentSink};
use crate::error::RenderError;
use crate::film::{Film, FilmParams, PixelBounds};
use crate::filter::Filter;
use crate::math::Transform;

/// Where the camera is and how it projects.
#[derive(Clone, Debug)]
pub struct CameraSpec {
    /// World-from-camera transform (pbrt's camera space: looks down +z, y up).
    pub world_from_camera: Transform,
    /// Perspective parameters.
    pub params: PerspectiveParams,
}

/// How a scene is seen, as its description gives it: the camera, pbrt's
/// `Film` parameters (resolution, crop, sensor), the pixel filter, the
/// exposure applied when writing 8-bit output, and where the camera and
/// the film were given (named in their errors).
#[derive(Clone, Debug)]
pub struct ViewSpec {
    /// The camera.
    pub camera: CameraSpec,
    /// The film's parameters; its resolution is the description's, which
    /// the resolved settings may replace.
    pub film: FilmParams,
    /// Pixel filter (importance-sampled by the pixel dimensions).
    pub filter: Filter,
    /// Factor applied to radiance when writing 8-bit output.
    pub exposure: f32,
    /// Where the camera was given (`file:line:column`), if in a file.
    pub camera_at: Option<String>,
    /// Where the film was given (`file:line:column`), if in a file.
    pub film_at: Option<String>,
}

impl ViewSpec {
    /// `camera` on a `resolution` film with `filter`, exposure 1, and
    /// otherwise pbrt's defaults.
    pub fn new(camera: CameraSpec, resolution: [u32; 2], filter: Filter) -> ViewSpec {
        ViewSpec {
            camera,
            film: FilmParams {
                resolution,
                ..FilmParams::default()
            },
            filter,
            exposure: 1.0,
            camera_at: None,
            film_at: None,
        }
    }

    /// pbrt's default camera (at the origin, looking down +z, 90°) on its
    /// default film.
    pub fn pbrt_default() -> ViewSpec {
        let camera = CameraSpec {
            world_from_camera: Transform::IDENTITY,
            params: PerspectiveParams::default(),
        };
        ViewSpec::new(camera, FilmParams::default().resolution, Filter::default())
    }
}

/// A view built at one resolution: the camera, the film's parameters and
/// its checked pixel bounds, the filter.
#[derive(Clone, Debug)]
pub struct View {
    spec: ViewSpec,
    camera: PerspectiveCamera,
    bounds: PixelBounds,
}

impl View {
    /// The view `spec` describes, at `resolution`: builds the camera and
    /// checks the film (an error names where the camera or film was given).
    pub fn new(spec: &ViewSpec, resolution: [u32; 2]) -> Result<View, RenderError> {
        let mut spec = spec.clone();
        spec.film.resolution = resolution;
        let bounds = Film::checked_bounds(&spec.film).map_err(|e| match &spec.film_at {
            Some(at) => RenderError::InvalidScene(format!("{at}: {e}")),
            None => RenderError::Film(e),
        })?;
        let c = &spec.camera;
        let camera =
            PerspectiveCamera::new(c.world_from_camera, resolution, &c.params).map_err(|e| {
                match &spec.camera_at {
                    Some(at) => RenderError::InvalidScene(format!("{at}: Camera: {e}")),
                    None => RenderError::Camera(e),
                }
            })?;
        Ok(View {
            spec,
            camera,
            bounds,
        })
    }

    /// The view at the resolution `spec` itself gives.
    pub fn native(spec: &ViewSpec) -> Result<View, RenderError> {
        View::new(spec, spec.film.resolution)
    }

    /// The description, with the view's resolution.
    pub fn spec(&self) -> &ViewSpec {
        &self.spec
    }
    /// The camera.
    pub fn camera(&self) -> &PerspectiveCamera {
        &self.camera
    }
    /// The film's parameters (with the view's resolution).
    pub fn film(&self) -> &FilmParams {
        &self.spec.film
    }
    /// The pixel filter.
    pub fn filter(&self) -> &Filter {
        &self.spec.filter
    }
    /// The factor applied to radiance when writing 8-bit output.
    pub fn exposure(&self) -> f32 {
        self.spec.exposure
    }
    /// The full image resolution (what the camera projects onto).
    pub fn resolution(&self) -> [u32; 2] {
        self.spec.film.resolution
    }
    /// The pixels the film stores (its crop), checked.
    pub fn pixel_bounds(&self) -> PixelBounds {
        self.bounds
    }
}

impl ContentHash for CameraSpec {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let CameraSpec {
            world_from_camera,
            params,
        } = self;
        (world_from_camera, params).feed(sink);
    }
}

/// What of a view changes pixels besides the settings: the camera and the
/// pixel filter. The film's parameters are render settings and the
/// resolution and crop are recorded by whoever hashes the view (a split
/// part records them); the exposure only scales 8-bit output; where the
/// camera and film were given names no content.
impl ContentHash for ViewSpec {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let ViewSpec {
            camera,
            film: _,
            filter,
            exposure: _,
            camera_at: _,
            film_at: _,
        } = self;
        (camera, filter).feed(sink);
    }
}
