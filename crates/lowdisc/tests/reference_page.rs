//! The reference page of the samplers, `docs/reference/samplers.md`, is
//! generated from the sampler table; this test fails when the committed
//! page differs from what the table gives. `LOWDISC_DOCS_UPDATE=1 cargo
//! test -p lowdisc --test reference_page` rewrites it.

use std::path::PathBuf;

use lowdisc::catalog::SamplerName;

fn page_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../docs/reference/samplers.md")
}

/// The page, from the table.
fn page() -> String {
    let mut out = String::from(
        "# Samplers\n\
         \n\
         <!-- Generated from the sampler table, crates/lowdisc/src/catalog/table.rs:\n\
         \x20    LOWDISC_DOCS_UPDATE=1 cargo test -p lowdisc --test reference_page -->\n\
         \n\
         Every name that `--sampler` accepts (`lowdisc render`, `lowdisc points`,\n\
         `lowdisc experiment --samplers`) and the Python package's functions take,\n\
         in the order `lowdisc render --help` lists them. A misspelt name is\n\
         refused with the nearest known name suggested.\n\
         \n\
         | name | family | description |\n\
         |---|---|---|\n",
    );
    for n in SamplerName::ALL {
        let family = n.family().label();
        out += &format!("| `{n}` | {family} | {} |\n", n.description());
    }
    out += &format!(
        "\nThe names that read a generator net instead of Joe & Kuo's matrices\n\
         (`--net`, see [Any digital net as a sampler](../guide/nets.md)): {}.\n",
        lowdisc::catalog::net_sampler_list()
    );
    out += "\n## Families\n\
            \n\
            The family says what `lowdisc points --sampler NAME` prints (the\n\
            points mode) for each name of the family.\n\
            \n\
            | family | points |\n\
            |---|---|\n";
    let mut seen = Vec::new();
    for n in SamplerName::ALL {
        let family = n.family();
        if !seen.contains(&family.label()) {
            seen.push(family.label());
            out += &format!("| {} | {} |\n", family.label(), family.points_mode());
        }
    }
    out
}

#[test]
fn the_reference_page_lists_the_table() {
    let want = page();
    let path = page_path();
    if std::env::var_os("LOWDISC_DOCS_UPDATE").is_some() {
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(&path, &want).unwrap();
    }
    let got = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    assert!(
        got == want,
        "{} is stale: rerun with LOWDISC_DOCS_UPDATE=1",
        path.display()
    );
    for n in SamplerName::ALL {
        assert!(got.contains(&format!("| `{n}` |")), "{n}");
    }
}
