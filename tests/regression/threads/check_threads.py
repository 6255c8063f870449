#!/usr/bin/env python3
"""The same run on one thread and on two gives the same bits.

The core's pair traversal gives every particle its contributions in a fixed order, and the
step size's scan over the particles is merged from the threads' shares in an order-free way
(fortran_core/integrate/time_step.f90), so the results do not depend on the thread count:
h5diff with no tolerance on the /particles group of the last snapshot. Two cases: a dam
break (the one parallel region per step of planar runs without surface tension, variable
step, list builds) and the Laplace disc (surface tension: the CSF passes, their own regions).

usage: check_threads.py SPHJET SOURCE_DIR WORK_DIR
"""
import os
import shutil
import subprocess
import sys

CASES = [
    ("dambreak", os.path.join("cases", "quickstart", "dambreak.toml"), "0.12",
     ["--set", "resolution.dx=0.025", "--set", "resolution.dz=0.025",
      "--set", "output.format=\"hdf5\"", "--set", "time.out=0.04"]),
    ("laplace_disc", os.path.join("cases", "laplace_disc", "laplace_disc.toml"), "0.02",
     ["--set", "output.format=\"hdf5\"", "--set", "time.out=0.01"]),
]


def main():
    sphjet, src, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    failures = 0
    for name, case, tmax, sets in CASES:
        outs = {}
        for threads in (1, 2):
            out = os.path.join(work, f"{name}_j{threads}")
            subprocess.run([sphjet, "run", os.path.join(src, case), "--tmax", tmax, "-q",
                            "-j", str(threads), "--out", out] + sets, check=True)
            outs[threads] = out
        snaps = sorted(f for f in os.listdir(outs[1]) if f.startswith("snap_"))
        same_list = snaps == sorted(f for f in os.listdir(outs[2]) if f.startswith("snap_"))
        last = snaps[-1]
        r = subprocess.run(["h5diff", "-q", os.path.join(outs[1], last),
                            os.path.join(outs[2], last), "/particles", "/particles"],
                           capture_output=True, text=True)
        ok = same_list and r.returncode == 0 and len(snaps) > 1
        print(f"{name}: {len(snaps)} snapshots; h5diff /particles of {last}, 1 against 2 "
              f"threads: exit {r.returncode} {r.stdout.strip()[:300]}-> "
              f"{'ok' if ok else 'FAIL'}")
        failures += 0 if ok else 1
    print(f"{len(CASES) - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
