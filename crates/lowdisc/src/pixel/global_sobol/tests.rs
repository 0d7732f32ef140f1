//! Tests of the global Sobol sampler's cached randomizations.

use super::*;

#[test]
fn cached_scrambles_equal_the_definition() {
    for r in RandomizeStrategy::ALL {
        let seed = 21;
        let mut s =
            GlobalSobolSampler::new(4, [8, 6], GlobalSobolMode::Randomize(r), seed).unwrap();
        let dims_seed = hash2(seed, SEED_PAD);
        for (visit, pixel) in [[0u32, 0], [0, 0], [3, 5], [11, 5], [3, 5], [7, 1]]
            .into_iter()
            .enumerate()
        {
            let start = [0, 1019, 30][visit % 3];
            s.start_pixel_sample(pixel, visit as u32, start);
            let index = s.sample_index();
            let [px, py] = pixel.map(|c| u64::from(c & 7));
            let offset_seed = hash_words(&[seed, SEED_PAD, PIXEL_SALT, px, py]);
            let want = [0, 1].map(|d| r.apply(sample(index, d) << 3, offset_seed, d));
            assert_eq!(s.get_pixel_2d_words(), want, "{r:?}");
            for d in start..start + 8 {
                let dim = 2 + d;
                let want = r.apply(sample(index, dim), dims_seed, dim);
                assert_eq!(s.get_1d_word(), want);
            }
        }
    }
}
