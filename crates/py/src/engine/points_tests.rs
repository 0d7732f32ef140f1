//! Tests of the point requests against lowdisc's own points mode (the
//! catalog), which `lowdisc points` prints.

use lowdisc::catalog::{Order, SamplerConfig, generate_points};

use super::*;

fn spec(sequence: Sequence, scramble: &str, n: u64, d: u32) -> PointSpec {
    PointSpec {
        sequence,
        n,
        d,
        start: 0,
        natural_order: false,
        scramble: scramble.into(),
        seed: 9,
        bits: 32,
        dtype: Dtype::U32,
    }
}

fn words(spec: &PointSpec) -> Vec<u32> {
    match generate(spec).unwrap() {
        Values::U32(w) => w,
        other => panic!("expected words, got {other:?}"),
    }
}

fn catalog(name: &str, n: u32, d: u32, order: Order) -> Vec<u32> {
    let mut config = SamplerConfig::new(name.parse().unwrap());
    config.seed = 9;
    generate_points(&config, n, 0..d, order).unwrap()
}

#[test]
fn sobol_equals_the_catalog_in_both_orders_and_every_scramble() {
    for (scramble, name) in [
        ("none", "sobol"),
        ("xor", "sobol-xor"),
        ("owen", "sobol-owen"),
        ("lms", "sobol-lms"),
        ("fast-owen", "sobol-fast-owen"),
    ] {
        let mut s = spec(Sequence::Sobol, scramble, 300, 7);
        assert_eq!(words(&s), catalog(name, 300, 7, Order::Gray), "{scramble}");
        s.natural_order = true;
        assert_eq!(
            words(&s),
            catalog(name, 300, 7, Order::Natural),
            "{scramble}"
        );
    }
}

#[test]
fn halton_and_independent_equal_the_catalog() {
    let h = spec(Sequence::Halton, "permute", 200, 5);
    assert_eq!(words(&h), catalog("halton", 200, 5, Order::Gray));
    let o = spec(Sequence::Halton, "owen", 200, 5);
    assert_eq!(words(&o), catalog("halton-owen", 200, 5, Order::Gray));
    let i = spec(Sequence::Independent, "none", 200, 5);
    assert_eq!(words(&i), catalog("independent", 200, 5, Order::Gray));
    let s = spec(Sequence::Stratified, "none", 64, 3);
    assert_eq!(words(&s), catalog("stratified", 64, 3, Order::Gray));
}

#[test]
fn a_request_from_start_continues_the_sequence_across_chunks() {
    // One dimension: 65,536 points per chunk, so 70,000 points span two.
    for sequence in [Sequence::Sobol, Sequence::Halton, Sequence::Independent] {
        let scramble = if sequence == Sequence::Independent {
            "none"
        } else {
            "owen"
        };
        let all = words(&spec(sequence, scramble, 70_000, 1));
        let mut tail = spec(sequence, scramble, 30_000, 1);
        tail.start = 40_000;
        assert_eq!(words(&tail), all[40_000..], "{sequence:?}");
    }
}

#[test]
fn bits_keep_the_leading_digits_and_floats_are_the_words_scaled() {
    let mut s = spec(Sequence::Sobol, "owen", 64, 3);
    let full = words(&s);
    s.bits = 30;
    let short = words(&s);
    assert!(full.iter().zip(&short).all(|(&f, &t)| t == f & !3));
    s.dtype = Dtype::F64;
    let Values::F64(x) = generate(&s).unwrap() else {
        panic!()
    };
    assert!(
        x.iter()
            .zip(&short)
            .all(|(&v, &w)| v == f64::from(w) / 4_294_967_296.0)
    );
}

#[test]
fn bad_requests_are_refused_with_the_reason() {
    let err = |s: &PointSpec| generate(s).unwrap_err().to_string();
    let mut s = spec(Sequence::Sobol, "none", 4, 21_202);
    assert!(err(&s).contains("21201 dimensions"), "{}", err(&s));
    s.d = 0;
    assert!(err(&s).contains("at least 1"));
    s.d = 2;
    s.bits = 33;
    assert!(err(&s).contains("bits must be between 1 and 32"));
    s.bits = 32;
    s.start = u32::MAX as u64;
    assert!(err(&s).contains("2^32 points"));
    s.start = 0;
    s.scramble = "owen-per-digit".into();
    assert!(err(&s).contains("'fast-owen'"));
    let h = spec(Sequence::Halton, "none", 4, 6543);
    assert!(err(&h).contains("6542 dimensions"));
    let big = spec(Sequence::Independent, "none", 1 << 62, 2);
    assert!(
        err(&big).contains("more than an array can hold"),
        "{}",
        err(&big)
    );
    let mut strat = spec(Sequence::Stratified, "none", 4, 2);
    strat.start = 1;
    assert!(err(&strat).contains("start must be 0"));
}

#[test]
fn generator_matrices_reproduce_the_points() {
    let m = sobol_matrices(3).unwrap();
    let x = words(&spec(Sequence::Sobol, "none", 32, 3));
    for k in 0..32u32 {
        let g = k ^ (k >> 1);
        for j in 0..3 {
            let cols = &m[j * 32..(j + 1) * 32];
            let w = (0..32)
                .filter(|c| g >> c & 1 == 1)
                .fold(0, |a, c| a ^ cols[c]);
            assert_eq!(w, x[k as usize * 3 + j]);
        }
    }
    assert!(sobol_matrices(0).is_err());
}

#[test]
fn results_do_not_depend_on_the_thread_count() {
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let s = spec(Sequence::Sobol, "owen-tree", 20_000, 8);
            let p = super::super::pixel::PixelSpec {
                sampler: "zsobol".into(),
                spp: 4,
                resolution: [64, 64],
                pixels: (0..4096).map(|k| [k % 64, k / 64]).collect(),
                dims: 6,
                seed: 2,
                net: lowdisc::net::Net::SOBOL,
            };
            (words(&s), super::super::pixel::pixel_samples(&p).unwrap())
        })
    };
    assert_eq!(run(1), run(3));
}
