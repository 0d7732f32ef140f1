//! The matrix file format: one dimension per line, its 32 generator-matrix
//! columns in order (column `c` is the digit word that index bit `c`
//! contributes; bit 31 is the first binary digit), each hexadecimal with a
//! `0x` prefix or decimal, separated by spaces, tabs or commas. `#` starts
//! a comment; blank lines are skipped. Every dimension must be a
//! `(0,1)`-sequence (see [`super::DigitalNet::from_columns`]).

use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec::Vec;

use super::{MAX_NET_DIMENSIONS, first_singular_block};
use crate::Error;

/// The generator matrices written in `text`; errors name `source` and the
/// line (see the module documentation).
pub(super) fn parse(source: &str, text: &str) -> Result<Vec<[u32; 32]>, Error> {
    let mut out = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let fail = |reason: String| Error::InvalidNet {
            source: source.to_string(),
            line: Some(i + 1),
            reason,
        };
        let words: Vec<&str> = raw
            .split('#')
            .next()
            .unwrap_or("")
            .split(|c: char| c.is_whitespace() || c == ',')
            .filter(|w| !w.is_empty())
            .collect();
        if words.is_empty() {
            continue;
        }
        if words.len() != 32 {
            return Err(fail(format!("{} columns; a dimension has 32", words.len())));
        }
        let mut columns = [0u32; 32];
        for (c, w) in columns.iter_mut().zip(&words) {
            *c = word(w).ok_or_else(|| fail(format!("`{w}` is not a 32-bit number")))?;
        }
        if let Some(k) = first_singular_block(&columns) {
            return Err(fail(format!(
                "dimension {} is not a (0,1)-sequence: its leading {k}x{k} block is singular",
                out.len()
            )));
        }
        out.push(columns);
        if out.len() > MAX_NET_DIMENSIONS {
            return Err(fail(format!("more than {MAX_NET_DIMENSIONS} dimensions")));
        }
    }
    if out.is_empty() {
        return Err(Error::InvalidNet {
            source: source.to_string(),
            line: None,
            reason: "no dimensions (an empty file)".to_string(),
        });
    }
    Ok(out)
}

/// A column word written in hexadecimal (`0x..`) or decimal.
fn word(w: &str) -> Option<u32> {
    match w.strip_prefix("0x").or_else(|| w.strip_prefix("0X")) {
        Some(hex) => u32::from_str_radix(hex, 16).ok(),
        None => w.parse().ok(),
    }
}
