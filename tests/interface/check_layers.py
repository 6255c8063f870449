#!/usr/bin/env python3
"""The driver's #include lines against its layer order (cpp_driver/layers.txt).

check_layers.py DRIVER_DIR: every `#include "folder/file"` of a file in DRIVER_DIR/<folder>/
names a folder of the same layer or a lower one; prints each that does not (file:line,
the include, both layers) and exits 1. A folder missing from layers.txt is an error too.
check_layers.py --self-test: runs the check on a small tree with one include against the
order and one within it, and fails unless exactly the first is reported.
"""
import pathlib
import re
import sys
import tempfile

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^/"]+)/[^"]+"')


def read_layers(driver):
    layers = []
    for line in (driver / "layers.txt").read_text().splitlines():
        line = line.strip()
        if line and not line.startswith("#"):
            layers.append(line.split()[0])
    return layers


def violations(driver):
    layers = read_layers(driver)
    rank = {name: i for i, name in enumerate(layers)}
    found = []
    for path in sorted(driver.rglob("*")):
        if path.suffix not in (".cpp", ".hpp", ".h") or not path.is_file():
            continue
        folder = path.relative_to(driver).parts[0]
        if folder not in rank:
            found.append(f"{path}: its folder '{folder}' is not in {driver / 'layers.txt'}")
            continue
        for no, text in enumerate(path.read_text().splitlines(), 1):
            m = INCLUDE.match(text)
            if not m or m.group(1) not in rank and not (driver / m.group(1)).is_dir():
                continue  # not a folder of the driver (a generated or system header)
            target = m.group(1)
            if target not in rank:
                found.append(f"{path}:{no}: includes '{target}/', a folder not in layers.txt")
            elif rank[target] > rank[folder]:
                found.append(f"{path}:{no}: {text.strip()} runs against the layers: "
                             f"{folder} (layer {rank[folder]}) may not include {target} (layer {rank[target]})")
    return found


def self_test():
    with tempfile.TemporaryDirectory() as tmp:
        d = pathlib.Path(tmp)
        (d / "layers.txt").write_text("# order\nlow  the bottom\nhigh the top\n")
        (d / "low").mkdir()
        (d / "high").mkdir()
        (d / "low" / "a.hpp").write_text('#include "high/b.hpp"\n')
        (d / "high" / "b.hpp").write_text('#include "low/a.hpp"\n#include <vector>\n')
        got = violations(d)
        ok = len(got) == 1 and "low/a.hpp:1" in got[0] and "may not include high" in got[0]
        print("self-test:", "ok" if ok else f"FAILED, reported {got}")
        return 0 if ok else 1


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    driver = pathlib.Path(sys.argv[1])
    found = violations(driver)
    for v in found:
        print(v)
    print(f"{len(found)} include(s) against the layer order of {driver / 'layers.txt'}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
