//! The `lowdisc` command-line tool (in progress).
fn main() {}
