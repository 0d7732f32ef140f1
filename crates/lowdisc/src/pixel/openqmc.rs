//! The samplers of the Academy Software Foundation's OpenQMC library
//! (through its bit-exact Rust port, the `openqmc-rs` crate), the sampling
//! library production renderers use, as lowdisc pixel samplers so that they
//! are compared with lowdisc's own in the same renderer.
//!
//! OpenQMC has a *domain tree*: a root per (pixel, frame, sample index),
//! child domains by integer key, each an independent 4-D pattern of which a
//! caller draws up to four dimensions. lowdisc's pixel-sampler calls map
//! onto it as a padded sampler with one domain per call:
//!
//! | call | domain key | lanes drawn |
//! |---|---|---|
//! | [`WordSampler::get_pixel_2d_words`] | 0 | 2 |
//! | [`WordSampler::get_2d_words`] at dimension `d` | `d + 1` | 2 |
//! | [`WordSampler::get_1d_word`] at dimension `d` | `d + 1` | 1 |
//!
//! so, as in pbrt-v4's padded Sobol, each value is stratified on its own
//! over a pixel's samples and values of different calls are independent.
//! The seed selects OpenQMC's *frame* (the argument a production renderer
//! passes the frame number in): frame = the top 30 bits of
//! [`crate::hash::mix64`] of the seed. OpenQMC's own limits apply: pixels
//! are told apart by their coordinates modulo 256 (its pixel key holds 8
//! bits of x and of y), and sample indices past `2^16` continue in a fresh
//! pattern. Values are OpenQMC's digit words bit for bit; lowdisc turns them
//! into floats with [`crate::to_f32`]. The OpenQMC crate needs `std`: without
//! the crate's `std` feature, [`OpenQmcSampler::new`] returns
//! [`Error::Unavailable`].
//!
//! ```
//! use lowdisc::pixel::{OpenQmcKind, OpenQmcSampler, PixelSampler};
//!
//! let mut sampler = OpenQmcSampler::new(OpenQmcKind::SobolBn, 16, 7).unwrap();
//! sampler.start_pixel_sample([3, 4], 0, 0);
//! let [x, y] = sampler.get_pixel_2d();
//! assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y));
//! ```

use super::WordSampler;
use crate::Error;

/// Which OpenQMC sampler.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum OpenQmcKind {
    /// Owen-scrambled Sobol (`oqmc::SobolSampler`).
    Sobol,
    /// Sobol with blue-noise pixel tables (`oqmc::SobolBnSampler`).
    SobolBn,
    /// Randomised rank-1 lattice (`oqmc::LatticeSampler`).
    Lattice,
    /// Lattice with blue-noise pixel tables (`oqmc::LatticeBnSampler`).
    LatticeBn,
    /// Progressive multi-jittered (0,2) (`oqmc::PmjSampler`).
    Pmj,
    /// Pmj with blue-noise pixel tables (`oqmc::PmjBnSampler`).
    PmjBn,
}

/// An OpenQMC sampler behind lowdisc's pixel-sampler calls; see the module
/// documentation.
#[derive(Debug, Clone)]
pub struct OpenQmcSampler {
    spp: u32,
    #[cfg(feature = "std")]
    frame: i32,
    #[cfg(feature = "std")]
    root: roots::Root,
    dimension: u32,
}

impl OpenQmcSampler {
    /// A sampler of `kind` with `spp` samples per pixel, seeded by `seed`.
    ///
    /// # Errors
    /// [`Error::InvalidSampleCount`] if `spp` is 0 or above `2^31 - 1`
    /// (OpenQMC's sample index is a signed 32-bit integer);
    /// [`Error::Unavailable`] without the `std` feature.
    pub fn new(kind: OpenQmcKind, spp: u32, seed: u64) -> Result<Self, Error> {
        super::check_spp(spp)?;
        if spp > i32::MAX as u32 {
            return Err(Error::InvalidSampleCount {
                count: u64::from(spp),
                reason: "OpenQMC's sample index is a signed 32-bit integer",
            });
        }
        #[cfg(feature = "std")]
        {
            let frame = (crate::hash::mix64(seed) >> 34) as i32;
            Ok(OpenQmcSampler {
                spp,
                frame,
                root: roots::Root::new(kind, [0, 0], frame, 0),
                dimension: 0,
            })
        }
        #[cfg(not(feature = "std"))]
        {
            let _ = (kind, seed);
            Err(Error::Unavailable {
                sampler: "openqmc",
                reason: "the OpenQMC samplers need the crate's `std` feature",
            })
        }
    }

    /// The domain key of the call at the current dimension, which then
    /// moves on by `count`.
    #[cfg(feature = "std")]
    #[inline]
    fn next_key(&mut self, count: u32) -> i32 {
        let key = self.dimension.wrapping_add(1) as i32;
        self.dimension = self.dimension.wrapping_add(count);
        key
    }
}

/// Domain key of the in-pixel offset; the call at dimension `d` uses
/// `d + 1`.
#[cfg(feature = "std")]
const PIXEL_DOMAIN: i32 = 0;

#[cfg(feature = "std")]
impl WordSampler for OpenQmcSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
        // OpenQMC keeps 8 bits of each coordinate; the top bit is cleared
        // only so that the conversion to its signed integers is exact.
        let pixel = pixel.map(|c| (c & 0x7fff_ffff) as i32);
        let index = (sample_index % self.spp) as i32;
        self.root = roots::Root::new(self.root.kind(), pixel, self.frame, index);
        self.dimension = dimension;
    }

    fn get_1d_word(&mut self) -> u32 {
        let key = self.next_key(1);
        self.root.draw::<1>(key)[0]
    }

    fn get_2d_words(&mut self) -> [u32; 2] {
        let key = self.next_key(2);
        self.root.draw::<2>(key)
    }

    fn get_pixel_2d_words(&mut self) -> [u32; 2] {
        self.root.draw::<2>(PIXEL_DOMAIN)
    }
}

/// Without `std` no sampler is ever built ([`OpenQmcSampler::new`] fails),
/// so these calls are never made.
#[cfg(not(feature = "std"))]
impl WordSampler for OpenQmcSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    fn start_pixel_sample(&mut self, _pixel: [u32; 2], _sample_index: u32, dimension: u32) {
        self.dimension = dimension;
    }

    fn get_1d_word(&mut self) -> u32 {
        0
    }

    fn get_2d_words(&mut self) -> [u32; 2] {
        [0; 2]
    }

    fn get_pixel_2d_words(&mut self) -> [u32; 2] {
        [0; 2]
    }
}

/// The root of the current pixel sample, one variant per OpenQMC sampler.
#[cfg(feature = "std")]
mod roots {
    use super::OpenQmcKind;
    use openqmc::{
        LatticeBnSampler, LatticeSampler, PmjBnSampler, PmjSampler, SobolBnSampler, SobolSampler,
    };

    #[derive(Debug, Clone, Copy)]
    pub(super) enum Root {
        Sobol(SobolSampler),
        SobolBn(SobolBnSampler),
        Lattice(LatticeSampler),
        LatticeBn(LatticeBnSampler),
        Pmj(PmjSampler),
        PmjBn(PmjBnSampler),
    }

    impl Root {
        #[inline]
        pub(super) fn new(kind: OpenQmcKind, [x, y]: [i32; 2], frame: i32, index: i32) -> Root {
            match kind {
                OpenQmcKind::Sobol => Root::Sobol(SobolSampler::new(x, y, frame, index)),
                OpenQmcKind::SobolBn => Root::SobolBn(SobolBnSampler::new(x, y, frame, index)),
                OpenQmcKind::Lattice => Root::Lattice(LatticeSampler::new(x, y, frame, index)),
                OpenQmcKind::LatticeBn => {
                    Root::LatticeBn(LatticeBnSampler::new(x, y, frame, index))
                }
                OpenQmcKind::Pmj => Root::Pmj(PmjSampler::new(x, y, frame, index)),
                OpenQmcKind::PmjBn => Root::PmjBn(PmjBnSampler::new(x, y, frame, index)),
            }
        }

        #[inline]
        pub(super) fn kind(&self) -> OpenQmcKind {
            match self {
                Root::Sobol(_) => OpenQmcKind::Sobol,
                Root::SobolBn(_) => OpenQmcKind::SobolBn,
                Root::Lattice(_) => OpenQmcKind::Lattice,
                Root::LatticeBn(_) => OpenQmcKind::LatticeBn,
                Root::Pmj(_) => OpenQmcKind::Pmj,
                Root::PmjBn(_) => OpenQmcKind::PmjBn,
            }
        }

        /// The first `N` dimensions of domain `key`.
        #[inline]
        pub(super) fn draw<const N: usize>(&self, key: i32) -> [u32; N] {
            match self {
                Root::Sobol(s) => s.new_domain(key).draw_sample::<N>(),
                Root::SobolBn(s) => s.new_domain(key).draw_sample::<N>(),
                Root::Lattice(s) => s.new_domain(key).draw_sample::<N>(),
                Root::LatticeBn(s) => s.new_domain(key).draw_sample::<N>(),
                Root::Pmj(s) => s.new_domain(key).draw_sample::<N>(),
                Root::PmjBn(s) => s.new_domain(key).draw_sample::<N>(),
            }
        }
    }
}
