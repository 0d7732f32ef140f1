//! Piecewise-constant 1D distribution sampled by inverting its CDF.

use super::clamp_unit;

/// A continuous sample from a [`Distribution1D`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContinuousSample {
    /// The sampled position in the distribution's domain.
    pub x: f32,
    /// Density at `x` with respect to the domain's length.
    pub pdf: f32,
    /// Index of the bin that holds `x`.
    pub offset: usize,
}

/// A discrete sample (a bin index) from a [`Distribution1D`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiscreteSample {
    /// The chosen bin.
    pub index: usize,
    /// Probability of choosing it.
    pub pmf: f32,
    /// The uniform input re-stretched to `[0, 1)` within the chosen bin
    /// (reusable as a fresh uniform sample).
    pub u_remapped: f32,
}

/// A piecewise-constant function on `[min, max]` split into `n` equal bins,
/// normalised to a density.
///
/// Negative values count by their magnitude and non-finite values as 0.
/// When every value is 0 the distribution is uniform (so it can still be
/// sampled) while [`Distribution1D::integral`] honestly reports 0.
#[derive(Clone, Debug, PartialEq)]
pub struct Distribution1D {
    func: Vec<f32>,
    /// `cdf[i]` is the probability of the bins before `i`; `cdf[n] = 1`.
    cdf: Vec<f32>,
    /// Sum of `func`.
    sum: f32,
    /// Integral of the function over the domain.
    integral: f32,
    min: f32,
    max: f32,
}

impl Distribution1D {
    /// A distribution over `[0, 1]`; `None` when `func` is empty.
    pub fn new(func: &[f32]) -> Option<Self> {
        Self::with_domain(func, 0.0, 1.0)
    }

    /// A distribution over `[min, max]`; `None` when `func` is empty or the
    /// domain is empty or not finite.
    pub fn with_domain(func: &[f32], min: f32, max: f32) -> Option<Self> {
        if func.is_empty() || !(max > min) || !(max - min).is_finite() {
            return None;
        }
        let func: Vec<f32> = func
            .iter()
            .map(|&f| if f.is_finite() { f.abs() } else { 0.0 })
            .collect();
        let n = func.len();
        let total: f64 = func.iter().map(|&f| f as f64).sum();
        let mut cdf = Vec::with_capacity(n + 1);
        if total > 0.0 && total.is_finite() {
            let mut acc = 0.0f64;
            for &f in &func {
                cdf.push((acc / total) as f32);
                acc += f as f64;
            }
        } else {
            cdf.extend((0..n).map(|i| i as f32 / n as f32));
        }
        cdf.push(1.0);
        let sum = if total.is_finite() { total as f32 } else { 0.0 };
        let integral = (total * (max - min) as f64 / n as f64) as f32;
        Some(Distribution1D {
            func,
            cdf,
            sum,
            integral,
            min,
            max,
        })
    }

    /// Number of bins.
    pub fn len(&self) -> usize {
        self.func.len()
    }
    /// Always false: a distribution has at least one bin.
    pub fn is_empty(&self) -> bool {
        self.func.is_empty()
    }
    /// The (non-negative) function values.
    pub fn func(&self) -> &[f32] {
        &self.func
    }
    /// Integral of the function over the domain (0 for an all-zero function).
    pub fn integral(&self) -> f32 {
        self.integral
    }
    /// True when every value is 0 (sampling is then uniform).
    pub fn is_all_zero(&self) -> bool {
        !(self.sum > 0.0)
    }
    /// The domain `[min, max]`.
    pub fn domain(&self) -> (f32, f32) {
        (self.min, self.max)
    }

    /// The bin whose CDF interval holds `u` (never a zero-probability bin).
    #[inline]
    fn find(&self, u: f32) -> usize {
        let i = self.cdf.partition_point(|&c| c <= u);
        i.saturating_sub(1).min(self.func.len() - 1)
    }

    /// Density of bin `i` with respect to the domain's length.
    #[inline]
    fn bin_pdf(&self, i: usize) -> f32 {
        if self.is_all_zero() {
            1.0 / (self.max - self.min)
        } else {
            self.func[i] / self.integral
        }
    }

    /// Samples a position with density proportional to the function.
    /// `u` is clamped to `[0, 1)` (NaN counts as 0).
    pub fn sample_continuous(&self, u: f32) -> ContinuousSample {
        let u = clamp_unit(u);
        let o = self.find(u);
        let width = self.cdf[o + 1] - self.cdf[o];
        let du = if width > 0.0 {
            ((u - self.cdf[o]) / width).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let n = self.func.len() as f32;
        let t = ((o as f32 + du) / n).min(1.0);
        let x = (self.min + t * (self.max - self.min)).min(self.max);
        ContinuousSample {
            x,
            pdf: self.bin_pdf(o),
            offset: o,
        }
    }

    /// The bin holding position `x` (clamped to the domain).
    #[inline]
    pub fn offset_of(&self, x: f32) -> usize {
        let t = (x - self.min) / (self.max - self.min) * self.func.len() as f32;
        if t > 0.0 {
            (t as usize).min(self.func.len() - 1)
        } else {
            0
        }
    }

    /// Density of [`Distribution1D::sample_continuous`] at `x` (0 outside the
    /// domain or for NaN).
    pub fn pdf(&self, x: f32) -> f32 {
        if !(x >= self.min && x <= self.max) {
            return 0.0;
        }
        self.bin_pdf(self.offset_of(x))
    }

    /// Samples a bin with probability proportional to its value.
    pub fn sample_discrete(&self, u: f32) -> DiscreteSample {
        let u = clamp_unit(u);
        let index = self.find(u);
        let width = self.cdf[index + 1] - self.cdf[index];
        let u_remapped = if width > 0.0 {
            clamp_unit((u - self.cdf[index]) / width)
        } else {
            0.0
        };
        DiscreteSample {
            index,
            pmf: self.pmf(index),
            u_remapped,
        }
    }

    /// Probability that [`Distribution1D::sample_discrete`] picks bin `i`
    /// (0 when out of range).
    pub fn pmf(&self, i: usize) -> f32 {
        match self.func.get(i) {
            None => 0.0,
            Some(_) if self.is_all_zero() => 1.0 / self.func.len() as f32,
            Some(&f) => f / self.sum,
        }
    }
}
