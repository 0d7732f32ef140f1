//! Parsers for the structured command-line values (`--pixel X,Y`,
//! `--res WxH`, `--dim-range A..B`, sampler names), each returning a
//! one-line error that says what was expected.

use std::ops::Range;
use std::str::FromStr;

use anyhow::{Context, Result, anyhow, bail};
use lowdisc::catalog::{SamplerConfig, SamplerName};

/// A sampler name, or an error listing every known name.
pub fn sampler_name(text: &str) -> Result<SamplerName> {
    SamplerName::from_str(text.trim()).map_err(|_| {
        let known: Vec<&str> = SamplerName::ALL.iter().map(|n| n.as_str()).collect();
        anyhow!(
            "unknown sampler `{text}`; known samplers: {}",
            known.join(", ")
        )
    })
}

/// The long help of a `--sampler` option: every catalog name with its
/// one-line description.
pub fn sampler_list() -> String {
    let width = SamplerName::ALL.iter().map(|n| n.as_str().len()).max();
    let lines = SamplerName::ALL.iter().map(|n| {
        let pad = width.unwrap_or(0);
        format!("  {:pad$}  {}", n.as_str(), n.description())
    });
    format!(
        "Sampler name, one of:\n{}",
        lines.collect::<Vec<_>>().join("\n")
    )
}

/// A paper-permutation threshold in `[0, 1]` (NaN rejected).
pub fn threshold(value: f64) -> Result<f64> {
    if (0.0..=1.0).contains(&value) {
        Ok(value)
    } else {
        bail!("--threshold must lie in [0, 1], got {value}")
    }
}

fn number(text: &str, what: &str, whole: &str, flag: &str) -> Result<u32> {
    text.trim().parse::<u32>().with_context(|| {
        format!("malformed {flag} `{whole}`: {what} `{text}` is not a non-negative integer")
    })
}

/// `X,Y`: a pixel.
pub fn pixel(text: &str) -> Result<[u32; 2]> {
    let Some((x, y)) = text.split_once(',') else {
        bail!("malformed --pixel `{text}`: expected X,Y (e.g. --pixel 0,1)");
    };
    Ok([
        number(x, "X", text, "--pixel")?,
        number(y, "Y", text, "--pixel")?,
    ])
}

/// `WxH`: an image resolution, both sides at least 1.
pub fn resolution(text: &str) -> Result<[u32; 2]> {
    let Some((w, h)) = text.split_once(['x', 'X']) else {
        bail!("malformed --res `{text}`: expected WxH (e.g. --res 2x2)");
    };
    let res = [
        number(w, "width", text, "--res")?,
        number(h, "height", text, "--res")?,
    ];
    if res.contains(&0) {
        bail!("malformed --res `{text}`: width and height must be at least 1");
    }
    Ok(res)
}

/// `A..B`: the dimensions `A` up to but excluding `B`, with `A < B`.
pub fn dim_range(text: &str) -> Result<Range<u32>> {
    let Some((a, b)) = text.split_once("..") else {
        bail!("malformed --dim-range `{text}`: expected A..B (e.g. --dim-range 2..4)");
    };
    let (a, b) = (
        number(a, "start", text, "--dim-range")?,
        number(b, "end", text, "--dim-range")?,
    );
    if a >= b {
        bail!("malformed --dim-range `{text}`: the start must be below the end (A..B excludes B)");
    }
    Ok(a..b)
}

/// A sampler configuration from the common options, validated.
pub fn sampler_config(
    name: &str,
    seed: u64,
    threshold_value: f64,
    paper_all_dims: bool,
) -> Result<SamplerConfig> {
    let mut config = SamplerConfig::new(sampler_name(name)?);
    config.seed = seed;
    config.threshold = threshold(threshold_value)?;
    config.paper_all_dims = paper_all_dims;
    Ok(config)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn well_formed_values_parse() {
        assert_eq!(pixel("3,4").unwrap(), [3, 4]);
        assert_eq!(pixel(" 3, 4 ").unwrap(), [3, 4]);
        assert_eq!(resolution("1280x720").unwrap(), [1280, 720]);
        assert_eq!(dim_range("2..5").unwrap(), 2..5);
        assert_eq!(sampler_name("sobol-owen").unwrap(), SamplerName::SobolOwen);
        assert_eq!(threshold(1.0).unwrap(), 1.0);
    }

    #[test]
    fn malformed_values_say_what_was_expected() {
        for (result, needle) in [
            (pixel("3").map(|_| ()), "expected X,Y"),
            (pixel("a,1").map(|_| ()), "X `a`"),
            (pixel("-1,1").map(|_| ()), "not a non-negative integer"),
            (resolution("12").map(|_| ()), "expected WxH"),
            (resolution("0x4").map(|_| ()), "at least 1"),
            (dim_range("4..4").map(|_| ()), "start must be below"),
            (dim_range("4-5").map(|_| ()), "expected A..B"),
            (
                sampler_name("sobel").map(|_| ()),
                "known samplers: independent, stratified",
            ),
            (threshold(f64::NAN).map(|_| ()), "[0, 1]"),
            (threshold(-0.5).map(|_| ()), "[0, 1]"),
        ] {
            let message = format!("{:#}", result.unwrap_err());
            assert!(message.contains(needle), "{message}");
            assert!(!message.contains('\n'), "{message}");
        }
    }
}
