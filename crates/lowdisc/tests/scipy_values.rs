//! Exactness against an independent implementation: digit words of
//! `scipy.stats.qmc.Sobol(d=21201, scramble=False, bits=32)` (see
//! `scripts/scipy_sobol_fixture.py`), for the first 64 points and points near
//! 10^6, 2^31 and 2^32 in 18 dimensions up to the last (21,200).
//! scipy emits Gray-code order, so its point `k` is `sample(gray_code(k), d)`.

use lowdisc::sobol::{GrayCodeBatch, gray_code, sample};

fn fixture() -> Vec<(u32, u32, u32)> {
    include_str!("data/scipy_sobol.txt")
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            let v: Vec<u64> = l.split_whitespace().map(|t| t.parse().unwrap()).collect();
            (v[0] as u32, v[1] as u32, v[2] as u32)
        })
        .collect()
}

#[test]
fn random_access_matches_scipy() {
    let values = fixture();
    assert_eq!(values.len(), 1584);
    for (k, dim, word) in values {
        assert_eq!(
            sample(gray_code(k), dim),
            word,
            "point {k}, dimension {dim}"
        );
    }
}

#[test]
fn gray_code_batch_matches_scipy() {
    let values = fixture();
    let mut batch = GrayCodeBatch::new(21_190, 11).unwrap();
    let mut out = vec![0u32; 11 * 64];
    batch.fill(&mut out);
    let mut checked = 0;
    for &(k, dim, word) in values.iter().filter(|v| v.0 < 64 && v.1 >= 21_190) {
        assert_eq!(out[k as usize * 11 + (dim - 21_190) as usize], word);
        checked += 1;
    }
    assert_eq!(checked, 64 * 2);
}

#[test]
fn natural_and_gray_orders_give_the_same_first_2m_points() {
    for m in [4u32, 10] {
        let mut natural: Vec<u32> = (0..1u32 << m).map(|i| sample(i, 5)).collect();
        let mut gray: Vec<u32> = (0..1u32 << m).map(|i| sample(gray_code(i), 5)).collect();
        assert_ne!(natural, gray, "the orders differ point by point");
        natural.sort_unstable();
        gray.sort_unstable();
        assert_eq!(natural, gray);
    }
}
