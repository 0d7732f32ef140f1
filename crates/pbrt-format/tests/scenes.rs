//! Every `.pbrt` file of the shared scene collection parses without error; the
//! numbers of shapes, lights and materials of each are pinned.

mod common;

use pbrt_format::{Directive, Recorder, parse_file};

#[derive(Debug, Default, PartialEq, Eq)]
struct Counts {
    shapes: usize,
    lights: usize,
    area_lights: usize,
    materials: usize,
    named_materials: usize,
    textures: usize,
    includes: usize,
    calls: usize,
    values: usize,
}

fn count(rec: &Recorder) -> Counts {
    Counts {
        shapes: rec.count(|c| matches!(c, Directive::Shape(..))),
        lights: rec.count(|c| matches!(c, Directive::LightSource(..))),
        area_lights: rec.count(|c| matches!(c, Directive::AreaLightSource(..))),
        materials: rec.count(|c| matches!(c, Directive::Material(..))),
        named_materials: rec.count(|c| matches!(c, Directive::MakeNamedMaterial(..))),
        textures: rec.count(|c| matches!(c, Directive::Texture(..))),
        includes: rec.files.iter().filter(|f| f.2).count() - 1,
        calls: rec.calls.len(),
        values: rec
            .calls
            .iter()
            .filter_map(|(c, _)| c.params())
            .flat_map(|p| p.iter())
            .map(|p| p.values.len())
            .sum(),
    }
}

/// (file, shapes, lights, area lights, materials, named materials, textures,
/// included files, directives, parameter values); counted by this parser and
/// cross-checked by hand with grep for shapes, lights and named materials.
const PINNED: &[(&str, [usize; 9])] = &[
    (
        "bitterli-classroom/scene-v4.pbrt",
        [79, 2, 0, 0, 44, 3, 0, 218, 304],
    ),
    (
        "bitterli-cornell-box/scene-v4.pbrt",
        [8, 0, 1, 0, 8, 0, 0, 34, 727],
    ),
    (
        "bitterli-material-testball/material-testball.pbrt",
        [4, 1, 0, 0, 4, 1, 0, 32, 81],
    ),
    (
        "bitterli-veach-mis/scene-v4.pbrt",
        [9, 0, 3, 0, 6, 0, 0, 48, 1056],
    ),
    ("bmw-m6/bmw-m6.pbrt", [114, 1, 0, 0, 28, 0, 0, 451, 236]),
    (
        "caustic-glass/caustic-glass-v4.pbrt",
        [2, 1, 0, 2, 0, 0, 0, 17, 21],
    ),
    (
        "killeroos/geometry/killeroo.pbrt",
        [1, 0, 0, 0, 0, 0, 0, 1, 37819],
    ),
    (
        "killeroos/geometry/killeroo3.pbrt",
        [1, 0, 0, 0, 0, 0, 0, 1, 37819],
    ),
    (
        "killeroos/killeroo-coated-gold.pbrt",
        [5, 1, 1, 4, 0, 2, 1, 30, 37923],
    ),
    (
        "killeroos/killeroo-gold.pbrt",
        [5, 1, 1, 4, 0, 2, 1, 30, 37922],
    ),
    (
        "killeroos/killeroo-simple.pbrt",
        [5, 0, 1, 4, 0, 0, 2, 29, 75713],
    ),
    (
        "sportscar-pbrt-v4/geometry/geometry.pbrt",
        [48, 0, 0, 0, 0, 0, 0, 199, 48],
    ),
    (
        "sportscar-pbrt-v4/materials.pbrt",
        [0, 0, 0, 0, 48, 0, 0, 48, 195],
    ),
    (
        "sportscar-pbrt-v4/sportscar-area-lights.pbrt",
        [53, 0, 5, 0, 48, 0, 2, 283, 331],
    ),
    (
        "sportscar-pbrt-v4/sportscar-sky.pbrt",
        [48, 1, 5, 0, 48, 0, 2, 282, 266],
    ),
];

fn parse(path: &std::path::Path) -> Recorder {
    let mut rec = Recorder::new();
    if let Err(e) = parse_file(path, &mut rec) {
        panic!("{e}");
    }
    rec
}

#[test]
fn every_scene_file_parses_with_pinned_counts() {
    let Some(dir) = common::scenes_dir() else {
        return;
    };
    let files = common::pbrt_files(&dir);
    let names: Vec<String> = files
        .iter()
        .map(|p| p.strip_prefix(&dir).unwrap().display().to_string())
        .collect();
    let pinned: Vec<&str> = PINNED.iter().map(|p| p.0).collect();
    assert_eq!(names, pinned, "the set of scene files changed");
    for (path, (name, n)) in files.iter().zip(PINNED) {
        let rec = parse(path);
        let c = count(&rec);
        let got = [
            c.shapes,
            c.lights,
            c.area_lights,
            c.materials,
            c.named_materials,
            c.textures,
            c.includes,
            c.calls,
            c.values,
        ];
        assert_eq!(&got, n, "{name}");
        assert!(rec.warnings.is_empty(), "{name}: {:?}", rec.warnings);
    }
}

#[test]
fn killeroo_subdivision_mesh_is_read_exactly() {
    let Some(dir) = common::scenes_dir() else {
        return;
    };
    let rec = parse(&dir.join("killeroos/geometry/killeroo.pbrt"));
    let Directive::Shape(ty, params) = &rec.calls[0].0 else {
        panic!("expected a shape, got {:?}", rec.calls[0].0)
    };
    assert_eq!(ty, "loopsubdiv");
    assert_eq!(params.get_int("levels"), Some(1));
    let p = params.get_point3s("P").unwrap();
    let idx = params.get_ints("indices").unwrap();
    assert_eq!(p[0], [-36.876, 26.033, -137.748]);
    assert_eq!(p.len() * 3 + idx.len() + 1, 37819);
    assert_eq!(idx.len() % 3, 0);
    assert!(idx.iter().all(|&i| i >= 0 && (i as usize) < p.len()));
    assert_eq!(params.unused().count(), 0);
}

#[test]
fn included_files_are_reported_and_located() {
    let Some(dir) = common::scenes_dir() else {
        return;
    };
    let rec = parse(&dir.join("killeroos/killeroo-simple.pbrt"));
    // The main file and two includes of geometry/killeroo.pbrt, each begun and ended.
    assert_eq!(rec.files.len(), 6);
    let shapes: Vec<_> = rec
        .calls
        .iter()
        .filter(|(c, _)| matches!(c, Directive::Shape(t, _) if t == "loopsubdiv"))
        .map(|(_, loc)| loc)
        .collect();
    assert_eq!(shapes.len(), 2);
    for loc in shapes {
        assert!(loc.file.ends_with("geometry/killeroo.pbrt"), "{loc}");
        assert_eq!((loc.line, loc.column), (1, 1));
    }
}
