//! The sampler catalog: names, configuration checks, pinned sampler values
//! and (in `catalog/pinned_points.rs`) pinned points for every name.

use lowdisc::Error;
use lowdisc::catalog::{Order, Sampler, SamplerConfig, SamplerName, generate_points};
use lowdisc::pixel::PixelSampler;
use lowdisc::sobol::{NUM_DIMENSIONS, gray_code, sample};

#[path = "catalog/pinned_points.rs"]
mod pinned_points;

fn config(name: SamplerName) -> SamplerConfig {
    let mut c = SamplerConfig::new(name);
    c.seed = 7;
    c.spp = 4;
    c.resolution = [3, 2];
    c
}

#[test]
fn names_round_trip_and_are_distinct() {
    let names: Vec<String> = SamplerName::ALL.iter().map(|n| n.to_string()).collect();
    for (i, n) in SamplerName::ALL.iter().enumerate() {
        assert_eq!(names[i].parse::<SamplerName>(), Ok(*n));
        assert!(!n.description().is_empty());
        assert!(names[..i].iter().all(|m| *m != names[i]));
    }
    assert_eq!(names.len(), 29);
    assert_eq!("sobol-fast-owen".parse(), Ok(SamplerName::SobolFastOwen));
    assert_eq!(
        "Sobol".parse::<SamplerName>(),
        Err(Error::UnknownSampler {
            name: "Sobol".into(),
            suggestion: Some("sobol")
        })
    );
    assert_eq!(
        "".parse::<SamplerName>(),
        Err(Error::UnknownSampler {
            name: String::new(),
            suggestion: None
        })
    );
    let message = "zsobol-4D".parse::<SamplerName>().unwrap_err().to_string();
    assert_eq!(
        message,
        "unknown sampler `zsobol-4D`; did you mean `zsobol-4d`?"
    );
}

#[test]
fn the_sampler_enum_is_clone_send_sync() {
    fn check<T: Clone + Send + Sync>() {}
    check::<Sampler>();
    check::<SamplerConfig>();
}

/// Pinned values (value stability): pixel (2, 1), sample 3 of a 3x2 image at
/// 4 spp, seed 7: `get_pixel_2d`, `get_1d`, `get_2d`.
const PINNED_SAMPLERS: &[(SamplerName, [f32; 5])] = &[
    (
        SamplerName::Independent,
        [0.055089355, 0.44098055, 0.65988755, 0.4078462, 0.13679874],
    ),
    (
        SamplerName::Stratified,
        [0.40988052, 0.14772975, 0.8622967, 0.43879992, 0.028814077],
    ),
    (
        SamplerName::Halton,
        [0.8488812, 0.6436839, 0.66558754, 0.39425474, 0.043714345],
    ),
    (
        SamplerName::HaltonOwen,
        [0.60834163, 0.5105626, 0.45511556, 0.14653951, 0.46754283],
    ),
    (
        SamplerName::Sobol,
        [0.6875, 0.5625, 0.328125, 0.171875, 0.515625],
    ),
    (
        SamplerName::SobolXor,
        [0.5125425, 0.29913533, 0.21024513, 0.9915904, 0.874925],
    ),
    (
        SamplerName::SobolOwen,
        [0.72907305, 0.56740224, 0.31326675, 0.71075207, 0.4819647],
    ),
    (
        SamplerName::SobolFastOwen,
        [0.86813724, 0.19409573, 0.25333405, 0.6156316, 0.36899823],
    ),
    (
        SamplerName::SobolLms,
        [0.16544163, 0.054018795, 0.33514053, 0.9111072, 0.6901953],
    ),
    (
        SamplerName::Paper,
        [0.6875, 0.5625, 0.328125, 0.921875, 0.73437494],
    ),
    (
        SamplerName::PaperRepro,
        [0.6875, 0.5625, 0.17187494, 0.921875, 0.515625],
    ),
    (
        SamplerName::PaddedSobol,
        [0.58683896, 0.98619604, 0.27414453, 0.98357207, 0.077943206],
    ),
    (
        SamplerName::PaddedSobolLms,
        [0.87984353, 0.7264884, 0.023731709, 0.52899283, 0.205742],
    ),
    (
        SamplerName::ZSobol,
        [0.65799886, 0.20376617, 0.45493573, 0.69660795, 0.2677477],
    ),
    (
        SamplerName::SobolBurley,
        [0.86986864, 0.246517, 0.9222194, 0.12691325, 0.66779095],
    ),
    (
        SamplerName::LaineKarras,
        [0.2902516, 0.22327322, 0.8078757, 0.09269214, 0.12133825],
    ),
    (
        SamplerName::SobolPixelXor,
        [0.42065853, 0.8610611, 0.9550967, 0.85675836, 0.56369215],
    ),
    (
        SamplerName::Pmj02,
        [0.18439686, 0.24341822, 0.8118019, 0.48934674, 0.9083149],
    ),
    (
        SamplerName::Pmj02Bn,
        [0.18439686, 0.24341822, 0.8118019, 0.48934674, 0.9083149],
    ),
    (
        SamplerName::ZSobol4d,
        [0.9587626, 0.38267314, 0.58248913, 0.73361933, 0.016222775],
    ),
    (
        SamplerName::ZSobolJoint,
        [0.9587626, 0.38267314, 0.58248913, 0.73361933, 0.016222775],
    ),
    (
        SamplerName::ZOrderSz,
        [0.8147841, 0.5291887, 0.69221556, 0.39676815, 0.83204716],
    ),
    (
        SamplerName::CascadedSobol,
        [0.08929324, 0.20743561, 0.3618505, 0.5417431, 0.2609762],
    ),
    (
        SamplerName::OpenQmcSobol,
        [0.34016734, 0.92545575, 0.06468725, 0.7411777, 0.5323781],
    ),
    (
        SamplerName::OpenQmcSobolBn,
        [0.29258716, 0.47288275, 0.31400126, 0.959523, 0.46046543],
    ),
    (
        SamplerName::OpenQmcLattice,
        [0.8114922, 0.7659483, 0.89876115, 0.62023693, 0.41507912],
    ),
    (
        SamplerName::OpenQmcLatticeBn,
        [0.3313058, 0.81130135, 0.44125557, 0.7684201, 0.2929374],
    ),
    (
        SamplerName::OpenQmcPmj,
        [0.36056292, 0.23409837, 0.6898367, 0.12251538, 0.24184275],
    ),
    (
        SamplerName::OpenQmcPmjBn,
        [0.59260184, 0.32382196, 0.68620837, 0.34868312, 0.20138162],
    ),
];

#[test]
fn pinned_sampler_values() {
    assert_eq!(PINNED_SAMPLERS.len(), SamplerName::ALL.len());
    for &(name, want) in PINNED_SAMPLERS {
        let mut s = config(name).build().unwrap();
        assert_eq!(s.samples_per_pixel(), 4);
        s.start_pixel_sample([2, 1], 3, 0);
        let [a, b] = s.get_pixel_2d();
        let c = s.get_1d();
        let [d, e] = s.get_2d();
        assert_eq!([a, b, c, d, e], want, "{name}");
    }
}

#[test]
fn unscrambled_sobol_pixel_sample_is_the_sequence_point() {
    // 3x2 image -> R = 4 (k = 2); the offset is x R - px for the index in use.
    let mut s = config(SamplerName::Sobol).build().unwrap();
    let Sampler::GlobalSobol(g) = &mut s else {
        panic!("sobol builds the global sampler")
    };
    g.start_pixel_sample([2, 1], 3, 0);
    let i = g.sample_index();
    let x = sample(i, 0) as f64 / 2f64.powi(32) * 4.0 - 2.0;
    let y = sample(i, 1) as f64 / 2f64.powi(32) * 4.0 - 1.0;
    assert_eq!(g.get_pixel_2d(), [x as f32, y as f32]);
    assert_eq!(g.get_1d(), sample(i, 2) as f32 / 2f32.powi(32));
}

#[test]
fn points_orders_and_ranges_agree() {
    let c = config(SamplerName::Sobol);
    let gray = generate_points(&c, 64, 5..9, Order::Gray).unwrap();
    let natural = generate_points(&c, 64, 5..9, Order::Natural).unwrap();
    for k in 0..64u32 {
        for d in 5..9u32 {
            let j = (k * 4 + d - 5) as usize;
            assert_eq!(gray[j], sample(gray_code(k), d));
            assert_eq!(natural[j], sample(k, d));
        }
    }
    // Names other than the Sobol family ignore the order; hashed ones give
    // each dimension the same value whatever range it is asked in.
    for name in [
        SamplerName::Halton,
        SamplerName::PaperRepro,
        SamplerName::PaddedSobol,
        SamplerName::ZSobol,
    ] {
        let c = config(name);
        let wide = generate_points(&c, 8, 0..6, Order::Natural).unwrap();
        let narrow = generate_points(&c, 8, 3..5, Order::Natural).unwrap();
        for k in 0..8 {
            assert_eq!(
                narrow[2 * k..2 * k + 2],
                wide[6 * k + 3..6 * k + 5],
                "{name}"
            );
        }
    }
    let h = config(SamplerName::Halton);
    assert_eq!(
        generate_points(&h, 8, 0..2, Order::Gray).unwrap(),
        generate_points(&h, 8, 0..2, Order::Natural).unwrap()
    );
}

#[test]
fn literal_paper_points_with_threshold_one_are_sobol() {
    let mut c = config(SamplerName::Paper);
    c.threshold = 1.0;
    let sobol = config(SamplerName::Sobol);
    for order in [Order::Gray, Order::Natural] {
        assert_eq!(
            generate_points(&c, 100, 0..7, order).unwrap(),
            generate_points(&sobol, 100, 0..7, order).unwrap()
        );
    }
}

#[test]
fn bad_points_requests_are_errors() {
    let c = config(SamplerName::Sobol);
    let n = NUM_DIMENSIONS as u32;
    assert!(matches!(
        generate_points(&c, 0, 0..2, Order::Gray),
        Err(Error::InvalidSampleCount { count: 0, .. })
    ));
    assert!(matches!(
        generate_points(&c, 4, 3..3, Order::Gray),
        Err(Error::DimensionOutOfRange { .. })
    ));
    assert_eq!(
        generate_points(&c, 4, n - 1..n + 1, Order::Gray),
        Err(Error::DimensionOutOfRange {
            dimension: u64::from(n),
            available: u64::from(n)
        })
    );
    assert!(generate_points(&c, 4, n - 2..n, Order::Gray).is_ok());
    let h = config(SamplerName::HaltonOwen);
    let hn = lowdisc::halton::NUM_DIMENSIONS;
    assert!(matches!(
        generate_points(&h, 4, 0..hn + 1, Order::Gray),
        Err(Error::DimensionOutOfRange { .. })
    ));
    let mut p = config(SamplerName::PaperRepro);
    for t in [f64::NAN, -0.01, 1.01] {
        p.threshold = t;
        assert!(matches!(
            generate_points(&p, 4, 0..2, Order::Gray),
            Err(Error::ThresholdOutOfRange(_))
        ));
    }
    assert!(matches!(
        generate_points(&c, u32::MAX, 0..1000, Order::Gray),
        Err(Error::InvalidSampleCount { .. })
    ));
}

#[test]
fn bad_configurations_are_errors() {
    for name in SamplerName::ALL {
        let mut c = config(name);
        c.spp = 0;
        assert!(
            matches!(c.build(), Err(Error::InvalidSampleCount { count: 0, .. })),
            "{name}"
        );
        let mut c = config(name);
        c.threshold = f64::NAN;
        assert!(
            matches!(c.build(), Err(Error::ThresholdOutOfRange(_))),
            "{name}"
        );
        for res in [[0, 5], [5, 0], [1 << 21, 3]] {
            let mut c = config(name);
            c.resolution = res;
            assert!(
                matches!(c.build(), Err(Error::InvalidResolution { .. })),
                "{name} {res:?}"
            );
        }
    }
    // Global Sobol: R^2 * spp must fit in 32 bits (4096^2 * 256 = 2^32 fits).
    let mut c = config(SamplerName::SobolOwen);
    c.resolution = [4000, 3000];
    c.spp = 256;
    assert!(c.build().is_ok());
    c.spp = 257;
    assert!(matches!(
        c.build(),
        Err(Error::InvalidSampleCount { count: 257, .. })
    ));
    // Z-order Sobol: 64-bit indices.
    let mut z = config(SamplerName::ZSobol);
    z.resolution = [1 << 20, 1 << 20];
    z.spp = 1 << 24;
    assert!(z.build().is_ok());
    z.spp = (1 << 24) + 1;
    assert!(matches!(z.build(), Err(Error::InvalidSampleCount { .. })));
}

#[test]
fn with_stream_reseeds_only_stateful_samplers() {
    let values = |s: &mut Sampler| {
        s.start_pixel_sample([1, 0], 2, 0);
        [s.get_1d(), s.get_1d(), s.get_1d(), s.get_1d()]
    };
    for name in SamplerName::ALL {
        let Ok(s) = config(name).build() else {
            continue;
        };
        let (mut a, mut b, mut c) = (s.with_stream(1), s.with_stream(1), s.with_stream(2));
        let (va, vb, vc) = (values(&mut a), values(&mut b), values(&mut c));
        assert_eq!(va, vb, "{name}");
        if name == SamplerName::Paper {
            assert_ne!(va, vc, "{name}");
        } else {
            assert_eq!(va, vc, "{name}");
        }
    }
}

#[test]
fn every_sampler_keeps_every_value_in_the_unit_interval() {
    // Offsets in [0, 1) mean every sample lies in its pixel (film position =
    // pixel + offset); non-square, non-power-of-two images and counts.
    for name in SamplerName::ALL {
        for (res, spp) in [([1, 1], 1), ([3, 5], 3), ([17, 9], 16), ([33, 2], 5)] {
            let mut c = config(name);
            c.resolution = res;
            c.spp = spp;
            c.paper_all_dims = spp == 5;
            let mut s = c.build().unwrap();
            for y in 0..res[1] {
                for x in 0..res[0] {
                    for i in 0..spp {
                        s.start_pixel_sample([x, y], i, 0);
                        let [a, b] = s.get_pixel_2d();
                        let [d, e] = s.get_2d();
                        let v = [a, b, s.get_1d(), d, e, s.get_1d()];
                        assert!(v.iter().all(|x| (0.0..1.0).contains(x)), "{name} {v:?}");
                    }
                }
            }
        }
    }
}
