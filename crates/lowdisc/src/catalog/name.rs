//! Reading and writing [`SamplerName`]s: `Display` is the command-line
//! name, and `FromStr` accepts exactly those names, suggesting the nearest
//! one (by edit distance) for a misspelt name.

use alloc::vec::Vec;
use core::fmt;
use core::str::FromStr;

use super::table::SamplerName;
use crate::Error;

impl fmt::Display for SamplerName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl FromStr for SamplerName {
    type Err = Error;

    /// The name written `s`; an unknown name is an error that carries the
    /// nearest known name when one is close.
    ///
    /// ```
    /// use lowdisc::Error;
    /// use lowdisc::catalog::SamplerName;
    ///
    /// assert_eq!("sobol-owen".parse(), Ok(SamplerName::SobolOwen));
    /// let Err(Error::UnknownSampler { suggestion, .. }) = "sobol-owne".parse::<SamplerName>()
    /// else {
    ///     panic!("a misspelt name is an error")
    /// };
    /// assert_eq!(suggestion, Some("sobol-owen"));
    /// ```
    fn from_str(s: &str) -> Result<Self, Error> {
        SamplerName::ALL
            .into_iter()
            .find(|n| n.as_str() == s)
            .ok_or_else(|| Error::UnknownSampler {
                name: s.into(),
                suggestion: SamplerName::nearest(s).map(SamplerName::as_str),
            })
    }
}

impl SamplerName {
    /// The known name closest to `text` in edit distance, if it is close
    /// enough to be a likely misspelling (at most `1 + len / 4` edits).
    pub fn nearest(text: &str) -> Option<SamplerName> {
        let limit = 1 + text.chars().count() / 4;
        SamplerName::ALL
            .into_iter()
            .map(|n| (edit_distance(text, n.as_str()), n))
            .filter(|&(d, _)| d <= limit)
            .min_by_key(|&(d, _)| d)
            .map(|(_, n)| n)
    }
}

/// The Levenshtein distance between `a` and `b` (insertions, deletions and
/// substitutions of characters, each counting 1), case-insensitive.
fn edit_distance(a: &str, b: &str) -> usize {
    let lower = |s: &str| -> Vec<char> { s.chars().flat_map(char::to_lowercase).collect() };
    let (a, b) = (lower(a), lower(b));
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let substitute = diagonal + usize::from(ca != cb);
            diagonal = row[j + 1];
            row[j + 1] = substitute.min(row[j] + 1).min(diagonal + 1);
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edit_distance_counts_single_character_edits() {
        assert_eq!(edit_distance("", ""), 0);
        assert_eq!(edit_distance("sobol", ""), 5);
        assert_eq!(edit_distance("", "pmj02"), 5);
        assert_eq!(edit_distance("sobol", "Sobol"), 0);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(edit_distance("sobol-owne", "sobol-owen"), 2);
        assert_eq!(edit_distance("zsobol", "zsobol-4d"), 3);
    }

    #[test]
    fn misspelt_names_suggest_the_nearest_and_others_nothing() {
        assert_eq!(SamplerName::nearest("Sobol"), Some(SamplerName::Sobol));
        assert_eq!(
            SamplerName::nearest("halton_owen"),
            Some(SamplerName::HaltonOwen)
        );
        assert_eq!(SamplerName::nearest("pmj02-bn"), Some(SamplerName::Pmj02Bn));
        assert_eq!(SamplerName::nearest("nope"), None);
        assert_eq!(SamplerName::nearest(""), None);
        for n in SamplerName::ALL {
            assert_eq!(SamplerName::nearest(n.as_str()), Some(n));
        }
    }
}
