//! Properties of the Sobol-based pixel samplers: samples stay in their pixel,
//! the global sampler uses every index exactly once, nets within a pixel,
//! order independence of the reproducible paper variant.

use lowdisc::hash::{bounded, mix64};
// The word-level trait only: its `start_pixel_sample` would be ambiguous
// beside `PixelSampler`'s, which is named in full where floats are asked for.
use lowdisc::pixel::{
    GlobalSobolMode, GlobalSobolSampler, PaddedSobolSampler, WordSampler, ZSobolSampler,
};
use lowdisc::sobol::sample;
use lowdisc::{RandomizeStrategy, to_f32};

#[path = "common/net.rs"]
mod net;
use net::is_net;

const STRATEGIES: [RandomizeStrategy; 5] = RandomizeStrategy::ALL;

fn global_modes() -> Vec<GlobalSobolMode> {
    let mut modes: Vec<_> = STRATEGIES
        .into_iter()
        .map(GlobalSobolMode::Randomize)
        .collect();
    for all_dims in [false, true] {
        modes.push(GlobalSobolMode::PaperLiteral {
            threshold: 0.5,
            all_dims,
        });
        modes.push(GlobalSobolMode::PaperReproducible {
            threshold: 0.5,
            all_dims,
        });
    }
    modes
}

/// The pixel a Sobol index lands in, from the unscrambled dimensions 0-1.
fn pixel_of(index: u32, k: u32) -> [u32; 2] {
    if k == 0 {
        return [0, 0];
    }
    [sample(index, 0) >> (32 - k), sample(index, 1) >> (32 - k)]
}

#[test]
fn global_sobol_finds_the_index_of_every_pixel_sample_by_brute_force() {
    // The s-th sample of pixel p is the unique index of block s
    // (`s R^2 .. (s + 1) R^2`) whose dimensions 0-1 fall in p.
    for (res, spp) in [
        ([1, 1], 8),
        ([2, 2], 16),
        ([8, 8], 4),
        ([5, 3], 3),
        ([32, 17], 2),
    ] {
        let s = GlobalSobolSampler::new(
            spp,
            res,
            GlobalSobolMode::Randomize(RandomizeStrategy::None),
            0,
        )
        .unwrap();
        let k = s.log2_resolution();
        for index in 0..(spp << (2 * k)) {
            let p = pixel_of(index, k);
            assert_eq!(
                s.index_for(p, index >> (2 * k)),
                index,
                "res {res:?} spp {spp}"
            );
        }
    }
}

#[test]
fn global_sobol_uses_exactly_the_first_indices_on_64x64_at_16_spp() {
    let mut s = GlobalSobolSampler::new(
        16,
        [64, 64],
        GlobalSobolMode::Randomize(RandomizeStrategy::None),
        0,
    )
    .unwrap();
    let mut seen = vec![false; 64 * 64 * 16];
    for y in 0..64 {
        for x in 0..64 {
            for i in 0..16 {
                s.start_pixel_sample([x, y], i, 0);
                let index = s.sample_index() as usize;
                assert!(
                    index < seen.len() && !seen[index],
                    "index {index} reused or too large"
                );
                seen[index] = true;
                // The offset is the digits of dimensions 0-1 below the top 6.
                let [ox, oy] = s.get_pixel_2d_words();
                assert_eq!(ox, sample(index as u32, 0) << 6);
                assert_eq!(oy, sample(index as u32, 1) << 6);
                assert_eq!(pixel_of(index as u32, 6), [x, y]);
                let floats = lowdisc::pixel::PixelSampler::get_pixel_2d(&mut s);
                assert_eq!(floats, [to_f32(ox), to_f32(oy)]);
            }
        }
    }
    assert!(seen.iter().all(|&v| v));
}

#[test]
fn every_global_sobol_sample_lies_in_its_pixel() {
    for mode in global_modes() {
        for (res, spp) in [
            ([1, 1], 5),
            ([3, 5], 16),
            ([17, 9], 3),
            ([100, 37], 2),
            ([7, 1], 33),
        ] {
            let mut s = GlobalSobolSampler::new(spp, res, mode, 11).unwrap();
            let k = s.log2_resolution();
            for y in 0..res[1] {
                for x in 0..res[0] {
                    for i in 0..spp {
                        s.start_pixel_sample([x, y], i, 0);
                        assert_eq!(pixel_of(s.sample_index(), k), [x, y], "{mode:?}");
                        let f: &mut dyn lowdisc::pixel::PixelSampler = &mut s;
                        let o = f.get_pixel_2d();
                        assert!(o.iter().all(|v| (0.0..1.0).contains(v)), "{mode:?} {o:?}");
                        let v = [f.get_1d(), f.get_2d()[0], f.get_2d()[1]];
                        assert!(v.iter().all(|v| (0.0..1.0).contains(v)));
                    }
                }
            }
        }
    }
}

#[test]
fn global_sobol_pixel_offsets_form_a_net_unless_the_permutation_touches_them() {
    for mode in global_modes() {
        let mut s = GlobalSobolSampler::new(16, [6, 6], mode, 3).unwrap();
        let mut broken = 0;
        for y in 0..6 {
            for x in 0..6 {
                let pts: Vec<[u32; 2]> = (0..16)
                    .map(|i| {
                        s.start_pixel_sample([x, y], i, 0);
                        s.get_pixel_2d_words()
                    })
                    .collect();
                broken += usize::from(!is_net(&pts, 4));
            }
        }
        match mode {
            GlobalSobolMode::PaperLiteral { all_dims: true, .. }
            | GlobalSobolMode::PaperReproducible { all_dims: true, .. } => {
                // Documented: permuting dimensions 0-1 breaks the sub-pixel net.
                assert!(broken > 0, "{mode:?}: expected broken stratification");
            }
            _ => assert_eq!(broken, 0, "{mode:?}"),
        }
    }
}

/// Values of one pixel sample: offset words, then 1-D, 2-D and 1-D words.
fn global_values(s: &mut GlobalSobolSampler, p: [u32; 2], i: u32) -> [u32; 6] {
    s.start_pixel_sample(p, i, 0);
    let [a, b] = s.get_pixel_2d_words();
    let c = s.get_1d_word();
    let [d, e] = s.get_2d_words();
    [a, b, c, d, e, s.get_1d_word()]
}

#[test]
fn reproducible_paper_values_do_not_depend_on_call_order() {
    for all_dims in [false, true] {
        let mode = GlobalSobolMode::PaperReproducible {
            threshold: 0.5,
            all_dims,
        };
        let mut jobs: Vec<([u32; 2], u32)> = (0..5)
            .flat_map(|y| (0..7).flat_map(move |x| (0..8).map(move |i| ([x, y], i))))
            .collect();
        let mut s = GlobalSobolSampler::new(8, [7, 5], mode, 42).unwrap();
        let natural: Vec<_> = jobs
            .iter()
            .map(|&(p, i)| global_values(&mut s, p, i))
            .collect();
        // A seeded Fisher-Yates shuffle of the visiting order, run on a fresh sampler.
        let order: Vec<usize> = {
            let mut o: Vec<usize> = (0..jobs.len()).collect();
            for j in (1..o.len()).rev() {
                o.swap(j, bounded(mix64(j as u64 + 99), j as u64 + 1) as usize);
            }
            o
        };
        jobs = order.iter().map(|&j| jobs[j]).collect();
        let mut fresh = GlobalSobolSampler::new(8, [7, 5], mode, 42).unwrap();
        for (&(p, i), &j) in jobs.iter().zip(&order) {
            assert_eq!(global_values(&mut fresh, p, i), natural[j]);
        }
        // The literal variant, by contrast, depends on the order (documented).
        let literal = GlobalSobolMode::PaperLiteral {
            threshold: 0.5,
            all_dims,
        };
        let mut a = GlobalSobolSampler::new(8, [7, 5], literal, 42).unwrap();
        let first = global_values(&mut a, [1, 1], 3);
        let second = global_values(&mut a, [1, 1], 3);
        assert_ne!(first, second);
    }
}

#[test]
fn literal_paper_with_threshold_one_is_unscrambled_sobol() {
    for all_dims in [false, true] {
        let plain = GlobalSobolMode::Randomize(RandomizeStrategy::None);
        let literal = GlobalSobolMode::PaperLiteral {
            threshold: 1.0,
            all_dims,
        };
        let mut a = GlobalSobolSampler::new(4, [9, 6], plain, 0).unwrap();
        let mut b = GlobalSobolSampler::new(4, [9, 6], literal, 77).unwrap();
        for y in 0..6 {
            for x in 0..9 {
                for i in 0..4 {
                    assert_eq!(
                        global_values(&mut a, [x, y], i),
                        global_values(&mut b, [x, y], i)
                    );
                }
            }
        }
    }
}

#[test]
fn with_stream_reseeds_only_the_literal_stream() {
    let literal = GlobalSobolMode::PaperLiteral {
        threshold: 0.5,
        all_dims: false,
    };
    let s = GlobalSobolSampler::new(4, [4, 4], literal, 1).unwrap();
    let (mut a, mut b, mut c) = (s.with_stream(0), s.with_stream(0), s.with_stream(1));
    let va: Vec<_> = (0..4).map(|i| global_values(&mut a, [2, 3], i)).collect();
    let vb: Vec<_> = (0..4).map(|i| global_values(&mut b, [2, 3], i)).collect();
    let vc: Vec<_> = (0..4).map(|i| global_values(&mut c, [2, 3], i)).collect();
    assert_eq!(va, vb);
    assert_ne!(va, vc);
    let repro = GlobalSobolMode::PaperReproducible {
        threshold: 0.5,
        all_dims: false,
    };
    let s = GlobalSobolSampler::new(4, [4, 4], repro, 1).unwrap();
    let (mut a, mut c) = (s.with_stream(0), s.with_stream(1));
    assert_eq!(
        global_values(&mut a, [1, 2], 3),
        global_values(&mut c, [1, 2], 3)
    );
}

#[test]
fn padded_and_zsobol_pixel_samples_form_nets_under_owen_and_lms() {
    for r in [
        RandomizeStrategy::Owen,
        RandomizeStrategy::FastOwen,
        RandomizeStrategy::Lms,
    ] {
        for m in [0u32, 1, 2, 4, 5, 8] {
            let spp = 1 << m;
            let mut padded = PaddedSobolSampler::new(spp, r, 4).unwrap();
            let mut z = ZSobolSampler::new(spp, [13, 10], r, 4).unwrap();
            for p in [[0, 0], [5, 7], [12, 9]] {
                let mut sets = [const { Vec::new() }; 4];
                for i in 0..spp {
                    padded.start_pixel_sample(p, i, 3);
                    sets[0].push(padded.get_pixel_2d_words());
                    sets[1].push(padded.get_2d_words());
                    z.start_pixel_sample(p, i, 3);
                    sets[2].push(z.get_pixel_2d_words());
                    sets[3].push(z.get_2d_words());
                }
                for (j, set) in sets.iter().enumerate() {
                    assert!(is_net(set, m), "{r:?} m {m} pixel {p:?} set {j}");
                }
            }
        }
    }
}

#[test]
fn padded_and_zsobol_values_are_in_range_for_odd_counts_and_shapes() {
    for r in STRATEGIES {
        for spp in [1u32, 3, 5, 17, 100] {
            let mut padded = PaddedSobolSampler::new(spp, r, 1).unwrap();
            let mut z = ZSobolSampler::new(spp, [21, 3], r, 1).unwrap();
            for p in [[0, 0], [20, 2], [7, 1]] {
                let mut seen = Vec::new();
                for i in 0..spp {
                    for s in [&mut padded as &mut dyn lowdisc::pixel::PixelSampler, &mut z] {
                        s.start_pixel_sample(p, i, 0);
                        let v = [s.get_pixel_2d(), s.get_2d(), [s.get_1d(), s.get_1d()]];
                        assert!(v.iter().flatten().all(|x| (0.0..1.0).contains(x)));
                    }
                    padded.start_pixel_sample(p, i, 0);
                    seen.push(padded.permuted_index(0));
                }
                // Padded samples of a pixel use the first `spp` Sobol points once each.
                seen.sort_unstable();
                assert_eq!(seen, (0..spp).collect::<Vec<_>>());
            }
        }
    }
}

#[test]
fn zsobol_non_power_of_two_uses_distinct_slots_of_the_rounded_block() {
    let mut z = ZSobolSampler::new(6, [4, 4], RandomizeStrategy::None, 2).unwrap();
    for p in [[0, 0], [3, 1]] {
        let mut idx: Vec<u64> = (0..6)
            .map(|i| {
                z.start_pixel_sample(p, i, 0);
                z.sample_index(0)
            })
            .collect();
        let block = idx[0] >> 3;
        assert!(idx.iter().all(|&i| i >> 3 == block));
        idx.dedup();
        assert_eq!(idx.len(), 6);
    }
}

#[test]
fn zsobol_index_range_limits() {
    // 2^17 x 2^17 at 1 spp needs 34 index bits: fine when scrambled (the
    // bits above 31 select the scramble), refused unscrambled.
    assert!(ZSobolSampler::new(1, [1 << 17, 1 << 17], RandomizeStrategy::None, 0).is_err());
    let mut z = ZSobolSampler::new(1, [1 << 17, 1 << 17], RandomizeStrategy::FastOwen, 0).unwrap();
    let values: Vec<[u32; 2]> = [[0, 0], [1 << 16, 0], [0, 1 << 16], [1 << 16, 1 << 16]]
        .iter()
        .map(|&p| {
            z.start_pixel_sample(p, 0, 0);
            z.get_2d_words()
        })
        .collect();
    for i in 0..4 {
        assert!(values[..i].iter().all(|v| *v != values[i]), "{values:?}");
    }
    assert!(ZSobolSampler::new(1, [1 << 16, 1 << 16], RandomizeStrategy::None, 0).is_ok());
}
