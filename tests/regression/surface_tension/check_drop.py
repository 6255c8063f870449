#!/usr/bin/env python3
"""Runs a surface-tension drop case and checks numbers of `sphjet drop`'s SUMMARY line.

Usage:
  check_drop.py SPHJET CASE OUT_DIR [--set KEY=VALUE ...] [--drop ARG ...]
                --expect KEY:LO:HI [--expect ...] [--regress KEY:REF:TOL ...]
                [--show KEY ...]

Runs `SPHJET run CASE --out OUT_DIR --force -q -j THREADS --set ...` (THREADS from the
environment variable SPHJET_TEST_THREADS, default 1), then `SPHJET drop OUT_DIR -q ARG...`,
parses the line `SUMMARY key=value ...`, and checks LO <= value <= HI for every --expect
(the validation target) and |value - REF| <= TOL for every --regress (the regression check);
a value of nan fails either. Prints one line per check and a final line `N passed, M failed`;
the exit status is 0 only when every check passed. The physics and the reason for each
tolerance are stated in the CMakeLists.txt that calls this script and in the case READMEs.
"""
import argparse
import os
import subprocess
import sys


sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from summary_checks import check, run_case, summary  # noqa: E402  (tests/regression/)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("sphjet")
    ap.add_argument("case")
    ap.add_argument("out")
    ap.add_argument("--set", action="append", default=[], dest="sets")
    ap.add_argument("--drop", action="append", default=[], help="argument for `sphjet drop`")
    ap.add_argument("--expect", action="append", default=[], help="KEY:LO:HI (validation target)")
    ap.add_argument("--regress", action="append", default=[],
                    help="KEY:REF:TOL (regression: |value - REF| <= TOL)")
    ap.add_argument("--show", action="append", default=[], help="KEY to print, not checked")
    a = ap.parse_args()

    if not run_case(a.sphjet, a.case, a.out, a.sets, len(a.expect) + len(a.regress)):
        return 1
    dcmd = [a.sphjet, "drop", a.out, "-q"] + a.drop
    print("$ " + " ".join(dcmd), flush=True)
    d = subprocess.run(dcmd, capture_output=True, text=True)
    s = summary(d.stdout)
    if d.returncode != 0 or s is None:
        print(d.stdout[-3000:])
        print(d.stderr[-3000:])
        print(f"0 passed, {len(a.expect) + len(a.regress)} failed")
        return 1
    print(next(l for l in d.stdout.splitlines() if l.startswith("SUMMARY ")))
    return check(s, a.expect, a.show, a.regress)


if __name__ == "__main__":
    sys.exit(main())
