//! The sampler lists of `--help` (`render`, `points`, `experiment`), built
//! at run time from the catalog's table so that a new sampler appears in
//! every list without an edit here, and the help of `--net`.

use lowdisc::catalog::{Family, SamplerName, net_sampler_list};
use lowdisc::net::NAMED_NETS;

/// The long help of a `--net` option: the built-in nets, the file formats
/// and the samplers that read a net.
pub fn net_help() -> String {
    let mut out = String::from(
        "Generator matrices for the Sobol samplers, in place of Joe & Kuo's: a \
         built-in net,\n",
    );
    for (name, description) in NAMED_NETS {
        out += &format!("  {name:8}  {description}\n");
    }
    out += "or a file: Joe & Kuo's direction numbers (header `d s a m_i`, then `d s a \
            m_1 .. m_s` per dimension; dimension 0 is implicit) or generator matrices \
            (one dimension per line, 32 columns, hex 0x.. or decimal, # comments); see \
            docs/guide/nets.md. Read by: ";
    out += &net_sampler_list();
    out += ". [default: sobol]";
    out
}

/// The long help of a `--sampler` option: `intro`, then every catalog name
/// with its one-line description, then `outro` (when not empty).
pub fn sampler_list(intro: &str, outro: &str) -> String {
    let width = SamplerName::ALL.iter().map(|n| n.as_str().len()).max();
    let pad = width.unwrap_or(0);
    let mut out = format!("{intro}\n");
    for n in SamplerName::ALL {
        out += &format!("  {:pad$}  {}\n", n.as_str(), n.description());
    }
    if outro.is_empty() {
        out.pop();
    } else {
        out += outro;
    }
    out
}

/// The names whose family satisfies `keep`, comma-separated and wrapped to
/// lines of at most `width` characters (the first line `indent` shorter).
pub fn names_where(keep: impl Fn(Family) -> bool, indent: usize, width: usize) -> String {
    let names = SamplerName::ALL.into_iter().filter(|n| keep(n.family()));
    let words: Vec<String> = names.map(|n| n.as_str().to_string()).collect();
    let joined = words.join(", ");
    wrap(&joined, indent, width)
}

/// `text` with spaces turned into line breaks so that no line is longer
/// than `width` (the first line counts `indent` characters already used).
fn wrap(text: &str, indent: usize, width: usize) -> String {
    let mut out = String::new();
    let mut column = indent;
    for (i, word) in text.split(' ').enumerate() {
        if i > 0 {
            if column + 1 + word.len() > width {
                out.push('\n');
                column = 0;
            } else {
                out.push(' ');
                column += 1;
            }
        }
        out.push_str(word);
        column += word.len();
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrapping_keeps_every_word_and_the_width() {
        let text = "a bb ccc dddd eeeee ffffff";
        let wrapped = wrap(text, 3, 10);
        assert_eq!(wrapped.replace('\n', " "), text);
        let mut lines = wrapped.lines();
        assert!(lines.next().unwrap().len() + 3 <= 10);
        assert!(lines.all(|l| l.len() <= 10));
    }

    #[test]
    fn the_lists_name_every_sampler_once() {
        let all = sampler_list("Samplers:", "");
        for n in SamplerName::ALL {
            let lines = all
                .lines()
                .filter(|l| l.split_whitespace().next() == Some(n.as_str()));
            assert_eq!(lines.count(), 1, "{n}");
        }
        let sobol = names_where(Family::is_sobol, 0, 72);
        assert!(sobol.contains("sobol-lms") && sobol.contains("paper-repro"));
        assert!(!sobol.contains("zsobol"));
    }
}
