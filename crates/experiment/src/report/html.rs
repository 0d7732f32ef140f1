//! `report.html`: the report's Markdown rendered by `pulldown-cmark`
//! (CommonMark with pipe tables) inside a page whose style sheet shows
//! every image at the full width of the page or of its table column (each
//! is a link to its full-size file); a table of images fills the page in
//! columns of equal width, so a sampler's render, crop and error heatmap
//! sit side by side at one size.

use pulldown_cmark::{Options, Parser, html::push_html};

/// The page's head: title and style sheet.
const HEAD: &str = "<!DOCTYPE html>
<html lang=\"en\"><head><meta charset=\"utf-8\">
<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">
<title>lowdisc experiment</title>
<style>
body{font-family:sans-serif;max-width:1600px;margin:auto;padding:0 1em;line-height:1.4}
img{max-width:100%;height:auto;image-rendering:pixelated}
table{border-collapse:collapse;margin:0.5em 0}
td,th{border:1px solid #ccc;padding:3px 6px;font-size:13px;vertical-align:top}
th{background:#f3f3f3}
table:has(img){width:100%;table-layout:fixed}
table:has(img) th:first-child{width:8em}
td img{width:100%}
p img{width:100%}
code{background:#f3f3f3;padding:0 3px}
</style></head><body>
";

/// The HTML page of `markdown`.
pub fn html(markdown: &str) -> String {
    let mut out = String::from(HEAD);
    push_html(&mut out, Parser::new_ext(markdown, Options::ENABLE_TABLES));
    out.push_str("</body></html>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_code_and_linked_images_become_html() {
        let md =
            "# T\n\nUse `sobol` & 1 < 2.\n\n| a | b |\n|---|---|\n| [![x](x.png)](x.png) | 1 |\n";
        let page = html(md);
        assert!(page.contains("<h1>T</h1>"), "{page}");
        assert!(
            page.contains("<code>sobol</code> &amp; 1 &lt; 2."),
            "{page}"
        );
        assert!(page.contains("<table>"), "{page}");
        assert!(
            page.contains("<a href=\"x.png\"><img src=\"x.png\" alt=\"x\" /></a>"),
            "{page}"
        );
        assert!(!page.contains('`') && !page.contains("|---"), "{page}");
        assert!(page.ends_with("</body></html>\n"));
    }
}
