//! The built-in Cornell box: the classic scene from the Cornell University
//! Program of Computer Graphics' published measurements ("Cornell Box Data",
//! <https://www.graphics.cornell.edu/online/box/data.html>).
//!
//! **Geometry** (millimetres, as published): floor, ceiling, back wall, the
//! red wall at `x ≈ 550`, the green wall at `x = 0`, the short and the tall
//! block, and the 130 mm x 105 mm light at `y = 548.8` (`x` 213–343, `z`
//! 227–332) facing down. The ceiling is cut around the light (four
//! rectangles) so that the light and the ceiling, which the data puts in the
//! same plane, never overlap. Every quadrilateral is split into two triangles
//! along its first diagonal.
//!
//! **Camera** (as published): at `(278, 273, -800)` looking at `(278, 273, 0)`,
//! up `+y`, focal length 35 mm on a 25 mm x 25 mm film, so the field of view is
//! `2 atan(12.5 / 35) ≈ 39.31°`. The published data uses a right-handed frame
//! while pbrt's camera space is left-handed; as pbrt-v4's Cornell scenes do,
//! the camera is mirrored in `x` (`Scale -1 1 1` before `LookAt`), which puts
//! the red wall on the left of the image as in the photographs.
//!
//! **Reflectances** (RGB): the published data are spectral reflectances from
//! 400 to 700 nm. This renderer is RGB, and the reductions used are the
//! widely used ones (those of Benedikt Bitterli's CC0 Cornell box scene,
//! shipped with the shared test scenes): white `(0.725, 0.71, 0.68)`, red
//! `(0.63, 0.065, 0.05)`, green `(0.14, 0.45, 0.091)`. The light's own surface
//! is black.
//!
//! **Emission**: the published light spectrum is `0, 8, 15.6, 18.4` at 400,
//! 500, 600 and 700 nm (relative units). Reduced like the crate's other
//! spectra (band averages of the linearly interpolated spectrum: red 600–700
//! nm, green 500–600 nm, blue 400–500 nm), that is `L = (17.0, 11.8, 4.0)`;
//! [`CORNELL_LIGHT_SCALE`] (1) multiplies it, so the radiance is in the
//! published relative units (the image mean is about (0.19, 0.12, 0.04)).

use crate::bsdf::Material;
use crate::camera::PerspectiveParams;
use crate::error::RenderError;
use crate::filter::Filter;
use crate::geometry::{MeshData, TriangleMesh};
use crate::math::{Point3, Transform, Vec3};
use crate::scene::{Emission, Scene, SceneBuilder};
use crate::spectrum::Rgb;
use crate::view::{CameraSpec, View, ViewSpec};

/// Multiplies the light's published relative emission.
pub const CORNELL_LIGHT_SCALE: f32 = 1.0;
/// Light radiance before scaling: band averages of the published spectrum.
pub const CORNELL_LIGHT_RGB: [f32; 3] = [17.0, 11.8, 4.0];
/// White walls, floor, ceiling and blocks.
pub const CORNELL_WHITE: [f32; 3] = [0.725, 0.71, 0.68];
/// The left (red) wall.
pub const CORNELL_RED: [f32; 3] = [0.63, 0.065, 0.05];
/// The right (green) wall.
pub const CORNELL_GREEN: [f32; 3] = [0.14, 0.45, 0.091];
/// Full field of view: `2 atan(12.5 mm / 35 mm)` in degrees.
pub const CORNELL_FOV_DEGREES: f32 = 39.307_6;

type Quad = [[f32; 3]; 4];

const FLOOR: Quad = [
    [552.8, 0.0, 0.0],
    [0.0, 0.0, 0.0],
    [0.0, 0.0, 559.2],
    [549.6, 0.0, 559.2],
];
const BACK_WALL: Quad = [
    [549.6, 0.0, 559.2],
    [0.0, 0.0, 559.2],
    [0.0, 548.8, 559.2],
    [556.0, 548.8, 559.2],
];
const GREEN_WALL: Quad = [
    [0.0, 0.0, 559.2],
    [0.0, 0.0, 0.0],
    [0.0, 548.8, 0.0],
    [0.0, 548.8, 559.2],
];
const RED_WALL: Quad = [
    [552.8, 0.0, 0.0],
    [549.6, 0.0, 559.2],
    [556.0, 548.8, 559.2],
    [556.0, 548.8, 0.0],
];
const LIGHT: Quad = [
    [343.0, 548.8, 227.0],
    [343.0, 548.8, 332.0],
    [213.0, 548.8, 332.0],
    [213.0, 548.8, 227.0],
];

const SHORT_BLOCK: [Quad; 5] = [
    [
        [130.0, 165.0, 65.0],
        [82.0, 165.0, 225.0],
        [240.0, 165.0, 272.0],
        [290.0, 165.0, 114.0],
    ],
    [
        [290.0, 0.0, 114.0],
        [290.0, 165.0, 114.0],
        [240.0, 165.0, 272.0],
        [240.0, 0.0, 272.0],
    ],
    [
        [130.0, 0.0, 65.0],
        [130.0, 165.0, 65.0],
        [290.0, 165.0, 114.0],
        [290.0, 0.0, 114.0],
    ],
    [
        [82.0, 0.0, 225.0],
        [82.0, 165.0, 225.0],
        [130.0, 165.0, 65.0],
        [130.0, 0.0, 65.0],
    ],
    [
        [240.0, 0.0, 272.0],
        [240.0, 165.0, 272.0],
        [82.0, 165.0, 225.0],
        [82.0, 0.0, 225.0],
    ],
];

const TALL_BLOCK: [Quad; 5] = [
    [
        [423.0, 330.0, 247.0],
        [265.0, 330.0, 296.0],
        [314.0, 330.0, 456.0],
        [472.0, 330.0, 406.0],
    ],
    [
        [423.0, 0.0, 247.0],
        [423.0, 330.0, 247.0],
        [472.0, 330.0, 406.0],
        [472.0, 0.0, 406.0],
    ],
    [
        [472.0, 0.0, 406.0],
        [472.0, 330.0, 406.0],
        [314.0, 330.0, 456.0],
        [314.0, 0.0, 456.0],
    ],
    [
        [314.0, 0.0, 456.0],
        [314.0, 330.0, 456.0],
        [265.0, 330.0, 296.0],
        [265.0, 0.0, 296.0],
    ],
    [
        [265.0, 0.0, 296.0],
        [265.0, 330.0, 296.0],
        [423.0, 330.0, 247.0],
        [423.0, 0.0, 247.0],
    ],
];

/// The ceiling (`y = 548.8`, `x` 0–556, `z` 0–559.2) minus the light's
/// rectangle, as four axis-aligned rectangles facing down.
fn ceiling() -> Vec<Quad> {
    let y = 548.8;
    let rect =
        |x0: f32, x1: f32, z0: f32, z1: f32| [[x0, y, z0], [x0, y, z1], [x1, y, z1], [x1, y, z0]];
    vec![
        rect(0.0, 556.0, 0.0, 227.0),
        rect(0.0, 556.0, 332.0, 559.2),
        rect(0.0, 213.0, 227.0, 332.0),
        rect(343.0, 556.0, 227.0, 332.0),
    ]
}

/// A mesh of quadrilaterals, each split along its first diagonal.
fn quads(qs: &[Quad]) -> Result<TriangleMesh, RenderError> {
    let mut data = MeshData::default();
    for q in qs {
        let b = data.positions.len() as u32;
        data.positions
            .extend(q.iter().map(|&v| Point3::from_array(v)));
        data.indices.push([b, b + 1, b + 2]);
        data.indices.push([b, b + 2, b + 3]);
    }
    Ok(TriangleMesh::new(&Transform::IDENTITY, data, false)?)
}

/// The camera of the published data, a pinhole (the field of view spans
/// the shorter side of the film).
pub fn cornell_camera() -> Result<CameraSpec, RenderError> {
    cornell_camera_with_lens(0.0, 1e6)
}

/// The camera of the published data with a thin lens of `lens_radius` mm
/// focused at `focal_distance` mm (0 is a pinhole).
pub fn cornell_camera_with_lens(
    lens_radius: f32,
    focal_distance: f32,
) -> Result<CameraSpec, RenderError> {
    let mirror = Transform::scale(Vec3::new(-1.0, 1.0, 1.0))
        .map_err(|_| RenderError::InvalidScene("singular camera".into()))?;
    let look = Transform::look_at(
        Point3::new(278.0, 273.0, -800.0),
        Point3::new(278.0, 273.0, 0.0),
        Vec3::Y,
    )
    .map_err(|_| RenderError::InvalidScene("singular camera".into()))?;
    // pbrt's CTM at `Camera` is camera-from-world = Scale * LookAt.
    let camera_from_world = mirror * look;
    Ok(CameraSpec {
        world_from_camera: camera_from_world.inverse(),
        params: PerspectiveParams {
            fov: CORNELL_FOV_DEGREES,
            lens_radius,
            focal_distance,
            ..PerspectiveParams::default()
        },
    })
}

/// The resolution the Cornell box is rendered at unless the settings say
/// otherwise.
pub const CORNELL_RESOLUTION: [u32; 2] = [512, 512];

/// The Cornell box and its view: the published camera on a
/// [`CORNELL_RESOLUTION`] film with a box pixel filter of radius 0.5 (each
/// sample lands in its own pixel).
pub fn cornell_scene() -> Result<(Scene, ViewSpec), RenderError> {
    Ok((cornell_geometry()?, cornell_view(cornell_camera()?)?))
}

/// The Cornell box's view through `camera` on a [`CORNELL_RESOLUTION`] film.
pub fn cornell_view(camera: CameraSpec) -> Result<ViewSpec, RenderError> {
    let filter =
        Filter::box_filter([0.5, 0.5]).map_err(|e| RenderError::InvalidScene(e.to_string()))?;
    Ok(ViewSpec::new(camera, CORNELL_RESOLUTION, filter))
}

/// The Cornell box and its view built at `resolution`.
pub fn cornell_box(resolution: [u32; 2]) -> Result<(Scene, View), RenderError> {
    cornell_box_with_camera(resolution, cornell_camera()?)
}

/// [`cornell_box`] seen through `camera` (e.g. [`cornell_camera_with_lens`]).
pub fn cornell_box_with_camera(
    resolution: [u32; 2],
    camera: CameraSpec,
) -> Result<(Scene, View), RenderError> {
    let view = View::new(&cornell_view(camera)?, resolution)?;
    Ok((cornell_geometry()?, view))
}

/// The box's geometry, materials and light.
fn cornell_geometry() -> Result<Scene, RenderError> {
    let mut b = SceneBuilder::new();
    let white = b.add_material(Material::diffuse(Rgb::from_array(CORNELL_WHITE)));
    let red = b.add_material(Material::diffuse(Rgb::from_array(CORNELL_RED)));
    let green = b.add_material(Material::diffuse(Rgb::from_array(CORNELL_GREEN)));
    let black = b.add_material(Material::diffuse(Rgb::ZERO));
    let mut whites = vec![FLOOR, BACK_WALL];
    whites.extend(ceiling());
    whites.extend(SHORT_BLOCK);
    whites.extend(TALL_BLOCK);
    b.add_mesh(quads(&whites)?, white, None);
    b.add_mesh(quads(&[RED_WALL])?, red, None);
    b.add_mesh(quads(&[GREEN_WALL])?, green, None);
    let emission = Emission {
        l: Rgb::from_array(CORNELL_LIGHT_RGB) * CORNELL_LIGHT_SCALE,
        two_sided: false,
    };
    b.add_mesh(quads(&[LIGHT])?, black, Some(emission));
    b.build()
}
