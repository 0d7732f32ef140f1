//! Built-in test scenes for sampler comparisons, in the spirit of Burley
//! 2020 ("Practical Hash-based Owen Scrambling", JCGT 9(4), Fig. 1): a
//! Cornell box under (a) direct lighting and (b) global illumination with
//! depth of field. Nothing is downloaded; both are [`crate::cornell`]'s box.
//!
//! | preset | scene | path depth | camera |
//! |---|---|---|---|
//! | `direct` | Cornell box, visible area light | 1 (emission + one light sample) | pinhole |
//! | `gi` | the same box | [`GI_MAX_DEPTH`] (5) | thin lens: radius [`GI_LENS_RADIUS`] mm, focus [`GI_FOCAL_DISTANCE`] mm |
//!
//! In `gi` the focal plane lies 1000 mm in front of the camera (world
//! `z = 200`, through the middle of the short block). A point at camera depth
//! `d` is blurred over a disk of angular radius `r |1/d - 1/f|`: at 128x128
//! (0.307° per pixel) about 2 pixels for the back wall (`d = 1359`), 1.2 for
//! the short block's front (`d ≈ 865`) and half a pixel for the light
//! (`d = 1080`), so the lens dimensions matter as in Burley's (b). Depth 1 in
//! `direct` makes each sample use the pixel (2 dimensions) and one light
//! sample (the first BSDF vertex's dimensions), the case where joint
//! stratification of pixel and light sample pays most.

use crate::cornell::{cornell_camera, cornell_camera_with_lens, cornell_scene, cornell_view};
use crate::render::RenderError;
use crate::scene::Scene;
use crate::view::ViewSpec;

/// Maximum path depth of the `gi` preset.
pub const GI_MAX_DEPTH: u32 = 5;
/// Thin-lens radius of the `gi` preset, in the box's millimetres.
pub const GI_LENS_RADIUS: f32 = 40.0;
/// Focal distance of the `gi` preset, in millimetres from the camera.
pub const GI_FOCAL_DISTANCE: f32 = 1000.0;

/// A built-in comparison scene with its path depth.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ScenePreset {
    /// Direct lighting in the Cornell box (path depth 1), light visible.
    Direct,
    /// Global illumination and depth of field in the Cornell box.
    Gi,
}

impl ScenePreset {
    /// Every preset.
    pub const ALL: [ScenePreset; 2] = [ScenePreset::Direct, ScenePreset::Gi];

    /// The command-line name.
    pub fn name(self) -> &'static str {
        match self {
            ScenePreset::Direct => "direct",
            ScenePreset::Gi => "gi",
        }
    }

    /// The preset called `name`, if any.
    pub fn from_name(name: &str) -> Option<ScenePreset> {
        ScenePreset::ALL.into_iter().find(|p| p.name() == name)
    }

    /// A stable id of the scene's content, for cache keys (bump the version
    /// when the scene changes).
    pub fn id(self) -> &'static str {
        match self {
            ScenePreset::Direct => "preset-direct-v1",
            ScenePreset::Gi => "preset-gi-v1",
        }
    }

    /// A one-line description.
    pub fn description(self) -> &'static str {
        match self {
            ScenePreset::Direct => {
                "Cornell box, direct lighting only (path depth 1), area light in view, pinhole"
            }
            ScenePreset::Gi => {
                "Cornell box, global illumination (path depth 5), thin-lens depth of field"
            }
        }
    }

    /// The path tracer's maximum depth for this preset.
    pub fn max_depth(self) -> u32 {
        match self {
            ScenePreset::Direct => 1,
            ScenePreset::Gi => GI_MAX_DEPTH,
        }
    }

    /// The scene and its view.
    pub fn scene(self) -> Result<(Scene, ViewSpec), RenderError> {
        let camera = match self {
            ScenePreset::Direct => cornell_camera()?,
            ScenePreset::Gi => cornell_camera_with_lens(GI_LENS_RADIUS, GI_FOCAL_DISTANCE)?,
        };
        Ok((cornell_scene()?.0, cornell_view(camera)?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrator::PathIntegrator;
    use crate::render::{NoProgress, RenderOptions, RenderOutput, render};
    use crate::view::View;
    use lowdisc::catalog::SamplerName;

    fn render_preset(p: ScenePreset, res: [u32; 2], opts: &RenderOptions) -> RenderOutput {
        let (scene, spec) = p.scene().unwrap();
        let view = View::new(&spec, res).unwrap();
        render(&scene, &view, opts, &NoProgress).unwrap()
    }

    fn options(preset: ScenePreset, seed: u64) -> RenderOptions {
        RenderOptions {
            integrator: PathIntegrator {
                max_depth: preset.max_depth(),
                ..PathIntegrator::default()
            },
            threads: Some(1),
            ..RenderOptions::new(SamplerName::SobolOwen, seed, 4)
        }
    }

    #[test]
    fn names_round_trip() {
        for p in ScenePreset::ALL {
            assert_eq!(ScenePreset::from_name(p.name()), Some(p));
        }
        assert_eq!(ScenePreset::from_name("cornell"), None);
        assert_ne!(ScenePreset::Direct.id(), ScenePreset::Gi.id());
    }

    /// Depth 5 adds indirect light to every surface: the gi image is
    /// brighter than the direct one (mean over the image), and the direct
    /// preset's pinhole image is the plain Cornell box's.
    #[test]
    fn gi_adds_indirect_light_and_direct_is_the_plain_box() {
        let res = [24, 24];
        let mean = |p: ScenePreset| {
            let out = render_preset(p, res, &options(p, 1));
            out.mean().iter().sum::<f64>()
        };
        let (direct, gi) = (mean(ScenePreset::Direct), mean(ScenePreset::Gi));
        assert!(gi > 1.3 * direct, "gi {gi}, direct {direct}");
        let (plain, view) = crate::cornell::cornell_box(res).unwrap();
        let a = render(&plain, &view, &options(ScenePreset::Direct, 1), &NoProgress).unwrap();
        let b = render_preset(ScenePreset::Direct, res, &options(ScenePreset::Direct, 1));
        assert_eq!(a.image.pixels(), b.image.pixels());
    }

    /// The gi preset's lens is real: with the same seed its image differs
    /// from the pinhole box rendered at the same depth.
    #[test]
    fn gi_preset_has_depth_of_field() {
        let res = [16, 16];
        let opts = options(ScenePreset::Gi, 2);
        let lens = render_preset(ScenePreset::Gi, res, &opts);
        let (scene, view) = crate::cornell::cornell_box(res).unwrap();
        let pinhole = render(&scene, &view, &opts, &NoProgress).unwrap();
        assert_ne!(lens.image.pixels(), pinhole.image.pixels());
    }
}
