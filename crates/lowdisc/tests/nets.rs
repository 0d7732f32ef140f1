//! Generator nets as samplers: Joe & Kuo's own direction numbers given as
//! a file reproduce the built-in samplers bit for bit; other nets give the
//! points an independent matrix-vector product gives, keep the pixel
//! stratification a (0,2)-sequence pair promises, and are refused by the
//! samplers that do not read a net.

use lowdisc::Error;
use lowdisc::catalog::{NET_SAMPLERS, Order, SamplerConfig, SamplerName, generate_points};
use lowdisc::net::{DigitalNet, Net};
use lowdisc::pixel::PixelSampler;

/// Joe & Kuo's published direction numbers of Sobol dimensions 1..64.
const JOE_KUO_64: &str = include_str!("data/new-joe-kuo-6.64");

fn config(name: SamplerName, net: Net) -> SamplerConfig {
    let mut c = SamplerConfig::new(name);
    (c.seed, c.spp, c.resolution, c.net) = (11, 16, [5, 3], net);
    c
}

/// The values of a few pixels, samples and dimensions (up to 40).
fn values(config: &SamplerConfig) -> Vec<f32> {
    let mut s = config.build().unwrap();
    let mut out = Vec::new();
    for (pixel, index) in [([0, 0], 0), ([4, 2], 7), ([1, 1], 15), ([3, 0], 20)] {
        s.start_pixel_sample(pixel, index, 0);
        out.extend(s.get_pixel_2d());
        for _ in 0..20 {
            out.extend(s.get_2d());
        }
        out.push(s.get_1d());
    }
    out
}

#[test]
fn joe_kuo_file_reproduces_every_net_sampler_bit_for_bit() {
    let file = DigitalNet::from_joe_kuo("new-joe-kuo-6.64", JOE_KUO_64)
        .unwrap()
        .into_net();
    for name in NET_SAMPLERS {
        let (built_in, given) = (config(name, Net::SOBOL), config(name, file));
        let [a, b] = [&built_in, &given].map(values);
        assert!(
            a.iter().zip(&b).all(|(x, y)| x.to_bits() == y.to_bits()),
            "{name}"
        );
        for order in [Order::Gray, Order::Natural] {
            assert_eq!(
                generate_points(&built_in, 64, 0..64, order).unwrap(),
                generate_points(&given, 64, 0..64, order).unwrap(),
                "{name} {order:?}"
            );
        }
    }
}

/// A seeded upper-triangular generator matrix with a unit diagonal.
fn random_matrix(state: &mut u64) -> [u32; 32] {
    core::array::from_fn(|c| {
        *state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        let above = if c == 0 { 0 } else { u32::MAX << (32 - c) };
        (1 << (31 - c)) | ((*state >> 32) as u32 & above)
    })
}

/// Digit `r` (from the first) of point `index`, one bit at a time: the
/// definition of a digital net's point.
fn slow_point(columns: &[u32; 32], index: u32) -> u32 {
    let mut word = 0u32;
    for r in 0..32 {
        let mut digit = 0;
        for (c, column) in columns.iter().enumerate() {
            digit ^= (index >> c & 1) & (column >> (31 - r) & 1);
        }
        word |= digit << (31 - r);
    }
    word
}

#[test]
fn random_nets_give_the_points_of_their_definition_and_render() {
    let mut state = 5;
    let matrices: Vec<[u32; 32]> = (0..6).map(|_| random_matrix(&mut state)).collect();
    let net = DigitalNet::from_columns("random", matrices.clone())
        .unwrap()
        .into_net();
    let c = config(SamplerName::Sobol, net);
    let points = generate_points(&c, 100, 0..6, Order::Natural).unwrap();
    for (k, point) in points.chunks(6).enumerate() {
        for (d, &word) in point.iter().enumerate() {
            assert_eq!(
                word,
                slow_point(&matrices[d], k as u32),
                "point {k} dim {d}"
            );
        }
    }
    // Random pairs are rarely (0,2)-nets at every resolution, but the
    // samplers that do not place pixels by them accept any net.
    for name in [
        SamplerName::ZSobol,
        SamplerName::PaddedSobol,
        SamplerName::ZSobol4d,
    ] {
        let v = values(&config(name, net));
        assert!(v.iter().all(|x| (0.0..1.0).contains(x)), "{name}");
        assert_ne!(v, values(&config(name, Net::SOBOL)), "{name}");
    }
}

/// Pascal's matrix mod 2 (column `c`, digit `r`: `binomial(c, r)` odd,
/// that is `r & !c == 0`): with the identity, the classic (0,2)-sequence.
fn pascal() -> [u32; 32] {
    core::array::from_fn(|c| {
        (0..32)
            .filter(|r| r & !c == 0)
            .fold(0, |w, r| w | 1 << (31 - r))
    })
}

/// Whether the words (pairs) fall one into every box of `2^m` cells of
/// every shape `2^a x 2^(m-a)`.
fn is_0m2_net(points: &[[u32; 2]], m: u32) -> bool {
    (0..=m).all(|a| {
        let mut seen = vec![false; 1 << m];
        points.iter().all(|p| {
            let x = p[0].checked_shr(32 - a).unwrap_or(0) as usize;
            let y = p[1].checked_shr(32 - (m - a)).unwrap_or(0) as usize;
            !std::mem::replace(&mut seen[(x << (m - a)) | y], true)
        })
    })
}

#[test]
fn a_pascal_pair_net_stratifies_the_pixel_and_an_unstratified_one_does_not() {
    let identity: [u32; 32] = core::array::from_fn(|c| 1 << (31 - c));
    assert_eq!(&pascal(), lowdisc::sobol::matrix(1));
    // The identity twice: each dimension a (0,1)-sequence, the pair on the
    // diagonal.
    for (columns, stratified) in [(pascal(), true), (identity, false)] {
        let net = DigitalNet::from_columns("pair", vec![identity, columns, identity, columns])
            .unwrap()
            .into_net();
        for name in [SamplerName::ZSobol, SamplerName::PaddedSobol] {
            let mut s = config(name, net).build().unwrap();
            let offsets: Vec<[u32; 2]> = (0..16)
                .map(|k| {
                    s.start_pixel_sample([2, 1], k, 0);
                    s.get_pixel_2d()
                        .map(|v| (f64::from(v) * 4_294_967_296.0) as u32)
                })
                .collect();
            assert_eq!(is_0m2_net(&offsets, 4), stratified, "{name}");
        }
    }
}

#[test]
fn samplers_without_a_net_refuse_one_and_short_nets_are_refused() {
    let net = DigitalNet::from_joe_kuo("jk", JOE_KUO_64)
        .unwrap()
        .into_net();
    for name in SamplerName::ALL {
        let result = config(name, net).build();
        assert_eq!(result.is_ok(), name.takes_net(), "{name}");
        if !name.takes_net() {
            assert_eq!(
                result.err(),
                Some(Error::NetNotSupported {
                    sampler: name.as_str()
                })
            );
        }
    }
    let two = DigitalNet::from_columns("two", lowdisc::sobol::matrices()[..2].to_vec())
        .unwrap()
        .into_net();
    assert!(config(SamplerName::ZSobol, two).build().is_ok());
    let e = config(SamplerName::ZSobol4d, two).build().unwrap_err();
    assert_eq!(
        e.to_string(),
        "two: 2 dimensions; a sampler padded by 4-D groups needs at least 4"
    );
    let e = generate_points(&config(SamplerName::SobolOwen, two), 4, 0..3, Order::Gray);
    assert_eq!(
        e.unwrap_err(),
        Error::DimensionOutOfRange {
            dimension: 2,
            available: 2
        }
    );
}
