//! Measured spectra from pbrt `.spd` files ("wavelength value" pairs,
//! wavelengths in nm, `#` comments) and their reduction to RGB for RGB
//! mode: the piecewise-linear spectrum averaged over three rough bands,
//! blue 400–500 nm, green 500–600 nm, red 600–700 nm
//! ([`spectrum_samples_to_rgb`]). This is a crude projection (no colour
//! matching functions), adequate for the smooth optical constants of
//! metals; spectral mode evaluates the spectra themselves.

use super::Rgb;
use std::path::{Path, PathBuf};

/// Errors from reading a spectrum file.
#[derive(Debug)]
pub enum SpectrumError {
    /// The file could not be read.
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// A token is not a number, or the values do not come in pairs.
    Parse {
        /// The file.
        path: PathBuf,
        /// 1-based line of the problem.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// The spectrum does not cover the visible bands (400–700 nm) or its
    /// wavelengths are not increasing.
    Range {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
}

impl std::fmt::Display for SpectrumError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SpectrumError::Io { path, source } => write!(f, "{}: {source}", path.display()),
            SpectrumError::Parse {
                path,
                line,
                message,
            } => write!(f, "{}:{line}: {message}", path.display()),
            SpectrumError::Range { path, message } => write!(f, "{}: {message}", path.display()),
        }
    }
}

impl std::error::Error for SpectrumError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            SpectrumError::Io { source, .. } => Some(source),
            _ => None,
        }
    }
}

/// The bands (nm) averaged for the red, green and blue channels, in that
/// order: 600–700, 500–600, 400–500.
pub const RGB_BANDS_NM: [(f32, f32); 3] = [(600.0, 700.0), (500.0, 600.0), (400.0, 500.0)];

/// Parses "wavelength value" pairs (whitespace separated, `#` comments) from
/// the text of a pbrt `.spd` file. `path` is used in error messages only.
pub fn parse_spectrum_text(text: &str, path: &Path) -> Result<Vec<(f32, f32)>, SpectrumError> {
    let mut values = Vec::new();
    let mut last_line = 0;
    for (i, line) in text.lines().enumerate() {
        let content = line.split('#').next().unwrap_or("");
        for tok in content.split_whitespace() {
            let v: f32 = tok.parse().map_err(|_| SpectrumError::Parse {
                path: path.to_path_buf(),
                line: i + 1,
                message: format!("not a number: {tok:?}"),
            })?;
            if !v.is_finite() {
                return Err(SpectrumError::Parse {
                    path: path.to_path_buf(),
                    line: i + 1,
                    message: format!("non-finite value {tok:?}"),
                });
            }
            values.push(v);
            last_line = i + 1;
        }
    }
    if values.len() % 2 != 0 {
        return Err(SpectrumError::Parse {
            path: path.to_path_buf(),
            line: last_line,
            message: "odd number of values: expected wavelength/value pairs".into(),
        });
    }
    Ok(values.chunks(2).map(|c| (c[0], c[1])).collect())
}

/// Reduces sampled `(wavelength nm, value)` pairs to RGB by averaging the
/// piecewise-linear spectrum over [`RGB_BANDS_NM`]. Wavelengths must increase
/// and cover 400–700 nm.
pub fn spectrum_samples_to_rgb(samples: &[(f32, f32)], path: &Path) -> Result<Rgb, SpectrumError> {
    let range_err = |message: String| SpectrumError::Range {
        path: path.to_path_buf(),
        message,
    };
    if samples.len() < 2 {
        return Err(range_err("fewer than two samples".into()));
    }
    if samples.windows(2).any(|w| !(w[1].0 > w[0].0)) {
        return Err(range_err("wavelengths are not strictly increasing".into()));
    }
    let (first, last) = (samples[0].0, samples[samples.len() - 1].0);
    if first > 400.0 || last < 700.0 {
        return Err(range_err(format!(
            "spectrum covers {first}..{last} nm, not 400..700 nm"
        )));
    }
    let mut out = [0.0f32; 3];
    for (c, &(lo, hi)) in RGB_BANDS_NM.iter().enumerate() {
        // Exact integral of the piecewise-linear interpolant over [lo, hi].
        let mut integral = 0.0f64;
        for w in samples.windows(2) {
            let ((x0, y0), (x1, y1)) = (w[0], w[1]);
            let a = x0.max(lo);
            let b = x1.min(hi);
            if b <= a {
                continue;
            }
            let at = |x: f32| y0 as f64 + (y1 - y0) as f64 * ((x - x0) / (x1 - x0)) as f64;
            integral += 0.5 * (at(a) + at(b)) * (b - a) as f64;
        }
        out[c] = (integral / (hi - lo) as f64) as f32;
    }
    Ok(Rgb::from_array(out))
}

/// Reads a pbrt `.spd` file ("wavelength value" pairs, nm) and reduces it to
/// RGB `[r, g, b]` with [`spectrum_samples_to_rgb`].
pub fn spectrum_file_to_rgb(path: impl AsRef<Path>) -> Result<[f32; 3], SpectrumError> {
    let path = path.as_ref();
    let bytes = lowdisc_files::read_input(path).map_err(|e| SpectrumError::Io {
        path: path.to_path_buf(),
        source: std::io::Error::new(e.io_error().kind(), e.io_error().to_string()),
    })?;
    let text = String::from_utf8(bytes).map_err(|e| SpectrumError::Io {
        path: path.to_path_buf(),
        source: std::io::Error::new(std::io::ErrorKind::InvalidData, e.utf8_error()),
    })?;
    let samples = parse_spectrum_text(&text, path)?;
    Ok(spectrum_samples_to_rgb(&samples, path)?.to_array())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p() -> &'static Path {
        Path::new("test.spd")
    }

    #[test]
    fn band_averages_are_exact_for_linear_spectra() {
        let flat = [(380.0, 2.0), (720.0, 2.0)];
        assert_eq!(
            spectrum_samples_to_rgb(&flat, p()).unwrap(),
            Rgb::splat(2.0)
        );
        // value = wavelength / 100: band means are the band midpoints / 100.
        let ramp = [(350.0, 3.5), (450.0, 4.5), (800.0, 8.0)];
        let c = spectrum_samples_to_rgb(&ramp, p()).unwrap();
        assert!((c.r - 6.5).abs() < 1e-5 && (c.g - 5.5).abs() < 1e-5 && (c.b - 4.5).abs() < 1e-5);
    }

    #[test]
    fn parsing_and_errors() {
        let s = parse_spectrum_text("# header\n400 1.5 # c\n500 2\n\n700 3\n", p()).unwrap();
        assert_eq!(s, vec![(400.0, 1.5), (500.0, 2.0), (700.0, 3.0)]);
        let e = parse_spectrum_text("400 1\n500 x\n", p()).unwrap_err();
        assert!(matches!(e, SpectrumError::Parse { line: 2, .. }), "{e}");
        let e = parse_spectrum_text("400 1\n500\n", p()).unwrap_err();
        assert!(matches!(e, SpectrumError::Parse { .. }), "{e}");
        let short = [(450.0, 1.0), (800.0, 1.0)];
        assert!(matches!(
            spectrum_samples_to_rgb(&short, p()),
            Err(SpectrumError::Range { .. })
        ));
        let unsorted = [(300.0, 1.0), (800.0, 1.0), (700.0, 1.0)];
        assert!(spectrum_samples_to_rgb(&unsorted, p()).is_err());
        let missing = spectrum_file_to_rgb("/nonexistent/x.spd").unwrap_err();
        assert!(matches!(missing, SpectrumError::Io { .. }));
        assert!(missing.to_string().contains("/nonexistent/x.spd"));
    }
}
