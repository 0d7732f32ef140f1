//! RGB to spectrum (spectral mode), as pbrt-v4's `RGBAlbedoSpectrum`,
//! `RGBUnboundedSpectrum` and `RGBIlluminantSpectrum` for sRGB.
//!
//! The sigmoid-polynomial table ([`lowdisc_colour::SigmoidTable`], Jakob &
//! Hanika 2019) is fitted by this project's optimiser when the crate is
//! built (`build.rs`, resolution [`TABLE_RESOLUTION`], a few seconds) and
//! embedded in the library; nothing is read at run time.
//!
//! * albedo: `σ(poly(λ))` with the coefficients of `rgb` clamped to `[0, 1]`;
//! * unbounded: `m = max(r, g, b)`, `2m · σ(poly_{rgb / 2m}(λ))`, so any
//!   non-negative RGB is represented (greys exactly: `(v, v, v)` gives `v`);
//! * illuminant: the unbounded spectrum times the sRGB white, D65,
//!   normalised to luminance 1 (`∫ ȳ D65 = 1`), so `(1, 1, 1)` is white light
//!   of luminance 1, as pbrt-v4's lights after their photometric scaling.
//!
//! **Memo.** A table lookup costs hundreds of instructions and a render
//! asks for the same few colours (constant reflectances, emission) at every
//! vertex, so each thread keeps the spectra of the last [`MEMO_SLOTS`]
//! inputs of [`albedo`] and of [`unbounded`], indexed by a hash of their
//! bits: a hit returns exactly what the table gave for the same bits.

use super::Rgb;
use lowdisc_colour::cie::{LAMBDA_MIN, d65, y_integral};
use lowdisc_colour::sigmoid::{SigmoidTable, eval};
use std::cell::Cell;
use std::sync::LazyLock;
use std::thread::LocalKey;

/// The resolution of the embedded table (its `z` axis and both ratio axes).
pub const TABLE_RESOLUTION: usize = 64;

static TABLE: LazyLock<SigmoidTable> = LazyLock::new(|| {
    SigmoidTable::from_bytes(include_bytes!(concat!(
        env!("OUT_DIR"),
        "/srgb_sigmoid.bin"
    )))
    .expect("build.rs writes a valid table")
});

/// D65 at every nanometre 360..=830, divided by `∫ ȳ D65`.
static D65_UNIT: LazyLock<[f32; 471]> = LazyLock::new(|| {
    let y = y_integral(|l| d65().eval(l));
    std::array::from_fn(|i| d65().eval(LAMBDA_MIN + i as f32) / y)
});

/// The uplift table.
pub fn table() -> &'static SigmoidTable {
    &TABLE
}

/// Entries of each thread's memos of [`albedo`] and [`unbounded`] (a power
/// of 2).
pub const MEMO_SLOTS: usize = 64;

/// One memo entry: the bits of an input colour and its spectrum.
#[derive(Clone, Copy)]
struct MemoEntry {
    filled: bool,
    key: [u32; 3],
    value: RgbSpectrum,
}

/// A memo: [`MEMO_SLOTS`] entries, indexed by a hash of the input's bits.
type Memo = [Cell<MemoEntry>; MEMO_SLOTS];

thread_local! {
    static ALBEDO_MEMO: Memo = const { [const { Cell::new(MemoEntry::EMPTY) }; MEMO_SLOTS] };
    static UNBOUNDED_MEMO: Memo = const { [const { Cell::new(MemoEntry::EMPTY) }; MEMO_SLOTS] };
}

impl MemoEntry {
    const EMPTY: MemoEntry = MemoEntry {
        filled: false,
        key: [0; 3],
        value: RgbSpectrum {
            coefficients: [0.0; 3],
            scale: 0.0,
        },
    };
}

/// `f(rgb)` through this thread's `memo`: the value `f` gave for the same
/// bits, or `f`'s value now (kept for the next call).
#[inline]
fn memoised(
    memo: &'static LocalKey<Memo>,
    rgb: Rgb,
    f: impl FnOnce(Rgb) -> RgbSpectrum,
) -> RgbSpectrum {
    let key = rgb.to_array().map(f32::to_bits);
    let hash = key[0].wrapping_mul(0x9e37_79b1)
        ^ key[1].wrapping_mul(0x85eb_ca77)
        ^ key[2].wrapping_mul(0xc2b2_ae3d);
    let slot = (hash >> (32 - MEMO_SLOTS.trailing_zeros())) as usize;
    memo.with(|memo| {
        let entry = &memo[slot];
        let e = entry.get();
        if e.filled && e.key == key {
            return e.value;
        }
        let value = f(rgb);
        entry.set(MemoEntry {
            filled: true,
            key,
            value,
        });
        value
    })
}

/// A sigmoid-polynomial spectrum times a scale.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RgbSpectrum {
    /// Coefficients for `λ` in nm.
    pub coefficients: [f32; 3],
    /// Multiplies the sigmoid.
    pub scale: f32,
}

impl RgbSpectrum {
    /// The value at `lambda` nm.
    #[inline]
    pub fn eval(&self, lambda: f32) -> f32 {
        self.scale * eval(self.coefficients, lambda)
    }
}

/// The reflectance spectrum of `rgb` (channels clamped to `[0, 1]`).
pub fn albedo(rgb: Rgb) -> RgbSpectrum {
    memoised(&ALBEDO_MEMO, rgb, albedo_from_table)
}

/// [`albedo`] from the table, without the memo.
fn albedo_from_table(rgb: Rgb) -> RgbSpectrum {
    RgbSpectrum {
        coefficients: TABLE.coefficients(rgb.clamp(0.0, 1.0).to_array()),
        scale: 1.0,
    }
}

/// The spectrum of a non-negative `rgb` of any magnitude.
pub fn unbounded(rgb: Rgb) -> RgbSpectrum {
    memoised(&UNBOUNDED_MEMO, rgb, unbounded_from_table)
}

/// [`unbounded`] from the table, without the memo.
fn unbounded_from_table(rgb: Rgb) -> RgbSpectrum {
    let rgb = rgb.clamp(0.0, f32::MAX);
    let scale = 2.0 * rgb.max_component();
    let unit = if scale > 0.0 { rgb / scale } else { Rgb::ZERO };
    RgbSpectrum {
        coefficients: TABLE.coefficients(unit.to_array()),
        scale,
    }
}

/// D65 normalised to `∫ ȳ D65 = 1` at `lambda` nm (linear between the
/// nanometres; zero outside 360–830 nm).
#[inline]
pub fn illuminant_d65(lambda: f32) -> f32 {
    let x = lambda - LAMBDA_MIN;
    if !(0.0..=470.0).contains(&x) {
        return 0.0;
    }
    // `x` is in `[0, 470]`: truncating through `i32` is `x as usize`, in
    // one instruction, and the table's fixed length needs no bounds checks.
    let i = (x as i32 as usize).min(469);
    let t = x - i as i32 as f32;
    let d = &*D65_UNIT;
    d[i] + t * (d[i + 1] - d[i])
}

#[cfg(test)]
mod tests {
    use super::*;
    use lowdisc_colour::cie::spectrum_to_xyz;
    use lowdisc_colour::srgb;

    /// The sRGB of reflectance `s` under D65 (1 nm sums).
    fn rgb_under_d65(s: impl Fn(f32) -> f32) -> [f64; 3] {
        let xyz = spectrum_to_xyz(|l| s(l) * illuminant_d65(l) * lowdisc_colour::CIE_Y_INTEGRAL);
        srgb().rgb_from_xyz.apply(xyz.map(f64::from))
    }

    #[test]
    fn round_trip_rgb_to_spectrum_to_rgb_over_the_gamut() {
        // A 10x10x10 grid of [0.05, 0.95]^3 (the cube's faces hold colours
        // no reflectance bounded by 1 reaches, e.g. (1, 1, 0.95)).
        let mut errors = Vec::new();
        for i in 0..10 {
            for j in 0..10 {
                for k in 0..10 {
                    let f = |n: i32| 0.05 + 0.1 * n as f32;
                    let rgb = Rgb::new(f(i), f(j), f(k));
                    let out = rgb_under_d65(|l| albedo(rgb).eval(l));
                    let e = (0..3)
                        .map(|c| (out[c] as f32 - rgb[c]).abs())
                        .fold(0.0, f32::max);
                    errors.push(e);
                }
            }
        }
        errors.sort_by(f32::total_cmp);
        let (p99, max) = (errors[989], errors[999]);
        assert!(p99 < 1e-3 && max < 1.5e-3, "p99 {p99}, max {max}");
    }

    #[test]
    fn the_memos_return_the_tables_spectra_bit_for_bit() {
        // Random colours (some above 1, for `unbounded`), each asked for
        // twice, far apart and interleaved (so that slots are refilled and
        // hit), plus greys, zeros of both signs, negatives and NaN.
        let mut rng = lowdisc::pcg::Pcg32::new(0x2545_f491_4f6c_dd1d, 0);
        let mut next = || 4.0 * rng.next_f32();
        let mut inputs: Vec<Rgb> = (0..500).map(|_| Rgb::new(next(), next(), next())).collect();
        inputs.extend([
            Rgb::splat(0.5),
            Rgb::ZERO,
            Rgb::new(-0.0, 0.0, 0.0),
            Rgb::new(1.0, 0.0, -2.0),
            Rgb::new(f32::NAN, 0.2, 0.1),
        ]);
        let bits = |s: RgbSpectrum| (s.coefficients.map(f32::to_bits), s.scale.to_bits());
        for _ in 0..2 {
            for (i, &rgb) in inputs.iter().enumerate() {
                let other = inputs[(i * 7 + 3) % inputs.len()];
                for c in [rgb, other] {
                    assert_eq!(bits(albedo(c)), bits(albedo_from_table(c)), "{c:?}");
                    assert_eq!(bits(unbounded(c)), bits(unbounded_from_table(c)), "{c:?}");
                }
            }
        }
    }

    #[test]
    fn greys_are_exact_and_unbounded_scales() {
        for v in [0.0f32, 0.2, 0.5, 1.0] {
            let s = albedo(Rgb::splat(v));
            assert!((s.eval(450.0) - v).abs() < 1e-6 && (s.eval(700.0) - v).abs() < 1e-6);
        }
        let s = unbounded(Rgb::splat(3.0));
        assert!((s.eval(500.0) - 3.0).abs() < 1e-5);
        let (a, b) = (
            unbounded(Rgb::new(0.2, 0.5, 0.1)),
            unbounded(Rgb::new(2.0, 5.0, 1.0)),
        );
        assert!((b.eval(600.0) - 10.0 * a.eval(600.0)).abs() < 1e-5);
        // White light is D65 of luminance 1 and renders as sRGB white.
        let w = rgb_under_d65(|_| 1.0);
        assert!(w.iter().all(|c| (c - 1.0).abs() < 1e-5), "{w:?}");
    }
}
