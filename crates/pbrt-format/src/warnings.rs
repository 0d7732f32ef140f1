//! A collector of warnings that reports each distinct warning once.
//!
//! The parser and the scene builder use [`Warnings`] for things that are not errors
//! (a deprecated directive, an unsupported parameter). A warning is identified by its
//! message and location, so a named material whose unused parameter is looked at
//! for every shape that uses it is still reported only once.

use std::collections::HashSet;
use std::fmt;

use crate::Loc;

/// One warning: an optional location and a message.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Warning {
    /// Where the warning applies, if anywhere in particular.
    pub loc: Option<Loc>,
    /// The message (without location or the word "warning").
    pub message: String,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.loc {
            Some(loc) => write!(f, "{loc}: warning: {}", self.message),
            None => write!(f, "warning: {}", self.message),
        }
    }
}

/// An ordered collection of distinct warnings.
///
/// Adding a warning whose message and location equal an earlier one does nothing.
/// [`Warnings::warn_once`] dedups by message alone (for "directive X is not
/// supported", reported at its first location only).
#[derive(Clone, Debug, Default)]
pub struct Warnings {
    list: Vec<Warning>,
    seen: HashSet<Warning>,
    seen_messages: HashSet<String>,
}

impl Warnings {
    /// An empty collection.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a warning at `loc`; returns `true` if it was new.
    pub fn warn(&mut self, loc: &Loc, message: impl Into<String>) -> bool {
        self.add(Warning {
            loc: Some(loc.clone()),
            message: message.into(),
        })
    }

    /// Adds a warning without a location; returns `true` if it was new.
    pub fn warn_global(&mut self, message: impl Into<String>) -> bool {
        self.add(Warning {
            loc: None,
            message: message.into(),
        })
    }

    /// Adds a warning at `loc` unless a warning with the same message was already
    /// added by this method (at any location); returns `true` if it was new.
    pub fn warn_once(&mut self, loc: &Loc, message: impl Into<String>) -> bool {
        let message = message.into();
        if self.seen_messages.contains(&message) {
            return false;
        }
        self.seen_messages.insert(message.clone());
        self.warn(loc, message)
    }

    /// Adds a warning (deduplicated by message and location); returns `true` if new.
    pub fn add(&mut self, warning: Warning) -> bool {
        if self.seen.contains(&warning) {
            return false;
        }
        self.seen.insert(warning.clone());
        self.list.push(warning);
        true
    }

    /// Number of distinct warnings.
    pub fn len(&self) -> usize {
        self.list.len()
    }

    /// Whether there are no warnings.
    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// The warnings in the order they were first added.
    pub fn iter(&self) -> std::slice::Iter<'_, Warning> {
        self.list.iter()
    }

    /// The warnings in the order they were first added.
    pub fn into_vec(self) -> Vec<Warning> {
        self.list
    }
}

impl<'a> IntoIterator for &'a Warnings {
    type Item = &'a Warning;
    type IntoIter = std::slice::Iter<'a, Warning>;
    fn into_iter(self) -> Self::IntoIter {
        self.list.iter()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dedups_by_message_and_location() {
        let a = Loc::new("a.pbrt", 3, 5);
        let b = Loc::new("a.pbrt", 4, 5);
        let mut w = Warnings::new();
        assert!(w.warn(&a, "unused parameter"));
        assert!(!w.warn(&a, "unused parameter"));
        assert!(w.warn(&b, "unused parameter"));
        assert!(w.warn(&a, "other"));
        assert!(w.warn_global("global"));
        assert!(!w.warn_global("global"));
        assert_eq!(w.len(), 4);
        let shown: Vec<String> = w.iter().map(|x| x.to_string()).collect();
        assert_eq!(
            shown,
            [
                "a.pbrt:3:5: warning: unused parameter",
                "a.pbrt:4:5: warning: unused parameter",
                "a.pbrt:3:5: warning: other",
                "warning: global",
            ]
        );
    }

    #[test]
    fn warn_once_dedups_by_message_only() {
        let mut w = Warnings::new();
        assert!(w.warn_once(&Loc::new("f", 1, 1), "Accelerator is not supported"));
        assert!(!w.warn_once(&Loc::new("f", 9, 1), "Accelerator is not supported"));
        assert_eq!(w.len(), 1);
        assert_eq!(w.into_vec()[0].loc.as_ref().unwrap().line, 1);
    }
}
