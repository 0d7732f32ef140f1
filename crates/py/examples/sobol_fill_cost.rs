//! One Sobol request of the Python package's engine, for counting its
//! instructions per value with callgrind (deterministic, unlike wall time):
//!
//! ```text
//! cargo build --profile wheel -p lowdisc-py --example sobol_fill_cost
//! valgrind --tool=callgrind --callgrind-out-file=/dev/null \
//!     target/wheel/examples/sobol_fill_cost owen 16384 64 30
//! ```
//!
//! Arguments: scramble (`none`, `owen`, ...), n, d, bits; the request is
//! float64, Gray order, seed 1, as `lowdisc.qmc.Sobol(d, seed=1).random(n)`.
//! Divide the instructions by `n * d` (the start-up costs about 0.5 M).

use _lowdisc::engine::points::{PointSpec, Sequence, generate};
use _lowdisc::engine::{Dtype, Values};

fn main() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [scramble, n, d, bits] = args.as_slice() else {
        return Err("usage: sobol_fill_cost SCRAMBLE N D BITS".into());
    };
    let number = |s: &str| s.parse::<u64>().map_err(|e| format!("{s}: {e}"));
    let spec = PointSpec {
        sequence: Sequence::Sobol,
        n: number(n)?,
        d: number(d)? as u32,
        start: 0,
        natural_order: false,
        scramble: scramble.clone(),
        seed: 1,
        bits: number(bits)? as u32,
        dtype: Dtype::F64,
    };
    let values = generate(&spec).map_err(|e| e.to_string())?;
    // A checksum, so the work cannot be optimised away.
    if let Values::F64(v) = values {
        println!("sum {}", v.iter().sum::<f64>());
    }
    Ok(())
}
