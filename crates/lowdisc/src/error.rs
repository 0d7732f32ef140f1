//! The error type of the sequence library.

use core::fmt;

/// What can go wrong when a sequence or sampler is configured.
#[derive(Debug, Clone, PartialEq)]
pub enum Error {
    /// A dimension at or beyond the number the sequence provides.
    DimensionOutOfRange {
        /// The dimension asked for.
        dimension: u64,
        /// The number of dimensions available (valid: `0..available`).
        available: u64,
    },
    /// The paper permutation threshold must lie in `[0, 1]`.
    ThresholdOutOfRange(f64),
    /// A sample count of zero, or one too large for the sequence's index range.
    InvalidSampleCount {
        /// The count asked for.
        count: u64,
        /// Why it cannot be used.
        reason: &'static str,
    },
    /// An image resolution the sampler cannot address.
    InvalidResolution {
        /// Width in pixels.
        width: u32,
        /// Height in pixels.
        height: u32,
        /// Why it cannot be used.
        reason: &'static str,
    },
    /// A pixel outside the image.
    PixelOutOfRange {
        /// The pixel asked for.
        pixel: [u32; 2],
        /// Width and height of the image.
        resolution: [u32; 2],
    },
    /// A sampler this build of the crate does not include (a feature is
    /// off).
    Unavailable {
        /// The sampler.
        sampler: &'static str,
        /// What the build lacks.
        reason: &'static str,
    },
    /// A sampler name that is not known.
    UnknownSampler {
        /// The name given.
        name: alloc::string::String,
        /// The known name nearest to it, when one is close.
        suggestion: Option<&'static str>,
    },
    /// Generator matrices or direction numbers that cannot make a net.
    InvalidNet {
        /// Where they came from: a file name, or the name given to the net.
        source: alloc::string::String,
        /// The line of the file (1-based), when the fault is on one.
        line: Option<usize>,
        /// What is wrong.
        reason: alloc::string::String,
    },
    /// A generator net given to a sampler that does not read one.
    NetNotSupported {
        /// The sampler's name.
        sampler: &'static str,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::DimensionOutOfRange {
                dimension,
                available,
            } => write!(
                f,
                "dimension {dimension} is out of range: this sequence has dimensions 0..{available}"
            ),
            Error::ThresholdOutOfRange(t) => {
                write!(f, "threshold {t} is outside [0, 1]")
            }
            Error::InvalidSampleCount { count, reason } => {
                write!(f, "invalid sample count {count}: {reason}")
            }
            Error::InvalidResolution {
                width,
                height,
                reason,
            } => {
                write!(f, "invalid resolution {width}x{height}: {reason}")
            }
            Error::PixelOutOfRange { pixel, resolution } => write!(
                f,
                "pixel ({}, {}) is outside the {}x{} image",
                pixel[0], pixel[1], resolution[0], resolution[1]
            ),
            Error::Unavailable { sampler, reason } => {
                write!(f, "sampler `{sampler}` is unavailable: {reason}")
            }
            Error::UnknownSampler { name, suggestion } => {
                write!(f, "unknown sampler `{name}`")?;
                match suggestion {
                    Some(s) => write!(f, "; did you mean `{s}`?"),
                    None => Ok(()),
                }
            }
            Error::InvalidNet {
                source,
                line: Some(line),
                reason,
            } => write!(f, "{source}:{line}: {reason}"),
            Error::InvalidNet {
                source,
                line: None,
                reason,
            } => write!(f, "{source}: {reason}"),
            Error::NetNotSupported { sampler } => write!(
                f,
                "sampler `{sampler}` does not take generator matrices (--net); the Sobol \
                 samplers do: {}",
                crate::catalog::net_sampler_list()
            ),
        }
    }
}

impl core::error::Error for Error {}
