//! Split renders: a render cut into independent *parts* (pixel windows and
//! sample ranges, [`lowdisc_render::render::RenderOptions::window`] and
//! [`lowdisc_render::render::RenderOptions::samples`]) that any job engine
//! runs, and the checked [`merge`] that assembles them.
//!
//! A [`RenderPart`] holds, for every pixel of its window, the film's exact
//! `f64` sums ([`PixelSum`]: `Σ w L` per channel and `Σ w`) over its sample
//! range, and a [`PartInfo`] naming what was rendered: a hash of the parsed
//! scene, the settings that change pixels, the full image's resolution and
//! film bounds, the window and the sample range.
//!
//! Parts are stored as EXR files (module `file`: [`write_part`],
//! [`read_part`]; the schema is documented there) that image viewers show
//! in place in the full image.
//!
//! **Exactness.** Merging the tiles of any split reproduces the single
//! render bit for bit, for every sampler: each pixel comes from exactly one
//! part and its sums are copied. Merging sample ranges adds each pixel's
//! per-range sums in ascending range order, which equals the single render's
//! in-order sum up to `f64` rounding: not bit for bit in general (see
//! [`merge`] for the bound); merging the same parts always gives the same
//! bits.

mod file;
mod merge;
mod part;

pub use file::{
    HEADER_ATTRIBUTE, HEADER_FORMAT, MAX_PART_BYTES, PartError, decode_part, encode_part,
    read_part, write_part,
};
pub use lowdisc_render::film::PixelSum;
pub use merge::{MergeError, NamedPart, merge};
pub use part::{PartInfo, RenderPart, SCENE_HASH_VERSION, content_digest, scene_hash, settings};
