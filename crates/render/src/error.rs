//! The crate's error types: [`Error`] for geometry and mesh files, and
//! [`RenderError`], everything that can stop a scene from being built,
//! loaded or rendered (it wraps [`Error`] and the other modules' errors), each
//! with a one-line `Display`.

use std::path::PathBuf;

/// Errors from loading or building geometry.
#[derive(Debug)]
pub enum Error {
    /// A file could not be read.
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// A PLY file is malformed or truncated.
    Ply {
        /// The file (or `<memory>` for in-memory data).
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
    /// Shape parameters are invalid (bad indices, counts, non-finite values...).
    InvalidShape(String),
    /// A transform is singular where an inverse is needed.
    SingularTransform,
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Error::Io { path, source } => write!(f, "{}: {source}", path.display()),
            Error::Ply { path, message } => write!(f, "{}: invalid PLY: {message}", path.display()),
            Error::InvalidShape(m) => write!(f, "invalid shape: {m}"),
            Error::SingularTransform => f.write_str("transform matrix is singular"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Io { source, .. } => Some(source),
            _ => None,
        }
    }
}

impl From<crate::math::SingularMatrix> for Error {
    fn from(_: crate::math::SingularMatrix) -> Self {
        Error::SingularTransform
    }
}

/// Why a scene could not be built, loaded or rendered.
#[derive(Debug)]
pub enum RenderError {
    /// A render option is out of range (message says which and why).
    InvalidOptions(String),
    /// The scene description is inconsistent (bad material index, no camera...).
    InvalidScene(String),
    /// The pixel sampler could not be built.
    Sampler(lowdisc::Error),
    /// The camera could not be built.
    Camera(crate::camera::CameraError),
    /// Geometry could not be built or loaded.
    Geometry(Error),
    /// A file could not be read or written.
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The thread pool could not be created.
    ThreadPool(String),
    /// The film could not be built or written.
    Film(crate::film::FilmError),
    /// The caller's cancel flag stopped the render
    /// ([`crate::render::render_cancellable`]).
    Cancelled,
}

impl std::fmt::Display for RenderError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RenderError::InvalidOptions(m) => write!(f, "invalid render options: {m}"),
            RenderError::InvalidScene(m) => write!(f, "invalid scene: {m}"),
            RenderError::Sampler(e) => write!(f, "sampler: {e}"),
            RenderError::Camera(e) => write!(f, "camera: {e}"),
            RenderError::Geometry(e) => write!(f, "{e}"),
            RenderError::Io { path, source } => write!(f, "{}: {source}", path.display()),
            RenderError::ThreadPool(m) => write!(f, "cannot start worker threads: {m}"),
            RenderError::Film(e) => write!(f, "{e}"),
            RenderError::Cancelled => f.write_str("the render was cancelled"),
        }
    }
}

/// No `source()`: every message above already contains its cause's, and a
/// chain printer (`anyhow`'s `{:#}`) would print it twice.
impl std::error::Error for RenderError {}

impl From<lowdisc::Error> for RenderError {
    fn from(e: lowdisc::Error) -> Self {
        RenderError::Sampler(e)
    }
}

impl From<crate::camera::CameraError> for RenderError {
    fn from(e: crate::camera::CameraError) -> Self {
        RenderError::Camera(e)
    }
}

impl From<Error> for RenderError {
    fn from(e: Error) -> Self {
        RenderError::Geometry(e)
    }
}
