//! Parser for the pbrt-v4 scene-file format, with file:line:column errors.
//!
//! As in pbrt-v4, parsing is separate from scene building: [`parse_file`] reads a
//! scene (following `Include` and `Import`) and hands a [`ParserTarget`] one
//! [`Directive`] per directive: a value with the typed arguments and a
//! [`ParamSet`] of typed parameters, plus the directive's [`Loc`]. A scene
//! builder implements `ParserTarget` (one `match` on the directive); this crate
//! provides two other targets, [`Recorder`] (keeps every directive) and
//! [`Formatter`] (prints the scene back as text).
//!
//! Modules: `token` and `stream` (tokenizer and argument reader), `parser`
//! (directives, `Include`/`Import`), `directive` ([`Directive`], [`Recorder`]),
//! `target` ([`ParserTarget`]), `param` and `paramset` (typed parameters and
//! lookups that remember use), `error` ([`ParseError`], [`Loc`]), `warnings`
//! ([`Warnings`]), `format` ([`Formatter`]).
//!
//! Syntax errors are [`ParseError`]s with an [`ErrorKind`] and a location; the
//! parser never panics on any input. [`Warnings`] collects deduplicated warnings,
//! and [`ParamSet::finish`] reports parameters a builder did not use (and
//! refuses single-value parameters with no or several values).
//!
//! Choices where pbrt-v4 and this crate could differ: numbers are kept as `f64`;
//! a raw newline inside a string is an error (as in pbrt-v4); the pbrt-v3
//! `WorldEnd` is ignored with a warning; legacy parameter types (`point`, `normal`,
//! `vector`, `color`) are read as their pbrt-v4 forms. pbrt-v4 resolves relative
//! file names in parameters (`"string filename"`) against the directory of the
//! *main* scene file, even inside included files; builders should do the same.
//!
//! ```
//! use pbrt_format::{parse_str, Directive, Recorder};
//! let mut rec = Recorder::new();
//! parse_str("WorldBegin\nShape \"sphere\" \"float radius\" [ 2 ]\n", "demo.pbrt", &mut rec)
//!     .unwrap();
//! let Directive::Shape(ty, params) = &rec.calls[1].0 else { panic!() };
//! assert_eq!((ty.as_str(), params.get_float("radius")), ("sphere", Some(2.0)));
//! assert_eq!(rec.calls[1].1.to_string(), "demo.pbrt:2:1");
//! ```

mod directive;
mod error;
mod format;
mod param;
mod paramset;
mod parser;
mod stream;
mod target;
pub mod token;
mod warnings;

pub use directive::{DIRECTIVES, Directive, Recorder, is_directive};
pub use error::{ErrorKind, Loc, ParseError};
pub use format::{Formatter, format_number, format_string};
pub use param::{Param, ParamType, ParamValues};
pub use paramset::{FloatOrTexture, ParamSet, SpectrumOrTexture, SpectrumValue};
pub use parser::{MAX_INCLUDE_DEPTH, parse_file, parse_str};
pub use target::{ActiveTransform, FileKind, ParserTarget, TargetResult};
pub use warnings::{Warning, Warnings};
