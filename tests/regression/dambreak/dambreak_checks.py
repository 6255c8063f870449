#!/usr/bin/env python3
"""Dam-break checks shared by the regression and validation tests (standard library only).

  obstacle-coarse: the dam break with an obstacle at a coarse spacing, short; surge front and
                   highest point over the obstacle against the fine legacy run's front.txt.
  martin-moyce:    the plain dam break; Z(T) against Martin & Moyce (1952).
  obstacle-legacy: (validation) a full-resolution sphjet run against the legacy run directory.

Each check runs `sphjet run` (unless --run-dir points at a finished run), then
`sphjet analyse`, prints a table with every number and its tolerance, and exits 0 (pass),
1 (fail) or 77 (skipped: reference data absent; CTest's SKIP_RETURN_CODE).
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys

SKIP = 77
FRONT_PARITY_TOL = 0.005  # relative; obstacle-legacy, see obstacle_legacy()
TOP_PARITY_TOL = 0.005


def sh(cmd):
    print("$", " ".join(cmd), flush=True)
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    tail = "\n".join(r.stdout.strip().split("\n")[-6:])
    print(tail, flush=True)
    if r.returncode != 0:
        print(f"FAILED (exit {r.returncode}): {' '.join(cmd)}")
        sys.exit(1)
    return r.stdout


def run_case(args, case, out, extra):
    if args.run_dir:
        return args.run_dir
    if os.path.isdir(out):
        shutil.rmtree(out)
    sh([args.sphjet, "run", case, "--out", out, "-j", str(args.threads), "--format", "legacy", "-q"] + extra)
    return out


def analyse(args, run_dir, csv_path, extra):
    sh([args.sphjet, "analyse", run_dir, "--csv", csv_path, "--front"] + extra)
    with open(csv_path) as f:
        return list(csv.DictReader(f))


def at_time(rows, t, tol=0.01):
    best = None
    for r in rows:
        if r["time"] and abs(float(r["time"]) - t) <= tol:
            if best is None or abs(float(r["time"]) - t) < abs(float(best["time"]) - t):
                best = r
    return best


def read_front_txt(path):
    """Legacy front.txt: frame itime time xfront_all xfront_floor xfront_floor4 zmax_obst n_obst n_out."""
    out = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            v = line.split()
            out.append(dict(time=float(v[2]), xfront_all=float(v[3]),
                            zmax_obst=None if v[6] == "nan" else float(v[6]), n_out=int(v[8])))
    return out


class Table:
    def __init__(self):
        self.fails = 0
        print(f"{'quantity':34s} {'t or T':>7s} {'sphjet':>9s} {'reference':>9s} {'diff':>9s} {'tolerance':>10s}  result")

    def check(self, name, t, ours, ref, tol, relative):
        if ours is None:
            print(f"{name:34s} {t:7.3f} {'missing':>9s} {ref:9.4f}  FAIL")
            self.fails += 1
            return
        d = (ours - ref) / ref if relative else ours - ref
        ok = abs(d) <= tol
        self.fails += 0 if ok else 1
        ds = f"{100 * d:+8.3f}%" if relative else f"{d:+9.4f}"
        ts = f"{100 * tol:8.2f}%" if relative else f"{tol:10.4f}"
        print(f"{name:34s} {t:7.3f} {ours:9.4f} {ref:9.4f} {ds:>9s} {ts:>10s}  {'ok' if ok else 'FAIL'}")


def fnum(r, key):
    return float(r[key]) if r and r.get(key) else None


def obstacle_coarse(args):
    """Reference: the fine (dx = 0.002) legacy run's front.txt. Tolerances (absolute, m): the
    front 3 coarse spacings, the tongue top over the obstacle 10; see
    cases/dambreak_obstacle/README.md."""
    front_txt = os.path.join(args.source, "tests", "regression", "dambreak", "legacy_obstacle_front.txt")
    ref = read_front_txt(front_txt)
    case = os.path.join(args.source, "cases", "dambreak_obstacle", "obstacle_wendland.toml")
    dx = args.dx
    out = run_case(args, case, os.path.join(args.work, "run"),
                   ["--set", f"resolution.dx={dx}", "--set", f"resolution.dz={dx}",
                    "--set", f"time.tmax={args.tmax}", "--set", "time.out=0.05", "--legacy-clock"])
    rows = analyse(args, out, os.path.join(args.work, "front.csv"), ["--obstacle", "0.292,0.316"])
    tab = Table()
    for r in ref:
        t = r["time"]
        if t < 0.04 or t > args.tmax + 1e-3:
            continue
        ours = at_time(rows, t)
        tab.check("surge front xfront_all [m]", t, fnum(ours, "xfront_all"), r["xfront_all"], args.front_tol, False)
        if r["zmax_obst"] is not None:
            tab.check("highest point over obstacle [m]", t, fnum(ours, "zmax_obst"), r["zmax_obst"],
                      args.height_tol, False)
    return tab.fails


def martin_moyce(args):
    data = os.path.join(args.shared, "data", "dambreak_front_martin_moyce_1952.csv")
    if not os.path.isfile(data):
        print(f"SKIPPED: {data} not found (the shared reference data sit beside the repository)")
        return None
    case = os.path.join(args.source, "cases", "dambreak", args.case)
    out = run_case(args, case, os.path.join(args.work, "run"), ["--tmax", str(args.tmax)])
    rows = analyse(args, out, os.path.join(args.work, "front.csv"), ["--column-width", str(args.a)])
    pts = sorted((float(r["T"]), float(r["Z"])) for r in rows if r["T"] and r["Z"])
    print(f"Martin & Moyce: run's Z read at T {args.shift:+g}; series {args.series or 'all'}; T <= {args.tmax_T:g}")
    tab = Table()
    with open(data) as f:
        exp = list(csv.DictReader(l for l in f if not l.startswith("#")))
    for e in exp:
        T, Z = float(e["T"]), float(e["Z"])
        if T > args.tmax_T or (args.series and e["series"] != args.series):
            continue
        zr = None
        for (t0, z0), (t1, z1) in zip(pts, pts[1:]):
            if t0 <= T + args.shift <= t1:
                zr = z0 + (z1 - z0) * (T + args.shift - t0) / (t1 - t0)
        tab.check(f"Z ({e['series']})", T, zr, Z, args.z_tol, True)
    return tab.fails


def obstacle_legacy(args):
    args.run_dir = args.run_dir or os.environ.get("SPHJET_OBSTACLE_RUN")
    legacy = os.path.join(args.shared, "legacy", "obstacle_wendland")
    if not os.path.isdir(legacy):
        print(f"SKIPPED: {legacy} not found (the legacy reference runs sit in ../shared beside the repository)")
        return None
    case = os.path.join(args.source, "cases", "dambreak_obstacle", "obstacle_wendland.txt")
    out = run_case(args, case, os.path.join(args.work, "run"), ["--legacy-clock"])
    ours = analyse(args, out, os.path.join(args.work, "ours.csv"),
                   ["--obstacle", "0.292,0.316", "--overlap-with", legacy])
    leg = analyse(args, legacy, os.path.join(args.work, "legacy.csv"), ["--obstacle", "0.292,0.316"])
    # Parity with legacy SPHysics on the same case at the same resolution (a regression check:
    # legacy is the code this one reproduces). Measured (cases/dambreak_obstacle/README.md,
    # the table under "Measures"): the surge front within 0.04% of legacy at every 0.05 s to
    # 0.30 s, the highest point over the obstacle within 0.01% at 0.20-0.30 s (below the 0.05%
    # that its four printed digits resolve). Tolerances about ten times those: 0.5% for both
    # (FRONT_PARITY_TOL, TOP_PARITY_TOL). What they catch: the cubic spline instead of
    # Wendland moves the top by 0.6-4% at 0.20-0.30 s (the same README), past 0.5%, though
    # its front by only 0.02-0.25%: the front alone is a weak witness of the model.
    tab = Table()
    for k in range(1, 7):
        t = 0.05 * k
        o, l = at_time(ours, t), at_time(leg, t)
        tab.check("surge front xfront_all (rel.)", t, fnum(o, "xfront_all"), fnum(l, "xfront_all"),
                  FRONT_PARITY_TOL, True)
        if k >= 4:
            tab.check("highest point over obstacle (rel.)", t, fnum(o, "zmax_obst"), fnum(l, "zmax_obst"),
                      TOP_PARITY_TOL, True)
    # The footprint of the fluid (cells of 2 dx) at every output to the end (0.6 s): it falls
    # as the splash and the breaking tongue decorrelate (measured 0.9875 at 0.30 s, 0.958 at
    # 0.6 s); at least 0.9 (--min-overlap) means the two runs put the fluid in the same cells
    # but for a tenth of them. A chaotic measure, so a physical bound, not ten times a scatter.
    for o in ours:
        if o["number" if "number" in o else "output"] != "0" and o.get("overlap"):
            tab.check("grid overlap (2 dx cells)", float(o["time"]), fnum(o, "overlap"), 1.0,
                      1.0 - args.min_overlap, False)
    return tab.fails


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("check", choices=["obstacle-coarse", "martin-moyce", "obstacle-legacy"])
    ap.add_argument("--sphjet", required=True)
    ap.add_argument("--source", required=True, help="repository root")
    ap.add_argument("--shared", help="the shared folder (default: SOURCE/../shared)")
    ap.add_argument("--work", required=True, help="scratch directory for the run")
    ap.add_argument("--run-dir", help="analyse this finished run instead of running")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--dx", type=float, default=0.004)
    ap.add_argument("--tmax", type=float, default=0.2)
    ap.add_argument("--front-tol", type=float, default=0.012)
    ap.add_argument("--height-tol", type=float, default=0.04)
    ap.add_argument("--case", default="dambreak_a25.toml")
    ap.add_argument("--a", type=float, default=0.05715)
    ap.add_argument("--tmax-T", type=float, default=3.0)
    ap.add_argument("--shift", type=float, default=0.0, help="compare the run's Z at T + SHIFT")
    ap.add_argument("--series", help="only this series of the Martin & Moyce data")
    ap.add_argument("--z-tol", type=float, default=0.05)
    ap.add_argument("--min-overlap", type=float, default=0.9)
    args = ap.parse_args()
    args.shared = args.shared or os.path.join(args.source, "..", "shared")
    os.makedirs(args.work, exist_ok=True)
    fails = {"obstacle-coarse": obstacle_coarse, "martin-moyce": martin_moyce,
             "obstacle-legacy": obstacle_legacy}[args.check](args)
    if fails is None:
        return SKIP
    print(f"{args.check}: {'PASS' if fails == 0 else f'FAIL ({fails} checks out of tolerance)'}")
    return 0 if fails == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
