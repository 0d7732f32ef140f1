//! The study's scene collection: the built-in scenes and the public pbrt-v4
//! scenes of the shared scene folder, by name, with the environment maps
//! they are lit by.

use std::path::Path;

use lowdisc_render::preset::ScenePreset;

use super::{SceneSource, StudyScene};

/// The shared scenes: name, file under the shared scene folder,
/// environment map (under the same folder) where the scene file names none
/// that ships with it, and whether its missing pbrt-v4 features are
/// approximated (bmw-m6 asks for the path tracer's `regularize`, which only
/// changes its caustic noise).
pub const SHARED_SCENES: [(&str, &str, Option<&str>, bool); 5] = [
    (
        "cornell-box",
        "bitterli-cornell-box/scene-v4.pbrt",
        None,
        false,
    ),
    ("veach-mis", "bitterli-veach-mis/scene-v4.pbrt", None, false),
    (
        "killeroo-simple",
        "killeroos/killeroo-simple.pbrt",
        None,
        false,
    ),
    (
        "material-testball",
        "bitterli-material-testball/material-testball.pbrt",
        Some("envmaps/polyhaven-studio_small_03_1k.hdr"),
        false,
    ),
    (
        "bmw-m6",
        "bmw-m6/bmw-m6.pbrt",
        Some("envmaps/polyhaven-kiara_1_dawn_1k.hdr"),
        true,
    ),
];

/// The name of the experiment's built-in scene in the collection.
pub const BUILTIN: &str = "builtin";

/// Every scene of the collection, in table order: the presets `direct` and
/// `gi`, the built-in scene, then [`SHARED_SCENES`] under `shared` (whether
/// or not their files exist).
pub fn collection(shared: &Path) -> Vec<StudyScene> {
    let mut scenes: Vec<StudyScene> = ScenePreset::ALL
        .iter()
        .map(|&p| StudyScene {
            name: p.name().into(),
            source: SceneSource::Preset(p),
            envmap: None,
            max_depth: None,
            approximate: false,
        })
        .collect();
    scenes.push(StudyScene {
        name: BUILTIN.into(),
        source: SceneSource::Builtin,
        envmap: None,
        max_depth: None,
        approximate: false,
    });
    for (name, file, envmap, approximate) in SHARED_SCENES {
        scenes.push(StudyScene {
            name: name.into(),
            source: SceneSource::File(shared.join(file)),
            envmap: envmap.map(|e| shared.join(e)),
            max_depth: None,
            approximate,
        });
    }
    scenes
}

/// Whether the files `scene` needs exist.
pub fn available(scene: &StudyScene) -> bool {
    let file_ok = match &scene.source {
        SceneSource::File(f) => f.is_file(),
        _ => true,
    };
    file_ok && scene.envmap.as_ref().is_none_or(|e| e.is_file())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_built_in_scenes_always_available() {
        let all = collection(Path::new("/nonexistent"));
        let mut names: Vec<&str> = all.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names[..3], ["direct", "gi", "builtin"]);
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), all.len());
        let available: Vec<&str> = all
            .iter()
            .filter(|s| available(s))
            .map(|s| s.name.as_str())
            .collect();
        assert_eq!(available, ["direct", "gi", "builtin"]);
    }
}
