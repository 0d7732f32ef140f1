//! Perspective camera: view direction, field of view on the shorter axis,
//! pbrt's handedness for LookAt and Bitterli-style `Transform` cameras, the
//! raster <-> world mapping, and thin-lens focusing.

use lowdisc_render::camera::{CameraError, PerspectiveCamera, PerspectiveParams, camera_sample};
use lowdisc_render::filter::Filter;
use lowdisc_render::math::{Matrix4, Point3, Transform, Vec3};

fn params(fov: f32) -> PerspectiveParams {
    PerspectiveParams {
        fov,
        ..Default::default()
    }
}

fn assert_dir(got: Vec3, want: Vec3) {
    let want = want.normalize();
    assert!((got - want).length() < 2e-6, "got {got:?}, want {want:?}");
    assert!((got.length() - 1.0).abs() < 1e-6);
}

/// pbrt's `Transform` directive lists the matrix column by column.
fn pbrt_transform(v: [f32; 16]) -> Transform {
    let mut m = Matrix4::IDENTITY;
    for (k, x) in v.iter().enumerate() {
        m.m[k % 4][k / 4] = *x;
    }
    Transform::from_matrix(m).unwrap()
}

/// A LookAt camera at (1, 2, 3) looking down world -z with +y up. pbrt's
/// LookAt puts camera +x along `up x dir` = y x (-z) = -x in world.
fn look_down_minus_z(res: [u32; 2], fov: f32) -> PerspectiveCamera {
    let eye = Point3::new(1.0, 2.0, 3.0);
    let ctm = Transform::look_at(eye, Point3::new(1.0, 2.0, -7.0), Vec3::Y).unwrap();
    PerspectiveCamera::from_ctm(&ctm, res, &params(fov)).unwrap()
}

#[test]
fn centre_ray_points_along_the_view_direction() {
    for res in [[100, 100], [200, 100], [64, 256]] {
        let cam = look_down_minus_z(res, 45.0);
        let r = cam.generate_ray([res[0] as f32 / 2.0, res[1] as f32 / 2.0], [0.5, 0.5]);
        assert_eq!(r.o, Point3::new(1.0, 2.0, 3.0));
        assert_dir(r.d, Vec3::new(0.0, 0.0, -1.0));
    }
}

#[test]
fn corner_rays_square_image() {
    // fov 90: tan(45°) = 1; camera (-1, 1, 1) at the top-left corner maps to
    // world (+1, 1, -1) because camera x is world -x here.
    let cam = look_down_minus_z([100, 100], 90.0);
    assert_dir(
        cam.generate_ray([0.0, 0.0], [0.0; 2]).d,
        Vec3::new(1.0, 1.0, -1.0),
    );
    assert_dir(
        cam.generate_ray([100.0, 0.0], [0.0; 2]).d,
        Vec3::new(-1.0, 1.0, -1.0),
    );
    assert_dir(
        cam.generate_ray([0.0, 100.0], [0.0; 2]).d,
        Vec3::new(1.0, -1.0, -1.0),
    );
    assert_dir(
        cam.generate_ray([100.0, 100.0], [0.0; 2]).d,
        Vec3::new(-1.0, -1.0, -1.0),
    );
}

#[test]
fn fov_spans_the_shorter_axis() {
    let t = 30f32.to_radians().tan(); // fov 60
    // Landscape 2:1: x in [-2, 2], y in [-1, 1].
    let cam = look_down_minus_z([200, 100], 60.0);
    assert_dir(
        cam.generate_ray([0.0, 0.0], [0.0; 2]).d,
        Vec3::new(2.0 * t, t, -1.0),
    );
    assert_dir(
        cam.generate_ray([200.0, 100.0], [0.0; 2]).d,
        Vec3::new(-2.0 * t, -t, -1.0),
    );
    let top = cam.generate_ray([100.0, 0.0], [0.0; 2]).d;
    let bottom = cam.generate_ray([100.0, 100.0], [0.0; 2]).d;
    assert!((top.dot(bottom).acos().to_degrees() - 60.0).abs() < 1e-3);
    // Portrait 1:2: x in [-1, 1], y in [-2, 2].
    let cam = look_down_minus_z([100, 200], 60.0);
    assert_dir(
        cam.generate_ray([0.0, 0.0], [0.0; 2]).d,
        Vec3::new(t, 2.0 * t, -1.0),
    );
    let left = cam.generate_ray([0.0, 100.0], [0.0; 2]).d;
    let right = cam.generate_ray([100.0, 100.0], [0.0; 2]).d;
    assert!((left.dot(right).acos().to_degrees() - 60.0).abs() < 1e-3);
}

#[test]
fn bitterli_cornell_box_transform_camera() {
    // bitterli-cornell-box/scene-v4.pbrt: camera at (0, 1, 6.8) looking down
    // world -z; this matrix has det -1, so camera +x is world +x.
    let ctm = pbrt_transform([
        1., -0., -0., -0., -0., 1., -0., -0., -0., -0., -1., -0., -0., -1., 6.8, 1.,
    ]);
    let cam = PerspectiveCamera::from_ctm(&ctm, [1024, 1024], &params(19.5)).unwrap();
    let r = cam.generate_ray([512.0, 512.0], [0.0; 2]);
    assert!((r.o - Point3::new(0.0, 1.0, 6.8)).length() < 1e-6);
    assert_dir(r.d, Vec3::new(0.0, 0.0, -1.0));
    let t = 9.75f32.to_radians().tan();
    assert_dir(
        cam.generate_ray([0.0, 0.0], [0.0; 2]).d,
        Vec3::new(-t, t, -1.0),
    );
    assert_dir(
        cam.generate_ray([1024.0, 1024.0], [0.0; 2]).d,
        Vec3::new(t, -t, -1.0),
    );
}

#[test]
fn bitterli_testball_rotated_camera() {
    // bitterli-material-testball: a rotation and translation, 1280x720.
    let ctm = pbrt_transform([
        0.721367, -0.373123, -0.583445, -0., -0., 0.842456, -0.538765, -0., -0.692553, -0.388647,
        -0.60772, -0., 0.0258668, -0.29189, 5.43024, 1.,
    ]);
    let cam = PerspectiveCamera::from_ctm(&ctm, [1280, 720], &params(20.114292)).unwrap();
    // Rows of the rotation part are the camera axes in world space.
    let x_axis = Vec3::new(0.721367, 0.0, -0.692553);
    let y_axis = Vec3::new(-0.373123, 0.842456, -0.388647);
    let z_axis = Vec3::new(-0.583445, -0.538765, -0.60772);
    let tol = |got: Vec3, want: Vec3| {
        assert!(
            (got - want.normalize()).length() < 2e-5,
            "{got:?} vs {want:?}"
        )
    };
    tol(cam.generate_ray([640.0, 360.0], [0.0; 2]).d, z_axis);
    let t = (20.114292f32 / 2.0).to_radians().tan();
    let a = 1280.0 / 720.0;
    tol(
        cam.generate_ray([0.0, 0.0], [0.0; 2]).d,
        x_axis * (-a * t) + y_axis * t + z_axis,
    );
    tol(
        cam.generate_ray([1280.0, 720.0], [0.0; 2]).d,
        x_axis * (a * t) - y_axis * t + z_axis,
    );
    // The camera position solves R p + t = 0: p = -R^T t.
    let tr = Vec3::new(0.0258668, -0.29189, 5.43024);
    let pos = -(x_axis * tr.x + y_axis * tr.y + z_axis * tr.z);
    assert!((cam.position() - pos).length() < 1e-4);
}

#[test]
fn raster_world_round_trip() {
    let cam = look_down_minus_z([320, 240], 50.0);
    for p in [[0.5, 0.5], [160.0, 120.0], [300.25, 17.75], [10.0, 239.0]] {
        let d = cam.world_direction(p);
        let world = cam.position() + d * 7.5;
        let back = cam.raster_from_world(world).unwrap();
        assert!(
            (back[0] - p[0]).abs() < 1e-3 && (back[1] - p[1]).abs() < 1e-3,
            "{p:?} -> {back:?}"
        );
    }
    assert!(
        cam.raster_from_world(cam.position() + Vec3::new(0.0, 0.0, 1.0))
            .is_none()
    );
}

#[test]
fn thin_lens_rays_meet_on_the_focal_plane() {
    let ctm = Transform::look_at(
        Point3::new(0.0, 1.0, 5.0),
        Point3::new(0.3, 0.8, 0.0),
        Vec3::Y,
    )
    .unwrap();
    let p = PerspectiveParams {
        fov: 40.0,
        lens_radius: 0.25,
        focal_distance: 4.0,
        ..Default::default()
    };
    let cam = PerspectiveCamera::from_ctm(&ctm, [64, 48], &p).unwrap();
    let centre = cam.position();
    for film in [[32.0, 24.0], [0.0, 0.0], [63.5, 10.25]] {
        let focus = cam.focus_point(film);
        let mut origins = Vec::new();
        for k in 0..50 {
            let lens = [
                ((k * 7) % 50) as f32 / 50.0 + 0.003,
                (k as f32 + 0.5) / 50.0,
            ];
            let r = cam.generate_ray(film, lens);
            assert!(
                (r.o - centre).length() <= 0.25 + 1e-5,
                "origin off the lens"
            );
            // The focus point lies on the ray, in front of it.
            let to = focus - r.o;
            let t = to.dot(r.d);
            assert!(t > 0.0);
            assert!(
                (r.at(t) - focus).length() < 1e-4 * to.length(),
                "ray misses the focus point"
            );
            origins.push(r.o);
        }
        let spread = origins
            .iter()
            .map(|o| (*o - centre).length())
            .fold(0.0, f32::max);
        assert!(spread > 0.2, "lens samples should move the origin");
    }
    // The focal plane is at camera depth 4 along the view direction.
    let view = cam.world_direction([32.0, 24.0]);
    assert!(((cam.focus_point([32.0, 24.0]) - centre).dot(view) - 4.0).abs() < 1e-4);
}

#[test]
fn camera_sample_offsets_from_pixel_centre() {
    let f = Filter::box_filter([0.5, 0.5]).unwrap();
    let s = camera_sample(&f, [3, 7], [0.25, 0.75], [0.1, 0.2]);
    assert_eq!(s.p_film, [3.25, 7.75]);
    assert_eq!(s.p_lens, [0.1, 0.2]);
    assert_eq!(s.filter_weight, 1.0);
}

#[test]
fn bad_parameters_are_errors() {
    let id = Transform::IDENTITY;
    assert_eq!(
        PerspectiveCamera::new(id, [10, 10], &params(180.0)).unwrap_err(),
        CameraError::InvalidFov(180.0)
    );
    assert!(PerspectiveCamera::new(id, [10, 10], &params(f32::NAN)).is_err());
    assert!(PerspectiveCamera::new(id, [0, 10], &params(45.0)).is_err());
    let bad_lens = PerspectiveParams {
        lens_radius: -1.0,
        ..Default::default()
    };
    assert!(PerspectiveCamera::new(id, [10, 10], &bad_lens).is_err());
    let bad_window = PerspectiveParams {
        screen_window: Some([1.0, -1.0, -1.0, 1.0]),
        ..Default::default()
    };
    assert!(PerspectiveCamera::new(id, [10, 10], &bad_window).is_err());
}

#[test]
fn screen_window_and_frame_aspect_override() {
    let id = Transform::IDENTITY;
    let p = PerspectiveParams {
        frame_aspect_ratio: Some(0.5),
        ..Default::default()
    };
    let cam = PerspectiveCamera::new(id, [100, 100], &p).unwrap();
    assert_eq!(cam.screen_window(), [-1.0, 1.0, -2.0, 2.0]);
    let p = PerspectiveParams {
        screen_window: Some([0.0, 1.0, 0.0, 1.0]),
        ..Default::default()
    };
    let cam = PerspectiveCamera::new(id, [10, 10], &p).unwrap();
    // The centre of the raster looks at screen (0.5, 0.5); fov 90 -> tan 1.
    assert_dir(
        cam.generate_ray([5.0, 5.0], [0.0; 2]).d,
        Vec3::new(0.5, 0.5, 1.0),
    );
}

#[test]
fn pinned_thin_lens_ray_never_drifts() {
    // Recorded once; `tan`, `sin` and `cos` may differ in the last bit
    // between maths libraries, hence the tight tolerance rather than bits.
    let ctm = Transform::look_at(
        Point3::new(0.0, 1.0, 5.0),
        Point3::new(0.3, 0.8, 0.0),
        Vec3::Y,
    )
    .unwrap();
    let p = PerspectiveParams {
        fov: 40.0,
        lens_radius: 0.25,
        focal_distance: 4.0,
        ..Default::default()
    };
    let cam = PerspectiveCamera::from_ctm(&ctm, [64, 48], &p).unwrap();
    let r = cam.generate_ray([10.25, 30.5], [0.2, 0.9]);
    let o = [1038350214u32, 1066747080, 1084227652].map(f32::from_bits);
    let d = [1051681269u32, 3190739065, 3211559464].map(f32::from_bits);
    assert!((r.o - Vec3::from_array(o)).length() < 1e-6, "{:?}", r.o);
    assert!((r.d - Vec3::from_array(d)).length() < 1e-6, "{:?}", r.d);
}
