#!/usr/bin/env python3
"""Check every relative link and anchor of a built HTML book.

Usage: check_links.py BOOK_DIR [--skip GLOB]... [--markdown FILE]...

Reads every .html file under BOOK_DIR (as written by `mdbook build docs`),
and for each `href` and `src` that is relative (no scheme, not
protocol-relative) checks that the file it names exists under BOOK_DIR and,
when it has a `#fragment`, that the target page has an element with that
`id` (or a named anchor). Prints one line per broken link,
`page: link (reason)`, and exits 1 if there is any; otherwise prints how many
links were checked and exits 0. Standard library only.

`--skip GLOB` (repeatable) leaves the links *of* the pages whose path under
BOOK_DIR matches GLOB unchecked (links *to* them are still checked): the
committed experiment reports under docs/experiments leave most of their
images out on purpose (docs/experiments/README.md). mdBook's own 404.html,
whose links are site-absolute, is always skipped.

`--markdown FILE` (repeatable) also checks a Markdown file that is not part
of the book (the repository's README.md): every relative link must name an
existing file or folder, and a `#fragment` into a Markdown file must match
one of its headings (GitHub's and mdBook's rule: lower case, spaces to
hyphens, other punctuation dropped).
"""

import argparse
import re
import sys
from fnmatch import fnmatch
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit


class Page(HTMLParser):
    """The links and the anchor ids of one HTML page."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.links = []
        self.ids = set()

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if value is None:
                continue
            if name == "id" or (tag == "a" and name == "name"):
                self.ids.add(value)
            if name in ("href", "src"):
                self.links.append(value)


def parse(path, cache):
    """The parsed page at `path`, parsed once."""
    if path not in cache:
        page = Page()
        page.feed(path.read_text(encoding="utf-8", errors="replace"))
        cache[path] = page
    return cache[path]


def is_relative(link):
    parts = urlsplit(link)
    return not parts.scheme and not parts.netloc and not link.startswith("//")


def broken_links(root, skip):
    """Yields (page, link, reason) for every broken relative link under root,
    except in the pages matching a glob of `skip`."""
    cache = {}
    root = root.resolve()
    for page_path in sorted(root.rglob("*.html")):
        name = page_path.relative_to(root).as_posix()
        if name == "404.html" or any(fnmatch(name, g) for g in skip):
            continue
        page = parse(page_path, cache)
        for link in page.links:
            if not link or not is_relative(link) or link.startswith("javascript:"):
                continue
            parts = urlsplit(link)
            target = page_path
            if parts.path:
                target = (page_path.parent / unquote(parts.path)).resolve()
                if target.is_dir():
                    target = target / "index.html"
                if root not in target.parents and target != root:
                    yield page_path, link, "points outside the book"
                    continue
                if not target.is_file():
                    yield page_path, link, "no such file"
                    continue
            fragment = unquote(parts.fragment)
            if fragment and target.suffix == ".html":
                if fragment not in parse(target, cache).ids:
                    yield page_path, link, f"no anchor #{fragment} in {target.relative_to(root)}"


MD_LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")


def slug(heading):
    """The anchor of a Markdown heading."""
    text = re.sub(r"[`*_]", "", heading.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def markdown_anchors(path):
    """The anchors of every heading of the Markdown file at path."""
    in_code = False
    anchors = set()
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            in_code = not in_code
        elif not in_code and line.startswith("#"):
            anchors.add(slug(line.lstrip("#")))
    return anchors


def broken_markdown_links(path):
    """Yields (link, reason) for every broken relative link of a Markdown file."""
    text = re.sub(r"```.*?```", "", path.read_text(encoding="utf-8"), flags=re.S)
    for link in MD_LINK.findall(text):
        if not is_relative(link):
            continue
        parts = urlsplit(link)
        target = (path.parent / unquote(parts.path)).resolve() if parts.path else path
        if not target.exists():
            yield link, "no such file"
        elif parts.fragment and target.suffix == ".md":
            if parts.fragment not in markdown_anchors(target):
                yield link, f"no heading #{parts.fragment} in {target.name}"


def main(argv):
    parser = argparse.ArgumentParser(description="Check the relative links and anchors of a built book.")
    parser.add_argument("book", type=Path, help="the built book (mdbook build docs writes target/book)")
    parser.add_argument("--skip", action="append", default=[], metavar="GLOB",
                        help="leave the links of matching pages unchecked")
    parser.add_argument("--markdown", action="append", default=[], type=Path, metavar="FILE",
                        help="also check the relative links of a Markdown file outside the book")
    args = parser.parse_args(argv[1:])
    root = args.book
    if not root.is_dir():
        print(f"error: {root} is not a folder (run `mdbook build docs` first)", file=sys.stderr)
        return 2
    bad = list(broken_links(root, args.skip))
    for page, link, reason in bad:
        print(f"{page.relative_to(root.resolve())}: {link} ({reason})")
    for md in args.markdown:
        for link, reason in broken_markdown_links(md):
            bad.append((md, link, reason))
            print(f"{md}: {link} ({reason})")
    pages = list(root.rglob("*.html"))
    if bad:
        print(f"{len(bad)} broken link(s)", file=sys.stderr)
        return 1
    print(f"links ok: every relative link and anchor of {len(pages)} pages")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
