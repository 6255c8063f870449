#!/usr/bin/env python3
"""Runs an axisymmetric case and checks numbers of the SUMMARY line of tools/axisymmetric.py.

Usage:
  check_axi.py SPHJET CASE OUT_DIR [--set KEY=VALUE ...] --analyse SUBCOMMAND
               [--arg ARG ...] --expect KEY:LO:HI [--expect ...] [--show KEY ...]

Runs `SPHJET run CASE --out OUT_DIR --force -q -j THREADS --set ...` (THREADS from the
environment variable SPHJET_TEST_THREADS, default 1), then
`tools/axisymmetric.py SUBCOMMAND OUT_DIR ARG...` with /usr/bin/python3 (numpy, h5py; or
$SPHJET_ANALYSIS_PYTHON), and checks
LO <= value <= HI for every --expect (nan fails). Prints one line per check and a final line
`N passed, M failed`; exit status 0 only when all passed. The physics and the reason for
each tolerance are in the CMakeLists.txt that calls this script and in
cases/axisymmetric/README.md.
"""
import argparse
import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.join(HERE, "..", "..", "..", "tools", "axisymmetric.py")


sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from summary_line import summary  # noqa: E402  (tests/regression/summary_line.py)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("sphjet")
    ap.add_argument("case")
    ap.add_argument("out")
    ap.add_argument("--set", action="append", default=[], dest="sets")
    ap.add_argument("--analyse", required=True)
    ap.add_argument("--arg", action="append", default=[], dest="args")
    ap.add_argument("--expect", action="append", default=[])
    ap.add_argument("--show", action="append", default=[])
    a = ap.parse_args()

    threads = os.environ.get("SPHJET_TEST_THREADS", "1")
    cmd = [a.sphjet, "run", a.case, "--out", a.out, "--force", "-q", "-j", threads]
    for s in a.sets:
        cmd += ["--set", s]
    print("$ " + " ".join(cmd), flush=True)
    t0 = time.time()
    r = subprocess.run(cmd, capture_output=True, text=True)
    print(f"run: exit {r.returncode}, {time.time() - t0:.1f} s wall", flush=True)
    if r.returncode != 0:
        print(r.stdout[-3000:])
        print(r.stderr[-3000:])
        print(f"0 passed, {len(a.expect)} failed")
        return 1
    # the analysis needs numpy and h5py: Debian's interpreter has them (README), the one that
    # runs this script may not
    py = os.environ.get("SPHJET_ANALYSIS_PYTHON",
                        "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable)
    acmd = [py, TOOL, a.analyse, a.out] + a.args
    print("$ " + " ".join(acmd), flush=True)
    r = subprocess.run(acmd, capture_output=True, text=True)
    print(r.stdout[-3000:], r.stderr[-2000:])
    s = summary(r.stdout)
    if r.returncode != 0 or s is None:
        print(f"0 passed, {len(a.expect)} failed")
        return 1
    ok = bad = 0
    for e in a.expect:
        key, lo, hi = e.rsplit(":", 2)
        v = s.get(key, float("nan"))
        good = isinstance(v, float) and not math.isnan(v) and float(lo) <= v <= float(hi)
        print(f"{'PASS' if good else 'FAIL'} {key} = {v} in [{lo}, {hi}]")
        ok += good
        bad += not good
    for k in a.show:
        print(f"show {k} = {s.get(k)}")
    print(f"{ok} passed, {bad} failed")
    return 0 if bad == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
