//! Pinned points-mode words of every catalog name (value stability).

use super::config;
use lowdisc::catalog::{Order, SamplerName, generate_points};

/// Pinned points (value stability): seed 7, the first 4 points in Gray
/// order, dimensions 0..3.
const PINNED_POINTS: &[(SamplerName, [u32; 12])] = &[
    (
        SamplerName::Independent,
        [
            0x50e272b0, 0xc795f2b7, 0x9320dcb1, 0xbd5a26a3, 0x6f7af2b2, 0xcf3bbb5f, 0x0a785080,
            0xdab141f6, 0x3f27edf4, 0xde644be7, 0x8db6faaf, 0x842cf7b7,
        ],
    ),
    (
        SamplerName::Stratified,
        [
            0x2e6e98c5, 0x798838ab, 0x10b1f8d5, 0xefa636ac, 0x67cc8f5c, 0x5f3a5c9f, 0x1b27219a,
            0xdbe7c02c, 0xbf55b0e3, 0xa8ff11d9, 0xa5a04697, 0xd47dc87d,
        ],
    ),
    (
        SamplerName::Halton,
        [
            0x49504766, 0x6269a7e8, 0x2338f0a5, 0xc9504766, 0xb7befd3e, 0x566c23d9, 0x09504766,
            0x0d145293, 0xbcd28a3f, 0x89504766, 0x9b4d3621, 0x899f570c,
        ],
    ),
    (
        SamplerName::HaltonOwen,
        [
            0x2c8072b7, 0xa6b858d1, 0xde1c40e9, 0x8de4b4c2, 0x31b9a890, 0xa2fdc22f, 0x53bd1d16,
            0xc7848659, 0x88f1bc3f, 0xefd51b7a, 0x872d797c, 0x2c52a843,
        ],
    ),
    // scipy.stats.qmc.Sobol(3, scramble=False): [0,0,0], [.5,.5,.5], [.75,.25,.25], [.25,.75,.75].
    (
        SamplerName::Sobol,
        [
            0x00000000, 0x00000000, 0x00000000, 0x80000000, 0x80000000, 0x80000000, 0xc0000000,
            0x40000000, 0x40000000, 0x40000000, 0xc0000000, 0xc0000000,
        ],
    ),
    (
        SamplerName::SobolXor,
        [
            0xef891f64, 0xe700b270, 0x6ac2a53a, 0x6f891f64, 0x6700b270, 0xeac2a53a, 0x2f891f64,
            0xa700b270, 0x2ac2a53a, 0xaf891f64, 0x2700b270, 0xaac2a53a,
        ],
    ),
    (
        SamplerName::SobolOwen,
        [
            0x113ab8f4, 0xaef89253, 0xaf37d463, 0x8ded71bf, 0x001e6c8c, 0x1e385e7a, 0xc5251871,
            0xe242a89d, 0xda803a34, 0x79f6f2d4, 0x69eba34c, 0x6099c52b,
        ],
    ),
    (
        SamplerName::SobolFastOwen,
        [
            0x34851310, 0xf18b8079, 0x4eab80bf, 0x935f3d13, 0x425df421, 0x89c8ef4d, 0xcc2422b9,
            0x80a21dff, 0x0af32eec, 0x73751ec4, 0x3e97bd7e, 0xe09e2e42,
        ],
    ),
    (
        SamplerName::SobolLms,
        [
            0xcc3ee54d, 0x3b82d093, 0x872a777f, 0x091c884b, 0xd9bc9556, 0x354eb1b1, 0x48d42aac,
            0x78e45d47, 0xc23f1317, 0x8df647aa, 0x9ada1882, 0x705bd5d9,
        ],
    ),
    (
        SamplerName::Paper,
        [
            0x00000000, 0x00000000, 0x00000000, 0x7fffffff, 0x80000000, 0x80000000, 0x40000000,
            0xbfffffff, 0xbfffffff, 0x40000000, 0xc0000000, 0x3fffffff,
        ],
    ),
    (
        SamplerName::PaperRepro,
        [
            0x00000000, 0x00000000, 0x00000000, 0x80000000, 0x80000000, 0x80000000, 0xc0000000,
            0xbfffffff, 0xbfffffff, 0x40000000, 0x3fffffff, 0xc0000000,
        ],
    ),
    (
        SamplerName::PaddedSobol,
        [
            0xe069c999, 0xfc91353b, 0xab70e9e8, 0x37f5f676, 0x296b6092, 0x02ff0210, 0x4aa44e78,
            0x89ab3cba, 0xf5452b5b, 0x82ab33c5, 0x515bdd4e, 0x652e63b3,
        ],
    ),
    (
        SamplerName::PaddedSobolLms,
        [
            0xac5c0bec, 0x38dc6ea3, 0x33e082fe, 0x7ec4a55e, 0xf0b6c500, 0xb4f45e36, 0x1b76277d,
            0x6f8e6acc, 0x444baaa6, 0xc9ee89cf, 0xa7e4c16f, 0xc35f766e,
        ],
    ),
    (
        SamplerName::ZSobol,
        [
            0xec7c869e, 0x8aacdbc7, 0x2f487c0d, 0x5ef17c4b, 0x5026ae61, 0xbe0bd932, 0x9ba78a8e,
            0x04b9c475, 0x557fab77, 0x2a352fca, 0xf03e9725, 0xcc81e442,
        ],
    ),
    (
        SamplerName::SobolBurley,
        [
            0x37804759, 0xc27c1b3e, 0x32f2d86e, 0xe9655563, 0x7e2a01b5, 0xd24d90e5, 0x56489f0d,
            0x0f0d4074, 0x92ec9349, 0xbba27f91, 0xb5f9355a, 0x578945af,
        ],
    ),
    (
        SamplerName::LaineKarras,
        [
            0xa0bad662, 0xd68e5024, 0xa81a7621, 0x554c29cd, 0x0ed0920f, 0x0eaafdfd, 0x2ef5143a,
            0xa8669b93, 0xe5407317, 0xed26aef9, 0x5f37236f, 0x5f58b999,
        ],
    ),
    (
        SamplerName::SobolPixelXor,
        [
            0x44bb22c8, 0x4d7f3acf, 0xd25f96c5, 0xc4bb22c8, 0xcd7f3acf, 0x525f96c5, 0x04bb22c8,
            0x8d7f3acf, 0x125f96c5, 0x84bb22c8, 0x0d7f3acf, 0x925f96c5,
        ],
    ),
    (
        SamplerName::Pmj02,
        [
            0xf6db0822, 0xffcd3362, 0xf94b3151, 0x6023ce55, 0x7b6e9f64, 0xa0beced9, 0xa8bac7e9,
            0x0058f497, 0x1be39fc3, 0x26114b7b, 0x98b49f6f, 0x790c9c0b,
        ],
    ),
    (
        SamplerName::Pmj02Bn,
        [
            0xcca8b99a, 0xd538e6a5, 0xf94b3151, 0x76db0822, 0x7fcd3362, 0x8a0a1c14, 0xa8bac7e9,
            0x0058f497, 0x20beced9, 0x26114b7b, 0x98b49f6f, 0x790c9c0b,
        ],
    ),
    (
        SamplerName::ZSobol4d,
        [
            0x426c6544, 0xbf5b2cb1, 0xce7b0651, 0xece2aba9, 0x4357db37, 0x08140ddc, 0x2c09a2a6,
            0x016cdb50, 0x75e3a882, 0x8d901c03, 0xdd555887, 0x997eb713,
        ],
    ),
    (
        SamplerName::ZSobolJoint,
        [
            0x426c6544, 0xbf5b2cb1, 0xce7b0651, 0xece2aba9, 0x4357db37, 0x08140ddc, 0x2c09a2a6,
            0x016cdb50, 0x75e3a882, 0x8d901c03, 0xdd555887, 0x997eb713,
        ],
    ),
    (
        SamplerName::ZOrderSz,
        [
            0xc5a8d907, 0x50dbb968, 0xb1350a6e, 0xba6b323f, 0xd13a2584, 0x08e804e6, 0x5baeb32e,
            0xb96a06dc, 0xe415f4d8, 0x0523f8d2, 0x12d571dc, 0x46dea1a3,
        ],
    ),
    (
        SamplerName::CascadedSobol,
        [
            0x14cb6910, 0xdec26826, 0xe7fa309f, 0xd764948b, 0xb383e0ed, 0x0ebec5f4, 0x77393c6d,
            0x3ccaed6a, 0xb1a1088a, 0x97963bef, 0x5050a3c3, 0x41d6537d,
        ],
    ),
    (
        SamplerName::OpenQmcSobol,
        [
            0x26db7bd2, 0xdcd0437e, 0x0a9000fa, 0x82e15d75, 0x5d1cf27f, 0xd83a117b, 0xc59bde08,
            0x92998c85, 0x61080b7b, 0x7bb2a5c8, 0x1198edc0, 0x919ad6bb,
        ],
    ),
    (
        SamplerName::OpenQmcSobolBn,
        [
            0x69f6814a, 0xc4904057, 0x12befbd7, 0xc2c97bd8, 0x78e367a6, 0xdedfaf68, 0x8dd434ac,
            0x9cd887b7, 0xa556a6bf, 0x3ae605f6, 0x38a0a0d7, 0x4b3b9194,
        ],
    ),
    (
        SamplerName::OpenQmcLattice,
        [
            0x39bdbfc3, 0x9f16e0ee, 0x3d92750a, 0xb9bdbfc3, 0x1f16e0ee, 0xbd92750a, 0xf9bdbfc3,
            0x5f16e0ee, 0x7d92750a, 0x79bdbfc3, 0xdf16e0ee, 0xfd92750a,
        ],
    ),
    (
        SamplerName::OpenQmcLatticeBn,
        [
            0x6533cdef, 0x7e412a96, 0x91f52892, 0xe533cdef, 0xfe412a96, 0x11f52892, 0x2533cdef,
            0x3e412a96, 0x51f52892, 0xa533cdef, 0xbe412a96, 0xd1f52892,
        ],
    ),
    (
        SamplerName::OpenQmcPmj,
        [
            0xa7fefc6a, 0xcfd40fd9, 0xd593495e, 0x4d1ca84b, 0x4cf277fa, 0x25a43dd9, 0x1a156b99,
            0x9cd60b05, 0x778e7227, 0xe971a98a, 0x224a6cba, 0x9d62dbfa,
        ],
    ),
    (
        SamplerName::OpenQmcPmjBn,
        [
            0xb53825dc, 0x86bda1fc, 0x27406967, 0x416e9b94, 0x3b79f641, 0xcd48e9c5, 0xfcd678e3,
            0x559d885c, 0x6fb75076, 0x16817508, 0xd52c0699, 0x9f119dca,
        ],
    ),
];

#[test]
fn pinned_points_for_every_name() {
    assert_eq!(PINNED_POINTS.len(), SamplerName::ALL.len());
    for &(name, want) in PINNED_POINTS {
        let got = generate_points(&config(name), 4, 0..3, Order::Gray).unwrap();
        assert_eq!(got, want, "{name}");
    }
}
