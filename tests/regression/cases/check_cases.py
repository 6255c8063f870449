#!/usr/bin/env python3
"""Every case file committed under cases/ starts, and each legacy/modern pair is one case.

For every cases/**/*.txt (legacy SPHysics case file) and cases/**/*.toml (modern case):
`sphjet run FILE --max-steps N --format legacy -j 1` must succeed, so a case file that a change
of a reader no longer accepts fails here, not in a user's hands.
For every STEM.txt with a STEM.toml beside it (the .toml written by `sphjet convert`), the two
runs must end with byte-identical EPART files (x z u w rho p m of every particle after N steps):
the modern file says exactly what the legacy one says. Byte-identical is the tolerance because
both files become the same parameters and particles before the first step; any difference is a
conversion or reader defect, not round-off.

usage: check_cases.py SPHJET CASES_DIR WORK_DIR [--steps N]
"""
import argparse
import filecmp
import os
import shutil
import subprocess
import sys


def run(sphjet, case, out, steps):
    shutil.rmtree(out, ignore_errors=True)
    p = subprocess.run([sphjet, "run", case, "--out", out, "--max-steps", str(steps), "--format", "legacy",
                        "-j", "1", "-q"], capture_output=True, text=True)
    if p.returncode != 0:
        print(f"FAIL {case}: sphjet run exited {p.returncode}\n{p.stderr.strip()}")
        return False
    if not os.path.isfile(os.path.join(out, "EPART")):
        print(f"FAIL {case}: no EPART written in {out}")
        return False
    return True


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("sphjet")
    ap.add_argument("cases")
    ap.add_argument("work")
    ap.add_argument("--steps", type=int, default=10)
    a = ap.parse_args()

    files = []
    for root, _, names in os.walk(a.cases):
        files += [os.path.join(root, n) for n in names if n.endswith((".txt", ".toml"))]
    files.sort()
    if not files:
        print(f"FAIL: no case files under {a.cases}")
        return 1
    ok, started = True, {}
    for f in files:
        out = os.path.join(a.work, os.path.relpath(f, a.cases).replace(os.sep, "__"))
        good = run(a.sphjet, f, out, a.steps)
        ok = ok and good
        if good:
            started[f] = out
            print(f"ok   {os.path.relpath(f, a.cases)}: {a.steps} steps")
    pairs = 0
    for f in files:
        if not f.endswith(".txt"):
            continue
        twin = f[:-4] + ".toml"
        if twin not in started or f not in started:
            continue
        pairs += 1
        same = filecmp.cmp(os.path.join(started[f], "EPART"), os.path.join(started[twin], "EPART"), shallow=False)
        ok = ok and same
        print(f"{'ok  ' if same else 'FAIL'} {os.path.relpath(f, a.cases)} and its .toml: EPART after "
              f"{a.steps} steps {'identical' if same else 'DIFFERS'}")
    print(f"{len(files)} case files, {pairs} legacy/modern pairs")
    if pairs == 0:
        print("FAIL: no legacy/modern pair found (expected e.g. cases/dambreak/dambreak_a25.txt and .toml)")
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
