use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec::Vec;

use super::*;
use crate::net_check::t_value;
use crate::sobol::{matrix, sample};

/// Joe & Kuo's published direction numbers of Sobol dimensions 1..64.
const JOE_KUO_64: &str = include_str!("../../tests/data/new-joe-kuo-6.64");

fn message(result: Result<DigitalNet, Error>) -> String {
    result.expect_err("the input is invalid").to_string()
}

#[test]
fn joe_kuo_text_reproduces_the_built_in_matrices() {
    let net = DigitalNet::from_joe_kuo("jk", JOE_KUO_64).unwrap();
    assert_eq!(net.dimensions(), 64);
    for d in 0..64 {
        assert_eq!(&net.columns()[d as usize], matrix(d), "dimension {d}");
    }
    // The spelled-out van der Corput row and 0-based numbering (Bonneel et
    // al.'s files) give the same net.
    let mut rows = JOE_KUO_64.lines();
    let header = rows.next().unwrap();
    let renumbered: Vec<String> = rows
        .map(|l| {
            let (d, rest) = l.split_once(char::is_whitespace).unwrap();
            format!("{}\t{}", d.parse::<u32>().unwrap() - 1, rest.trim())
        })
        .collect();
    let text = format!(
        "{header}\n0 0 0 # van der Corput\n{}\n",
        renumbered.join("\n")
    );
    assert_eq!(
        DigitalNet::from_joe_kuo("jk0", &text).unwrap().columns(),
        net.columns()
    );
}

#[test]
fn onetwo_pairs_2k_2k_plus_1_are_1_2_sequences_where_joe_kuo_are_not() {
    let onetwo = Net::named("onetwo").unwrap();
    // The largest t of the first 2^m points of dimensions d, d + 1 over
    // m = 1..=10.
    let pair_t = |net: Net, d: u32| {
        (1..=10)
            .map(|m| {
                let points: Vec<Vec<u32>> = (0..1u32 << m)
                    .map(|i| alloc::vec![net.sample(i, d), net.sample(i, d + 1)])
                    .collect();
                t_value(&points, m)
            })
            .max()
            .unwrap()
    };
    let pairs = (0..onetwo.dimensions() - 1).step_by(2);
    let worst = pairs.clone().map(|d| pair_t(onetwo, d)).max().unwrap();
    assert_eq!(worst, 1, "the worst pair of onetwo");
    let sobol_bad = pairs.filter(|&d| pair_t(Net::SOBOL, d) > 1).count();
    assert_eq!(sobol_bad, 344, "Joe-Kuo pairs with t > 1");
    // The guarantee is for the aligned pairs only: (3, 4) has t = 2.
    assert_eq!(pair_t(onetwo, 3), 2);
}

#[test]
fn matrix_text_round_trips_and_accepts_both_notations() {
    let dims: Vec<[u32; 32]> = (0..5).map(|d| *matrix(d)).collect();
    let text: String = dims
        .iter()
        .enumerate()
        .map(|(d, m)| {
            let words: Vec<String> = m
                .iter()
                .map(|&c| {
                    if d % 2 == 0 {
                        format!("{c:#010x}")
                    } else {
                        c.to_string()
                    }
                })
                .collect();
            format!(
                "# dimension {d}\n{}\n\n",
                words.join(if d == 3 { ", " } else { " " })
            )
        })
        .collect();
    let net = DigitalNet::parse("m.txt", &text).unwrap();
    assert_eq!(net.columns(), &dims[..]);
    assert_eq!(net.sample(77, 4), sample(77, 4));
    assert_eq!(
        net.id(),
        DigitalNet::from_columns("other", dims).unwrap().id()
    );
}

#[test]
fn bad_joe_kuo_files_name_the_file_and_line() {
    let jk = |body: &str| {
        message(DigitalNet::from_joe_kuo(
            "f.txt",
            &format!("d s a m_i\n{body}"),
        ))
    };
    assert_eq!(
        jk("2 1 0 1\n3 2 1 1 4\n"),
        "f.txt:3: m_2 = 4 is even; every m_i must be odd"
    );
    assert_eq!(jk("2 2 1 1 5\n"), "f.txt:2: m_2 = 5 is not below 2^2");
    assert_eq!(
        jk("2 1 0 1\n3 3 1 1 3\n"),
        "f.txt:3: 2 direction numbers for degree s = 3; expected 3 (truncated line?)"
    );
    assert_eq!(
        jk("2 1 0 1\n4 1 0 1\n"),
        "f.txt:3: dimension number 4 follows 2; expected 3"
    );
    assert_eq!(
        jk("2 2 3 1 3\n"),
        "f.txt:2: a = 3 has more than s - 1 = 1 bits"
    );
    assert_eq!(
        jk("2 33 0 1\n"),
        "f.txt:2: degree s = 33; it must be 1 to 32 (32-bit digits)"
    );
    assert_eq!(
        jk("2 1\n"),
        "f.txt:2: 2 numbers; a line holds d, s, a and m_1 .. m_s"
    );
    assert_eq!(jk("2 1 0 x1\n"), "f.txt:2: `x1` is not a number");
    assert_eq!(jk("2 1 0 1\nd s a\n"), "f.txt:3: `d` is not a number");
    assert_eq!(jk(""), "f.txt: no dimensions (an empty or truncated file)");
    let many: String = (0..MAX_NET_DIMENSIONS as u32)
        .map(|d| format!("{} 1 0 1\n", d + 2))
        .collect();
    assert_eq!(
        jk(&many),
        format!(
            "f.txt:{}: more than 65536 dimensions",
            MAX_NET_DIMENSIONS + 1
        )
    );
}

#[test]
fn bad_matrix_files_name_the_file_and_line() {
    let identity: Vec<String> = (0..32)
        .map(|c| format!("{:#x}", 1u32 << (31 - c)))
        .collect();
    let good = identity.join(" ");
    let m = |text: &str| message(DigitalNet::from_matrix_text("g.txt", text));
    assert_eq!(
        m(&format!("{good}\n0x1 2\n")),
        "g.txt:2: 2 columns; a dimension has 32"
    );
    let bad_word = good.replacen("0x80000000", "0x1ffffffff", 1);
    assert_eq!(
        m(&bad_word),
        "g.txt:1: `0x1ffffffff` is not a 32-bit number"
    );
    // Column 1 equal to column 0: the leading 2x2 block is singular.
    let singular = good.replacen("0x40000000", "0x80000000", 1);
    assert_eq!(
        m(&format!("# ok\n{good}\n{singular}\n")),
        "g.txt:3: dimension 1 is not a (0,1)-sequence: its leading 2x2 block is singular"
    );
    assert_eq!(m("# nothing\n\n"), "g.txt: no dimensions (an empty file)");
    assert_eq!(
        message(DigitalNet::from_columns("mem", Vec::new())),
        "mem: 0 dimensions; a net has 1 to 65536"
    );
}

#[test]
fn singular_blocks_are_found_at_their_size() {
    let identity: [u32; 32] = core::array::from_fn(|c| 1 << (31 - c));
    assert_eq!(first_singular_block(&identity), None);
    for d in 0..64 {
        assert_eq!(first_singular_block(matrix(d)), None, "Sobol dimension {d}");
    }
    let mut m = identity;
    m[5] |= 1 << 31; // still upper triangular with a unit diagonal
    assert_eq!(first_singular_block(&m), None);
    m[5] = 1 << 31; // digit 6 missing from column 5: block 6 singular
    assert_eq!(first_singular_block(&m), Some(6));
}

#[test]
fn nets_compare_by_matrices() {
    let a = DigitalNet::from_joe_kuo("a", JOE_KUO_64)
        .unwrap()
        .into_net();
    let b = DigitalNet::from_joe_kuo("b", JOE_KUO_64)
        .unwrap()
        .into_net();
    assert_eq!(a, b);
    assert_ne!(a, Net::SOBOL);
    assert_eq!(Net::SOBOL, Net::default());
    assert_eq!(a.id(), b.id());
    assert_eq!(Net::SOBOL.id(), None);
    assert_eq!(a.matrix(9), matrix(9));
    assert!(a.require(65, "x").is_err() && a.require(64, "x").is_ok());
}
