//! Reading point sets from text files (`discrepancy --input FILE`) and from
//! the sequence catalog.
//!
//! File format: one point per line, coordinates in `[0, 1]` separated by
//! whitespace and/or commas (empty fields, e.g. a trailing comma, are
//! ignored); blank lines and lines whose first non-blank character is `#`
//! are skipped. Every line must hold as many coordinates as the first.
//! Any violation is an error naming the file and the 1-based line number.

use std::ops::Range;
use std::path::Path;

use anyhow::{Result, bail};
use lowdisc::catalog::{Order, SamplerConfig, generate_points};
use lowdisc_metrics::PointSet;

/// `2^-32`: the scale from 32-bit digit words to `[0, 1)`.
const WORD_SCALE: f64 = 1.0 / 4_294_967_296.0;

/// Reads and validates a point file (see the module documentation) whose
/// parsed points fit in `max_memory` MiB (`--max-memory`): every value takes
/// at least two bytes of text and eight of memory, so the file may hold at
/// most a fifth of that.
pub fn read_points(path: &Path, max_memory: u64) -> Result<PointSet> {
    let name = path.display();
    let limit = max_memory.saturating_mul(1 << 20) / 5;
    let bytes = lowdisc_files::read_input_limited(path, limit).map_err(|e| {
        let hint = if e.io_error().kind() == std::io::ErrorKind::InvalidData {
            " (raise --max-memory)"
        } else {
            ""
        };
        anyhow::anyhow!("{e}{hint}")
    })?;
    let text = String::from_utf8(bytes).map_err(|e| {
        let line = 1 + e.as_bytes()[..e.utf8_error().valid_up_to()]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
        anyhow::anyhow!("{name}:{line}: the file is not UTF-8 text")
    })?;
    parse_points(&text, &name.to_string())
}

/// Parses the text of a point file; `name` is used in the error messages.
pub fn parse_points(text: &str, name: &str) -> Result<PointSet> {
    let mut coords = Vec::new();
    let mut dims: Option<(usize, usize)> = None;
    for (index, raw) in text.lines().enumerate() {
        let line_no = index + 1;
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let mut count = 0;
        for field in line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|f| !f.is_empty())
        {
            count += 1;
            let value: f64 = field.parse().map_err(|_| {
                anyhow::anyhow!("{name}:{line_no}: coordinate {count} `{field}` is not a number")
            })?;
            if value.is_nan() {
                bail!("{name}:{line_no}: coordinate {count} is NaN");
            }
            if !(0.0..=1.0).contains(&value) {
                bail!("{name}:{line_no}: coordinate {count} = {field} is outside [0, 1]");
            }
            coords.push(value);
        }
        match dims {
            None => dims = Some((count, line_no)),
            Some((expected, first)) if expected != count => bail!(
                "{name}:{line_no}: {count} coordinates, but line {first} has {expected} \
                 (every point needs the same number)"
            ),
            Some(_) => {}
        }
    }
    let Some((dims, _)) = dims else {
        bail!("{name}: no points (the file is empty or holds only comments)");
    };
    Ok(PointSet::new(dims, coords)?)
}

/// The first `n` points of a catalog sequence in dimensions `dims`, each
/// digit word `w` mapped to `w * 2^-32`.
pub fn sequence_points(
    config: &SamplerConfig,
    n: u32,
    dims: Range<u32>,
    order: Order,
) -> Result<PointSet> {
    let width = dims.len();
    let words = generate_points(config, n, dims, order)?;
    let coords = words.iter().map(|&w| f64::from(w) * WORD_SCALE).collect();
    Ok(PointSet::new(width, coords)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comments_commas_and_blank_lines_are_accepted() {
        let set = parse_points("# header\n0.5, 0.25\n\n  1 0,\n0\t1\n", "f").unwrap();
        assert_eq!(set.dims(), 2);
        assert_eq!(set.coords(), &[0.5, 0.25, 1.0, 0.0, 0.0, 1.0]);
    }

    #[test]
    fn errors_name_the_file_and_line() {
        for (text, needle) in [
            (
                "0.5 0.5\n0.5 1.5\n",
                "f:2: coordinate 2 = 1.5 is outside [0, 1]",
            ),
            ("0.5 NaN\n", "f:1: coordinate 2 is NaN"),
            (
                "0.5 0.5\n# c\n0.5\n",
                "f:3: 1 coordinates, but line 1 has 2",
            ),
            ("0.5 x\n", "f:1: coordinate 2 `x` is not a number"),
            ("-0.0001\n", "outside [0, 1]"),
            ("inf\n", "outside [0, 1]"),
            ("", "f: no points"),
            ("# only\n\n", "f: no points"),
        ] {
            let message = format!("{:#}", parse_points(text, "f").unwrap_err());
            assert!(message.contains(needle), "{text:?}: {message}");
        }
    }
}
