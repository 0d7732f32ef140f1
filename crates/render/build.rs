//! Fits the sRGB RGB-to-spectrum sigmoid table (Jakob & Hanika 2019) with
//! lowdisc-colour's optimiser and writes it to `OUT_DIR/srgb_sigmoid.bin`,
//! which `src/spectrum/uplift.rs` embeds. lowdisc-colour is built optimised
//! even for build scripts (see the workspace Cargo.toml), so this takes a few
//! seconds of CPU.

fn main() {
    println!("cargo::rerun-if-changed=build.rs");
    // Keep in step with spectrum::uplift::TABLE_RESOLUTION.
    let table = lowdisc_colour::SigmoidTable::optimise(64);
    let dir = std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR");
    let path = std::path::Path::new(&dir).join("srgb_sigmoid.bin");
    std::fs::write(&path, table.to_bytes()).expect("OUT_DIR is writable");
}
