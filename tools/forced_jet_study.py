#!/usr/bin/python3
"""Forced round jets against linear theory: a disturbance of known amplitude at the nozzle, its
growth along the jet, the breakup length and the drops. Run them, then tabulate them.

Usage (Debian's python3 has numpy, matplotlib and h5py):
  /usr/bin/python3 tools/forced_jet_study.py run [--root runs/forced_jet] [--d0-over-dx 10]
      [--artificial-alpha 0 [--reconstruct]] [--c0 C] [--cfl K] [--leapfrog] [--xsph E] [--only RUN ...] [--threads 2]
      [--sphjet build/cpp_driver/sphjet] [--dry-run]
  /usr/bin/python3 tools/forced_jet_study.py report [--root runs/forced_jet] [--d0-over-dx 10]
      [--artificial-alpha 0 [--reconstruct]] [--c0 C] [--cfl K] [--leapfrog] [--xsph E] [--out cases/round_jet/forced]

The plan: `--set` overrides on cases/round_jet/round_jet.toml, in ROOT/nN/NAME, one run for each
speed of U_SPEEDS (Mansour & Chigier's 0.78 and 1.57 m/s, We_d = 10 and 41) and each target
amplitude delta0/a of DELTAS (1e-2, 1e-3, 1e-4), at k a = 0.697 (Rayleigh's fastest wave). Every
run has the quiet exit of the round-jet study (`round_jet_study.py --axis-pair rings_fit
--quiet-exit`: the rings pair, the surface fit, the tensile correction, the bulk viscosity
0.5, a refilling nozzle of 3 d0 and the split of rings too heavy for their radius);
--artificial-alpha A adds numerics.artificial_alpha = A to every run (study ROOT/nN_alphaA), and
--reconstruct numerics.artificial_reconstruction (ROOT/nN_alphaA_rec); --c0 C the sound speed
fluid.c0 = C (16 m/s in the case; suffix _c0C); --cfl K the Courant number time.cfl = K (0.2 in
the case; suffix _cflK); --leapfrog numerics.integrator = "leapfrog" (one evaluation of the
rates per step; suffix _lf).

The forcing (nozzle.disturbance = eps: the plug moves at u0 (1 + eps sin(omega_f t)), omega_f =
u0 k) is set from the target with linear theory, not fitted: a plug whose speed varies by
eps u0 sin(k z) along the jet leaves it, by continuity, with the radial surface velocity
eps u0 k a / 2 and no displacement; a Rayleigh-Plateau mode of growth rate omega started so
grows as eta = (eps u0 k a / (2 omega)) sinh(omega t), that is delta0 e^(omega t) with
delta0 / a = eps u0 k / (4 omega). So eps = 4 (delta0/a) omega / (u0 k), with omega Weber's
(1931) viscous rate at k a = 0.697.

What the report measures, each run over the samples after the start-up head has left the box
(t >= T_head, the box's length over u0):
- the envelope A(s) of the surface's disturbance (tools/jet_noise.py) and the fit of
  A = 2 delta0 sinh(omega s / u0) to it where A < A_LINEAR a: the measured delta0/a (against the
  target) and omega (against Weber's);
- the breakup length: the mean intact length (jet.csv L, the paper's 1.5 h rule), and the
  pinch-off point, the median of the intact lengths just after each pinch-off (a drop in L of
  more than half a wavelength); linear theory's L = u0 ln(a / delta0) / omega (Weber's omega,
  the target and the measured delta0) is where the mode's amplitude reaches a, that is where
  the jet pinches: a jet that pinches there every forcing period has an intact length between
  L and L + lambda, mean L + lambda/2;
- the drops: the median equivalent diameter of the main drops (d >= d0) over the window
  against one wavelength's volume, (3/2 d0^2 lambda)^(1/3) = 1.89 d0, their count and that of
  the satellites per sample, and the satellites' share of the drops' volume;
- the pressure's standard deviation at the last snapshot in the intact jet (to 2 d0 before the
  pinch-off length) and among the drops (from 1 d0 past it), in sigma/a.

`run` is resumable (tools/study_runs.py). `report` reads what exists; missing runs are listed.
"""
import math
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from axisymmetric import spatial_growth, weber_omega  # noqa: E402
from jet_noise import envelope  # noqa: E402
from round_jet_study import (BASE_CASE, D0_MC, MU, QUIET_BULK_VISCOSITY, REFILL_NOZZLE, RHO,  # noqa: E402
                             SIGMA, groups)
from study_runs import (add_numerics_arguments, add_run_arguments, blew_up, check_numerics,  # noqa: E402
                        numerics_flags, numerics_sets, numerics_tag, dispatch, fmt, is_broken, md_table,
                        open_report, read_csv, run_all, run_summary, select_runs, study_parser)

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
U_SPEEDS = (0.7814, 1.5699)       # m/s, two of Mansour & Chigier's jets: We_d = 10.1 and 40.9
DELTAS = (1e-2, 1e-3, 1e-4)       # target delta0 / a
KA = 0.697                        # the forcing's wave, Rayleigh's fastest
LAMBDA_D0 = math.pi / KA          # its wavelength 2 pi a / KA, in d0
DROP_D0 = (1.5 * LAMBDA_D0) ** (1.0 / 3.0)   # one wavelength's volume as a sphere, d/d0
BOX_L_FACTOR, BOX_EXTRA_D0 = 1.5, 10.0   # the box reaches 1.5 L_theory + 10 d0 below the orifice
WINDOW_PERIODS = 10               # the window after the head has gone: ten forcing periods
SAMPLES_PER_PERIOD = 40           # breakup checks per forcing period
A_LINEAR = 0.1                    # the envelope's linear stretch: A < 0.1 a
SET_NAME = "forced"


# ---------------------------------------------------------------- theory
def theory(u, d0, delta):
    """Linear theory of one forced jet: Weber's temporal growth omega [1/s], the spatial growth
    in the same units (u0 -Im(k), Keller, Rubinow & Tu's problem), eps, L/d0 (temporal), the
    forcing period [s]."""
    a = 0.5 * d0
    t_cap = math.sqrt(RHO * a ** 3 / SIGMA)
    oh = MU / math.sqrt(RHO * SIGMA * a)
    omega = weber_omega(KA, oh) / t_cap
    omega_s = u * spatial_growth(KA, RHO * u * u * a / SIGMA, oh) / a
    k = KA / a
    return {"omega": omega, "omega_spatial": omega_s, "eps": 4.0 * delta * omega / (u * k),
            "L_d0": u * math.log(1.0 / delta) / omega / d0, "period": 2.0 * math.pi / (u * k)}


def run_name(u, delta):
    return f"u{u:g}_d{delta:g}"


def plan(n, numerics=()):
    """-> list of (set, name, overrides, info); numerics: more overrides of every run
    (study_runs.numerics_sets)."""
    runs = []
    d0 = D0_MC
    dx = d0 / n
    for u in U_SPEEDS:
        for delta in DELTAS:
            th = theory(u, d0, delta)
            below = (BOX_L_FACTOR * th["L_d0"] + BOX_EXTRA_D0) * d0
            t_head = below / u
            t_end = t_head + WINDOW_PERIODS * th["period"]
            sets = [f"resolution.dx={dx:.9g}", f"nozzle.d0={d0:g}", f"nozzle.u0={u:g}",
                    f"nozzle.length_over_d0={REFILL_NOZZLE:g}", "nozzle.refill=true",
                    f"nozzle.z0={below:.9g}", f"domain.lz={below + REFILL_NOZZLE * d0 + 2.0 * dx:.9g}",
                    f"domain.lx={2.5 * d0:.9g}", f"time.tmax={t_end:.6g}",
                    f"breakup.check_every={th['period'] / SAMPLES_PER_PERIOD:.4g}",
                    f"time.out={th['period']:.4g}",
                    f"nozzle.disturbance={th['eps']:.6g}", f"nozzle.disturbance_ka={KA:g}",
                    "domain.axis_pair=rings", "surface_tension.curvature=surface_fit",
                    "numerics.tensile_correction=on", f"numerics.bulk_viscosity={QUIET_BULK_VISCOSITY:g}",
                    "domain.split_axis_rings=true"] + list(numerics)
            info = dict(th, U=u, d0=d0, delta=delta, z0=below, t_head=t_head, t_end=t_end)
            runs.append((SET_NAME, run_name(u, delta), sets, info))
    return runs


def study_dir(args):
    """args.root/nN (N = args.d0_over_dx) with args' numerics tag (study_runs.numerics_tag)."""
    return os.path.join(args.root, f"n{args.d0_over_dx:g}" + numerics_tag(args))


def cmd_run(args):
    sdir = study_dir(args)
    todo = select_runs(plan(args.d0_over_dx, numerics_sets(args)), [SET_NAME], args.only, args.sphjet, args.dry_run)
    title = f"forced jet study: {len(todo)} run(s) in {sdir} (d0/dx = {args.d0_over_dx:g})"
    return run_all([(name, sets) for _s, name, sets, _i in todo], sdir, os.path.join(REPO, BASE_CASE),
                   args.sphjet, args.threads, args.tmax, args.dry_run, "forced_jet_study.py run", title, REPO, args.parallel)


# ---------------------------------------------------------------- analysis
def fit_sinh(env, u, d0, a_max=A_LINEAR):
    """Fit A(s) = 2 delta0 sinh(omega s / u) (least squares in ln A) over the envelope's points
    from the orifice up to the first one at or above a_max (excluded): -> (delta0/a, omega,
    s_end/d0) or None. omega is searched on a grid of 0.1% steps from 20 to 5000 1/s; delta0
    then follows in closed form."""
    pts = []
    for s, amp, _n in env:
        if amp >= a_max:
            break
        if s > 0 and amp > 0:
            pts.append((s * d0, math.log(amp)))
    if len(pts) < 5:
        return None
    best = None
    w = 20.0
    while w < 5000.0:
        res = [y - math.log(2.0 * math.sinh(w * s / u)) for s, y in pts]
        c = sum(res) / len(res)
        sq = sum((r - c) ** 2 for r in res)
        if best is None or sq < best[0]:
            best = (sq, math.exp(c), w)
        w *= 1.001
    return best[1], best[2], pts[-1][0] / d0


def pinch_lengths(rows, lam_d0):
    """The intact lengths L/d0 just after each pinch-off: the samples where L fell by more than
    half a wavelength since the sample before (both broken)."""
    out = []
    for prev, cur in zip(rows, rows[1:]):
        if is_broken(prev) and is_broken(cur):
            lp, lc = float(prev["L_over_d0"]), float(cur["L_over_d0"])
            if lp - lc > 0.5 * lam_d0:
                out.append(lc)
    return out


def read_run(run_dir, info):
    r = {"status": "missing", "notes": [], "finished": False, "wall_s": None, "particles": None,
         "particle_steps_per_s": None}
    t0 = info["t_head"]

    def window_of(rows):
        return [x for x in rows if float(x["time"]) >= t0]

    window = run_summary(run_dir, r, window_of)
    if window is None:
        return r
    r["n_window"] = len(window)
    broken = [x for x in window if is_broken(x)]
    r["n_broken"] = len(broken)
    if broken:
        ls = [float(x["L_over_d0"]) for x in broken]
        r["L_mean"] = sum(ls) / len(ls)
        r["L_std"] = math.sqrt(sum((v - r["L_mean"]) ** 2 for v in ls) / len(ls))
    pinches = pinch_lengths(window, LAMBDA_D0)
    r["n_pinch"] = len(pinches)
    r["L_pinch"] = statistics.median(pinches) if pinches else None
    steps = {x["step"] for x in window}
    try:
        surface = [x for x in read_csv(os.path.join(run_dir, "jet_surface.csv")) if x["step"] in steps]
        env = envelope(surface, window, 0.5 * info["d0"])
        r["envelope"] = [(x, amp) for x, amp, _n in env]
        fit = fit_sinh(env, info["U"], info["d0"])
        if fit:
            r["delta0"], r["omega"], r["fit_end"] = fit
    except (OSError, KeyError, ValueError) as e:
        r["notes"].append(f"jet_surface.csv: {e}")
    try:
        drops = [x for x in read_csv(os.path.join(run_dir, "drops.csv")) if x["step"] in steps]
        main = [float(x["d_eq_over_d0"]) for x in drops if x["satellite"] == "0"]
        sat = [float(x["d_eq_over_d0"]) for x in drops if x["satellite"] == "1"]
        r["drop_median"] = statistics.median(main) if main else None
        if main:
            q = sorted(main)
            r["drop_q"] = (q[len(q) // 10], q[(9 * len(q)) // 10])
        vol_main, vol_sat = sum(d ** 3 for d in main), sum(d ** 3 for d in sat)
        r["sat_share"] = vol_sat / (vol_main + vol_sat) if vol_main + vol_sat > 0 else None
        n_samples = max(1, len(window))
        r["main_per_sample"], r["sat_per_sample"] = len(main) / n_samples, len(sat) / n_samples
    except (OSError, KeyError, ValueError) as e:
        r["notes"].append(f"drops.csv: {e}")
    r["snap"] = last_snapshot(run_dir, info)
    if r["snap"] and r.get("L_pinch"):
        r["p_std"] = pressure_noise(r["snap"], info, r["L_pinch"])
    boom = blew_up(run_dir)
    if boom:
        r["status"] = "blew up"
        r["notes"].append(boom)
    else:
        r["status"] = "finished" if r["finished"] else "unfinished"
    return r


def last_snapshot(run_dir, info):
    """The active particles of the run's last snapshot: s/d0 from the orifice, r/d0, p [Pa]
    (numpy arrays) and the time [s]; None without a snapshot."""
    import glob
    snaps = sorted(glob.glob(os.path.join(run_dir, "snap_*.h5")))
    if not snaps:
        return None
    import h5py
    with h5py.File(snaps[-1], "r") as h:
        g = h["particles"]
        act = g["active"][()] != 0
        return {"s": (info["z0"] - g["z"][()][act]) / info["d0"], "r": g["x"][()][act] / info["d0"],
                "p": g["p"][()][act], "time": float(h.attrs["time"])}


def pressure_noise(snap, info, l_pinch):
    """The standard deviation of the particles' pressure at the last snapshot, in sigma/a,
    in the intact jet up to 2 d0 before the pinch-off length and among the drops from 1 d0
    past it: (jet, drops), each None with fewer than two particles."""
    s, p = snap["s"], snap["p"]
    unit = SIGMA / (0.5 * info["d0"])

    def std(sel):
        return float(p[sel].std()) / unit if sel.sum() >= 2 else None

    return std((s >= 0.0) & (s < l_pinch - 2.0)), std(s > l_pinch + 1.0)


def report(args):
    sdir = study_dir(args)
    open_report(sdir, args.out, f"forced_jet_study.py run --d0-over-dx {args.d0_over_dx:g}" + numerics_flags(args))
    header = ["run", "U [m/s]", "We_d", "eps", "delta0/a target", "delta0/a measured",
              "growth / Weber's (temporal), / spatial", "L/d0 pinch-off (pinches)",
              "L/d0 theory from the target delta0: temporal, spatial",
              "L/d0 theory from the measured delta0: temporal, spatial",
              "pinch-off vs spatial theory: target, measured delta0",
              "L/d0 mean (std)", "main drop d/d0 median (10-90%)", "main drops, satellites per sample",
              "satellite volume share", "p std / (sigma/a): jet, drops (last snapshot)", "status", "wall [s]"]
    rows, missing, done = [], [], []
    for _s, name, _sets, info in plan(args.d0_over_dx, numerics_sets(args)):
        r = read_run(os.path.join(sdir, name), info)
        if r["status"] == "missing":
            missing.append(name)
            continue
        done.append((info, r))
        g = groups(info["U"], info["d0"])

        def lengths(delta):
            c = math.log(1.0 / delta) * info["U"] / info["d0"]
            return c / info["omega"], c / info["omega_spatial"]

        def err(l_th):
            return (None if r.get("L_pinch") is None
                    else f"{100.0 * (r['L_pinch'] - l_th) / l_th:+.1f}%")

        lt_target, ls_target = lengths(info["delta"])
        measured, growth, err_m = "-, -", "-", "-"
        if r.get("delta0"):
            lt_m, ls_m = lengths(r["delta0"])
            measured = f"{lt_m:.2f}, {ls_m:.2f}"
            growth = f"{r['omega'] / info['omega']:.3f}, {r['omega'] / info['omega_spatial']:.3f}"
            err_m = err(ls_m) or "-"
        q = r.get("drop_q") or (None, None)
        rows.append([name, f"{info['U']:g}", f"{g['We_d']:.3g}", f"{info['eps']:.4g}", f"{info['delta']:g}",
                     fmt(r.get("delta0"), ".3g"), growth,
                     f"{fmt(r.get('L_pinch'))} ({r.get('n_pinch', 0)})",
                     f"{lt_target:.2f}, {ls_target:.2f}", measured,
                     f"{err(ls_target) or '-'}, {err_m}",
                     f"{fmt(r.get('L_mean'))} ({fmt(r.get('L_std'))})",
                     f"{fmt(r.get('drop_median'))} ({fmt(q[0])}-{fmt(q[1])})",
                     f"{fmt(r.get('main_per_sample'))}, {fmt(r.get('sat_per_sample'))}",
                     fmt(r.get("sat_share"), ".3f"),
                     f"{fmt((r.get('p_std') or (None, None))[0])}, {fmt((r.get('p_std') or (None, None))[1])}",
                     r["status"], fmt(r["wall_s"], ".0f")])
    text = (f"# Forced round jets (generated by tools/forced_jet_study.py report)\n\n"
            f"Study {os.path.relpath(sdir, REPO) if sdir.startswith(REPO) else os.path.join('ROOT', os.path.basename(sdir))}"
            f" (ROOT: `run --root`): d0/dx = "
            f"{args.d0_over_dx:g}, k a = {KA}, the quiet exit"
            + "".join(f", {s.replace('=', ' = ')}" for s in numerics_sets(args))
            + f"; one wavelength's drop "
            f"{DROP_D0:.3f} d0.\n\n" + md_table(header, rows) +
            f"\nMissing runs ({len(missing)}): {', '.join(missing) if missing else 'none'}.\n")
    with open(os.path.join(args.out, "forced_jets.md"), "w") as f:
        f.write(text)
    if not args.no_figures and done:
        figure(os.path.join(args.out, "forced_jets_envelope.png"), done)
        rz_figure(os.path.join(args.out, "forced_jets_rz.png"), done)
    print(text)
    return 0


def figure(path, done):
    """The envelopes A(s)/a of the runs, one panel per speed, beside linear theory from the
    target delta0: 2 delta0 sinh(omega s / u0) with the spatial growth; a mark at each run's
    pinch-off length."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    speeds = sorted({info["U"] for info, _r in done})
    fig, axes = plt.subplots(1, len(speeds), figsize=(5.0 * len(speeds), 4.0), squeeze=False)
    for ax, u in zip(axes[0], speeds):
        for j, (info, r) in enumerate(x for x in done if x[0]["U"] == u):
            col = f"C{j}"
            env = r.get("envelope") or []
            ax.semilogy([e[0] for e in env], [e[1] for e in env], ".", ms=2, color=col,
                        label=f"delta0/a = {info['delta']:g}: measured")
            top = max([e[0] for e in env] + [info["L_d0"]])
            ss = [0.05 * i for i in range(1, int(top / 0.05) + 1)]
            ax.semilogy(ss, [2 * info["delta"] * math.sinh(info["omega_spatial"] * x * info["d0"] / u)
                             for x in ss], "-", lw=0.8, color=col, label="linear theory (spatial)")
            if r.get("L_pinch"):
                ax.axvline(r["L_pinch"], color=col, ls=":", lw=0.8)
        ax.set_ylim(1e-5, 2.0)
        ax.set_xlabel("s / d0 (from the orifice); dotted: pinch-off length")
        ax.set_ylabel("disturbance amplitude / a")
        ax.set_title(f"U = {u:g} m/s, We_d = {groups(u, D0_MC)['We_d']:.1f}")
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def rz_figure(path, done):
    """Each run's particles at its last snapshot, mirrored about the axis, s / d0 from the
    orifice across: the jet, its drops and satellites as they are (one dot a particle), with a
    tick every wavelength from the pinch-off point."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    shown = [(info, r) for info, r in done if r.get("snap")]
    if not shown:
        return
    top = max(info["z0"] / info["d0"] for info, _r in shown)
    fig, axes = plt.subplots(len(shown), 1, figsize=(11.0, 0.9 * len(shown) + 0.6), squeeze=False)
    for ax, (info, r) in zip(axes[:, 0], shown):
        snap = r["snap"]
        ax.plot(snap["s"], snap["r"], ",", color="k")
        ax.plot(snap["s"], -snap["r"], ",", color="k")
        if r.get("L_pinch"):
            k = r["L_pinch"]
            while k < top:
                ax.axvline(k, color="C3", lw=0.4, alpha=0.6)
                k += LAMBDA_D0
        ax.set_xlim(-0.5, top)
        ax.set_ylim(-1.6, 1.6)
        ax.set_aspect("equal")
        ax.set_yticks([])
        ax.set_title(f"U = {info['U']:g} m/s, delta0/a = {info['delta']:g}, t = {1000 * snap['time']:.1f} ms "
                     f"(red: the pinch-off length, then one wavelength apart)", fontsize=7)
    axes[-1, 0].set_xlabel("s / d0 from the orifice")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def main(argv=None):
    ap, sub = study_parser(__doc__)
    for name in ("run", "report"):
        p = sub.add_parser(name, help="run what is missing (resumable)" if name == "run"
                           else "the table of the runs that exist")
        p.add_argument("--root", default=os.path.join(REPO, "runs", "forced_jet"),
                       help="study root (default: REPO/runs/forced_jet)")
        p.add_argument("--d0-over-dx", type=float, default=10.0, help="particles across d0 (default 10)")
        add_numerics_arguments(p)
        if name == "run":
            add_run_arguments(p, (SET_NAME,), REPO)
        else:
            p.add_argument("--out", default=os.path.join(REPO, "cases", "round_jet", "forced"))
            p.add_argument("--no-figures", action="store_true")
    args = ap.parse_args(argv)
    if not args.d0_over_dx >= 4:
        ap.error(f"--d0-over-dx {args.d0_over_dx}: expected >= 4 (2 rings across the radius)")
    check_numerics(ap, args)
    return dispatch(args, cmd_run, report, "forced_jet_study")


if __name__ == "__main__":
    sys.exit(main())
