//! Measures what the paper's digit permutation does to stratification.
//!
//! For the first 2^m points of Sobol dimensions 0 and 1 (and 2 and 3), with the
//! permutation at several thresholds, prints whether the points still form a
//! (0,m,2)-net and the worst-case share of occupied elementary intervals
//! (over all splits 2^-a x 2^-b, a + b = m; 100 % means a net), averaged over
//! 16 seeds (the literal variant uses one stream per seed, consumed point by
//! point, dimension by dimension).
//!
//! Run: `cargo run --release -p lowdisc --example paper_stratification`

use lowdisc::paper::{PaperLiteral, paper_reproducible};

/// Smallest share of the 2^m elementary intervals of any shape that hold a point.
fn worst_occupancy(points: &[(u32, u32)], m: u32) -> f64 {
    (0..=m)
        .map(|a| {
            let b = m - a;
            let mut seen = vec![false; 1 << m];
            for &(x, y) in points {
                let cx = if a == 0 { 0 } else { (x >> (32 - a)) as usize };
                let cy = if b == 0 { 0 } else { (y >> (32 - b)) as usize };
                seen[(cx << b) | cy] = true;
            }
            seen.iter().filter(|&&s| s).count() as f64 / (1u64 << m) as f64
        })
        .fold(1.0, f64::min)
}

fn main() {
    let thresholds = [1.0, 0.9, 0.75, 0.5, 0.25, 0.0];
    let seeds = 16u64;
    for (d0, d1) in [(0u32, 1u32), (2, 3)] {
        println!("## Sobol dimensions {d0} and {d1}\n");
        println!(
            "| m | variant | {} |",
            thresholds.map(|t| format!("t = {t}")).join(" | ")
        );
        println!("|---|---|{}", "---|".repeat(thresholds.len()));
        for m in [4u32, 6, 8, 10, 12] {
            for variant in ["literal", "reproducible"] {
                let cells: Vec<String> = thresholds
                    .iter()
                    .map(|&t| {
                        let mut total = 0.0;
                        let mut nets = 0;
                        for seed in 0..seeds {
                            let mut literal = PaperLiteral::new(t, Some(seed)).unwrap();
                            let pts: Vec<(u32, u32)> = (0..1u32 << m)
                                .map(|i| match variant {
                                    "literal" => {
                                        let x = literal.sample(i, d0);
                                        (x, literal.sample(i, d1))
                                    }
                                    _ => (
                                        paper_reproducible(i, d0, t, seed),
                                        paper_reproducible(i, d1, t, seed),
                                    ),
                                })
                                .collect();
                            let occ = worst_occupancy(&pts, m);
                            total += occ;
                            nets += usize::from(occ == 1.0);
                        }
                        format!(
                            "{:.1} % ({nets}/{seeds} nets)",
                            100.0 * total / seeds as f64
                        )
                    })
                    .collect();
                println!("| {m} | {variant} | {} |", cells.join(" | "));
            }
        }
        println!();
    }
}
