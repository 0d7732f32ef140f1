//! Test support: whether a point set of digit words is stratified in
//! elementary boxes, and the (t,m,s)-net checks built on it, shared by the
//! structural tests of the sequences and pixel samplers.

use alloc::vec::Vec;

/// Whether every elementary box with `bits[i]` leading binary digits on
/// axis `i` holds `points.len() >> sum(bits)` points (at most one when
/// fewer points than boxes are given).
pub(crate) fn stratified(points: &[Vec<u32>], bits: &[u32]) -> bool {
    let m: u32 = bits.iter().sum();
    let mut count = alloc::vec![0usize; 1 << m];
    for p in points {
        let cell = p.iter().zip(bits).fold(0usize, |c, (&w, &b)| {
            (c << b) | w.checked_shr(32 - b).unwrap_or(0) as usize
        });
        count[cell] += 1;
    }
    let want = (points.len() >> m).max(1);
    count.iter().all(|&c| c <= want) && (points.len() < 1 << m || count.iter().all(|&c| c == want))
}

/// Every split of `m` digits over `dims` axes.
pub(crate) fn shapes(m: u32, dims: usize) -> Vec<Vec<u32>> {
    if dims == 1 {
        return alloc::vec![alloc::vec![m]];
    }
    (0..=m)
        .flat_map(|a| {
            shapes(m - a, dims - 1).into_iter().map(move |mut r| {
                r.insert(0, a);
                r
            })
        })
        .collect()
}

/// Whether `points` is stratified in every elementary box of `m` digits
/// in base `2^digit_bits` (a (0,m,s)-net when there are `b^m` points).
pub(crate) fn is_net(points: &[Vec<u32>], m: u32, digit_bits: u32) -> bool {
    shapes(m, points[0].len()).iter().all(|shape| {
        let bits: Vec<u32> = shape.iter().map(|d| digit_bits * d).collect();
        stratified(points, &bits)
    })
}

/// The smallest `t` for which `points` (`2^m` of them) is a binary
/// (t, m, s)-net.
pub(crate) fn t_value(points: &[Vec<u32>], m: u32) -> u32 {
    (0..=m).find(|&t| is_net(points, m - t, 1)).unwrap_or(m)
}
