//! Eight `f32` lanes for the ray queries (BVH box tests, triangle packets),
//! with the instruction set chosen at run time.
//!
//! Kernels are written once, generic over [`Lanes`], and instantiated twice:
//! with [`Portable`] (`wide::f32x8`: two SSE registers on a baseline x86-64
//! build, plain arrays elsewhere) and, on x86-64 CPUs with AVX2, with
//! [`Avx2`] (one AVX register, through `pulp`'s safe, run-time-checked
//! intrinsics). [`LaneSet::detect`] picks one; [`LaneSet::run`] enters the
//! target-feature context for it.
//!
//! Every operation is a single IEEE-754 operation per lane (no fused
//! multiply-adds, no approximations), and the minimum and maximum have the
//! same NaN rule in both sets, so a kernel gives bit-identical results with
//! either: images never depend on the CPU.

use wide::{CmpGe, CmpGt, CmpLe, CmpLt, CmpNe, f32x8};

/// Eight `f32` lanes: vectors `F` and lane masks `M`. The implementing value
/// is a token that proves the instruction set is available.
pub trait Lanes: Copy {
    /// Eight floats.
    type F: Copy;
    /// Eight lane masks.
    type M: Copy;
    /// All lanes `x`.
    fn splat(self, x: f32) -> Self::F;
    /// Lanes from an array.
    fn load(self, a: &[f32; 8]) -> Self::F;
    /// Lanes to an array.
    fn store(self, a: Self::F) -> [f32; 8];
    /// `a + b`.
    fn add(self, a: Self::F, b: Self::F) -> Self::F;
    /// `a - b`.
    fn sub(self, a: Self::F, b: Self::F) -> Self::F;
    /// `a * b`.
    fn mul(self, a: Self::F, b: Self::F) -> Self::F;
    /// `a / b`.
    fn div(self, a: Self::F, b: Self::F) -> Self::F;
    /// `if a > b { a } else { b }` (a NaN in either keeps `b`).
    fn max_gt(self, a: Self::F, b: Self::F) -> Self::F;
    /// `if a < b { a } else { b }` (a NaN in either keeps `b`).
    fn min_lt(self, a: Self::F, b: Self::F) -> Self::F;
    /// `|a|`.
    fn abs(self, a: Self::F) -> Self::F;
    /// `a < b` (false for NaN).
    fn lt(self, a: Self::F, b: Self::F) -> Self::M;
    /// `a <= b` (false for NaN).
    fn le(self, a: Self::F, b: Self::F) -> Self::M;
    /// `a > b` (false for NaN).
    fn gt(self, a: Self::F, b: Self::F) -> Self::M;
    /// `a >= b` (false for NaN).
    fn ge(self, a: Self::F, b: Self::F) -> Self::M;
    /// `a != b` (true for NaN).
    fn ne(self, a: Self::F, b: Self::F) -> Self::M;
    /// Lanes set in both masks.
    fn and(self, a: Self::M, b: Self::M) -> Self::M;
    /// The mask as bits, lane `l` in bit `l`.
    fn bits(self, m: Self::M) -> u32;
}

/// The portable lane set, `wide::f32x8`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Portable;

impl Lanes for Portable {
    type F = f32x8;
    type M = f32x8;
    #[inline(always)]
    fn splat(self, x: f32) -> f32x8 {
        f32x8::splat(x)
    }
    #[inline(always)]
    fn load(self, a: &[f32; 8]) -> f32x8 {
        f32x8::from(*a)
    }
    #[inline(always)]
    fn store(self, a: f32x8) -> [f32; 8] {
        a.to_array()
    }
    #[inline(always)]
    fn add(self, a: f32x8, b: f32x8) -> f32x8 {
        a + b
    }
    #[inline(always)]
    fn sub(self, a: f32x8, b: f32x8) -> f32x8 {
        a - b
    }
    #[inline(always)]
    fn mul(self, a: f32x8, b: f32x8) -> f32x8 {
        a * b
    }
    #[inline(always)]
    fn div(self, a: f32x8, b: f32x8) -> f32x8 {
        a / b
    }
    #[inline(always)]
    fn max_gt(self, a: f32x8, b: f32x8) -> f32x8 {
        // MAXPS returns its second operand unless the first is greater.
        #[cfg(target_feature = "sse")]
        {
            a.fast_max(b)
        }
        #[cfg(not(target_feature = "sse"))]
        {
            a.cmp_gt(b).blend(a, b)
        }
    }
    #[inline(always)]
    fn min_lt(self, a: f32x8, b: f32x8) -> f32x8 {
        // MINPS returns its second operand unless the first is smaller.
        #[cfg(target_feature = "sse")]
        {
            a.fast_min(b)
        }
        #[cfg(not(target_feature = "sse"))]
        {
            a.cmp_lt(b).blend(a, b)
        }
    }
    #[inline(always)]
    fn abs(self, a: f32x8) -> f32x8 {
        a.abs()
    }
    #[inline(always)]
    fn lt(self, a: f32x8, b: f32x8) -> f32x8 {
        a.cmp_lt(b)
    }
    #[inline(always)]
    fn le(self, a: f32x8, b: f32x8) -> f32x8 {
        a.cmp_le(b)
    }
    #[inline(always)]
    fn gt(self, a: f32x8, b: f32x8) -> f32x8 {
        a.cmp_gt(b)
    }
    #[inline(always)]
    fn ge(self, a: f32x8, b: f32x8) -> f32x8 {
        a.cmp_ge(b)
    }
    #[inline(always)]
    fn ne(self, a: f32x8, b: f32x8) -> f32x8 {
        a.cmp_ne(b)
    }
    #[inline(always)]
    fn and(self, a: f32x8, b: f32x8) -> f32x8 {
        a & b
    }
    #[inline(always)]
    fn bits(self, m: f32x8) -> u32 {
        m.move_mask() as u32
    }
}

#[cfg(target_arch = "x86_64")]
pub use avx2::Avx2;

#[cfg(target_arch = "x86_64")]
mod avx2 {
    use super::Lanes;
    use core::arch::x86_64::{__m256, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LE_OQ, _CMP_LT_OQ, _CMP_NEQ_UQ};
    use pulp::x86::V3;

    /// AVX2 lanes (x86-64-v3): one `__m256` register. The token is only
    /// made by [`super::LaneSet::detect`] after checking the CPU.
    #[derive(Clone, Copy, Debug)]
    pub struct Avx2(pub(super) V3);

    impl Lanes for Avx2 {
        type F = __m256;
        type M = __m256;
        #[inline(always)]
        fn splat(self, x: f32) -> __m256 {
            self.0.avx._mm256_set1_ps(x)
        }
        #[inline(always)]
        fn load(self, a: &[f32; 8]) -> __m256 {
            bytemuck::cast(*a)
        }
        #[inline(always)]
        fn store(self, a: __m256) -> [f32; 8] {
            bytemuck::cast(a)
        }
        #[inline(always)]
        fn add(self, a: __m256, b: __m256) -> __m256 {
            self.0.avx._mm256_add_ps(a, b)
        }
        #[inline(always)]
        fn sub(self, a: __m256, b: __m256) -> __m256 {
            self.0.avx._mm256_sub_ps(a, b)
        }
        #[inline(always)]
        fn mul(self, a: __m256, b: __m256) -> __m256 {
            self.0.avx._mm256_mul_ps(a, b)
        }
        #[inline(always)]
        fn div(self, a: __m256, b: __m256) -> __m256 {
            self.0.avx._mm256_div_ps(a, b)
        }
        #[inline(always)]
        fn max_gt(self, a: __m256, b: __m256) -> __m256 {
            self.0.avx._mm256_max_ps(a, b)
        }
        #[inline(always)]
        fn min_lt(self, a: __m256, b: __m256) -> __m256 {
            self.0.avx._mm256_min_ps(a, b)
        }
        #[inline(always)]
        fn abs(self, a: __m256) -> __m256 {
            let sign = self.0.avx._mm256_set1_ps(-0.0);
            self.0.avx._mm256_andnot_ps(sign, a)
        }
        #[inline(always)]
        fn lt(self, a: __m256, b: __m256) -> __m256 {
            self.0.avx._mm256_cmp_ps::<_CMP_LT_OQ>(a, b)
        }
        #[inline(always)]
        fn le(self, a: __m256, b: __m256) -> __m256 {
            self.0.avx._mm256_cmp_ps::<_CMP_LE_OQ>(a, b)
        }
        #[inline(always)]
        fn gt(self, a: __m256, b: __m256) -> __m256 {
            self.0.avx._mm256_cmp_ps::<_CMP_GT_OQ>(a, b)
        }
        #[inline(always)]
        fn ge(self, a: __m256, b: __m256) -> __m256 {
            self.0.avx._mm256_cmp_ps::<_CMP_GE_OQ>(a, b)
        }
        #[inline(always)]
        fn ne(self, a: __m256, b: __m256) -> __m256 {
            self.0.avx._mm256_cmp_ps::<_CMP_NEQ_UQ>(a, b)
        }
        #[inline(always)]
        fn and(self, a: __m256, b: __m256) -> __m256 {
            self.0.avx._mm256_and_ps(a, b)
        }
        #[inline(always)]
        fn bits(self, m: __m256) -> u32 {
            self.0.avx._mm256_movemask_ps(m) as u32
        }
    }
}

/// The lane set a query runs with.
#[derive(Clone, Copy, Debug, Default)]
pub enum LaneSet {
    /// [`Portable`].
    #[default]
    Portable,
    /// [`Avx2`].
    #[cfg(target_arch = "x86_64")]
    Avx2(Avx2),
}

impl LaneSet {
    /// The widest set this CPU runs.
    pub fn detect() -> LaneSet {
        #[cfg(target_arch = "x86_64")]
        if let Some(v3) = pulp::x86::V3::try_new() {
            return LaneSet::Avx2(Avx2(v3));
        }
        LaneSet::Portable
    }

    /// The set's name: `"avx2"` or `"portable"`.
    pub fn name(self) -> &'static str {
        match self {
            LaneSet::Portable => "portable",
            #[cfg(target_arch = "x86_64")]
            LaneSet::Avx2(_) => "avx2",
        }
    }

    /// Runs `op` with the set's lanes, compiled for its instruction set
    /// (`op` must be inlined into this call to be; mark what it calls
    /// `#[inline(always)]`).
    #[inline(always)]
    pub fn run<R>(self, op: impl RunLanes<Output = R>) -> R {
        match self {
            LaneSet::Portable => op.run(Portable),
            #[cfg(target_arch = "x86_64")]
            LaneSet::Avx2(a) => a.0.vectorize(
                #[inline(always)]
                || op.run(a),
            ),
        }
    }
}

/// An operation generic over the lane set, for [`LaneSet::run`].
pub trait RunLanes {
    /// The result.
    type Output;
    /// Runs with lanes `l`.
    fn run<L: Lanes>(self, l: L) -> Self::Output;
}
