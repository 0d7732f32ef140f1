//! The renderer's pixel samplers, by catalog name: the values a renderer
//! would draw for given pixels, so they can be studied outside it.
//!
//! For each pixel and each sample index `0..spp` (in order) the row is:
//! columns 0-1 the in-pixel offset (`get_pixel_2d`), then `get_2d` pairs and,
//! for an odd last column, one `get_1d`, from the sampler as the renderer
//! uses it: the stream of the pixel's tile in the full image's grid
//! ([`lowdisc_tiles::pixel_rows`]; the paper's literal stream is replayed
//! from the tile's first pixel). This is exactly what `lowdisc points
//! --sampler NAME --pixel X,Y --spp N --res WxH --dims D-2` prints (as film
//! positions `X + offset`).

use core::str::FromStr;

use lowdisc::catalog::{MAX_POINT_WORDS, SamplerConfig, SamplerName};
use lowdisc::net::Net;
use lowdisc_tiles::{pixel_draws, pixel_rows};
use rayon::prelude::*;

use super::{EngineError, Result};

/// The most values of a sample after the pixel offset (as `lowdisc points`).
pub const MAX_EXTRA_DIMS: u32 = 1 << 16;
/// The most sampler draws of one request, the paper stream's replays
/// included.
pub const MAX_DRAWS: u64 = 1 << 32;

/// The names of every pixel sampler, in the catalog's order.
pub fn sampler_names() -> Vec<&'static str> {
    SamplerName::ALL.iter().map(|n| n.as_str()).collect()
}

/// A request for pixel samples.
#[derive(Debug, Clone, PartialEq)]
pub struct PixelSpec {
    /// Catalog name of the sampler.
    pub sampler: String,
    /// Samples per pixel.
    pub spp: u32,
    /// Image width and height.
    pub resolution: [u32; 2],
    /// The pixels (x, y), each inside the image.
    pub pixels: Vec<[u32; 2]>,
    /// Values per sample, at least 2 (the pixel offset).
    pub dims: u32,
    /// Seed of every random choice.
    pub seed: u64,
    /// The generator matrices of the Sobol samplers ([`Net::SOBOL`]: the
    /// built-in ones); a sampler that reads none refuses any other.
    pub net: Net,
}

/// The sampler called `name`; an unknown name is an error listing them all.
pub fn sampler_name(name: &str) -> Result<SamplerName> {
    SamplerName::from_str(name).map_err(|_| {
        EngineError::value(format!(
            "unknown sampler {name:?}; expected one of {}",
            sampler_names().join(", ")
        ))
    })
}

/// The samples of `spec`, `pixels x spp x dims` values (row-major).
pub fn pixel_samples(spec: &PixelSpec) -> Result<Vec<f32>> {
    let name = sampler_name(&spec.sampler)?;
    let mut config = SamplerConfig::new(name);
    config.seed = spec.seed;
    config.spp = spec.spp;
    config.resolution = spec.resolution;
    config.net = spec.net;
    let sampler = config.build()?;
    if spec.dims < 2 || spec.dims - 2 > MAX_EXTRA_DIMS {
        return Err(EngineError::value(format!(
            "dims must be between 2 (the pixel offset) and {}, got {}",
            MAX_EXTRA_DIMS + 2,
            spec.dims
        )));
    }
    let [w, h] = spec.resolution;
    if let Some((i, p)) = spec
        .pixels
        .iter()
        .enumerate()
        .find(|(_, p)| p[0] >= w || p[1] >= h)
    {
        return Err(EngineError::value(format!(
            "pixel {i} = ({}, {}) is outside the {w}x{h} image",
            p[0], p[1]
        )));
    }
    let row = spec.dims as usize;
    let per_pixel = spec.spp as usize * row;
    let total = (spec.pixels.len() as u64).saturating_mul(per_pixel as u64);
    if total > MAX_POINT_WORDS {
        return Err(EngineError::value(format!(
            "pixels * spp * dims = {total} exceeds {MAX_POINT_WORDS} values; ask in batches"
        )));
    }
    let draws = spec.pixels.iter().fold(0u64, |sum, &p| {
        sum.saturating_add(pixel_draws(&config, &sampler, p, spec.dims))
    });
    if draws > MAX_DRAWS {
        return Err(EngineError::value(format!(
            "the request needs {draws} sampler draws (the {} stream is replayed from each \
             pixel's tile start), over {MAX_DRAWS}: ask for fewer pixels or samples",
            spec.sampler
        )));
    }
    let mut out = vec![0f32; total as usize];
    if per_pixel == 0 {
        return Ok(out);
    }
    out.par_chunks_mut(per_pixel)
        .zip(spec.pixels.par_iter())
        .for_each(|(block, &pixel)| {
            let mut rows = block.chunks_exact_mut(row);
            pixel_rows(&config, &sampler, pixel, row, |r| {
                if let Some(dst) = rows.next() {
                    dst.copy_from_slice(r);
                }
            });
        });
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use lowdisc::pixel::PixelSampler;

    fn spec(sampler: &str, pixels: Vec<[u32; 2]>, dims: u32) -> PixelSpec {
        PixelSpec {
            sampler: sampler.into(),
            spp: 8,
            resolution: [4, 3],
            pixels,
            dims,
            seed: 5,
            net: Net::SOBOL,
        }
    }

    #[test]
    fn rows_are_the_calls_a_renderer_makes() {
        // The paper's stream depends on the pixels before (its own test).
        for name in sampler_names().into_iter().filter(|&n| n != "paper") {
            let got = pixel_samples(&spec(name, vec![[1, 2], [3, 0]], 5)).unwrap();
            assert_eq!(got.len(), 2 * 8 * 5);
            let mut config = SamplerConfig::new(name.parse().unwrap());
            (config.seed, config.spp, config.resolution) = (5, 8, [4, 3]);
            for (p, pixel) in [[1u32, 2], [3, 0]].into_iter().enumerate() {
                let mut s = config.build().unwrap().with_stream(0);
                for index in 0..8 {
                    s.start_pixel_sample(pixel, index, 0);
                    let [a, b] = s.get_pixel_2d();
                    let [c, d] = s.get_2d();
                    let e = s.get_1d();
                    let at = (p * 8 + index as usize) * 5;
                    assert_eq!(&got[at..at + 5], &[a, b, c, d, e], "{name}");
                }
            }
        }
    }

    #[test]
    fn the_paper_stream_is_its_tiles_replayed() {
        let mut config = SamplerConfig::new(SamplerName::Paper);
        (config.seed, config.spp, config.resolution) = (5, 8, [4, 3]);
        let s = config.build().unwrap();
        let mut want = Vec::new();
        pixel_rows(&config, &s, [3, 0], 4, |r| want.extend_from_slice(r));
        assert_eq!(
            pixel_samples(&spec("paper", vec![[3, 0]], 4)).unwrap(),
            want
        );
        // Without the replay of pixels (0..3, 0) the stream gives other values.
        let mut fresh = s.with_stream(0);
        let mut alone = Vec::new();
        for index in 0..8 {
            fresh.start_pixel_sample([3, 0], index, 0);
            alone.extend(fresh.get_pixel_2d());
            alone.extend(fresh.get_2d());
        }
        assert_ne!(alone, want);
    }

    #[test]
    fn a_pixel_does_not_depend_on_the_others_asked_for() {
        for name in sampler_names() {
            let alone = pixel_samples(&spec(name, vec![[2, 1]], 4)).unwrap();
            let many = pixel_samples(&spec(name, vec![[0, 0], [2, 1], [3, 2]], 4)).unwrap();
            assert_eq!(alone[..], many[32..64], "{name}");
        }
    }

    #[test]
    fn bad_requests_are_refused_with_the_reason() {
        let err = |s: PixelSpec| pixel_samples(&s).unwrap_err().to_string();
        assert!(err(spec("nope", vec![], 2)).contains("unknown sampler \"nope\""));
        assert!(err(spec("sobol", vec![[4, 0]], 2)).contains("outside the 4x3 image"));
        assert!(err(spec("sobol", vec![], 1)).contains("dims must be between 2"));
        let mut zero = spec("halton", vec![], 2);
        zero.spp = 0;
        assert!(err(zero).contains("at least one sample per pixel"));
        let mut halton = spec("halton", vec![], 2);
        halton.net = Net::named("onetwo").unwrap();
        assert!(err(halton).contains("does not take generator matrices"));
    }

    #[test]
    fn a_net_changes_the_samplers_that_read_it_only_as_its_matrices_do() {
        use crate::engine::nets::{NetSource, resolve};
        let mut with = spec("zsobol-4d", vec![[1, 2]], 6);
        let plain = pixel_samples(&with).unwrap();
        with.net = resolve(&NetSource::Matrices(
            lowdisc::sobol::matrices()[..4].to_vec(),
        ))
        .unwrap();
        assert_eq!(pixel_samples(&with).unwrap(), plain);
        with.net = Net::named("onetwo").unwrap();
        assert_ne!(pixel_samples(&with).unwrap(), plain);
    }
}
