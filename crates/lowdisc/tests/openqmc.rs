//! The OpenQMC catalog entries: their values are the `openqmc` crate's own
//! draws under the documented domain layout, and each value is stratified
//! over a pixel's samples as the library promises.

use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc::pixel::{OpenQmcKind, OpenQmcSampler, PixelSampler, WordSampler};
use openqmc::SobolSampler;

const OPENQMC: [SamplerName; 6] = [
    SamplerName::OpenQmcSobol,
    SamplerName::OpenQmcSobolBn,
    SamplerName::OpenQmcLattice,
    SamplerName::OpenQmcLatticeBn,
    SamplerName::OpenQmcPmj,
    SamplerName::OpenQmcPmjBn,
];

fn config(name: SamplerName, spp: u32, seed: u64) -> SamplerConfig {
    SamplerConfig {
        spp,
        seed,
        resolution: [64, 64],
        ..SamplerConfig::new(name)
    }
}

#[test]
fn values_are_openqmcs_draws_in_the_documented_domains() {
    let mut ours = OpenQmcSampler::new(OpenQmcKind::Sobol, 16, 9).unwrap();
    // The seed selects the frame: 30 bits of its hash.
    WordSampler::start_pixel_sample(&mut ours, [5, 6], 3, 0);
    let offset = ours.get_pixel_2d_words();
    let frame = (lowdisc::hash::mix64(9) >> 34) as i32;
    let root = SobolSampler::new(5, 6, frame, 3);
    assert_eq!(offset, root.new_domain(0).draw_sample::<2>());
    let a = ours.get_2d_words();
    let b = ours.get_1d_word();
    let c = ours.get_2d_words();
    assert_eq!(a, root.new_domain(1).draw_sample::<2>());
    assert_eq!([b], root.new_domain(3).draw_sample::<1>());
    assert_eq!(c, root.new_domain(4).draw_sample::<2>());
    // Starting at dimension 7 reads domain 8.
    WordSampler::start_pixel_sample(&mut ours, [5, 6], 3, 7);
    assert_eq!(ours.get_2d_words(), root.new_domain(8).draw_sample::<2>());
}

/// One value of each of `spp` samples in each of `spp` equal intervals.
fn stratified(values: &[f32]) -> bool {
    let n = values.len();
    let mut seen = vec![false; n];
    for &v in values {
        let cell = (v * n as f32) as usize;
        if cell >= n || std::mem::replace(&mut seen[cell], true) {
            return false;
        }
    }
    true
}

#[test]
fn every_value_is_stratified_over_a_pixels_samples() {
    for name in OPENQMC {
        for seed in [0, 1, u64::MAX] {
            let spp = 16;
            let mut s = config(name, spp, seed).build().unwrap();
            for pixel in [[0, 0], [7, 3], [63, 63]] {
                let mut lanes = vec![Vec::new(); 5];
                for i in 0..spp {
                    s.start_pixel_sample(pixel, i, 0);
                    let [x, y] = s.get_pixel_2d();
                    let [u, v] = s.get_2d();
                    let w = s.get_1d();
                    for (lane, value) in lanes.iter_mut().zip([x, y, u, v, w]) {
                        lane.push(value);
                    }
                }
                for (k, lane) in lanes.iter().enumerate() {
                    assert!(stratified(lane), "{name} seed {seed} {pixel:?} lane {k}");
                }
            }
        }
    }
}

#[test]
fn seeds_and_pixels_change_the_values() {
    for name in OPENQMC {
        let first = |seed: u64, pixel: [u32; 2]| {
            let mut s = config(name, 4, seed).build().unwrap();
            s.start_pixel_sample(pixel, 1, 0);
            (s.get_pixel_2d(), s.get_2d())
        };
        assert_ne!(first(0, [1, 2]), first(1, [1, 2]), "{name}");
        assert_ne!(first(0, [1, 2]), first(0, [2, 1]), "{name}");
        assert_eq!(first(5, [1, 2]), first(5, [1, 2]), "{name}");
        // OpenQMC's documented limit: its pixel key holds 8 bits of x and y.
        assert_eq!(first(5, [1, 2]), first(5, [257, 2]), "{name}");
        assert_eq!(first(5, [1, 2]), first(5, [1, 258]), "{name}");
    }
}

#[test]
fn sample_counts_past_the_signed_index_are_refused() {
    assert!(OpenQmcSampler::new(OpenQmcKind::Sobol, 1 << 31, 0).is_err());
    assert!(OpenQmcSampler::new(OpenQmcKind::Sobol, 0, 0).is_err());
    assert!(OpenQmcSampler::new(OpenQmcKind::Sobol, i32::MAX as u32, 0).is_ok());
}
