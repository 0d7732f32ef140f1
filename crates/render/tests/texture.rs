//! Textures: checkerboard parity, uv mapping, image bilinear lookups at texel
//! centres and midpoints, wrap modes, 8-bit encodings, scale/mix, registry.

use lowdisc_image::{RgbImage, srgb8_decode, write_png};
use lowdisc_render::math::{Point2, Point3, Transform, Vec3};
use lowdisc_render::spectrum::Rgb;
use lowdisc_render::texture::{
    Checker, ColorEncoding, FloatTexture, ImageTexture, SpectrumTexture, TexImage, TextureError,
    TextureEvalContext, TextureMapping, TextureRegistry, WrapMode,
};
use std::sync::Arc;

fn at(u: f32, v: f32) -> TextureEvalContext {
    TextureEvalContext {
        p: Point3::ZERO,
        uv: Point2::new(u, v),
    }
}

const A: [f32; 3] = [1.0, 0.0, 0.0];
const B: [f32; 3] = [0.0, 2.0, 0.0];
const C: [f32; 3] = [0.0, 0.0, 4.0];
const D: [f32; 3] = [8.0, 8.0, 8.0];

/// 2x2 image, top row `A B`, bottom row `C D`.
fn two_by_two() -> Arc<TexImage> {
    Arc::new(TexImage::new(
        RgbImage::from_pixels(2, 2, vec![A, B, C, D]).unwrap(),
    ))
}

fn avg(vs: &[[f32; 3]]) -> Rgb {
    let n = vs.len() as f32;
    Rgb::new(
        vs.iter().map(|v| v[0]).sum::<f32>() / n,
        vs.iter().map(|v| v[1]).sum::<f32>() / n,
        vs.iter().map(|v| v[2]).sum::<f32>() / n,
    )
}

fn assert_rgb(got: Rgb, want: Rgb) {
    assert!(
        (got - want).max_component().abs() < 1e-6 && (want - got).max_component().abs() < 1e-6,
        "{got:?} vs {want:?}"
    );
}

#[test]
fn checkerboard_at_known_uv() {
    // The material-testball checkerboard: uscale = vscale = 20.
    let mapping = TextureMapping::Uv {
        su: 20.0,
        sv: 20.0,
        du: 0.0,
        dv: 0.0,
    };
    let t1 = Rgb::new(0.325, 0.31, 0.25);
    let t2 = Rgb::new(0.725, 0.71, 0.68);
    let tex = SpectrumTexture::Checkerboard {
        checker: Arc::new(Checker::TwoD(mapping)),
        tex1: Arc::new(SpectrumTexture::Constant(t1)),
        tex2: Arc::new(SpectrumTexture::Constant(t2)),
    };
    // (s, t) = (1, 1) -> floor sum 0+... : s = 20 * 0.025 = 0.5, t = 0.5 -> 0 + 0 even.
    assert_eq!(tex.evaluate(&at(0.025, 0.025)), t1);
    assert_eq!(tex.evaluate(&at(0.075, 0.025)), t2); // s = 1.5: 1 + 0 odd
    assert_eq!(tex.evaluate(&at(0.075, 0.075)), t1); // 1 + 1 even
    assert_eq!(tex.evaluate(&at(-0.025, 0.025)), t2); // floor(-0.5) = -1: odd
    assert_eq!(tex.evaluate(&at(0.999, 0.001)), t2); // 19 + 0
    // 3-D variant: parity of floor(x) + floor(y) + floor(z) in texture space.
    let solid = FloatTexture::Checkerboard {
        checker: Arc::new(Checker::ThreeD(Transform::scale(Vec3::splat(2.0)).unwrap())),
        tex1: Arc::new(FloatTexture::Constant(1.0)),
        tex2: Arc::new(FloatTexture::Constant(0.0)),
    };
    let p = |x, y, z| TextureEvalContext {
        p: Point3::new(x, y, z),
        uv: Point2::default(),
    };
    assert_eq!(solid.evaluate(&p(0.1, 0.1, 0.1)), 1.0);
    assert_eq!(solid.evaluate(&p(0.6, 0.1, 0.1)), 0.0); // x scaled to 1.2
    assert_eq!(solid.evaluate(&p(0.6, 0.6, 0.1)), 1.0);
}

#[test]
fn image_lookup_at_texel_centres_and_midpoints() {
    let tex = ImageTexture::new(two_by_two());
    // Texture t points up: v = 0.75 is the top image row.
    assert_rgb(tex.evaluate_rgb(&at(0.25, 0.75)), Rgb::from_array(A));
    assert_rgb(tex.evaluate_rgb(&at(0.75, 0.75)), Rgb::from_array(B));
    assert_rgb(tex.evaluate_rgb(&at(0.25, 0.25)), Rgb::from_array(C));
    assert_rgb(tex.evaluate_rgb(&at(0.75, 0.25)), Rgb::from_array(D));
    // Midpoints between two texels and the centre of all four.
    assert_rgb(tex.evaluate_rgb(&at(0.5, 0.75)), avg(&[A, B]));
    assert_rgb(tex.evaluate_rgb(&at(0.25, 0.5)), avg(&[A, C]));
    assert_rgb(tex.evaluate_rgb(&at(0.5, 0.5)), avg(&[A, B, C, D]));
    // A quarter of the way from A to B.
    let q = tex.evaluate_rgb(&at(0.375, 0.75));
    assert_rgb(q, Rgb::new(0.75, 0.5, 0.0));
    // The float texture reads the first channel.
    assert!((tex.evaluate_float(&at(0.5, 0.75)) - 0.5).abs() < 1e-6);
}

#[test]
fn wrap_modes() {
    let img = two_by_two();
    let with = |wrap| ImageTexture {
        wrap,
        ..ImageTexture::new(img.clone())
    };
    // u = 0 sits halfway between texel column -1 and column 0 of the top row.
    let edge = at(0.0, 0.75);
    assert_rgb(with(WrapMode::Repeat).evaluate_rgb(&edge), avg(&[A, B]));
    assert_rgb(
        with(WrapMode::Clamp).evaluate_rgb(&edge),
        Rgb::from_array(A),
    );
    assert_rgb(
        with(WrapMode::Black).evaluate_rgb(&edge),
        Rgb::from_array(A) * 0.5,
    );
    // Far outside: repeat tiles, clamp extends, black is black.
    let far = at(3.25, -1.25); // same texel as (0.25, 0.75) under repeat
    assert_rgb(
        with(WrapMode::Repeat).evaluate_rgb(&far),
        Rgb::from_array(A),
    );
    // Clamp: u > 1 is the right column, v < 0 (below the image) the bottom row.
    assert_rgb(with(WrapMode::Clamp).evaluate_rgb(&far), Rgb::from_array(D));
    assert_rgb(with(WrapMode::Black).evaluate_rgb(&far), Rgb::ZERO);
    assert_eq!(WrapMode::parse("clamp").unwrap(), WrapMode::Clamp);
    assert!(matches!(
        WrapMode::parse("mirror"),
        Err(TextureError::UnknownWrap(_))
    ));
    // Non-finite coordinates give black rather than a panic.
    assert_eq!(
        with(WrapMode::Repeat).evaluate_rgb(&at(f32::NAN, 0.5)),
        Rgb::ZERO
    );
}

#[test]
fn uv_mapping_scale_invert() {
    let tex = ImageTexture {
        mapping: TextureMapping::Uv {
            su: 2.0,
            sv: 2.0,
            du: 0.5,
            dv: 0.0,
        },
        scale: 0.25,
        invert: true,
        ..ImageTexture::new(two_by_two())
    };
    // s = 2 * 0.125 + 0.5 = 0.75, t = 2 * 0.375 = 0.75 -> texel B = (0, 2, 0),
    // scaled (0, 0.5, 0), inverted (1, 0.5, 1).
    assert_rgb(tex.evaluate_rgb(&at(0.125, 0.375)), Rgb::new(1.0, 0.5, 1.0));
    // D scaled is (2, 2, 2): inverted and clamped at zero.
    assert_rgb(tex.evaluate_rgb(&at(0.125, 0.125)), Rgb::ZERO);
    let planar = TextureMapping::Planar {
        texture_from_world: Transform::translate(Vec3::new(1.0, 0.0, 0.0)),
        vs: Vec3::X,
        vt: Vec3::Z,
        ds: 0.5,
        dt: 0.0,
    };
    let ctx = TextureEvalContext {
        p: Point3::new(1.0, 7.0, 2.0),
        uv: Point2::default(),
    };
    assert_eq!(planar.map(&ctx), [2.5, 2.0]);
}

#[test]
fn scale_and_mix() {
    let c = |v| Arc::new(FloatTexture::Constant(v));
    let s = SpectrumTexture::Scale {
        tex: Arc::new(SpectrumTexture::Constant(Rgb::new(1.0, 2.0, 4.0))),
        scale: c(0.5),
    };
    assert_eq!(s.evaluate(&at(0.0, 0.0)), Rgb::new(0.5, 1.0, 2.0));
    let m = FloatTexture::Mix {
        tex1: c(2.0),
        tex2: c(6.0),
        amount: c(0.25),
    };
    assert_eq!(m.evaluate(&at(0.0, 0.0)), 3.0);
    let fs = FloatTexture::Scale {
        tex: c(3.0),
        scale: c(-2.0),
    };
    assert_eq!(fs.evaluate(&at(0.0, 0.0)), -6.0);
    assert_eq!(fs.as_constant(), None);
    assert_eq!(FloatTexture::Constant(1.5).as_constant(), Some(1.5));
}

fn temp_dir(tag: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("lowdisc-texture-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn eight_bit_encodings() {
    let dir = temp_dir("enc");
    // 8-bit codes 0, 64, 128, 255 in a 4x1 PNG (written from their sRGB values).
    let codes = [0u8, 64, 128, 255];
    let linear: Vec<[f32; 3]> = codes.iter().map(|&c| [srgb8_decode(c); 3]).collect();
    let png = dir.join("ramp.png");
    write_png(&png, &RgbImage::from_pixels(4, 1, linear).unwrap(), 1.0).unwrap();
    let mut reg = TextureRegistry::new();
    let check = |img: &TexImage, f: &dyn Fn(u8) -> f32| {
        for (x, &c) in codes.iter().enumerate() {
            let got = img.texel(x as i64, 0, WrapMode::Clamp)[1];
            assert!((got - f(c)).abs() < 1e-6, "code {c}: {got} vs {}", f(c));
        }
    };
    // .png defaults to sRGB.
    let srgb = reg.load_image(&png, None).unwrap();
    check(&srgb, &|c| srgb8_decode(c));
    assert!((srgb.texel(2, 0, WrapMode::Clamp)[0] - 0.215_860_5).abs() < 1e-6); // code 128
    let lin = reg.load_image(&png, Some(ColorEncoding::Linear)).unwrap();
    check(&lin, &|c| f32::from(c) / 255.0);
    let gamma = reg
        .load_image(&png, Some(ColorEncoding::parse("gamma 2.2").unwrap()))
        .unwrap();
    check(&gamma, &|c| (f32::from(c) / 255.0).powf(2.2));
    // The cache returns the same image for the same file and encoding.
    assert!(Arc::ptr_eq(
        &srgb,
        &reg.load_image(&png, Some(ColorEncoding::Srgb)).unwrap()
    ));
    assert_eq!(reg.image_count(), 3);
    assert!(ColorEncoding::parse("gamma x").is_err() && ColorEncoding::parse("rgb").is_err());
    // pbrt-v4 reads 8-bit files other than PNG as sRGB.
    assert_eq!(
        ColorEncoding::default_for(std::path::Path::new("a.tga")),
        ColorEncoding::Srgb
    );
    // A missing file is an error, not a panic.
    assert!(matches!(
        reg.load_image(&dir.join("nope.png"), None),
        Err(TextureError::Image(_))
    ));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn registry_keeps_float_and_spectrum_apart() {
    let mut reg = TextureRegistry::new();
    assert!(reg.add_float("t", FloatTexture::Constant(0.5)).is_none());
    assert!(
        reg.add_spectrum("t", SpectrumTexture::Constant(Rgb::ONE))
            .is_none()
    );
    assert_eq!(reg.len(), 2);
    assert_eq!(reg.float("t").unwrap().evaluate(&at(0.0, 0.0)), 0.5);
    assert_eq!(reg.spectrum("t").unwrap().evaluate(&at(0.0, 0.0)), Rgb::ONE);
    // Redefinition replaces and hands back the old one.
    assert!(reg.add_float("t", FloatTexture::Constant(0.7)).is_some());
    assert_eq!(reg.require_float("t").unwrap().as_constant(), Some(0.7));
    assert!(matches!(
        reg.require_spectrum("u"),
        Err(TextureError::Missing("spectrum", _))
    ));
}

#[test]
fn scene_textures_load_when_present() {
    let Some(path) = shared_scenes::file("killeroos/textures/lines.png") else {
        return;
    };
    let mut reg = TextureRegistry::new();
    let img = reg.load_image(&path, None).unwrap();
    let [w, h] = img.resolution();
    assert!(w > 0 && h > 0);
    let tex = ImageTexture::new(img);
    let v = tex.evaluate_rgb(&at(0.3, 0.6));
    assert!(v.is_finite() && v.min_component() >= 0.0 && v.max_component() <= 1.0);
}
