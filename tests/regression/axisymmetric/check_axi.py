#!/usr/bin/env python3
"""Runs an axisymmetric case and checks numbers of the SUMMARY line of tools/axisymmetric.py.

Usage:
  check_axi.py SPHJET CASE OUT_DIR [--set KEY=VALUE ...] --analyse SUBCOMMAND
               [--arg ARG ...] --expect KEY:LO:HI [--expect ...]
               [--regress KEY:REF:TOL ...] [--show KEY ...]

Runs `SPHJET run CASE --out OUT_DIR --force -q -j THREADS --set ...` (THREADS from the
environment variable SPHJET_TEST_THREADS, default 1), then
`tools/axisymmetric.py SUBCOMMAND OUT_DIR ARG...` with /usr/bin/python3 (numpy, h5py; or
$SPHJET_ANALYSIS_PYTHON), and checks
LO <= value <= HI for every --expect (the validation target) and |value - REF| <= TOL for
every --regress (the regression check); nan fails either. Prints one line per check and a final line
`N passed, M failed`; exit status 0 only when all passed. The physics and the reason for
each tolerance are in the CMakeLists.txt that calls this script and in
cases/axisymmetric/README.md.
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.join(HERE, "..", "..", "..", "tools", "axisymmetric.py")


sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from summary_checks import check_output_of, run_case  # noqa: E402  (tests/regression/)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("sphjet")
    ap.add_argument("case")
    ap.add_argument("out")
    ap.add_argument("--set", action="append", default=[], dest="sets")
    ap.add_argument("--analyse", required=True)
    ap.add_argument("--arg", action="append", default=[], dest="args")
    ap.add_argument("--expect", action="append", default=[], help="KEY:LO:HI (validation target)")
    ap.add_argument("--regress", action="append", default=[],
                    help="KEY:REF:TOL (regression: |value - REF| <= TOL)")
    ap.add_argument("--show", action="append", default=[])
    a = ap.parse_args()

    if not run_case(a.sphjet, a.case, a.out, a.sets, len(a.expect) + len(a.regress)):
        return 1
    # the analysis needs numpy and h5py: Debian's interpreter has them (README), the one that
    # runs this script may not
    py = os.environ.get("SPHJET_ANALYSIS_PYTHON",
                        "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable)
    return check_output_of([py, TOOL, a.analyse, a.out] + a.args, a.expect, a.show, a.regress)

if __name__ == "__main__":
    sys.exit(main())
