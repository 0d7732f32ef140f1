//! The (0,m,2)-net check shared by the pixel-sampler tests.

/// Whether `points` (digit-word pairs, `2^m` of them) have exactly one point
/// in every elementary interval of volume `2^-m`.
pub fn is_net(points: &[[u32; 2]], m: u32) -> bool {
    assert_eq!(points.len(), 1 << m);
    (0..=m).all(|a| {
        let mut seen = vec![false; 1 << m];
        points.iter().all(|&[x, y]| {
            let cx = (u64::from(x) >> (32 - a)) as usize;
            let cy = (u64::from(y) >> (32 - (m - a))) as usize;
            let cell = (cx << (m - a)) | cy;
            !std::mem::replace(&mut seen[cell], true)
        })
    })
}
