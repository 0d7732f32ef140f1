//! Colours, a categorical palette for series and panels, and colour maps for
//! heatmaps.

/// An sRGB colour with alpha (not premultiplied).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Color {
    /// Red.
    pub r: u8,
    /// Green.
    pub g: u8,
    /// Blue.
    pub b: u8,
    /// Opacity (255 = opaque).
    pub a: u8,
}

impl Color {
    /// Opaque black.
    pub const BLACK: Color = Color::rgb(0, 0, 0);
    /// Opaque white.
    pub const WHITE: Color = Color::rgb(255, 255, 255);
    /// A light grey for grid lines.
    pub const GRID: Color = Color::rgb(215, 215, 215);
    /// A mid grey for secondary text and boundaries.
    pub const GREY: Color = Color::rgb(110, 110, 110);

    /// An opaque colour.
    pub const fn rgb(r: u8, g: u8, b: u8) -> Color {
        Color { r, g, b, a: 255 }
    }

    /// The same colour with opacity `a`.
    pub const fn with_alpha(self, a: u8) -> Color {
        Color { a, ..self }
    }

    /// `#rrggbb` (opacity is written separately in SVG).
    pub fn hex(self) -> String {
        format!("#{:02x}{:02x}{:02x}", self.r, self.g, self.b)
    }

    /// Colour `i` of a 10-colour categorical palette (cycled); the hues of
    /// the widely used "category10" palette.
    pub fn palette(i: usize) -> Color {
        const P: [Color; 10] = [
            Color::rgb(31, 119, 180),
            Color::rgb(214, 39, 40),
            Color::rgb(44, 160, 44),
            Color::rgb(255, 127, 14),
            Color::rgb(148, 103, 189),
            Color::rgb(140, 86, 75),
            Color::rgb(227, 119, 194),
            Color::rgb(127, 127, 127),
            Color::rgb(188, 189, 34),
            Color::rgb(23, 190, 207),
        ];
        P[i % P.len()]
    }

    fn lerp(self, other: Color, t: f64) -> Color {
        let m = |a: u8, b: u8| (f64::from(a) + (f64::from(b) - f64::from(a)) * t).round() as u8;
        Color::rgb(m(self.r, other.r), m(self.g, other.g), m(self.b, other.b))
    }
}

/// A map from `[0, 1]` to colours.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ColorMap {
    /// Perceptually uniform dark-blue to yellow (viridis, 10 published stops
    /// interpolated linearly).
    #[default]
    Viridis,
    /// Black to white.
    Gray,
    /// Blue through light grey to red, for signed quantities centred on 0.5.
    Diverging,
}

impl ColorMap {
    /// The colour of `t` (clamped to `[0, 1]`; NaN maps to magenta).
    pub fn map(self, t: f64) -> Color {
        if t.is_nan() {
            return Color::rgb(255, 0, 255);
        }
        let t = t.clamp(0.0, 1.0);
        match self {
            ColorMap::Viridis => interpolate(&VIRIDIS, t),
            ColorMap::Gray => interpolate(&[Color::BLACK, Color::WHITE], t),
            ColorMap::Diverging => interpolate(&DIVERGING, t),
        }
    }
}

/// The viridis colour map of matplotlib sampled at `i / 9`.
const VIRIDIS: [Color; 10] = [
    Color::rgb(0x44, 0x01, 0x54),
    Color::rgb(0x48, 0x28, 0x78),
    Color::rgb(0x3e, 0x49, 0x89),
    Color::rgb(0x31, 0x68, 0x8e),
    Color::rgb(0x26, 0x82, 0x8e),
    Color::rgb(0x1f, 0x9e, 0x89),
    Color::rgb(0x35, 0xb7, 0x79),
    Color::rgb(0x6e, 0xce, 0x58),
    Color::rgb(0xb5, 0xde, 0x2b),
    Color::rgb(0xfd, 0xe7, 0x25),
];

const DIVERGING: [Color; 3] = [
    Color::rgb(0x3b, 0x4c, 0xc0),
    Color::rgb(0xdd, 0xdd, 0xdd),
    Color::rgb(0xb4, 0x04, 0x26),
];

fn interpolate(stops: &[Color], t: f64) -> Color {
    let scaled = t * (stops.len() - 1) as f64;
    let i = (scaled.floor() as usize).min(stops.len() - 2);
    stops[i].lerp(stops[i + 1], scaled - i as f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn maps_hit_their_end_stops() {
        assert_eq!(ColorMap::Viridis.map(0.0), VIRIDIS[0]);
        assert_eq!(ColorMap::Viridis.map(1.0), VIRIDIS[9]);
        assert_eq!(ColorMap::Gray.map(0.5), Color::rgb(128, 128, 128));
        assert_eq!(ColorMap::Diverging.map(0.5), DIVERGING[1]);
        assert_eq!(ColorMap::Gray.map(-3.0), Color::BLACK);
        assert_eq!(ColorMap::Gray.map(f64::NAN), Color::rgb(255, 0, 255));
    }

    #[test]
    fn viridis_lightness_rises_at_every_stop() {
        // Rec.709 luminance of the decoded sRGB stops.
        let decode = |c: u8| {
            let v = f64::from(c) / 255.0;
            if v <= 0.04045 {
                v / 12.92
            } else {
                ((v + 0.055) / 1.055).powf(2.4)
            }
        };
        let lum = |c: Color| 0.2126 * decode(c.r) + 0.7152 * decode(c.g) + 0.0722 * decode(c.b);
        for pair in VIRIDIS.windows(2) {
            assert!(lum(pair[1]) > lum(pair[0]), "{pair:?}");
        }
    }

    #[test]
    fn hex_is_lowercase_rrggbb() {
        assert_eq!(Color::rgb(255, 16, 1).hex(), "#ff1001");
    }
}
