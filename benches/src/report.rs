//! Turns criterion's saved estimates into the markdown tables of the README.
//!
//! Criterion stores each benchmark's statistics under
//! `<target>/criterion/<group>/<function>/<parameter>/new/estimates.json`;
//! the median time per iteration is read from there (with a small scanner:
//! the file's layout is fixed and only one number is needed) and divided by
//! the work of one iteration ([`PAIRS`] calls, or [`BATCH_VALUES`] values).

use std::fmt;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use crate::{BATCH_VALUES, BATCH_WIDTHS, PAIRS};

/// Why a table could not be made.
#[derive(Debug)]
pub enum ReportError {
    /// An estimates file could not be read (benchmark not run?).
    Missing(PathBuf, std::io::Error),
    /// An estimates file has no readable median.
    Malformed(PathBuf),
}

impl fmt::Display for ReportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReportError::Missing(path, e) => write!(
                f,
                "cannot read {} ({e}); run `cargo bench -p lowdisc-benches` first",
                path.display()
            ),
            ReportError::Malformed(path) => {
                write!(f, "no median estimate found in {}", path.display())
            }
        }
    }
}

impl std::error::Error for ReportError {}

/// The median time of one iteration of benchmark `id` (`group/function/param`)
/// in nanoseconds, from criterion's output directory `criterion_dir`.
pub fn median_ns(criterion_dir: &Path, id: &str) -> Result<f64, ReportError> {
    let path = criterion_dir.join(id).join("new").join("estimates.json");
    let text = std::fs::read_to_string(&path).map_err(|e| ReportError::Missing(path.clone(), e))?;
    parse_median(&text).ok_or(ReportError::Malformed(path))
}

/// The `point_estimate` of the `median` entry of an estimates file.
fn parse_median(text: &str) -> Option<f64> {
    let median = &text[text.find("\"median\"")?..];
    let key = "\"point_estimate\":";
    let value = median[median.find(key)? + key.len()..].trim_start();
    let end = value.find([',', '}']).unwrap_or(value.len());
    value[..end].trim().parse().ok()
}

/// One row of the per-sample table: a label, lowdisc's benchmark and, where
/// there is a like-for-like one, `sobol_burley`'s.
struct Row {
    label: &'static str,
    lowdisc: &'static str,
    burley: Option<&'static str>,
}

const fn row(label: &'static str, lowdisc: &'static str, burley: Option<&'static str>) -> Row {
    Row {
        label,
        lowdisc,
        burley,
    }
}

/// The rows of the per-sample table, in order.
const ROWS: [Row; 12] = [
    row(
        "1-D `sample_randomized`, None",
        "sample_1d/lowdisc/none",
        None,
    ),
    row(
        "1-D `sample_randomized`, Xor",
        "sample_1d/lowdisc/xor",
        None,
    ),
    row(
        "1-D `sample_randomized`, Owen (exact)",
        "sample_1d/lowdisc/owen",
        None,
    ),
    row(
        "1-D `sample_randomized`, FastOwen (`u32`)",
        "sample_1d/lowdisc/fast-owen",
        None,
    ),
    row(
        "1-D FastOwen as `f32` vs `sobol_burley::sample`",
        "sample_1d/lowdisc/fast-owen-f32",
        Some("sample_1d/sobol_burley/sample"),
    ),
    row(
        "1-D `paper_reproducible` (threshold 0.5)",
        "sample_1d/lowdisc/paper-reproducible",
        None,
    ),
    row(
        "1-D `PaperLiteral::sample` (threshold 0.5)",
        "sample_1d/lowdisc/paper-literal",
        None,
    ),
    row("4-D `sample_4d`, None", "sample_4d/lowdisc/none", None),
    row("4-D `sample_4d`, Xor", "sample_4d/lowdisc/xor", None),
    row(
        "4-D `sample_4d`, Owen (exact)",
        "sample_4d/lowdisc/owen",
        None,
    ),
    row(
        "4-D `sample_4d`, FastOwen (`u32`)",
        "sample_4d/lowdisc/fast-owen",
        None,
    ),
    row(
        "4-D FastOwen as `f32` vs `sobol_burley::sample_4d`",
        "sample_4d/lowdisc/fast-owen-f32",
        Some("sample_4d/sobol_burley/sample_4d"),
    ),
];

/// Formats nanoseconds with three significant digits.
fn ns(value: f64) -> String {
    if value >= 100.0 {
        format!("{value:.0}")
    } else if value >= 10.0 {
        format!("{value:.1}")
    } else {
        format!("{value:.2}")
    }
}

/// The per-call table (ns per 1-D value or per 4-D call, and the ratio
/// `sobol_burley / lowdisc`: above 1 means lowdisc is faster).
pub fn sample_table(criterion_dir: &Path) -> Result<String, ReportError> {
    let mut out = String::from(
        "| operation | lowdisc ns/call | sobol_burley ns/call | ratio (burley / lowdisc) |\n\
         |---|---:|---:|---:|\n",
    );
    for r in &ROWS {
        let ours = median_ns(criterion_dir, r.lowdisc)? / PAIRS as f64;
        let (theirs, ratio) = match r.burley {
            Some(id) => {
                let theirs = median_ns(criterion_dir, id)? / PAIRS as f64;
                (ns(theirs), format!("{:.2}", theirs / ours))
            }
            None => (String::new(), String::new()),
        };
        let _ = writeln!(out, "| {} | {} | {theirs} | {ratio} |", r.label, ns(ours));
    }
    Ok(out)
}

/// The batch table: unscrambled values per second of `GrayCodeBatch::fill`
/// and `fill_f32` for each benchmarked width.
pub fn batch_table(criterion_dir: &Path) -> Result<String, ReportError> {
    let mut out = String::from(
        "| `GrayCodeBatch` width (dims per point) | `fill` (`u32`) samples/s | `fill_f32` samples/s |\n\
         |---:|---:|---:|\n",
    );
    for width in BATCH_WIDTHS {
        let rate = |kind: &str| -> Result<String, ReportError> {
            let t = median_ns(criterion_dir, &format!("gray_batch/{kind}/{width}"))?;
            Ok(format!("{:.2e}", BATCH_VALUES as f64 * 1e9 / t))
        };
        let _ = writeln!(
            out,
            "| {width} | {} | {} |",
            rate("fill")?,
            rate("fill_f32")?
        );
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_the_median_not_the_mean() {
        let text = r#"{"mean":{"confidence_interval":{"confidence_level":0.95,"lower_bound":1.0,"upper_bound":3.0},"point_estimate":2.0,"standard_error":0.1},"median":{"confidence_interval":{"confidence_level":0.95,"lower_bound":4.0,"upper_bound":6.0},"point_estimate":5.5e3,"standard_error":0.2}}"#;
        assert_eq!(parse_median(text), Some(5500.0));
        assert_eq!(parse_median("{}"), None);
    }

    #[test]
    fn tables_come_from_the_files() {
        let dir = std::env::temp_dir().join(format!("lowdisc-report-{}", std::process::id()));
        let put = |id: &str, ns: f64| {
            let d = dir.join(id).join("new");
            std::fs::create_dir_all(&d).unwrap();
            let body = format!(r#"{{"median":{{"point_estimate":{ns}}}}}"#);
            std::fs::write(d.join("estimates.json"), body).unwrap();
        };
        for r in &ROWS {
            put(r.lowdisc, 4096.0 * 10.0);
            if let Some(id) = r.burley {
                put(id, 4096.0 * 20.0);
            }
        }
        for w in BATCH_WIDTHS {
            put(&format!("gray_batch/fill/{w}"), 65536.0);
            put(&format!("gray_batch/fill_f32/{w}"), 2.0 * 65536.0);
        }
        let samples = sample_table(&dir).unwrap();
        let batch = batch_table(&dir).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        assert!(
            samples.contains("| 1-D `sample_randomized`, None | 10.0 |  |  |"),
            "{samples}"
        );
        assert!(samples.contains("| 10.0 | 20.0 | 2.00 |"), "{samples}");
        assert!(batch.contains("| 1 | 1.00e9 | 5.00e8 |"), "{batch}");
        assert!(matches!(
            median_ns(&dir, "absent"),
            Err(ReportError::Missing(..))
        ));
    }
}
