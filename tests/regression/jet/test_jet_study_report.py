#!/usr/bin/python3
"""tools/jet_study.py on a fake study (synthetic jet.csv, drops.csv and run.log; no sphjet, no
snapshots): the report's numbers, its handling of missing and unfinished runs, and which
command `run` would give each run directory.

Checks, each with its reason:
1. table1.csv carries the paper's groups and eq 37 (Pourabedian et al. 2016, Table 1; the
   digest): We 0.34/2.01/2.78/4.34, Re 350/850/1000/1250 (the paper prints 1200 for the last,
   a misprint), Fr 0.22/0.54/0.64/0.80, eq 37 7.62/18.51/21.78/27.22, each to the 2 decimals
   printed there (tolerance 0.005 + 1e-9: the table's rounding).
2. Errors against eq 37 are (L - eq37)/eq37 in %, computed from the full-precision eq 37:
   ours from the synthetic L (within 1e-3 %, the CSV's 6 significant digits), the paper's
   from Table 1 (their magnitudes round to the digest's 13/1/14/10/7/6/11/3 %).
3. L/D0, its time and the head drop come from the first row with broken = 1, not a later
   one; the mean orifice speed uses only rows with jet_tip_over_d0 >= 1.
4. run.log: wall time summed over a resumed run's parts (10 + 20 s), particle-steps/s over all of
   them (each part's printed rate times its wall time, summed, over the summed wall time,
   to 1e-6: the report's digits); a run whose last part was stopped by a signal is
   unfinished even though sphjet writes `done:` then.
5. Missing runs are named on stdout and in table1.md, and the report still exits 0; figures
   are written (fig5 skipped: no snapshots).
6. `run --dry-run` resumes a run with a checkpoint, starts afresh (with --force) one with
   neither a finished log nor a checkpoint, and skips a finished one.
usage: test_jet_study_report.py   (exit 0 on success, 1 with a message on failure)
"""
import csv
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
TOOL = os.path.join(REPO, "tools", "jet_study.py")
# The tool plots with Debian's matplotlib under /usr/bin/python3 (README); ctest may run this
# file under another interpreter.
PY = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable

failures = []


def check(cond, msg):
    if not cond:
        failures.append(msg)


def close(a, b, tol):
    return a is not None and abs(a - b) <= tol


JET_HEADER = ("time,step,volume_out,flux,u_flux,u_orifice,broken,L,L_over_d0,jet_tip_over_d0,"
              "n_drops,head_drop_d_over_d0,largest_drop_d_over_d0")


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def jet_csv(rows):
    """rows: (time, step, u_flux, broken, L_over_d0, tip, n_drops, head) -> jet.csv text."""
    out = [JET_HEADER]
    for t, step, uf, b, l, tip, nd, head in rows:
        out.append(f"{t},{step},0,0,{uf},{uf},{b},{l * 0.01},{l},{tip},{nd},{head},{head}")
    return "\n".join(out) + "\n"


def log(parts, particles=1802):
    """parts: list of (kind 'starting'|'resuming', steps, wall, interrupted)."""
    lines, total = [], 0
    for kind, steps, wall, interrupted in parts:
        total += steps
        lines.append(f"sphjet 0.1.0 (abc) {kind}")
        lines.append("command: sphjet run ...")
        lines.append(f"case: cases/jet/jet.toml | particles {particles} (boundary 302, fluid "
                     f"{particles - 302}) | h = 0.0013 m, c0 = 20 m/s | kernel wendland | threads 2")
        if interrupted:
            lines.append(f"stopped by signal 2 at step {total} t = 0.05 s; checkpoint written: "
                         f"continue with `sphjet run --resume DIR`")
        lines.append(f"done: {steps} steps ({total} in all) to t = 0.0{total % 10}5 s (SPHysics "
                     f"clock 0.05 s) in {wall:.2f} s wall; {particles * steps / wall:.3g} "
                     f"particle-steps/s; 8 outputs; 0 particles left the domain")
    return "\n".join(lines) + "\n"


def main():
    with tempfile.TemporaryDirectory(prefix="jet_study_test_") as tmp:
        study(tmp)


def study(tmp):
    root = os.path.join(tmp, "root")
    sdir = os.path.join(root, "dx0.001")
    out = os.path.join(tmp, "report")

    # t1_wendland_u0.25: finished in two parts (10 s + 20 s), first breakup at row 3
    d = os.path.join(sdir, "t1_wendland_u0.25")
    write(os.path.join(d, "jet.csv"), jet_csv([
        (0.01, 100, 0.10, 0, 0.0, 0.5, 0, 0.0),      # tip < 1: not in the mean speed
        (0.02, 200, 0.25, 0, 0.0, 1.0, 0, 0.0),
        (0.03, 300, 0.26, 1, 20.0, 21.0, 2, 1.75),   # the first breakup
        (0.04, 400, 0.25, 1, 5.0, 22.0, 3, 0.5),     # a later one: not L
    ]))
    write(os.path.join(d, "drops.csv"),
          "time,step,drop,particles,area,d_eq_over_d0,xc,zc,s_max_over_d0\n"
          "0.03,300,0,40,4e-5,1.75,0.04,0.2,1\n0.03,300,1,5,5e-6,0.4,0.04,0.3,1\n"
          "0.04,400,0,3,3e-6,0.2,0.04,0.1,1\n")
    write(os.path.join(d, "run.log"), log([("starting", 1000, 10.0, True),
                                           ("resuming", 2000, 20.0, False)]))
    # t1_cubic_spline_u0.07: finished, breaks at L/D0 = 6.0
    d = os.path.join(sdir, "t1_cubic_spline_u0.07")
    write(os.path.join(d, "jet.csv"), jet_csv([(0.1, 10, 0.07, 0, 0, 2.0, 0, 0),
                                               (0.2, 20, 0.07, 1, 6.0, 7.0, 1, 1.9)]))
    write(os.path.join(d, "run.log"), log([("starting", 500, 5.0, False)]))
    # inv_wendland_u0.25: stopped by a signal, with a checkpoint: unfinished, `run` resumes it
    d = os.path.join(sdir, "inv_wendland_u0.25")
    write(os.path.join(d, "jet.csv"), jet_csv([(0.01, 100, 0.25, 0, 0, 0.5, 0, 0)]))
    write(os.path.join(d, "run.log"), log([("starting", 100, 1.0, True)]))
    write(os.path.join(d, "checkpoint.h5"), "fake")
    # phys_base: a start that died before its first checkpoint: `run` starts afresh, --force
    write(os.path.join(sdir, "phys_base", "run.log"), "sphjet 0.1.0 (abc) starting\n")

    p = subprocess.run([PY, TOOL, "report", "--root", root, "--dx", "0.001", "--out", out],
                       capture_output=True, text=True)
    check(p.returncode == 0, f"report exited {p.returncode}:\n{p.stdout}\n{p.stderr}")
    if p.returncode != 0:
        return
    with open(os.path.join(out, "table1.csv"), newline="") as f:
        rows = {(float(r["u0"]), r["kernel"]): r for r in csv.DictReader(f)}

    def num(r, k):
        return float(r[k]) if r[k] != "" else None

    # 1. groups and eq 37 against the paper's printed values
    paper = {0.07: (350, 0.34, 0.22, 7.62), 0.17: (850, 2.01, 0.54, 18.51),
             0.20: (1000, 2.78, 0.64, 21.78), 0.25: (1250, 4.34, 0.80, 27.22)}
    for u0, (re, we, fr, eq) in paper.items():
        for kernel in ("wendland", "cubic_spline"):
            r = rows.get((u0, kernel))
            check(r is not None, f"table1.csv: no row u0 = {u0} {kernel}")
            if r is None:
                continue
            for key, want in (("Re", re), ("We", we), ("Fr", fr), ("L_over_d0_eq37", eq)):
                check(close(num(r, key), want, 0.005 + 1e-9),
                      f"table1.csv u0 = {u0} {kernel}: {key} = {r[key]}, the paper {want}")
    # 2. errors
    eq37 = 13 * math.sqrt(4.340277777) * (1 + 3 * math.sqrt(4.340277777) / 1250)
    r = rows[(0.25, "wendland")]
    check(close(num(r, "err_vs_eq37_pct"), 100 * (20.0 - eq37) / eq37, 1e-3),
          f"u0 = 0.25 Wendland: error {r['err_vs_eq37_pct']}, expected {100 * (20 - eq37) / eq37:.4f}")
    check(close(num(r, "paper_err_vs_eq37_pct"), 100 * (28.10 - eq37) / eq37, 1e-3),
          f"u0 = 0.25 Wendland: paper error {r['paper_err_vs_eq37_pct']}")
    r7 = rows[(0.07, "cubic_spline")]
    eq7 = float(r7["L_over_d0_eq37"])
    check(close(num(r7, "err_vs_eq37_pct"), 100 * (6.0 - eq7) / eq7, 1e-3),
          f"u0 = 0.07 spline: error {r7['err_vs_eq37_pct']}")
    digest = {(0.07, "cubic_spline"): 13, (0.07, "wendland"): 1, (0.17, "cubic_spline"): 14,
              (0.17, "wendland"): 10, (0.20, "cubic_spline"): 7, (0.20, "wendland"): 6,
              (0.25, "cubic_spline"): 11, (0.25, "wendland"): 3}
    for key, pct in digest.items():
        got = abs(num(rows[key], "paper_err_vs_eq37_pct"))
        check(round(got) == pct or math.floor(got) == pct,
              f"paper error {key}: |{got:.2f}|% does not print as the digest's {pct}%")
    # 3. first breakup, head drop, orifice speed
    check(close(num(r, "L_over_d0"), 20.0, 1e-9), f"L/D0 {r['L_over_d0']}: not the first breakup's 20")
    check(close(num(r, "t_break"), 0.03, 1e-9), f"t_break {r['t_break']}, expected 0.03")
    check(close(num(r, "head_drop_d_over_d0"), 1.75, 1e-9), f"head drop {r['head_drop_d_over_d0']}")
    check(close(num(r, "u_flux_mean"), (0.25 + 0.26 + 0.25) / 3, 1e-6),
          f"mean orifice speed {r['u_flux_mean']}, expected {(0.25 + 0.26 + 0.25) / 3:.6f}")
    check(close(num(r, "u_flux_vs_u0_pct"), 100 * ((0.76 / 3) - 0.25) / 0.25, 1e-3),
          f"orifice speed vs u0 {r['u_flux_vs_u0_pct']}%")
    # 4. run.log
    check(close(num(r, "wall_s"), 30.0, 1e-9), f"wall {r['wall_s']} s, expected 10 + 20")
    # each part's rate as its log prints it (3 digits), weighted by its wall time
    rate = (float(f"{1802 * 1000 / 10.0:.3g}") * 10.0
            + float(f"{1802 * 2000 / 20.0:.3g}") * 20.0) / 30.0
    check(close(num(r, "particle_steps_per_s"), rate, 1e-6 * rate),
          f"particle-steps/s {r['particle_steps_per_s']}, expected {rate:.0f}")
    check(r["particles"] == "1802", f"particles {r['particles']}")
    check(r["status"] == "finished", f"u0 = 0.25 Wendland status {r['status']!r}")
    with open(os.path.join(out, "inviscid.csv"), newline="") as f:
        inv = {float(x["u0"]): x for x in csv.DictReader(f)}
    check(inv[0.25]["status"] == "unfinished",
          f"interrupted inviscid run: status {inv[0.25]['status']!r}, expected 'unfinished'")
    check(close(float(inv[0.25]["L_over_d0_13sqrtWe"]), 13 * math.sqrt(4.340277777), 1e-4),
          f"inviscid reference {inv[0.25]['L_over_d0_13sqrtWe']}")
    # 5. missing runs named; files written
    for name in ("t1_wendland_u0.07", "t1_cubic_spline_u0.25", "phys_nogravity", "phys_fine"):
        check(name in p.stdout and "missing" in p.stdout, f"stdout does not name missing run {name}")
    with open(os.path.join(out, "table1.md")) as f:
        md = f.read()
    check("Missing runs: t1_wendland_u0.07" in md, "table1.md does not list the missing runs")
    check("| 0.25 | 1250 | 4.34 |" in md and "27.22" in md, "table1.md: no u0 = 0.25 row with eq 37")
    check("Summed wall time of the study: 36.0 s" in md,   # 10 + 20 + 5 + the interrupted 1 s
          "table1.md: summed wall time is not 36.0 s (10 + 20 + 5 + 1)")
    for name in ("physics.md", "physics.csv", "fig6_L_vs_Re.png", "fig7_L_vs_We.png",
                 "fig8_inviscid.png"):
        check(os.path.isfile(os.path.join(out, name)), f"report did not write {name}")
    check(not os.path.exists(os.path.join(out, "fig5_snapshots.png")) and "fig5" in p.stdout,
          "fig5 should be skipped (no snapshots) and say so")

    # 6. what `run` would do
    p = subprocess.run([PY, TOOL, "run", "--root", root, "--dry-run", "--sphjet", "/nonexistent",
                        "--only", "t1_wendland_u0.25", "inv_wendland_u0.25", "phys_base",
                        "phys_nogravity"], capture_output=True, text=True)
    check(p.returncode == 0, f"run --dry-run exited {p.returncode}: {p.stderr}")
    o = p.stdout
    check("t1_wendland_u0.25: finished, skipped" in o, f"finished run not skipped:\n{o}")
    check(f"run --resume {os.path.join(sdir, 'inv_wendland_u0.25')} -j 2" in o,
          f"interrupted run with a checkpoint not resumed:\n{o}")
    check(f"--out {os.path.join(sdir, 'phys_base')} -j 2 --force --set resolution.dx=0.001" in o,
          f"aborted start without checkpoint not restarted with --force:\n{o}")
    check("--out " + os.path.join(sdir, "phys_nogravity") + " -j 2 --set resolution.dx=0.001 "
          "--set nozzle.u0=0.25 --set numerics.kernel=wendland --set gravity.gz=0" in o,
          f"new run phys_nogravity: wrong command:\n{o}")
    check("[4/4]" in o, f"progress counts: expected [4/4] in\n{o}")

    # 7. a binary that cannot be started (here: executable, but not a program; as when a
    # build replaces it while a study runs): a message naming it, exit 2, runs kept
    bad = os.path.join(root, "not_a_program")
    with open(bad, "w") as f:
        f.write("not a program\n")
    os.chmod(bad, 0o755)
    p = subprocess.run([PY, TOOL, "run", "--root", root, "--sphjet", bad, "--only",
                        "phys_nogravity"], capture_output=True, text=True)
    check(p.returncode == 2 and f"cannot start {bad}" in p.stderr and "Traceback" not in p.stderr,
          f"unstartable binary: exit {p.returncode}, stderr:\n{p.stderr}")
    check(os.path.isfile(os.path.join(sdir, "t1_wendland_u0.25", "run.log")),
          "unstartable binary: a finished run's files went missing")


if __name__ == "__main__":
    main()
    if failures:
        print("test_jet_study_report: FAILED", file=sys.stderr)
        for m in failures:
            print(f"  - {m}", file=sys.stderr)
        sys.exit(1)
    print("test_jet_study_report: all checks passed")
