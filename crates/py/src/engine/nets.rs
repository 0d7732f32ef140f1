//! The generator matrices (`net=`) a render or a pixel sampler reads: a
//! built-in net's name, a file (Joe & Kuo's direction numbers or a matrix
//! file, as `lowdisc render --net FILE`), or matrices in memory (a numpy
//! array), each checked by `lowdisc::net` and turned into its `Copy`
//! handle [`Net`].
//!
//! A [`Net`] handle leaks its matrices (they live for the rest of the
//! program). A Python session may render with the same net many times, so
//! the handles made here are kept and reused for equal matrices of the
//! same name: memory grows with the number of distinct nets only.

use std::sync::Mutex;

use lowdisc::net::{DigitalNet, NAMED_NETS, Net};

use super::{EngineError, Result};

/// The largest net file read (bytes), as the CLI's `--net`: Joe & Kuo's
/// 21,201 dimensions take under 2 MB.
pub const MAX_NET_FILE: u64 = 64 << 20;

/// The name of a net given as matrices in memory, in its error messages.
pub const ARRAY_NET_NAME: &str = "net array";

/// Where a net comes from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum NetSource {
    /// A built-in net's name ([`NAMED_NETS`]), else a file's path.
    NameOrFile(String),
    /// One 32-column generator matrix per dimension: column `c` is the
    /// digit word that bit `c` of the index contributes, bit 31 the first
    /// binary digit (`lowdisc::net`'s matrix-file convention).
    Matrices(Vec<[u32; 32]>),
}

/// The handles made so far (see the module documentation).
static MADE: Mutex<Vec<Net>> = Mutex::new(Vec::new());

/// The net of `source`, checked: an unknown name that is no readable file,
/// a malformed file, or matrices that are not a net (no dimensions, too
/// many, a dimension that is not a `(0,1)`-sequence) are errors saying so.
pub fn resolve(source: &NetSource) -> Result<Net> {
    match source {
        NetSource::NameOrFile(name) if name == "sobol" => Ok(Net::SOBOL),
        NetSource::NameOrFile(name) if NAMED_NETS.iter().any(|(n, _)| *n == name.as_str()) => {
            if let Some(net) = made(|n| n.name() == name.as_str()) {
                return Ok(net);
            }
            let net = Net::named(name)
                .ok_or_else(|| EngineError::value(format!("the built-in net {name} is missing")))?;
            Ok(keep(net))
        }
        NetSource::NameOrFile(path) => {
            let text = read_net_file(path)?;
            let net = DigitalNet::parse(path, &text)?;
            Ok(reuse_or_keep(net))
        }
        NetSource::Matrices(columns) => {
            let net = DigitalNet::from_columns(ARRAY_NET_NAME, columns.clone())?;
            Ok(reuse_or_keep(net))
        }
    }
}

/// A kept handle that satisfies `pred`.
fn made(pred: impl Fn(&Net) -> bool) -> Option<Net> {
    let kept = MADE.lock().unwrap_or_else(|e| e.into_inner());
    kept.iter().copied().find(|n| pred(n))
}

/// Keeps `net` for reuse and returns it.
fn keep(net: Net) -> Net {
    MADE.lock().unwrap_or_else(|e| e.into_inner()).push(net);
    net
}

/// The kept handle of `net`'s name and matrices, else a new one, kept.
fn reuse_or_keep(net: DigitalNet) -> Net {
    let same = |n: &Net| {
        n.id() == Some(net.id()) && n.name() == net.name() && n.columns() == net.columns()
    };
    made(same).unwrap_or_else(|| keep(net.into_net()))
}

/// The text of the net file `path` (at most [`MAX_NET_FILE`] bytes).
fn read_net_file(path: &str) -> Result<String> {
    let names: Vec<&str> = NAMED_NETS.iter().map(|(n, _)| *n).collect();
    let unreadable = |e: String| {
        EngineError::value(format!(
            "net {path:?} is not a built-in net ({}) nor a readable file: {e}",
            names.join(", ")
        ))
    };
    let size = std::fs::metadata(path)
        .map_err(|e| unreadable(e.to_string()))?
        .len();
    if size > MAX_NET_FILE {
        return Err(unreadable(format!(
            "{size} bytes, over the limit of {MAX_NET_FILE}"
        )));
    }
    let bytes = std::fs::read(path).map_err(|e| unreadable(e.to_string()))?;
    String::from_utf8(bytes)
        .map_err(|_| EngineError::value(format!("{path}: the file is not UTF-8 text")))
}

/// The matrices of `values`, `dims x 32` column words in row-major order.
pub fn matrices(values: &[u32]) -> Result<Vec<[u32; 32]>> {
    if values.len() % 32 != 0 {
        return Err(EngineError::value(format!(
            "a net has 32 columns per dimension; got {} values",
            values.len()
        )));
    }
    Ok(values
        .chunks_exact(32)
        .map(|c| c.try_into().expect("32 values"))
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sobol(d: usize) -> Vec<[u32; 32]> {
        lowdisc::sobol::matrices()[..d].to_vec()
    }

    #[test]
    fn names_files_and_matrices_become_handles_reused_when_equal() {
        assert!(
            resolve(&NetSource::NameOrFile("sobol".into()))
                .unwrap()
                .is_sobol()
        );
        let onetwo = resolve(&NetSource::NameOrFile("onetwo".into())).unwrap();
        assert_eq!((onetwo.name(), onetwo.dimensions()), ("onetwo", 692));
        let again = resolve(&NetSource::NameOrFile("onetwo".into())).unwrap();
        assert!(std::ptr::eq(onetwo.columns(), again.columns()));

        let a = resolve(&NetSource::Matrices(sobol(4))).unwrap();
        let b = resolve(&NetSource::Matrices(sobol(4))).unwrap();
        assert_eq!((a.name(), a.dimensions()), (ARRAY_NET_NAME, 4));
        assert!(std::ptr::eq(a.columns(), b.columns()));
        assert_eq!(a.columns(), &sobol(4)[..]);

        let file = std::env::temp_dir().join(format!("lowdisc-py-net-{}.txt", std::process::id()));
        let line: Vec<String> = sobol(1)[0].iter().map(|c| format!("{c:#x}")).collect();
        std::fs::write(&file, line.join(" ") + "\n").unwrap();
        let path = file.to_str().unwrap().to_string();
        let from_file = resolve(&NetSource::NameOrFile(path.clone())).unwrap();
        std::fs::remove_file(&file).unwrap();
        assert_eq!(
            (from_file.name(), from_file.dimensions()),
            (path.as_str(), 1)
        );
        assert_eq!(from_file.columns(), &sobol(1)[..]);
    }

    #[test]
    fn bad_nets_are_refused_with_the_reason() {
        let err = |s: NetSource| resolve(&s).unwrap_err().to_string();
        let missing = err(NetSource::NameOrFile("no/such/net.txt".into()));
        assert!(
            missing.starts_with("net \"no/such/net.txt\" is not a built-in net (sobol, onetwo)"),
            "{missing}"
        );
        let mut singular = sobol(3);
        singular[2][5] = singular[2][4];
        let e = err(NetSource::Matrices(singular));
        assert!(
            e.starts_with("net array: dimension 2 is not a (0,1)-sequence"),
            "{e}"
        );
        assert!(err(NetSource::Matrices(Vec::new())).contains("0 dimensions"));
        assert!(
            matrices(&[1; 33])
                .unwrap_err()
                .to_string()
                .contains("32 columns")
        );
        assert_eq!(matrices(&[7; 64]).unwrap(), vec![[7; 32]; 2]);
    }
}
