//! Split renders of the built-in Cornell box merged back: tiles are
//! bit-identical to the single render for every sampler of the catalog,
//! sample ranges equal it within the stated bound, and bad splits are
//! refused with the part named.

use lowdisc::catalog::SamplerName;
use lowdisc_render::bsdf::LayeredExitWeight;
use lowdisc_render::cornell::{cornell_box, cornell_box_with_camera, cornell_camera_with_lens};
use lowdisc_render::film::PixelBounds;
use lowdisc_render::integrator::PathIntegrator;
use lowdisc_render::render::{NoProgress, RenderOptions, SampleRange, render};
use lowdisc_render::scene::Scene;
use lowdisc_render::view::View;
use lowdisc_split::{NamedPart, RenderPart, merge};

const W: i32 = 24;
const H: i32 = 16;

fn scene() -> (Scene, View) {
    cornell_box([W as u32, H as u32]).unwrap()
}

fn opts(sampler: SamplerName, seed: u64) -> RenderOptions {
    RenderOptions {
        integrator: PathIntegrator {
            max_depth: 2,
            ..PathIntegrator::default()
        },
        threads: Some(1),
        ..RenderOptions::new(sampler, seed, 4)
    }
}

fn part((scene, view): &(Scene, View), o: RenderOptions, name: &str) -> NamedPart {
    let out = render(scene, view, &o, &NoProgress).unwrap();
    NamedPart {
        name: name.to_string(),
        part: RenderPart::new(scene, view, &o, &out),
    }
}

fn window(x0: i32, x1: i32, y0: i32, y1: i32) -> Option<PixelBounds> {
    Some(PixelBounds::new([x0, y0], [x1, y1]))
}

fn split(
    scene: &(Scene, View),
    o: RenderOptions,
    windows: &[Option<PixelBounds>],
) -> Vec<NamedPart> {
    let parts = windows.iter().enumerate();
    parts
        .map(|(i, &w)| part(scene, RenderOptions { window: w, ..o }, &format!("p{i}")))
        .collect()
}

/// How many sums of `a` and `b` differ in any bit (all of them when the
/// sizes differ).
fn differing(a: &RenderPart, b: &RenderPart) -> usize {
    let (x, y) = (bits(a), bits(b));
    if x.len() != y.len() {
        return x.len().max(y.len());
    }
    x.iter().zip(&y).filter(|(p, q)| p != q).count()
}

fn bits(p: &RenderPart) -> Vec<u64> {
    p.sums
        .iter()
        .flat_map(|s| [s.rgb[0], s.rgb[1], s.rgb[2], s.weight].map(f64::to_bits))
        .collect()
}

#[test]
fn tile_merges_are_bit_identical_for_every_sampler() {
    let scene = scene();
    let quarters = [
        window(0, 12, 0, 8),
        window(12, W, 0, 8),
        window(0, 12, 8, H),
        window(12, W, 8, H),
    ];
    let strips = [window(0, 5, 0, H), window(5, 17, 0, H), window(17, W, 0, H)];
    for name in SamplerName::ALL {
        let o = opts(name, 3);
        let single = part(&scene, o, "single").part;
        assert!(single.is_complete());
        for windows in [&quarters[..], &strips[..]] {
            let mut parts = split(&scene, o, windows);
            parts.reverse();
            let merged = merge(&parts).unwrap();
            assert_eq!(merged.info, single.info, "{name}");
            assert_eq!(differing(&merged, &single), 0, "{name}");
        }
    }
}

#[test]
fn a_window_does_not_change_its_pixels_with_the_thread_count() {
    let scene = scene();
    let o = RenderOptions {
        window: window(3, 19, 2, 13),
        ..opts(SamplerName::Paper, 1)
    };
    let one = part(&scene, o, "a").part;
    let two = part(
        &scene,
        RenderOptions {
            threads: Some(2),
            ..o
        },
        "b",
    )
    .part;
    assert_eq!(differing(&one, &two), 0);
}

#[test]
fn sample_range_merges_are_within_the_rounding_bound() {
    let scene = scene();
    for name in [
        SamplerName::ZSobol,
        SamplerName::Paper,
        SamplerName::Independent,
    ] {
        let o = opts(name, 5);
        let single = part(&scene, o, "single").part;
        let ranges = [(0, 1), (1, 3), (3, 4)];
        let parts: Vec<NamedPart> = ranges
            .iter()
            .map(|&(a, b)| {
                let r = Some(SampleRange::new(a, b));
                part(
                    &scene,
                    RenderOptions { samples: r, ..o },
                    &format!("{a}..{b}"),
                )
            })
            .collect();
        let merged = merge(&parts).unwrap();
        assert_eq!(merged.info, single.info);
        // (spp + ranges) * 2^-53 of the sum of magnitudes; every term of this
        // scene is non-negative, so the sum itself bounds it.
        let bound = (4.0 + 3.0) * f64::EPSILON / 2.0;
        for (m, s) in merged.sums.iter().zip(&single.sums) {
            for (x, y) in m
                .rgb
                .iter()
                .chain([&m.weight])
                .zip(s.rgb.iter().chain([&s.weight]))
            {
                assert!((x - y).abs() <= bound * y.abs(), "{name}: {x} vs {y}");
            }
        }
        // The same parts in any order give the same bits.
        let mut shuffled = parts.clone();
        shuffled.rotate_left(1);
        assert_eq!(differing(&merge(&shuffled).unwrap(), &merged), 0);
    }
}

#[test]
fn merging_a_merge_alone_changes_nothing() {
    let scene = scene();
    let o = opts(SamplerName::SobolOwen, 2);
    let halves = split(&scene, o, &[window(0, 10, 0, H), window(10, W, 0, H)]);
    let merged = merge(&halves).unwrap();
    let again = merge(&[NamedPart {
        name: "m".into(),
        part: merged.clone(),
    }])
    .unwrap();
    assert_eq!(again, merged);
}

#[test]
fn bad_splits_are_refused_naming_the_part() {
    let scene = scene();
    let o = opts(SamplerName::ZSobol, 0);
    let err = |parts: &[NamedPart]| merge(parts).unwrap_err().to_string();
    let overlap = split(&scene, o, &[window(0, 13, 0, H), window(12, W, 0, H)]);
    let e = err(&overlap);
    assert!(
        e.starts_with("p1: pixel (12, 0) samples 0..4 overlap p0's"),
        "{e}"
    );
    let gap = split(&scene, o, &[window(0, 11, 0, H), window(12, W, 0, H)]);
    let e = err(&gap);
    assert!(e.starts_with("gap: pixel (11, 0) has no part"), "{e}");
    let mut seeds = split(&scene, o, &[window(0, 12, 0, H)]);
    seeds.push(part(
        &scene,
        RenderOptions {
            window: window(12, W, 0, H),
            ..opts(SamplerName::ZSobol, 9)
        },
        "other-seed",
    ));
    assert_eq!(err(&seeds), "other-seed: seed 9 differs from p0's 0");
    // The layered materials' exit weight changes pixels too.
    let mut weights = split(&scene, o, &[window(0, 12, 0, H)]);
    let mut pbrt = o;
    pbrt.integrator.layered_exit_weight = LayeredExitWeight::PBRT_V4;
    let half = window(12, W, 0, H);
    weights.push(part(
        &scene,
        RenderOptions {
            window: half,
            ..pbrt
        },
        "pbrt",
    ));
    assert_eq!(
        err(&weights),
        "pbrt: layered_weight pbrt-v4 differs from p0's unbiased"
    );
    let mut scenes = split(&scene, o, &[window(0, 12, 0, H)]);
    let lens = cornell_camera_with_lens(40.0, 1000.0).unwrap();
    let other = cornell_box_with_camera([W as u32, H as u32], lens).unwrap();
    let p = part(
        &other,
        RenderOptions {
            window: window(12, W, 0, H),
            ..o
        },
        "s",
    );
    scenes.push(p);
    assert!(
        err(&scenes).starts_with("s: scene hash "),
        "{}",
        err(&scenes)
    );
    let ranges = [(0, 1), (2, 4)].map(|(a, b)| {
        let r = Some(SampleRange::new(a, b));
        part(
            &scene,
            RenderOptions { samples: r, ..o },
            &format!("{a}..{b}"),
        )
    });
    let e = err(&ranges);
    assert!(
        e.starts_with("2..4: pixel (0, 0) misses samples 1..2"),
        "{e}"
    );
    assert_eq!(err(&[]), "no parts to merge");
}

#[test]
fn bad_windows_and_ranges_are_refused_before_rendering() {
    let scene = scene();
    let o = opts(SamplerName::ZSobol, 0);
    let e = render(
        &scene.0,
        &scene.1,
        &RenderOptions {
            window: window(0, 25, 0, H),
            ..o
        },
        &NoProgress,
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("pixel bounds 0,25,0,16 must be non-empty and inside"),
        "{e}"
    );
    let r = Some(SampleRange::new(2, 5));
    let e = render(
        &scene.0,
        &scene.1,
        &RenderOptions { samples: r, ..o },
        &NoProgress,
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("sample range 2..5 must be non-empty and within 0..4"),
        "{e}"
    );
}

#[test]
fn spectral_parts_hold_and_merge_to_the_single_renders_rgb_image() {
    let scene = scene();
    let o = RenderOptions {
        spectral: true,
        ..opts(SamplerName::ZSobol, 5)
    };
    let out = render(&scene.0, &scene.1, &o, &NoProgress).unwrap();
    let expected = out.film.to_image().unwrap();
    let halves = [window(0, 12, 0, H), window(12, W, 0, H)];
    let merged = merge(&split(&scene, o, &halves)).unwrap();
    assert_eq!(merged.info.settings["white_balance"], "0.0");
    let image = merged.image().unwrap();
    // Linear sRGB, as the film gives it (not the sensor's XYZ sums).
    assert_eq!(image.pixels(), expected.pixels());
    let raw: Vec<[f32; 3]> = merged.sums.iter().map(|s| s.value()).collect();
    assert_ne!(image.pixels(), &raw[..]);
}
