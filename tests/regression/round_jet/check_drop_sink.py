#!/usr/bin/env python3
"""Regression test of [breakup] remove_drops_beyond_d0 (cases/CASE_FORMAT.md), the sink that
follows the jet, on a round jet (cases/round_jet/round_jet.toml, d0/dx = 10, the first 2 ms; a
few seconds a run).

As in check_drop_removal.py, the drops are put there at the start: two spheres of fluid on the
axis downstream of the orifice (z0 = 0.05 m), a small one at z = 0.025 m (20.9 d0 from the
orifice, its nearest particle 20.8 d0) and a larger one at z = 0.035 m (12.6 d0, nearest 12.3
d0). At the first check (0.1 ms) the jet has just reached the orifice (L = 0.02 d0), and the 1.5 h
rule finds it broken, the spheres being apart from it.

Checks, each with its reason:
  1. M = 15: at the first check the far (small) sphere goes and the near one stays: removed_drops.csv
     has one row, rule beyond_d0, its particle count that of the drop drops.csv lists there, and
     jet.csv's L at that step puts the sphere's nearest point beyond L + 15 d0 and the near
     sphere's before it. No "removed a drop" log line (the sink's removals are counted at the
     end): the last lines count 1 drop removed beyond the jet's end.
  2. M = 5: both spheres go at the first check (12.3 d0 > L + 5 d0): the rule is the distance,
     not the size; in the last snapshot exactly their particles are inactive.
  3. M = 5 stopped right after the removal's step and resumed: the final /particles bitwise the
     uninterrupted run's, and the same removed_drops.csv: the sink reads only the state at the
     check.
  4. M = 15 with the rings pair and domain.renormalise_ring_continuity, whose reach (the jet's
     intact length at the latest check: the near sphere, beyond it, keeps the plain rate) the
     checkpoint keeps: the final checkpoint's run_state renormalise_reach is the last jet.csv
     sample's L, and the run stopped between two checks and resumed ends bitwise as the
     uninterrupted one (a resumed run that took the reach as 0, everywhere, would give the
     sphere's rings the scaled rate).
Usage: check_drop_sink.py SPHJET SOURCE_DIR WORK_DIR
"""
import os
import pathlib
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from summary_checks import h5_particles, resumed_particles, same_particles, sphjet_run, with_h5py  # noqa: E402  (tests/regression/)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_drop_removal import round_jet_with_spheres, rows  # noqa: E402  (the same directory)

D0, DX = 0.001194, 0.0001194
Z0 = 0.05
SPHERES = ((0.025, 1.5 * DX), (0.035, 3.0 * DX))   # (zc, radius): the far small one, the near larger one
SETS = ["nozzle.disturbance=0", "nozzle.length_over_d0=6", "time.tmax=0.002", "time.out=0.001",
        "breakup.check_every=0.0001", "output.format=\"hdf5\""]


def main():
    with_h5py()
    sphjet, src, work = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    case = round_jet_with_spheres(src, work, "round_jet_sink.toml", SPHERES)
    fails = []

    far = work / "m15"
    sphjet_run(sphjet, case, far, SETS + ["breakup.remove_drops_beyond_d0=15"])
    removed = rows(far / "removed_drops.csv")
    print(f"1. M = 15: removed_drops.csv {len(removed)} row(s) (must be 1): {removed}")
    if len(removed) != 1:
        sys.exit("FAIL: removed drops " + str(len(removed)))
    r = removed[0]
    step = int(r["step"])
    jet = [x for x in rows(far / "jet.csv") if int(x["step"]) == step]
    length = float(jet[0]["L_over_d0"]) if jet and jet[0]["broken"] == "1" else None
    listed = [d for d in rows(far / "drops.csv") if int(d["step"]) == step and abs(float(d["zc"]) - SPHERES[0][0]) < DX]
    nearest = [(Z0 - zc - rad) / D0 for zc, rad in SPHERES]
    print(f"   step {step}, rule {r['rule']}, {r['particles']} particles at zc = {float(r['zc']):.5f} m; L = {length} d0; "
          f"the spheres' nearest points {nearest[0]:.2f} and {nearest[1]:.2f} d0 (L + 15 = "
          f"{(length or 0) + 15:.2f})")
    if not (r["rule"] == "beyond_d0" and abs(float(r["zc"]) - SPHERES[0][0]) < DX and len(listed) == 1
            and listed[0]["particles"] == r["particles"] and length is not None
            and nearest[0] > length + 15 > nearest[1]):
        fails.append("M = 15: the far sphere only")
    log = (far / "run.log").read_text()
    total = [x for x in log.splitlines() if "drop(s) removed" in x]
    print(f"   log: {total[-1:]}")
    want = f"1 drop(s) removed ({r['particles']} particles): 1 wholly beyond the jet's end by 15 D0"
    if "removed a drop" in log or not total or not total[-1].endswith(want):
        fails.append("M = 15: log lines")

    near = work / "m5"
    sphjet_run(sphjet, case, near, SETS + ["breakup.remove_drops_beyond_d0=5"])
    removed5 = rows(near / "removed_drops.csv")
    steps5 = {int(x["step"]) for x in removed5}
    p = h5_particles(sorted(near.glob("snap_*.h5"))[-1])
    gone = (p["kind"] == 2) & (p["active"] == 0)
    n_both = sum(int(x["particles"]) for x in removed5)
    print(f"2. M = 5: {len(removed5)} row(s) (must be 2) at steps {sorted(steps5)}; {int(gone.sum())} inactive fluid "
          f"particles in the last snapshot (must be {n_both})")
    if len(removed5) != 2 or steps5 != {step} or int(gone.sum()) != n_both \
            or any(x["rule"] != "beyond_d0" for x in removed5):
        fails.append("M = 5: both spheres")

    ref_cp = h5_particles(near / "checkpoint.h5")
    d = work / "m5_resumed"
    same = same_particles(resumed_particles(sphjet, case, d, SETS + ["breakup.remove_drops_beyond_d0=5"], step),
                          ref_cp)
    tables = (d / "removed_drops.csv").read_text() == (near / "removed_drops.csv").read_text()
    print(f"3. M = 5 stopped after step {step}, resumed: final /particles bitwise equal: {same}; removed_drops.csv "
          f"equal: {tables}")
    if not (same and tables):
        fails.append("resume")

    keyed = SETS + ["breakup.remove_drops_beyond_d0=15", "domain.axis_pair=\"rings\"",
                    "domain.renormalise_ring_continuity=true"]
    whole = work / "key"
    sphjet_run(sphjet, case, whole, keyed)
    import h5py
    with h5py.File(whole / "checkpoint.h5", "r") as f:
        reach = float(f["run_state"].attrs["renormalise_reach"])
    last = rows(whole / "jet.csv")[-1]
    print(f"4. the key: checkpoint's reach {reach:.9g} m, the last sample's L {last['L']} m (broken {last['broken']})")
    if not (last["broken"] == "1" and reach > 0 and abs(reach - float(last["L"])) <= 1e-8 * reach):
        fails.append("the key's reach")
    d = work / "key_resumed"
    same = same_particles(resumed_particles(sphjet, case, d, keyed, step + 7), h5_particles(whole / "checkpoint.h5"))
    print(f"   stopped after step {step + 7}, resumed: final /particles bitwise equal: {same}")
    if not same:
        fails.append("the key's resume")
    if fails:
        sys.exit("FAIL: " + ", ".join(fails))
    print("PASS")


if __name__ == "__main__":
    main()
