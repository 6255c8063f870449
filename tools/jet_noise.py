#!/usr/bin/env python3
"""The disturbance of a jet along its length, from a run's jet.csv and jet_surface.csv
(cases/CASE_FORMAT.md, [breakup]): where it starts, how fast it grows, and how quiet the exit is.

    /usr/bin/python3 tools/jet_noise.py RUN [--from T] [--to T1] [--rows] [--plot OUT.png]
        [--wave S0 S1] [--frequency OMEGA] [--row-curvature S0 S1] [--at S ...] [--spatial]

The samples read are those from T to T1 (default: the run's last), so that two runs can be read
over the same times while one of them goes on.
- exit: the medians over the samples (T <= t <= T1) of the pressure's mean and standard deviation
  and of the radial velocity's rms over the jet's particles within 2 d0 of the orifice, in
  units of sigma/a (a = d0/2; round jets) and of the capillary velocity sqrt(sigma/(rho a)).
- envelope: at each slice s of the surface profile r_s(s, t), the disturbance amplitude
  A(s) = sqrt(2) x the rms over the samples of r_s - its median (the amplitude of a sine of that
  rms), over the slices that the intact jet reaches in at least half of the samples.
- fit: ln A(s) = ln(delta0) + k_s s over the growing stretch (from the smallest A after the
  first half d0 to where A first passes a/4): the spatial growth k_s, its temporal equivalent
  omega = k_s u0 (the jet carries the disturbance at u0), and the intercept delta0 at the
  orifice. C = ln(a/delta0) is the constant of Weber's law L = u0 C / omega; C / k_s is where the
  fitted line reaches a, the breakup length linear growth gives with the jet's own delta0 and k_s.
- theory: Weber's (1931) viscous growth rate, the largest over ka and at the case's forcing
  wavenumber (nozzle.disturbance_ka), and the breakup length C u0 / omega_Weber that the
  measured C gives with it.
- falling (a round jet with gravity along it, the case's [gravity] on its nozzle.axis): the
  envelope's growth over the fit's stretch against Weber's growth integrated along a jet that
  gravity speeds up and thins (tools/jet_gravity_theory.py's N(z), at the case's u0, radius and
  fluid): the slope of the straight line through ln A(s) against N(s) over the stretch's
  slices, and over each of its four quarters; 1 where the jet grows as the falling theory
  says, everywhere along it. The same against the N of the frequency that has grown most
  (--one-frequency there: each wave carried down at its own frequency), below the fastest local
  rate's wherever the jet speeds up; with --spatial, also against the same picture at each
  frequency's spatial rate (--spatial there).
- spectrum: the mean amplitude spectrum of r_s along the intact jet (samples whose profile is
  at least 4 d0 long), and its peak ka.
- noise along the jet (from the snapshots snap_*.h5 at T <= t <= T1, where the run wrote them): the
  pressure's standard deviation over the particles of each 2 d0 slice of the intact jet (s < L
  of the jet.csv sample nearest in time), its median over the snapshots in units of sigma/a;
  `quiet to` is where the first slice exceeds sigma/(4a) (the exit's target), and L minus it how
  far up the jet the noise of the breakup reaches. For a round jet with resolution.dx in its
  case.toml, the axis order of each slice as well: its particles within 0.6 dx of the axis (the
  nozzle builds the innermost rings at dx/2) over the count of the nozzle's lattice stretched
  with the flow, 2 (d0/dx) u0 / |mean axial velocity|; 1 where the rows keep their order. And
  the same standard deviation about each ring row's own mean (rows as in --rows), with its own
  `quiet about the rows' means to`: a lattice of many rings holds a steady row-to-row pattern
  (about +-0.4 sigma/a at d0/dx 20) that the plain one counts as noise.
- rows (--rows; a round jet with resolution.dx): along the intact jet, each ring row's mean
  pressure over the local Laplace pressure sigma/a_s (a_s the slice's own radius, the rows
  counted across it) and its mean radius over the local row spacing a_s/n (j + 1/2 for the
  nozzle's lattice, n = a/dx rows), medians over the snapshots: a column at rest holds a fixed
  pattern (the lattice's), and a lattice that deforms as the jet stretches shows it in its rows
  first.
- rows' curvature (--row-curvature S0 S1; a round jet with surface tension and resolution.dx,
  from the snapshots at T <= t <= T1): on the stretch S0-S1 d0, each row of rings' curvature
  (the one the surface tension gives it) against the surface's geometric curvature, as a slope
  (row_curvature): 1 where the row is bent as the surface is, below 0 where it pulls the other
  way. The rings are found as the nozzle's rows, layers of one z, so it reads where those hold.
- at (--at S ...): the envelope at those distances (the nearest slice), so that the same
  places can be compared over successive stretches of time (--from, --to).
- start-up front (the samples before T): at each one the first slice past 1 d0 where r_s departs
  from a by more than 1e-3 a, the edge of the start-up's disturbance; the straight line through
  its positions over time gives the speed at which the front leaves the orifice (lab frame) and
  u0 minus it, the speed at which the disturbance runs up the jet against the fluid (in m/s and
  in units of sqrt(sigma/(rho a))). A jet whose u0 is close to that speed clears its start-up
  slowly.
- dominant wave (--wave S0 S1, the samples from T whose intact jet covers S0-S1 d0): the peak of
  the (k, omega) spectrum of r_s(s, t) there, its ka and the speed of its crests in the lab, and
  the same against the fluid (minus u0). A wave the jet carries (Rayleigh-Plateau's) moves at
  u0; a capillary wave (ka > 1) runs against the fluid at its phase speed, printed beside it with
  its group velocity from Rayleigh's inviscid dispersion relation (a group velocity above u0
  carries a disturbance up the jet). On a falling round jet the speed against the fluid is taken at
  the stretch's middle, where the jet is faster and thinner (the speed U(z) and radius a(z) of
  tools/jet_gravity_theory.py), and the line adds the wave's local ka there (ka a(z)/a), and the
  frequency that has grown most by the jet's mean length in the one-frequency picture
  (jet_gravity_theory --one-frequency) with its local ka there: a wave carried down at its own
  frequency has its ka fall as (u0/U(z))^(3/2), below Weber's fastest, which does not.
- one frequency (--frequency OMEGA, in 1/s): the amplitude of r_s at that angular frequency along
  the jet (at each slice the intact jet reaches in 90% of the samples, the Hann-windowed Fourier
  coefficient over its samples), so that one wave is followed down the jet apart from the rest
  of the envelope; its growing stretch (the fit's rule), and on a round jet the slope of ln A
  against that wave's own Weber growth along the jet, at its local ka omega a(z)/U(z)
  (tools/jet_gravity_theory.py's Jet.wave_exponent; with gravity along the jet or without),
  over the stretch and its quarters, with the line's C = ln(a/delta0) at the orifice.
Prints `key = value` lines and, last, `SUMMARY key=value ...`. Round (axisymmetric) jets; a
planar jet's profile is its half-width, read the same way (the theory lines then do not apply).
"""
import argparse
import csv
import math
import os
import statistics
import sys
import tomllib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from axisymmetric import rayleigh_omega2, weber_omega  # noqa: E402


class NoiseError(Exception):
    """A run that cannot be read (the message names it)."""


def read_case(run):
    with open(os.path.join(run, "case.toml"), "rb") as f:
        case = tomllib.load(f)
    nz, fl = case["nozzle"], case["fluid"]
    grav = case.get("gravity", {})
    along = {"down": (0.0, -1.0), "up": (0.0, 1.0), "left": (-1.0, 0.0), "right": (1.0, 0.0)}
    ax, az = along.get(nz.get("axis", "down"), (0.0, -1.0))
    rho = fl.get("rho0", 1000.0)
    nu = fl["mu"] / rho if "mu" in fl else fl.get("nu", 0.0)
    return {
        "d0": nz["d0"], "u0": nz["u0"], "z0": nz.get("z0", 0.0), "x0": nz.get("x0", 0.0),
        "axis": nz.get("axis", "down"), "column": nz.get("column_over_d0", 0.0), "rho": rho, "nu": nu,
        "sigma": case.get("surface_tension", {}).get("sigma", 0.0),
        "ka": nz.get("disturbance_ka", 0.697), "eps": nz.get("disturbance", 0.0),
        "round": case.get("domain", {}).get("geometry", "planar") == "axisymmetric",
        "dx": case.get("resolution", {}).get("dx"),
        "g_along": ax * grav.get("gx", 0.0) + az * grav.get("gz", -9.81),   # along the jet (CASE_FORMAT's defaults)
    }


def read_rows(path):
    try:
        with open(path, newline="") as f:
            return list(csv.DictReader(f))
    except OSError as e:
        raise NoiseError(f"cannot read {path} ({e.strerror})")


def median(v):
    v = sorted(v)
    n = len(v)
    if n == 0:
        return float("nan")
    return v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2])


def weber_max(oh):
    """Weber's largest growth rate over ka and its ka (units of sqrt(sigma/(rho a^3)))."""
    best = max((weber_omega(k / 1000.0, oh), k / 1000.0) for k in range(10, 1000))
    return best


def envelope(surface, times, a):
    """Slice centre s/d0 -> (A/a, samples) over the slices reached in >= half of the samples."""
    by_slice = {}
    for r in surface:
        by_slice.setdefault(float(r["s_over_d0"]), []).append(float(r["r_over_d0"]))
    out = []
    for s in sorted(by_slice):
        v = by_slice[s]
        if len(v) < 0.5 * len(times):
            break
        m = median(v)
        rms = math.sqrt(sum((x - m) ** 2 for x in v) / len(v))
        out.append((s, math.sqrt(2.0) * rms * 2.0, len(v)))  # r/d0 -> r/a: x 2
    return out


def fit_growth(env):
    """The straight line through ln A over the growing stretch: (k_s [1/d0], ln delta0/a, s0, s1)."""
    cross = next((i for i, e in enumerate(env) if e[1] > 0.25), len(env))
    start = [i for i, e in enumerate(env[:cross]) if e[0] >= 0.5]
    if len(start) < 2:
        return None
    i0 = min(start, key=lambda i: env[i][1])
    pts = [(s, math.log(A)) for s, A, _ in env[i0:cross + 1] if A > 0]
    if len(pts) < 3:
        return None
    k, ln_d = statistics.linear_regression([p[0] for p in pts], [p[1] for p in pts])
    return k, ln_d, pts[0][0], pts[-1][0]


def falling_growth(env, s0, s1, c, one_frequency=False, spatial=False):
    """The envelope's growth over [s0, s1] d0 over Weber's growth integrated along a jet that
    gravity (c["g_along"] > 0) speeds up and thins (tools/jet_gravity_theory.py's N(z), at the
    case's u0, radius and fluid; the fastest local rate's, or with one_frequency the frequency
    that has grown most's, or with spatial the same at each frequency's spatial rate): the slope
    of the straight line through ln A against N over the stretch's slices, and over each of its
    four quarters -> (slope, [four slopes]), or None with fewer than nine slices in it (three a
    quarter, the quarters sharing their ends)."""
    from jet_gravity_theory import Jet   # here: it imports round_jet_study, which imports this module
    d0 = c["d0"]
    jet = Jet(c["u0"], 0.5 * d0, c["g_along"], c["rho"], c["sigma"], c["nu"] * c["rho"], one_frequency, spatial)
    got = growth_over(env, s0, s1, lambda s: jet.exponent(s * d0))
    return None if got is None else got[:2]


def growth_over(env, s0, s1, exponent):
    """The slope of the straight line through ln A against exponent(s) (a theory's N at s d0)
    over env's slices in [s0, s1], over each of its four quarters, and the line's value at N = 0
    -> (slope, [four slopes], ln(delta0/a)), or None with fewer than nine slices (three a
    quarter, the quarters sharing their ends)."""
    pts = [(exponent(s), math.log(A)) for s, A, _ in env if s0 <= s <= s1 and A > 0]
    if len(pts) < 9:
        return None

    def line(part):
        return statistics.linear_regression([p[0] for p in part], [p[1] for p in part])

    ends = [round(i * (len(pts) - 1) / 4) for i in range(5)]
    whole = line(pts)
    return whole.slope, [line(pts[ends[i]:ends[i + 1] + 1]).slope for i in range(4)], whole.intercept


FREQ_COVER = 0.9   # --frequency reads the slices the intact jet reaches in this share of the samples


def frequency_envelope(surface, omega):
    """The amplitude of r_s at the angular frequency omega [1/s] along the jet: at each slice the
    intact jet reaches in at least FREQ_COVER of the samples, 2 |sum w x e^(-i omega t)| / sum w
    over its samples, x = r_s/a - 1 less its mean and w a Hann window over their times (the
    samples need not be evenly spaced) -> [(s/d0, A/a, samples)], in s (envelope's form)."""
    per = {}
    for r in surface:
        per.setdefault(float(r["s_over_d0"]), []).append((float(r["time"]), 2.0 * float(r["r_over_d0"]) - 1.0))
    n = max((len(v) for v in per.values()), default=0)
    out = []
    for s in sorted(per):
        got = sorted(per[s])
        if len(got) < max(FREQ_COVER * n, 8):
            break
        t0, t1 = got[0][0], got[-1][0]
        mean = sum(x for _t, x in got) / len(got)
        re = im = wsum = 0.0
        for t, x in got:
            w = 0.5 * (1.0 - math.cos(2.0 * math.pi * (t - t0) / (t1 - t0)))
            re += w * (x - mean) * math.cos(omega * t)
            im -= w * (x - mean) * math.sin(omega * t)
            wsum += w
        out.append((s, 2.0 * math.hypot(re, im) / wsum, len(got)))
    return out


def spectrum(surface, d0, a):
    """Mean amplitude spectrum of r_s along the intact jet: (ka, amplitude/a) pairs."""
    per = {}
    for r in surface:
        per.setdefault(r["step"], []).append((float(r["s_over_d0"]), float(r["r_over_d0"])))
    nk = 64
    acc = [0.0] * nk
    used = 0
    kmax = 0.0
    for prof in per.values():
        if len(prof) < 8 or prof[-1][0] - prof[0][0] < 4.0:
            continue
        ds = prof[1][0] - prof[0][0]
        mean = sum(p[1] for p in prof) / len(prof)
        kmax = math.pi / ds * 0.5  # ka at the Nyquist wavenumber (s in d0, a = d0/2)
        for j in range(nk):
            ka = (j + 1) * kmax / nk
            k = ka / 0.5  # per d0
            re = sum((p[1] - mean) * math.cos(k * p[0]) for p in prof)
            im = sum((p[1] - mean) * math.sin(k * p[0]) for p in prof)
            acc[j] += 2.0 * math.hypot(re, im) / len(prof) * 2.0  # amplitude / a
        used += 1
    if used == 0:
        return []
    return [((j + 1) * kmax / nk, acc[j] / used) for j in range(nk)]


FRONT_THRESHOLD = 1e-3   # |r_s/a - 1| that marks the start-up's disturbance (the exit is quieter)
FRONT_FROM_D0 = 1.0      # the front is looked for past this s/d0 (clear of the exit's own shape)


def startup_front(surface, t0):
    """The start-up's disturbance front over the samples at t < t0: (t, s_f/d0) pairs, the first
    slice past FRONT_FROM_D0 where |r_s/a - 1| > FRONT_THRESHOLD (samples without one skipped),
    and the least-squares slope ds_f/dt in d0 per second (None below three points)."""
    per = {}
    for r in surface:
        t = float(r["time"])
        if t < t0:
            per.setdefault(t, []).append((float(r["s_over_d0"]), float(r["r_over_d0"])))
    pts = []
    for t in sorted(per):
        s = next((s for s, r in sorted(per[t]) if s >= FRONT_FROM_D0 and abs(2.0 * r - 1.0) > FRONT_THRESHOLD),
                 None)
        if s is not None:
            pts.append((t, s))
    if len(pts) < 3:
        return pts, None
    return pts, statistics.linear_regression([p[0] for p in pts], [p[1] for p in pts]).slope


def dominant_wave(surface, s0, s1):
    """The peak of the (k, omega) spectrum of r_s(s, t)/a - 1 over the slices in [s0, s1) d0 and
    the samples whose profile covers them all: (ka, omega [1/s], crest speed [d0/s], samples),
    omega > 0 for crests moving down the jet; None with fewer than 8 samples or 8 slices. Each
    slice's mean over the samples is taken out (the steady shape), both directions are Hann
    windowed, and the transform is taken directly (the samples need not be evenly spaced) on 400 k
    from one wavelength in the stretch to the slices' Nyquist and 401 omega of either sign up to
    the samples'."""
    import numpy as np
    per = {}
    for r in surface:
        s = float(r["s_over_d0"])
        if s0 <= s < s1:
            per.setdefault(float(r["time"]), {})[round(s, 6)] = float(r["r_over_d0"])
    if not per:
        return None
    slices = sorted(set().union(*per.values()))
    times = [t for t in sorted(per) if len(per[t]) == len(slices) and min(per[t].values()) > 0.0]
    if len(times) < 8 or len(slices) < 8:
        return None
    m = np.array([[2.0 * per[t][s] - 1.0 for s in slices] for t in times])
    m -= m.mean(axis=0)
    m *= np.hanning(len(times))[:, None] * np.hanning(len(slices))[None, :]
    t = np.array(times)
    sv = np.array(slices)
    ds = float(np.median(np.diff(sv)))
    dt = float(np.median(np.diff(t)))
    span = sv[-1] - sv[0] + ds
    k = np.linspace(2.0 * math.pi / span, math.pi / ds, 400)         # per d0: one wave in the stretch to Nyquist
    w = np.linspace(-1.0, 1.0, 401) * math.pi / dt                   # 1/s, both signs
    x = m @ np.exp(-1j * np.outer(sv, k))                             # (samples, k): picks cos(k s - ...)
    power = np.abs(np.exp(1j * np.outer(w, t)) @ x)                   # (omega, k)
    i, j = np.unravel_index(int(np.argmax(power)), power.shape)
    return 0.5 * k[j], float(w[i]), float(w[i] / k[j]), len(times)


def snapshot_names(run):
    """The run's snapshot files (snap_*.h5), in order."""
    return sorted(n for n in os.listdir(run) if n.startswith("snap_") and n.endswith(".h5"))


def fluid_snapshots(run, t0, t1):
    """Each snapshot of the run at t0 <= t <= t1: (file name, t, its particles group, the mask of
    its active fluid particles), while the file is open."""
    import h5py
    for name in snapshot_names(run):
        with h5py.File(os.path.join(run, name), "r") as f:
            t = float(f.attrs["time"])
            if t < t0 or t > t1:
                continue
            g = f["particles"]
            yield name, t, g, (g["active"][:] == 1) & (g["kind"][:] == 2)  # fluid (ParticleKind)


def noise_along(run, z0, d0, p_unit, t0, jet, axis_dx=None, u0=None, t1=math.inf):
    """[(s0 of a 2 d0 slice, median p std / (sigma/a), median axis order or None, rows or None,
    median p std about the rows' own means / (sigma/a) or None)]
    over the intact jet of every snapshot at t0 <= t <= t1; None without snapshots. axis_dx (a
    round jet's particle spacing dx) adds the axis order: the particles within 0.6 dx of the axis
    (the rings nearest it, at dx/2 as built) over the count of an ordered lattice stretched with
    the flow, 2 (d0/dx) u0 / |mean axial velocity| in a 2 d0 slice; it is 1 while the rows hold
    the nozzle's order and falls where they leave the axis. It adds the rows as well: (the
    slice's radius a_s / a, [each row's mean pressure / (sigma/a_s)], [each row's mean radius /
    (a_s/n)]), medians over the snapshots. The nozzle's n = a/dx rows sit at (j + 1/2) dx; a
    slice's rows are counted on its own radius, a_s = its outermost particle's radius x a /
    (a - dx/2), so that a jet thinning as it stretches keeps them apart: row j holds the radii
    [j, j + 1) a_s / n. The last, pressure std about the rows' means, is the slice's spread with
    the rows' fixed pattern taken out (each particle's pressure less its row's mean): what is
    left is noise, where a lattice of many rows holds a steady pattern of its own."""
    if not snapshot_names(run):
        return None
    import numpy as np
    times = [float(r["time"]) for r in jet]
    per, order, rows, in_rows = {}, {}, {}, {}
    n_rows = max(1, round(0.5 * d0 / axis_dx)) if axis_dx else 0
    for _name, t, g, on in fluid_snapshots(run, t0, t1):
        row = jet[min(range(len(times)), key=lambda i: abs(times[i] - t))]
        if row["broken"] != "1":
            continue
        s = (z0 - g["z"][:][on]) / d0
        p = g["p"][:][on]
        if axis_dx:
            r, w = np.abs(g["x"][:][on]), g["w"][:][on]
        length = float(row["L_over_d0"])
        for b in range(int(length // 2.0)):
            m = (s >= 2.0 * b) & (s < 2.0 * b + 2.0)
            if m.sum() >= 5:
                per.setdefault(b, []).append(float(np.std(p[m])) / p_unit)
                speed = abs(float(np.mean(w[m]))) if axis_dx else 0.0
                if speed > 0:
                    ordered = 2.0 * (d0 / axis_dx) * u0 / speed
                    order.setdefault(b, []).append(float(np.sum(m & (r < 0.6 * axis_dx))) / ordered)
                if axis_dx:
                    rm, pm = r[m], p[m]
                    a_s = float(np.max(rm)) * 0.5 * d0 / (0.5 * d0 - 0.5 * axis_dx)
                    j = np.minimum((rm / a_s * n_rows).astype(int), n_rows - 1)
                    unit = p_unit * 0.5 * d0 / a_s   # sigma / a_s
                    spacing = a_s / n_rows
                    ins = [j == i for i in range(n_rows)]
                    means = np.array([float(np.mean(pm[k])) if np.any(k) else 0.0 for k in ins])
                    in_rows.setdefault(b, []).append(float(np.sqrt(np.mean((pm - means[j]) ** 2))) / p_unit)
                    rows.setdefault(b, []).append(
                        [a_s / (0.5 * d0)]
                        + [m_k / unit if np.any(k) else math.nan for m_k, k in zip(means, ins)]
                        + [float(np.mean(rm[k])) / spacing if np.any(k) else math.nan for k in ins])

    def med_rows(b):
        if b not in rows:
            return None
        cols = [median([v[i] for v in rows[b] if not math.isnan(v[i])]) for i in range(2 * n_rows + 1)]
        return cols[0], cols[1:n_rows + 1], cols[n_rows + 1:]
    return [(2.0 * b, median(v), median(order[b]) if b in order else None, med_rows(b),
             median(in_rows[b]) if b in in_rows else None) for b, v in sorted(per.items())]


LAYER_GAP = 0.4     # --row-curvature: rings further apart along the axis than this share of the
                    # spacing start a new layer (a nozzle row's rings stay much closer in z than
                    # that while the lattice holds; the layers are about a spacing apart or more)
LAYER_FIT = 4       # the surface's curvature: a parabola through this many layers either side
MIN_LAYERS = 30     # a snapshot with fewer layers in the stretch is passed over


def row_curvature(run, c, t0, t1, s0, s1):
    """--row-curvature S0 S1: over the snapshots at t0 <= t <= t1, the curvature that the surface
    tension gives each row of rings against the surface's geometric curvature, on the stretch
    S0-S1 d0 of a round jet (its fluid within d0 of the axis). The rings are found as layers (one
    nozzle row's, nearly one z: sorted along the axis and split where the gap passes LAYER_GAP
    spacings, the layers of a/dx rings +-1 kept); row j is each layer's (j+1)-th widest ring.
    The surface's curvature at a layer (sphjet's sign, -1/a for a cylinder) is that of the
    parabola through the widest rings of the LAYER_FIT layers either side. Each row's curvature against it, both less their straight line
    along the stretch (the taper), gives a slope: 1 where the row is bent as the surface is,
    below 0 where it pulls the other way -> [(row, median slope, first and third quartiles,
    snapshots)] and the median count of layers, or ([], 0) without MIN_LAYERS layers in any."""
    import numpy as np
    d0, dx = c["d0"], c["dx"]
    n = max(1, round(0.5 * d0 / dx))
    sign = 1.0 if c["axis"] == "down" else -1.0
    per, counts = {}, []
    for name, _t, g, on in fluid_snapshots(run, t0, t1):
        if "curvature" not in g:
            raise NoiseError(f"{run}/{name}: no particles/curvature in the snapshot, which --row-curvature reads")
        x, z, kap = np.abs(g["x"][:][on]), g["z"][:][on], g["curvature"][:][on]
        s = sign * (c["z0"] - z) / d0
        m = (s >= s0) & (s < s1) & (x < d0)
        x, s, kap = x[m], s[m], kap[m]
        o = np.argsort(s)
        x, s, kap = x[o], s[o], kap[o]
        cuts = np.nonzero(np.diff(s) * d0 / dx > LAYER_GAP)[0] + 1
        layers = [ly[np.argsort(-x[ly])] for ly in np.split(np.arange(len(s)), cuts) if abs(len(ly) - n) <= 1]
        if len(layers) < MIN_LAYERS:
            continue
        counts.append(len(layers))
        zl = np.array([s[ly].mean() * d0 for ly in layers])
        rl = np.array([x[ly[0]] for ly in layers])
        kg = np.full(len(layers), np.nan)
        for i in range(LAYER_FIT, len(layers) - LAYER_FIT):
            q = np.polyfit(zl[i - LAYER_FIT:i + LAYER_FIT + 1] - zl[i], rl[i - LAYER_FIT:i + LAYER_FIT + 1], 2)
            r, r1, r2 = q[2], q[1], 2.0 * q[0]
            kg[i] = -(1.0 / (r * math.sqrt(1.0 + r1 * r1)) - r2 / (1.0 + r1 * r1) ** 1.5)
        for j in range(n + 1):
            kj = np.array([kap[ly[j]] if len(ly) > j else np.nan for ly in layers])
            use = ~np.isnan(kg) & ~np.isnan(kj) & (kj != 0.0)
            if use.sum() < MIN_LAYERS // 2:
                continue
            zu = zl[use]
            gg, yy = (v - np.polyval(np.polyfit(zu, v, 1), zu) for v in (kg[use], kj[use]))   # less the taper
            if np.dot(gg, gg) > 0.0:
                per.setdefault(j, []).append(float(np.dot(gg, yy) / np.dot(gg, gg)))
    if not counts:
        return [], 0
    return ([(j, float(np.median(v)), float(np.percentile(v, 25)), float(np.percentile(v, 75)), len(v))
             for j, v in sorted(per.items())], int(np.median(counts)))


def one_frequency(surface, omega, c, summary):
    """--frequency: prints the amplitude of r_s at omega along the jet (frequency_envelope), its
    growing stretch (fit_growth's rule) and, on a round jet with surface tension, its growth
    over that wave's own Weber growth along the jet (tools/jet_gravity_theory.py's
    Jet.wave_exponent: its local ka omega a(z) / U(z), with gravity along the jet or without);
    adds freq_* keys to summary."""
    env = frequency_envelope(surface, omega)
    if not env:
        print(f"one frequency omega = {omega:.4g} 1/s: no slice reached in {FREQ_COVER:.0%} of the samples")
        return
    print(f"one frequency omega = {omega:.4g} 1/s (r_s's amplitude at it over the samples, Hann-windowed, "
          f"at the slices the intact jet reaches in {FREQ_COVER:.0%} of them), A/a at s/d0: "
          + ", ".join(f"{s:.2f}:{A:.2e}" for s, A, _ in env[:: max(1, len(env) // 16)]))
    fit = fit_growth(env)
    if fit is None or not (c["round"] and c["sigma"] > 0):
        return
    if c["g_along"] < 0.0:
        print("  its Weber growth along the jet: not computed for a jet that gravity slows")
        return
    from jet_gravity_theory import Jet
    d0 = c["d0"]
    jet = Jet(c["u0"], 0.5 * d0, c["g_along"], c["rho"], c["sigma"], c["nu"] * c["rho"])
    n = jet.wave_exponent(omega)
    got = growth_over(env, fit[2], fit[3], lambda s: jet.exponent_at(n, s * d0))
    if got is None:
        return
    print(f"  over s = {fit[2]:.2f}-{fit[3]:.2f} d0 it grows at {got[0]:.3f} of its own Weber growth along the "
          f"jet (tools/jet_gravity_theory.py, the wave's local ka omega a(z)/U(z): {omega * 0.5 * d0 / c['u0']:.3f} "
          f"at the orifice); by quarters " + ", ".join(f"{q:.3f}" for q in got[1])
          + f"; the line's C = ln(a/delta0) at the orifice {-got[2]:.2f}")
    summary.update({"freq_growth_over_theory": got[0], "freq_C": -got[2]})


def analyse(run, t0=None, wave=None, t1=None, at=(), show_rows=False, frequency=None, row_curv=None,
            spatial=False):
    """Prints the measures of the run directory `run` over its samples at t0 <= t <= t1 (t0 None:
    twice the first breakup time; t1 None: the last sample) and returns them: a dict with "summary" (the SUMMARY line's values)
    and what the plot draws. wave: None or (s0, s1), the stretch (in d0) whose dominant wave to
    read. at: distances s/d0 at which to print the envelope (the nearest slice). show_rows: print
    the rows' pressures and radii along the jet (noise_along; round jets). frequency: None or
    the angular frequency [1/s] whose own amplitude and growth to read. row_curv: None or (s0,
    s1), the stretch whose rows' curvature to read (row_curvature; round jets). spatial: on a
    falling round jet, the growth over the spatial one-frequency picture too. NoiseError for
    a run without the files or samples it needs."""
    try:
        c = read_case(run)
    except (OSError, KeyError, tomllib.TOMLDecodeError) as e:
        raise NoiseError(f"{run}: cannot read its case.toml ({e})")
    d0, u0 = c["d0"], c["u0"]
    a = 0.5 * d0
    jet = read_rows(os.path.join(run, "jet.csv"))
    if not jet:
        raise NoiseError(f"{run}/jet.csv has no samples")
    if "p_exit_mean" not in jet[0]:
        raise NoiseError(f"{run}/jet.csv has no exit-noise columns (a run older than them)")
    if t0 is None:
        first = next((float(r["time"]) for r in jet if r["broken"] == "1"), None)
        t0 = 2.0 * first if first is not None else 0.5 * float(jet[-1]["time"])
    t1 = math.inf if t1 is None else t1
    rows = [r for r in jet if t0 <= float(r["time"]) <= t1]
    if not rows:
        raise NoiseError(f"{run}: no sample at {t0:g} s <= t <= {t1:g} s (the run's samples: "
                         f"{jet[0]['time']} to {jet[-1]['time']} s)")
    steps = {r["step"] for r in rows}
    all_surface = read_rows(os.path.join(run, "jet_surface.csv"))
    surface = [r for r in all_surface if r["step"] in steps]

    sig = c["sigma"]
    p_unit = sig / a if sig > 0 else float("nan")
    v_cap = math.sqrt(sig / (c["rho"] * a)) if sig > 0 else float("nan")
    t_cap = math.sqrt(c["rho"] * a ** 3 / sig) if sig > 0 else float("nan")
    oh = c["nu"] * math.sqrt(c["rho"] / (sig * a)) if sig > 0 else 0.0

    def med(col):
        return median([float(r[col]) for r in rows if r[col] not in ("nan", "")])

    pm, ps, ur = med("p_exit_mean"), med("p_exit_std"), med("ur_exit_rms")
    lengths = [float(r["L_over_d0"]) for r in rows if r["broken"] == "1"]
    l_mean = sum(lengths) / len(lengths) if lengths else float("nan")
    print(f"samples = {len(rows)} from t = {t0:.4g} s to {rows[-1]['time']} s; "
          f"broken in {len(lengths)}; L/d0 mean {l_mean:.3f}")
    print(f"exit (0-2 d0): p mean = {pm:.4g} Pa = {pm / p_unit:.3f} sigma/a, p std = {ps:.4g} Pa = "
          f"{ps / p_unit:.3f} sigma/a, u_r rms = {ur:.3g} m/s = {ur / v_cap:.3g} sqrt(sigma/(rho a))")

    env = envelope(surface, rows, a)
    fit = fit_growth(env)
    w_max, ka_max = weber_max(oh)
    w_ka = weber_omega(c["ka"], oh)
    summary = {"samples": len(rows), "L_over_d0": l_mean, "p_exit_mean_over_sigma_a": pm / p_unit,
               "p_exit_std_over_sigma_a": ps / p_unit, "ur_exit_rms_over_vcap": ur / v_cap}
    if env:
        print("envelope A/a at s/d0: " + ", ".join(f"{s:.2f}:{A:.2e}" for s, A, _ in env[:: max(1, len(env) // 16)]))
    half = 0.5 * (env[1][0] - env[0][0] if len(env) > 1 else 1.0) * (1 + 1e-6)   # a slice's half width
    for s_at in at:
        near = min(env, key=lambda e: abs(e[0] - s_at)) if env else None
        if near is None or abs(near[0] - s_at) > half:
            print(f"envelope at s = {s_at:g} d0: not reached by the intact jet in half of the samples")
            continue
        print(f"envelope at s = {s_at:g} d0 (slice {near[0]:.4g}): A/a = {near[1]:.3e}")
        summary[f"A_at_{s_at:g}"] = near[1]
    if fit:
        k, ln_d, s0, s1 = fit
        omega = k / d0 * u0
        c_fit = -ln_d
        print(f"growth fit over s = {s0:.2f}-{s1:.2f} d0: k_s = {k:.4g} per d0 (one e-fold per {1 / k:.3g} d0), "
              f"omega = k_s u0 = {omega:.4g} 1/s = {omega * t_cap:.3f} / t_cap")
        print(f"intercept at the orifice: delta0/a = {math.exp(ln_d):.3e}, C = ln(a/delta0) = {c_fit:.2f}; "
              f"the fitted line reaches a at s = C / k_s = {c_fit / k:.4g} d0")
        summary.update({"k_s_per_d0": k, "omega": omega, "omega_over_weber": omega * t_cap / w_max,
                        "delta0_over_a": math.exp(ln_d), "C": c_fit, "L_fit_over_d0": c_fit / k})
        falling = falling_growth(env, s0, s1, c) if c["round"] and sig > 0 and c["g_along"] > 0 else None
        if falling is not None:
            print(f"growth along the falling jet (g = {c['g_along']:g} m/s^2 along it) over Weber's growth "
                  f"integrated along it (the local radius and speed; tools/jet_gravity_theory.py): "
                  f"{falling[0]:.3f} over s = {s0:.2f}-{s1:.2f} d0; by quarters of it "
                  + ", ".join(f"{q:.3f}" for q in falling[1]))
            summary["growth_over_falling_theory"] = falling[0]
            one = falling_growth(env, s0, s1, c, one_frequency=True)
            print(f"the same over the growth of the frequency that has grown most along it (each carried "
                  f"down at its own frequency; tools/jet_gravity_theory.py --one-frequency): {one[0]:.3f}; "
                  "by quarters " + ", ".join(f"{q:.3f}" for q in one[1]))
            summary["growth_over_one_frequency_theory"] = one[0]
            if spatial:
                sp = falling_growth(env, s0, s1, c, spatial=True)
                print(f"the same over that frequency's spatial growth (Keller, Rubinow & Tu's -Im k; "
                      f"tools/jet_gravity_theory.py --spatial): {sp[0]:.3f}; by quarters "
                      + ", ".join(f"{q:.3f}" for q in sp[1]))
                summary["growth_over_spatial_theory"] = sp[0]
    else:
        print("growth fit: no growing stretch found (envelope too short or flat)")
    if c["round"] and sig > 0:
        print(f"Weber (Oh = {oh:.4g}): omega_max = {w_max / t_cap:.4g} 1/s at ka = {ka_max:.3f}; "
              f"at ka = {c['ka']:.3f}: {w_ka / t_cap:.4g} 1/s; t_cap = sqrt(rho a^3/sigma) = {t_cap:.4g} s")
        if fit:
            l_weber = u0 * (-fit[1]) / (w_max / t_cap) / d0
            print(f"Weber's L = u0 C / omega_max with this C: {l_weber:.3g} d0")
            summary["L_weber_over_d0"] = l_weber
    front, slope = startup_front(all_surface, t0)
    if slope is not None:
        v_f = slope * d0
        print(f"start-up front (|r_s/a - 1| > {FRONT_THRESHOLD:g} past {FRONT_FROM_D0:g} d0, {len(front)} samples "
              f"before t = {t0:.4g} s): from s = {front[0][1]:.2f} d0 at {front[0][0]:.4g} s to {front[-1][1]:.2f} d0 "
              f"at {front[-1][0]:.4g} s; leaves the orifice at {v_f:.3g} m/s, runs up the jet at u0 - that = "
              f"{u0 - v_f:.3g} m/s = {(u0 - v_f) / v_cap:.3g} sqrt(sigma/(rho a))")
        summary.update({"front_speed": v_f, "front_upstream_over_vcap": (u0 - v_f) / v_cap})
    if wave is not None:
        got = dominant_wave(surface, *wave)
        if got is None:
            print(f"dominant wave over s = {wave[0]:g}-{wave[1]:g} d0: fewer than 8 samples cover it")
        else:
            ka, om, c_d0, n = got
            c_lab = c_d0 * d0
            falls = c["round"] and sig > 0 and c["g_along"] > 0
            if falls:   # the stretch's middle, where a falling jet is faster and thinner than at the orifice
                from jet_gravity_theory import Jet
                one = Jet(u0, a, c["g_along"], c["rho"], sig, c["nu"] * c["rho"], one_frequency=True)
                z_mid = 0.5 * (wave[0] + wave[1]) * d0
                u_mid, a_mid = one.local(z_mid)
            else:
                u_mid, a_mid = u0, a
            line = (f"dominant wave over s = {wave[0]:g}-{wave[1]:g} d0 ({n} samples): ka = {ka:.3g}, "
                    f"omega = {om:.4g} 1/s, crests move at {c_lab:+.3g} m/s in the lab (down the jet > 0), "
                    f"{c_lab - u_mid:+.3g} m/s against the fluid")
            if falls and lengths:
                om_l = one.best_frequency(l_mean * d0)
                line += (f"; at the stretch's middle the falling jet moves at {u_mid:.4g} m/s with radius "
                         f"{a_mid / a:.4f} a, so the wave's local ka = {ka * a_mid / a:.3g}; the frequency that has "
                         f"grown most by the jet's length {l_mean:.1f} d0 (tools/jet_gravity_theory.py "
                         f"--one-frequency) is omega = {om_l:.4g} 1/s, local ka {om_l * a_mid / u_mid:.3g} there; "
                         f"Weber's fastest there is ka = {weber_max(c['nu'] * math.sqrt(c['rho'] / (sig * a_mid)))[1]:.3f}")
                summary.update({"wave_local_ka": ka * a_mid / a, "wave_one_frequency_omega": om_l,
                                "wave_one_frequency_local_ka": om_l * a_mid / u_mid})
            if ka > 1.01 and sig > 0:   # the stable branch, clear of ka = 1 where omega -> 0
                def om_r(x):
                    return math.sqrt(-rayleigh_omega2(x)) / t_cap
                c_r = om_r(ka) * a / ka
                cg_r = (om_r(ka * 1.001) - om_r(ka * 0.999)) / (0.002 * ka / a)
                line += f"; Rayleigh's capillary wave at that ka: phase speed {c_r:.3g} m/s, group velocity {cg_r:.3g} m/s"
            print(line)
            summary.update({"wave_ka": ka, "wave_speed": c_lab})
    if frequency is not None:
        one_frequency(surface, frequency, c, summary)
    if row_curv is not None:
        if not (c["round"] and sig > 0 and c["dx"]):
            print("rows' curvature: only for a round jet with surface tension and resolution.dx in its case.toml")
        else:
            got, layers = row_curvature(run, c, t0, t1, *row_curv)
            if not got:
                print(f"rows' curvature over s = {row_curv[0]:g}-{row_curv[1]:g} d0: no snapshot with {MIN_LAYERS} "
                      "layers of rings there (the rings no longer lie in layers, or no snapshots)")
            else:
                print(f"rows' curvature over s = {row_curv[0]:g}-{row_curv[1]:g} d0 ({layers} layers of rings, median "
                      "over the snapshots): each row's against the surface's geometric curvature (1 bent as the "
                      "surface, below 0 the other way), row 0 the surface's: " + "; ".join(
                          f"row {j} {m:+.2f} ({lo:+.2f} to {hi:+.2f}, {k} snapshots)" for j, m, lo, hi, k in got))
                summary.update({f"row{j}_curvature_slope": m for j, m, _lo, _hi, _k in got})
    spec = spectrum(surface, d0, a)
    if spec:
        kpk, apk = max(spec, key=lambda e: e[1])
        print(f"spectrum peak: ka = {kpk:.3f}, amplitude {apk:.3e} a")
        summary["spectrum_peak_ka"] = kpk
    prof = (noise_along(run, c["z0"], d0, p_unit, t0, jet, c["dx"] if c["round"] else None, u0, t1)
            if sig > 0 else None)
    if prof:
        def quiet_to(slices):   # the first 2 d0 slice above sigma/(4a), or past the last one
            return next((s0 for s0, v in slices if v > 0.25), slices[-1][0] + 2.0)
        quiet = quiet_to([(s0, v) for s0, v, _o, _r, _i in prof])
        print("pressure std / (sigma/a) along the intact jet (2 d0 slices, median over snapshots): "
              + ", ".join(f"{s0:.0f}:{v:.3g}" for s0, v, _o, _r, _i in prof))
        orders = [(s0, o) for s0, _v, o, _r, _i in prof if o is not None]
        if orders:
            print("axis order along the intact jet (rings within 0.6 dx of the axis over an ordered lattice "
                  "stretched with the flow, 2 d0 slices, median over snapshots): "
                  + ", ".join(f"{s0:.0f}:{o:.2f}" for s0, o in orders))
            summary["axis_order_min"] = min(o for _s, o in orders)
        if show_rows:
            spreads = []
            for s0, _v, _o, rw, _i in prof:
                if rw is None:
                    continue
                a_s, ps, rs = rw
                print(f"rows at s = {s0:.0f}-{s0 + 2:.0f} d0: a_s/a = {a_s:.3f}, mean p / (sigma/a_s) from the axis "
                      "out: " + " ".join(f"{v:.3f}" for v in ps) + "; mean r / (a_s/n): "
                      + " ".join(f"{v:.3f}" for v in rs))
                if not any(math.isnan(v) for v in ps):
                    spreads.append(max(ps) - min(ps))
            if spreads:
                summary["rows_spread_max"] = max(spreads)
        print(f"quiet (p std <= sigma/(4a)) to s = {quiet:.0f} d0, {l_mean - quiet:.1f} d0 above the "
              f"breakup (L {l_mean:.1f} d0)")
        summary.update({"quiet_to_over_d0": quiet, "noisy_reach_over_d0": l_mean - quiet})
        in_rows = [(s0, i) for s0, _v, _o, _r, i in prof if i is not None]
        if in_rows:
            quiet_in = quiet_to(in_rows)
            print("pressure std about the rows' means / (sigma/a) along the intact jet (the rows' pattern taken "
                  "out): " + ", ".join(f"{s0:.0f}:{i:.3g}" for s0, i in in_rows))
            print(f"quiet about the rows' means to s = {quiet_in:.0f} d0, {l_mean - quiet_in:.1f} d0 above the "
                  "breakup")
            summary.update({"quiet_in_rows_to_over_d0": quiet_in, "noisy_in_rows_reach_over_d0": l_mean - quiet_in})
    elif prof is None:
        print("noise along the jet: no snapshots (snap_*.h5) in the run directory")
    print("SUMMARY " + " ".join(f"{k}={v:.6g}" if isinstance(v, float) else f"{k}={v}" for k, v in summary.items()))
    return {"summary": summary, "case": c, "env": env, "fit": fit, "spec": spec, "w_max": w_max,
            "ka_max": ka_max, "t_cap": t_cap}


def plot(run, got, out):
    """The envelope and its fit beside the spectrum, from analyse's `got`, to the PNG out."""
    c, env, fit, spec = got["case"], got["env"], got["fit"], got["spec"]
    d0, u0, sig = c["d0"], c["u0"], c["sigma"]
    w_max, ka_max, t_cap = got["w_max"], got["ka_max"], got["t_cap"]
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    if env:
        ax1.semilogy([e[0] for e in env], [e[1] for e in env], ".", label="A(s) / a")
    if fit:
        k, ln_d, s0, s1 = fit
        ss = [0.0, s1]
        ax1.semilogy(ss, [math.exp(ln_d + k * s) for s in ss], "-", label=f"fit: C = {-ln_d:.2f}")
        if c["round"] and sig > 0:
            kw = w_max / t_cap / u0 * d0
            ax1.semilogy(ss, [math.exp(ln_d + kw * (s - s0) + k * s0) for s in ss], "--",
                         label="Weber's growth")
    ax1.set_xlabel("s / d0 (from the orifice)")
    ax1.set_ylabel("disturbance amplitude / a")
    ax1.legend()
    if spec:
        ax2.semilogy([e[0] for e in spec], [e[1] for e in spec], "-")
        ax2.axvline(ka_max, ls=":", color="k")
    ax2.set_xlabel("ka")
    ax2.set_ylabel("mean amplitude / a")
    fig.suptitle(os.path.basename(os.path.normpath(run)))
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    print(f"plot: {out}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("run")
    ap.add_argument("--from", dest="t0", type=float, default=None,
                    help="first sample time [s] (default: twice the first breakup time: the start-up head gone)")
    ap.add_argument("--to", dest="t1", type=float, default=None,
                    help="last sample time [s] (default: the run's last sample)")
    ap.add_argument("--plot", default=None, help="write the envelope and the spectrum to this PNG")
    ap.add_argument("--at", nargs="+", type=float, default=[], metavar="S",
                    help="print the envelope A/a at these distances from the orifice [d0] (SUMMARY A_at_S): "
                         "read over successive stretches of time, whether the disturbance at a place is steady")
    ap.add_argument("--rows", action="store_true",
                    help="print each ring row's mean pressure over the local Laplace pressure and its mean radius "
                         "over the local row spacing along the intact jet (2 d0 slices, medians over the snapshots; "
                         "SUMMARY rows_spread_max: the largest pressure spread between a slice's rows)")
    ap.add_argument("--frequency", type=float, default=None, metavar="OMEGA",
                    help="read the amplitude of r_s at this angular frequency [1/s] along the jet and its growth "
                         "over that wave's own Weber growth")
    ap.add_argument("--wave", nargs=2, type=float, default=None, metavar=("S0", "S1"),
                    help="read the dominant wave of r_s over s = S0-S1 d0 (its ka and speed)")
    ap.add_argument("--row-curvature", nargs=2, type=float, default=None, metavar=("S0", "S1"),
                    help="read, from the snapshots, how each row of rings over s = S0-S1 d0 is bent by the surface "
                         "tension against the surface's geometric curvature (round jets)")
    ap.add_argument("--spatial", action="store_true",
                    help="on a falling round jet, also the growth over the frequency that has grown most at its "
                         "spatial rate (tools/jet_gravity_theory.py --spatial; 15-60 s more)")
    args = ap.parse_args(argv)
    if args.t0 is not None and args.t1 is not None and args.t1 < args.t0:
        ap.error(f"--to {args.t1:g} is before --from {args.t0:g}")
    if args.frequency is not None and not args.frequency > 0.0:
        ap.error(f"--frequency needs an angular frequency above 0 (1/s), got {args.frequency:g}")
    if args.wave is not None and not 0.0 <= args.wave[0] < args.wave[1]:
        ap.error(f"--wave S0 S1 needs 0 <= S0 < S1 (d0), got {args.wave[0]:g} {args.wave[1]:g}")
    if args.row_curvature is not None and not 0.0 <= args.row_curvature[0] < args.row_curvature[1]:
        ap.error(f"--row-curvature S0 S1 needs 0 <= S0 < S1 (d0), got {args.row_curvature[0]:g} "
                 f"{args.row_curvature[1]:g}")
    try:
        got = analyse(args.run, args.t0, args.wave, args.t1, args.at, args.rows, args.frequency,
                      args.row_curvature, args.spatial)
    except NoiseError as e:
        sys.exit(f"jet_noise.py: {e}")
    if args.plot:
        plot(args.run, got, args.plot)
    return 0


if __name__ == "__main__":
    sys.exit(main())
