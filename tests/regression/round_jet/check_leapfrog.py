#!/usr/bin/env python3
"""Regression test of numerics.integrator = "leapfrog" (cases/CASE_FORMAT.md,
fortran_core/integrate/leapfrog.f90) on the quick start's round jet: cases/round_jet/round_jet.toml
at d0/dx = 6, u0 = 1.2545 m/s, the round-jet study's numerics at c0 = 12 m/s and cfl 0.25 (the
rings pair, the surface fit, the bulk viscosity, a refilling nozzle, split axis rings), to 20 ms
(about 2600 steps; about 20 s in all).

The leapfrog carries the rates of each step's end to the next step's start; these checks are
what that must not break:
  1. Resume: stopped after 1800 steps (past the first breakup, with rows entered into the nozzle
     and rings split before it) and resumed, the final checkpoint's /particles and jet.csv are
     bitwise the uninterrupted run's (the checkpoint keeps those rates).
  2. Threads: the run on two threads ends bitwise as on one (the pair traversal's order is the
     threads' own, the integrator's particle loops are independent per particle).
  3. The jet: it breaks first at 5.0 d0 (4.4-5.6; the predictor-corrector's run of the same case
     breaks at 5.007 d0, and its first breakup is a property of the start, not of the step), and
     the orifice speed in jet.csv stays within 2% of u0 once the jet is out by d0.
Usage: check_leapfrog.py SPHJET SOURCE_DIR WORK_DIR
"""
import csv
import os
import pathlib
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from summary_checks import h5_particles, resumed_particles, same_particles, sphjet_run, with_h5py  # noqa: E402  (tests/regression/)

D0, U0 = 0.001194, 1.2545
SETS = ["resolution.dx=0.000199", f"nozzle.d0={D0!r}", f"nozzle.u0={U0!r}", "nozzle.length_over_d0=3",
        "nozzle.z0=0.03", "domain.lz=0.034", "domain.lx=0.002985", "breakup.check_every=0.0004364",
        "time.out=0.005", "time.tmax=0.02", "nozzle.refill=true", "nozzle.disturbance=0",
        "domain.axis_pair=rings", "surface_tension.curvature=surface_fit", "numerics.tensile_correction=on",
        "numerics.bulk_viscosity=0.5", "domain.split_axis_rings=true", "numerics.artificial_alpha=0.02",
        "numerics.artificial_reconstruction=true", "fluid.c0=12", "time.cfl=0.25",
        "breakup.remove_drops_beyond_d0=15", "numerics.integrator=leapfrog"]
STOP = 1800
FIRST_BREAKUP = (4.4, 5.6)   # d0
FLUX_TOL = 0.02


def main():
    with_h5py()
    sphjet, src, work = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    case = src / "cases" / "round_jet" / "round_jet.toml"
    fails = []

    ref = work / "whole"
    sphjet_run(sphjet, case, ref, SETS)
    whole = h5_particles(ref / "checkpoint.h5")
    resumed = resumed_particles(sphjet, case, work / "resumed", SETS, STOP)
    same_jet = (ref / "jet.csv").read_bytes() == (work / "resumed" / "jet.csv").read_bytes()
    print(f"1. stopped after {STOP} steps and resumed: particles bitwise {same_particles(whole, resumed)}, "
          f"jet.csv bitwise {same_jet}")
    if not (same_particles(whole, resumed) and same_jet):
        fails.append("resume")

    two = work / "two_threads"
    cmd = [str(sphjet), "run", str(case), "--out", str(two), "-j", "2", "-q"]
    for s in SETS:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True)
    same = same_particles(whole, h5_particles(two / "checkpoint.h5"))
    print(f"2. two threads against one: bitwise {same}")
    if not same:
        fails.append("threads")

    log = (ref / "run.log").read_text()
    m = re.search(r"jet broken at t = \S+ s \(step \d+\): L = \S+ m, L/D0 = (\S+);", log)
    first = float(m.group(1)) if m else None
    with open(ref / "jet.csv") as f:
        rows = [r for r in csv.DictReader(f) if float(r["time"]) * U0 > D0]
    worst = max(abs(float(r["u_flux"]) / U0 - 1.0) for r in rows) if rows else None
    print(f"3. first breakup L/d0 = {first} (expected {FIRST_BREAKUP}); orifice speed within "
          f"{worst:.3%} of u0 over {len(rows)} samples" if worst is not None else "3. no jet.csv samples")
    if first is None or not FIRST_BREAKUP[0] <= first <= FIRST_BREAKUP[1]:
        fails.append("first breakup")
    if worst is None or worst > FLUX_TOL:
        fails.append("orifice speed")

    if fails:
        sys.exit("FAIL: " + ", ".join(fails))
    print("PASS")


if __name__ == "__main__":
    main()
