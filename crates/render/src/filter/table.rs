//! A tabulated filter and its piecewise-constant 2-D sampling distribution,
//! used to importance-sample filters with no analytic inverse (pbrt-v4's
//! `FilterSampler`).
//!
//! The filter is evaluated at the centres of a grid of `32 * radius` cells per
//! axis over `[-rx, rx] x [-ry, ry]`. Sampling picks a row by its integral of
//! `|f|` (the marginal), then a cell in that row (the conditional), then a
//! uniform point inside the cell; the returned weight is `f(cell) / pdf`,
//! which is `± ∫|f|` (of the table): constant for a positive filter.
//!
//! Each CDF has a guide table (one entry per bucket, as many as the CDF has
//! cells): where the search for a `u` in that bucket starts, so inverting
//! takes a step or two instead of a binary search. The result is exactly
//! the binary search's.

/// Cells per unit of filter radius (pbrt-v4's choice).
pub const CELLS_PER_UNIT_RADIUS: f32 = 32.0;

/// A tabulated 2-D filter with its sampling distribution.
#[derive(Clone, Debug)]
pub struct FilterTable {
    radius: [f32; 2],
    nx: usize,
    ny: usize,
    /// Signed filter values, row-major (`y * nx + x`).
    values: Vec<f32>,
    /// Cumulative `|f|` per row, normalised: `ny + 1` entries.
    marginal_cdf: Vec<f64>,
    /// Cumulative `|f|` within each row, normalised: `ny * (nx + 1)` entries.
    conditional_cdf: Vec<f64>,
    /// The guide of `marginal_cdf` (see [`guide`]): `ny` entries.
    marginal_guide: Vec<u32>,
    /// The guides of the rows of `conditional_cdf`: `ny * nx` entries.
    conditional_guide: Vec<u32>,
    /// `∫|f|` over the domain, of the piecewise-constant table.
    abs_integral: f64,
}

impl FilterTable {
    /// Tabulates `f` over `[-radius, radius]` (radius components must be
    /// positive and finite; the caller checks).
    pub fn new(radius: [f32; 2], f: impl Fn(f32, f32) -> f32) -> FilterTable {
        let cells = |r: f32| ((CELLS_PER_UNIT_RADIUS * r) as usize).max(1);
        let (nx, ny) = (cells(radius[0]), cells(radius[1]));
        let mut values = Vec::with_capacity(nx * ny);
        for j in 0..ny {
            let y = -radius[1] + 2.0 * radius[1] * ((j as f32 + 0.5) / ny as f32);
            for i in 0..nx {
                let x = -radius[0] + 2.0 * radius[0] * ((i as f32 + 0.5) / nx as f32);
                let v = f(x, y);
                values.push(if v.is_finite() { v } else { 0.0 });
            }
        }
        let mut conditional_cdf = Vec::with_capacity(ny * (nx + 1));
        let mut row_sums = Vec::with_capacity(ny);
        for row in values.chunks_exact(nx) {
            let start = conditional_cdf.len();
            conditional_cdf.push(0.0);
            let mut acc = 0.0f64;
            for &v in row {
                acc += f64::from(v.abs());
                conditional_cdf.push(acc);
            }
            normalise_cdf(&mut conditional_cdf[start..]);
            row_sums.push(acc);
        }
        let mut marginal_cdf = Vec::with_capacity(ny + 1);
        marginal_cdf.push(0.0);
        let mut acc = 0.0f64;
        for &s in &row_sums {
            acc += s;
            marginal_cdf.push(acc);
        }
        normalise_cdf(&mut marginal_cdf);
        let cell_area = f64::from(2.0 * radius[0]) * f64::from(2.0 * radius[1]) / (nx * ny) as f64;
        let marginal_guide = guide(&marginal_cdf);
        let conditional_guide = conditional_cdf
            .chunks_exact(nx + 1)
            .flat_map(guide)
            .collect();
        FilterTable {
            radius,
            nx,
            ny,
            values,
            marginal_cdf,
            conditional_cdf,
            marginal_guide,
            conditional_guide,
            abs_integral: acc * cell_area,
        }
    }

    /// Number of cells `[nx, ny]`.
    pub fn size(&self) -> [usize; 2] {
        [self.nx, self.ny]
    }

    /// `∫|f|` of the tabulated function.
    pub fn abs_integral(&self) -> f64 {
        self.abs_integral
    }

    /// Density (per unit area) of [`Self::sample`] at offset `p`.
    pub fn pdf(&self, p: [f32; 2]) -> f32 {
        match self.cell_of(p) {
            Some(k) if self.abs_integral > 0.0 => {
                (f64::from(self.values[k].abs()) / self.abs_integral) as f32
            }
            Some(_) => (1.0 / (4.0 * f64::from(self.radius[0]) * f64::from(self.radius[1]))) as f32,
            None => 0.0,
        }
    }

    /// Samples an offset from `u` in `[0,1)^2`; returns the offset and
    /// `f(cell) / pdf`. A table that is zero everywhere is sampled uniformly
    /// with weight 0.
    #[inline]
    pub fn sample(&self, u: [f32; 2]) -> ([f32; 2], f32) {
        let (j, dv) = sample_cdf(&self.marginal_cdf, &self.marginal_guide, f64::from(u[1]));
        let (nx, ny) = (self.nx, self.ny);
        let row = &self.conditional_cdf[j * (nx + 1)..][..nx + 1];
        let row_guide = &self.conditional_guide[j * nx..][..nx];
        let (i, du) = sample_cdf(row, row_guide, f64::from(u[0]));
        // Cell counts fit in `u32` (at most 32 * 64 per axis), so these
        // conversions give `i as f64` and `nx as f64` exactly, in one
        // instruction each.
        let fx = ((f64::from(i as u32) + du) / f64::from(nx as u32)) as f32;
        let fy = ((f64::from(j as u32) + dv) / f64::from(ny as u32)) as f32;
        let [rx, ry] = self.radius;
        let offset = [
            (-rx + 2.0 * rx * fx).clamp(-rx, rx),
            (-ry + 2.0 * ry * fy).clamp(-ry, ry),
        ];
        let v = self.values[j * nx + i];
        let weight = if v == 0.0 {
            0.0
        } else {
            (self.abs_integral as f32).copysign(v)
        };
        (offset, weight)
    }

    /// The cell holding offset `p`, if inside the domain.
    fn cell_of(&self, p: [f32; 2]) -> Option<usize> {
        let [rx, ry] = self.radius;
        if !(p[0].abs() <= rx && p[1].abs() <= ry) {
            return None;
        }
        let i = (((p[0] + rx) / (2.0 * rx)) * self.nx as f32) as usize;
        let j = (((p[1] + ry) / (2.0 * ry)) * self.ny as f32) as usize;
        Some(j.min(self.ny - 1) * self.nx + i.min(self.nx - 1))
    }
}

/// Divides a running sum by its last entry; an all-zero sum becomes uniform.
fn normalise_cdf(cdf: &mut [f64]) {
    let n = cdf.len() - 1;
    let total = cdf[n];
    if total > 0.0 {
        cdf.iter_mut().for_each(|c| *c /= total);
    } else {
        cdf.iter_mut()
            .enumerate()
            .for_each(|(i, c)| *c = i as f64 / n as f64);
    }
    cdf[n] = 1.0;
}

/// The guide of a CDF of `n` buckets (`n + 1` entries): entry `g` is the
/// number of entries `<= g / n`, where [`sample_cdf`] starts looking for a
/// `u` of bucket `g`.
fn guide(cdf: &[f64]) -> Vec<u32> {
    let n = cdf.len() - 1;
    (0..n)
        .map(|g| cdf.partition_point(|&c| c <= g as f64 / n as f64) as u32)
        .collect()
}

/// Inverts a normalised CDF (`n + 1` entries) with its [`guide`]: the
/// bucket `o` with `cdf[o] <= u < cdf[o+1]` and the position `du` in
/// `[0,1)` inside it.
#[inline(always)]
fn sample_cdf(cdf: &[f64], guide: &[u32], u: f64) -> (usize, f64) {
    let n = cdf.len() - 1;
    // The number of entries `<= u` (a binary search's partition point),
    // walked to from the guide's start: any start reaches the same point,
    // as the CDF never decreases. NaN and negative `u` search directly.
    let end = if u >= 0.0 {
        // `u * n >= 0` here, so truncating through `i64` (one instruction)
        // gives the `usize` truncation, saturating alike once `min`-ed.
        let g = ((u * n as i64 as f64) as i64 as usize).min(n - 1);
        let mut p = guide.get(g).map_or(0, |&p| p as usize);
        while let Some(&c) = cdf.get(p.wrapping_sub(1)) {
            if !(c > u) {
                break;
            }
            p -= 1;
        }
        while let Some(&c) = cdf.get(p) {
            if !(c <= u) {
                break;
            }
            p += 1;
        }
        p
    } else {
        cdf.partition_point(|&c| c <= u)
    };
    let o = end.saturating_sub(1).min(n - 1);
    let (lo, hi) = (cdf[o], cdf[o + 1]);
    let width = hi - lo;
    let du = if width > 0.0 {
        ((u - lo) / width).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (o, du)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cdf_inversion_skips_empty_buckets() {
        let cdf = [0.0, 0.5, 0.5, 1.0];
        let g = guide(&cdf);
        assert_eq!(sample_cdf(&cdf, &g, 0.25), (0, 0.5));
        assert_eq!(sample_cdf(&cdf, &g, 0.5), (2, 0.0));
        assert_eq!(sample_cdf(&cdf, &g, 0.75), (2, 0.5));
        assert_eq!(sample_cdf(&cdf, &g, 0.0), (0, 0.0));
    }

    /// The guided inversion finds the binary search's bucket for every `u`,
    /// whatever the guide says (a guide only moves the start).
    #[test]
    fn guided_inversion_equals_the_binary_search() {
        let binary = |cdf: &[f64], u: f64| {
            let n = cdf.len() - 1;
            cdf.partition_point(|&c| c <= u)
                .saturating_sub(1)
                .min(n - 1)
        };
        let cdfs: [&[f64]; 3] = [
            &[0.0, 0.5, 0.5, 1.0],
            &[0.0, 0.0, 0.0, 0.01, 0.02, 0.9, 0.9, 1.0, 1.0],
            &[0.0, 0.1, 0.3, 0.6, 1.0],
        ];
        let us = (0..=1000).map(|k| f64::from(k) / 1000.0);
        let us = us.chain([-0.5, f64::NAN, 1.5, 1.0 - f64::EPSILON, 0.01, 0.02]);
        for cdf in cdfs {
            let n = cdf.len() - 1;
            let shifted: Vec<u32> = (0..n as u32)
                .map(|g| (g * 7 + 3) % (n as u32 + 1))
                .collect();
            for u in us.clone() {
                let want = binary(cdf, u);
                for g in [guide(cdf), shifted.clone()] {
                    assert_eq!(sample_cdf(cdf, &g, u).0, want, "{cdf:?} {u}");
                }
            }
        }
    }

    /// The table's sampling written plainly (binary searches, `usize`
    /// conversions): [`FilterTable::sample`] must give its values bit for bit.
    fn plain_sample(t: &FilterTable, u: [f32; 2]) -> ([f32; 2], f32) {
        let invert = |cdf: &[f64], u: f64| {
            let n = cdf.len() - 1;
            let o = cdf
                .partition_point(|&c| c <= u)
                .saturating_sub(1)
                .min(n - 1);
            let width = cdf[o + 1] - cdf[o];
            let du = if width > 0.0 {
                ((u - cdf[o]) / width).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (o, du)
        };
        let (j, dv) = invert(&t.marginal_cdf, f64::from(u[1]));
        let row = &t.conditional_cdf[j * (t.nx + 1)..(j + 1) * (t.nx + 1)];
        let (i, du) = invert(row, f64::from(u[0]));
        let fx = ((i as f64 + du) / t.nx as f64) as f32;
        let fy = ((j as f64 + dv) / t.ny as f64) as f32;
        let r = t.radius;
        let offset = [
            (-r[0] + 2.0 * r[0] * fx).clamp(-r[0], r[0]),
            (-r[1] + 2.0 * r[1] * fy).clamp(-r[1], r[1]),
        ];
        let v = t.values[j * t.nx + i];
        let w = if v == 0.0 {
            0.0
        } else {
            (t.abs_integral as f32).copysign(v)
        };
        (offset, w)
    }

    #[test]
    fn sampling_equals_the_plain_inversion_bit_for_bit() {
        let gauss = |x: f32, y: f32| (-2.0 * (x * x + y * y)).exp() - 0.0003;
        let tables = [
            FilterTable::new([2.0, 1.5], gauss),
            FilterTable::new([1.0, 1.0], |x, _| if x < 0.0 { -1.0 } else { 3.0 }),
            FilterTable::new([0.5, 0.5], |x, y| (x * y).max(0.0)),
        ];
        let mut rng = lowdisc::pcg::Pcg32::new(0x9e37_79b9_7f4a_7c15, 0);
        let mut next = || rng.next_f32();
        let edges = [
            0.0,
            0.5,
            1.0 - f32::EPSILON / 2.0,
            1.0,
            -0.25,
            1.5,
            f32::NAN,
        ];
        for t in &tables {
            let mut us: Vec<[f32; 2]> = (0..20_000).map(|_| [next(), next()]).collect();
            us.extend(
                edges
                    .iter()
                    .flat_map(|&a| edges.iter().map(move |&b| [a, b])),
            );
            for u in us {
                let (got, want) = (t.sample(u), plain_sample(t, u));
                assert_eq!(got.0.map(f32::to_bits), want.0.map(f32::to_bits), "{u:?}");
                assert_eq!(got.1.to_bits(), want.1.to_bits(), "{u:?}");
            }
        }
    }

    #[test]
    fn zero_table_samples_uniformly_with_zero_weight() {
        let t = FilterTable::new([1.0, 1.0], |_, _| 0.0);
        let (p, w) = t.sample([0.75, 0.25]);
        assert_eq!(w, 0.0);
        assert!((p[0] - 0.5).abs() < 1e-6 && (p[1] + 0.5).abs() < 1e-6);
    }

    #[test]
    fn signed_table_weights_carry_the_sign() {
        // Negative on the left half, positive on the right.
        let t = FilterTable::new([1.0, 1.0], |x, _| if x < 0.0 { -1.0 } else { 3.0 });
        assert!((t.abs_integral() - 8.0).abs() < 1e-9);
        let (p, w) = t.sample([0.1, 0.5]);
        assert!(p[0] < 0.0 && w == -8.0);
        let (p, w) = t.sample([0.9, 0.5]);
        assert!(p[0] > 0.0 && w == 8.0);
        assert!((t.pdf([-0.5, 0.0]) - 1.0 / 8.0).abs() < 1e-7);
        assert!((t.pdf([0.5, 0.0]) - 3.0 / 8.0).abs() < 1e-7);
    }
}
