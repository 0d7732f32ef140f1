//! Digital nets in base 2 from user-given generator matrices: any such net
//! can drive the Sobol-based pixel samplers in place of the built-in
//! Joe-Kuo Sobol matrices.
//!
//! A [`DigitalNet`] holds one generator matrix per dimension as 32 columns
//! (column `c` is the digit word that bit `c` of the index contributes; bit
//! 31 is the first binary digit), exactly as [`crate::sobol::matrix`]: point
//! `index` of dimension `d` is the XOR of the columns selected by the bits
//! of `index` ([`crate::sobol::multiply`]). It is made
//!
//! * from matrices in memory, [`DigitalNet::from_columns`] (the form a
//!   caller holding an array of integers uses);
//! * from Joe & Kuo's direction-number format, [`DigitalNet::from_joe_kuo`]
//!   (`joe_kuo.rs`);
//! * from a plain matrix file, [`DigitalNet::from_matrix_text`]
//!   (`matrix_text.rs`): one dimension per line, 32 columns, hexadecimal
//!   `0x..` or decimal, `#` comments;
//! * or by name, [`Net::named`]: the built-in nets of `data/` (`onetwo`,
//!   Bonneel et al. 2025's Sobol' matrices with guaranteed-quality 2-D
//!   projections, see `data/README.md`).
//!
//! Every dimension must be a `(0,1)`-sequence: the leading `k x k` block
//! of its matrix nonsingular for every `k`, so the first `2^k` points of
//! every aligned block fall one into each interval of length `2^-k` (what
//! the samplers' stratification rests on). A bad input is an
//! [`Error::InvalidNet`] naming the source and, for files, the line.
//!
//! A pixel sampler holds a [`Net`]: a `Copy` handle, either the built-in
//! Sobol table ([`Net::SOBOL`], the default) or a net that lives for the
//! rest of the program ([`DigitalNet::into_net`] leaks it once; programs
//! load a net once per run, and a `Copy` handle keeps sampler
//! configurations plain values). With [`Net::SOBOL`] every sampler
//! computes exactly what it computed before nets existed.

mod joe_kuo;
mod matrix_text;
/// The direction-number recurrence, shared with `build.rs`.
mod recurrence {
    include!("net/recurrence.rs");

    pub(super) fn columns(a: u32, m: &[u32]) -> [u32; 32] {
        sobol_columns(a, m)
    }
}

use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec::Vec;
use core::fmt;

use crate::Error;
use crate::hash::WordHasher;
use crate::sobol::{NUM_DIMENSIONS, multiply};

/// The most dimensions a net may have.
pub const MAX_NET_DIMENSIONS: usize = 1 << 16;

/// Sobol' direction numbers with guaranteed-quality 2-D projections
/// (Bonneel, Coeurjolly, Iehl & Ostromoukhov 2025), in Joe & Kuo's format.
const ONETWO_DATA: &str = include_str!("../data/onetwo-sobol-692.dat");

/// The built-in nets [`Net::named`] knows: name, description.
pub const NAMED_NETS: [(&str, &str); 2] = [
    (
        "sobol",
        "Joe & Kuo 2008 Sobol' (new-joe-kuo-6.21201), the default",
    ),
    (
        "onetwo",
        "Sobol' with guaranteed-quality 2-D projections (Bonneel et al. 2025), 692 dimensions",
    ),
];

/// Generator matrices of a digital net in base 2; see the module
/// documentation.
#[derive(Clone, PartialEq, Eq)]
pub struct DigitalNet {
    name: String,
    columns: Vec<[u32; 32]>,
    id: u64,
}

impl fmt::Debug for DigitalNet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "DigitalNet({}, {} dimensions, id {:016x})",
            self.name,
            self.columns.len(),
            self.id
        )
    }
}

impl DigitalNet {
    /// A net from one 32-column generator matrix per dimension (column `c`:
    /// the digit word of index bit `c`, bit 31 the first digit). `name`
    /// names the net in messages. Fails when there are no dimensions, more
    /// than [`MAX_NET_DIMENSIONS`], or a dimension is not a
    /// `(0,1)`-sequence.
    ///
    /// ```
    /// use lowdisc::net::DigitalNet;
    ///
    /// // Van der Corput and the second Sobol' dimension.
    /// let identity: [u32; 32] = core::array::from_fn(|c| 1 << (31 - c));
    /// let net = DigitalNet::from_columns("pair", vec![identity, *lowdisc::sobol::matrix(1)])?;
    /// assert_eq!(net.dimensions(), 2);
    /// assert_eq!(net.sample(3, 1), lowdisc::sobol::sample(3, 1));
    ///
    /// let singular = [0u32; 32];
    /// assert!(DigitalNet::from_columns("zero", vec![singular]).is_err());
    /// # Ok::<(), lowdisc::Error>(())
    /// ```
    pub fn from_columns(name: &str, columns: Vec<[u32; 32]>) -> Result<DigitalNet, Error> {
        let invalid = |reason: String| Error::InvalidNet {
            source: name.to_string(),
            line: None,
            reason,
        };
        if columns.is_empty() || columns.len() > MAX_NET_DIMENSIONS {
            return Err(invalid(format!(
                "{} dimensions; a net has 1 to {MAX_NET_DIMENSIONS}",
                columns.len()
            )));
        }
        if let Some((d, k)) = columns
            .iter()
            .enumerate()
            .find_map(|(d, m)| first_singular_block(m).map(|k| (d, k)))
        {
            return Err(invalid(format!(
                "dimension {d} is not a (0,1)-sequence: its leading {k}x{k} block is singular"
            )));
        }
        Ok(Self::new_unchecked(name, columns))
    }

    /// The net without the checks (callers checked every dimension).
    fn new_unchecked(name: &str, columns: Vec<[u32; 32]>) -> DigitalNet {
        let id = columns
            .iter()
            .flatten()
            .fold(WordHasher::new(columns.len() * 32), |h, &c| {
                h.push(u64::from(c))
            })
            .finish();
        DigitalNet {
            name: name.to_string(),
            columns,
            id,
        }
    }

    /// A net from direction numbers in Joe & Kuo's format (the text of a
    /// file such as `new-joe-kuo-6.21201`); `source` (the file name) and
    /// the line start every error. See `joe_kuo.rs` for the rules.
    ///
    /// ```
    /// use lowdisc::net::DigitalNet;
    ///
    /// let text = "d s a m_i\n2 1 0 1\n3 2 1 1 3\n";
    /// let net = DigitalNet::from_joe_kuo("three.txt", text)?;
    /// assert_eq!(net.dimensions(), 3);
    /// assert_eq!(net.sample(5, 2), lowdisc::sobol::sample(5, 2));
    ///
    /// let err = DigitalNet::from_joe_kuo("bad.txt", "d s a m_i\n2 1 0 2\n").unwrap_err();
    /// assert_eq!(err.to_string(), "bad.txt:2: m_1 = 2 is even; every m_i must be odd");
    /// # Ok::<(), lowdisc::Error>(())
    /// ```
    pub fn from_joe_kuo(source: &str, text: &str) -> Result<DigitalNet, Error> {
        let columns = joe_kuo::parse(source, text)?;
        Ok(Self::new_unchecked(source, columns))
    }

    /// A net from a matrix file's text: one dimension per line, 32 column
    /// words (hexadecimal `0x..` or decimal, separated by spaces or
    /// commas), `#` starting a comment. See `matrix_text.rs`.
    ///
    /// ```
    /// use lowdisc::net::DigitalNet;
    ///
    /// let identity: Vec<String> = (0..32).map(|c| format!("{:#x}", 1u32 << (31 - c))).collect();
    /// let text = format!("# van der Corput\n{}\n", identity.join(" "));
    /// let net = DigitalNet::from_matrix_text("vdc.txt", &text)?;
    /// assert_eq!(net.sample(1, 0), 1 << 31);
    ///
    /// let err = DigitalNet::from_matrix_text("short.txt", "0x80000000 0x40000000\n").unwrap_err();
    /// assert_eq!(err.to_string(), "short.txt:1: 2 columns; a dimension has 32");
    /// # Ok::<(), lowdisc::Error>(())
    /// ```
    pub fn from_matrix_text(source: &str, text: &str) -> Result<DigitalNet, Error> {
        let columns = matrix_text::parse(source, text)?;
        Ok(Self::new_unchecked(source, columns))
    }

    /// A net from a file's text in either format: Joe & Kuo's when the
    /// first line that is not blank or a comment starts with a word that
    /// is not a number (their header `d s a m_i`), else a matrix file.
    pub fn parse(source: &str, text: &str) -> Result<DigitalNet, Error> {
        let first = text
            .lines()
            .map(|l| l.split('#').next().unwrap_or("").trim())
            .find(|l| !l.is_empty());
        let header = first
            .and_then(|l| l.split_whitespace().next())
            .is_some_and(|w| !w.starts_with(|c: char| c.is_ascii_digit()));
        if header {
            Self::from_joe_kuo(source, text)
        } else {
            Self::from_matrix_text(source, text)
        }
    }

    /// The name given at construction (a file name for files).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The number of dimensions.
    pub fn dimensions(&self) -> u32 {
        self.columns.len() as u32
    }

    /// The generator matrices, one per dimension.
    pub fn columns(&self) -> &[[u32; 32]] {
        &self.columns
    }

    /// A hash of the matrices (not of the name): equal matrices, equal id.
    pub fn id(&self) -> u64 {
        self.id
    }

    /// The digit word of point `index` in dimension `dim`.
    ///
    /// # Panics
    /// If `dim >= self.dimensions()`.
    pub fn sample(&self, index: u32, dim: u32) -> u32 {
        multiply(&self.columns[dim as usize], index)
    }

    /// A [`Net`] handle to these matrices, which are leaked: they live for
    /// the rest of the program (see the module documentation).
    pub fn into_net(self) -> Net {
        Net(Some(alloc::boxed::Box::leak(alloc::boxed::Box::new(self))))
    }
}

/// The smallest `k` whose leading `k x k` block of `columns` is singular
/// (rows are digits from the first, columns index bits), if any.
fn first_singular_block(columns: &[u32; 32]) -> Option<usize> {
    // The block of size k is nonsingular for every k exactly when, for
    // every k, column k - 1 restricted to the first k digits is independent
    // of the earlier columns restricted to them; eliminate incrementally.
    (1..=32).find(|&k| {
        let mask = u32::MAX << (32 - k);
        let mut rows: Vec<u32> = columns[..k].iter().map(|c| c & mask).collect();
        rank(&mut rows) < k
    })
}

/// The rank over GF(2) of the given words (as vectors).
fn rank(words: &mut [u32]) -> usize {
    let mut rank = 0;
    for bit in (0..32).rev() {
        let Some(p) = (rank..words.len()).find(|&i| words[i] >> bit & 1 == 1) else {
            continue;
        };
        words.swap(rank, p);
        let pivot = words[rank];
        for (i, w) in words.iter_mut().enumerate() {
            if i != rank && *w >> bit & 1 == 1 {
                *w ^= pivot;
            }
        }
        rank += 1;
    }
    rank
}

/// The matrices a sampler uses: the built-in Joe-Kuo Sobol table or a
/// leaked [`DigitalNet`]; see the module documentation.
#[derive(Clone, Copy, Default)]
pub struct Net(Option<&'static DigitalNet>);

impl Net {
    /// The built-in Sobol matrices (Joe & Kuo 2008, all 21,201 dimensions).
    pub const SOBOL: Net = Net(None);

    /// A built-in net by name (see [`NAMED_NETS`]), or `None` for an
    /// unknown name. The net's matrices are made (and leaked) by each call.
    ///
    /// ```
    /// use lowdisc::net::Net;
    ///
    /// let onetwo = Net::named("onetwo").unwrap();
    /// assert_eq!(onetwo.dimensions(), 692);
    /// assert_eq!(onetwo.name(), "onetwo");
    /// assert!(Net::named("sobol").unwrap().is_sobol());
    /// assert!(Net::named("nope").is_none());
    /// ```
    pub fn named(name: &str) -> Option<Net> {
        match name {
            "sobol" => Some(Net::SOBOL),
            "onetwo" => {
                let columns = joe_kuo::parse("onetwo", ONETWO_DATA).ok()?;
                Some(DigitalNet::new_unchecked("onetwo", columns).into_net())
            }
            _ => None,
        }
    }

    /// True for the built-in Sobol table.
    pub fn is_sobol(self) -> bool {
        self.0.is_none()
    }

    /// The net's name: `sobol` for the built-in table.
    pub fn name(self) -> &'static str {
        self.0.map_or("sobol", |n| n.name.as_str())
    }

    /// The hash of the matrices ([`DigitalNet::id`]), `None` for the
    /// built-in table.
    pub fn id(self) -> Option<u64> {
        self.0.map(|n| n.id)
    }

    /// The number of dimensions.
    pub fn dimensions(self) -> u32 {
        self.0.map_or(NUM_DIMENSIONS as u32, DigitalNet::dimensions)
    }

    /// Every dimension's generator matrix.
    pub fn columns(self) -> &'static [[u32; 32]] {
        self.0
            .map_or(crate::sobol::matrices(), |n| n.columns.as_slice())
    }

    /// The generator matrix of dimension `dim`.
    ///
    /// # Panics
    /// If `dim >= self.dimensions()`.
    #[inline]
    pub fn matrix(self, dim: u32) -> &'static [u32; 32] {
        match self.0 {
            None => crate::sobol::matrix(dim),
            Some(n) => &n.columns[dim as usize],
        }
    }

    /// The digit word of point `index` in dimension `dim` (for
    /// [`Net::SOBOL`], [`crate::sobol::sample`]).
    ///
    /// # Panics
    /// If `dim >= self.dimensions()`.
    #[inline]
    pub fn sample(self, index: u32, dim: u32) -> u32 {
        multiply(self.matrix(dim), index)
    }

    /// Checks that the net has at least `needed` dimensions, which `user`
    /// (a sampler's description) reads.
    pub fn require(self, needed: u32, user: &'static str) -> Result<(), Error> {
        if self.dimensions() >= needed {
            return Ok(());
        }
        Err(Error::InvalidNet {
            source: self.name().to_string(),
            line: None,
            reason: format!(
                "{} dimensions; {user} needs at least {needed}",
                self.dimensions()
            ),
        })
    }
}

impl PartialEq for Net {
    /// Equal matrices (the built-in table equals only itself).
    fn eq(&self, other: &Net) -> bool {
        match (self.0, other.0) {
            (None, None) => true,
            (Some(a), Some(b)) => a.id == b.id && a.columns == b.columns,
            _ => false,
        }
    }
}

impl fmt::Debug for Net {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            None => f.write_str("Net::SOBOL"),
            Some(n) => write!(f, "Net({n:?})"),
        }
    }
}

#[cfg(test)]
mod tests;
