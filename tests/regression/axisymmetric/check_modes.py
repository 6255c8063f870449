#!/usr/bin/env python3
"""Runs `sphjet modes` on a case and checks numbers of its SUMMARY line.

Usage:
  check_modes.py SPHJET CASE [--arg ARG ...] [--expect KEY:LO:HI ...] [--regress KEY:REF:TOL ...]
                 [--show KEY ...]

Runs `SPHJET modes CASE ARG...` and checks LO <= value <= HI for every --expect (the physics
target) and |value - REF| <= TOL for every --regress; nan fails either. Prints one line per
check and a final line `N passed, M failed`; exit status 0 only when all passed. The physics
and the reason for each tolerance are in the CMakeLists.txt that calls this script.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from summary_checks import check_output_of  # noqa: E402  (tests/regression/)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("sphjet")
    ap.add_argument("case")
    ap.add_argument("--arg", action="append", default=[], dest="args")
    ap.add_argument("--expect", action="append", default=[], help="KEY:LO:HI")
    ap.add_argument("--regress", action="append", default=[], help="KEY:REF:TOL")
    ap.add_argument("--show", action="append", default=[])
    a = ap.parse_args()
    return check_output_of([a.sphjet, "modes", a.case] + a.args, a.expect, a.show, a.regress)

if __name__ == "__main__":
    sys.exit(main())
