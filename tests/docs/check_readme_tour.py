#!/usr/bin/env python3
"""Runs the five-minute tour of README.md as it is written, with short end times.

Usage: check_readme_tour.py SPHJET SOURCE_DIR WORK_DIR --part main|legacy

The tour is the fenced block that follows the line `<!-- tour` in README.md. Its command lines
run from WORK_DIR/repo, a stand-in for the checkout: `cases` links to SOURCE_DIR/cases,
`tools` is a copy of SOURCE_DIR/tools (the tools find the checkout from their own place, so
their default outputs land under WORK_DIR), `build/cpp_driver/sphjet` links to SPHJET and
`../shared` to SOURCE_DIR/../shared when that exists. Only the end time changes:
- `sphjet run` of a case in the checkout gets `--tmax 0.02` (3 snapshots of the jet; the
  README's run goes to the first breakup, about 0.15 s);
- `tools/jet_study.py run` gets `--tmax 0.002 -j 1` (each of the 16 runs 100-200 steps);
- `paraview FILE` is not started (no display here): FILE must exist. ParaView itself is
  checked by interface.paraview_opens_xdmf where it is installed.
Lines that read ../shared (legacy SPHysics runs) form the part `legacy`, the rest `main`;
`--part legacy` exits 77 (ctest: skipped) when ../shared/legacy is absent.
After the commands, what the README says they give is checked: the jet's XDMF index and
snapshots, the PNG, compare's SUMMARY line and its RMS position difference (README.md quotes
2.3e-6 dx; at most 1e-5 dx), the study's table1.md.
"""
import argparse
import os
import re
import shlex
import shutil
import subprocess
import sys

MAIN_TMAX = "0.02"
STUDY_ARGS = ["--tmax", "0.002", "-j", "1"]


def tour_lines(readme):
    """The command lines of the fenced block after the `<!-- tour` marker."""
    lines = open(readme, encoding="utf-8").read().split("\n")
    start = next((i for i, l in enumerate(lines) if l.startswith("<!-- tour")), None)
    if start is None:
        sys.exit(f"{readme}: no line starting with '<!-- tour' (the marker of the tour's block)")
    i = start + 1
    if i >= len(lines) or not lines[i].startswith("```"):
        sys.exit(f"{readme}:{i + 1}: expected a fenced block (```) right after the tour marker, "
                 f"found {lines[i]!r}" if i < len(lines) else f"{readme}: the file ends after the marker")
    out = []
    for j in range(i + 1, len(lines)):
        if lines[j].startswith("```"):
            return out
        text = lines[j].strip()
        if text and not text.startswith("#"):
            out.append((j + 1, text))
    sys.exit(f"{readme}: the tour's block is not closed")


def shortened(words):
    """The command with its short end time (a list of words)."""
    if len(words) >= 2 and words[0].endswith("sphjet") and words[1] == "run":
        if "--tmax" not in words and not any("../shared" in w for w in words):
            return words + ["--tmax", MAIN_TMAX]
    if any(w.endswith("jet_study.py") for w in words) and "run" in words:
        return words + STUDY_ARGS
    return words


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("sphjet")
    ap.add_argument("source")
    ap.add_argument("work")
    ap.add_argument("--part", choices=("main", "legacy"), required=True)
    a = ap.parse_args()

    source = os.path.abspath(a.source)
    shared = os.path.join(os.path.dirname(source), "shared")
    lines = tour_lines(os.path.join(source, "README.md"))
    mine = [(n, t) for n, t in lines if ("../shared" in t) == (a.part == "legacy")]
    if not mine:
        sys.exit(f"README.md: the tour has no {a.part} commands (expected at least one)")
    if a.part == "legacy" and not os.path.isdir(os.path.join(shared, "legacy")):
        print(f"SKIPPED: {shared}/legacy is absent (the legacy SPHysics runs): the tour's "
              f"comparison with legacy is not run")
        return 77

    work = os.path.abspath(a.work)
    shutil.rmtree(work, ignore_errors=True)
    repo = os.path.join(work, "repo")
    os.makedirs(os.path.join(repo, "build", "cpp_driver"))
    os.symlink(os.path.join(source, "cases"), os.path.join(repo, "cases"))
    shutil.copytree(os.path.join(source, "tools"), os.path.join(repo, "tools"),
                    ignore=shutil.ignore_patterns("__pycache__"))
    os.symlink(os.path.abspath(a.sphjet), os.path.join(repo, "build", "cpp_driver", "sphjet"))
    if os.path.isdir(shared):
        os.symlink(shared, os.path.join(work, "shared"))

    outputs = {}
    for n, text in mine:
        words = shortened(shlex.split(text))
        if words[0] == "paraview":
            target = os.path.join(repo, words[-1])
            print(f"README.md:{n}: {text}\n  (not started here) {words[-1]} exists: {os.path.isfile(target)}")
            if not os.path.isfile(target):
                print(f"FAIL: README.md:{n}: ParaView would open {words[-1]}, which the commands "
                      f"before it did not write")
                return 1
            continue
        print(f"README.md:{n}: {text}\n  runs as: {shlex.join(words)}", flush=True)
        p = subprocess.run(words, cwd=repo, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True)
        outputs[n] = p.stdout
        tail = "\n".join(p.stdout.strip().split("\n")[-8:])
        print("  " + tail.replace("\n", "\n  "))
        if p.returncode != 0:
            print(f"FAIL: README.md:{n}: exit status {p.returncode}")
            return 1

    # What the README says the commands give.
    failures = []
    def expect(ok, what):
        print(("ok: " if ok else "FAIL: ") + what)
        if not ok:
            failures.append(what)

    def mentioned(pattern):
        return [t for _, t in mine if re.search(pattern, t)]

    if a.part == "main":
        for t in mentioned(r"sphjet run \S+\.toml"):
            out = shlex.split(t)[shlex.split(t).index("--out") + 1]
            d = os.path.join(repo, out)
            snaps = [f for f in os.listdir(d) if f.startswith("snap_")] if os.path.isdir(d) else []
            expect(os.path.isfile(os.path.join(d, "sphjet.xmf")) and len(snaps) >= 2,
                   f"{out}: sphjet.xmf and at least two snapshots ({len(snaps)})")
        for t in mentioned(r"plot_jet\.py"):
            w = shlex.split(t)
            png = w[w.index("-o") + 1] if "-o" in w else os.path.join(w[2], "jet.png")
            expect(os.path.getsize(os.path.join(repo, png)) > 1000 if os.path.isfile(os.path.join(repo, png)) else False,
                   f"{png}: a PNG written")
        for t in mentioned(r"jet_study\.py report"):
            w = shlex.split(t)
            out = w[w.index("--out") + 1]
            expect(os.path.isfile(os.path.join(repo, out, "table1.md")), f"{out}/table1.md written")
    else:
        compared = [n for n, t in mine if " compare " in f" {t} "]
        expect(bool(compared), "the legacy part runs `sphjet compare`")
        for n in compared:
            m = re.search(r"^SUMMARY .*", outputs.get(n, ""), re.M)
            expect(m is not None, f"README.md:{n}: compare printed its SUMMARY line")
            if m:
                print("  " + m.group(0))
                # README.md quotes the RMS position difference of the last output (2.3e-6 dx
                # after 292 steps); 1e-5 dx keeps that statement true. The parity itself, with
                # its own tolerance, is regression.case1_early_parity.
                rms = re.search(r"rms_dx_last=(\S+)", m.group(0))
                expect(rms is not None and float(rms.group(1)) <= 1e-5,
                       f"README.md:{n}: RMS position difference of the last output "
                       f"{rms.group(1) if rms else '?'} dx <= 1e-5 dx")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
