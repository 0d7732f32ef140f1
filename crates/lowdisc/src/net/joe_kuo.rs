//! Joe & Kuo's direction-number format (`new-joe-kuo-6.21201`), read into
//! generator matrices.
//!
//! An optional header line (its first word is not a number, as `d s a
//! m_i`), then one line per dimension: its number `d`, the degree `s` of
//! its primitive polynomial, the polynomial's middle coefficients `a`
//! (`< 2^(s-1)`) and the initial direction numbers `m_1 .. m_s` (each odd,
//! `m_i < 2^i`). Dimension 0, van der Corput, is implicit: the first line
//! is dimension 1, whatever its `d` (Joe & Kuo number it 2). A first line
//! of degree 0 with no `m_i` (`0 0 0`, as Bonneel et al.'s files write
//! it) is that implicit dimension spelled out. Numbers must increase by
//! one per line. `#` starts a comment; blank lines are skipped. Degrees
//! above 32 cannot be used with 32-bit digits and are refused.

use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec::Vec;

use super::MAX_NET_DIMENSIONS;
use super::recurrence::columns;
use crate::Error;

/// The generator matrices of the direction numbers in `text`; errors name
/// `source` and the line (see the module documentation).
pub(super) fn parse(source: &str, text: &str) -> Result<Vec<[u32; 32]>, Error> {
    let identity: [u32; 32] = core::array::from_fn(|c| 1 << (31 - c));
    let mut out = alloc::vec![identity];
    let mut previous: Option<u64> = None;
    let mut started = false;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let fail = |reason: String| Error::InvalidNet {
            source: source.to_string(),
            line: Some(line),
            reason,
        };
        let words: Vec<&str> = raw
            .split('#')
            .next()
            .unwrap_or("")
            .split_whitespace()
            .collect();
        let Some(first) = words.first() else {
            continue;
        };
        let header = !first.starts_with(|c: char| c.is_ascii_digit());
        if header && started {
            return Err(fail(format!("`{first}` is not a number")));
        }
        started = true;
        if header {
            continue;
        }
        let numbers = words
            .iter()
            .map(|w| {
                w.parse::<u64>()
                    .map_err(|_| fail(format!("`{w}` is not a number")))
            })
            .collect::<Result<Vec<u64>, Error>>()?;
        let [d, s, a, ref m @ ..] = numbers[..] else {
            return Err(fail(format!(
                "{} numbers; a line holds d, s, a and m_1 .. m_s",
                numbers.len()
            )));
        };
        if let Some(p) = previous
            && d != p + 1
        {
            return Err(fail(format!(
                "dimension number {d} follows {p}; expected {}",
                p + 1
            )));
        }
        previous = Some(d);
        if s == 0 && out.len() == 1 && m.is_empty() && a == 0 {
            continue; // van der Corput spelled out
        }
        out.push(dimension(s, a, m).map_err(fail)?);
        if out.len() > MAX_NET_DIMENSIONS {
            return Err(fail(format!("more than {MAX_NET_DIMENSIONS} dimensions")));
        }
    }
    if out.len() == 1 && previous.is_none() {
        return Err(Error::InvalidNet {
            source: source.to_string(),
            line: None,
            reason: "no dimensions (an empty or truncated file)".to_string(),
        });
    }
    Ok(out)
}

/// The generator matrix of one line's degree `s`, coefficients `a` and
/// direction numbers `m`, or why they are invalid.
fn dimension(s: u64, a: u64, m: &[u64]) -> Result<[u32; 32], String> {
    if s == 0 || s > 32 {
        return Err(format!(
            "degree s = {s}; it must be 1 to 32 (32-bit digits)"
        ));
    }
    if m.len() as u64 != s {
        return Err(format!(
            "{} direction numbers for degree s = {s}; expected {s} (truncated line?)",
            m.len()
        ));
    }
    if a >> (s - 1) != 0 {
        return Err(format!("a = {a} has more than s - 1 = {} bits", s - 1));
    }
    let mut words = Vec::with_capacity(m.len());
    for (i, &mi) in m.iter().enumerate() {
        let n = i + 1;
        if mi % 2 == 0 {
            return Err(format!("m_{n} = {mi} is even; every m_i must be odd"));
        }
        if mi >> n != 0 {
            return Err(format!("m_{n} = {mi} is not below 2^{n}"));
        }
        words.push(mi as u32);
    }
    Ok(columns(a as u32, &words))
}
