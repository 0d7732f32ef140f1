//! The directive parser: reads files, follows `Include`/`Import`, and calls the
//! [`ParserTarget`] once per directive.
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
use crate::{ActiveTransform, ErrorKind, FileKind, Loc, ParseError, ParserTarget};

/// How deeply `Include`/`Import` may nest before the parser reports
/// [`ErrorKind::IncludeDepth`] (a file that includes itself, directly or not).
pub const MAX_INCLUDE_DEPTH: usize = 32;

/// Every directive keyword the parser accepts.
pub const DIRECTIVES: &[&str] = &[
    "Accelerator",
    "ActiveTransform",
    "AreaLightSource",
    "Attribute",
    "AttributeBegin",
    "AttributeEnd",
    "Camera",
    "ColorSpace",
    "ConcatTransform",
    "CoordinateSystem",
    "CoordSysTransform",
    "Film",
    "Identity",
    "Import",
    "Include",
    "Integrator",
    "LightSource",
    "LookAt",
    "MakeNamedMaterial",
    "MakeNamedMedium",
    "Material",
    "MediumInterface",
    "NamedMaterial",
    "ObjectBegin",
    "ObjectEnd",
    "ObjectInstance",
    "Option",
    "PixelFilter",
    "ReverseOrientation",
    "Rotate",
    "Sampler",
    "Scale",
    "Shape",
    "Texture",
    "Transform",
    "TransformBegin",
    "TransformEnd",
    "TransformTimes",
    "Translate",
    "WorldBegin",
    "WorldEnd",
];

/// Whether `word` is a directive keyword.
pub fn is_directive(word: &str) -> bool {
    DIRECTIVES.contains(&word)
}

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
        let t = &mut *self.target;
        match word {
            "AttributeBegin" => t.attribute_begin(loc),
            "AttributeEnd" => t.attribute_end(loc),
            "TransformBegin" => t.transform_begin(loc),
            "TransformEnd" => t.transform_end(loc),
            "WorldBegin" => t.world_begin(loc),
            "WorldEnd" => {
                t.warning(loc, "WorldEnd (pbrt-v3) is ignored");
                Ok(())
            }
            "Identity" => t.identity(loc),
            "ReverseOrientation" => t.reverse_orientation(loc),
            "ObjectEnd" => t.object_end(loc),
            "Translate" => t.translate(s.numbers(loc, word)?, loc),
            "Scale" => t.scale(s.numbers(loc, word)?, loc),
            "Rotate" => {
                let [a, x, y, z] = s.numbers(loc, word)?;
                t.rotate(a, [x, y, z], loc)
            }
            "LookAt" => {
                let [ex, ey, ez, lx, ly, lz, ux, uy, uz] = s.numbers(loc, word)?;
                t.look_at([ex, ey, ez], [lx, ly, lz], [ux, uy, uz], loc)
            }
            "TransformTimes" => {
                let [a, b] = s.numbers(loc, word)?;
                t.transform_times(a, b, loc)
            }
            "Transform" => t.transform(s.matrix(loc, word)?, loc),
            "ConcatTransform" => t.concat_transform(s.matrix(loc, word)?, loc),
            "ActiveTransform" => {
                let what = "StartTime, EndTime or All after ActiveTransform";
                let tok = s.word_arg(loc, what)?;
                let which = match tok.text {
                    "StartTime" => ActiveTransform::StartTime,
                    "EndTime" => ActiveTransform::EndTime,
                    "All" => ActiveTransform::All,
                    other => {
                        let msg = format!("expected {what}, found '{other}'");
                        return Err(ParseError::new(
                            ErrorKind::UnexpectedToken,
                            &s.loc(&tok),
                            msg,
                        ));
                    }
                };
                t.active_transform(which, loc)
            }
            "Option" => t.option(s.param()?, loc),
            "ColorSpace" => t.color_space(&s.string_arg(loc, "a color space name")?, loc),
            "CoordinateSystem" => {
                t.coordinate_system(&s.string_arg(loc, "a coordinate system name")?, loc)
            }
            "CoordSysTransform" => {
                t.coord_sys_transform(&s.string_arg(loc, "a coordinate system name")?, loc)
            }
            "NamedMaterial" => t.named_material(&s.string_arg(loc, "a material name")?, loc),
            "ObjectBegin" => t.object_begin(&s.string_arg(loc, "an object name")?, loc),
            "ObjectInstance" => t.object_instance(&s.string_arg(loc, "an object name")?, loc),
            "MediumInterface" => {
                let inside = s.string_arg(loc, "a medium name")?;
                let outside = match s.peek()? {
                    Some(tok) if tok.kind == TokenKind::String => {
                        s.string_arg(loc, "a medium name")?
                    }
                    _ => inside.clone(),
                };
                t.medium_interface(&inside, &outside, loc)
            }
            "Texture" => {
                let name = s.string_arg(loc, "a texture name")?;
                let ty = s.string_arg(loc, "a texture type (\"float\" or \"spectrum\")")?;
                let class = s.string_arg(loc, "a texture class such as \"imagemap\"")?;
                t.texture(&name, &ty, &class, s.params()?, loc)
            }
            "Include" | "Import" => {
                let name = s.string_arg(loc, "a file name")?;
                let kind = if word == "Include" {
                    FileKind::Include
                } else {
                    FileKind::Import
                };
                self.include(&name, kind, loc, path, depth)
            }
            _ => self.named_directive(word, s, loc),
        }
    }

    /// Directives of the form `Keyword "name-or-type" params`.
    fn named_directive(
        &mut self,
        word: &str,
        s: &mut Stream<'_>,
        loc: &Loc,
    ) -> Result<(), ParseError> {
        type Method<T> = fn(&mut T, &str, crate::ParamSet, &Loc) -> Result<(), ParseError>;
        let (method, what): (Method<T>, &str) = match word {
            "Shape" => (T::shape, "a shape type"),
            "Material" => (T::material, "a material type"),
            "MakeNamedMaterial" => (T::make_named_material, "a material name"),
            "LightSource" => (T::light_source, "a light type"),
            "AreaLightSource" => (T::area_light_source, "an area light type"),
            "Camera" => (T::camera, "a camera type"),
            "Film" => (T::film, "a film type"),
            "Sampler" => (T::sampler, "a sampler type"),
            "Integrator" => (T::integrator, "an integrator type"),
            "PixelFilter" => (T::pixel_filter, "a filter type"),
            "Accelerator" => (T::accelerator, "an accelerator type"),
            "MakeNamedMedium" => (T::make_named_medium, "a medium name"),
            "Attribute" => (T::attribute, "an attribute target such as \"shape\""),
            _ => {
                let msg = format!("unknown directive '{word}'");
                return Err(ParseError::new(ErrorKind::UnknownDirective, loc, msg));
            }
        };
        let name = s.string_arg(loc, &format!("{what} after {word}"))?;
        let params = s.params()?;
        method(self.target, &name, params, loc)
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
