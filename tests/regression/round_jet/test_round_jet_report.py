#!/usr/bin/env python3
"""tools/round_jet_study.py on a fake study (synthetic jet.csv, drops.csv and run.log; no sphjet):
the breakup length is the mean of L over the window t >= 1.5 L_ref / U and needs every sample
there broken; the fits of L/d0 = C x (x = sqrt(We_d)(1 + 3 Oh_d)) are least squares through the
origin; the groups are the diameter ones; missing runs are listed; `run --dry-run` sizes a run
as its docstring says; `report --only --brief` prints the chosen run in lines (its theory line
checked on test_jet_noise.py's synthetic run, whose answer is known); `--own-window` takes the
window from a run's own length (own_window, on a synthetic jet that grows and then holds, and on
one that keeps growing), its clock from when the orifice went quiet (quiet_since, on synthetic
surfaces whose start-up fades, holds, or that drip short of 5 d0); `--column` sizes each run's
starting column from its L_ref; `--gravity` makes the runs fall and its report gives Weber's
growth along the falling jet; `--fixed-step` and `--step-cap` give every run the fixed or capped
step their docstring says, `--landed` the release on the orifice line, `--renormalise-margin`
the margin of the renormalised continuity (with --gravity only), `--relaxed-exit` the measured
jets' plugs at the tube's relaxed speed and diameter (relaxed_exit's root, as_tube's lengths).

The answers are known by construction: run mc_u0.7814 (L_ref = 67.52 d0, window from
t = 1.5 * 67.52 * 0.001194 / 0.7814 = 0.15476 s) has samples 60, 70 and 90 (before the window,
not counted; the 90 at 0.14 s would be in a window from 1.25 L_ref / U) and 64, 66, 68, 70 in
it: mean 67, std sqrt(5) = 2.236, halves (64, 66) and (68, 70): 65 and 69. Run mc_u1.0179 has
one intact sample of two in its window: no steady length. A window's samples intact short of the
box's end are skipped up to 5% of it; one intact to the box's end leaves no length. The fit
through the origin to two points (x1, y1), (x2, y2) is (x1 y1 + x2 y2) / (x1^2 + x2^2).

usage: test_round_jet_report.py   (exit 0 on success, 1 with a message on failure)
"""
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
TOOL = os.path.join(REPO, "tools", "round_jet_study.py")
PY = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
sys.path.insert(0, os.path.join(REPO, "tools"))
import round_jet_study as rjs  # noqa: E402

failures = []


def check(cond, msg):
    if not cond:
        failures.append(msg)


HEADER = ("time,step,volume_out,flux,u_flux,u_orifice,broken,L,L_over_d0,jet_tip_over_d0,n_drops,"
          "head_drop_d_over_d0,largest_drop_d_over_d0,n_satellites,neck_r_over_d0,neck_s_over_d0")


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def fake_run(d, samples):
    """samples: (time, step, broken, L/d0[, jet tip / d0 (default L/d0 + 2)])."""
    rows = [HEADER] + [f"{x[0]},{x[1]},0,0,0.78,0.78,{x[2]},{x[3] * 0.001194},{x[3]},"
                       f"{x[4] if len(x) > 4 else x[3] + 2},1,1.9,1.9,0,0.3,5" for x in samples]
    write(os.path.join(d, "jet.csv"), "\n".join(rows) + "\n")
    write(os.path.join(d, "run.log"),
          "sphjet 0.1.0 (abc) starting\n"
          "case: x | particles 9000 (boundary 0, fluid 9000) | h | kernel wendland | threads 2\n"
          "done: 1000 steps (1000 in all) to t = 0.25 s (SPHysics clock 0.25 s) in 100.00 s wall; "
          "9e+04 particle-steps/s; 8 outputs; 0 particles left the domain\n")


def main():
    with tempfile.TemporaryDirectory(prefix="round_jet_test_") as tmp:
        root = os.path.join(tmp, "root")
        sdir = os.path.join(root, "eps0.01_n10")
        d = os.path.join(sdir, "mc_u0.7814")
        fake_run(d, [(0.05, 10, 1, 60.0), (0.10, 20, 1, 70.0), (0.14, 25, 1, 90.0),
                     (0.16, 30, 1, 64.0), (0.18, 40, 1, 66.0), (0.20, 50, 1, 68.0),
                     (0.25, 60, 1, 70.0)])
        write(os.path.join(d, "drops.csv"),
              "time,step,drop,particles,volume,d_eq_over_d0,xc,zc,s_max_over_d0,satellite\n"
              "0.25,60,0,50,1e-9,1.8,0,0.01,80,0\n0.25,60,1,60,1e-9,2.0,0,0.01,75,0\n"
              "0.25,60,2,3,1e-11,0.4,0,0.01,72,1\n0.2,50,0,3,1e-11,5.0,0,0.01,72,0\n"
              "0.1,20,0,90,1e-9,9.0,0,0.01,70,0\n")   # before the window: not in the median
        # three particles leave the box, two before the window (from 0.1548 s) and one in it; a
        # part made again from an earlier checkpoint logs that one again
        left = ("step 9 t = 0.1 s: 2 particle(s) left the domain and were removed (2 in all); ids 5 6\n"
                "step 30 t = 0.17 s: 1 particle(s) left the domain and were removed (3 in all); ids 7\n")
        write(os.path.join(d, "run.log"),
              "sphjet 0.1.0 (abc) starting\n"
              "case: x | particles 9000 (boundary 0, fluid 9000) | h | kernel wendland | threads 2\n" + left
              + "sphjet 0.1.0 (abc) resuming\n" + left.split("\n")[1] + "\n"
              "done: 1000 steps (1000 in all) to t = 0.25 s (SPHysics clock 0.25 s) in 100.00 s wall; "
              "9e+04 particle-steps/s; 8 outputs; 3 particles left the domain; 0 drop(s) (0 particles) removed\n")
        fake_run(os.path.join(sdir, "mc_u1.0179"),
                 [(0.05, 10, 1, 80.0), (0.2, 20, 1, 90.0), (0.25, 30, 0, 0.0)])
        # mc_u1.5699 (L_ref 94.96 d0, box 1.6 L_ref + 10 d0 = 161.9 d0, window from 0.10834 s): one
        # sample of 21 intact short of the box's end (a drop touching the jet's end): skipped and
        # counted. mc_u1.2545 (box 164.4 d0, window from 0.1378 s): one of 21 intact to within
        # 1 d0 of the box's end: the jet is longer than the box, no length.
        fake_run(os.path.join(sdir, "mc_u1.5699"),
                 [(0.11 + 0.001 * i, 100 + i, 1, 100.0 + (i % 2)) for i in range(20)]
                 + [(0.2, 200, 0, 0.0, 80.0)])
        write(os.path.join(sdir, "mc_u1.5699", "drops.csv"),
              "time,step,drop,particles,volume,d_eq_over_d0,xc,zc,s_max_over_d0,satellite\n")
        fake_run(os.path.join(sdir, "mc_u1.2545"),
                 [(0.14 + 0.001 * i, 100 + i, 1, 90.0) for i in range(20)] + [(0.2, 200, 0, 0.0, 164.0)])
        out = os.path.join(tmp, "out")
        p = subprocess.run([PY, TOOL, "report", "--root", root, "--out", out, "--no-figures"],
                           capture_output=True, text=True)
        check(p.returncode == 0, f"report exit {p.returncode}: {p.stderr}")
        with open(os.path.join(out, "round_jets.csv")) as f:
            rows = {r["run"]: r for r in csv.DictReader(f)}
        r = rows.get("mc_u0.7814", {})
        check(r.get("L/d0 SPH (std)") == "67.00 (2.24)", f"mc_u0.7814 L: {r.get('L/d0 SPH (std)')}")
        check(r.get("L/d0 window halves") == "65.00 / 69.00", f"halves: {r.get('L/d0 window halves')}")
        check(r.get("err vs measured") == "-1%", f"error vs 67.52: {r.get('err vs measured')}")
        check(r.get("window samples") == "4", f"samples at t >= 0.155 s: {r.get('window samples')}")
        check(r.get("window from t [s] (its own L/U)") == "0.1548 (1.51)",
              f"the window's start, 1.5 L_ref / U = 1.51 of its own 67 d0 / U: {r}")
        check(r.get("main drop d/d0") == "1.90", f"main drops (1.8 + 2.0) / 2: {r.get('main drop d/d0')}")
        check(r.get("drops (satellites)") == "3 (1)", f"drops: {r.get('drops (satellites)')}")
        med = r.get("main drops d/d0 window median (drop-samples)")
        check(med == "2.00 (3)", f"window median of 1.8, 2.0 (step 60), 5.0 (step 50), not 9.0 (step 20): {med}")
        check(r.get("main drops d/d0 window mode") == "1.8",
              f"window mode of 1.8, 2.0, 5.0 in 0.1 d0 bins, a three-way tie: the smallest: {r}")
        check(rjs.drop_mode([1.88, 1.91, 2.38, 2.41, 2.39, 1.02]) == 2.4 and rjs.drop_mode([]) is None,
              "mode: the 2.4 bin holds three")
        check(r.get("first breakup t [s], L/d0") == "0.0500, 60.00", r.get("first breakup t [s], L/d0"))
        check(r.get("particles left the box (in the window)") == "3 (1)",
              f"left the box: {r.get('particles left the box (in the window)')}")
        we_d = 1000 * 0.7814 ** 2 * 0.001194 / 0.072
        check(r.get("We_d") == f"{we_d:.3g}", f"We_d {r.get('We_d')} vs {we_d:.3g}")
        r2 = rows.get("mc_u1.0179", {})
        check(r2.get("L/d0 SPH (std)") == "- (-)", f"an intact sample in the window: {r2.get('L/d0 SPH (std)')}")
        check(r2.get("status") == "finished, no steady breakup", r2.get("status"))
        check(r2.get("L/d0 window halves") == "-", f"no halves without a length: {r2.get('L/d0 window halves')}")
        check(rows.get("mc_u0.3441", {}).get("status") == "missing", "missing run")
        r3 = rows.get("mc_u1.5699", {})
        check(r3.get("L/d0 SPH (std)") == "100.50 (0.50)", f"20 broken samples of 100, 101: {r3.get('L/d0 SPH (std)')}")
        check(r3.get("window samples") == "21 (1 intact)", f"the intact one counted: {r3.get('window samples')}")
        r4 = rows.get("mc_u1.2545", {})
        check(r4.get("L/d0 SPH (std)") == "- (-)", f"intact to the box's end: {r4.get('L/d0 SPH (std)')}")
        # C = L / (d0 x), measured and SPH; the regime without gravity (We_d against 2 pi)
        x1 = rjs.groups(0.7814, 0.001194)["x"]
        check(r.get("C = L/(d0 x) measured / SPH") == f"{67.52 / x1:.1f} / {67.0 / x1:.1f}",
              f"C columns: {r.get('C = L/(d0 x) measured / SPH')}")
        check(r.get("instability without gravity") == "convective", "We_d 10.1: convective")
        check(rows.get("mc_u0.3441", {}).get("instability without gravity") == "absolute", "We_d 1.96: absolute")
        with open(os.path.join(out, "round_jets.md")) as f:
            md = f.read()
        x3 = rjs.groups(1.5699, 0.001194)["x"]
        c_two = (x1 * 67.0 + x3 * 100.5) / (x1 * x1 + x3 * x3)
        check(f"| SPH (2 runs) | {c_two:.2f} |" in md, f"C through the origin of two SPH points: {md[-600:]}")
        check("left the box (through its side or its end; the drops the sink removed are not counted): 3 in 1 of "
              "the 4 runs made" in md and "1 of them within the windows of 1 of the runs with a length" in md,
              f"the box's losses: {md[-900:]}")
        check("mc_u1.5699: 1 of 21 window samples intact short of the box's end (t = 0.2 s): skipped" in md,
              f"the skipped sample's note: {md[-900:]}")
        check("mc_u1.2545: 1 of 21 samples after t = 0.1378 s intact to the box's end" in md,
              f"the box's end note: {md[-900:]}")
        # --keep-rows: a study made on two machines. This machine holds mc_u1.5699 only; the report
        # in `out` keeps the earlier rows of the runs not here (mc_u0.7814's row as it was, its L in
        # the fits) and says which; a missing run stays missing. A report of another study is
        # refused rather than merged.
        root2 = os.path.join(tmp, "root2")
        shutil.copytree(os.path.join(sdir, "mc_u1.5699"), os.path.join(root2, "eps0.01_n10", "mc_u1.5699"))
        shutil.copytree(out, os.path.join(tmp, "out_before"))
        p = subprocess.run([PY, TOOL, "report", "--root", root2, "--out", out, "--no-figures", "--keep-rows"],
                           capture_output=True, text=True)
        check(p.returncode == 0, f"--keep-rows report exit {p.returncode}: {p.stderr}")
        with open(os.path.join(out, "round_jets.csv")) as f:
            kept = {r["run"]: r for r in csv.DictReader(f)}
        check(kept.get("mc_u0.7814") == r and kept.get("mc_u1.5699") == r3,
              f"--keep-rows: the kept row and the one read here as before: {kept.get('mc_u0.7814')}")
        check(kept.get("mc_u0.3441", {}).get("status") == "missing", "--keep-rows: a missing run stays missing")
        with open(os.path.join(out, "round_jets.md")) as f:
            md2 = f.read()
        check(f"| SPH (2 runs) | {c_two:.2f} |" in md2, f"--keep-rows: the kept length in the fit: {md2[-900:]}")
        check("(3; their runs are not in this study directory): mc_u0.7814, mc_u1.0179, mc_u1.2545." in md2
              and "mc_u1.2545: 1 of 21 samples after t = 0.1378 s intact to the box's end" in md2,
              f"--keep-rows: the kept rows named, their notes kept: {md2[-900:]}")
        other = os.path.join(tmp, "out_before")
        os.makedirs(os.path.join(root2, "eps0_n10"))
        p = subprocess.run([PY, TOOL, "report", "--root", root2, "--out", other, "--no-figures", "--keep-rows",
                            "--eps", "0"], capture_output=True, text=True)
        check(p.returncode != 0 and "expected a report of the study eps0_n10" in p.stderr
              and "found eps0.01_n10" in p.stderr, f"--keep-rows into another study's report: {p.stderr}")
        # one C within 20% of every measured c x: [max c / 1.2, min c / 0.8]
        lo, hi = rjs.one_c_band([15.0, 20.0], 0.2)
        check(abs(lo - 20.0 / 1.2) < 1e-12 and abs(hi - 15.0 / 0.8) < 1e-12, f"band of 15, 20: {lo}, {hi}")
        check(rjs.absolutely_unstable(2 * math.pi - 1e-9) and not rjs.absolutely_unstable(2 * math.pi),
              "absolute instability below We_d = 2 pi")
        g = rjs.groups(0.3441, 0.001194)
        check(abs(g["Oh_d"] - 1e-3 / math.sqrt(1000 * 0.072 * 0.001194)) < 1e-12, "Oh_d")
        check(abs(rjs.fit_origin([1.0, 2.0], [3.0, 5.0]) - 13.0 / 5.0) < 1e-12, "fit through origin")
        c, b, r2fit = rjs.fit_line([1.0, 2.0, 3.0], [2.0, 4.0, 6.0])
        check(abs(c - 2) < 1e-12 and abs(b) < 1e-12 and abs(r2fit - 1) < 1e-12, "line fit")
        # run --dry-run: the run of U = 0.7814 m/s lasts 2.5 L_ref / U (--window 1) with a nozzle that holds it
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"),
                            "--only", "mc_u0.7814"],
                           capture_output=True, text=True)
        t_end = 2.5 * 67.52 * 0.001194 / 0.7814
        check(f"time.tmax={t_end:.6g}" in p.stdout, f"dry run tmax {t_end:.6g}: {p.stdout}")
        check("nozzle.disturbance=0.01" in p.stdout, "the disturbance of the study")
        # --size-c 8: L_ref = 8 x d0 (at least 10 d0), in a study directory of its own
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"),
                            "--size-c", "8", "--only", "mc_u0.7814", "mc_u0.3441"],
                           capture_output=True, text=True)
        t_end = 2.5 * 8.0 * x1 * 0.001194 / 0.7814
        check(f"time.tmax={t_end:.6g}" in p.stdout, f"--size-c tmax {t_end:.6g}: {p.stdout}")
        t_end = 2.5 * max(8.0 * g["x"], 10.0) * 0.001194 / 0.3441
        check(f"time.tmax={t_end:.6g}" in p.stdout, f"--size-c tmax {t_end:.6g}: {p.stdout}")
        check("eps0.01_n10_c8" in p.stdout, f"--size-c study directory: {p.stdout}")
        # --remove-drops-below-h 2: the key on every run, in a study directory of its own
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"),
                            "--size-c", "8", "--remove-drops-below-h", "2", "--only", "mc_u0.7814"],
                           capture_output=True, text=True)
        check("breakup.remove_drops_below_h=2" in p.stdout and "eps0.01_n10_c8_rm2" in p.stdout,
              f"--remove-drops-below-h: {p.stdout}")
        # --artificial-alpha 0.02: the key on every run, in a study directory of its own; 2 refused
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"),
                            "--size-c", "8", "--artificial-alpha", "0.02", "--only", "mc_u0.7814"],
                           capture_output=True, text=True)
        check("numerics.artificial_alpha=0.02" in p.stdout and "eps0.01_n10_c8_alpha0.02" in p.stdout,
              f"--artificial-alpha: {p.stdout}")
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--artificial-alpha", "2"], capture_output=True, text=True)
        check(p.returncode == 2 and "--artificial-alpha" in p.stderr, f"--artificial-alpha 2: exit {p.returncode}")
        # --reconstruct: with an alpha, its key too, apart again; without one refused
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--size-c", "8",
                            "--artificial-alpha", "0.02", "--reconstruct", "--only", "mc_u0.7814"],
                           capture_output=True, text=True)
        check("numerics.artificial_reconstruction=true" in p.stdout and "eps0.01_n10_c8_alpha0.02_rec" in p.stdout,
              f"--reconstruct: {p.stdout}")
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--reconstruct"], capture_output=True, text=True)
        check(p.returncode == 2 and "--artificial-alpha" in p.stderr, f"--reconstruct alone: exit {p.returncode}")
        # --axis-pair rings: the key on every run, in a study directory of its own
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"),
                            "--size-c", "8", "--axis-pair", "rings", "--only", "mc_u0.7814"],
                           capture_output=True, text=True)
        check("domain.axis_pair=rings" in p.stdout and "eps0.01_n10_c8_rings" in p.stdout
              and "rings_curvature" not in p.stdout, f"--axis-pair: {p.stdout}")
        # --axis-pair rings_own: the rings pair with its surface rows' own curvature, apart again
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"),
                            "--size-c", "8", "--axis-pair", "rings_own", "--only", "mc_u0.7814"],
                           capture_output=True, text=True)
        check("domain.axis_pair=rings" in p.stdout and "surface_tension.rings_curvature=own" in p.stdout
              and "eps0.01_n10_c8_rings_own" in p.stdout, f"--axis-pair rings_own: {p.stdout}")
        # --axis-pair rings_fit: the rings pair with the surface fit and the tensile correction
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"),
                            "--size-c", "8", "--axis-pair", "rings_fit", "--only", "mc_u0.7814"],
                           capture_output=True, text=True)
        check("domain.axis_pair=rings" in p.stdout and "surface_tension.curvature=surface_fit" in p.stdout
              and "numerics.tensile_correction=on" in p.stdout and "eps0.01_n10_c8_rings_fit" in p.stdout,
              f"--axis-pair rings_fit: {p.stdout}")
        # --quiet-exit: the bulk viscosity and a 3 d0 nozzle that refills, in a directory of its own
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"),
                            "--size-c", "8", "--axis-pair", "rings_fit", "--quiet-exit", "--only", "mc_u0.7814"],
                           capture_output=True, text=True)
        check("numerics.bulk_viscosity=0.5" in p.stdout and "nozzle.refill=true" in p.stdout
              and "domain.split_axis_rings=true" in p.stdout
              and "nozzle.length_over_d0=3 " in p.stdout and "eps0.01_n10_c8_rings_fit_quiet" in p.stdout,
              f"--quiet-exit: {p.stdout}")
        # --sink 15: the sink that follows the jet on every run, in a directory of its own; 0 refused
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"),
                            "--size-c", "8", "--sink", "15", "--only", "mc_u0.7814"],
                           capture_output=True, text=True)
        check("breakup.remove_drops_beyond_d0=15" in p.stdout and "eps0.01_n10_c8_sink15" in p.stdout,
              f"--sink: {p.stdout}")
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--sink", "0"], capture_output=True, text=True)
        check(p.returncode == 2 and "--sink" in p.stderr, f"--sink 0: exit {p.returncode}")
        check(rjs.study_flags(rjs.parse(["report", "--eps", "0", "--axis-pair", "rings_fit", "--quiet-exit",
                                         "--sink", "15"])) ==
              " --eps 0 --d0-over-dx 10 --axis-pair rings_fit --quiet-exit --sink 15", "the report's run command")
        # --window 0.4: runs end at 1.9 L_ref / U, in a directory of its own; 0 refused
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"),
                            "--window", "0.4", "--only", "mc_u0.7814"], capture_output=True, text=True)
        t_end = 1.9 * 67.52 * 0.001194 / 0.7814
        check(f"time.tmax={t_end:.6g}" in p.stdout and "eps0.01_n10_w0.4" in p.stdout, f"--window: {p.stdout}")
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--window", "0"], capture_output=True, text=True)
        check(p.returncode == 2 and "--window" in p.stderr, f"--window 0: exit {p.returncode}")
        check(rjs.study_flags(rjs.parse(["report", "--window", "0.4"])) == " --eps 0.01 --d0-over-dx 10 --window 0.4",
              "the report's run command with --window")
        # --cfl 0.3: time.cfl on every run, in a directory of its own; 0 and above 1 refused
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"),
                            "--window", "0.4", "--cfl", "0.3", "--only", "mc_u0.7814"],
                           capture_output=True, text=True)
        check("time.cfl=0.3" in p.stdout and "eps0.01_n10_cfl0.3_w0.4" in p.stdout, f"--cfl: {p.stdout}")
        for bad in ("0", "1.5"):
            p = subprocess.run([PY, TOOL, "run", "--dry-run", "--cfl", bad], capture_output=True, text=True)
            check(p.returncode == 2 and "--cfl" in p.stderr, f"--cfl {bad}: exit {p.returncode}")
        check(rjs.study_flags(rjs.parse(["report", "--window", "0.4", "--cfl", "0.3"]))
              == " --eps 0.01 --d0-over-dx 10 --cfl 0.3 --window 0.4", "the report's run command with --cfl")
        # --c0 12: the measured jets' sound speed, in a directory of its own; the paper's jets keep 4 m/s
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--c0", "12",
                            "--only", "mc_u0.7814", "paper_u0.2"], capture_output=True, text=True)
        # (the costlier run first: the paper's round jet, then the measured one)
        lines = sorted((ln for ln in p.stdout.splitlines() if " run " in ln and "--out" in ln),
                       key=lambda ln: "paper_u0.2" in ln)
        check(len(lines) == 2 and "fluid.c0=12" in lines[0] and "eps0.01_n10_c012" in lines[0]
              and "fluid.c0=4" in lines[1] and "fluid.c0=12" not in lines[1], f"--c0: {p.stdout}")
        check(p.stdout.index("paper_u0.2: starting") < p.stdout.index("mc_u0.7814: starting"),
              f"the costliest run (L_ref^2 / U) first: {p.stdout}")
        check(rjs.study_flags(rjs.parse(["report", "--c0", "12"])) == " --eps 0.01 --d0-over-dx 10 --c0 12",
              "the report's run command with --c0")
        # --quiet-jets: the quiet numerics' eight options in one flag, the same directory as the
        # options given one by one; an option it sets given otherwise is refused; the report's run
        # command says --quiet-jets
        long_form = ["--axis-pair", "rings_fit", "--quiet-exit", "--artificial-alpha", "0.02", "--reconstruct",
                     "--c0", "12", "--cfl", "0.25", "--leapfrog", "--sink", "15"]
        outs = [subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--eps", "0",
                                "--only", "mc_u0.7814"] + form, capture_output=True, text=True).stdout
                for form in (long_form, ["--quiet-jets"], ["--quiet-jets", "--c0", "12"])]
        check(outs[0] == outs[1] == outs[2] and "eps0_n10_rings_fit_quiet_alpha0.02_rec_c012_cfl0.25_lf_sink15" in outs[1]
              and "numerics.integrator=leapfrog" in outs[1], f"--quiet-jets: {outs}")
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--quiet-jets", "--c0", "16"], capture_output=True, text=True)
        check(p.returncode == 2 and "--quiet-jets sets --c0 12; found --c0 16" in p.stderr,
              f"--quiet-jets --c0 16: exit {p.returncode} {p.stderr}")
        check(rjs.study_flags(rjs.parse(["report", "--eps", "0", "--window", "0.5", "--own-window"] + long_form))
              == " --eps 0 --d0-over-dx 10 --quiet-jets --window 0.5 --own-window", "the report's run command, quiet")
        # --column 0.5: each run starts with a column half its L_ref long (0.7814 m/s: 67.52 / 2 =
        # 33.76 d0), in a directory of its own; 0 and beyond the box (1.6 L_ref) refused
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--column", "0.5",
                            "--only", "mc_u0.7814"], capture_output=True, text=True)
        check("nozzle.column_over_d0=33.76 " in p.stdout and "eps0.01_n10_col0.5" in p.stdout, f"--column: {p.stdout}")
        for bad in ("0", "1.6"):
            p = subprocess.run([PY, TOOL, "run", "--dry-run", "--column", bad], capture_output=True, text=True)
            check(p.returncode == 2 and "--column" in p.stderr, f"--column {bad}: exit {p.returncode}")
        check(rjs.study_flags(rjs.parse(["report", "--column", "0.5"])) == " --eps 0.01 --d0-over-dx 10 --column 0.5",
              "the report's run command with --column")
        # --box-radius 5: the box reaches 5 d0 from the axis instead of 2.5 (0.7814 m/s: d0 =
        # 1.194 mm, domain.lx = 5.97 mm), in a directory of its own; below 1 d0 refused
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--box-radius", "5",
                            "--only", "mc_u0.7814"], capture_output=True, text=True)
        check(f"--set domain.lx={5 * rjs.D0_MC:.9g} " in p.stdout and "eps0.01_n10_box5" in p.stdout,
              f"--box-radius: {p.stdout}")
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--only", "mc_u0.7814"],
                           capture_output=True, text=True)
        check(f"--set domain.lx={2.5 * rjs.D0_MC:.9g} " in p.stdout, f"the default box: {p.stdout}")
        for bad in ("0.5", "-1"):
            p = subprocess.run([PY, TOOL, "run", "--dry-run", "--box-radius", bad], capture_output=True, text=True)
            check(p.returncode == 2 and "--box-radius" in p.stderr, f"--box-radius {bad}: exit {p.returncode}")
        check(rjs.study_flags(rjs.parse(["report", "--box-radius", "5"])) == " --eps 0.01 --d0-over-dx 10 --box-radius 5",
              "the report's run command with --box-radius")
        # --gravity: every run falls (gravity.gz = -9.81) with the renormalised continuity and the
        # release at the crossing, in a directory of its own; refused without a rings pair; its
        # report adds the falling C of tools/jet_gravity_theory.py at the measured length (0.7814
        # m/s: 18.52, that tool's table in cases/round_jet/README.md) and at the run's (67.0 d0)
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--gravity",
                            "--axis-pair", "rings", "--only", "mc_u0.7814"], capture_output=True, text=True)
        check(all(w in p.stdout for w in ("gravity.gz=-9.81 ", "domain.renormalise_ring_continuity=true ",
                                          "nozzle.release=crossing", "eps0.01_n10_rings_g")), f"--gravity: {p.stdout}")
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--gravity"], capture_output=True, text=True)
        check(p.returncode == 2 and "--gravity" in p.stderr and "--axis-pair" in p.stderr,
              f"--gravity without a rings pair: exit {p.returncode} {p.stderr}")
        check(rjs.study_flags(rjs.parse(["report", "--axis-pair", "rings", "--gravity"]))
              == " --eps 0.01 --d0-over-dx 10 --axis-pair rings --gravity", "the report's run command with --gravity")
        import jet_gravity_theory  # noqa: E402
        shutil.copytree(d, os.path.join(root, "eps0.01_n10_rings_g", "mc_u0.7814"))
        gout = os.path.join(tmp, "gout")
        os.makedirs(gout)
        p = subprocess.run([PY, TOOL, "report", "--root", root, "--out", gout, "--no-figures", "--gravity",
                            "--axis-pair", "rings"], capture_output=True, text=True)
        with open(os.path.join(gout, "round_jets.csv")) as f:
            grow = {r["run"]: r for r in csv.DictReader(f)}.get("mc_u0.7814", {})
        c_run = jet_gravity_theory.Jet(0.7814, 0.000597, 9.81).exponent(67.0 * 0.001194)
        check(grow.get("C = ln(a/delta0) falling, measured / SPH") == f"18.5 / {c_run:.1f}" and 16.0 < c_run < 18.5,
              f"--gravity report's falling C: {grow.get('C = ln(a/delta0) falling, measured / SPH')} "
              f"(run's {c_run:.2f}) {p.stderr}")
        check("here the jets fall" in p.stdout, f"--gravity report's text: {p.stdout[-600:]}")
        # and the same followed at one frequency (Jet's one_frequency): its own values at both
        # lengths, each below the fastest rate's (the jet speeds up, so a wave's ka drifts off the fastest)
        one = jet_gravity_theory.Jet(0.7814, 0.000597, 9.81, one_frequency=True)
        l_meas = dict(rjs.read_mc())[0.7814]
        c_one = [one.exponent(l * 0.001194) for l in (l_meas, 67.0)]
        check(grow.get("C falling at one frequency, measured / SPH") == f"{c_one[0]:.1f} / {c_one[1]:.1f}"
              and c_one[1] < c_run, f"--gravity report's falling C at one frequency: "
              f"{grow.get('C falling at one frequency, measured / SPH')} (built {c_one[0]:.2f} / {c_one[1]:.2f})")
        # --fixed-step F: every run a fixed step of F cfl h / c0 (the case's h = 2 dx): at d0/dx 10
        # with --c0 12 --cfl 0.25, 0.6 x 0.25 x 2.388e-4 / 12 = 2.985e-6 s for every measured jet;
        # the paper's jets keep their c0 = 4 m/s, and the case's cfl 0.2 without --cfl:
        # 0.5 x 0.2 x 2 x 1e-3 / 4 = 5e-5 s (d0 = 10 mm, 10 across)
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--c0", "12",
                            "--cfl", "0.25", "--fixed-step", "0.6", "--set-name", "mc"], capture_output=True, text=True)
        steps = [ln for ln in p.stdout.splitlines() if "sphjet run" in ln]
        check(len(steps) == 20 and all("--set time.variable_dt=false --set time.dt=2.985e-06" in ln for ln in steps)
              and "eps0.01_n10_c012_cfl0.25_fix0.6 " in p.stdout, f"--fixed-step 0.6: {p.stdout[:400]}")
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--fixed-step", "0.5",
                            "--set-name", "paper"], capture_output=True, text=True)
        steps = [ln for ln in p.stdout.splitlines() if "sphjet run" in ln]
        check(len(steps) == 4 and all("fluid.c0=4 " in ln and ln.endswith("--set time.dt=5e-05") for ln in steps),
              f"--fixed-step 0.5, the paper's jets: {p.stdout[:400]}")
        for bad in ("0", "1", "-0.5"):
            p = subprocess.run([PY, TOOL, "run", "--dry-run", "--fixed-step", bad], capture_output=True, text=True)
            check(p.returncode == 2 and f"--fixed-step {float(bad)}: expected 0 < F < 1" in p.stderr,
                  f"--fixed-step {bad}: exit {p.returncode} {p.stderr}")
        check(rjs.study_flags(rjs.parse(["report", "--fixed-step", "0.6"])) == " --eps 0.01 --d0-over-dx 10 --fixed-step 0.6",
              "the report's run command with --fixed-step")
        # --step-cap F: the variable step capped at the same F cfl h / c0 (time.dt_max), its own
        # directory; refused beside --fixed-step and outside (0, 1)
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--c0", "12",
                            "--cfl", "0.25", "--step-cap", "0.6", "--set-name", "mc"], capture_output=True, text=True)
        steps = [ln for ln in p.stdout.splitlines() if "sphjet run" in ln]
        check(len(steps) == 20 and all(ln.endswith("--set time.dt_max=2.985e-06") and "variable_dt" not in ln
                                       for ln in steps)
              and "eps0.01_n10_c012_cfl0.25_cap0.6 " in p.stdout, f"--step-cap 0.6: {p.stdout[:400]}")
        for argv, want in ((["--step-cap", "1"], "--step-cap 1.0: expected 0 < F < 1"),
                           (["--step-cap", "0.5", "--fixed-step", "0.5"], "--fixed-step and --step-cap: give one")):
            p = subprocess.run([PY, TOOL, "run", "--dry-run"] + argv, capture_output=True, text=True)
            check(p.returncode == 2 and want in p.stderr, f"{argv}: exit {p.returncode} {p.stderr}")
        # --landed: every run's rows freed on the orifice line (nozzle.release = "landed"), with
        # --gravity in place of the falling jets' crossing, in a directory of its own
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--landed",
                            "--gravity", "--axis-pair", "rings", "--step-cap", "0.6", "--set-name", "mc"],
                           capture_output=True, text=True)
        steps = [ln for ln in p.stdout.splitlines() if "sphjet run" in ln]
        check(len(steps) == 20 and all("--set nozzle.release=landed" in ln and "release=crossing" not in ln
                                       and "gravity.gz=-9.81" in ln for ln in steps)
              and "eps0.01_n10_rings_g_cap0.6_land " in p.stdout, f"--landed --gravity: {p.stdout[:400]}")
        check(rjs.study_flags(rjs.parse(["report", "--landed"])) == " --eps 0.01 --d0-over-dx 10 --landed",
              "the report's run command with --landed")
        # --renormalise-margin M: every falling run's domain.renormalise_margin_d0, in a directory
        # of its own; refused without --gravity (whose renormalised continuity it stops short)
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--gravity",
                            "--axis-pair", "rings", "--renormalise-margin", "2", "--set-name", "mc"],
                           capture_output=True, text=True)
        steps = [ln for ln in p.stdout.splitlines() if "sphjet run" in ln]
        check(len(steps) == 20 and all("--set domain.renormalise_margin_d0=2" in ln for ln in steps)
              and "eps0.01_n10_rings_g_margin2 " in p.stdout, f"--renormalise-margin: {p.stdout[:400]}")
        check(rjs.study_flags(rjs.parse(["report", "--axis-pair", "rings", "--gravity", "--renormalise-margin", "2"]))
              == " --eps 0.01 --d0-over-dx 10 --axis-pair rings --gravity --renormalise-margin 2",
              "the report's run command with --renormalise-margin")
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--renormalise-margin", "2"], capture_output=True, text=True)
        check(p.returncode == 2 and "with --gravity" in p.stderr, f"--renormalise-margin alone: {p.stderr}")
        # --bound-xsph, --free-bodies and --thin-rings: every run's key, in a directory of its own (suffix)
        for flag, key, suffix in (("--bound-xsph", "domain.bound_ring_xsph", "_bx"),
                                  ("--free-bodies", "surface_tension.balance_free_bodies", "_fb"),
                                  ("--thin-rings", "surface_tension.thin_rings_normals", "_tr")):
            p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--quiet-jets",
                                flag, "--set-name", "mc"], capture_output=True, text=True)
            steps = [ln for ln in p.stdout.splitlines() if "sphjet run" in ln]
            check(len(steps) == 20 and all(f"--set {key}=true" in ln for ln in steps)
                  and f"_sink15{suffix} " in p.stdout, f"{flag}: {p.stdout[:400]}")
            check(rjs.study_flags(rjs.parse(["report", "--quiet-jets", flag]))
                  == f" --eps 0.01 --d0-over-dx 10 --quiet-jets {flag}", f"the report's run command with {flag}")
        # --bound-xsph is refused without the rings pair
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--bound-xsph"], capture_output=True, text=True)
        check(p.returncode == 2 and "--axis-pair rings" in p.stderr, f"--bound-xsph alone: {p.stderr}")
        # --fit-points N, --kernel K: every run's surface_tension.fit_points_min or numerics.kernel,
        # suffix _fpN or _K; --fit-points refused at 3 or without the surface fit, a kernel not
        # measured on the jets refused
        for flag, value, key, suffix in (("--fit-points", "4", "surface_tension.fit_points_min", "_fp4"),
                                         ("--kernel", "cubic_spline", "numerics.kernel", "_cubic_spline")):
            p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--quiet-jets",
                                flag, value, "--set-name", "mc"], capture_output=True, text=True)
            steps = [ln for ln in p.stdout.splitlines() if "sphjet run" in ln]
            check(len(steps) == 20 and all(f"--set {key}={value}" in ln for ln in steps)
                  and f"_sink15{suffix} " in p.stdout, f"{flag}: {p.stdout[:400]}")
            check(rjs.study_flags(rjs.parse(["report", "--quiet-jets", flag, value]))
                  == f" --eps 0.01 --d0-over-dx 10 --quiet-jets {flag} {value}", f"the report's run command with {flag}")
        # --kernel naming the case's own kernel is the default's study (same runs, same directory)
        check(rjs.study_dir(rjs.parse(["run", "--quiet-jets", "--kernel", rjs.CASE_KERNEL]))
              == rjs.study_dir(rjs.parse(["run", "--quiet-jets"])), "--kernel with the case's kernel")
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--kernel", "gaussian"], capture_output=True, text=True)
        check(p.returncode == 2 and "--kernel" in p.stderr and "cubic_spline" in p.stderr, f"--kernel gaussian: {p.stderr}")
        for extra in (["--quiet-jets", "--fit-points", "3"], ["--axis-pair", "rings", "--fit-points", "4"]):
            p = subprocess.run([PY, TOOL, "run", "--dry-run", *extra], capture_output=True, text=True)
            check(p.returncode == 2 and "--fit-points" in p.stderr and "rings_fit or --quiet-jets" in p.stderr,
                  f"{' '.join(extra)}: {p.stderr}")
        # --h-over-dx H: every run's resolution.h_over_dx, suffix _hH, the step's cap that of the
        # case's h (the same time.dt_max as without the option); refused outside 1-4 spacings
        caps = []
        for extra in ([], ["--h-over-dx", "2.32"]):
            p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--quiet-jets",
                                "--step-cap", "0.6", "--set-name", "mc", *extra], capture_output=True, text=True)
            steps = [ln for ln in p.stdout.splitlines() if "sphjet run" in ln]
            caps.append([ln.split("--set time.dt_max=")[1].split()[0] for ln in steps])
        check(len(steps) == 20 and all("--set resolution.h_over_dx=2.32" in ln for ln in steps)
              and "_cap0.6_h2.32 " in p.stdout, f"--h-over-dx: {p.stdout[:400]}")
        check(caps[0] == caps[1] and len(caps[0]) == 20, f"--h-over-dx changed the step's cap: {caps}")
        check(rjs.study_flags(rjs.parse(["report", "--quiet-jets", "--h-over-dx", "2.32"]))
              == " --eps 0.01 --d0-over-dx 10 --quiet-jets --h-over-dx 2.32", "the report's run command with --h-over-dx")
        for bad in ("0.5", "5"):
            p = subprocess.run([PY, TOOL, "run", "--dry-run", "--h-over-dx", bad], capture_output=True, text=True)
            check(p.returncode == 2 and "--h-over-dx" in p.stderr and "1 to 4 spacings" in p.stderr,
                  f"--h-over-dx {bad}: {p.stderr}")
        # --thin-rings is refused without the surface fit
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--axis-pair", "rings", "--thin-rings"],
                           capture_output=True, text=True)
        check(p.returncode == 2 and "--axis-pair rings_fit or --quiet-jets" in p.stderr,
              f"--thin-rings without the fit: {p.stderr}")
        # --relaxed-exit: the measured jets' plugs at the tube's relaxed state. The root meets
        # x - (2/We_d) x^(-1/2) = 4/3 - 2/We_d, keeps the flux (U_f d_f^2 = U d0^2) and tends to
        # the inviscid 4/3 as the surface tension's share vanishes; each mc run's plug, spacing and
        # step follow it (d0/dx over the plug's diameter), the paper's jets keep theirs
        for u in (0.3441, 0.5806, 1.5842):
            x, uf, df = rjs.relaxed_exit(u, rjs.D0_MC)
            we = rjs.groups(u, rjs.D0_MC)["We_d"]
            check(1.0 < x < 4.0 / 3.0 and abs(x - 2.0 / (we * math.sqrt(x)) - (4.0 / 3.0 - 2.0 / we)) < 1e-12
                  and abs(uf * df * df - u * rjs.D0_MC ** 2) < 1e-15 * u, f"relaxed_exit({u}): {x}, {uf}, {df}")
        check(abs(rjs.relaxed_exit(1000.0, rjs.D0_MC)[0] - 4.0 / 3.0) < 1e-6, "relaxed_exit at We_d 1.6e7")
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--quiet-jets",
                            "--step-cap", "0.6", "--relaxed-exit"], capture_output=True, text=True)
        steps = {ln.split("--out ")[1].split()[0].rsplit("/", 1)[1]: ln for ln in p.stdout.splitlines()
                 if "sphjet run" in ln}
        x, uf, df = rjs.relaxed_exit(0.5806, rjs.D0_MC)
        ln = steps.get("mc_u0.5806", "")
        check(f"--set nozzle.u0={uf:g} " in ln and f"--set nozzle.d0={df:g} " in ln
              and f"--set resolution.dx={df / 10:.9g} " in ln
              and f"--set time.dt_max={0.6 * 0.25 * rjs.CASE_H_OVER_DX * df / 10 / 12:.6g}" in ln
              and "_cap0.6_rx " in p.stdout, f"--relaxed-exit mc_u0.5806: {ln}")
        ln = steps.get("paper_u0.07", "")
        check("--set nozzle.u0=0.07 " in ln and "--set nozzle.d0=0.01 " in ln, f"--relaxed-exit paper_u0.07: {ln}")
        check(rjs.study_flags(rjs.parse(["report", "--quiet-jets", "--relaxed-exit"]))
              == " --eps 0.01 --d0-over-dx 10 --quiet-jets --relaxed-exit", "the report's run command with --relaxed-exit")
        # as_tube: lengths over the plug's d0 become the tube's, the drops stay over the jet's own
        info = next(i for _s, n, _sets, i in rjs.plan(rjs.parse(["report", "--relaxed-exit"])) if n == "mc_u0.5806")
        shown, r = rjs.as_tube(info, {"L": 50.0, "L_std": 2.0, "L_first": 20.0, "L_halves": (49.0, 51.0),
                                      "drops_median": 1.9})
        k = df / rjs.D0_MC
        check(shown["U"] == 0.5806 and shown["d0"] == rjs.D0_MC and shown["plug"] == (uf, df)
              and r["L"] == 50.0 * k and r["L_std"] == 2.0 * k and r["L_first"] == 20.0 * k
              and r["L_halves"] == (49.0 * k, 51.0 * k) and r["drops_median"] == 1.9,
              f"as_tube: {shown}, {r}")
        # the scale from the run's own d0 to the tube's, read alike from the plan's info and as_tube's
        check(abs(rjs.tube_scale(info) - k) < 1e-15 and abs(rjs.tube_scale(shown) - k) < 1e-15,
              f"tube_scale: {rjs.tube_scale(info)}, {rjs.tube_scale(shown)}, {k}")
        plain = next(i for _s, n, _sets, i in rjs.plan(rjs.parse(["report"])) if n == "mc_u0.5806")
        check(rjs.as_tube(plain, {"L": 50.0}) == (plain, {"L": 50.0}), "as_tube without --relaxed-exit")
        # the notes' lengths (over the run's own d0) give the tube's beside them
        check(rjs.length_text(info, 50.0, 2.0) == f"L/d0 = 50.0 (std 2.0), {50 * k:.1f} (std {2 * k:.1f}) over the tube's d0"
              and rjs.length_text(plain, 50.0) == "L/d0 = 50.0" and rjs.tube_scale(plain) == 1.0, f"length_text: {rjs.length_text(info, 50.0, 2.0)}")
        # report --only --brief: the chosen run alone, in lines; the theory needs jet_noise's
        # inputs (the fake run has no case.toml: said so, not a crash)
        p = subprocess.run([PY, TOOL, "report", "--root", root, "--out", out, "--no-figures", "--only",
                            "mc_u0.7814", "--brief"], capture_output=True, text=True)
        c_meas = rjs.measured_c()
        for want in ("mc_u0.7814: U = 0.7814 m/s", "breakup length L/d0 = 67.0 (std 2.2) over 4 samples",
                     "measured (Mansour & Chigier 1994): 67.5, this run -1%", "theory: no fit",
                     f"the measurements' C = {c_meas:.1f}: {c_meas * x1:.1f}",
                     "main drops: 2.00 d0 (median over the window, 3 drop-samples), most frequent 1.8 d0; Rayleigh's: 1.89 d0"):
            check(want in p.stdout, f"--brief lacks {want!r}: {p.stdout} {p.stderr}")
        check("mc_u1.0179" not in p.stdout and abs(c_meas - 18.4) < 0.05,
              f"--only: one run; the measurements' C 18.4: {c_meas}")
        # the theory line on tests/regression/round_jet/test_jet_noise.py's synthetic run (delta0 =
        # 1e-4 a, Weber's L = 30.5 d0 there), the window from t = 0
        sys.path.insert(0, HERE)
        import test_jet_noise  # noqa: E402
        syn = os.path.join(tmp, "syn", "mc_u0.7814")
        os.makedirs(syn)
        test_jet_noise.write_run(syn)
        info = {"U": 0.7814, "d0": 0.001194, "L_ref": 0.0, "L_meas": 67.52}
        r = {"status": "finished", "L": 12.0, "L_std": 0.0, "n_window": 400, "drops_median": 1.9,
             "n_main_window": 5, "notes": []}
        text = rjs.brief(os.path.dirname(syn), rjs.parse(["report"]), "mc_u0.7814", info, r, c_meas)
        check("theory: Weber's L = u0 ln(a/delta0) / omega_max = 30.5, with this run's disturbance at the "
              "orifice, delta0 = 0.0001 a" in text, f"the theory line: {text}")
        check("with its own growth too: L = ln(a/delta0) / k_s = 11.5 (where" in text,
              f"the own-growth line (9.21 / 0.8 per d0 built): {text}")
        # --own-window: the window from the run's own length (own_window's docstring). A jet at
        # 0.7814 m/s grows at 0.7 U to 55 d0 (t = 0.12 s), then holds it: tau = 55 d0 / U =
        # 0.084043 s; the window's first sample is the first at t >= 1.75 tau = 0.14707 s,
        # 0.148 s (checks every 1 ms), and it ends at the first at t >= 0.148 + 0.5 tau =
        # 0.19002 s, 0.191 s: flat, so steady
        d0, u = 0.001194, 0.7814
        tau = 55 * d0 / u
        grow = [{"time": f"{k / 1000:.3f}", "broken": "1",
                 "L_over_d0": f"{min(55.0, 0.7 * u * (k / 1000) / d0):.6f}"} for k in range(5, 251)]
        ow = rjs.own_window(grow, u, d0, 0.5)
        check(ow["start"] == 0.148 and abs(ow["L"] - 55) < 1e-9 and ow["end"] == 0.191
              and ow["steady"] is True
              and ow["drift"] == 0.0 and ow["parts"] == 0.0, f"own window of the growing jet: {ow}")
        # cut at 0.13 s: no start yet (the candidates from 0.1 s on still growing, their ends not
        # reached); the window a 55 d0 jet needs, 2.25 tau = 0.18910 s (more than 1.25 times 0.13 s,
        # the least a run is made longer by)
        ow = rjs.own_window(grow[:126], u, d0, 0.5)
        check(ow["start"] is None and abs(ow["need"] - 2.25 * tau) < 1e-12, f"own window not yet: {ow}")
        # cut at 0.17 s: the start is pending (0.148 s passes on the rows so far; the candidates
        # from 0.140 s on do not yet, and their ends are not reached), its end 0.19002 s
        ow = rjs.own_window(grow[:166], u, d0, 0.5)
        check(ow["start"] == 0.148 and ow["end"] is None and ow["steady"] is None
              and abs(ow["need"] - (0.148 + 0.5 * tau)) < 1e-12, f"own window pending: {ow}")
        # a starting column (--column) 68 d0 long, intact over its first 4 ms: its lengths count
        # only up to the U t issued by then (at most 2.6 d0), so the run is sized as a 10 d0 jet,
        # 2.25 x 10 d0 / U = 0.03438 s, and not as a 68 d0 one (0.2338 s)
        column = [{"time": f"{k / 2000:.4f}", "broken": "1", "L_over_d0": "68"} for k in range(3, 9)]
        ow = rjs.own_window(column, u, d0, 0.5)
        check(ow["start"] is None and abs(ow["need"] - 2.25 * 10 * d0 / u) < 1e-12,
              f"own window of a starting column: {ow}")
        # a jet that grows at 0.45 U throughout: at 0.027 s it is 7.95 d0, so tau is the 10 d0
        # floor's 0.015280 s and it passes the start's test (1.75 tau = 0.02674 s); its first
        # window (to 0.035 s) rises by far more than 10% of its mean, and it stays rising as it is
        # made longer by a quarter of tau at a time: cut at 0.038 s it waits for 0.027 + 0.75 tau;
        # at 2 tau (0.058 s) it is unsteady, whatever the rows after it
        creep = [{"time": f"{k / 1000:.3f}", "broken": "1", "L_over_d0": f"{0.45 * u * (k / 1000) / d0:.9f}"}
                 for k in range(5, 201)]
        tau_c = 10 * d0 / u
        ow = rjs.own_window(creep[:34], u, d0, 0.5)
        check(ow["start"] == 0.027 and ow["steady"] is None and ow["drift"] > 0.1
              and abs(ow["need"] - (0.027 + 0.75 * tau_c)) < 1e-12, f"a jet still growing, pending: {ow}")
        ow = rjs.own_window(creep, u, d0, 0.5)
        check(ow["start"] == 0.027 and ow["end"] == 0.058 and ow["steady"] is False and ow["drift"] > 0.1,
              f"a jet still growing: {ow}")
        # a jet held at 31 d0 that dips in a V to 11 d0 about t = 0.092 s (8 ms wide): its first
        # window (from 0.0735 s, to 0.0945 s) falls; made longer to 0.75 of its own L / U its line
        # falls by 8.9%, under OWN_DRIFT, but its middle third is 15% below the mean (parts_off), so
        # (cut at 0.11 s) it waits for the whole of its own L / U
        def vee_l(t):
            return 31.0 - 20.0 * max(0.0, 1.0 - abs(t - 0.092) / 0.004)
        vee = [{"time": f"{k / 2000:.4f}", "broken": "1", "L_over_d0": f"{vee_l(k / 2000):.6f}"}
               for k in range(10, 221)]
        ow = rjs.own_window(vee, u, d0, 0.5)
        check(ow["start"] == 0.0735 and abs(ow["drift"]) < 0.1 and ow["parts"] > 0.1 and ow["steady"] is None
              and abs(ow["need"] - (0.0735 + ow["tau"])) < 1e-12, f"a jet that fell and grew back: {ow}")

        # the window is the same however the run was staged: for every cut of the rows, once the
        # window is decided it is the one of all the rows; before, it is undecided. On the jets
        # above and on a noisy one (lengths 40 +- 6 d0 from a fixed sequence, a fall to 20 d0 at
        # 0.1 s); each decided as soon as the rows reach its end
        def noisy_l(k):
            return (20.0 if 0.1 <= k / 2000 < 0.11 else 40.0) + 6.0 * math.sin(k * k * 0.37)
        noisy = [{"time": f"{k / 2000:.4f}", "broken": "1", "L_over_d0": f"{noisy_l(k):.6f}"}
                 for k in range(10, 700)]
        for name, rows in (("grow", grow), ("creep", creep), ("vee", vee), ("noisy", noisy)):
            whole = rjs.own_window(rows, u, d0, 0.5)
            seen = None
            for n in range(1, len(rows) + 1):
                ow = rjs.own_window(rows[:n], u, d0, 0.5)
                if ow["steady"] is None:
                    check(seen is None, f"{name}: undecided again at {n} rows")
                    continue
                key = (ow["start"], ow["end"], ow["steady"], ow["drift"], ow["parts"])
                if seen is None:
                    seen = key
                    check(float(rows[n - 1]["time"]) == ow["end"], f"{name}: decided at its end ({n} rows)")
                check(key == seen == (whole["start"], whole["end"], whole["steady"], whole["drift"],
                                      whole["parts"]), f"{name}: {key} at {n} rows, {seen} before")
            check(seen is not None or name == "vee", f"{name}: decided within its rows")
        # own_verdict (run and report alike), the 0.78 m/s run's checks every 67.52 d0 / (200 U):
        # whole; more (to the need and a check); capped (a 150 d0 jet in a 118 d0 box at 0.41 s)
        info = {"U": u, "d0": d0, "L_ref": 67.52 * d0, "box": rjs.box_below(67.52 * d0, d0), "own": True, "W": 0.5}
        every = 67.52 * d0 / (200 * u)
        check(rjs.own_verdict(grow, info, 0.5)[1] == "whole", "the grown jet's window is whole")
        ow, verdict, end = rjs.own_verdict(grow[:126], info, 0.5)
        check(verdict == "more" and abs(end - (2.25 * tau + every)) < 1e-12, f"more: {verdict}, {end}")
        long_jet = [{"time": f"{k / 1000:.3f}", "broken": "1", "L_over_d0": "150"} for k in range(5, 411)]
        check(rjs.own_verdict(long_jet, info, 0.5)[1] == "capped" and abs(rjs.own_cap(info, 0.5) - 0.40574) < 1e-4,
              f"capped at {rjs.own_cap(info, 0.5)}")
        check(rjs.own_verdict(creep, info, 0.5)[1] == "unsteady", "the creeping jet is unsteady")
        # a jet of 4 d0 at 0.3441 m/s is taken as 10 d0 long: from 1.75 x 0.034698 s, 0.061 s, to
        # the first sample at 0.061 + 0.5 x 0.034698 s, 0.079 s
        slow = [{"time": f"{k / 1000:.3f}", "broken": "1", "L_over_d0": "4"} for k in range(10, 120)]
        ow = rjs.own_window(slow, 0.3441, d0, 0.5)
        check(ow["start"] == 0.061 and ow["end"] == 0.079 and ow["steady"] is True,
              f"own window of a short jet: {ow}")
        # a dripping jet at 0.3441 m/s whose length wanders between 4 and 8 d0 (a triangle of 60 ms):
        # its window (from 0.061 s, tau = 10 d0 / U = 0.034698 s) is made longer up to 2 tau from
        # its start, to the first sample at or past 0.13040 s, and no further: "unsteady" once the
        # rows reach 0.1305 s (samples every 0.5 ms)
        slow_info = {"U": 0.3441, "d0": d0, "L_ref": 31.85 * d0, "box": rjs.box_below(31.85 * d0, d0),
                     "own": True, "W": 0.5}

        def wander(t_end):
            return [{"time": f"{k * 0.0005:.4f}", "broken": "1",
                     "L_over_d0": f"{4 + 8 * min((k * 0.0005 / 0.06) % 1, 1 - (k * 0.0005 / 0.06) % 1):.6f}"}
                    for k in range(20, round(t_end / 0.0005) + 1)]
        longest = 0.061 + 2.0 * 10 * d0 / 0.3441
        ow, verdict, end = rjs.own_verdict(wander(0.12), slow_info, 0.5)
        check(verdict == "more" and ow["parts"] > 0.1 and end <= longest + 0.00056, f"wandering, 0.12 s: {verdict} {end}")
        ow, verdict, end = rjs.own_verdict(wander(0.13), slow_info, 0.5)
        check(verdict == "more" and abs(ow["need"] - longest) < 1e-12, f"wandering, 0.13 s: {verdict} {ow}")
        for t_end in (0.131, 0.2):
            ow, verdict, end = rjs.own_verdict(wander(t_end), slow_info, 0.5)
            check(verdict == "unsteady" and end is None and ow["end"] == 0.1305,
                  f"wandering, {t_end} s: {verdict} {ow}")
        check(rjs.own_verdict(grow, info, 0.5)[1] == "whole", "a steady jet is never unsteady")
        # quiet_since: a jet at 0.4014 m/s (spans of 10 d0 / U = 0.029746 s) whose surface 5 d0
        # below the orifice (slices 0.1 d0 wide: the one centred at 5.05 d0) carries a wave of
        # period 4 ms, sampled every 1 ms. Its amplitude halves every 30 ms up to 0.15 s and then
        # holds: 4 spans from span 4 (0.119-0.149 s, a mean amplitude about 1.4 times the held
        # one) end within a factor 2 of it, and from span 3 they do not (about 2.9 times): quiet
        # from 4 spans, 0.11898 s. Halving throughout to 0.45 s: never quiet. Held throughout
        # below OWN_QUIET_LEVEL (1e-3 a): quiet from 0; held above it: never quiet. A jet that never reaches 5 d0 (it drips) waits for nothing: quiet from 0.
        def surface(amp, t_end=0.45, reach=True):
            out = []
            for k in range(1, round(t_end * 1000) + 1):
                t = k / 1000
                out.append({"time": f"{t:.4f}", "s_over_d0": "0.05", "r_over_d0": "0.5"})
                if reach:
                    out.append({"time": f"{t:.4f}", "s_over_d0": "5.05",
                                "r_over_d0": f"{0.5 + amp(t) * math.sin(2 * math.pi * t / 0.004):.12f}"})
            return out
        u4 = 0.4014
        span4 = 10 * d0 / u4
        q = rjs.quiet_since(surface(lambda t: 1e-3 * 2 ** (-min(t, 0.15) / 0.03)), u4, d0)
        check(q is not None and abs(q - 4 * span4) < 1e-12, f"quiet after a start-up that fades by 0.15 s: {q}")
        check(rjs.quiet_since(surface(lambda t: 1e-3 * 2 ** (-t / 0.03)), u4, d0) is None,
              "a start-up still fading at 0.45 s: not quiet")
        check(rjs.quiet_since(surface(lambda t: 1e-6), u4, d0) == 0.0, "a jet quiet from the start")
        # held flat, but at 2e-3 a (a sine of 1e-3 d0), above OWN_QUIET_LEVEL: loud, not quiet; and
        # at half the level (a sine of 2.5e-4 d0, 5e-4 a): quiet from the start
        check(rjs.quiet_since(surface(lambda t: 1e-3), u4, d0) is None, "a jet held loud (2e-3 a): not quiet")
        check(rjs.quiet_since(surface(lambda t: 2.5e-4), u4, d0) == 0.0, "a jet held at 5e-4 a: quiet from the start")
        check(rjs.quiet_since(surface(lambda t: 1e-6, reach=False), u4, d0) == 0.0,
              "a jet short of 5 d0 (it drips) waits for nothing")
        # one long and fading up to 0.2 s and short of 5 d0 since (it drips): span 7 (from
        # 0.2082 s; span 6, 0.178-0.208 s, is mostly long) is the first short in most of its
        # samples, so the 4 spans from span 4 end quiet: from 0.11898 s
        fading = surface(lambda t: 1e-3 * 2 ** (-t / 0.03))
        q = rjs.quiet_since([x for x in fading if float(x["time"]) <= 0.2 or x["s_over_d0"] == "0.05"], u4, d0)
        check(q is not None and abs(q - 4 * span4) < 1e-12, f"a jet that drips from 0.2 s: {q}")
        # the spans' amplitudes: a sine of 1e-6 d0 is 2e-6 a (sqrt 2 x its rms over whole periods,
        # 7.4 periods a span: within 2%); 15 complete spans to 0.45 s; None where the jet is short
        held = rjs.quiet_spans(surface(lambda t: 1e-6), u4, d0)
        check(len(held) == 15 and all(abs(a / 2e-6 - 1) < 0.02 for a in held), f"held amplitudes: {held}")
        check(all(a is None for a in rjs.quiet_spans(surface(lambda t: 1e-6, reach=False), u4, d0)),
              "no amplitude where the jet is short of 5 d0")
        # own_window's clock from the quiet time: the grown jet quiet from 0.02 s has its window
        # from the first sample at t >= 0.02 + 1.75 tau = 0.16707 s, 0.168 s, to 0.211 s; not quiet,
        # no window; at the quiet run's cap (the 150 d0 jet to 0.41 s) it is made longer, to at most
        # twice that cap, 0.81148 s, and there it is made no longer
        ow = rjs.own_window(grow, u, d0, 0.5, 0.02)
        check(ow["start"] == 0.168 and ow["end"] == 0.211, f"quiet from 0.02 s: {ow}")
        ow = rjs.own_window(grow, u, d0, 0.5, None)
        check(ow["start"] is None and ow["quiet"] is None, f"not quiet: {ow}")
        ow, verdict, end = rjs.own_verdict(long_jet, info, 0.5, None)
        check(verdict == "more" and 0.41 < end <= 2 * rjs.own_cap(info, 0.5) + 1e-12,
              f"not quiet at the quiet run's cap: {verdict}, {end}")
        longer_jet = [{"time": f"{k / 1000:.3f}", "broken": "1", "L_over_d0": "150"} for k in range(5, 814)]
        ow, verdict, _end = rjs.own_verdict(longer_jet, info, 0.5, None)
        check(abs(rjs.own_cap(info, 0.5, None) - 2 * 0.40574) < 2e-4 and verdict == "capped"
              and "orifice not quiet" in rjs.no_longer(ow, verdict, info, 0.5),
              f"not quiet at twice the cap ({rjs.own_cap(info, 0.5, None)}): {verdict}")
        check(abs(rjs.own_cap(info, 0.5, 0.02) - (0.02 + rjs.own_cap(info, 0.5))) < 1e-12,
              "the cap's clock from the quiet time")
        # the runs: sized for 10 d0 (2.25 x 10 d0 / U), checks every L_ref / (200 U), a
        # refilling nozzle, in a directory of its own; without --quiet-exit refused
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--root", os.path.join(tmp, "fresh"), "--axis-pair",
                            "rings_fit", "--quiet-exit", "--window", "0.5", "--own-window", "--only", "mc_u0.7814"],
                           capture_output=True, text=True)
        check(f"time.tmax={2.25 * 10 * d0 / u:.6g}" in p.stdout
              and f"breakup.check_every={67.52 * d0 / (200 * u):.4g}" in p.stdout
              and "nozzle.refill=true" in p.stdout and "_quiet_w0.5_own" in p.stdout, f"--own-window: {p.stdout}")
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--own-window"], capture_output=True, text=True)
        check(p.returncode == 2 and "--quiet-exit" in p.stderr, f"--own-window alone: {p.stderr}")
        # report: the grown jet to 0.25 s has its window (0.148-0.191 s: 44 samples of 55 d0); the
        # same lengths at 1.0179 m/s to 0.14 s fall short of their window (from 0.112 s, to 0.1439
        # s): unfinished
        osdir = os.path.join(root, "eps0.01_n10_rings_fit_quiet_w0.5_own")
        for name, rows in (("mc_u0.7814", grow), ("mc_u1.0179", grow[:136]), ("mc_u0.3441", wander(0.131))):
            fake_run(os.path.join(osdir, name), [(float(x["time"]), k, 1, float(x["L_over_d0"]))
                                                 for k, x in enumerate(rows)])
        # a jet at 0.4014 m/s of 24 d0 to its cap while not quiet (0.9042 s, twice a 67.55 d0 box's
        # window) whose start-up is still fading 5 d0 below the orifice: no window, no length
        fake_run(os.path.join(osdir, "mc_u0.4014"), [(k / 1000, k, 1, 24.0) for k in range(5, 905)])
        with open(os.path.join(osdir, "mc_u0.4014", "jet_surface.csv"), "w", newline="") as f:
            w = csv.DictWriter(f, ["time", "step", "s_over_d0", "r_over_d0"])
            w.writeheader()
            w.writerows({"step": 0, **x} for x in surface(lambda t: 1e-3 * 2 ** (-t / 0.03), 0.904))
        p = subprocess.run([PY, TOOL, "report", "--root", root, "--out", os.path.join(tmp, "own"), "--no-figures",
                            "--axis-pair", "rings_fit", "--quiet-exit", "--window", "0.5", "--own-window"],
                           capture_output=True, text=True)
        check(p.returncode == 0, f"report --own-window: {p.stderr}")
        with open(os.path.join(tmp, "own", "round_jets.csv")) as f:
            rows = {r["run"]: r for r in csv.DictReader(f)}
        r = rows.get("mc_u0.7814", {})
        check(r.get("L/d0 SPH (std)") == "55.00 (0.00)" and r.get("window samples") == "44"
              and r.get("window from t [s] (its own L/U)") == "0.148 (1.76)"
              and r.get("window to t [s]") == "0.191",
              f"own window's length: {r}")
        r = rows.get("mc_u1.0179", {})
        check(r.get("status") == "unfinished (its own window not reached)" and r.get("L/d0 SPH (std)") == "- (-)",
              f"short of its own window: {r}")
        r = rows.get("mc_u0.3441", {})
        with open(os.path.join(tmp, "own", "round_jets.md")) as f:
            md = f.read()
        r4 = rows.get("mc_u0.4014", {})
        check(r.get("orifice quiet from t [s]") == "0" and r4.get("orifice quiet from t [s]") == "-",
              f"the quiet column: a run without jet_surface.csv from 0, one never quiet: {r}, {r4}")
        check(r4.get("status") == "finished, start-up not cleared" and r4.get("L/d0 SPH (std)") == "- (-)"
              and "orifice not quiet" in md and "over its last 4 spans of 10 d0 / U: not quiet" in md
              and "the jet broke at L/d0 = 24.0 (std 0.0), not a steady length" in md,
              f"not quiet by its cap: {r4}")
        # the cost line: four runs of 100 s at 9e4 particle-steps/s (fake_run's run.log)
        check("Cost: 3.60e7 particle-steps; the runs' walls sum to 400 s of one core (0.06 h on two cores"
              in md, f"the cost line: {md}")
        check(r.get("status") == "finished, unsteady window" and "not steady over 2 of its own L / U" in md
              and r.get("L/d0 SPH (std)", "-").split()[0] != "-", f"unsteady window: {r}")
        # --set-name mc: the report of the measured speeds only, the paper's four jets not listed
        # as missing; the same rows as the report of both sets
        p = subprocess.run([PY, TOOL, "report", "--root", root, "--out", os.path.join(tmp, "own_mc"), "--no-figures",
                            "--axis-pair", "rings_fit", "--quiet-exit", "--window", "0.5", "--own-window",
                            "--set-name", "mc"], capture_output=True, text=True)
        check(p.returncode == 0, f"report --set-name mc: {p.stderr}")
        with open(os.path.join(tmp, "own_mc", "round_jets.csv")) as f:
            mc_rows = {r["run"]: r for r in csv.DictReader(f)}
        check(len(mc_rows) == 20 and all(k.startswith("mc_") for k in mc_rows)
              and all(mc_rows[k] == rows[k] for k in mc_rows), f"report --set-name mc: {sorted(mc_rows)}")
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--quiet-exit"], capture_output=True, text=True)
        check(p.returncode == 2 and "--axis-pair" in p.stderr, f"--quiet-exit without the rings pair: {p.stderr}")
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--size-c", "0"], capture_output=True, text=True)
        check(p.returncode == 2 and "--size-c" in p.stderr, f"--size-c 0: {p.stderr}")
        p = subprocess.run([PY, TOOL, "run", "--dry-run", "--only", "nope"], capture_output=True, text=True)
        check(p.returncode == 2 and "not in the plan" in p.stderr, f"unknown run: {p.stderr}")
    if failures:
        for f in failures:
            print("FAIL:", f, file=sys.stderr)
        print("test_round_jet_report: FAILED", file=sys.stderr)
        return 1
    print("test_round_jet_report: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
