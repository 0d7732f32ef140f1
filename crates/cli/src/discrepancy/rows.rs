//! The rows of `discrepancy`: each chosen metric computed, timed and named
//! with its method, then printed as an aligned table.

use std::io::Write;
use std::time::Instant;

use anyhow::{Result, bail};
use clap::ValueEnum;
use lowdisc_metrics::{
    BoundsOptions, DistanceMetric, ExactOptions, L2Method, MetricsError, PointSet, cost,
    distance_stats, l2_discrepancies, l2_discrepancy, random_box_lower_bound, star_bounds,
    star_discrepancy_with,
};
use serde::Serialize;

use crate::limits;
use crate::progress::Reporter;

/// Which metric to compute.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Metric {
    /// Exact star discrepancy (refused when too costly: use star-bounds).
    Star,
    /// Lower and upper bounds of the star discrepancy, with their methods.
    StarBounds,
    /// The paper's lower bound only: the worst of --boxes random anchored boxes.
    StarLower,
    /// Warnock's L2-star discrepancy (square root, as scipy).
    L2Star,
    /// Centered L2 discrepancy (squared, as scipy).
    Cd,
    /// Wrap-around L2 discrepancy (squared, as scipy).
    Wd,
    /// Mixture L2 discrepancy (squared, as scipy).
    Md,
    /// Minimum Euclidean and toroidal distance, and mean nearest-neighbour distances.
    Mindist,
    /// Every metric above (exact star only when affordable).
    All,
}

/// Options shared by the metrics.
#[derive(Debug, Clone, Copy)]
pub struct Options {
    /// Random anchored boxes of the paper's lower bound.
    pub boxes: usize,
    /// Seed of the bounds' random choices.
    pub seed: u64,
    /// Work limit of the exact star discrepancy.
    pub max_work: f64,
}

/// One computed metric.
#[derive(Debug, Clone, Serialize)]
pub struct MetricRow {
    /// Metric name (`star`, `cd`, `mindist-euclidean`, ...).
    pub metric: String,
    /// The value (absent for bounds and for refused metrics).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub value: Option<f64>,
    /// Lower bound (`star-bounds`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lower: Option<f64>,
    /// Upper bound (`star-bounds`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub upper: Option<f64>,
    /// How the value was obtained, or why it is missing.
    pub method: String,
    /// Wall-clock seconds of the computation.
    pub seconds: f64,
}

impl MetricRow {
    fn value(metric: &str, value: f64, method: impl Into<String>, seconds: f64) -> Self {
        MetricRow {
            metric: metric.into(),
            value: Some(value),
            lower: None,
            upper: None,
            method: method.into(),
            seconds,
        }
    }
}

/// Runs `f` and returns its result with the elapsed seconds; counts one
/// computation done on `progress`.
fn timed<T>(progress: &Reporter, f: impl FnOnce() -> T) -> (T, f64) {
    let start = Instant::now();
    let result = f();
    progress.add(1);
    (result, start.elapsed().as_secs_f64())
}

/// The number of separate computations [`compute`] runs for `metric` (the
/// units of its progress).
pub fn computations(metric: Metric) -> u64 {
    match metric {
        Metric::All => 6,
        Metric::Mindist => 2,
        _ => 1,
    }
}

/// The method note of the exact star discrepancy in `d` dimensions.
fn exact_method(d: usize) -> &'static str {
    match d {
        1 => "exact: closed form on sorted points",
        2 => "exact: plane sweep, O(N^1.5)",
        _ => "exact: DEM-style recursion over critical boxes",
    }
}

/// Whether a metric of estimated `work` may run: `Ok(true)` within
/// `--max-work`; beyond it an error for a single metric, or (for
/// [`Metric::All`]) a refused row in `rows` and `Ok(false)`.
fn affordable(
    rows: &mut Vec<MetricRow>,
    all: bool,
    name: &str,
    work: f64,
    max_work: f64,
) -> Result<bool> {
    match limits::check_work(name, work, max_work) {
        Ok(()) => Ok(true),
        Err(why) => refuse(rows, all, name, why.to_string(), 0.0).map(|()| false),
    }
}

/// A metric that cannot run: the error `why` for a single metric, a row
/// without value (method `refused: why`) for [`Metric::All`].
fn refuse(
    rows: &mut Vec<MetricRow>,
    all: bool,
    name: &str,
    why: String,
    seconds: f64,
) -> Result<()> {
    if !all {
        bail!("{why}");
    }
    rows.push(MetricRow {
        metric: name.into(),
        value: None,
        lower: None,
        upper: None,
        method: format!("refused: {why}"),
        seconds,
    });
    Ok(())
}

/// Computes the rows of `metric` (all metrics for [`Metric::All`], where an
/// unaffordable exact star discrepancy or a one-point distance becomes a row
/// without value instead of an error).
pub fn compute(
    points: &PointSet,
    metric: Metric,
    options: &Options,
    progress: &Reporter,
) -> Result<Vec<MetricRow>> {
    let all = metric == Metric::All;
    let mut rows = Vec::new();
    let (n, d) = (points.len(), points.dims());
    if all || metric == Metric::Star {
        let exact = ExactOptions {
            max_work: options.max_work,
        };
        let (result, seconds) = timed(progress, || star_discrepancy_with(points, &exact));
        match result {
            Ok(v) => rows.push(MetricRow::value("star", v, exact_method(d), seconds)),
            Err(MetricsError::TooExpensive {
                n, estimated_work, ..
            }) => {
                let why = format!(
                    "exact star discrepancy for n = {n}, d = {d} needs about \
                     {estimated_work:.1e} operations, above --max-work {:.1e}; \
                     use --metric star-bounds for lower and upper bounds",
                    options.max_work
                );
                refuse(&mut rows, all, "star", why, seconds)?;
            }
            Err(MetricsError::TooManyDims { dims, limit }) => {
                let why = format!(
                    "exact star discrepancy supports at most {limit} dimensions, got {dims}; \
                     use --metric star-bounds for lower and upper bounds"
                );
                refuse(&mut rows, all, "star", why, seconds)?;
            }
            Err(e) => return Err(e.into()),
        }
    }
    if all || metric == Metric::StarBounds {
        let bounds_options = BoundsOptions {
            random_boxes: options.boxes,
            seed: options.seed,
            ..BoundsOptions::default()
        };
        let work = cost::bounds_work(n, d, &bounds_options);
        if affordable(&mut rows, all, "star-bounds", work, options.max_work)? {
            let (bounds, seconds) = timed(progress, || star_bounds(points, &bounds_options));
            let bounds = bounds?;
            rows.push(MetricRow {
                metric: "star-bounds".into(),
                value: None,
                lower: Some(bounds.lower),
                upper: Some(bounds.upper),
                method: format!(
                    "lower: {}; upper: {}",
                    bounds.lower_method, bounds.upper_method
                ),
                seconds,
            });
        }
    }
    let work = cost::random_box_work(n, d, options.boxes);
    if (all || metric == Metric::StarLower)
        && affordable(&mut rows, all, "star-lower", work, options.max_work)?
    {
        let (v, seconds) = timed(progress, || {
            random_box_lower_bound(points, options.boxes, options.seed)
        });
        let method = format!(
            "lower bound: worst of {} random anchored boxes (the paper's method), seed {}",
            options.boxes, options.seed
        );
        rows.push(MetricRow::value("star-lower", v, method, seconds));
    }
    let l2_wanted: Vec<(L2Method, &str)> = [
        (Metric::L2Star, L2Method::L2Star, "l2-star"),
        (Metric::Cd, L2Method::Centered, "cd"),
        (Metric::Wd, L2Method::WrapAround, "wd"),
        (Metric::Md, L2Method::Mixture, "md"),
    ]
    .into_iter()
    .filter(|(m, _, _)| all || metric == *m)
    .map(|(_, method, name)| (method, name))
    .collect();
    let l2_affordable = l2_wanted.is_empty()
        || affordable(
            &mut rows,
            all,
            "l2 discrepancies",
            cost::l2_work(n, d),
            options.max_work,
        )?;
    if !l2_affordable {
    } else if all {
        let (values, seconds) = timed(progress, || l2_discrepancies(points));
        for (method, name) in l2_wanted {
            let v = match method {
                L2Method::L2Star => values.l2_star,
                L2Method::Centered => values.cd,
                L2Method::WrapAround => values.wd,
                L2Method::Mixture => values.md,
            };
            rows.push(MetricRow::value(name, v, l2_note(method, true), seconds));
        }
    } else if let Some(&(method, name)) = l2_wanted.first() {
        let (v, seconds) = timed(progress, || l2_discrepancy(points, method));
        rows.push(MetricRow::value(name, v, l2_note(method, false), seconds));
    }
    if all || metric == Metric::Mindist {
        if points.len() < 2 && all {
            rows.push(MetricRow {
                metric: "mindist".into(),
                value: None,
                lower: None,
                upper: None,
                method: "skipped: distances need at least 2 points".into(),
                seconds: 0.0,
            });
        } else if affordable(
            &mut rows,
            all,
            "mindist",
            cost::distance_work(n, d),
            options.max_work,
        )? {
            for (distance, name) in [
                (DistanceMetric::Euclidean, "euclidean"),
                (DistanceMetric::Toroidal, "toroidal"),
            ] {
                let (stats, seconds) = timed(progress, || distance_stats(points, distance));
                let stats = stats?;
                let note = format!("{name}, exact (grid search)");
                rows.push(MetricRow::value(
                    &format!("mindist-{name}"),
                    stats.min_distance,
                    note.clone(),
                    seconds,
                ));
                rows.push(MetricRow::value(
                    &format!("mean-nn-{name}"),
                    stats.mean_nn_distance,
                    format!("{note}; same run as mindist-{name}"),
                    seconds,
                ));
            }
        }
    }
    Ok(rows)
}

/// The method note of an L2 discrepancy.
fn l2_note(method: L2Method, shared: bool) -> String {
    let form = if method.is_squared() {
        "squared"
    } else {
        "square root"
    };
    let shared = if shared {
        "; one pair sum for all four"
    } else {
        ""
    };
    format!(
        "scipy `{}` convention ({form}), exact pair sum{shared}",
        method.scipy_name()
    )
}

/// A value in a readable fixed or scientific form.
pub fn format_value(v: f64) -> String {
    if v == 0.0 || (1e-3..1e4).contains(&v.abs()) {
        format!("{v:.10}")
    } else {
        format!("{v:.6e}")
    }
}

/// A duration in seconds as ms or s.
fn format_seconds(s: f64) -> String {
    if s < 1.0 {
        format!("{:.2} ms", s * 1e3)
    } else {
        format!("{s:.3} s")
    }
}

/// Prints the rows as an aligned table: metric, value, time, method.
pub fn write_table(out: &mut impl Write, rows: &[MetricRow]) -> Result<()> {
    let cells: Vec<[String; 4]> = rows
        .iter()
        .map(|r| {
            let value = match (r.value, r.lower, r.upper) {
                (Some(v), _, _) => format_value(v),
                (None, Some(lo), Some(hi)) => {
                    format!("[{}, {}]", format_value(lo), format_value(hi))
                }
                _ => "-".into(),
            };
            [
                r.metric.clone(),
                value,
                format_seconds(r.seconds),
                r.method.clone(),
            ]
        })
        .collect();
    let header = ["metric", "value", "time", "method / notes"].map(String::from);
    let mut widths = [0usize; 3];
    for row in std::iter::once(&header).chain(&cells) {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    for row in std::iter::once(&header).chain(&cells) {
        writeln!(
            out,
            "{:<w0$}  {:<w1$}  {:>w2$}  {}",
            row[0],
            row[1],
            row[2],
            row[3],
            w0 = widths[0],
            w1 = widths[1],
            w2 = widths[2]
        )?;
    }
    Ok(())
}
