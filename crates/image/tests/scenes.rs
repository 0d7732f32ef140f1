//! The real image files of the shared scene folder load with plausible
//! contents. Skipped with a message when the folder is absent.

use std::path::{Path, PathBuf};

use lowdisc_image::{ReadOptions, crop, read_image, read_image_with, stats};

fn scenes() -> Option<PathBuf> {
    shared_scenes::existing(shared_scenes::dir())
}

fn files_with_extension(dir: &Path, ext: &str) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|r| r.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    files.retain(|p| p.extension().is_some_and(|e| e.eq_ignore_ascii_case(ext)));
    files.sort();
    files
}

#[test]
fn radiance_hdr_envmaps_load() {
    let Some(root) = scenes() else { return };
    let maps = files_with_extension(&root.join("envmaps"), "hdr");
    if maps.is_empty() {
        shared_scenes::skip(&format!(
            "no .hdr files in {}",
            root.join("envmaps").display()
        ));
        return;
    }
    for path in maps {
        let img = read_image(&path).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            (img.width(), img.height()),
            (1024, 512),
            "{}",
            path.display()
        );
        let s = stats(&img);
        assert!(s.all_finite(), "{}", path.display());
        assert_eq!(s.negative_count, 0, "{}", path.display());
        assert!(
            s.mean_luminance > 0.0 && s.mean.iter().all(|&m| m > 0.0),
            "{}: {s:?}",
            path.display()
        );
        // A real sky has a range of values, not one constant.
        assert!(s.max[1] > 2.0 * s.min[1], "{}: {s:?}", path.display());
        // Rows run top to bottom (-Y): the sky half is brighter than the ground half.
        let half = img.height() / 2;
        let top = stats(&crop(&img, 0, 0, img.width(), half).unwrap());
        let bottom = stats(&crop(&img, 0, half, img.width(), half).unwrap());
        assert!(
            top.mean_luminance > bottom.mean_luminance,
            "{}",
            path.display()
        );
        // An independent decoder (the `image` crate's) gives the same values.
        let other = image::ImageReader::open(&path)
            .and_then(|r| r.with_guessed_format())
            .map_err(|e| e.to_string())
            .and_then(|r| r.decode().map_err(|e| e.to_string()))
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
            .to_rgb32f();
        assert_eq!(
            (other.width() as usize, other.height() as usize),
            (1024, 512)
        );
        for (ours, theirs) in img.pixels().iter().zip(other.pixels()) {
            assert_eq!(*ours, theirs.0, "{}", path.display());
        }
    }
}

#[test]
fn exr_envmaps_load() {
    let Some(root) = scenes() else { return };
    let maps = files_with_extension(&root.join("envmaps"), "exr");
    if maps.is_empty() {
        shared_scenes::skip(&format!(
            "no .exr files in {}",
            root.join("envmaps").display()
        ));
        return;
    }
    for path in maps {
        let img = read_image(&path).unwrap_or_else(|e| panic!("{e}"));
        let s = stats(&img);
        assert!(s.all_finite(), "{}", path.display());
        assert!(s.mean_luminance > 0.0, "{}: {s:?}", path.display());
        println!(
            "{}: {}x{}, mean {:?}",
            path.display(),
            img.width(),
            img.height(),
            s.mean
        );
    }
}

#[test]
fn classroom_skydome_pfm_and_textures_load() {
    let Some(root) = scenes() else { return };
    let textures = root.join("bitterli-classroom/textures");
    let sky = textures.join("Skydome.pfm");
    if !sky.is_file() {
        shared_scenes::skip(&format!("{} is absent", sky.display()));
        return;
    }
    let img = read_image(&sky).unwrap_or_else(|e| panic!("{e}"));
    // The header says PF 512 512 -1.0 (little endian).
    assert_eq!((img.width(), img.height()), (512, 512));
    let s = stats(&img);
    assert!(s.all_finite());
    assert!(s.mean_luminance > 0.0, "{s:?}");
    for path in files_with_extension(&textures, "tga") {
        let colour = read_image(&path).unwrap_or_else(|e| panic!("{e}"));
        let raw = read_image_with(&path, &ReadOptions::raw()).unwrap();
        assert!(colour.same_size(&raw));
        let (sc, sr) = (stats(&colour), stats(&raw));
        assert!(
            sc.all_finite() && sc.mean_luminance > 0.0,
            "{}",
            path.display()
        );
        assert!(sr.max.iter().all(|&v| v <= 1.0));
        // sRGB decoding darkens mid-tones: the linear mean is below the raw mean.
        assert!(sc.mean_luminance < sr.mean_luminance, "{}", path.display());
    }
}

#[test]
fn killeroos_png_texture_loads() {
    let Some(root) = scenes() else { return };
    let path = root.join("killeroos/textures/lines.png");
    if !path.is_file() {
        shared_scenes::skip(&format!("{} is absent", path.display()));
        return;
    }
    let img = read_image(&path).unwrap_or_else(|e| panic!("{e}"));
    let s = stats(&img);
    assert!(s.all_finite() && s.max.iter().all(|&v| v <= 1.0), "{s:?}");
}
