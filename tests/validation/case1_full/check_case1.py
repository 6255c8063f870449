#!/usr/bin/env python3
"""Full legacy Case1 (dry-bed dam break, 4 m box, Wendland, MLS, dynamic boundaries) to 1.0 s
against legacy SPHysics 2D v2.2 (../shared/legacy/case1, PART files every 0.1 s).

Checks: the surge front (max x of fluid) against legacy at every 0.1 s before the front hits
the right wall (legacy front < 3.99 m, i.e. up to 0.7 s), and reports the particles that leave
the domain (legacy leaks one at about 0.75 s).

A parity (regression) check: legacy is the code sphjet reproduces; the dam break's physics is
judged against Martin & Moyce by the dambreak tests. Measured at 963bb70 (this script, two
threads; results are bitwise across thread counts): relative differences 4.6e-7, 2.2e-6,
1.2e-7, 1.2e-6, 1.0e-6, 3.5e-6, 9.9e-6 at 0.1 ... 0.7 s, growing from legacy's
single-precision round-off. Tolerance REL_TOL = 1e-4, ten times the largest.

usage: check_case1.py SPHJET WORK_DIR SHARED_DIR
"""
import os
import re
import subprocess
import sys

SKIP = 77  # CTest's SKIP_RETURN_CODE: reported as skipped, not passed
REL_TOL = 1e-4  # ten times the largest measured relative difference (docstring)


def main():
    sphjet, work, shared = sys.argv[1:4]
    legacy = os.path.join(shared, "legacy", "case1")
    if not os.path.isdir(legacy):
        print(f"SKIP: {legacy} not found (the legacy reference runs live in ../shared)")
        return SKIP
    subprocess.run([sphjet, "run", os.path.join(legacy, "Case1.txt"), "--out", work, "--force",
                    "--tmax", "1.0", "--legacy-clock", "--format", "legacy", "-q"], check=True)
    out = subprocess.run([sphjet, "compare", legacy, work], check=True, capture_output=True,
                         text=True).stdout
    print(out)
    ok = True
    checked = 0
    for line in out.splitlines():
        f = line.split()
        if len(f) != 14 or not re.match(r"^\d+$", f[0]):
            continue
        t_leg, front_leg, rel = float(f[3]), float(f[11]), float(f[13])
        if front_leg < 3.99:
            checked += 1
            good = rel < REL_TOL
            ok = ok and good
            print(f"t = {t_leg:.3f} s: front legacy {front_leg:.4f} m, relative difference "
                  f"{rel:.2e} {'ok' if good else f'FAIL (> {REL_TOL:g})'}")
    ok = ok and checked >= 7
    log = open(os.path.join(work, "run.log")).read()
    for m in re.finditer(r"step (\d+) t = ([0-9.e-]+) s: (\d+) particle\(s\) left the domain.*", log):
        print("sphjet:", m.group(0))
    print("1 passed, 0 failed" if ok else "0 passed, 1 failed")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
