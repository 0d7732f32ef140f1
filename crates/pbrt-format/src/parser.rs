//! The directive parser: reads files, follows `Include`/`Import`, and hands the
//! [`ParserTarget`] one [`Directive`] per directive.
//!
//! Included files are parsed recursively (at most [`MAX_INCLUDE_DEPTH`] deep), each
//! with its own tokenizer, so a directive never spans two files. A relative
//! `Include` path is looked up next to the including file first and then next to
//! the main scene file (pbrt-v4 resolves it against the main file's directory; for
//! files included from the main file the two agree).

use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::stream::Stream;
use crate::token::TokenKind;
use crate::{
    ActiveTransform, Directive, ErrorKind, FileKind, Loc, ParamSet, ParseError, ParserTarget,
};

/// How deeply `Include`/`Import` may nest before the parser reports
/// [`ErrorKind::IncludeDepth`] (a file that includes itself, directly or not).
pub const MAX_INCLUDE_DEPTH: usize = 32;

/// Parses the scene file at `path` (and the files it includes) into `target`.
///
/// The file is read whole; invalid UTF-8 is replaced (it can only matter inside
/// comments and strings). Locations name files by the path given here, joined with
/// `Include` arguments for included files.
pub fn parse_file<T: ParserTarget + ?Sized>(
    path: impl AsRef<Path>,
    target: &mut T,
) -> Result<(), ParseError> {
    let path = path.as_ref();
    let text = read_text(path).map_err(|e| {
        let msg = format!("cannot read scene file {}: {e}", path.display());
        ParseError::without_loc(ErrorKind::Io, msg)
    })?;
    parse_main(&text, path, target)
}

/// Parses scene text into `target`. `name` is used in locations and, as a path,
/// to resolve relative `Include`s (relative to its directory, or the current
/// directory when it has none).
pub fn parse_str<T: ParserTarget + ?Sized>(
    source: &str,
    name: &str,
    target: &mut T,
) -> Result<(), ParseError> {
    parse_main(source, Path::new(name), target)
}

/// Reads a scene file: a regular file only (a directory or a device such as
/// `/dev/zero` is refused by name) of at most [`lowdisc_files::MAX_INPUT_BYTES`].
fn read_text(path: &Path) -> std::io::Result<String> {
    let bytes = lowdisc_files::read_input(path).map_err(|e| {
        let source = e.io_error();
        std::io::Error::new(source.kind(), source.to_string())
    })?;
    Ok(match String::from_utf8(bytes) {
        Ok(s) => s,
        Err(e) => String::from_utf8_lossy(e.as_bytes()).into_owned(),
    })
}

fn parent_dir(path: &Path) -> PathBuf {
    path.parent().map(Path::to_path_buf).unwrap_or_default()
}

fn parse_main<T: ParserTarget + ?Sized>(
    text: &str,
    path: &Path,
    target: &mut T,
) -> Result<(), ParseError> {
    let mut parser = Parser {
        target,
        main_dir: parent_dir(path),
    };
    parser.parse_file_text(text, path, FileKind::Main, None, 0)?;
    parser.target.end_of_files()
}

struct Parser<'t, T: ?Sized> {
    target: &'t mut T,
    main_dir: PathBuf,
}

impl<T: ParserTarget + ?Sized> Parser<'_, T> {
    fn parse_file_text(
        &mut self,
        text: &str,
        path: &Path,
        kind: FileKind,
        from: Option<&Loc>,
        depth: usize,
    ) -> Result<(), ParseError> {
        self.target.file_begin(path, kind, from)?;
        let file: Arc<str> = path.to_string_lossy().into();
        // A UTF-8 byte order mark, as some editors write, is not part of the scene.
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let mut s = Stream::new(text, file);
        while let Some(tok) = s.next()? {
            let loc = s.loc(&tok);
            match tok.kind {
                TokenKind::Word => {}
                TokenKind::CloseBracket => {
                    let msg = "']' without a matching '['";
                    return Err(ParseError::new(ErrorKind::MissingBracket, &loc, msg));
                }
                _ => {
                    let msg = format!("expected a directive, found {}", tok.describe());
                    return Err(ParseError::new(ErrorKind::UnexpectedToken, &loc, msg));
                }
            }
            self.directive(tok.text, &mut s, &loc, path, depth)?;
        }
        self.target.file_end(path, kind)
    }

    fn directive(
        &mut self,
        word: &str,
        s: &mut Stream<'_>,
        loc: &Loc,
        path: &Path,
        depth: usize,
    ) -> Result<(), ParseError> {
        let directive = match word {
            "AttributeBegin" => Directive::AttributeBegin,
            "AttributeEnd" => Directive::AttributeEnd,
            "TransformBegin" => Directive::TransformBegin,
            "TransformEnd" => Directive::TransformEnd,
            "WorldBegin" => Directive::WorldBegin,
            "WorldEnd" => {
                self.target.warning(loc, "WorldEnd (pbrt-v3) is ignored");
                return Ok(());
            }
            "Identity" => Directive::Identity,
            "ReverseOrientation" => Directive::ReverseOrientation,
            "ObjectEnd" => Directive::ObjectEnd,
            "Translate" => Directive::Translate(s.numbers(loc, word)?),
            "Scale" => Directive::Scale(s.numbers(loc, word)?),
            "Rotate" => {
                let [a, x, y, z] = s.numbers(loc, word)?;
                Directive::Rotate(a, [x, y, z])
            }
            "LookAt" => {
                let [ex, ey, ez, lx, ly, lz, ux, uy, uz] = s.numbers(loc, word)?;
                Directive::LookAt([ex, ey, ez], [lx, ly, lz], [ux, uy, uz])
            }
            "TransformTimes" => {
                let [a, b] = s.numbers(loc, word)?;
                Directive::TransformTimes(a, b)
            }
            "Transform" => Directive::Transform(s.matrix(loc, word)?),
            "ConcatTransform" => Directive::ConcatTransform(s.matrix(loc, word)?),
            "ActiveTransform" => Directive::ActiveTransform(active_transform(s, loc)?),
            "Option" => Directive::Option(s.param()?),
            "ColorSpace" => {
                Directive::ColorSpace(s.string_arg(loc, "a color space name")?.into_owned())
            }
            "CoordinateSystem" => Directive::CoordinateSystem(
                s.string_arg(loc, "a coordinate system name")?.into_owned(),
            ),
            "CoordSysTransform" => Directive::CoordSysTransform(
                s.string_arg(loc, "a coordinate system name")?.into_owned(),
            ),
            "NamedMaterial" => {
                Directive::NamedMaterial(s.string_arg(loc, "a material name")?.into_owned())
            }
            "ObjectBegin" => {
                Directive::ObjectBegin(s.string_arg(loc, "an object name")?.into_owned())
            }
            "ObjectInstance" => {
                Directive::ObjectInstance(s.string_arg(loc, "an object name")?.into_owned())
            }
            "MediumInterface" => {
                let inside = s.string_arg(loc, "a medium name")?.into_owned();
                let outside = match s.peek()? {
                    Some(tok) if tok.kind == TokenKind::String => {
                        s.string_arg(loc, "a medium name")?.into_owned()
                    }
                    _ => inside.clone(),
                };
                Directive::MediumInterface(inside, outside)
            }
            "Texture" => {
                let name = s.string_arg(loc, "a texture name")?.into_owned();
                let ty = s
                    .string_arg(loc, "a texture type (\"float\" or \"spectrum\")")?
                    .into_owned();
                let class = s
                    .string_arg(loc, "a texture class such as \"imagemap\"")?
                    .into_owned();
                Directive::Texture(name, ty, class, s.params()?)
            }
            "Include" | "Import" => {
                let name = s.string_arg(loc, "a file name")?;
                let kind = if word == "Include" {
                    FileKind::Include
                } else {
                    FileKind::Import
                };
                return self.include(&name, kind, loc, path, depth);
            }
            _ => named_directive(word, s, loc)?,
        };
        self.target.directive(directive, loc)
    }

    fn include(
        &mut self,
        name: &str,
        kind: FileKind,
        loc: &Loc,
        including: &Path,
        depth: usize,
    ) -> Result<(), ParseError> {
        if depth + 1 > MAX_INCLUDE_DEPTH {
            let msg = format!(
                "\"{name}\": files nested more than {MAX_INCLUDE_DEPTH} deep (does a file include itself?)"
            );
            return Err(ParseError::new(ErrorKind::IncludeDepth, loc, msg));
        }
        let path = self.resolve(name, including);
        let text = read_text(&path).map_err(|e| {
            let msg = format!(
                "cannot read included file \"{name}\" ({}): {e}",
                path.display()
            );
            ParseError::new(ErrorKind::Io, loc, msg)
        })?;
        self.parse_file_text(&text, &path, kind, Some(loc), depth + 1)
    }

    fn resolve(&self, name: &str, including: &Path) -> PathBuf {
        let name = Path::new(name);
        if name.is_absolute() {
            return name.to_path_buf();
        }
        let local = parent_dir(including).join(name);
        if !local.exists() {
            let from_main = self.main_dir.join(name);
            if from_main.exists() {
                return from_main;
            }
        }
        local
    }
}

/// The argument of `ActiveTransform`.
fn active_transform(s: &mut Stream<'_>, loc: &Loc) -> Result<ActiveTransform, ParseError> {
    let what = "StartTime, EndTime or All after ActiveTransform";
    let tok = s.word_arg(loc, what)?;
    match tok.text {
        "StartTime" => Ok(ActiveTransform::StartTime),
        "EndTime" => Ok(ActiveTransform::EndTime),
        "All" => Ok(ActiveTransform::All),
        other => {
            let msg = format!("expected {what}, found '{other}'");
            Err(ParseError::new(
                ErrorKind::UnexpectedToken,
                &s.loc(&tok),
                msg,
            ))
        }
    }
}

/// Directives of the form `Keyword "name-or-type" params`.
fn named_directive(word: &str, s: &mut Stream<'_>, loc: &Loc) -> Result<Directive, ParseError> {
    type Make = fn(String, ParamSet) -> Directive;
    let (make, what): (Make, &str) = match word {
        "Shape" => (Directive::Shape, "a shape type"),
        "Material" => (Directive::Material, "a material type"),
        "MakeNamedMaterial" => (Directive::MakeNamedMaterial, "a material name"),
        "LightSource" => (Directive::LightSource, "a light type"),
        "AreaLightSource" => (Directive::AreaLightSource, "an area light type"),
        "Camera" => (Directive::Camera, "a camera type"),
        "Film" => (Directive::Film, "a film type"),
        "Sampler" => (Directive::Sampler, "a sampler type"),
        "Integrator" => (Directive::Integrator, "an integrator type"),
        "PixelFilter" => (Directive::PixelFilter, "a filter type"),
        "Accelerator" => (Directive::Accelerator, "an accelerator type"),
        "MakeNamedMedium" => (Directive::MakeNamedMedium, "a medium name"),
        "Attribute" => (
            Directive::Attribute,
            "an attribute target such as \"shape\"",
        ),
        _ => {
            let msg = format!("unknown directive '{word}'");
            return Err(ParseError::new(ErrorKind::UnknownDirective, loc, msg));
        }
    };
    let name = s.string_arg(loc, &format!("{what} after {word}"))?;
    let params = s.params()?;
    Ok(make(name.into_owned(), params))
}
