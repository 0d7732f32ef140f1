//! PCG32 (O'Neill 2014, "XSH RR" output, 64-bit LCG state) with
//! random access by stream and offset.
//!
//! The default-constructed generator has the state pbrt-v3's `RNG` starts
//! with, so the literal paper variant can replay pbrt-v3's static stream.

const MULTIPLIER: u64 = 6_364_136_223_846_793_005;
/// pbrt-v3's `PCG32_DEFAULT_STATE`.
const DEFAULT_STATE: u64 = 0x853c_49e6_748f_ea9b;
/// pbrt-v3's `PCG32_DEFAULT_STREAM` (the increment, already odd).
const DEFAULT_INCREMENT: u64 = 0xda3e_39cb_94b9_5bdb;

/// A PCG32 generator: 2^64 values per stream, 2^63 streams.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Pcg32 {
    state: u64,
    increment: u64,
}

impl Default for Pcg32 {
    /// The state of pbrt-v3's default-constructed `RNG`.
    fn default() -> Self {
        Pcg32 {
            state: DEFAULT_STATE,
            increment: DEFAULT_INCREMENT,
        }
    }
}

impl Pcg32 {
    /// Seeds a generator the way the PCG reference `pcg32_srandom_r` does:
    /// `seed` picks the starting state, `stream` the sequence.
    pub fn new(seed: u64, stream: u64) -> Self {
        let mut rng = Pcg32 {
            state: 0,
            increment: (stream << 1) | 1,
        };
        rng.next_u32();
        rng.state = rng.state.wrapping_add(seed);
        rng.next_u32();
        rng
    }

    /// The next 32 random bits.
    #[inline]
    pub fn next_u32(&mut self) -> u32 {
        let old = self.state;
        self.state = old.wrapping_mul(MULTIPLIER).wrapping_add(self.increment);
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        let rot = (old >> 59) as u32;
        xorshifted.rotate_right(rot)
    }

    /// A uniform `f32` in `[0, 1)`, as pbrt-v3's `RNG::UniformFloat`
    /// (`min(OneMinusEpsilon, u * 2^-32)`).
    #[inline]
    pub fn next_f32(&mut self) -> f32 {
        let x = self.next_u32() as f32 * (1.0 / 4_294_967_296.0);
        x.min(crate::ONE_MINUS_EPSILON_F32)
    }

    /// A uniform `f64` in `[0, 1)` from 53 random bits (two draws).
    #[inline]
    pub fn next_f64(&mut self) -> f64 {
        let hi = u64::from(self.next_u32()) << 21;
        let lo = u64::from(self.next_u32()) >> 11;
        (hi | lo) as f64 * (1.0 / 9_007_199_254_740_992.0)
    }

    /// Skips `delta` draws in O(log delta) (Brown's LCG jump-ahead).
    pub fn advance(&mut self, delta: u64) {
        let (mut acc_mult, mut acc_plus) = (1u64, 0u64);
        let (mut cur_mult, mut cur_plus) = (MULTIPLIER, self.increment);
        let mut d = delta;
        while d > 0 {
            if d & 1 == 1 {
                acc_mult = acc_mult.wrapping_mul(cur_mult);
                acc_plus = acc_plus.wrapping_mul(cur_mult).wrapping_add(cur_plus);
            }
            cur_plus = cur_mult.wrapping_add(1).wrapping_mul(cur_plus);
            cur_mult = cur_mult.wrapping_mul(cur_mult);
            d >>= 1;
        }
        self.state = acc_mult.wrapping_mul(self.state).wrapping_add(acc_plus);
    }

    /// Skips the draws of a precomputed [`Jump`]: the same state as
    /// [`Pcg32::advance`] by the jump's length, in two multiplications.
    #[inline]
    pub fn jump(&mut self, jump: &Jump) {
        self.state = jump
            .mult
            .wrapping_mul(self.state)
            .wrapping_add(self.increment.wrapping_mul(jump.sum));
    }
}

/// A jump of a fixed number of draws for every PCG32 stream.
///
/// `n` steps of the LCG map the state `x` to `M^n x + c (1 + M + ... +
/// M^(n-1))` (mod `2^64`), with `c` the stream's increment: both factors
/// depend on `n` only, so they are computed once (by the doubling of
/// [`Pcg32::advance`] with increment 1) and a jump is two multiplications.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Jump {
    /// `M^n`.
    mult: u64,
    /// `1 + M + ... + M^(n-1)`.
    sum: u64,
}

impl Jump {
    /// The jump of `delta` draws.
    pub fn new(delta: u64) -> Self {
        let mut unit = Pcg32 {
            state: 0,
            increment: 1,
        };
        unit.advance(delta);
        let sum = unit.state;
        let mut one = Pcg32 {
            state: 1,
            increment: 0,
        };
        one.advance(delta);
        Jump {
            mult: one.state,
            sum,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first outputs of the PCG reference demo (`pcg32-demo`, seeded with
    /// `pcg32_srandom_r(&rng, 42u, 54u)`), as published with the reference code.
    #[test]
    fn matches_reference_demo_values() {
        let mut rng = Pcg32::new(42, 54);
        let got: [u32; 6] = core::array::from_fn(|_| rng.next_u32());
        assert_eq!(
            got,
            [
                0xa15c02b7, 0x7b47f409, 0xba1d3330, 0x83d2f293, 0xbfa4784b, 0xcbed606e
            ]
        );
    }

    #[test]
    fn advance_equals_stepping() {
        let mut a = Pcg32::new(7, 3);
        let mut b = a.clone();
        for _ in 0..1000 {
            a.next_u32();
        }
        b.advance(1000);
        assert_eq!(a, b);
        b.advance(0);
        assert_eq!(a.next_u32(), b.next_u32());
    }

    #[test]
    fn jumps_equal_advance() {
        let mut rng = Pcg32::new(99, 12345);
        for delta in [0u64, 1, 2, 7, 1000, (1 << 32) - 2, 1 << 32, u64::MAX] {
            let jump = Jump::new(delta);
            for stream in [0u64, 3, u64::MAX >> 1] {
                let mut a = Pcg32::new(rng.next_u32().into(), stream);
                let mut b = a.clone();
                a.advance(delta);
                b.jump(&jump);
                assert_eq!(a, b, "delta {delta} stream {stream}");
            }
        }
        let mut a = Pcg32::new(5, 6);
        let mut b = a.clone();
        a.jump(&Jump::new(3));
        for _ in 0..3 {
            b.next_u32();
        }
        assert_eq!(a, b);
    }

    #[test]
    fn floats_are_in_unit_interval() {
        let mut rng = Pcg32::default();
        for _ in 0..10_000 {
            let x = rng.next_f32();
            assert!((0.0..1.0).contains(&x));
            let y = rng.next_f64();
            assert!((0.0..1.0).contains(&y));
        }
    }
}
