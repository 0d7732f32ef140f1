//! `report.html`: the report's Markdown as an HTML page.

use std::fmt::Write as _;

/// Minimal Markdown-to-HTML for the report's own Markdown (headings,
/// paragraphs, pipe tables and images).
pub fn html(md: &str) -> String {
    let esc = |s: &str| {
        s.replace('&', "&amp;")
            .replace('<', "&lt;")
            .replace('>', "&gt;")
    };
    let cell = |c: &str| {
        let c = c.trim();
        match c.strip_prefix("![](").and_then(|r| r.strip_suffix(')')) {
            Some(src) => format!("<img src=\"{}\" style=\"max-width:320px\">", esc(src)),
            None => esc(c),
        }
    };
    let mut out = String::from(
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>lowdisc experiment</title>\
<style>body{font-family:sans-serif;max-width:1400px;margin:auto}table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:3px 6px;font-size:13px}</style></head><body>\n",
    );
    let mut in_table = false;
    for line in md.lines() {
        if line.starts_with('|') {
            if line.starts_with("|---") {
                continue;
            }
            let cells: Vec<String> = line.trim_matches('|').split('|').map(cell).collect();
            if !in_table {
                out.push_str("<table>\n<tr>");
                cells.iter().for_each(|c| {
                    let _ = write!(out, "<th>{c}</th>");
                });
                out.push_str("</tr>\n");
                in_table = true;
            } else {
                out.push_str("<tr>");
                cells.iter().for_each(|c| {
                    let _ = write!(out, "<td>{c}</td>");
                });
                out.push_str("</tr>\n");
            }
            continue;
        }
        if in_table {
            out.push_str("</table>\n");
            in_table = false;
        }
        if let Some(t) = line.strip_prefix("## ") {
            let _ = writeln!(out, "<h2>{}</h2>", esc(t));
        } else if let Some(t) = line.strip_prefix("# ") {
            let _ = writeln!(out, "<h1>{}</h1>", esc(t));
        } else if !line.is_empty() {
            let _ = writeln!(out, "<p>{}</p>", cell(line));
        }
    }
    if in_table {
        out.push_str("</table>\n");
    }
    out.push_str("</body></html>\n");
    out
}
