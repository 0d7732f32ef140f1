//! Tests of the Sobol core: exact values, order conventions, net property.
use super::*;

#[test]
fn first_points_are_the_textbook_values() {
    // Dimension 0 is van der Corput: 0, 1/2, 1/4, 3/4, 1/8, ...
    let vdc: [u32; 5] = core::array::from_fn(|i| sample(i as u32, 0));
    assert_eq!(vdc, [0, 0x8000_0000, 0x4000_0000, 0xc000_0000, 0x2000_0000]);
    // Dimension 1 (Joe-Kuo: s = 1, a = 0, m1 = 1): 0, 1/2, 3/4, 1/4, ...
    let d1: [u32; 4] = core::array::from_fn(|i| sample(i as u32, 1));
    assert_eq!(d1, [0, 0x8000_0000, 0xc000_0000, 0x4000_0000]);
    for dim in 0..NUM_DIMENSIONS as u32 {
        assert_eq!(sample(0, dim), 0);
        assert_eq!(sample(1, dim), 0x8000_0000);
    }
}
