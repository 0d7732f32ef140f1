//! The `Film`'s `"float whitebalance"` against its analytic truth: pbrt-v4
//! (film with the `cie1931` sensor) adapts the white of the CIE daylight
//! illuminant `D(T)` to the output's white by von Kries scaling in
//! Bradford's cone space, a linear map of each pixel. White balance changes
//! no sample, so a balanced render must be the unbalanced one with every
//! pixel multiplied by `M = sRGB←XYZ · WB(D(T) → D65) · XYZ←sRGB`, in RGB
//! and in spectral mode alike.

use lowdisc::catalog::SamplerName;
use lowdisc_colour::cie::{chromaticity, daylight, spectrum_to_xyz};
use lowdisc_colour::matrix::{Mat3, white_balance};
use lowdisc_colour::srgb;
use lowdisc_render::pbrt::{LoadOptions, load_pbrt_scene};
use lowdisc_render::render::{NoProgress, RenderOptions, render};
use lowdisc_render::view::View;
use std::path::PathBuf;

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("lowdisc-wb-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A red diffuse sphere under a bluish sky and a warm point light.
fn scene(film: &str) -> String {
    format!(
        "LookAt 0 0 -4  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n\
         Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 6 {film}\n\
         WorldBegin\n\
         LightSource \"infinite\" \"rgb L\" [0.3 0.5 0.9]\n\
         LightSource \"point\" \"point3 from\" [2 2 -3] \"rgb I\" [9 6 3]\n\
         Material \"diffuse\" \"rgb reflectance\" [0.7 0.2 0.1]\n\
         Shape \"sphere\" \"float radius\" 1\n"
    )
}

/// The image of `scene(film)` (RGB or spectral), as rows of pixels.
fn render_film(name: &str, film: &str, spectral: bool) -> Vec<[f32; 3]> {
    let path = temp_dir(name).join("scene.pbrt");
    std::fs::write(&path, scene(film)).unwrap();
    let loaded = load_pbrt_scene(&path, &LoadOptions::default()).unwrap();
    let opts = RenderOptions {
        spectral,
        ..RenderOptions::new(SamplerName::ZSobol, 3, 4)
    };
    let view = View::native(&loaded.view).unwrap();
    let out = render(&loaded.scene, &view, &opts, &NoProgress).unwrap();
    out.image.pixels().to_vec()
}

/// `M` for `kelvin`, from the colour crate's published tables and formulas.
fn analytic(kelvin: f32) -> Mat3 {
    let d = daylight(kelvin);
    let src = chromaticity(spectrum_to_xyz(|l| d.eval(l))).map(f64::from);
    let s = srgb();
    s.rgb_from_xyz
        .mul(&white_balance(src, s.white))
        .mul(&s.xyz_from_rgb)
}

fn assert_balanced(kelvin: f32, spectral: bool) {
    let name = format!("{kelvin}-{spectral}");
    let plain = render_film(&format!("{name}-plain"), "", spectral);
    let film = format!("\"float whitebalance\" {kelvin}");
    let balanced = render_film(&format!("{name}-wb"), &film, spectral);
    let m = analytic(kelvin);
    let mut changed = false;
    for (p, b) in plain.iter().zip(&balanced) {
        let want = m.apply(p.map(f64::from));
        for c in 0..3 {
            let tol = 1e-5 * (1.0 + want[c].abs());
            assert!(
                (f64::from(b[c]) - want[c]).abs() < tol,
                "{kelvin} K, spectral {spectral}: {b:?} is not M · {p:?} = {want:?}"
            );
            changed |= (b[c] - p[c]).abs() > 1e-3 * p[c].abs().max(1e-3);
        }
    }
    assert!(changed, "{kelvin} K changed no pixel");
}

#[test]
fn whitebalance_multiplies_rgb_pixels_by_the_von_kries_matrix() {
    assert_balanced(3000.0, false);
    assert_balanced(9000.0, false);
}

#[test]
fn whitebalance_multiplies_spectral_pixels_by_the_von_kries_matrix() {
    assert_balanced(4000.0, true);
}

#[test]
fn whitebalance_zero_is_no_balance() {
    let plain = render_film("zero-plain", "", false);
    let zero = render_film("zero-wb", "\"float whitebalance\" 0", false);
    assert_eq!(plain, zero);
}

#[test]
fn a_negative_whitebalance_is_an_error_at_the_film() {
    let path = temp_dir("negative").join("scene.pbrt");
    std::fs::write(&path, scene("\"float whitebalance\" -5")).unwrap();
    let e = load_pbrt_scene(&path, &LoadOptions::default()).unwrap_err();
    let msg = e.to_string();
    assert!(
        msg.contains("scene.pbrt:3:") && msg.contains("whitebalance"),
        "{msg}"
    );
}
