#!/usr/bin/env python3
"""The project speaks of itself: no word of how it was built in its docs, cases and code.

Usage: check_wording.py SOURCE_DIR

Searches README.md, docs/, cases/, cpp_driver/, fortran_core/ and tools/ (every text file)
for four words of the project's build history, any case, singular or plural. They are given
by the first 16 hex digits of their SHA-256 (BANNED), so that this file does not spell them;
a line's words are its runs of letters and digits. Prints each hit as FILE:LINE: text, and
exits 1 if there is any.
"""
import hashlib
import os
import re
import sys

ROOTS = ("README.md", "docs", "cases", "cpp_driver", "fortran_core", "tools")
BANNED = {"3f3af1ecebbd1410", "4a502846d070e208", "e81d3b0e9d82feaa", "c3c7674c52b55b0e"}
TOKEN = re.compile(r"[a-z0-9]+")


def files(source):
    for root in ROOTS:
        top = os.path.join(source, root)
        if os.path.isfile(top):
            yield top
            continue
        for d, dirs, names in os.walk(top):
            dirs[:] = [x for x in dirs if x != "__pycache__"]
            for name in sorted(names):
                yield os.path.join(d, name)


def banned(word):
    """True for a banned word or its plural in -s."""
    forms = (word, word[:-1]) if word.endswith("s") else (word,)
    return any(hashlib.sha256(f.encode()).hexdigest()[:16] in BANNED for f in forms)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    source = os.path.abspath(sys.argv[1])
    hits, n_files = [], 0
    for path in files(source):
        try:
            text = open(path, encoding="utf-8").read()
        except (UnicodeDecodeError, OSError):
            continue  # binary: images, HDF5
        n_files += 1
        for n, line in enumerate(text.split("\n"), 1):
            rest = line.lower()
            if any(banned(w) for w in TOKEN.findall(rest)):
                hits.append(f"{os.path.relpath(path, source)}:{n}: {line.strip()[:160]}")
    for h in hits:
        print(h)
    print(f"{n_files} text files searched, {len(hits)} lines with a banned word")
    return 1 if hits else 0


if __name__ == "__main__":
    sys.exit(main())
