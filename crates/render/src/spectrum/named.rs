//! Spectra given by name or by physics, for spectral mode: pbrt-v4's named
//! metals (`"metal-Au-eta"`, `"metal-Au-k"`, ... for Ag, Al, Au, Cu), and
//! emission spectra (blackbodies, sampled or file spectra of lights)
//! normalised to luminance 1 as pbrt-v4's lights are.
//!
//! The metals' optical constants are the luxpop.com measurements that
//! pbrt-v4 and Mitsuba also ship, embedded from `data/spectra/*.spd`
//! (copied from Mitsuba's distribution; its licence is
//! `data/spectra/LICENSE-mitsuba.txt`). Each keeps its RGB-mode value, the
//! band averages of [`super::metals::NAMED_METALS`].
//!
//! A blackbody of temperature `T` is Planck's law; like every emission
//! spectrum here it is scaled so that `∫ ȳ(λ) s(λ) dλ = 1` (1 nm sums), which
//! is pbrt-v4's `BlackbodySpectrum` (normalised to its peak) after the
//! light's `scale /= SpectrumToPhotometric(L)`.

use super::Rgb;
use super::file::parse_spectrum_text;
use super::metals::NAMED_METALS;
use crate::content_hash::{ContentHash, ContentSink};
use lowdisc_colour::cie::{LAMBDA_MAX, LAMBDA_MIN, Tabulated, y_integral};
use std::path::Path;
use std::sync::LazyLock;

/// An emission spectrum of luminance 1, shared by the lights it belongs to.
pub type EmissionSpectrum = std::sync::Arc<Tabulated>;

/// A measured spectrum and its RGB-mode value.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedSpectrum {
    /// pbrt-v4's name, e.g. `"metal-Au-eta"`.
    pub name: &'static str,
    /// The measurements, linear between samples.
    pub spectrum: Tabulated,
    /// The value RGB mode uses.
    pub rgb: Rgb,
}

/// The embedded `.spd` text of a named metal spectrum.
fn metal_data(name: &str) -> Option<&'static str> {
    Some(match name {
        "metal-Ag-eta" => include_str!("../../data/spectra/Ag.eta.spd"),
        "metal-Ag-k" => include_str!("../../data/spectra/Ag.k.spd"),
        "metal-Al-eta" => include_str!("../../data/spectra/Al.eta.spd"),
        "metal-Al-k" => include_str!("../../data/spectra/Al.k.spd"),
        "metal-Au-eta" => include_str!("../../data/spectra/Au.eta.spd"),
        "metal-Au-k" => include_str!("../../data/spectra/Au.k.spd"),
        "metal-Cu-eta" => include_str!("../../data/spectra/Cu.eta.spd"),
        "metal-Cu-k" => include_str!("../../data/spectra/Cu.k.spd"),
        _ => return None,
    })
}

static METALS: LazyLock<Vec<NamedSpectrum>> = LazyLock::new(|| {
    NAMED_METALS
        .iter()
        .filter_map(|&(name, rgb)| {
            let text = metal_data(name)?;
            let samples = parse_spectrum_text(text, Path::new(name)).ok()?;
            let (lambda, value) = samples.into_iter().unzip();
            Some(NamedSpectrum {
                name,
                spectrum: Tabulated { lambda, value },
                rgb: Rgb::from_array(rgb),
            })
        })
        .collect()
});

/// The named metal spectrum `name` (`"metal-Cu-eta"` ...), if embedded.
pub fn named_metal(name: &str) -> Option<&'static NamedSpectrum> {
    METALS.iter().find(|m| m.name == name)
}

/// Measured spectra read from scene files (`"spectrum eta" "Au.eta.spd"`,
/// inline samples), kept for the rest of the process: materials refer to
/// spectra by `&'static` reference. Each distinct content is stored once,
/// so memory is bounded by the distinct spectra of the scenes loaded.
static INTERNED: std::sync::Mutex<Vec<&'static NamedSpectrum>> = std::sync::Mutex::new(Vec::new());

/// The measured spectrum of `samples` (`(λ nm, value)`, increasing), whose
/// RGB-mode value is `rgb`, as a `'static` reference (see [`INTERNED`]).
pub fn intern_measured(name: &str, samples: &[(f32, f32)], rgb: Rgb) -> &'static NamedSpectrum {
    let (lambda, value) = samples.iter().copied().unzip();
    let spectrum = Tabulated { lambda, value };
    let mut all = INTERNED.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(s) = all.iter().find(|s| s.spectrum == spectrum && s.rgb == rgb) {
        return s;
    }
    let s: &'static NamedSpectrum = Box::leak(Box::new(NamedSpectrum {
        name: Box::leak(name.to_string().into_boxed_str()),
        spectrum,
        rgb,
    }));
    all.push(s);
    s
}

/// Planck's law at `lambda_nm` for temperature `t` kelvin (relative units).
pub fn planck(lambda_nm: f64, t: f64) -> f64 {
    const C: f64 = 299_792_458.0;
    const H: f64 = 6.626_070_15e-34;
    const KB: f64 = 1.380_649e-23;
    let l = lambda_nm * 1e-9;
    2.0 * H * C * C / (l.powi(5) * ((H * C / (l * KB * t)).exp() - 1.0))
}

/// `f` tabulated at every nanometre 360..=830 and scaled to `∫ ȳ f = 1`, or
/// `None` when that integral is not positive and finite.
pub fn unit_luminance(f: impl Fn(f32) -> f32) -> Option<Tabulated> {
    let lambda: Vec<f32> = (0..=(LAMBDA_MAX - LAMBDA_MIN) as usize)
        .map(|i| LAMBDA_MIN + i as f32)
        .collect();
    let value: Vec<f32> = lambda.iter().map(|&l| f(l)).collect();
    let t = Tabulated { lambda, value };
    let y = y_integral(|l| t.eval(l));
    (y > 0.0 && y.is_finite()).then(|| t.scaled(1.0 / y))
}

/// A blackbody's emission spectrum of luminance 1, or `None` for a
/// temperature that is not positive and finite.
pub fn blackbody(t: f64) -> Option<Tabulated> {
    if !(t > 0.0 && t.is_finite()) {
        return None;
    }
    unit_luminance(|l| planck(f64::from(l), t) as f32)
}

/// The emission spectrum of sampled `(λ nm, value)` pairs (linear between
/// them, constant beyond the ends as pbrt-v4 extends them), luminance 1.
pub fn sampled_emission(samples: &[(f32, f32)]) -> Option<Tabulated> {
    let (first, last) = (samples.first()?, samples.last()?);
    let (lambda, value) = samples.iter().copied().unzip();
    let t = Tabulated { lambda, value };
    unit_luminance(|l| {
        if l <= first.0 {
            first.1
        } else if l >= last.0 {
            last.1
        } else {
            t.eval(l)
        }
    })
}

impl ContentHash for Tabulated {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let Tabulated { lambda, value } = self;
        lambda.feed(sink);
        value.feed(sink);
    }
}

impl ContentHash for NamedSpectrum {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let NamedSpectrum {
            name,
            spectrum,
            rgb,
        } = self;
        name.feed(sink);
        spectrum.feed(sink);
        rgb.feed(sink);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spectrum::spectrum_samples_to_rgb;

    #[test]
    fn embedded_metals_reduce_to_the_rgb_table() {
        assert_eq!(METALS.len(), NAMED_METALS.len());
        for m in METALS.iter() {
            let pairs: Vec<(f32, f32)> = m
                .spectrum
                .lambda
                .iter()
                .copied()
                .zip(m.spectrum.value.iter().copied())
                .collect();
            let rgb = spectrum_samples_to_rgb(&pairs, Path::new(m.name)).unwrap();
            for c in 0..3 {
                assert!((rgb[c] - m.rgb[c]).abs() < 1e-5, "{}: {rgb:?}", m.name);
            }
        }
        assert!(named_metal("metal-CuZn-eta").is_none());
        // Gold absorbs blue: k is larger in the red than in the blue.
        let k = &named_metal("metal-Au-k").unwrap().spectrum;
        assert!(k.eval(650.0) > k.eval(450.0));
    }

    #[test]
    fn emission_spectra_have_unit_luminance() {
        let b = blackbody(6500.0).unwrap();
        assert!((y_integral(|l| b.eval(l)) - 1.0).abs() < 1e-5);
        // Hotter is bluer.
        let (cold, hot) = (blackbody(2000.0).unwrap(), blackbody(10000.0).unwrap());
        assert!(cold.eval(450.0) / cold.eval(650.0) < hot.eval(450.0) / hot.eval(650.0));
        assert!(blackbody(0.0).is_none() && blackbody(f64::NAN).is_none());
        let flat = sampled_emission(&[(500.0, 2.0), (600.0, 2.0)]).unwrap();
        assert!((flat.eval(400.0) - flat.eval(700.0)).abs() < 1e-9);
        assert!(sampled_emission(&[(500.0, 0.0), (600.0, 0.0)]).is_none());
    }
}
