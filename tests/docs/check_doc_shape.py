#!/usr/bin/env python3
"""README.md stays short enough to read in five minutes, and every case says where it stands first.

Usage: check_doc_shape.py SOURCE_DIR

- README.md has at most 300 lines, and no cell of a table in it is longer than 300 characters
  (the findings behind a figure belong in docs/ or a case README, not in a table cell);
- every cases/*/README.md opens (after its title) with a summary paragraph that starts with
  `**Summary.**` and has at most 10 lines of at most 160 characters each: what the case is,
  against what, where it stands (a line count alone lets one line grow without bound).
Prints each breach as FILE:LINE: what, and exits 1 if there is any.
"""
import glob
import os
import re
import sys

MAX_LINES, MAX_CELL, MAX_SUMMARY, MAX_SUMMARY_LINE = 300, 300, 10, 160


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    source = os.path.abspath(sys.argv[1])
    bad = []
    lines = open(os.path.join(source, "README.md"), encoding="utf-8").read().split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    if len(lines) > MAX_LINES:
        bad.append(f"README.md: {len(lines)} lines, at most {MAX_LINES}")
    for n, line in enumerate(lines, 1):
        if line.startswith("|"):
            cells = re.split(r"(?<!\\)\|", line.strip().strip("|"))
            longest = max(len(c.strip()) for c in cells)
            if longest > MAX_CELL:
                bad.append(f"README.md:{n}: a table cell of {longest} characters, at most {MAX_CELL}")
    for path in sorted(glob.glob(os.path.join(source, "cases", "*", "README.md"))):
        rel = os.path.relpath(path, source)
        text = open(path, encoding="utf-8").read().split("\n")
        body = [i for i, l in enumerate(text) if i > 0 and l.strip()]
        first = body[0] if body else None
        if first is None or not text[first].startswith("**Summary.**"):
            bad.append(f"{rel}:{(first or 0) + 1}: the first paragraph after the title must start "
                       f"with **Summary.**, found {text[first][:40]!r}" if first is not None else
                       f"{rel}: empty")
            continue
        end = next((i for i in range(first, len(text)) if not text[i].strip()), len(text))
        if end - first > MAX_SUMMARY:
            bad.append(f"{rel}:{first + 1}: a summary of {end - first} lines, at most {MAX_SUMMARY}")
        for i in range(first, end):
            if len(text[i]) > MAX_SUMMARY_LINE:
                bad.append(f"{rel}:{i + 1}: a summary line of {len(text[i])} characters, "
                           f"at most {MAX_SUMMARY_LINE}")
    for b in bad:
        print(b)
    print(f"README.md {len(lines)} lines; {len(glob.glob(os.path.join(source, 'cases', '*', 'README.md')))} "
          f"case READMEs; {len(bad)} breaches")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
