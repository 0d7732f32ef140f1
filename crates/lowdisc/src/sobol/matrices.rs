//! Access to the generator matrices that `build.rs` computes from the
//! Joe-Kuo direction numbers (see `LICENSE-JOE-KUO`).

include!(concat!(env!("OUT_DIR"), "/sobol_dimensions.rs"));

#[repr(C, align(4))]
struct Aligned<Bytes: ?Sized>(Bytes);

static RAW: &Aligned<[u8]> = &Aligned(*include_bytes!(concat!(
    env!("OUT_DIR"),
    "/sobol_matrices.bin"
)));

/// All generator matrices, one `[u32; 32]` (columns 0..32) per dimension.
#[inline]
pub(crate) fn table() -> &'static [[u32; 32]] {
    bytemuck::cast_slice(&RAW.0)
}

/// Every dimension's generator matrix ([`matrix`] of each).
#[inline]
pub fn matrices() -> &'static [[u32; 32]] {
    table()
}

/// The generator matrix of dimension `dim`: column `c` is the digit word
/// contributed by bit `c` of the index (bit 31 = first digit after the point).
///
/// # Panics
/// If `dim >= NUM_DIMENSIONS`.
#[inline]
pub fn matrix(dim: u32) -> &'static [u32; 32] {
    &table()[dim as usize]
}
