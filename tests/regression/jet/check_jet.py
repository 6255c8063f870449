#!/usr/bin/env python3
"""Regression test of the jet (cases/jet/jet.toml: D0 = 0.01 m, u0 = 0.25 m/s, gravity along
the jet, D0/dx = 10; about 25 s on two cores).

Checks, each with its reason:
  1. The orifice speed: every sample once the jet is out by D0 has flux / D0 within 2% of
     u0 (the project's target for the orifice speed; the plug is rigid, so only the compressibility of the fluid just
     past the orifice moves it: 1.0% measured).
  2. The jet breaks, and where gravity says: a jet leaving at u0 and falling freely thins to
     w(s) = D0 u0 / sqrt(u0^2 + 2 g s); at the breakup length L it must be between 1.5 and 4
     particle spacings wide (a planar jet this coarse breaks where it is a few particles
     across; measured 2.6 dx). The jet's tip lags free fall (s = u0 t + g t^2 / 2): the
     capillary rim of a planar sheet retracts (Taylor-Culick) and the head gathers mass; it
     must stay between u0 t (no gravity) and free fall (measured 58% of free fall at 0.1 s).
  3. The detector agrees with itself: at the first breakup L <= the jet's tip, at least one
     drop; run.h5 /jet holds every row of jet.csv.
  4. A run stopped after its first breakup, between two checks (t = 0.1113 s), and resumed
     writes the same jet.csv, byte for byte, as the straight run: resume cuts the rows after
     the checkpoint, takes the flux baseline from the last kept row, the first breakup back
     for stop_after.
Usage: check_jet.py SPHJET SOURCE_DIR WORK_DIR
"""
import csv
import math
import os
import pathlib
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from summary_checks import run_or_exit, with_h5py  # noqa: E402  (tests/regression/)

G, D0, U0, DX = 9.81, 0.01, 0.25, 0.001


def rows(path):
    with open(path) as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def main():
    with_h5py(required=False)   # without h5py the run.h5 check is skipped below
    sphjet, src, work = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    case = src / "cases" / "jet" / "jet.toml"
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    straight, split = work / "straight", work / "split"
    run_or_exit([sphjet, "run", case, "--out", straight, "-j", "2", "-q"])
    run_or_exit([sphjet, "run", case, "--out", split, "-j", "2", "-q", "--tmax", "0.1113"])
    run_or_exit([sphjet, "run", "--resume", split, "-j", "2", "-q", "--tmax", "2.5"])
    failures = []

    samples = rows(straight / "jet.csv")
    out = [s for s in samples if s["jet_tip_over_d0"] >= 1.0]
    worst = max(abs(s["u_flux"] / U0 - 1.0) for s in out)
    print(f"orifice speed: {len(out)} samples, largest deviation from u0 {100 * worst:.2f}% (bound 2%)")
    if not out or worst > 0.02:
        failures.append(f"orifice speed off by {100 * worst:.2f}% (> 2%)")

    broken = [s for s in samples if s["broken"] == 1]
    if not broken:
        failures.append("the jet did not break")
    else:
        b = broken[0]
        L, t = b["L"], b["time"]
        width = D0 * U0 / math.sqrt(U0 ** 2 + 2 * G * L)
        last = [s for s in samples if s["broken"] == 0][-1]  # the last sample of the whole jet
        tip, tl = last["jet_tip_over_d0"] * D0, last["time"]
        tip_fall = U0 * tl + 0.5 * G * tl * tl
        print(f"first breakup: t = {t:.4f} s, L/D0 = {L / D0:.3f}; free-fall width there "
              f"{width / DX:.2f} dx (bounds 1.5-4); tip {tip:.4f} m vs free fall {tip_fall:.4f} m "
              f"at t = {tl:.4f} s ({100 * tip / tip_fall:.0f}% of it; bounds u0 t to free fall); drops {int(b['n_drops'])}")
        if not 1.5 * DX <= width <= 4 * DX:
            failures.append(f"breakup where the free-falling jet is {width / DX:.2f} dx wide (not in 1.5-4)")
        if not U0 * tl <= tip <= tip_fall:
            failures.append(f"jet tip {tip:.4f} m not between u0 t = {U0 * tl:.4f} m and free fall {tip_fall:.4f} m")
        if L > b["jet_tip_over_d0"] * D0 + 1e-12 or b["n_drops"] < 1:
            failures.append(f"detector inconsistent: L = {L}, tip = {b['jet_tip_over_d0'] * D0}, drops = {b['n_drops']}")

    try:
        import h5py
        with h5py.File(straight / "run.h5", "r") as f:
            n = f["jet/time"].shape[0]
        print(f"run.h5 /jet: {n} rows, jet.csv: {len(samples)}")
        if n != len(samples):
            failures.append(f"run.h5 /jet has {n} rows, jet.csv {len(samples)}")
    except ImportError:
        print("h5py not installed: run.h5 /jet not checked")

    a, b = (straight / "jet.csv").read_bytes(), (split / "jet.csv").read_bytes()
    print(f"resumed jet.csv {'identical' if a == b else 'DIFFERS'} ({len(a)} bytes)")
    if a != b:
        failures.append("jet.csv of the stopped and resumed run differs from the straight run's")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("PASS")


if __name__ == "__main__":
    main()
