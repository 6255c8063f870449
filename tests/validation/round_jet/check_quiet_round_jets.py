#!/usr/bin/env python3
"""Validation: the quiet round jets of the study at c0 = 12 m/s with cfl 0.25 and the leapfrog
(cases/round_jet/README.md, "The study at c0 = 12 m/s with cfl 0.25" and "One evaluation per
step: the leapfrog") at the four speeds of Mansour & Chigier (1994) spread over the
convectively unstable range (0.78, 1.02, 1.25, 1.57 m/s; below We_d = 2 pi a jet without
gravity is absolutely unstable), d0/dx = 10, no imposed disturbance, with the quiet exit,
alpha 0.02 with the reconstruction, the sink 15 d0 past the jet's end and each run's window
from its own length (0.5 of its own L/U):

    round_jet_study.py run --eps 0 --quiet-jets --window 0.5 --own-window \\
        --only mc_u0.7814 mc_u1.0179 mc_u1.2545 mc_u1.5699 --parallel 2 --threads 1

About 1.5 h of one core (0.8 h on two; 5466 s of one core at 5e46a49), resumable (a killed
test continues where it stopped);
runs made by another build are made again. Each run is read over its own window (the report's
"window from" and "window to") by the study's report and by tools/jet_noise.py (its analyse()). Two modes:

--noise-floor: the noise floor and the exit, the targets of the quiet jets.
  - every run has a breakup length over its window;
  - C = ln(a/delta0) of jet_noise.py's envelope fit at least 10 at every speed (the jets broke
    at C = 3.4 before the quiet exit; the measurements' fit is 18.4; 15.4-16.8 on the same runs
    made by the default study's command with 7defe6a's binary);
  - the exit's pressure (the median over the window's samples of the jet's particles within
    2 d0 of the orifice) within 5% of sigma/a on average, its standard deviation at most
    sigma/(4a) (measured 0.967-0.968 and 0.106-0.111 sigma/a).
--mansour-chigier: the lengths within 20% of the measured ones at the four speeds. NOT MET at
  1.57 m/s (+24%; the others -14%, -17%, -7%, 7defe6a's binary; with the predictor-corrector
  +26%, -14%, -14%, +0%): these jets follow Weber's law with one C (17.4-18.2) while the measured
  C falls from 21.9 to 14.7 over these speeds, and no one C is within 20% of all of them (the
  report's interval). This test fails until the model changes; it is not widened.
--relaxed-exit (after the mode): the same jets leaving as the plug to which the tube's parabolic
  profile relaxes (round_jet_study.py --relaxed-exit; cases/round_jet/README.md, "A plug at the
  tube's relaxed state"), lengths over the tube's d0, a the plug's radius. Measured with
  cfa665b's build (2720 s on two cores, shared for part of it): C = 15.9, 15.8, 15.7, 15.6,
  exit pressure 0.968-0.971 sigma/a, std 0.091-0.109; lengths -3%, -8%, +2%, +31% (NOT MET at
  1.57 m/s, as above).
Usage: check_quiet_round_jets.py SPHJET SOURCE_DIR WORK_DIR --noise-floor|--mansour-chigier [--relaxed-exit]
"""
import importlib.util
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from check_round_jet_study import drop_stale_runs, number, run_and_report  # noqa: E402  (the same directory)

STUDY = ["--eps", "0", "--d0-over-dx", "10", "--quiet-jets", "--window", "0.5", "--own-window"]
RUNS = ["mc_u0.7814", "mc_u1.0179", "mc_u1.2545", "mc_u1.5699"]
C_MIN = 10.0          # the noise floor's target: C = ln(a/delta0) >= 10
EXIT_MEAN_TOL = 0.05  # the exit pressure's mean within 5% of sigma/a
EXIT_STD_MAX = 0.25   # and its standard deviation at most sigma/(4a)
MC_TOL = 0.20


def main():
    modes = ("--noise-floor", "--mansour-chigier")
    if len(sys.argv) < 5 or sys.argv[4] not in modes or sys.argv[5:] not in ([], ["--relaxed-exit"]):
        sys.exit(__doc__)
    sphjet, src, work = map(pathlib.Path, sys.argv[1:4])
    mode = sys.argv[4]
    tool = src / "tools" / "round_jet_study.py"
    sys.path.insert(0, str(tool.parent))
    spec = importlib.util.spec_from_file_location("round_jet_study", tool)
    study = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(study)
    import jet_noise   # tools/, beside the study tool
    common = ["--root", str(work), *STUDY, *sys.argv[5:]]
    opts = study.parse(["run", *common])
    sdir = pathlib.Path(study.study_dir(opts))
    drop_stale_runs(sphjet, sdir, RUNS)
    rows = run_and_report(tool, common, sphjet, RUNS, work / "report_quiet",
                          run_opts=("--parallel", "2", "--threads", "1"))

    failures = []
    for name in RUNS:
        row = rows.get(name)
        length = number(row["L/d0 SPH (std)"]) if row else None
        if length is None:
            failures.append(f"{name}: no breakup length ({row['status'] if row else 'not in the report'})")
            continue
        measured = float(row["L/d0 measured"])
        try:
            s = jet_noise.analyse(str(sdir / name), number(row["window from t [s] (its own L/U)"]),
                                  t1=number(row["window to t [s]"]))["summary"]
        except jet_noise.NoiseError as e:
            failures.append(f"{name}: jet_noise.py: {e}")
            continue
        print(f"{name}: L/d0 = {row['L/d0 SPH (std)']} (measured {measured}, {length / measured - 1:+.0%}); "
              f"C = {s.get('C', float('nan')):.2f} (growth {s.get('omega_over_weber', float('nan')):.3f} of "
              f"Weber's, delta0 {s.get('delta0_over_a', float('nan')):.3g} a); exit p "
              f"{s['p_exit_mean_over_sigma_a']:.3f} +- {s['p_exit_std_over_sigma_a']:.3f} sigma/a")
        if mode == "--noise-floor":
            if not s.get("C", 0.0) >= C_MIN:
                failures.append(f"{name}: C = {s.get('C')} below {C_MIN:g}")
            if not abs(s["p_exit_mean_over_sigma_a"] - 1.0) <= EXIT_MEAN_TOL:
                failures.append(f"{name}: exit pressure {s['p_exit_mean_over_sigma_a']:.3f} sigma/a, "
                                f"not within {EXIT_MEAN_TOL:.0%}")
            if not s["p_exit_std_over_sigma_a"] <= EXIT_STD_MAX:
                failures.append(f"{name}: exit pressure std {s['p_exit_std_over_sigma_a']:.3f} sigma/a above "
                                f"{EXIT_STD_MAX:g}")
        elif abs(length / measured - 1.0) > MC_TOL:
            failures.append(f"{name}: L/d0 {length} against the measured {measured} "
                            f"({length / measured - 1.0:+.0%}, the target is {MC_TOL:.0%})")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("PASS")


if __name__ == "__main__":
    main()
