// Shared by `build.rs` (which `include!`s this file to build the Joe-Kuo
// table) and `net::joe_kuo` (user-given direction numbers), so both turn
// direction numbers into generator matrices with the same code.

/// The 32 generator-matrix columns of one dimension from its primitive
/// polynomial coefficients `a` (degree `s = m.len()`, `1 <= s <= 32`) and
/// initial direction numbers `m_1..m_s` (Joe & Kuo's notation; `m_i` odd
/// and `< 2^i`). Column `c` is the digit word contributed by index bit `c`
/// (bit 31 = first digit), by the recurrence of Joe & Kuo's reference
/// generator.
fn sobol_columns(a: u32, m: &[u32]) -> [u32; 32] {
    let s = m.len();
    let mut v = [0u32; 32];
    for i in 0..s.min(32) {
        v[i] = m[i] << (31 - i);
    }
    for i in s..32 {
        let mut x = v[i - s] ^ (v[i - s] >> s);
        for k in 1..s {
            if (a >> (s - 1 - k)) & 1 == 1 {
                x ^= v[i - k];
            }
        }
        v[i] = x;
    }
    v
}
