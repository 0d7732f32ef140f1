//! pbrt-v4's `Camera "perspective"`: a pinhole or thin-lens camera.
//!
//! Conventions follow pbrt exactly:
//! * the current transformation matrix at the `Camera` directive is the
//!   *camera-from-world* transform; [`PerspectiveCamera::from_ctm`] takes it
//!   as is, [`PerspectiveCamera::new`] takes its inverse (world-from-camera);
//! * camera space is left-handed: x right, y up, the camera looks down +z;
//! * raster space has its origin at the top-left corner of the full image,
//!   x to the right and y *down*, one unit per pixel (pixel `(i, j)` covers
//!   `[i, i+1) x [j, j+1)`, so its centre is at `(i + 0.5, j + 0.5)`);
//! * the screen window is `[-a, a] x [-1, 1]` for an aspect ratio `a =
//!   width / height > 1` and `[-1, 1] x [-1/a, 1/a]` otherwise, so `fov`
//!   (degrees) spans the *shorter* image axis; `frameaspectratio` and
//!   `screenwindow` override it as in pbrt;
//! * the thin lens (`lensradius`, `focaldistance`) maps the lens sample with
//!   the concentric disk map and focuses at camera-space depth
//!   `z = focaldistance`.

use crate::content_hash::{ContentHash, ContentSink};
use crate::filter::Filter;
use crate::math::sampling::sample_uniform_disk_concentric;
use crate::math::{Point2, Point3, Ray, Transform, Vec3};

/// Why a camera could not be built.
#[derive(Clone, Debug, PartialEq)]
pub enum CameraError {
    /// The field of view is not in `(0, 180)` degrees.
    InvalidFov(f32),
    /// The film resolution has a zero side.
    EmptyResolution([u32; 2]),
    /// The screen window is empty or not finite.
    InvalidScreenWindow([f32; 4]),
    /// The frame aspect ratio is not positive and finite.
    InvalidAspectRatio(f32),
    /// The lens radius is negative, or the focal distance not positive, or either is not finite.
    InvalidLens {
        /// `lensradius`.
        lens_radius: f32,
        /// `focaldistance`.
        focal_distance: f32,
    },
}

impl std::fmt::Display for CameraError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CameraError::InvalidFov(v) => write!(f, "camera fov {v} is not in (0, 180) degrees"),
            CameraError::EmptyResolution(r) => {
                write!(f, "film resolution {}x{} is empty", r[0], r[1])
            }
            CameraError::InvalidScreenWindow(w) => {
                write!(f, "screen window {w:?} is empty or not finite")
            }
            CameraError::InvalidAspectRatio(a) => {
                write!(f, "frame aspect ratio {a} is not positive")
            }
            CameraError::InvalidLens {
                lens_radius,
                focal_distance,
            } => write!(
                f,
                "invalid thin lens: lensradius {lens_radius} must be >= 0 and focaldistance {focal_distance} > 0"
            ),
        }
    }
}

impl std::error::Error for CameraError {}

/// The parameters of pbrt's `Camera "perspective"`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PerspectiveParams {
    /// Full field of view of the shorter image axis, in degrees (pbrt default 90).
    pub fov: f32,
    /// Lens radius; 0 (the default) is a pinhole.
    pub lens_radius: f32,
    /// Distance of the plane in focus (pbrt default 1e6).
    pub focal_distance: f32,
    /// `frameaspectratio`; `None` means width / height.
    pub frame_aspect_ratio: Option<f32>,
    /// `screenwindow` as `[xmin, xmax, ymin, ymax]`; `None` derives it from the aspect ratio.
    pub screen_window: Option<[f32; 4]>,
}

impl Default for PerspectiveParams {
    fn default() -> Self {
        PerspectiveParams {
            fov: 90.0,
            lens_radius: 0.0,
            focal_distance: 1e6,
            frame_aspect_ratio: None,
            screen_window: None,
        }
    }
}

/// The inputs of one camera ray: a film position and a lens sample, plus the
/// pixel filter's weight for the sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraSample {
    /// Position on the film in raster coordinates (pixels).
    pub p_film: [f32; 2],
    /// Lens sample in `[0,1)^2`.
    pub p_lens: [f32; 2],
    /// The filter sample's weight (`f / pdf`), to pass to the film.
    pub filter_weight: f32,
}

/// pbrt-v4's `GetCameraSample`: importance-samples `filter` with `u_filter`
/// (the sampler's pixel dimensions) around the centre of `pixel`.
pub fn camera_sample(
    filter: &Filter,
    pixel: [i32; 2],
    u_filter: [f32; 2],
    u_lens: [f32; 2],
) -> CameraSample {
    let fs = filter.sample(u_filter);
    CameraSample {
        p_film: [
            pixel[0] as f32 + 0.5 + fs.offset[0],
            pixel[1] as f32 + 0.5 + fs.offset[1],
        ],
        p_lens: u_lens,
        filter_weight: fs.weight,
    }
}

/// A perspective camera with an optional thin lens.
#[derive(Clone, Debug)]
pub struct PerspectiveCamera {
    world_from_camera: Transform,
    /// `world_from_camera.point(Point3::ZERO)`: every pinhole ray's origin.
    pinhole_origin: Point3,
    resolution: [u32; 2],
    /// `resolution` converted to `f32` once.
    resolution_f32: [f32; 2],
    /// Screen window `[xmin, xmax, ymin, ymax]`.
    screen: [f32; 4],
    tan_half_fov: f32,
    lens_radius: f32,
    focal_distance: f32,
}

impl PerspectiveCamera {
    /// A camera placed by `world_from_camera`, for a film of `resolution`
    /// (the *full* resolution: a crop window does not change the projection).
    pub fn new(
        world_from_camera: Transform,
        resolution: [u32; 2],
        params: &PerspectiveParams,
    ) -> Result<PerspectiveCamera, CameraError> {
        if !(params.fov > 0.0 && params.fov < 180.0) {
            return Err(CameraError::InvalidFov(params.fov));
        }
        if resolution[0] == 0 || resolution[1] == 0 {
            return Err(CameraError::EmptyResolution(resolution));
        }
        let lens_ok = params.lens_radius >= 0.0
            && params.lens_radius.is_finite()
            && params.focal_distance > 0.0
            && params.focal_distance.is_finite();
        if !lens_ok {
            return Err(CameraError::InvalidLens {
                lens_radius: params.lens_radius,
                focal_distance: params.focal_distance,
            });
        }
        let screen = match params.screen_window {
            Some(w) => w,
            None => {
                let frame = params
                    .frame_aspect_ratio
                    .unwrap_or(resolution[0] as f32 / resolution[1] as f32);
                if !(frame > 0.0 && frame.is_finite()) {
                    return Err(CameraError::InvalidAspectRatio(frame));
                }
                if frame > 1.0 {
                    [-frame, frame, -1.0, 1.0]
                } else {
                    [-1.0, 1.0, -1.0 / frame, 1.0 / frame]
                }
            }
        };
        let window_ok =
            screen.iter().all(|v| v.is_finite()) && screen[1] > screen[0] && screen[3] > screen[2];
        if !window_ok {
            return Err(CameraError::InvalidScreenWindow(screen));
        }
        Ok(PerspectiveCamera {
            pinhole_origin: world_from_camera.point(Point3::ZERO),
            world_from_camera,
            resolution,
            resolution_f32: resolution.map(|r| r as f32),
            screen,
            tan_half_fov: (params.fov.to_radians() * 0.5).tan(),
            lens_radius: params.lens_radius,
            focal_distance: params.focal_distance,
        })
    }

    /// A camera from pbrt's current transformation matrix at the `Camera`
    /// directive, which is the camera-from-world transform.
    pub fn from_ctm(
        camera_from_world: &Transform,
        resolution: [u32; 2],
        params: &PerspectiveParams,
    ) -> Result<PerspectiveCamera, CameraError> {
        PerspectiveCamera::new(camera_from_world.inverse(), resolution, params)
    }

    /// The world-from-camera transform.
    pub fn world_from_camera(&self) -> &Transform {
        &self.world_from_camera
    }
    /// The full film resolution `[width, height]`.
    pub fn resolution(&self) -> [u32; 2] {
        self.resolution
    }
    /// The screen window `[xmin, xmax, ymin, ymax]`.
    pub fn screen_window(&self) -> [f32; 4] {
        self.screen
    }
    /// The camera position in world space.
    pub fn position(&self) -> Point3 {
        self.world_from_camera.point(Point3::ZERO)
    }

    /// The camera-space point on the plane `z = 1` seen through raster
    /// position `p` (not normalised; its direction is the pinhole ray's).
    pub fn camera_from_raster(&self, p: [f32; 2]) -> Point3 {
        let [x0, x1, y0, y1] = self.screen;
        let [w, h] = self.resolution_f32;
        let sx = x0 + (p[0] / w) * (x1 - x0);
        let sy = y1 - (p[1] / h) * (y1 - y0);
        Vec3::new(sx * self.tan_half_fov, sy * self.tan_half_fov, 1.0)
    }

    /// The raster position of camera-space point `p`, or `None` when it is not
    /// in front of the camera (`z <= 0`). Inverse of [`Self::camera_from_raster`].
    pub fn raster_from_camera(&self, p: Point3) -> Option<[f32; 2]> {
        if !(p.z > 0.0) {
            return None;
        }
        let [x0, x1, y0, y1] = self.screen;
        let sx = p.x / (p.z * self.tan_half_fov);
        let sy = p.y / (p.z * self.tan_half_fov);
        Some([
            (sx - x0) / (x1 - x0) * self.resolution[0] as f32,
            (y1 - sy) / (y1 - y0) * self.resolution[1] as f32,
        ])
    }

    /// The raster position where world point `p` projects (pinhole model), or
    /// `None` when it is behind the camera.
    pub fn raster_from_world(&self, p: Point3) -> Option<[f32; 2]> {
        self.raster_from_camera(self.world_from_camera.inverse().point(p))
    }

    /// The world-space direction (normalised) of the pinhole ray through
    /// raster position `p`.
    pub fn world_direction(&self, p: [f32; 2]) -> Vec3 {
        self.world_from_camera
            .vector(self.camera_from_raster(p))
            .normalize()
    }

    /// The world-space ray for film position `film_pos` (raster pixels) and
    /// lens sample `lens` in `[0,1)^2` (ignored for a pinhole). The direction
    /// is normalised.
    #[inline]
    pub fn generate_ray(&self, film_pos: [f32; 2], lens: [f32; 2]) -> Ray {
        let p_cam = self.camera_from_raster(film_pos);
        if !(self.lens_radius > 0.0) {
            // The pinhole ray from the camera-space origin, whose world
            // position is kept.
            let d = self.world_from_camera.vector(p_cam.normalize());
            return Ray::new(self.pinhole_origin, d.normalize());
        }
        let d = sample_uniform_disk_concentric(Point2::new(lens[0], lens[1]));
        let o = Point3::new(d.x * self.lens_radius, d.y * self.lens_radius, 0.0);
        // The pinhole ray reaches depth `focal_distance` at `p_cam * focal_distance`.
        let focus = p_cam * self.focal_distance;
        let d = (focus - o).normalize();
        Ray::new(
            self.world_from_camera.point(o),
            self.world_from_camera.vector(d).normalize(),
        )
    }

    /// [`Self::generate_ray`] for a [`CameraSample`].
    #[inline]
    pub fn generate_ray_for(&self, sample: &CameraSample) -> Ray {
        self.generate_ray(sample.p_film, sample.p_lens)
    }

    /// The world-space point in focus for raster position `p` (on the plane
    /// at camera depth `focal_distance`): every lens ray through `p` passes here.
    pub fn focus_point(&self, p: [f32; 2]) -> Point3 {
        self.world_from_camera
            .point(self.camera_from_raster(p) * self.focal_distance)
    }
}

impl ContentHash for PerspectiveParams {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let PerspectiveParams {
            fov,
            lens_radius,
            focal_distance,
            frame_aspect_ratio,
            screen_window,
        } = self;
        (fov, lens_radius, focal_distance).feed(sink);
        (frame_aspect_ratio, screen_window).feed(sink);
    }
}
