//! The media of a scene file by name ([`MediaTable`]), as the loader keeps
//! them while it reads `MakeNamedMedium` and `MediumInterface`
//! ([`super::media`]).

use crate::medium::Medium;
use pbrt_format::{Loc, ParseError};
use std::collections::HashMap;

/// The media of a scene file by name.
#[derive(Debug, Default)]
pub(super) struct MediaTable {
    /// Name to scene index.
    index: HashMap<String, u32>,
    /// By scene index: the medium (once defined), and where its name was
    /// first mentioned.
    pub(super) slots: Vec<(Option<Medium>, String, Loc)>,
}

impl MediaTable {
    /// The scene index of medium `name` (`None` for `""`, vacuum).
    pub(super) fn index(&mut self, name: &str, loc: &Loc) -> Option<u32> {
        if name.is_empty() {
            return None;
        }
        let next = self.slots.len() as u32;
        let i = *self.index.entry(name.to_string()).or_insert(next);
        if i == next {
            self.slots.push((None, name.to_string(), loc.clone()));
        }
        Some(i)
    }

    /// Every medium in index order, or the error at the first use of a
    /// medium that was never defined.
    pub(super) fn into_media(self) -> Result<Vec<Medium>, ParseError> {
        self.slots
            .into_iter()
            .map(|(m, name, loc)| {
                m.ok_or_else(|| {
                    ParseError::scene(&loc, format!("medium \"{name}\" is not defined"))
                })
            })
            .collect()
    }
}
