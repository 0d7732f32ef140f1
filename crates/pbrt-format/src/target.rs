//! [`ParserTarget`]: the interface between the parser and whoever consumes a scene.
//!
//! As in pbrt-v4, the parser knows only syntax: it hands the target one
//! [`Directive`] per directive, in file order, with the [`Loc`] of the
//! directive's keyword. Graphics state, named objects and scene-building errors
//! belong to the target. A target returning an error stops the parse, and the
//! error is returned from [`crate::parse_file`].

use std::path::Path;

use crate::{Directive, Loc, ParseError};

/// Result type of every target method.
pub type TargetResult = Result<(), ParseError>;

/// The argument of `ActiveTransform`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ActiveTransform {
    /// `ActiveTransform StartTime`
    StartTime,
    /// `ActiveTransform EndTime`
    EndTime,
    /// `ActiveTransform All`
    All,
}

impl ActiveTransform {
    /// The keyword as written in scene files.
    pub fn keyword(self) -> &'static str {
        match self {
            ActiveTransform::StartTime => "StartTime",
            ActiveTransform::EndTime => "EndTime",
            ActiveTransform::All => "All",
        }
    }
}

/// How a file came to be parsed (see [`ParserTarget::file_begin`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FileKind {
    /// The top-level file given to [`crate::parse_file`] or [`crate::parse_str`].
    Main,
    /// A file named by `Include`: its text is parsed as if it stood in place of the
    /// directive.
    Include,
    /// A file named by `Import`. The parser treats it like `Include`; pbrt-v4 gives
    /// it a copy of the graphics state whose changes do not flow back (only named
    /// materials, textures, media and object definitions do), so a builder should
    /// save its graphics state in `file_begin` and restore it in `file_end`.
    Import,
}

/// Receives the directives of a scene, in file order, one [`Directive`] value
/// per directive.
///
/// Every call gets the location of the directive keyword. Only `file_begin`,
/// `file_end` and `end_of_files` have default (empty) implementations.
///
/// ```
/// use pbrt_format::{Directive, Loc, ParserTarget, TargetResult, parse_str};
/// #[derive(Default)]
/// struct Spheres(usize);
/// impl ParserTarget for Spheres {
///     fn directive(&mut self, directive: Directive, _loc: &Loc) -> TargetResult {
///         if let Directive::Shape(ty, _) = &directive {
///             self.0 += usize::from(ty == "sphere");
///         }
///         Ok(())
///     }
///     fn warning(&mut self, _loc: &Loc, _message: &str) {}
/// }
/// let mut spheres = Spheres::default();
/// parse_str("Shape \"sphere\"\nShape \"disk\"", "s.pbrt", &mut spheres).unwrap();
/// assert_eq!(spheres.0, 1);
/// ```
pub trait ParserTarget {
    /// One directive (everything but `Include`, `Import` and the ignored
    /// `WorldEnd`, which the parser handles itself).
    fn directive(&mut self, directive: Directive, loc: &Loc) -> TargetResult;
    /// A non-fatal problem the parser noticed (e.g. the pbrt-v3 `WorldEnd`, which is
    /// ignored). The target decides whether and how to report it.
    fn warning(&mut self, loc: &Loc, message: &str);

    /// A file starts: the main file (`loc` is `None`), or an included/imported one
    /// (`loc` is the `Include`/`Import` directive). `path` is the path opened (for
    /// [`crate::parse_str`], the name given).
    fn file_begin(&mut self, path: &Path, kind: FileKind, loc: Option<&Loc>) -> TargetResult {
        let _ = (path, kind, loc);
        Ok(())
    }
    /// The file begun by the matching `file_begin` has ended.
    fn file_end(&mut self, path: &Path, kind: FileKind) -> TargetResult {
        let _ = (path, kind);
        Ok(())
    }
    /// The whole scene has been parsed without error (called last, once).
    fn end_of_files(&mut self) -> TargetResult {
        Ok(())
    }
}
