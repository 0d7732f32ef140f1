//! Generates the Sobol generator matrices for all 21,201 dimensions of the
//! Joe-Kuo 2008 direction numbers (file `new-joe-kuo-6.21201`, taken unchanged
//! from the `sobol` crate on crates.io, which ships the published file) and
//! writes them as a flat little/native-endian `u32` table to `OUT_DIR`.
//!
//! Layout: `NUM_DIMENSIONS * 32` words; word `32 * d + c` is column `c` of the
//! generator matrix of dimension `d`, with the most significant output digit in
//! bit 31 (so dimension 0, van der Corput, has column `c` equal to `1 << (31 - c)`).
//! The recurrence is the one of Joe & Kuo's reference generator (their
//! `sobol.cc`), see `crates/lowdisc/LICENSE-JOE-KUO` for attribution.

use std::io::Write;

const BITS: usize = 32;

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=src/net/recurrence.rs");
    avx512_cfg();
    let params = sobol::params::JoeKuoD6::extended();
    let num_dimensions = params.dim_params.len() + 1;
    assert_eq!(num_dimensions, 21_201, "unexpected Joe-Kuo table size");

    let mut table: Vec<u32> = Vec::with_capacity(num_dimensions * BITS);
    // Dimension 0: the van der Corput sequence (identity generator matrix).
    table.extend((0..BITS).map(|c| 1u32 << (31 - c)));
    for (offset, dim) in params.dim_params.iter().enumerate() {
        assert_eq!(dim.d as usize, offset + 2, "Joe-Kuo rows out of order");
        table.extend_from_slice(&sobol_columns(dim.a, &dim.m));
    }

    let big_endian = std::env::var("CARGO_CFG_TARGET_ENDIAN").as_deref() == Ok("big");
    let mut bytes = Vec::with_capacity(table.len() * 4);
    for word in &table {
        let b = if big_endian {
            word.to_be_bytes()
        } else {
            word.to_le_bytes()
        };
        bytes.extend_from_slice(&b);
    }
    let out = std::path::PathBuf::from(std::env::var_os("OUT_DIR").unwrap());
    std::fs::File::create(out.join("sobol_matrices.bin"))
        .and_then(|mut f| f.write_all(&bytes))
        .expect("cannot write Sobol table");
    std::fs::write(
        out.join("sobol_dimensions.rs"),
        format!("/// Number of Sobol dimensions in the table.\npub const NUM_DIMENSIONS: usize = {num_dimensions};\n"),
    )
    .expect("cannot write dimension count");
}

/// Sets `cfg(lowdisc_avx512)` when the compiler has the AVX-512 intrinsics
/// and target features (stable from Rust 1.89): the vectorised Owen tree
/// kernel (`scramble/owen_tree_avx512.rs`) is compiled only then, so older
/// compilers of the declared `rust-version` still build the crate.
fn avx512_cfg() {
    println!("cargo:rustc-check-cfg=cfg(lowdisc_avx512)");
    let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
    let version = std::process::Command::new(rustc)
        .arg("--version")
        .output()
        .ok()
        .and_then(|out| String::from_utf8(out.stdout).ok())
        .unwrap_or_default();
    // "rustc 1.95.0 (59807616e 2026-04-14)" -> 95
    let minor = version
        .split_whitespace()
        .nth(1)
        .and_then(|v| v.split('.').nth(1))
        .and_then(|m| m.parse::<u32>().ok());
    if minor.is_some_and(|m| m >= 89) {
        println!("cargo:rustc-cfg=lowdisc_avx512");
    }
}

include!("src/net/recurrence.rs");
