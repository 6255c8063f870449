#!/usr/bin/env python3
"""The Fortran core's `use` statements against its layer order (fortran_core/layers.txt).

check_fortran_layers.py CORE_DIR: every `use m` of a file in CORE_DIR/<folder>/ (or of a file
directly in CORE_DIR, folder ".") names a module of the core that lives in a folder of the same
layer or a lower one; prints each that does not (file:line, the use, both layers) and exits 1.
Modules outside the core (iso_c_binding, omp_lib, ...) are not checked. A folder missing from
layers.txt is an error too.
check_fortran_layers.py --self-test: runs the check on a small tree with one use against the
order and one within it, and fails unless exactly the first is reported.
"""
import pathlib
import re
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from check_layers import read_layers  # noqa: E402  (the same layers.txt format)

MODULE = re.compile(r"^\s*module\s+(\w+)\s*(?:!.*)?$", re.I)
USE = re.compile(r"^\s*use\s*(?:,\s*\w+\s*::)?\s*(?:::)?\s*(\w+)", re.I)


def folder_of(core, path):
    rel = path.relative_to(core).parts
    return rel[0] if len(rel) > 1 else "."


def violations(core):
    rank = {name: i for i, name in enumerate(read_layers(core))}
    sources = sorted(p for p in core.rglob("*.f90") if p.is_file())
    home = {}  # module name -> folder
    for path in sources:
        for text in path.read_text().splitlines():
            m = MODULE.match(text)
            if m:
                home[m.group(1).lower()] = folder_of(core, path)
    found = []
    for path in sources:
        folder = folder_of(core, path)
        if folder not in rank:
            found.append(f"{path}: its folder '{folder}' is not in {core / 'layers.txt'}")
            continue
        for no, text in enumerate(path.read_text().splitlines(), 1):
            m = USE.match(text)
            if not m or m.group(1).lower() not in home:
                continue  # not a module of the core (an intrinsic or library module)
            target = home[m.group(1).lower()]
            if target not in rank:
                found.append(f"{path}:{no}: uses {m.group(1)} of '{target}', a folder not in layers.txt")
            elif rank[target] > rank[folder]:
                found.append(f"{path}:{no}: `use {m.group(1)}` runs against the layers: "
                             f"{folder} (layer {rank[folder]}) may not use {target} (layer {rank[target]})")
    return found


SELF_TEST_TREE = {
    "layers.txt": "# order\n.  the root\nlow  the bottom\nhigh the top\n",
    "kinds.f90": "module kinds\nend module kinds\n",
    "low/a.f90": "module a\n  use kinds\n  use b, only: x\nend module a\n",
    "high/b.f90": "module b\n  use, intrinsic :: iso_c_binding\n  use a\n  use omp_lib\nend module b\n",
}


def self_test():
    """Exactly the one use against the order in SELF_TEST_TREE (low/a.f90 line 3) is found."""
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        for name, text in SELF_TEST_TREE.items():
            (root / name).parent.mkdir(exist_ok=True)
            (root / name).write_text(text)
        got = violations(root)
    ok = len(got) == 1 and "low/a.f90:3" in got[0] and "may not use high" in got[0]
    print("self-test:", "ok" if ok else f"FAILED, reported {got}")
    return 0 if ok else 1


def main(args):
    if args == ["--self-test"]:
        return self_test()
    if len(args) != 1:
        print(__doc__)
        return 2
    found = violations(pathlib.Path(args[0]))
    print("\n".join(found + [f"{len(found)} use statement(s) against the layer order of "
                             f"{pathlib.Path(args[0]) / 'layers.txt'}"]))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
