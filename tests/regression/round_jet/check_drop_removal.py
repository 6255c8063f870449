#!/usr/bin/env python3
"""Regression test of [breakup] remove_drops_below_h (cases/CASE_FORMAT.md) on a round jet
(cases/round_jet/round_jet.toml, d0/dx = 10, the first 2 ms; a few seconds a run).

A real satellite drop takes a 20-minute run to form, so the drops are put there at the
start: two spheres of fluid on the axis downstream of the orifice ([[fluid.disc]] with
xc = 0), a small one (radius 1.5 dx: d_eq about 1.5 h) and a larger one (radius 3 dx: d_eq
about 3 h). Both are clusters apart from the jet, i.e. drops of the jet monitor. With
remove_drops_below_h = 2 (d_eq < 2 h: a radius below h) the small one must go at the first
check and the larger one must stay.

Checks, each with its reason:
  1. removed_drops.csv has one row, the small sphere's: d_eq below 2 h, its particle count
     that of the drop drops.csv lists at that check, its centroid at the sphere's z.
  2. run.log has the removal line (step, particles) and the run's count of removed drops.
  3. In the last snapshot the small sphere's particles are inactive (active = 0, velocity 0)
     and every other fluid particle is active: the larger sphere stays, nothing "left the
     domain".
  4. With the key off (the default) nothing is removed and there is no removed_drops.csv.
  5. Resume: the run stopped (--max-steps) right at the removal's step (its checkpoint has
     the pairs to list again), one step before it and 200 steps after it, and resumed to the
     end, gives the uninterrupted run's final checkpoint /particles
     bitwise and the same removed_drops.csv, drops.csv and jet.csv: the removal depends only on
     the state at the check, which the checkpoint holds. One exception, older than the
     removal and independent of it: the removal is at the first check, and a run resumed
     before its first check takes that check's flux (and u_flux) from the resume, not from
     t = 0 (the checkpoint does not hold the volume out at t = 0), so those two numbers of
     jet.csv's first row are left out of the comparison for the stop one step before.
  6. The same resume with numerics.bulk_viscosity = 0.5, stopped after 300 steps: bitwise the
     uninterrupted run's final /particles (the bulk viscosity uses the density rates of the
     step before, which the checkpoint keeps as drho_dt), and not bitwise the run without it
     (the key acts).
Usage: check_drop_removal.py SPHJET SOURCE_DIR WORK_DIR
"""
import csv
import os
import pathlib
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from summary_checks import h5_particles, resumed_particles, same_particles, sphjet_run, with_h5py  # noqa: E402  (tests/regression/)

D0, DX = 0.001194, 0.0001194
H = 2.0 * DX
Z_SMALL, R_SMALL = 0.025, 1.5 * DX
Z_LARGE, R_LARGE = 0.035, 3.0 * DX
SETS = ["nozzle.disturbance=0", "nozzle.length_over_d0=6", "time.tmax=0.002", "time.out=0.001",
        "breakup.check_every=0.0001", "output.format=\"hdf5\""]




def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def round_jet_with_spheres(src, work, name, spheres):
    """work (made empty) / name: cases/round_jet/round_jet.toml with a sphere of fluid on the
    axis ([[fluid.disc]] with xc = 0) for each (zc, radius) of spheres -> its path."""
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    case = work / name
    text = (src / "cases" / "round_jet" / "round_jet.toml").read_text()
    for zc, r in spheres:
        text += f"\n[[fluid.disc]]\nxc = 0.0\nzc = {zc!r}\nradius = {r!r}\n"
    case.write_text(text)
    return case


def same_tables(a, b, first_flux):
    """removed_drops.csv, drops.csv and jet.csv equal byte for byte; with first_flux=False
    jet.csv's first data row without its flux and u_flux (columns 3 and 4)."""
    for f in ("removed_drops.csv", "drops.csv", "jet.csv"):
        x, y = (a / f).read_text().splitlines(), (b / f).read_text().splitlines()
        if f == "jet.csv" and not first_flux and len(x) > 1 and len(y) > 1:
            x[1], y[1] = ([v for i, v in enumerate(r.split(",")) if i not in (3, 4)] for r in (x[1], y[1]))
        if x != y:
            return False
    return True




def main():
    with_h5py()
    import numpy as np
    sphjet, src, work = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    case = round_jet_with_spheres(src, work, "round_jet_drops.toml", ((Z_SMALL, R_SMALL), (Z_LARGE, R_LARGE)))
    fails = []

    ref = work / "on"
    sphjet_run(sphjet, case, ref, SETS + ["breakup.remove_drops_below_h=2"])
    removed = rows(ref / "removed_drops.csv")
    print(f"1. removed_drops.csv: {len(removed)} row(s) (must be 1): {removed}")
    if len(removed) != 1:
        sys.exit("FAIL: removed drops " + str(len(removed)))
    r = removed[0]
    step = int(r["step"])
    listed = [d for d in rows(ref / "drops.csv") if int(d["step"]) == step and abs(float(d["zc"]) - Z_SMALL) < DX]
    d_eq_h = float(r["d_eq_over_d0"]) * D0 / H
    print(f"   step {step}, {r['particles']} particles, d_eq = {d_eq_h:.3f} h (must be < 2), zc = "
          f"{float(r['zc']):.5f} m (sphere at {Z_SMALL}); drops.csv lists {len(listed)} drop there")
    if not (d_eq_h < 2 and abs(float(r["zc"]) - Z_SMALL) < DX and len(listed) == 1
            and listed[0]["particles"] == r["particles"]):
        fails.append("removed_drops.csv row")
    log = (ref / "run.log").read_text()
    line = [x for x in log.splitlines() if x.startswith(f"step {step} ") and "removed a drop" in x]
    total = [x for x in log.splitlines() if "drop(s) removed" in x]
    print(f"2. log: {line[:1]} {total[-1:]}")
    if len(line) != 1 or f"{r['particles']} particles" not in line[0] or not total \
            or f"1 drop(s) removed ({r['particles']} particles" not in total[-1]:
        fails.append("log lines")

    snaps = sorted(ref.glob("snap_*.h5"))
    p = h5_particles(snaps[-1])
    fluid = p["kind"] == 2  # ParticleKind::Fluid
    gone = fluid & (p["active"] == 0)
    print(f"3. last snapshot {snaps[-1].name}: {int(gone.sum())} inactive fluid particles (must be "
          f"{r['particles']}), their largest speed {float(np.abs(np.r_[p['u'][gone], p['w'][gone], 0]).max()):.3g} "
          f"m/s, z {p['z'][gone].min() if gone.any() else 0:.5f}-{p['z'][gone].max() if gone.any() else 0:.5f} m")
    if int(gone.sum()) != int(r["particles"]) or np.any(p["u"][gone] != 0) or np.any(p["w"][gone] != 0) \
            or np.any(np.abs(p["z"][gone] - Z_SMALL) > R_SMALL + H):
        fails.append("inactive particles")
    large = fluid & (np.abs(p["z"] - Z_LARGE) < R_LARGE + H) & (p["x"] < R_LARGE + H)
    if not large.any() or np.any(p["active"][large] == 0):
        fails.append("the larger sphere was touched")

    off = work / "off"
    sphjet_run(sphjet, case, off, SETS)
    off_rows = [d for d in rows(off / "drops.csv") if abs(float(d["zc"]) - Z_SMALL) < DX]
    print(f"4. key off: removed_drops.csv exists: {(off / 'removed_drops.csv').exists()} (must not); the small "
          f"sphere listed at {len(off_rows)} checks")
    if (off / "removed_drops.csv").exists() or "removed a drop" in (off / "run.log").read_text() or not off_rows:
        fails.append("key off")

    ref_cp = h5_particles(ref / "checkpoint.h5")
    for stop in (step, step - 1, step + 200):
        d = work / f"resumed_{stop}"
        same = same_particles(resumed_particles(sphjet, case, d, SETS + ["breakup.remove_drops_below_h=2"], stop),
                              ref_cp)
        tables = same_tables(d, ref, first_flux=stop >= step)
        print(f"5. stopped after step {stop}, resumed: final /particles bitwise equal: {same}; "
              f"removed_drops.csv, drops.csv, jet.csv equal{'' if stop >= step else ' (but the first flux)'}: "
              f"{tables}")
        if not (same and tables):
            fails.append(f"resume at step {stop}")
    bulk = ["breakup.remove_drops_below_h=2", "numerics.bulk_viscosity=0.5"]
    straight = work / "bulk"
    sphjet_run(sphjet, case, straight, SETS + bulk)
    a = h5_particles(straight / "checkpoint.h5")
    same = same_particles(a, resumed_particles(sphjet, case, work / "bulk_resumed", SETS + bulk, 300))
    acts = a["rho"].tobytes() != ref_cp["rho"].tobytes()
    print(f"6. bulk viscosity 0.5, stopped after step 300, resumed: final /particles bitwise equal: {same}; "
          f"differs from the run without it: {acts}")
    if not (same and acts):
        fails.append("resume with the bulk viscosity")
    if fails:
        sys.exit("FAIL: " + ", ".join(fails))
    print("PASS")


if __name__ == "__main__":
    main()
