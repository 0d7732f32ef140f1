//! Which catalog names read a generator net ([`crate::net::Net`]) in place
//! of the built-in Sobol matrices: the global, padded and Z-order Sobol
//! samplers with their standard scrambles. The others (Halton, PMJ, the
//! paper's permutations, Burley's hashed Sobol, the base-4 and cascaded
//! sequences...) have matrices or tables of their own and refuse a net.

use alloc::string::String;
use alloc::vec::Vec;

use super::table::SamplerName;

/// The names whose constructors pass [`super::SamplerConfig::net`] on.
pub const NET_SAMPLERS: [SamplerName; 10] = [
    SamplerName::Sobol,
    SamplerName::SobolXor,
    SamplerName::SobolOwen,
    SamplerName::SobolFastOwen,
    SamplerName::SobolLms,
    SamplerName::PaddedSobol,
    SamplerName::PaddedSobolLms,
    SamplerName::ZSobol,
    SamplerName::ZSobol4d,
    SamplerName::ZSobolJoint,
];

impl SamplerName {
    /// True when the sampler reads a generator net ([`NET_SAMPLERS`]).
    pub fn takes_net(self) -> bool {
        NET_SAMPLERS.contains(&self)
    }
}

/// [`NET_SAMPLERS`] as a comma-separated list (for messages and help).
pub fn net_sampler_list() -> String {
    NET_SAMPLERS
        .iter()
        .map(|n| n.as_str())
        .collect::<Vec<_>>()
        .join(", ")
}
