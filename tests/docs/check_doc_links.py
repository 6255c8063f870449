#!/usr/bin/env python3
"""Every relative link in README.md, docs/ and cases/ resolves.

Usage: check_doc_links.py SOURCE_DIR

For each Markdown file (README.md, docs/**/*.md, cases/**/*.md) every link [text](target) and
image ![alt](target) outside code (fenced blocks and `inline code`) whose target is not a URL
(http:, https:, mailto:) must name a file or folder that exists, relative to the file. A
`#anchor` must be a heading of the target Markdown file (of the file itself when the target is
only `#anchor`), in GitHub's form: lower case, punctuation other than `-` and `_` dropped,
spaces turned into `-`, a repeated heading suffixed -1, -2, ... Prints each broken link as
FILE:LINE: target: why, and exits 1 if there is any.
"""
import os
import re
import sys

LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")


def markdown_files(source):
    yield os.path.join(source, "README.md")
    for top in ("docs", "cases"):
        for d, _, files in os.walk(os.path.join(source, top)):
            for f in sorted(files):
                if f.endswith(".md"):
                    yield os.path.join(d, f)


def prose_lines(path):
    """(line number, text) outside fenced blocks, with inline code removed."""
    fenced = False
    for n, line in enumerate(open(path, encoding="utf-8"), 1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if not fenced:
            yield n, re.sub(r"`[^`]*`", "", line)


def slug(heading):
    s = heading.strip().lower()
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


_anchors = {}


def anchors(path):
    if path not in _anchors:
        seen, out = {}, set()
        fenced = False
        for line in open(path, encoding="utf-8"):
            if line.lstrip().startswith("```"):
                fenced = not fenced
                continue
            m = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
            if fenced or not m:
                continue
            base = slug(m.group(1))
            k = seen.get(base, 0)
            seen[base] = k + 1
            out.add(base if k == 0 else f"{base}-{k}")
        _anchors[path] = out
    return _anchors[path]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    source = os.path.abspath(sys.argv[1])
    broken, checked = [], 0
    for md in markdown_files(source):
        rel_md = os.path.relpath(md, source)
        for n, text in prose_lines(md):
            for target in LINK.findall(text):
                if re.match(r"[a-z][a-z0-9+.-]*:", target):
                    continue
                checked += 1
                path, _, anchor = target.partition("#")
                full = os.path.normpath(os.path.join(os.path.dirname(md), path)) if path else md
                if not os.path.exists(full):
                    broken.append(f"{rel_md}:{n}: {target}: no such file or folder "
                                  f"({os.path.relpath(full, source)})")
                elif anchor and full.endswith(".md") and anchor not in anchors(full):
                    broken.append(f"{rel_md}:{n}: {target}: no heading #{anchor} in "
                                  f"{os.path.relpath(full, source)}")
    for b in broken:
        print(b)
    print(f"{checked} relative links checked, {len(broken)} broken")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
