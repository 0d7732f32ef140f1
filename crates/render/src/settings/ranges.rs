//! The accepted range of every render setting, each checked by one function
//! here: [`super::Settings::resolve`] calls them with the source to name in
//! the error (a flag, a scene file's directive), and
//! [`crate::render::RenderOptions::validate`] calls them for options built
//! in code. Each check returns the problem in a sentence without its source.

use super::sample_range::SampleRange;

/// The most samples per pixel accepted.
pub const MAX_SPP: u32 = 1 << 24;
/// The most worker threads accepted.
pub const MAX_THREADS: usize = 1024;
/// The largest image side accepted.
pub const MAX_SIDE: u32 = 16_384;
/// The most pixels accepted (a 16k x 16k image).
pub const MAX_PIXELS: u64 = 1 << 28;
/// The largest `max_depth` accepted (pbrt scenes use up to a few hundred).
pub const MAX_DEPTH_LIMIT: u32 = 10_000;

/// A problem with one setting's value, in a sentence.
pub type Check = Result<(), String>;

/// Samples per pixel in `1..=MAX_SPP`.
pub fn spp(spp: u32) -> Check {
    ok_if((1..=MAX_SPP).contains(&spp), || {
        format!("samples per pixel {spp} must be between 1 and {MAX_SPP}")
    })
}

/// The paper permutation's threshold in `[0, 1]` (not NaN).
pub fn threshold(t: f64) -> Check {
    ok_if((0.0..=1.0).contains(&t), || {
        format!("threshold {t} must lie in [0, 1]")
    })
}

/// The path depth at most [`MAX_DEPTH_LIMIT`].
pub fn max_depth(d: u32) -> Check {
    ok_if(d <= MAX_DEPTH_LIMIT, || {
        format!("max depth {d} must be at most {MAX_DEPTH_LIMIT}")
    })
}

/// Worker threads in `1..=MAX_THREADS`.
pub fn threads(t: usize) -> Check {
    ok_if((1..=MAX_THREADS).contains(&t), || {
        format!("thread count {t} must be between 1 and {MAX_THREADS}")
    })
}

/// A resolution with sides in `1..=MAX_SIDE` and at most [`MAX_PIXELS`] pixels.
pub fn resolution(r: [u32; 2]) -> Check {
    let [w, h] = r;
    ok_if(w >= 1 && h >= 1, || {
        format!("resolution {w}x{h}: width and height must be at least 1")
    })?;
    let pixels = u64::from(w) * u64::from(h);
    ok_if(
        w <= MAX_SIDE && h <= MAX_SIDE && pixels <= MAX_PIXELS,
        || format!("resolution {w}x{h} is too large: each side must be at most {MAX_SIDE} pixels"),
    )
}

/// A sample range that is non-empty and within `0..spp`.
pub fn samples(r: SampleRange, spp: u32) -> Check {
    ok_if(!r.is_empty() && r.end <= spp, || {
        format!("sample range {r} must be non-empty and within 0..{spp}")
    })
}

fn ok_if(ok: bool, problem: impl FnOnce() -> String) -> Check {
    if ok { Ok(()) } else { Err(problem()) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_are_inclusive_and_nan_is_refused() {
        assert!(spp(1).is_ok() && spp(MAX_SPP).is_ok());
        assert!(spp(0).is_err() && spp(MAX_SPP + 1).is_err());
        assert!(threshold(0.0).is_ok() && threshold(1.0).is_ok());
        assert!(threshold(f64::NAN).is_err() && threshold(1.5).is_err());
        assert!(max_depth(MAX_DEPTH_LIMIT).is_ok() && max_depth(MAX_DEPTH_LIMIT + 1).is_err());
        assert!(threads(0).is_err() && threads(MAX_THREADS + 1).is_err());
        assert!(resolution([0, 4]).is_err() && resolution([MAX_SIDE, 1]).is_ok());
        assert!(resolution([MAX_SIDE + 1, 1]).is_err());
        assert!(samples(SampleRange::new(2, 2), 4).is_err());
        assert!(samples(SampleRange::new(0, 5), 4).is_err());
        assert!(samples(SampleRange::new(3, 4), 4).is_ok());
    }
}
