#!/usr/bin/env python3
"""Validation: the round (axisymmetric) jets against Mansour & Chigier (1994), the study of
cases/round_jet/README.md at six speeds of the file spread over its range (0.34-1.57 m/s),
d0/dx = 10, the runs sized for the jets' own lengths (round_jet_study.py --size-c 8), the
plug disturbance 0.01; about 32 min on two cores, resumable (a killed test continues where
it stopped). Three modes read the same study (ctest keeps them apart with a resource lock):

--weber: the form of the law.
  - at least four of the six speeds give a breakup length (a run may stop on the density check
    at an unresolved drop on the axis, a result the report names: two of six did in the study
    of the README; fewer than four lengths leave no line to judge);
  - the lengths are linear in x = sqrt(We_d)(1 + 3 Oh_d), Weber's law: R^2 of the line
    L/d0 = C x + b at least 0.95 (a length is a mean over a window with a standard deviation
    of 1-4 d0, so a line through four to six of them cannot be expected to do better than
    about 0.95; the measurements' own line has 0.92 over twenty speeds).
--rayleigh-drops: the median of the main (non-satellite) drops over the window of every jet
  longer than 10 d0 (just over two wavelengths of the fastest-growing wave, 4.5 d0: a shorter
  jet breaks before that wave is established and its drops merge; a long jet without a main
  drop fails) within 15% of Rayleigh's 1.89 d0 (the drops of one jet spread by +-30% between
  their quartiles; Rayleigh's value is for the fastest-growing wave alone). At least one jet
  must qualify.
--mansour-chigier: the project's target, the breakup length within 20% of the measured one
  at every speed (a speed without a length fails it too). NOT MET (cases/round_jet/README.md:
  the lengths are 76-88% short, C = 3.4 against the measurements' 18.4: the jets break from
  the particles' noise, 3% of the radius, not from the experiment's 1e-8, and the imposed
  disturbance cannot go below that noise). This test fails until a change of the model meets
  it; it is not widened.
The report prints the study's table either way. Runs are reused only if the build that made
them is this one (run.log's first line against `sphjet --version`): a run of another build is
removed and run again, so that the tests judge the model as built. Needs no ../shared (the
measurements are in cases/round_jet/mansour_chigier_1994.csv).
Usage: check_round_jet_study.py SPHJET SOURCE_DIR WORK_DIR --weber|--rayleigh-drops|--mansour-chigier
"""
import csv
import importlib.util
import pathlib
import re
import shutil
import subprocess
import sys

# The tool plots with Debian's matplotlib under /usr/bin/python3 (README).
PY = "/usr/bin/python3" if pathlib.Path("/usr/bin/python3").exists() else sys.executable

# the study: round_jet_study.py's plan at this disturbance, resolution and sizing
EPS, D0_OVER_DX, SIZE_C = 0.01, 10, 8
RUNS = ["mc_u0.3441", "mc_u0.5161", "mc_u0.7814", "mc_u1.0179", "mc_u1.2545", "mc_u1.5699"]
RAYLEIGH_DROP = 1.89      # d / d0 (Rayleigh 1878)
DROP_TOL = 0.15
R2_MIN = 0.95
MIN_LENGTHS = 4
LONG_JET = 10.0           # d0: just over two wavelengths of ka = 0.697 (9.0 d0)
MC_TOL = 0.20


def number(cell):
    """The leading number of a report cell ('5.91 (1.09)' -> 5.91), None for '-'."""
    head = cell.split("(")[0].strip()
    return None if head in ("", "-") else float(head)


def build_id(line):
    """The source hash in 'sphjet 0.1.0 (52a86ad73607) starting' or '0.1.0 (52a86ad73607, ...)'."""
    m = re.search(r"\(([^,)]+)", line)
    return m.group(1) if m else None


def drop_stale_runs(sphjet, sdir, runs=RUNS):
    """Removes the runs (names) made by another build than sphjet, so that they are run again."""
    v = subprocess.run([str(sphjet), "--version"], capture_output=True, text=True)
    current = build_id(v.stdout)
    for name in runs:
        log = sdir / name / "run.log"
        if not log.exists():
            continue
        made_by = build_id(log.read_text(errors="replace").split("\n", 1)[0])
        if current is None or made_by != current:
            print(f"{name}: made by {made_by}, this build is {current}: run again")
            shutil.rmtree(sdir / name)


def run_and_report(tool, common, sphjet, runs, out, run_opts=("--threads", "2")):
    """round_jet_study.py run (with run_opts: one run at a time on two threads by default) and
    report (into out) of runs with the options common -> the report's rows of those runs, by
    name; exits with FAIL if either fails."""
    r = subprocess.run([PY, str(tool), "run", *common, "--sphjet", str(sphjet), *run_opts,
                        "--only", *runs])
    if r.returncode != 0:
        sys.exit(f"FAIL: round_jet_study.py run exited {r.returncode}")
    r = subprocess.run([PY, str(tool), "report", *common, "--out", str(out), "--no-figures"])
    if r.returncode != 0:
        sys.exit(f"FAIL: round_jet_study.py report exited {r.returncode}")
    with open(out / "round_jets.csv") as f:
        return {row["run"]: row for row in csv.DictReader(f) if row["run"] in runs}


def main():
    modes = ("--weber", "--rayleigh-drops", "--mansour-chigier")
    if len(sys.argv) != 5 or sys.argv[4] not in modes:
        sys.exit(__doc__)
    sphjet, src, work = map(pathlib.Path, sys.argv[1:4])
    mode = sys.argv[4]
    tool = src / "tools" / "round_jet_study.py"
    sys.path.insert(0, str(tool.parent))   # the tool's fits, and the module it imports
    spec = importlib.util.spec_from_file_location("round_jet_study", tool)
    study = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(study)
    common = ["--root", str(work), "--eps", f"{EPS:g}", "--d0-over-dx", f"{D0_OVER_DX:g}",
              "--size-c", f"{SIZE_C:g}"]
    opts = study.parse(["run", *common])   # the study directory as the tool names it
    drop_stale_runs(sphjet, pathlib.Path(study.study_dir(opts)))
    rows = run_and_report(tool, common, sphjet, RUNS, work / "report")

    failures = []
    xs, ls = [], []
    drops_checked = 0
    for name in RUNS:
        row = rows.get(name)
        if row is None or row["status"] in ("missing", "unfinished"):
            failures.append(f"{name}: no run ({row['status'] if row else 'not in the report'})")
            continue
        x = float(row["x = sqrt(We_d)(1+3Oh_d)"])
        length = number(row["L/d0 SPH (std)"])
        measured = float(row["L/d0 measured"])
        drop = number(row["main drops d/d0 window median (drop-samples)"])
        print(f"{name}: x = {x:.3f}, L/d0 = {row['L/d0 SPH (std)']} over {row['window samples']} "
              f"samples (measured {measured}), "
              f"main drops (window median) {drop if drop is not None else '-'} d0, {row['status']}")
        if length is None:
            if mode == "--mansour-chigier":
                failures.append(f"{name}: no breakup length ({row['status']})")
            continue
        xs.append(x)
        ls.append(length)
        if mode == "--rayleigh-drops" and length > LONG_JET:
            if drop is None:
                failures.append(f"{name}: a jet of {length} d0 without a main drop in its window")
                continue
            drops_checked += 1
            if abs(drop / RAYLEIGH_DROP - 1.0) > DROP_TOL:
                failures.append(f"{name}: main drops {drop} d0, Rayleigh's {RAYLEIGH_DROP} "
                                f"+-{DROP_TOL:.0%}")
        if mode == "--mansour-chigier" and abs(length / measured - 1.0) > MC_TOL:
            failures.append(f"{name}: L/d0 {length} against the measured {measured} "
                            f"({length / measured - 1.0:+.0%}, the target is {MC_TOL:.0%})")
    if len(xs) >= 2:
        c0 = study.fit_origin(xs, ls)
        print(f"C through the origin {c0:.2f} (the measurements: 18.4; theory C = ln(a/delta0))")
    if mode == "--weber":
        if len(xs) < MIN_LENGTHS:
            failures.append(f"{len(xs)} speeds with a length, at least {MIN_LENGTHS} needed")
        else:
            c, b, r2 = study.fit_line(xs, ls)
            print(f"line L/d0 = {c:.2f} x {b:+.2f}, R^2 = {r2:.3f} over {len(xs)} speeds")
            if not r2 >= R2_MIN:   # NaN fails too
                failures.append(f"R^2 {r2:.3f} of the line below {R2_MIN}")
    if mode == "--rayleigh-drops" and drops_checked == 0:
        failures.append(f"no jet longer than {LONG_JET:g} d0 to compare with Rayleigh's drop")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("PASS")


if __name__ == "__main__":
    main()
