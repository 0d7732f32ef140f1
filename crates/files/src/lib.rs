//! Files for lowdisc: every file it writes for a user goes through
//! [`write_with`] or [`write_bytes`] (module `output`), so a destination
//! holds either its old contents or the complete new ones, never a mix.
//!
//! A write creates a temporary sibling `.NAME.RANDOM.tmp` in the
//! destination's folder (a fresh random name, created exclusively, so
//! concurrent writers and processes never share one), fills it through a
//! buffered writer, flushes and fsyncs it, renames it over the destination
//! and fsyncs the folder so the rename itself survives a crash. On any error
//! the temporary file is removed and the destination is left untouched.
//!
//! Live temporaries are kept in a process-wide registry (module
//! [`registry`]): a binary's SIGINT/SIGTERM handler calls
//! [`remove_live_temporaries`] before exiting, so an interrupted write leaves
//! nothing behind.
//!
//! Every file it reads from a user (scenes, includes, point files, images)
//! goes through [`read_input`] (module `input`): only regular files are
//! read, a directory or a device such as `/dev/zero` is refused by name,
//! and the size is limited before reading, so no input can exhaust memory.
//!
//! The library never installs handlers, prints or exits.

mod error;
mod input;
mod output;
pub mod registry;

pub use error::Error;
pub use input::{MAX_INPUT_BYTES, check_input, read_input, read_input_limited};
pub use output::{write_bytes, write_with};
pub use registry::remove_live_temporaries;
