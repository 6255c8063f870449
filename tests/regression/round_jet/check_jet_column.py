#!/usr/bin/env python3
"""tools/jet_column.py: the capillary growth of the round jets' own numerics, a periodic column
at rest at k a = 0.7 against Weber's rate.

The numerics are those of the falling study from the tube's relaxed state, taken from
tools/round_jet_study.py's plan for its 0.78 m/s run (`--quiet-jets --gravity --column 1
--step-cap 0.6 --landed --bound-xsph --relaxed-exit`), so that the check follows the study's
flags rather than a copy of them. Checks, each with its reason:
- the measure: at the start the rows' surface radii have the wave of the outer row's radius
  times eps, (1 - dx / (2a)) eps a (the row sits half a spacing inside a), within 1e-3 of it
  (measured 5e-7 off it: the build's rows, read as the slices' largest radius);
- at each resolution the wave grows as one exponential over the fit's range: the fit's rms
  residual in ln A below jet_column.ONE_EXPONENTIAL (measured 0.0014 at d0/dx 10), else the
  rate is no growth rate;
- d0/dx = 10 (the study's resolution): the growth within 8% of Weber's. Measured +5.5%;
  cases/round_jet/README.md ("The jets' own capillary growth") states the study's lengths with
  this resolution error, and the bound holds it there;
- d0/dx = 16: within 3% of Weber's (measured +2.1%; +0.9% at d0/dx 20, too long for the
  default set), and nearer to it than at d0/dx 10: the growth converges on Weber's as the rows
  get finer;
- --speed-ratio R builds the lattice of a jet that has sped up R times (no run, the case text
  only): at R = 1.5 the radius and the spacing across are R^-1/2 of R = 1's, the spacing along
  the axis R times, h the same, so each ring keeps the volume r dr dz of its nozzle's ring
  (to 1e-12, rounding); at R = 1 the text is the one without the option, byte for byte;
- --rows reads each row's curvature against the column's geometric one (row_curvatures, no
  run: a snapshot written here, five rows under r = a + A cos(kz), A = 1e-3 a, ka 0.49, each
  row j given the curvature -1/a + c_j A (1 - (ka)^2)/a^2 cos(kz) with c_j = 1, 0.5, -2, 3, 0
  and the fifth row none): the means -1 and the waves c_j to 1e-9 (sums of a sampled cosine
  over whole periods), the rows down to the fourth, in every slice;
- surface_tension.fit_points_min on the stretched lattice: the d0/dx 16 column (eight rings) at
  R = 1.35, ka 0.49, from 1e-4 a, fitted over 1e-3-1e-2 a, with --rows. With the key's default
  (3) a fifth row under the surface, at the edge of the kernel's reach, fits a parabola through
  three points of the outer row and the rings' mean bends the rows the wrong way: the deepest
  row's wave negative (measured rows 0-4 +1.09, +0.40, -2.18, -8.61, -21.3; growth 0.617 of
  Weber's). With fit_points_min = 4 every row's wave is positive (measured +1.13 ... +0.72) and
  the growth at least 0.8 of Weber's (measured 0.873; the ten-ring column on this lattice 0.881
  without the key): the bound is the fix, not the remaining deficit, which is unexplained;
- --h-over-dx H writes h = H d0 / N and leaves the step as it was (case text only);
- the stretched lattice of the slow falling jets: the d0/dx 10 column (five rings) at R = 1.8,
  ka 0.49, seeded at 1e-9 a and fitted over 1e-7-1e-4 a. With the study's h = 2 dx, 1.11 axial
  spacings, the wave grows faster than Weber's by more than half (measured 2.26); with
  --h-over-dx 2.5 (1.39 axial spacings) it grows as one exponential within 15% of Weber's
  (measured 1.087; 1.020 at 2.4 dx, 0.889 at 2.68 dx, but 1.49 at 2.28 dx, not one exponential).
  The first bound states the limit the README reports, the second that a wider kernel lifts it
  at this stretch (not at every one: at R 1.5 and 2.5 dx the wave hardly grows). The cubic
  spline at the study's h (numerics.kernel) grows it as one exponential within 15% of Weber's
  too (measured 0.980; 0.96-1.16 from R 1 to 2, "The cubic spline on a stretched lattice"): the
  Wendland kernel's limit there is the kernel's, not the lattice's;
- the cubic spline's rows pair at d0/dx 16: the eight-ring column at rest (R = 1), ka 0.49,
  seeded at 1e-9 a and fitted over 1e-8-1e-6 a, grows at twice Weber's rate with the spline's
  own gradient (measured 1.975; 1.99 over 1e-7-1e-4 a: its rows pair) and within 6% of it, as
  one exponential, with Thomas & Couchman's gradient (numerics.kernel = "cubic_spline_tc", which
  repels a pair inside q = 2/3 as hard as at 2/3; measured 0.959, fit_rms 0.0012): the bounds
  state the pairing and its cure ("The cubic spline without pairing");
- bad input: a planar case is refused naming domain.geometry; --ka 1.2 (a stable wave),
  --d0-over-dx 15 (7.5 rings across the radius) and --speed-ratio 0.5 (a jet that slows) are
  refused naming the option.

usage: check_jet_column.py SPHJET SOURCE_DIR WORK_DIR
"""
import contextlib
import io
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))
from summary_checks import summary, with_h5py  # noqa: E402  (tests/regression/)

STUDY = ["run", "--eps", "0", "--quiet-jets", "--gravity", "--column", "1", "--step-cap", "0.6",
         "--landed", "--bound-xsph", "--relaxed-exit", "--set-name", "mc", "--only", "mc_u0.7814"]
RUN = "mc_u0.7814"
EPS = 1e-5
BOUNDS = {10: 0.08, 16: 0.03}   # |growth / Weber - 1| at each d0/dx (the docstring's reasons)


def check_speed_ratio(jet_column, resolved):
    """The lattice of a jet sped up R times (the docstring's check) from the jet's case as sphjet
    wrote it (jet_column.resolve's) -> the failures."""
    import math
    import tomllib
    with open(resolved, "rb") as f:
        jet = tomllib.load(f)
    fails = []
    plain = jet_column.column_case(jet, "jet", 10, 0.7, EPS, 5e-3)
    one = jet_column.column_case(jet, "jet", 10, 0.7, EPS, 5e-3, 1.0)
    ok = plain[0] == one[0]
    print(f"{'ok' if ok else 'FAIL'}: --speed-ratio 1 writes the case without the option, byte for byte")
    if not ok:
        fails.append("--speed-ratio 1 changes the column's case")
    r = 1.5
    cols = [tomllib.loads(text) for text in (one[0], jet_column.column_case(jet, "jet", 10, 0.7, EPS, 5e-3, r)[0])]
    res = [c["resolution"] for c in cols]
    rad = [c["fluid"]["cylinder"][0]["radius"] for c in cols]
    got = {"radius": rad[1] / rad[0], "dx": res[1]["dx"] / res[0]["dx"], "dz": res[1]["dz"] / res[0]["dz"],
           "h": res[1]["h"] / res[0]["h"]}
    want = {"radius": r ** -0.5, "dx": r ** -0.5, "dz": r, "h": 1.0}
    ring = (rad[1] * res[1]["dx"] * res[1]["dz"]) / (rad[0] * res[0]["dx"] * res[0]["dz"])
    ok = all(abs(got[k] / want[k] - 1) <= 1e-12 for k in want) and abs(ring - 1) <= 1e-12
    print(f"{'ok' if ok else 'FAIL'}: --speed-ratio {r:g} against 1: " + ", ".join(f"{k} x {got[k]:.12g} (expected {want[k]:.12g})" for k in want)
          + f"; a ring's r dr dz x {ring:.12g} (expected 1)")
    if not ok:
        fails.append(f"--speed-ratio {r:g} builds {got}, ring volume x {ring:.12g}")
    ok = math.isclose(res[1]["dz"], res[0]["dx"] * r, rel_tol=1e-12)
    print(f"{'ok' if ok else 'FAIL'}: at R = {r:g} the rings are R spacings apart along the axis: dz {res[1]['dz']:.6g} m "
          f"against R dx = {res[0]['dx'] * r:.6g} m")
    if not ok:
        fails.append("dz is not R times the jet's spacing")
    wide = tomllib.loads(jet_column.column_case(jet, "jet", 10, 0.7, EPS, 5e-3, r, 2.32)[0])
    ok = (math.isclose(wide["resolution"]["h"], 2.32 * res[0]["dx"], rel_tol=1e-12)
          and wide["time"] == cols[1]["time"])
    print(f"{'ok' if ok else 'FAIL'}: --h-over-dx 2.32: h {wide['resolution']['h']:.6g} m against 2.32 dx = "
          f"{2.32 * res[0]['dx']:.6g} m, the step's keys as without it")
    if not ok:
        fails.append("--h-over-dx 2.32 does not write h = 2.32 dx with the step kept")
    return fails


def check_stretched_lattice(jet_column, sets, case, sphjet, work):
    """The five-ring column on the lattice of a jet sped up 1.8 times, at the study's h, at 2.5 dx
    and with the cubic spline (the docstring's check); sets: the study's d0/dx 10 run's
    overrides -> the failures."""
    fails = []
    for h_over_dx, kernel in ((None, None), (2.5, None), (None, "cubic_spline")):
        extra = ["--speed-ratio", "1.8", "--ka", "0.49", "--eps", "1e-9", "--fit-from", "1e-7", "--fit-to", "1e-4"]
        if h_over_dx is not None:
            extra += ["--h-over-dx", f"{h_over_dx:g}"]
        over = h_over_dx is None and kernel is None   # the study's: the limit stated
        fails += judged_column(jet_column, case, sphjet,
                               os.path.join(work, f"stretched_h{h_over_dx or 2:g}_{kernel or 'wendland'}"),
                               list(sets) + ([f"numerics.kernel={kernel}"] if kernel else []), extra,
                               f"R 1.8 at d0/dx 10, h {h_over_dx or 2:g} dx, {kernel or 'wendland'}",
                               (1.5, "the limit stated") if over else 0.15)
    return fails


def check_pairing(jet_column, sets, case, sphjet, work):
    """The d0/dx 16 column at rest with the cubic spline and with its Thomas-Couchman gradient
    (the docstring's check); sets: the study's d0/dx 16 run's overrides -> the failures."""
    fails = []
    for kernel in ("cubic_spline", "cubic_spline_tc"):
        fails += judged_column(jet_column, case, sphjet, os.path.join(work, f"n16_{kernel}"),
                               sets + [f"numerics.kernel={kernel}"],
                               ["--ka", "0.49", "--eps", "1e-9", "--fit-from", "1e-8", "--fit-to", "1e-6"],
                               f"d0/dx 16 at rest, {kernel}",
                               (1.5, "its rows pair") if kernel == "cubic_spline" else 0.06)
    return fails


def judged_column(jet_column, case, sphjet, out, sets, extra, label, expect):
    """One column (run_column) and its growth over Weber's against expect: (bound, reason), a
    growth above bound; or tol, one exponential within tol of Weber's -> the failures."""
    rc, text = run_column(jet_column, case, sphjet, out, sets, extra)
    if rc != 0:
        return [f"{label}: jet_column.py exited {rc}"]
    s = summary(text)
    ratio = float(s["growth_over_weber"])
    if isinstance(expect, tuple):
        ok, want = ratio > expect[0], f"above {expect[0]:g} ({expect[1]})"
    else:
        ok = abs(ratio - 1) <= expect and s["fit_rms"] <= jet_column.ONE_EXPONENTIAL
        want = f"within {expect:g} of 1, one exponential (fit_rms {s['fit_rms']:.3g})"
    print(f"{'ok' if ok else 'FAIL'}: {label}: growth / Weber {ratio:.4f}, expected {want}")
    return [] if ok else [f"{label}: growth / Weber {ratio:.4f}, expected {want}"]


def run_column(jet_column, case, sphjet, out, sets, extra=()):
    """jet_column.py on the case with the study's overrides sets and the options extra, its output
    echoed -> (exit status, output)."""
    argv = [case, "--sphjet", sphjet, "--out", out, *extra]
    for s in sets:
        argv += ["--set", s]
    text = io.StringIO()
    with contextlib.redirect_stdout(text):
        rc = jet_column.main(argv)
    print(text.getvalue(), end="")
    return rc, text.getvalue()


def check_fit_points(jet_column, sets, case, sphjet, work):
    """surface_tension.fit_points_min on the stretched eight-ring column (the docstring's check);
    sets: the study's d0/dx 16 run's overrides -> the failures."""
    import re
    fails = []
    for points in (3, 4):
        rc, text = run_column(jet_column, case, sphjet, os.path.join(work, f"fp{points}"),
                              sets + [f"surface_tension.fit_points_min={points}"],
                              ["--speed-ratio", "1.35", "--ka", "0.49", "--eps", "1e-4", "--fit-from", "1e-3",
                               "--fit-to", "1e-2", "--rows"])
        if rc != 0:
            fails.append(f"fit_points_min {points}: jet_column.py exited {rc}")
            continue
        ratio = float(summary(text)["growth_over_weber"])
        waves = [float(w) for w in re.findall(r"^\s*row \d+: .*wave ([-+][0-9.]+)", text, re.M)]
        if points == 3:
            ok = len(waves) >= 5 and waves[-1] < 0
            want = "the deepest row's wave negative"
        else:
            ok = len(waves) >= 5 and min(waves) > 0 and ratio >= 0.8
            want = "every row's wave positive and the growth at least 0.8 of Weber's"
        print(f"{'ok' if ok else 'FAIL'}: fit_points_min {points} at R 1.35: rows' waves "
              f"{', '.join(f'{w:+.3g}' for w in waves)}, growth / Weber {ratio:.4f}; expected {want}")
        if not ok:
            fails.append(f"fit_points_min {points}: waves {waves}, growth {ratio:.4f}; expected {want}")
    return fails


def check_row_curvatures(jet_column, work):
    """--rows' reading on a snapshot written here (the docstring's check) -> the failures."""
    import math
    import h5py
    import numpy as np
    run = os.path.join(work, "rows")
    os.makedirs(run, exist_ok=True)
    a, ka, amp, nb, n_rows = 1e-3, 0.49, 1e-6, 40, 5
    lam = 2 * math.pi * a / ka
    dz, k = lam / nb, ka / a
    c = [1.0, 0.5, -2.0, 3.0, 0.0]
    z = np.repeat((np.arange(nb) + 0.5) * dz, n_rows)
    j = np.tile(np.arange(n_rows), nb)
    wave = np.cos(k * z)
    x = (a - (j + 0.5) * a / n_rows) + amp * wave
    curv = np.where(j < 4, -1.0 / a + np.take(c, j) * amp * (1 - ka ** 2) / a ** 2 * wave, 0.0)
    with h5py.File(os.path.join(run, "snap_000000.h5"), "w") as h:
        g = h.create_group("particles")
        for name, v in (("x", x), ("z", z), ("curvature", curv), ("m", np.ones_like(x)),
                        ("rho", np.ones_like(x)), ("kind", np.full(len(x), 2))):
            g[name] = v
        h.attrs["time"] = 0.0
    got = jet_column.row_curvatures(run, a, dz, lam, 1e-4, 1e-2)
    fails = []
    ok = len(got) == 4 and all(abs(m + 1) <= 1e-9 and abs(w - c[r]) <= 1e-9 and share == 1.0
                               for r, share, m, w in got)
    print(f"{'ok' if ok else 'FAIL'}: --rows on a written snapshot: " + "; ".join(
        f"row {r} in {share:.0%}, mean {m:+.9f}, wave {w:+.9f} (expected {c[r]:+g})" for r, share, m, w in got))
    if not ok:
        fails.append(f"--rows read {got}, expected means -1 and waves {c[:4]}")
    return fails


def main():
    with_h5py()
    sphjet, src, work = sys.argv[1:4]
    sys.path.insert(0, os.path.join(src, "tools"))
    import jet_column
    import round_jet_study
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    case = os.path.join(src, "cases", "round_jet", "round_jet.toml")
    fails, errors = [], {}
    for n, bound in BOUNDS.items():
        args = round_jet_study.parse(STUDY + ["--d0-over-dx", str(n)])
        sets = [s for _set, name, run_sets, _info in round_jet_study.plan(args) if name == RUN for s in run_sets]
        if not sets:
            sys.exit(f"FAIL: the study's plan has no run {RUN}")
        if n == 16:
            fails += check_fit_points(jet_column, sets, case, sphjet, work)
            fails += check_pairing(jet_column, sets, case, sphjet, work)
        else:
            fails += check_stretched_lattice(jet_column, sets, case, sphjet, work)
        out = os.path.join(work, f"n{n}")
        rc, text = run_column(jet_column, case, sphjet, out, sets, ["--eps", f"{EPS:g}"])
        if rc != 0:
            fails.append(f"d0/dx {n}: jet_column.py exited {rc}")
            continue
        s = summary(text)
        ratio = float(s["growth_over_weber"])
        errors[n] = abs(ratio - 1)
        ok = s["fit_rms"] <= jet_column.ONE_EXPONENTIAL
        print(f"{'ok' if ok else 'FAIL'}: d0/dx {n}: the fit's rms residual in ln A {s['fit_rms']:.3g}, "
              f"expected at most {jet_column.ONE_EXPONENTIAL:g}")
        if not ok:
            fails.append(f"d0/dx {n}: not one exponential (fit_rms {s['fit_rms']:.3g})")
        ok = abs(ratio - 1) <= bound
        print(f"{'ok' if ok else 'FAIL'}: d0/dx {n}: growth / Weber = {ratio:.4f}, expected within {bound:g} of 1")
        if not ok:
            fails.append(f"d0/dx {n}: growth / Weber {ratio:.4f} not within {bound:g} of 1")
        if n == 10:
            import tomllib
            with open(os.path.join(out, "column.toml"), "rb") as f:
                col = tomllib.load(f)
            a, dx = col["fluid"]["cylinder"][0]["radius"], col["resolution"]["dx"]
            _t, amp = jet_column.column_amplitudes(os.path.join(out, "column"), a, dx,
                                                      col["fluid"]["cylinder"][0]["wavelength"])
            want = (1 - dx / (2 * a)) * EPS
            ok = abs(amp[0] / want - 1) <= 1e-3
            print(f"{'ok' if ok else 'FAIL'}: the start reads {amp[0]:.9g} a, expected {want:.9g} a within 1e-3")
            if not ok:
                fails.append(f"the start reads {amp[0]:.6g} a against {want:.6g}")
    fails += check_row_curvatures(jet_column, work)
    resolved = os.path.join(work, "n10", "jet", "case.toml")
    if os.path.isfile(resolved):
        fails += check_speed_ratio(jet_column, resolved)
    else:
        fails.append(f"{resolved}: not written (the d0/dx 10 column's run above failed); --speed-ratio not checked")
    if len(errors) == 2:
        ok = errors[16] < errors[10]
        print(f"{'ok' if ok else 'FAIL'}: |growth / Weber - 1| {errors[16]:.4f} at d0/dx 16 against "
              f"{errors[10]:.4f} at 10, expected smaller")
        if not ok:
            fails.append("the growth not nearer to Weber's at d0/dx 16 than at 10")
    tool = os.path.join(src, "tools", "jet_column.py")
    for extra, want in (([os.path.join(src, "cases", "jet", "jet.toml")], "domain.geometry"),
                        ([case, "--ka", "1.2"], "--ka 1.2"),
                        ([case, "--d0-over-dx", "15"], "--d0-over-dx"),
                        ([case, "--speed-ratio", "0.5"], "--speed-ratio"),
                        ([case, "--h-over-dx", "0.5"], "--h-over-dx")):
        r = subprocess.run([sys.executable, tool, *extra, "--sphjet", sphjet], capture_output=True, text=True)
        ok = r.returncode != 0 and want in r.stderr
        print(f"{'ok' if ok else 'FAIL'}: {' '.join(extra[1:]) or os.path.basename(extra[0])}: exit "
              f"{r.returncode}, message names {want!r}: {r.stderr.strip().splitlines()[-1] if r.stderr.strip() else ''}")
        if not ok:
            fails.append(f"{extra}: expected a refusal naming {want}")
    if fails:
        sys.exit("FAIL: " + "; ".join(fails))
    print("all checks passed")


if __name__ == "__main__":
    main()
