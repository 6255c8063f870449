#!/usr/bin/env python3
"""Regression test of nozzle.refill (cases/CASE_FORMAT.md) on a round jet
(cases/round_jet/round_jet.toml, d0/dx = 10, u0 = 0.78 m/s, unforced; about 15 s in all).

The nozzle is 3 d0 long and would run dry at 3 d0 / u0 = 4.6 ms; the box ends 6 d0 below the
orifice, so its far end is the jet's sink from about 9 ms on. The run goes to 24 ms.

Checks, each with its reason:
  1. The run reaches its end: run.log has no "ran dry" line and says done at 24 ms.
  2. The orifice speed: every jet.csv sample once the jet is out by d0 has u_flux within 2% of
     u0 (the project's bound for the orifice speed, as the jet tests: only the fluid's
     compressibility just past the orifice moves it). A row entering late or twice would
     show as a flux step of 1/30 of u0 (one row in 3 d0).
  3. The plug in the last snapshot: the active fluid upstream of the orifice within the driven
     strip stands in rows exactly one spacing apart (each gap within 1e-9 of dz: new rows are
     copies of the back row shifted by dz), 5 rings a row (d0 / 2 / dx), and its back row
     within one spacing of where the case built it, s = -(30 - 1/2) dz. The snapshot is written
     before the step's refill (cpp_driver/core/simulation.cpp, step_once), so in a step that
     completes a spacing the back row stands up to that step's plug travel past -28.5 dz:
     u0 dt = 0.015 dz at this run's mean step (2.35e-6 s); STEP_TRAVEL = 0.05 dz allows a step
     three times as long.
  4. The cost stays flat: the active particles of the last two snapshots (the jet through the
     box) differ by less than 10%, while the arrays hold more particles than the box does
     (the left ones stay, inactive).
  5. Resume: stopped after 3000 steps (after rows have entered) and resumed, the final
     checkpoint's /particles are bitwise the uninterrupted run's.
  6. Without the key the same case stops on "the nozzle ran dry".
Usage: check_refill.py SPHJET SOURCE_DIR WORK_DIR
"""
import csv
import os
import pathlib
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from summary_checks import h5_particles, resumed_particles, same_particles, sphjet_run, with_h5py  # noqa: E402  (tests/regression/)

D0, DX, U0 = 0.001194, 0.0001194, 0.7814
STEP_TRAVEL = 0.05  # [dz] the plug's travel in one step, bounded (check 3)
Z0 = 6 * D0
SETS = ["nozzle.disturbance=0", "nozzle.length_over_d0=3", f"nozzle.z0={Z0!r}",
        f"domain.lz={Z0 + 3.5 * D0!r}", "time.tmax=0.024", "time.out=0.002", "breakup.check_every=0.0002"]






def main():
    with_h5py()
    import numpy as np
    sphjet, src, work = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    case = src / "cases" / "round_jet" / "round_jet.toml"
    fails = []

    ref = work / "on"
    sphjet_run(sphjet, case, ref, SETS + ["nozzle.refill=true"])
    log = (ref / "run.log").read_text()
    done = [x for x in log.splitlines() if x.startswith("done:")]
    print(f"1. {done[:1]}; 'ran dry' in the log: {'ran dry' in log}")
    if "ran dry" in log or not done or "t = 0.024" not in done[0]:
        fails.append("the run's end")

    with open(ref / "jet.csv") as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    out = [r for r in rows if r["jet_tip_over_d0"] >= 1.0 or r["broken"] == 1]
    dev = max(abs(r["u_flux"] / U0 - 1) for r in out)
    print(f"2. {len(out)} samples out by d0, the last at {out[-1]['time']:.4f} s; largest |u_flux / u0 - 1| = "
          f"{dev:.4f} (must be < 0.02)")
    if not (dev < 0.02 and out[-1]["time"] > 0.023):
        fails.append("orifice speed")

    snaps = sorted(ref.glob("snap_*.h5"))
    p = h5_particles(snaps[-1])
    s = Z0 - p["z"]  # along the jet (down) from the orifice
    plug = (p["kind"] == 2) & (p["active"] == 1) & (s < 0) & (p["x"] <= 0.5 * D0 + 0.25 * DX)
    zs = np.unique(np.round(s[plug] / DX, 6))
    per_row = [int(np.sum(np.abs(s[plug] / DX - z) < 1e-3)) for z in zs]
    gaps = np.diff(np.sort(np.unique(s[plug])))
    gaps = gaps[gaps > 0.5 * DX]
    back = s[plug].min() / DX
    print(f"3. plug rows: {len(zs)}, rings a row {sorted(set(per_row))} (must be [5]), gaps / dz "
          f"{gaps.min() / DX:.12f}-{gaps.max() / DX:.12f} (must be 1 within 1e-9), back row at s = {back:.4f} dz "
          f"(must be in [-29.5, -28.5 + {STEP_TRAVEL:g}))")
    if not (set(per_row) == {5} and np.all(np.abs(gaps / DX - 1) < 1e-9) and -29.5 - 1e-9 <= back < -28.5 + STEP_TRAVEL):
        fails.append("plug rows")

    a1 = int(h5_particles(snaps[-2])["active"].sum())
    a2 = int(p["active"].sum())
    print(f"4. active particles at the last two snapshots: {a1}, {a2}; arrays hold {len(p['active'])}")
    if not (abs(a2 - a1) < 0.1 * a1 and len(p["active"]) > 1.5 * a2):
        fails.append("flat cost")

    same = same_particles(h5_particles(ref / "checkpoint.h5"),
                          resumed_particles(sphjet, case, work / "resumed", SETS + ["nozzle.refill=true"], 3000))
    print(f"5. stopped after step 3000 and resumed: final /particles bitwise equal: {same}")
    if not same:
        fails.append("resume")

    off = work / "off"
    sphjet_run(sphjet, case, off, SETS, check=False)
    dry = "ran dry" in (off / "run.log").read_text()
    print(f"6. without the key: 'ran dry' in the log: {dry}")
    if not dry:
        fails.append("key off")
    if fails:
        sys.exit("FAIL: " + ", ".join(fails))
    print("PASS")


if __name__ == "__main__":
    main()
