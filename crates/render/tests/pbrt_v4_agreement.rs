//! Spectral renders against pbrt-v4's own renders of the same scene files
//! (`../shared/pbrt-v4-refs`, made by pbrt-v4 at 5f7a6068, spectral, the
//! default `rgb` film; the README there gives the commands). Each scene is
//! rendered by lowdisc in spectral mode at the reference's resolution with
//! fewer samples, and the agreement is stated as the issue asks:
//!
//! * the mean of every channel within 1 % of pbrt-v4's;
//! * the distribution of 8x8-block luminance ratios lowdisc / pbrt-v4
//!   centred on 1: its median within 1 % (its 5-95 % range is printed).
//!
//! The renders use pbrt-v4's MIS weight in layered BSDFs
//! ([`LayeredExitWeight::PBRT_V4`]), which makes pbrt-v4's coated materials
//! too bright (`tests/layered_exit_weight.rs`); lowdisc's default, unbiased
//! weight is rendered too for the coated gold killeroo, whose red is then
//! about 2 % below pbrt-v4's.
//!
//! Needs the shared data: skipped with a `SKIPPED:` line when absent, a
//! failure under `LOWDISC_REQUIRE_SCENES=1`. The figures in the README come
//! from `cargo test --release -p lowdisc-render --test pbrt_v4_agreement --
//! --nocapture`, which also prints RGB mode's for comparison.

use lowdisc::catalog::SamplerName;
use lowdisc_image::{RgbImage, luminance, read_image};
use lowdisc_render::bsdf::LayeredExitWeight;
use lowdisc_render::integrator::PathIntegrator;
use lowdisc_render::pbrt::{LoadOptions, load_pbrt_scene};
use lowdisc_render::render::{NoProgress, RenderOptions, render};
use lowdisc_render::settings::Settings;
use lowdisc_render::view::View;

/// What lowdisc's image and pbrt-v4's have in common.
struct Agreement {
    /// Channel means, lowdisc / pbrt-v4.
    mean_ratio: [f64; 3],
    /// Median, 5 % and 95 % quantiles of the 8x8-block luminance ratios.
    blocks: [f64; 3],
}

fn agreement(ours: &RgbImage, theirs: &RgbImage) -> Agreement {
    assert_eq!(
        (ours.width(), ours.height()),
        (theirs.width(), theirs.height())
    );
    let mean = |im: &RgbImage| {
        let mut m = [0.0f64; 3];
        for p in im.pixels() {
            (0..3).for_each(|c| m[c] += f64::from(p[c]));
        }
        m
    };
    let (a, b) = (mean(ours), mean(theirs));
    let block = |im: &RgbImage, bx: usize, by: usize| {
        let mut s = 0.0f64;
        for y in by * 8..by * 8 + 8 {
            for x in bx * 8..bx * 8 + 8 {
                s += f64::from(luminance(im.pixels()[y * im.width() + x]));
            }
        }
        s
    };
    let mut ratios = Vec::new();
    for by in 0..ours.height() / 8 {
        for bx in 0..ours.width() / 8 {
            let t = block(theirs, bx, by);
            // Blocks that are black in the reference say nothing.
            if t > 1e-3 * 64.0 {
                ratios.push(block(ours, bx, by) / t);
            }
        }
    }
    ratios.sort_by(f64::total_cmp);
    let q = |p: f64| ratios[((ratios.len() - 1) as f64 * p).round() as usize];
    Agreement {
        mean_ratio: [0, 1, 2].map(|c| a[c] / b[c]),
        blocks: [q(0.5), q(0.05), q(0.95)],
    }
}

/// Renders `scene` (under ../shared/scenes) like `reference` (under
/// ../shared/pbrt-v4-refs) with `spp` samples, spectral or RGB, with the
/// given weight in layered BSDFs.
fn compare(
    scene: &str,
    reference: &str,
    spp: u32,
    spectral: bool,
    layered_exit_weight: LayeredExitWeight,
) -> Option<Agreement> {
    let scene_path = shared_scenes::file(scene)?;
    let ref_path =
        shared_scenes::existing(shared_scenes::dir().join("../pbrt-v4-refs").join(reference))?;
    let theirs = read_image(&ref_path).unwrap();
    let loaded = load_pbrt_scene(&scene_path, &LoadOptions::default()).unwrap();
    let (w, h) = (theirs.width() as u32, theirs.height() as u32);
    let view = View::new(&loaded.view, [w, h]).unwrap();
    let file = Settings::resolve(&[&loaded.settings.layer]).unwrap();
    let opts = RenderOptions {
        integrator: PathIntegrator {
            layered_exit_weight,
            ..file.render.integrator
        },
        spectral,
        ..RenderOptions::new(SamplerName::ZSobol, 1, spp)
    };
    let out = render(&loaded.scene, &view, &opts, &NoProgress).unwrap();
    let a = agreement(&out.image, &theirs);
    println!(
        "{scene} ({}, {} layered weight, {spp} spp): \
         channel means / pbrt-v4 = {:.4} {:.4} {:.4}; \
         8x8 block luminance ratio median {:.4}, 5-95 % {:.3}-{:.3}; {:.1} s",
        if spectral { "spectral" } else { "RGB" },
        if layered_exit_weight == LayeredExitWeight::PBRT_V4 {
            "pbrt-v4"
        } else {
            "unbiased"
        },
        a.mean_ratio[0],
        a.mean_ratio[1],
        a.mean_ratio[2],
        a.blocks[0],
        a.blocks[1],
        a.blocks[2],
        out.stats.time.as_secs_f64()
    );
    Some(a)
}

/// Renders spectrally with pbrt-v4's layered weight and checks the block
/// median and every channel mean within 1 %; returns the agreement.
fn check(scene: &str, reference: &str, spp: u32) -> Option<Agreement> {
    let a = compare(scene, reference, spp, true, LayeredExitWeight::PBRT_V4)?;
    for (c, r) in a.mean_ratio.iter().enumerate() {
        assert!(
            (r - 1.0).abs() < 0.01,
            "{scene}: channel {c} mean ratio {r}"
        );
    }
    assert!(
        (a.blocks[0] - 1.0).abs() < 0.01,
        "{scene}: block median {}",
        a.blocks[0]
    );
    if std::env::var_os("LOWDISC_AGREEMENT_RGB").is_some() {
        compare(scene, reference, spp, false, LayeredExitWeight::PBRT_V4);
    }
    Some(a)
}

#[test]
fn cornell_box_agrees_with_pbrt_v4() {
    check(
        "bitterli-cornell-box/scene-v4.pbrt",
        "bitterli-cornell-box_128x128_1024spp.exr",
        64,
    );
}

#[test]
fn killeroo_gold_agrees_with_pbrt_v4() {
    check(
        "killeroos/killeroo-gold.pbrt",
        "killeroo-gold_171x128_512spp.exr",
        64,
    );
}

#[test]
fn killeroo_coated_gold_agrees_with_pbrt_v4() {
    let (scene, reference) = (
        "killeroos/killeroo-coated-gold.pbrt",
        "killeroo-coated-gold_171x128_512spp.exr",
    );
    let Some(pbrt_weight) = check(scene, reference, 64) else {
        return;
    };
    // lowdisc's default weight: pbrt-v4's bias removed, so every channel is
    // darker than with pbrt-v4's weight, but by no more than 3 %.
    let own = compare(scene, reference, 64, true, LayeredExitWeight::UNBIASED).unwrap();
    for c in 0..3 {
        let (r, p) = (own.mean_ratio[c], pbrt_weight.mean_ratio[c]);
        assert!(r < p && r > p - 0.03, "channel {c}: {r} against {p}");
    }
}
