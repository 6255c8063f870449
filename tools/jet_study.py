#!/usr/bin/python3
"""The jet study of Pourabedian, Omidvar & Morad (2016), section 3-2: run it, then tabulate and
plot it (Table 1, figures 5-8, and what breaks a planar 2D jet).

Usage (Debian's python3 has numpy, matplotlib and h5py):
  /usr/bin/python3 tools/jet_study.py run [--root runs/jet_study] [--dx 0.001]
      [--set-name table1 inviscid physics] [--only RUN ...] [--threads 2]
      [--sphjet build/cpp_driver/sphjet] [--dry-run]
  /usr/bin/python3 tools/jet_study.py report [--root runs/jet_study] [--dx 0.001] [--out cases/jet]

The plan: `--set` overrides on the base case cases/jet/jet.toml, every run at resolution.dx = DX
(default 1 mm, D0/dx = 10), in ROOT/dxDX/NAME so that runs at different dx never mix:
  table1    t1_{wendland,cubic_spline}_u{0.07,0.17,0.2,0.25}: nozzle.u0, numerics.kernel
  inviscid  inv_wendland_u{...}: the same u0, Wendland, fluid.mu=0 (figure 8)
  physics   phys_base (u0 = 0.25, Wendland), phys_nogravity (gravity.gz=0),
            phys_nosigma (surface_tension.sigma=0), phys_fine (resolution.dx = DX/2)

`run` runs what is missing, one run at a time, resumable, a blow-up counted as a result
(tools/study_runs.py says how; its runs' locks are ROOT/dxDX/.NAME.lock). A hidden --tmax T is passed to
sphjet as --tmax (short plumbing checks; use a scratch --root: such runs count as finished).

`report` reads the run directories that exist (missing ones are listed, not fatal) and writes
into OUT: table1.csv/.md (+ inviscid.csv), physics.csv/.md, fig5_snapshots.png,
fig6_L_vs_Re.png, fig7_L_vs_We.png, fig8_inviscid.png. Groups as the paper computes them
(R = D0/2): We = rho u0^2 R / sigma, Re = rho u0 R / mu, Oh = sqrt(We)/Re, Fr = u0/sqrt(g D0);
eq 37: L/D0 = 13 sqrt(We) (1 + 3 Oh). Errors are signed, (L - eq37)/eq37; the paper prints
their magnitude. L/D0 is the first row of jet.csv with broken = 1.

Defaults of --root, --out and --sphjet are relative to the repository root (this file's ..);
paths given on the command line are taken as given.
"""
import csv
import math
import os
import sys

from study_runs import (KERNELS, StudyError, add_run_arguments, blew_up, dispatch, drops_at, first_breakup, fmt,
                        md_table, open_report, read_csv, run_all, run_summary, select_runs, shown, study_parser)

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BASE_CASE = os.path.join("cases", "jet", "jet.toml")

# The paper's data (DIGEST.md section 3) and constants.
RHO, MU, SIGMA, D0, G = 1000.0, 1.0e-3, 0.072, 0.01, 9.81
U0S = (0.07, 0.17, 0.20, 0.25)
PAPER_L = {"cubic_spline": dict(zip(U0S, (6.61, 15.83, 20.22, 24.17))),
           "wendland": dict(zip(U0S, (7.73, 16.64, 23.02, 28.10)))}
PAPER_HEAD_DROP, RAYLEIGH_HEAD_DROP = 1.98, 1.89   # D/D0, fig 5 (u0 = 0.25, Wendland)
PAPER_T_BREAK = 0.78                                # s, fig 5
KERNEL_LABEL = {"wendland": "Wendland", "cubic_spline": "cubic spline"}


# ---------------------------------------------------------------- physics of the paper
def groups(u0):
    """u0 -> dict Re, We, Oh, Fr, eq37 as the paper computes them (radius-based)."""
    r = D0 / 2
    we = RHO * u0 ** 2 * r / SIGMA
    re = RHO * u0 * r / MU
    oh = math.sqrt(we) / re
    return {"Re": re, "We": we, "Oh": oh, "Fr": u0 / math.sqrt(G * D0),
            "eq37": 13.0 * math.sqrt(we) * (1.0 + 3.0 * oh)}


def rel_err_pct(value, ref):
    return None if value is None else 100.0 * (value - ref) / ref


# ---------------------------------------------------------------- the plan
def u0_tag(u0):
    return f"u{u0:g}"


def plan(dx):
    """-> list of (set name, run name, [key=value overrides]) at study resolution dx."""
    runs = []
    for kernel in KERNELS:
        for u0 in U0S:
            runs.append(("table1", f"t1_{kernel}_{u0_tag(u0)}",
                         [f"nozzle.u0={u0:g}", f"numerics.kernel={kernel}"]))
    for u0 in U0S:
        runs.append(("inviscid", f"inv_wendland_{u0_tag(u0)}",
                     [f"nozzle.u0={u0:g}", "numerics.kernel=wendland", "fluid.mu=0"]))
    base = ["nozzle.u0=0.25", "numerics.kernel=wendland"]
    runs.append(("physics", "phys_base", list(base)))
    runs.append(("physics", "phys_nogravity", base + ["gravity.gz=0"]))
    runs.append(("physics", "phys_nosigma", base + ["surface_tension.sigma=0"]))
    runs.append(("physics", "phys_fine", base + [f"resolution.dx={dx / 2:g}"]))
    # every run gets the study dx unless it names its own
    out = []
    for s, name, sets in runs:
        if not any(o.startswith("resolution.dx=") for o in sets):
            sets = [f"resolution.dx={dx:g}"] + sets
        out.append((s, name, sets))
    return out


SET_NAMES = ("table1", "inviscid", "physics")
PHYSICS_CHANGE = {"phys_base": "the case as is", "phys_nogravity": "gravity.gz = 0",
                  "phys_nosigma": "surface_tension.sigma = 0", "phys_fine": "dx halved"}


def study_dir(root, dx):
    return os.path.join(root, f"dx{dx:g}")


# ---------------------------------------------------------------- run
def cmd_run(args):
    root = args.root
    sdir = study_dir(root, args.dx)
    case = os.path.join(REPO, BASE_CASE)
    names = args.set_name or list(SET_NAMES)
    todo = select_runs(plan(args.dx), names, args.only, args.sphjet, args.dry_run)
    if not os.path.isfile(case):
        raise StudyError(f"{case}: base case not found")

    title = (f"jet study: {len(todo)} run(s) in {sdir} (D0/dx = {D0 / args.dx:g}, "
             f"sets {', '.join(names)})")
    return run_all([(name, sets) for _set, name, sets in todo], sdir, case, args.sphjet,
                   args.threads, args.tmax, args.dry_run, "jet_study.py run", title, REPO, args.parallel)


# ---------------------------------------------------------------- report: reading a run
def case_value(toml, key):
    """'section.key' from the run's case.toml dict (fluid.mu from nu * rho0)."""
    sec, _, k = key.partition(".")
    s = toml.get(sec, {})
    if k in s:
        return s[k]
    if key == "fluid.mu" and "nu" in s:
        return s["nu"] * s.get("rho0", RHO)
    return None


def check_case(run_dir, sets):
    """Plan overrides against the run's case.toml; -> list of mismatch messages."""
    path = os.path.join(run_dir, "case.toml")
    if not os.path.isfile(path):
        return []
    try:
        import tomllib
        with open(path, "rb") as f:
            toml = tomllib.load(f)
    except Exception as e:   # noqa: BLE001 (a note in the report, not a failure)
        return [f"{path}: unreadable ({e})"]
    bad = []
    for s in sets:
        key, _, want = s.partition("=")
        have = case_value(toml, key)
        if have is None:
            continue
        try:
            same = math.isclose(float(have), float(want), rel_tol=1e-9, abs_tol=1e-12)
        except (TypeError, ValueError):
            same = str(have) == want
        if not same:
            bad.append(f"{path}: {key} = {have}, the plan says {want}")
    return bad


JET_COLUMNS = ("time", "step", "broken", "L_over_d0", "u_flux", "jet_tip_over_d0", "n_drops",
               "head_drop_d_over_d0")


def read_run(run_dir, sets):
    """-> dict with status and the numbers of one run (status 'missing' if no directory)."""
    r = {"dir": run_dir, "status": "missing", "t_break": None, "L_over_d0": None,
         "head_drop": None, "n_drops": None, "drops_d": None, "u_flux_mean": None,
         "notes": [], "particles": None, "wall_s": None, "particle_steps_per_s": None,
         "finished": False}
    r["notes"] += check_case(run_dir, sets)  # none where the run has no case.toml

    def first_and_flux(rows):
        return (first_breakup(rows),
                [float(x["u_flux"]) for x in rows if float(x["jet_tip_over_d0"]) >= 1.0])

    got = run_summary(run_dir, r, first_and_flux, need=JET_COLUMNS)
    if got is None:
        return r
    first, flux = got
    r["u_flux_mean"] = sum(flux) / len(flux) if flux else None
    if first is not None:
        r["t_break"] = float(first["time"])
        r["L_over_d0"] = float(first["L_over_d0"])
        r["head_drop"] = float(first["head_drop_d_over_d0"])
        r["n_drops"] = int(float(first["n_drops"]))
        drops_csv = os.path.join(run_dir, "drops.csv")
        if os.path.isfile(drops_csv):
            try:
                d = drops_at(read_csv(drops_csv), first["step"])
                r["drops_d"] = sorted((float(x["d_eq_over_d0"]) for x in d), reverse=True)
            except (ValueError, KeyError) as e:
                r["notes"].append(f"{drops_csv}: {e}")
    boom = blew_up(run_dir)
    if boom:
        import re
        m = re.search(r"\(t = ([-+0-9.eE]+) s\): ([^;]+)", boom)
        when = f" at t = {float(m.group(1)):.3f} s ({m.group(2)})" if m else ""
        r["status"] = ("broken, then blew up" if first is not None else "blew up") + when
        r["notes"].append(f"{os.path.basename(run_dir)}: {boom}")
    elif r["finished"]:
        r["status"] = "finished" if first is not None else "finished, not broken"
    else:
        r["status"] = "broken, unfinished" if first is not None else "unfinished"
    return r


# ---------------------------------------------------------------- report: tables
def with_err(value, ref):
    """'L (+e%)' or '-' for a Markdown cell."""
    return "-" if value is None else f"{value:.2f} ({rel_err_pct(value, ref):+.0f}%)"


def write_csv(path, header, rows):
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        for row in rows:
            w.writerow(["" if v is None else (f"{v:.6g}" if isinstance(v, float) else v)
                        for v in row])
    os.replace(tmp, path)


def write_text(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def uflux_pct(r, u0):
    return rel_err_pct(r["u_flux_mean"], u0)


def report_tables(out, runs, dx, sdir):
    res = f"D0/dx = {D0 / dx:g} (dx = {dx * 1000:g} mm)"
    # table1.csv: one row per (u0, kernel)
    header = ["u0", "kernel", "Re", "We", "Oh", "Fr", "L_over_d0_eq37", "L_over_d0",
              "err_vs_eq37_pct", "paper_L_over_d0", "paper_err_vs_eq37_pct", "t_break",
              "head_drop_d_over_d0", "paper_head_drop_d_over_d0", "rayleigh_head_drop_d_over_d0",
              "u_flux_mean", "u_flux_vs_u0_pct", "status", "wall_s", "particles",
              "particle_steps_per_s", "dx", "run"]
    rows = []
    for u0 in U0S:
        g = groups(u0)
        for kernel in KERNELS:
            r = runs[f"t1_{kernel}_{u0_tag(u0)}"]
            p = PAPER_L[kernel][u0]
            rows.append([u0, kernel, g["Re"], g["We"], g["Oh"], g["Fr"], g["eq37"],
                         r["L_over_d0"], rel_err_pct(r["L_over_d0"], g["eq37"]), p,
                         rel_err_pct(p, g["eq37"]), r["t_break"], r["head_drop"],
                         PAPER_HEAD_DROP if (kernel == "wendland" and u0 == 0.25) else None,
                         RAYLEIGH_HEAD_DROP, r["u_flux_mean"], uflux_pct(r, u0), r["status"],
                         r["wall_s"], r["particles"], r["particle_steps_per_s"], dx,
                         os.path.basename(r["dir"])])
    write_csv(os.path.join(out, "table1.csv"), header, rows)

    inv_header = ["u0", "We", "Oh_viscous", "L_over_d0_13sqrtWe", "L_over_d0", "err_vs_13sqrtWe_pct",
                  "t_break", "head_drop_d_over_d0", "u_flux_mean", "u_flux_vs_u0_pct", "status",
                  "wall_s", "particles", "particle_steps_per_s", "dx", "run"]
    inv_rows = []
    for u0 in U0S:
        g = groups(u0)
        r = runs[f"inv_wendland_{u0_tag(u0)}"]
        ref = 13.0 * math.sqrt(g["We"])
        inv_rows.append([u0, g["We"], g["Oh"], ref, r["L_over_d0"],
                         rel_err_pct(r["L_over_d0"], ref), r["t_break"], r["head_drop"],
                         r["u_flux_mean"], uflux_pct(r, u0), r["status"], r["wall_s"],
                         r["particles"], r["particle_steps_per_s"], dx,
                         os.path.basename(r["dir"])])
    write_csv(os.path.join(out, "inviscid.csv"), inv_header, inv_rows)

    # table1.md
    md = [f"# Table 1: jet breakup length, ours at {res} against the paper\n\n",
          f"Runs: `{shown(sdir, REPO)}` (tools/jet_study.py; base case {BASE_CASE}). L/D0 is the first "
          "breakup (jet.csv, first row with broken = 1). Errors are signed, (L - eq 37)/eq 37; "
          "the paper prints their magnitude. Groups radius-based as the paper: "
          "We = rho u0^2 R/sigma, Re = rho u0 R/mu, Fr = u0/sqrt(g D0), "
          "eq 37: L/D0 = 13 sqrt(We)(1 + 3 Oh).\n\n"]
    t = []
    for u0 in U0S:
        g = groups(u0)
        rs, rw = runs[f"t1_cubic_spline_{u0_tag(u0)}"], runs[f"t1_wendland_{u0_tag(u0)}"]
        ps, pw = PAPER_L["cubic_spline"][u0], PAPER_L["wendland"][u0]
        t.append([f"{u0:g}", f"{g['Re']:.0f}", f"{g['We']:.2f}", f"{g['Oh']:.5f}", f"{g['Fr']:.2f}",
                  f"{g['eq37']:.2f}",
                  with_err(rs["L_over_d0"], g["eq37"]), with_err(rw["L_over_d0"], g["eq37"]),
                  with_err(ps, g["eq37"]), with_err(pw, g["eq37"])])
    md.append(md_table(["u0 (m/s)", "Re", "We", "Oh", "Fr", "L/D0 eq 37", "ours spline (err)",
                        "ours Wendland (err)", "paper spline (err)", "paper Wendland (err)"], t))
    md.append("\n## Per run\n\nFirst breakup time, head drop at first breakup (paper: 1.98 D0 "
              "at u0 = 0.25 m/s, Wendland, t = 0.78 s; Rayleigh: 1.89 D0), mean orifice speed "
              "(jet.csv u_flux over rows with jet_tip_over_d0 >= 1) against u0, and cost "
              "(run.log; wall time summed over a resumed run's parts).\n\n")
    t = []
    all_runs = [(f"t1_{k}_{u0_tag(u0)}", u0) for k in KERNELS for u0 in U0S] + \
               [(f"inv_wendland_{u0_tag(u0)}", u0) for u0 in U0S] + \
               [(n, 0.25) for n in PHYSICS_CHANGE]
    for name, u0 in all_runs:
        r = runs[name]
        t.append([name, r["status"], fmt(r["t_break"], ".4f"), fmt(r["L_over_d0"]),
                  fmt(r["head_drop"]), fmt(r["u_flux_mean"], ".4f"),
                  fmt(uflux_pct(r, u0), "+.2f"), fmt(r["wall_s"], ".1f"),
                  fmt(r["particles"], "d"), fmt(r["particle_steps_per_s"], ".3g")])
    md.append(md_table(["run", "status", "t break (s)", "L/D0", "head drop D/D0",
                        "mean orifice speed (m/s)", "vs u0 (%)", "wall (s)", "particles",
                        "particle-steps/s"], t))
    walls = [runs[n]["wall_s"] for n, _ in all_runs if runs[n]["wall_s"] is not None]
    missing = [n for n, _ in all_runs if runs[n]["status"] == "missing"]
    md.append(f"\nSummed wall time of the study: {sum(walls):.1f} s ({sum(walls) / 3600:.2f} h) "
              f"over {len(walls)} run(s) with a `done:` line.\n")
    md.append(f"Missing runs: {', '.join(missing) if missing else 'none'}.\n")
    md.append("\n## Inviscid runs (figure 8; fluid.mu = 0, Wendland)\n\n")
    t = []
    for u0 in U0S:
        g = groups(u0)
        r = runs[f"inv_wendland_{u0_tag(u0)}"]
        ref = 13.0 * math.sqrt(g["We"])
        t.append([f"{u0:g}", f"{g['We']:.2f}", f"{ref:.2f}", fmt(r["L_over_d0"]),
                  fmt(rel_err_pct(r["L_over_d0"], ref), "+.0f"), r["status"]])
    md.append(md_table(["u0 (m/s)", "We", "13 sqrt(We)", "ours L/D0", "err (%)", "status"], t))
    notes = [n for name, _ in all_runs for n in runs[name]["notes"]]
    if notes:
        md.append("\n## Notes\n\n" + "".join(f"- {n}\n" for n in notes))
    write_text(os.path.join(out, "table1.md"), "".join(md))

    # physics
    header = ["run", "change", "dx", "status", "t_break", "L_over_d0", "n_drops",
              "drops_d_over_d0", "head_drop_d_over_d0", "u_flux_mean", "wall_s", "particles"]
    rows, t = [], []
    for name, change in PHYSICS_CHANGE.items():
        r = runs[name]
        rdx = dx / 2 if name == "phys_fine" else dx
        drops = " ".join(f"{d:.2f}" for d in r["drops_d"]) if r["drops_d"] else None
        rows.append([name, change, rdx, r["status"], r["t_break"], r["L_over_d0"], r["n_drops"],
                     drops, r["head_drop"], r["u_flux_mean"], r["wall_s"], r["particles"]])
        t.append([name, change, f"{D0 / rdx:g}", r["status"], fmt(r["t_break"], ".4f"),
                  fmt(r["L_over_d0"]), fmt(r["n_drops"], "d"), drops or "-", fmt(r["head_drop"]),
                  fmt(r["wall_s"], ".1f")])
    write_csv(os.path.join(out, "physics.csv"), header, rows)
    write_text(os.path.join(out, "physics.md"),
               f"# What breaks a planar 2D jet: u0 = 0.25 m/s, Wendland, {res} unless said\n\n"
               f"Runs: `{shown(sdir, REPO)}`. At the first breakup (jet.csv, first row with broken = 1): its "
               "time, L/D0, the number of drops and their equivalent diameters (drops.csv, "
               "same step, largest first), the head drop.\n\n" +
               md_table(["run", "change", "D0/dx", "status", "t break (s)", "L/D0", "drops",
                         "drop D/D0", "head drop D/D0", "wall (s)"], t))
    return missing, sum(walls)


# ---------------------------------------------------------------- report: figures
def snapshot_frames(run_dir):
    import h5py
    frames = []
    for n in sorted(os.listdir(run_dir)):
        if n.startswith("snap_") and n.endswith(".h5"):
            p = os.path.join(run_dir, n)
            with h5py.File(p, "r") as f:
                frames.append((float(f.attrs["time"]), p))
    return sorted(frames)


def load_snapshot(path):
    import h5py
    import numpy as np
    with h5py.File(path, "r") as f:
        g = f["particles"]
        d = {c: np.asarray(g[c][()]) for c in ("x", "z", "p", "kind", "active")}
    fluid = (d["kind"] == 2) & (d["active"] != 0)
    bnd = d["kind"] != 2
    return d, fluid, bnd


def fig5(out, run, dx, plt):
    """Snapshots of the u0 = 0.25 Wendland run, up to and after the first breakup."""
    import numpy as np
    if run["status"] == "missing":
        return "run missing"
    frames = snapshot_frames(run["dir"])
    if not frames:
        return "no snap_*.h5 in the run"
    t_last = frames[-1][0]
    tb = run["t_break"]
    if tb is None:
        targets = list(np.linspace(t_last / 6, t_last, 6))
    else:
        targets = [tb * k / 5 for k in range(1, 6)] + [min(tb + 0.04, t_last)]
    chosen = []
    for t in targets:
        f = min(frames, key=lambda fr: abs(fr[0] - t))
        if f not in chosen:
            chosen.append(f)
    data = [(t, load_snapshot(p)) for t, p in chosen]
    pf = np.concatenate([d["p"][fl] for _, (d, fl, _) in data])
    vmin, vmax = (np.percentile(pf, 1), np.percentile(pf, 99)) if pf.size else (0, 1)
    zf = np.concatenate([d["z"][fl] for _, (d, fl, _) in data])
    xf = np.concatenate([d["x"][fl] for _, (d, fl, _) in data])
    # the nozzle: read from the run's case.toml when there, else the base case values
    x0, z0, up = 0.04, 0.41, 3 * D0
    try:
        import tomllib
        with open(os.path.join(run["dir"], "case.toml"), "rb") as f:
            nz = tomllib.load(f).get("nozzle", {})
        x0, z0 = nz.get("x0", x0), nz.get("z0", z0)
    except (OSError, ValueError):
        pass
    zlo = min(zf.min() if zf.size else z0 - D0, z0 - D0) - 0.5 * D0
    zhi = z0 + up
    half = max(2 * D0, (np.abs(xf - x0).max() + 0.5 * D0) if xf.size else 2 * D0)
    n = len(data)
    zr, xr = zhi - zlo, 2 * half
    ax_h = min(8.0, max(3.0, 2.2 * zr / xr))          # inches per panel, equal aspect
    ax_w = min(3.0, max(1.6, ax_h * xr / zr))
    fig, axes = plt.subplots(1, n, figsize=(n * ax_w + 2.0, ax_h + 1.6), sharey=True,
                             squeeze=False)
    # marker about one spacing across (equal aspect: the tighter of the two scales)
    pts_per_m = 72 * min(ax_h / zr, ax_w / xr)
    s = max(0.5, (0.9 * dx * pts_per_m) ** 2)
    sc = None
    for ax, (t, (d, fl, bnd)) in zip(axes[0], data):
        ax.scatter(d["x"][bnd], d["z"][bnd], s=s, c="0.6", lw=0)
        sc = ax.scatter(d["x"][fl], d["z"][fl], s=s, c=d["p"][fl], cmap="viridis", vmin=vmin,
                        vmax=vmax, lw=0)
        ax.axhline(z0, color="k", ls=":", lw=0.7)
        ax.set_xlim(x0 - half, x0 + half)
        ax.set_ylim(zlo, zhi)
        ax.set_aspect("equal")
        tag = ""
        if tb is not None:
            tag = " (after breakup)" if t > tb + 1e-9 else (" (breakup)" if abs(t - tb) < 1e-9 else "")
        ax.set_title(f"t = {t:.3f} s{tag}", fontsize=9)
        ax.set_xlabel("x [m]")
        ax.tick_params(labelsize=7)
        ax.locator_params(axis="x", nbins=3)
    axes[0][0].set_ylabel("z [m] (dotted: orifice)")
    fig.subplots_adjust(left=0.9 / (n * ax_w + 2.0), right=0.88, bottom=0.8 / (ax_h + 1.6),
                        top=1 - 0.8 / (ax_h + 1.6), wspace=0.15)
    cb = fig.colorbar(sc, ax=list(axes[0]), shrink=0.8, pad=0.02)
    cb.set_label("pressure p [Pa]")
    brk = (f"first breakup at t = {tb:.3f} s, L/D0 = {run['L_over_d0']:.2f} "
           f"(paper: t = {PAPER_T_BREAK} s, L/D0 = 28.10)") if tb is not None else "not broken"
    fig.canvas.draw()   # equal aspect shrinks the panels: put the title just above them
    top = max(ax.get_position().y1 for ax in axes[0])
    fig.text(0.5 * (axes[0][0].get_position().x0 + axes[0][-1].get_position().x1), top + 0.06,
             f"Jet u0 = 0.25 m/s, Wendland, D0/dx = {D0 / dx:g}: {brk}\n"
             "fluid coloured by pressure, boundary particles grey", fontsize=10, ha="center",
             va="bottom")
    fig.savefig(os.path.join(out, "fig5_snapshots.png"), dpi=110, bbox_inches="tight")
    plt.close(fig)
    return None


def eq37_curve():
    import numpy as np
    u = np.linspace(0.05, 0.27, 100)
    return u, [groups(x) for x in u]


def finish_L_figure(fig, ax, xlabel, title, path, plt):
    """Axes, legend and title of an L/D0 figure, then the PNG."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel("breakup length L/D0 [-]")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def fig_L(out, runs, dx, plt, xkey, fname, xlabel):
    u, gs = eq37_curve()
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    ax.plot([g[xkey] for g in gs], [g["eq37"] for g in gs], "k-",
            label="eq 37: 13 sqrt(We)(1 + 3 Oh)")
    style = {"wendland": ("o", "C0"), "cubic_spline": ("s", "C3")}
    for kernel in KERNELS:
        mk, col = style[kernel]
        xs = [groups(u0)[xkey] for u0 in U0S]
        ax.plot(xs, [PAPER_L[kernel][u0] for u0 in U0S], mk, mfc="none", color=col, ms=8,
                label=f"paper, {KERNEL_LABEL[kernel]}")
        ours = [(groups(u0)[xkey], runs[f"t1_{kernel}_{u0_tag(u0)}"]["L_over_d0"]) for u0 in U0S]
        ours = [p for p in ours if p[1] is not None]
        if ours:
            ax.plot(*zip(*ours), mk, color=col, ms=7,
                    label=f"ours, {KERNEL_LABEL[kernel]} ({len(ours)} of {len(U0S)} runs)")
    finish_L_figure(fig, ax, xlabel, f"Breakup length against {xkey} (ours at D0/dx = {D0 / dx:g}; "
                    "paper: 80175 particles)", os.path.join(out, fname), plt)


def fig8(out, runs, dx, plt):
    import numpy as np
    we = np.linspace(0.2, 4.8, 100)
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    ax.plot(we, 13 * np.sqrt(we), "k-", label="eq 37 at Oh = 0: 13 sqrt(We)")
    inv = [(groups(u0)["We"], runs[f"inv_wendland_{u0_tag(u0)}"]["L_over_d0"]) for u0 in U0S]
    inv = [p for p in inv if p[1] is not None]
    if inv:
        ax.plot(*zip(*inv), "D", color="C2", ms=7,
                label=f"ours, inviscid, Wendland ({len(inv)} of {len(U0S)} runs)")
    vis = [(groups(u0)["We"], runs[f"t1_wendland_{u0_tag(u0)}"]["L_over_d0"]) for u0 in U0S]
    vis = [p for p in vis if p[1] is not None]
    if vis:
        ax.plot(*zip(*vis), "o", mfc="none", color="C0", ms=7,
                label="ours, viscous (mu = 1e-3 Pa s), Wendland")
    finish_L_figure(fig, ax, "Weber number We = rho u0^2 (D0/2) / sigma [-]",
                    f"Inviscid jets (fluid.mu = 0), ours at D0/dx = {D0 / dx:g}\n(the paper's "
                    "MPS and experimental points are only in its figure)",
                    os.path.join(out, "fig8_inviscid.png"), plt)


def cmd_report(args):
    sdir = study_dir(args.root, args.dx)
    open_report(sdir, args.out, f"jet_study.py run --root {args.root} --dx {args.dx:g}")
    runs = {name: read_run(os.path.join(sdir, name), sets) for _s, name, sets in plan(args.dx)}
    missing, wall = report_tables(args.out, runs, args.dx, sdir)
    written = ["table1.csv", "table1.md", "inviscid.csv", "physics.csv", "physics.md"]
    skipped = []
    if not args.no_figures:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        why = fig5(args.out, runs[f"t1_wendland_{u0_tag(0.25)}"], args.dx, plt)
        if why:
            skipped.append(f"fig5_snapshots.png ({why})")
        else:
            written.append("fig5_snapshots.png")
        fig_L(args.out, runs, args.dx, plt, "Re", "fig6_L_vs_Re.png",
              "Reynolds number Re = rho u0 (D0/2) / mu [-]")
        fig_L(args.out, runs, args.dx, plt, "We", "fig7_L_vs_We.png",
              "Weber number We = rho u0^2 (D0/2) / sigma [-]")
        fig8(args.out, runs, args.dx, plt)
        written += ["fig6_L_vs_Re.png", "fig7_L_vs_We.png", "fig8_inviscid.png"]
    print(f"jet study report: {sdir} (D0/dx = {D0 / args.dx:g}) -> {args.out}")
    for name, r in runs.items():
        print(f"  {name:22s} {r['status']:22s} L/D0 {fmt(r['L_over_d0']):>6s}  "
              f"t_break {fmt(r['t_break'], '.4f'):>7s} s  wall {fmt(r['wall_s'], '.1f'):>7s} s")
        for n in r["notes"]:
            print(f"    note: {n}")
    print(f"  summed wall time {wall:.1f} s")
    print(f"  missing runs ({len(missing)}): {', '.join(missing) if missing else 'none'}")
    print(f"  wrote {', '.join(written)}")
    for s in skipped:
        print(f"  skipped {s}")
    return 0


def main(argv=None):
    ap, sub = study_parser(__doc__)
    root_default = os.path.join(REPO, "runs", "jet_study")
    r = sub.add_parser("run", help="run what is missing of the study (resumable)")
    r.add_argument("--root", default=root_default, help="study root (default: REPO/runs/jet_study)")
    r.add_argument("--dx", type=float, default=0.001, help="particle spacing [m] (default 0.001: D0/dx = 10)")
    add_run_arguments(r, SET_NAMES, REPO)
    p = sub.add_parser("report", help="tables and figures of the runs that exist")
    p.add_argument("--root", default=root_default, help="study root (default: REPO/runs/jet_study)")
    p.add_argument("--dx", type=float, default=0.001, help="particle spacing of the study [m]")
    p.add_argument("--out", default=os.path.join(REPO, "cases", "jet"),
                   help="where to write tables and figures (default: REPO/cases/jet)")
    p.add_argument("--no-figures", action="store_true", help="tables only")
    args = ap.parse_args(argv)
    if not args.dx > 0:
        ap.error(f"--dx {args.dx}: expected a spacing > 0 [m]")
    if args.cmd == "run" and args.threads < 1:
        ap.error(f"--threads {args.threads}: expected >= 1")
    return dispatch(args, cmd_run, cmd_report, "jet_study")


if __name__ == "__main__":
    sys.exit(main())
