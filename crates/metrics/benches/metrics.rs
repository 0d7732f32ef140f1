//! Benchmarks of the metrics: exact 2-D star discrepancy at 4096/16384/65536 points and
//! the four L2-type discrepancies at n = 4096, d = 8, plus a same-run comparison with
//! `scipy.stats.qmc.discrepancy` when python3 with SciPy is available.
//!
//! Run: `cargo bench -p lowdisc-metrics --bench metrics` (short criterion settings).

use std::io::Write;
use std::process::Command;
use std::time::{Duration, Instant};

use criterion::{Criterion, criterion_group, criterion_main};
use lowdisc_metrics::{L2Method, PointSet, l2_discrepancy, star_discrepancy};

/// Seeded uniform points (SplitMix64), so every run measures the same input.
fn random_points(n: usize, d: usize, seed: u64) -> PointSet {
    let mut s = seed;
    let coords = (0..n * d)
        .map(|_| {
            s = s.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = s;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
        })
        .collect();
    PointSet::new(d, coords).expect("valid points")
}

/// The 2-D Hammersley set `(i/n, radical inverse of i in base 2)`.
fn hammersley(n: usize) -> PointSet {
    let coords = (0..n)
        .flat_map(|i| {
            let v = f64::from((i as u32).reverse_bits()) / 4_294_967_296.0;
            [i as f64 / n as f64, v]
        })
        .collect();
    PointSet::new(2, coords).expect("valid points")
}

fn bench_star(c: &mut Criterion) {
    let mut group = c.benchmark_group("star_2d_exact");
    group.sample_size(10);
    group.warm_up_time(Duration::from_millis(500));
    group.measurement_time(Duration::from_secs(3));
    for n in [4096usize, 16384, 65536] {
        let p = random_points(n, 2, 7);
        group.bench_function(format!("n={n}"), |b| {
            b.iter(|| star_discrepancy(&p).expect("2-D exact"))
        });
    }
    group.finish();
    // Wall time suffers when the machine is shared; CPU time shows the work itself.
    // Block pruning helps less on very uniform sets, so a Hammersley set is timed too.
    for (name, p) in [
        ("random", random_points(65536, 2, 7)),
        ("hammersley", hammersley(65536)),
    ] {
        let (wall, cpu, value) = measure(3, || star_discrepancy(&p).expect("2-D exact"));
        println!(
            "star 2-D exact, {name} n = 65536: best wall {wall:.3} s, mean CPU {cpu:.3} s (all threads), D* = {value:.6e}"
        );
    }
}

fn bench_l2(c: &mut Criterion) {
    let p = random_points(4096, 8, 11);
    let mut group = c.benchmark_group("l2_n4096_d8");
    group.sample_size(10);
    group.warm_up_time(Duration::from_millis(500));
    group.measurement_time(Duration::from_secs(2));
    for m in L2Method::ALL {
        group.bench_function(m.scipy_name(), |b| b.iter(|| l2_discrepancy(&p, m)));
    }
    group.finish();
    compare_with_scipy(&p);
}

/// User + system CPU seconds of this process so far (Linux /proc; NaN elsewhere).
fn cpu_seconds() -> f64 {
    let Ok(stat) = std::fs::read_to_string("/proc/self/stat") else {
        return f64::NAN;
    };
    // Fields after the command name (which ends with ')'): state is field 3, utime and
    // stime are fields 14 and 15, all threads of the process included.
    let rest = stat.rsplit_once(')').map_or("", |(_, r)| r);
    let f: Vec<&str> = rest.split_whitespace().collect();
    let field = |i: usize| f.get(i - 3).and_then(|v| v.parse::<f64>().ok());
    let (Some(utime), Some(stime)) = (field(14), field(15)) else {
        return f64::NAN;
    };
    // Clock ticks are 100 per second on Linux.
    (utime + stime) / 100.0
}

/// Best wall time and mean CPU time of `runs` runs, and the value.
fn measure(runs: usize, f: impl Fn() -> f64) -> (f64, f64, f64) {
    let mut best = f64::INFINITY;
    let mut value = 0.0;
    let cpu0 = cpu_seconds();
    for _ in 0..runs {
        let t = Instant::now();
        value = std::hint::black_box(f());
        best = best.min(t.elapsed().as_secs_f64());
    }
    (best, (cpu_seconds() - cpu0) / runs as f64, value)
}

const SCIPY_SCRIPT: &str = r#"
import sys, time, resource
import numpy as np
from scipy.stats import qmc
x = np.loadtxt(sys.argv[1], delimiter=",")
for m in ["CD", "WD", "MD", "L2-star"]:
    best = float("inf")
    c0 = resource.getrusage(resource.RUSAGE_SELF)
    for _ in range(5):
        t = time.perf_counter()
        v = qmc.discrepancy(x, method=m)
        best = min(best, time.perf_counter() - t)
    c1 = resource.getrusage(resource.RUSAGE_SELF)
    cpu = (c1.ru_utime + c1.ru_stime - c0.ru_utime - c0.ru_stime) / 5
    print(m, best, cpu, repr(float(v)))
"#;

/// Runs of our side in the comparison: each takes milliseconds, and CPU time is read in
/// 10 ms clock ticks, so many runs are needed for a meaningful mean.
const OUR_RUNS: usize = 40;

fn compare_with_scipy(p: &PointSet) {
    let available = Command::new("python3")
        .args(["-c", "import scipy.stats.qmc"])
        .output()
        .is_ok_and(|o| o.status.success());
    if !available {
        println!("scipy comparison: skipped: scipy not available");
        return;
    }
    let path =
        std::env::temp_dir().join(format!("lowdisc-metrics-bench-{}.csv", std::process::id()));
    let mut file = std::fs::File::create(&path).expect("temp file");
    for q in p.iter() {
        let row: Vec<String> = q.iter().map(|v| format!("{v:.17e}")).collect();
        writeln!(file, "{}", row.join(",")).expect("write temp file");
    }
    drop(file);
    let out = Command::new("python3")
        .args(["-c", SCIPY_SCRIPT, path.to_str().expect("utf-8 path")])
        .output()
        .expect("run python3");
    let _ = std::fs::remove_file(&path);
    if !out.status.success() {
        println!(
            "scipy comparison: skipped: scipy run failed: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        return;
    }
    println!(
        "scipy comparison, n = {}, d = {}, scipy default workers=1; best wall and mean CPU \
         of {OUR_RUNS} runs (ours, all rayon threads) and 5 runs (scipy):",
        p.len(),
        p.dims()
    );
    println!(
        "{:<8} {:>10} {:>10} {:>11} {:>11} {:>9} {:>9} {:>9}",
        "method", "ours wall", "ours cpu", "scipy wall", "scipy cpu", "x wall", "x cpu", "rel.diff"
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    for m in L2Method::ALL {
        let (wall, cpu, value) = measure(OUR_RUNS, || l2_discrepancy(p, m));
        let row: Vec<f64> = stdout
            .lines()
            .map(|l| l.split_whitespace().collect::<Vec<_>>())
            .find(|f| f.len() == 4 && f[0] == m.scipy_name())
            .map(|f| {
                f[1..]
                    .iter()
                    .map(|v| v.parse().unwrap_or(f64::NAN))
                    .collect()
            })
            .unwrap_or_else(|| vec![f64::NAN; 3]);
        println!(
            "{:<8} {:>10.4} {:>10.4} {:>11.4} {:>11.4} {:>9.1} {:>9.1} {:>9.1e}",
            m.scipy_name(),
            wall,
            cpu,
            row[0],
            row[1],
            row[0] / wall,
            row[1] / cpu,
            ((value - row[2]) / row[2]).abs()
        );
    }
}

criterion_group!(benches, bench_star, bench_l2);
criterion_main!(benches);
