//! The catalog of named samplers: what the CLI and the renderer accept as
//! `--sampler NAME`, a validated configuration that builds the pixel
//! [`Sampler`], and a *points mode* ([`generate_points`]) that emits the raw
//! sequence behind each name.
//!
//! Every sampler is declared once, in the table of `catalog/table.rs`: its
//! pixel sampler type and, under it, each name with its [`Family`],
//! description and constructor. [`SamplerName`] (with `ALL`, parsing and
//! `description`), [`Sampler`] and its dispatch, [`SamplerConfig::build`]
//! and [`generate_points`] all come from that table; the reference page
//! `docs/reference/samplers.md` lists it (a test keeps the page current).
//!
//! ```
//! use lowdisc::catalog::{Family, SamplerName};
//!
//! let name: SamplerName = "zsobol".parse()?;
//! assert_eq!(name.family(), Family::PerPixel);
//! assert!(SamplerName::ALL.iter().any(|n| n.as_str() == "paper-repro"));
//! # Ok::<(), lowdisc::Error>(())
//! ```

mod config;
mod define;
mod family;
mod name;
mod nets;
mod params;
mod points;
mod sampler;
mod table;

pub use config::{MAX_RESOLUTION, SamplerConfig};
pub use family::Family;
pub use nets::{NET_SAMPLERS, net_sampler_list};
pub use points::{MAX_POINT_WORDS, Order, generate_points};
pub use table::{Sampler, SamplerName};
