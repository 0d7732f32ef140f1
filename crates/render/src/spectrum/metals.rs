//! RGB reductions of pbrt-v4's named spectra used by materials: the metal
//! optical constants (`"metal-Au-eta"`, `"metal-Au-k"`, ...) and the named
//! glasses (`"glass-BK7"`, ...).
//!
//! Metals: computed by this project with
//! [`super::spectrum_file_to_rgb`] (band averages of the measured
//! spectra: red 600–700 nm, green 500–600 nm, blue 400–500 nm) from the
//! luxpop.com optical-constant files shipped with the shared scenes
//! (`scenes/spectra/{Ag,Al,Au,Cu}.{eta,k}.spd`, the same data pbrt-v4 embeds);
//! a test re-derives them from those files when present. pbrt-v4's other
//! named metals (CuZn, MgO, TiO2) have no data here: [`named_spectrum_rgb`]
//! returns `None` for them and the caller decides the fallback.
//!
//! Glasses: pbrt-v4 uses dispersive spectra; an RGB renderer needs one
//! index, so each glass is reduced to its catalogue refractive index `n_d` at
//! the helium d line (587.6 nm, Schott data sheets).

use super::Rgb;

/// `(name, [r, g, b])` for the named metal spectra.
pub const NAMED_METALS: [(&str, [f32; 3]); 8] = [
    ("metal-Ag-eta", [0.136_293, 0.125_141, 0.150_100]),
    ("metal-Ag-k", [4.127_181, 3.336_757, 2.462_041]),
    ("metal-Al-eta", [1.486_911, 0.967_191, 0.621_731]),
    ("metal-Al-k", [7.795_373, 6.679_945, 5.470_626]),
    ("metal-Au-eta", [0.176_072, 0.411_782, 1.417_957]),
    ("metal-Au-k", [3.302_028, 2.595_472, 1.880_714]),
    ("metal-Cu-eta", [0.242_674, 0.875_739, 1.162_401]),
    ("metal-Cu-k", [3.604_633, 2.644_739, 2.380_738]),
];

/// `(name, n_d)` for pbrt-v4's named glasses (Schott catalogue `n_d`).
pub const NAMED_GLASSES: [(&str, f32); 7] = [
    ("glass-BK7", 1.5168),
    ("glass-BAF10", 1.6700),
    ("glass-FK51A", 1.4866),
    ("glass-LASF9", 1.8503),
    ("glass-F5", 1.6727),
    ("glass-F10", 1.7283),
    ("glass-F11", 1.7847),
];

/// The RGB value of a named metal spectrum (`"metal-Cu-eta"` ...), or `None`
/// when the name is unknown.
pub fn named_spectrum_rgb(name: &str) -> Option<Rgb> {
    NAMED_METALS
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, v)| Rgb::from_array(*v))
}

/// The scalar index of refraction of a named glass, or `None`.
pub fn named_glass_eta(name: &str) -> Option<f32> {
    NAMED_GLASSES
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, v)| *v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bsdf::fresnel::fr_complex_colour;
    use crate::spectrum::spectrum_file_to_rgb;

    #[test]
    fn table_matches_the_shared_spectra() {
        let Some(dir) = shared_scenes::file("spectra") else {
            return;
        };
        let dir = dir.display();
        for (name, want) in NAMED_METALS {
            // "metal-Au-eta" -> "Au.eta.spd"
            let rest = name.strip_prefix("metal-").unwrap();
            let (metal, which) = rest.split_once('-').unwrap();
            let got = spectrum_file_to_rgb(format!("{dir}/{metal}.{which}.spd")).unwrap();
            for c in 0..3 {
                assert!(
                    (got[c] - want[c]).abs() < 1e-5,
                    "{name}: {got:?} vs {want:?}"
                );
            }
        }
    }

    #[test]
    fn metals_look_like_metals() {
        let refl = |m: &str| {
            let eta = named_spectrum_rgb(&format!("metal-{m}-eta")).unwrap();
            let k = named_spectrum_rgb(&format!("metal-{m}-k")).unwrap();
            fr_complex_colour(1.0, eta, k)
        };
        let (au, ag, al, cu) = (refl("Au"), refl("Ag"), refl("Al"), refl("Cu"));
        // Gold and copper are red-yellow (red > blue); silver and aluminium
        // are bright and nearly grey.
        assert!(au.r > 0.9 && au.b < 0.5 * au.r, "{au:?}");
        assert!(cu.r > 0.9 && cu.b < 0.7 * cu.r, "{cu:?}");
        assert!(ag.min_component() > 0.9, "{ag:?}");
        assert!(
            al.min_component() > 0.85 && al.max_component() < 0.95,
            "{al:?}"
        );
        assert!(named_spectrum_rgb("metal-CuZn-eta").is_none());
        assert_eq!(named_glass_eta("glass-BK7"), Some(1.5168));
        assert_eq!(named_glass_eta("glass-nope"), None);
    }
}
