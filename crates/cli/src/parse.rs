//! Parsers for the structured command-line values (`--pixel X,Y`,
//! `--res WxH`, `--dim-range A..B`, `--sample-range A..B`,
//! `--pixel-bounds X0,X1,Y0,Y1`, sampler names, `--net NAME|FILE`), each
//! returning a one-line error that says what was expected.

use std::ops::Range;
use std::str::FromStr;

use anyhow::{Context, Result, anyhow, bail};
use lowdisc::catalog::{SamplerConfig, SamplerName};
use lowdisc::net::{DigitalNet, NAMED_NETS, Net};
use lowdisc_render::film::PixelBounds;
use lowdisc_render::render::SampleRange;

/// A sampler name, or an error with the nearest known name (when one is
/// close) and every known name.
pub fn sampler_name(text: &str) -> Result<SamplerName> {
    SamplerName::from_str(text.trim()).map_err(|_| {
        let known: Vec<&str> = SamplerName::ALL.iter().map(|n| n.as_str()).collect();
        let hint = match SamplerName::nearest(text.trim()) {
            Some(n) => format!(" (did you mean `{n}`?)"),
            None => String::new(),
        };
        anyhow!(
            "unknown sampler `{text}`{hint}; known samplers: {}",
            known.join(", ")
        )
    })
}

/// A paper-permutation threshold in `[0, 1]` (NaN rejected).
pub fn threshold(value: f64) -> Result<f64> {
    lowdisc::paper::check_threshold(value).map_err(|e| anyhow!("--threshold: {e}"))
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
    half_open(text, "--dim-range", "2..4")
}

/// The dimensions of `--dim-range A..B`, else `0..D` for `--dims D`
/// (at least 1; 2 when neither is given).
pub fn dims(range: Option<&str>, count: Option<u32>) -> Result<Range<u32>> {
    match (range, count) {
        (Some(range), _) => dim_range(range),
        (None, Some(0)) => bail!("--dims must be at least 1"),
        (None, d) => Ok(0..d.unwrap_or(2)),
    }
}

/// `A..B`: the sample indices `A` up to but excluding `B`, with `A < B`
/// (whether `B` is within the samples per pixel is checked with the
/// render's options).
pub fn sample_range(text: &str) -> Result<SampleRange> {
    half_open(text, "--sample-range", "0..8").map(|r| SampleRange::new(r.start, r.end))
}

/// `A..B` with `A < B` for `flag`.
fn half_open(text: &str, flag: &str, example: &str) -> Result<Range<u32>> {
    let Some((a, b)) = text.split_once("..") else {
        bail!("malformed {flag} `{text}`: expected A..B (e.g. {flag} {example})");
    };
    let (a, b) = (
        number(a, "start", text, flag)?,
        number(b, "end", text, flag)?,
    );
    if a >= b {
        bail!("malformed {flag} `{text}`: the start must be below the end (A..B excludes B)");
    }
    Ok(a..b)
}

/// `X0,X1,Y0,Y1`: the pixels `X0 <= x < X1`, `Y0 <= y < Y1` (pbrt-v4's
/// `pixelbounds` order), non-empty; whether they are inside the film is
/// checked with the scene.
pub fn pixel_bounds(text: &str) -> Result<PixelBounds> {
    let flag = "--pixel-bounds";
    let parts: Vec<&str> = text.split(',').collect();
    let [x0, x1, y0, y1] = parts[..] else {
        bail!("malformed {flag} `{text}`: expected X0,X1,Y0,Y1 (e.g. {flag} 0,64,0,32)");
    };
    let mut v = [0i32; 4];
    for (out, (t, what)) in v
        .iter_mut()
        .zip([(x0, "X0"), (x1, "X1"), (y0, "Y0"), (y1, "Y1")])
    {
        let n = number(t, what, text, flag)?;
        *out = i32::try_from(n)
            .with_context(|| format!("malformed {flag} `{text}`: {what} is too large"))?;
    }
    if v[0] >= v[1] || v[2] >= v[3] {
        bail!("malformed {flag} `{text}`: need X0 < X1 and Y0 < Y1 (the bounds exclude X1 and Y1)");
    }
    Ok(PixelBounds::new([v[0], v[2]], [v[1], v[3]]))
}

/// The largest net file read (bytes): Joe & Kuo's 21,201 dimensions take
/// under 2 MB.
const MAX_NET_FILE: u64 = 64 << 20;

/// `--net`: a built-in net's name ([`NAMED_NETS`]), else a file of
/// direction numbers (Joe & Kuo's format) or generator matrices
/// (`lowdisc::net`); a bad file is an error naming it and the line.
pub fn net(text: &str) -> Result<Net> {
    if let Some(net) = Net::named(text) {
        return Ok(net);
    }
    let names: Vec<&str> = NAMED_NETS.iter().map(|(n, _)| *n).collect();
    let bytes = lowdisc_files::read_input_limited(text, MAX_NET_FILE).map_err(|e| {
        anyhow!(
            "--net `{text}` is not a built-in net ({}) nor a readable file: {e}",
            names.join(", ")
        )
    })?;
    let contents =
        String::from_utf8(bytes).map_err(|_| anyhow!("{text}: the file is not UTF-8 text"))?;
    Ok(DigitalNet::parse(text, &contents)?.into_net())
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
        assert_eq!(sample_range("4..9").unwrap(), SampleRange::new(4, 9));
        let b = PixelBounds::new([1, 3], [2, 7]);
        assert_eq!(pixel_bounds("1,2,3,7").unwrap(), b);
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
                sample_range("3").map(|_| ()),
                "--sample-range `3`: expected A..B",
            ),
            (sample_range("3..3").map(|_| ()), "start must be below"),
            (pixel_bounds("0,4,0").map(|_| ()), "expected X0,X1,Y0,Y1"),
            (
                pixel_bounds("0,4,2,2").map(|_| ()),
                "need X0 < X1 and Y0 < Y1",
            ),
            (
                pixel_bounds("0,4,-1,2").map(|_| ()),
                "Y0 `-1` is not a non-negative",
            ),
            (
                pixel_bounds("0,4,0,4294967295").map(|_| ()),
                "Y1 is too large",
            ),
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
