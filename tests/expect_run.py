#!/usr/bin/env python3
"""Runs a command and checks both its exit status and its output.

CTest's PASS_REGULAR_EXPRESSION alone ignores the exit status: a run that printed the right
line and then crashed, or that should have failed and exited 0, would pass. This checks both.

usage: expect_run.py EXIT REGEX CMD [ARG...]
  EXIT   the exit status the command must return (0, or 1 for an error sphjet reports)
  REGEX  a Python regular expression that must match somewhere in stdout + stderr
Exits 0 when both hold, 1 otherwise, printing the command's output and what did not hold.
"""
import re
import subprocess
import sys


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    want, regex, cmd = int(sys.argv[1]), sys.argv[2], sys.argv[3:]
    print("$", " ".join(cmd), flush=True)
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(r.stdout[-6000:])
    fails = []
    if r.returncode != want:
        fails.append(f"exit status {r.returncode}, expected {want}")
    if not re.search(regex, r.stdout):
        fails.append(f"no line matches {regex!r}")
    for f in fails:
        print("FAIL:", f)
    if not fails:
        print(f"exit status {want} and output matching {regex!r}: ok")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
