#!/usr/bin/python3
"""The capillary growth of a round jet's own numerics: a periodic column of the jet's radius at
rest, one wavelength long at k a = KA, with the jet case's numerics, fluid and surface tension,
and its growth rate against Weber's.

Usage (Debian's python3 has numpy and h5py):
  /usr/bin/python3 tools/jet_column.py SOURCE [--set KEY=VALUE ...] [--d0-over-dx N] [--ka 0.7]
      [--eps 1e-5] [--speed-ratio 1] [--h-over-dx H] [--rows] [--out DIR] [--threads 1] [--sphjet build/cpp_driver/sphjet]
      [--force]

SOURCE is a round-jet case file (a modern .toml with a [nozzle]) or a run directory (its
case.toml); --set overrides its keys as `sphjet run --set` does, before the column is built
from it. The column takes the case's [numerics], [fluid], [surface_tension] and [domain] keys
(geometry, axis pair, continuity, XSPH bound), the radius a = nozzle.d0 / 2, the spacing d0 / N
(N = --d0-over-dx, or the case's own nozzle.d0 / resolution.dx; an even number, so that whole
rings span the radius) with the case's h / dx and jitter, and the case's step settings with its
step and the step's cap scaled by the spacing. Gravity, the nozzle and the breakup checks are
left out. The column, r = a (1 + eps cos(k z)) at rest (fluid.cylinder), runs for the time
Weber's rate takes from eps to --fit-to, and two of its e-folds more.

A falling jet speeds up from U0 to U and each ring keeps its mass and volume: the rings move
U/U0 times as far apart along the axis and the radius and the radial spacing shrink as
(U0/U)^1/2, while h stays the nozzle's (measured on the 0.78 m/s jet at d0/dx 16, 35a8c29, 75 d0 down:
rings 1.50 spacings apart on the axis, radius 0.796 a, against U/U0 = 1.55). --speed-ratio R
builds the column on that lattice: radius a R^-1/2 (ka and Weber's rate are the column's own),
R^-1/2 of the spacing across, R times it along the axis, h and the step as at R = 1. At R = 1 the
case is the one without the option, byte for byte. --h-over-dx H gives the column a smoothing length
of H nozzle spacings (d0 / N) in place of the case's, the step kept: on the lattice of a falling jet
the kernel's reach along the axis is h / (R dx), 1.11 at h = 2 dx and R = 1.8, where a column of
five rings grows its wave at 2.3 times Weber's rate (cases/round_jet/README.md, "A stretched
lattice").

The amplitude is the first Fourier mode over the period of the rows' surface radii (the largest
radius in each row's slice of z, as `tools/axisymmetric.py roughness` reads them): at the start
it is the outer row's radius times eps, (1 - dx / (2a)) eps a, where the volume per slice of
`axisymmetric.py growth` reads the lattice's aliasing (4.5e-3 a at a/dx = 5 over 32 slices).
The growth rate is the slope of its logarithm against time over the samples between --fit-from
and --fit-to, 1e-4 a and 5e-3 a by default. Below them lies the start from rest, whose first
e-fold runs at about 0.6 of the settled rate and its second at 0.9-1.0. Above 1e-2 a the
slices' reading departs: the e-fold before 1.5e-2 a reads 10-30% faster than the ones before
it. Between them the rate per e-fold holds within 1% (measured at d0/dx 10-20). The rate over
each e-fold of the amplitude is printed too, so that the fit's range can be judged.

--rows prints the curvature the surface tension gives each row, counted inward from the surface
row of each slice of z, over the snapshots whose wave lies in the fit's range: its mean times a
(-1 for a cylinder, sphjet's sign) and its wave over the column's geometric one (1 is right;
row_curvatures). The CSF acts on every row the kernel's reach from the surface touches (four at
h = 2 dx), each with its own curvature.

Prints the table and a line
  SUMMARY d0_over_dx=N a_over_dx=.. ka=.. eps=.. growth=.. weber=.. growth_over_weber=.. ... speed_ratio=R h_over_dx=H
with the fit's rms residual in ln A (fit_rms), and a line saying so when that is above 0.05: the
amplitude then does not grow as one exponential and the rate is no growth rate. Exit status 1 with a message naming the file or key on bad input, or when the fit's range holds
fewer than four samples.
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tomllib

TOOLS = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(TOOLS)
sys.path.insert(0, TOOLS)

import axisymmetric  # noqa: E402  (weber_omega, snapshots, fluid, row_radii, mode_amplitudes)

# the [domain] keys a column keeps from the jet: the pair, the continuity and the XSPH bound
DOMAIN_KEYS = ("geometry", "axis_pair", "split_axis_rings", "renormalise_ring_continuity",
               "bound_ring_xsph")
# the [time] keys a column keeps from the jet (dt and dt_max are scaled by the spacing)
TIME_KEYS = ("variable_dt", "cfl")
BOX_RADII = 4.0          # the box reaches 4 a from the axis: the column's surface moves < 0.2 a
SAMPLES_PER_EFOLD = 8    # outputs per e-fold of Weber's growth
ONE_EXPONENTIAL = 0.05   # the fit's rms residual in ln A above which the amplitude is no one exponential
                         # (0.0014 at d0/dx 10, 0.018 for d0/dx 8's quickening wave; a wave that
                         # oscillates reads 0.3-0.5)
EXTRA_EFOLDS = 2.0       # the run goes on two of Weber's e-folds past --fit-to (a column at 0.85 of
                         # Weber's rate still passes it)


class ColumnError(Exception):
    pass


def toml_value(v, key):
    """A scalar or a list of them as TOML writes it (key: its name, for the error)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)   # a JSON string's escapes are TOML's basic string's
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x, key) for x in v) + "]"
    raise ColumnError(f"{key}: expected a number, string, boolean or a list of them, found {v!r}")


def toml_table(name, table):
    """[name] and its scalar keys (sub-tables and arrays of tables are left out)."""
    lines = [f"[{name}]"]
    lines += [f"{k} = {toml_value(v, f'{name}.{k}')}" for k, v in table.items()
              if not isinstance(v, dict) and not (isinstance(v, list) and v and isinstance(v[0], dict))]
    return "\n".join(lines) + "\n"


def resolve(source, sets, sphjet, work):
    """The jet case as sphjet reads it (every key written out, --set applied): `sphjet run
    --max-steps 0` into work/jet, then its case.toml parsed. A run directory gives its case.toml."""
    case = os.path.join(source, "case.toml") if os.path.isdir(source) else source
    if not os.path.isfile(case):
        raise ColumnError(f"{source}: no such case file or run directory with a case.toml")
    out = os.path.join(work, "jet")
    argv = [sphjet, "run", case, "--out", out, "--max-steps", "0", "-j", "1", "-q", "--force",
            "--format", "hdf5"]
    for s in sets:
        argv += ["--set", s]
    r = subprocess.run(argv, capture_output=True, text=True)
    if r.returncode != 0:
        raise ColumnError(f"{case}: sphjet refused the case:\n{r.stderr.strip() or r.stdout.strip()}")
    written = os.path.join(out, "case.toml")
    try:
        with open(written, "rb") as f:
            return tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise ColumnError(f"{written}: expected the case as sphjet wrote it, found: {e}") from None


def need(jet, table, key, source):
    try:
        return jet[table][key]
    except KeyError:
        raise ColumnError(f"{source}: {table}.{key}: expected in a round jet's case, found none") from None


def column_case(jet, source, d0_over_dx, ka, eps, fit_to, speed_ratio=1.0, h_over_dx=None):
    """-> (the column's case text, its parameters). jet: the resolved jet case (resolve).
    speed_ratio R: the lattice of a jet that has sped up R times (--speed-ratio): the radius and
    the radial spacing R^-1/2 times the jet's, the axial spacing R times, h and the step kept.
    h_over_dx H: the smoothing length H times the nozzle's spacing d0 / N (None: the case's h / dx),
    the step kept."""
    if need(jet, "domain", "geometry", source) != "axisymmetric":
        raise ColumnError(f"{source}: domain.geometry: expected \"axisymmetric\" (a round jet), "
                          f"found {jet['domain']['geometry']!r}")
    d0 = need(jet, "nozzle", "d0", source)
    dx_jet = need(jet, "resolution", "dx", source)
    if h_over_dx is None:
        h_over_dx = need(jet, "resolution", "h", source) / dx_jet
    n = d0_over_dx if d0_over_dx is not None else d0 / dx_jet
    if abs(n / 2 - round(n / 2)) > 1e-3 * n:   # the case's keys carry 9 digits
        # fluid.cylinder lays round(a / dx) rings across the radius: a/dx between two whole
        # numbers would give a radial spacing other than dx, a lattice the jet does not have
        raise ColumnError(f"{'--d0-over-dx' if d0_over_dx is not None else source + ': nozzle.d0 / resolution.dx'}: "
                          f"expected an even number (whole rings across the radius), found {n:.6g}")
    # each ring keeps its mass and volume as the jet speeds up: r and dr shrink as R^-1/2, dz grows as R
    a, dx = 0.5 * d0 / math.sqrt(speed_ratio), d0 / n / math.sqrt(speed_ratio)
    dz, h = d0 / n * speed_ratio, h_over_dx * (d0 / n)
    wavelength = 2.0 * math.pi * a / ka
    rho, nu = need(jet, "fluid", "rho0", source), need(jet, "fluid", "nu", source)
    sigma = need(jet, "surface_tension", "sigma", source)
    if not sigma > 0:
        raise ColumnError(f"{source}: surface_tension.sigma: expected > 0 (a capillary column), found {sigma}")
    scale = math.sqrt(sigma / (rho * a ** 3))
    oh = nu * math.sqrt(rho / (sigma * a))
    weber = axisymmetric.weber_omega(ka, oh) * scale
    if not weber > 0:
        raise ColumnError(f"--ka {ka}: expected a capillary-unstable wave (0 < ka < 1)")
    tmax = (math.log(fit_to / eps) + EXTRA_EFOLDS) / weber
    domain = {k: jet["domain"][k] for k in DOMAIN_KEYS if k in jet["domain"]}
    domain |= {"lx": BOX_RADII * a, "lz": wavelength, "periodic_z": True, "wall_left": False,
               "wall_right": False, "wall_bottom": False, "wall_top": False}
    time = {k: jet["time"][k] for k in TIME_KEYS if k in jet["time"]}
    for k in ("dt", "dt_max"):   # a fixed step, the initial step and the cap: F cfl h / c0 scales with dx
        if k in jet["time"]:
            time[k] = jet["time"][k] * (d0 / n) / dx_jet
    time |= {"tmax": tmax, "out": 1.0 / (SAMPLES_PER_EFOLD * weber)}
    text = (f"# a periodic column with the numerics of {source} (tools/jet_column.py)\n"
            "format_version = 1\n\n"
            + toml_table("numerics", jet["numerics"]) + "\n"
            + toml_table("fluid", jet["fluid"])
            + f"\n[[fluid.cylinder]]\nradius = {a!r}\neps = {eps!r}\nwavelength = {wavelength!r}\n\n"
            + toml_table("surface_tension", jet["surface_tension"]) + "\n"
            + "[gravity]\ngx = 0.0\ngz = 0.0\n\n"
            + toml_table("domain", domain) + "\n"
            + toml_table("resolution", {"dx": dx, "dz": dz, "h": h}
                         | {k: jet["resolution"][k] for k in ("jitter", "jitter_seed") if k in jet["resolution"]}) + "\n"
            + toml_table("time", time) + "\n"
            + '[output]\nformat = "hdf5"\ncheckpoint_every_minutes = 0.0\n')
    return text, {"a": a, "dx": dx, "dz": dz, "n": n, "wavelength": wavelength, "weber": weber, "oh": oh,
                  "h_over_dx": h_over_dx}


def column_amplitudes(run, a, dz, wavelength):
    """-> (times, amplitude / a) of the column's wave: the first Fourier mode of the rows' surface
    radii over the period (axisymmetric.row_radii, the largest radius in each row's slice; rows
    dz apart along the axis), up to the first snapshot where a slice is empty."""
    import numpy as np
    times, amps = [], []
    for d in axisymmetric.snapshots(run):
        rs = axisymmetric.row_radii(axisymmetric.fluid(d), wavelength, dz)
        if rs is None:
            break
        times.append(d["time"])
        amps.append(float(axisymmetric.mode_amplitudes(rs, a)[1]))
    return np.array(times), np.array(amps)


def row_curvatures(run, a, dz, wavelength, lo, hi):
    """The curvature the CSF gives each row, counted from the surface inward in each row's slice
    of z (row 0 its largest radius), over the snapshots whose wave is between lo and hi a ->
    [(row, share of its slices where the curvature is not zero, mean curvature times a, its
    wave over the geometric one)], medians over those snapshots; the rows down to the last whose
    curvature is not zero (the surface band). The geometric wave is the column's: r = a + A
    cos(kz) bends the surface by kappa' = A (1 - (ka)^2) / a^2 in sphjet's sign (a cylinder's
    kappa is -1/a), so that 1 is right; the wave is the first Fourier mode over the period,
    taken in phase with the surface's (it means something for a row in the band in every slice;
    --rows prints it only for those)."""
    import numpy as np
    k = 2.0 * math.pi / wavelength
    per = {}
    for d in axisymmetric.snapshots(run):
        f = axisymmetric.fluid(d)
        if "curvature" not in f:
            raise ColumnError(f"{run}: the snapshots hold no curvature (a run older than the field)")
        rs = axisymmetric.row_radii(f, wavelength, dz)
        if rs is None:   # a slice is empty: the column has broken
            break
        nb, b = axisymmetric.row_slices(f, wavelength, dz)
        phase = np.exp(-1j * k * (np.arange(nb) + 0.5) * wavelength / nb)   # at the slices' centres
        rows = [r[np.argsort(-np.abs(f["x"][r]))] for r in (np.nonzero(b == i)[0] for i in range(nb))]
        wave = 2.0 * np.mean((rs - rs.mean()) * phase)
        if not lo <= abs(wave) / a <= hi:
            continue
        geometric = wave * (1.0 - (k * a) ** 2) / a ** 2
        for j in range(min(len(r) for r in rows)):
            kj = np.array([f["curvature"][r[j]] for r in rows])
            if not np.any(kj):
                break
            m = 2.0 * np.mean((kj - kj.mean()) * phase)
            per.setdefault(j, []).append((float(np.mean(kj != 0.0)), float(kj.mean()) * a,
                                          float((m / geometric).real)))
    return [(j, *(float(np.median([v[i] for v in vals])) for i in range(3))) for j, vals in sorted(per.items())]


def growth_fit(t, amp, lo, hi):
    """-> (slope of ln amp against t over lo <= amp <= hi, samples, the rms of the line's residual
    in ln amp), the samples before the amplitude first passes hi."""
    import numpy as np
    past = np.nonzero(amp > hi)[0]
    end = past[0] if len(past) else len(amp)
    sel = np.nonzero(amp[:end] >= lo)[0]
    if len(sel) < 4:
        return float("nan"), len(sel), float("nan")
    line = np.polyfit(t[sel], np.log(amp[sel]), 1)
    rms = float(np.sqrt(np.mean((np.polyval(line, t[sel]) - np.log(amp[sel])) ** 2)))
    return float(line[0]), len(sel), rms


def efold_table(t, amp, weber):
    """The slope over each e-fold of the amplitude (from its first sample), over Weber's rate."""
    import numpy as np
    rows, i = [], 0
    while True:
        j = np.nonzero(amp[i:] >= amp[i] * math.e)[0]
        if not len(j) or not 0 < amp[i] <= 0.1:
            break
        j = i + j[0]
        rate = math.log(amp[j] / amp[i]) / (t[j] - t[i])
        rows.append(f"  {t[i] * 1e3:8.2f} {t[j] * 1e3:8.2f}   {amp[i]:9.3e}   {rate / weber:7.3f}")
        i = j
    return ["  t0 [ms]  t1 [ms]   A(t0) / a   growth / Weber"] + rows


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("source", help="a round jet's case file, or a run directory with a case.toml")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="override a key of the jet's case (sphjet run --set)")
    ap.add_argument("--d0-over-dx", type=float, default=None, help="particles across d0 (default: the case's)")
    ap.add_argument("--ka", type=float, default=0.7, help="the column's wave, k a (default 0.7)")
    ap.add_argument("--eps", type=float, default=1e-5, help="its amplitude at the start / a (default 1e-5)")
    ap.add_argument("--fit-from", type=float, default=1e-4, help="the fit's smallest amplitude / a (default 1e-4)")
    ap.add_argument("--fit-to", type=float, default=5e-3, help="the fit's largest amplitude / a (default 5e-3)")
    ap.add_argument("--speed-ratio", type=float, default=1.0, metavar="R",
                    help="the lattice of a falling jet where it has sped up R times: its rings R times as far "
                         "apart along the axis, the radius and the radial spacing R^-1/2 times (h and the step "
                         "kept; default 1)")
    ap.add_argument("--h-over-dx", type=float, default=None, metavar="H",
                    help="the column's smoothing length H nozzle spacings d0 / N (default: the case's h / dx), "
                         "the step kept")
    ap.add_argument("--rows", action="store_true",
                    help="also print the curvature the CSF gives each row from the surface inward, against the "
                         "column's geometric curvature, over the fit's range")
    ap.add_argument("--out", default=None, help="run directory (default: a temporary one, removed after)")
    ap.add_argument("--force", action="store_true", help="write into a non-empty --out")
    ap.add_argument("--threads", "-j", type=int, default=1)
    ap.add_argument("--sphjet", default=os.path.join(REPO, "build", "cpp_driver", "sphjet"))
    a = ap.parse_args(argv)
    if not 0 < a.ka < 1:
        ap.error(f"--ka {a.ka}: expected 0 < ka < 1 (a capillary-unstable wave)")
    if not 0 < a.eps < a.fit_from < a.fit_to <= 0.1:
        ap.error(f"--eps {a.eps:g} --fit-from {a.fit_from:g} --fit-to {a.fit_to:g}: expected "
                 "0 < eps < fit-from < fit-to <= 0.1")
    if not 1.0 <= a.speed_ratio <= 4.0:
        ap.error(f"--speed-ratio {a.speed_ratio:g}: expected 1 to 4 (a jet that gravity speeds up; at 4 the "
                 "rings are 4 spacings apart along the axis, as far as the kernel reaches)")
    if a.h_over_dx is not None and not 1.0 <= a.h_over_dx <= 4.0:
        ap.error(f"--h-over-dx {a.h_over_dx:g}: expected a smoothing length of 1 to 4 spacings")
    if a.d0_over_dx is not None and not a.d0_over_dx >= 4:
        ap.error(f"--d0-over-dx {a.d0_over_dx}: expected >= 4 (2 rows across the radius)")
    if not os.access(a.sphjet, os.X_OK):
        ap.error(f"--sphjet {a.sphjet}: not an executable (build first: cmake --build build)")
    import tempfile
    work = a.out if a.out is not None else tempfile.mkdtemp(prefix="jet_column_")
    try:
        if a.out and os.path.isdir(a.out) and os.listdir(a.out) and not a.force:
            raise ColumnError(f"--out {a.out}: not empty (give --force to write into it)")
        os.makedirs(work, exist_ok=True)
        jet = resolve(a.source, a.set, a.sphjet, work)
        text, p = column_case(jet, a.source, a.d0_over_dx, a.ka, a.eps, a.fit_to, a.speed_ratio, a.h_over_dx)
        case = os.path.join(work, "column.toml")
        with open(case, "w") as f:
            f.write(text)
        run = os.path.join(work, "column")
        r = subprocess.run([a.sphjet, "run", case, "--out", run, "-j", str(a.threads), "-q", "--force"],
                           capture_output=True, text=True)
        if r.returncode != 0:
            raise ColumnError(f"{case}: the column's run failed:\n{r.stderr.strip() or r.stdout.strip()}")
        t, amp = column_amplitudes(run, p["a"], p["dz"], p["wavelength"])
        rate, m, rms = growth_fit(t, amp, a.fit_from, a.fit_to)
        print(f"periodic column of {a.source}: a = {p['a']:.6g} m, d0/dx = {p['n']:.4g}, ka = {a.ka:g}, "
              f"Oh = {p['oh']:.4g}, Weber's rate {p['weber']:.5g} 1/s"
              + (f"; the lattice of the jet sped up {a.speed_ratio:g} times (spacings {p['dx']:.4g} m across, "
                 f"{p['dz']:.4g} m along the axis)" if a.speed_ratio != 1.0 else ""))
        print("\n".join(efold_table(t, amp, p["weber"])))
        if m < 4:
            raise ColumnError(f"{a.source}: --fit-from {a.fit_from:g} --fit-to {a.fit_to:g}: expected at least "
                              f"4 samples in that range, found {m} (the wave's amplitude reached at most "
                              f"{amp.max() if len(amp) else 0.0:.3g} a by t = {t[-1] if len(t) else 0.0:.4g} s; the table above gives its course"
                              + ("" if a.out is not None else "; --out DIR keeps the run") + ")")
        print(f"SUMMARY d0_over_dx={p['n']:.4g} a_over_dx={p['n'] / 2:.4g} ka={a.ka:g} eps={a.eps:g} "
              f"growth={rate:.5g} weber={p['weber']:.5g} growth_over_weber={rate / p['weber']:.4f} "
              f"fit_from={a.fit_from:g} fit_to={a.fit_to:g} samples={m} fit_rms={rms:.3g} "
              f"speed_ratio={a.speed_ratio:g} h_over_dx={p['h_over_dx']:.4g}")
        if a.rows:
            got = row_curvatures(run, p["a"], p["dz"], p["wavelength"], a.fit_from, a.fit_to)
            print(f"the rows' curvature over the snapshots with the wave at {a.fit_from:g}-{a.fit_to:g} a (medians; "
                  "row 0 the surface's; the share of its slices with a curvature; its mean times a, -1 a "
                  "cylinder's; its wave over the geometric one, 1 right):")
            print("\n".join(f"  row {j}: in {share:.0%} of the slices, mean {m:+.3f}, "
                            + (f"wave {w:+.3f}" if share == 1.0 else "wave not read (a row partly in the band)")
                            for j, share, m, w in got) or "  no snapshot in that range")
        if rms > ONE_EXPONENTIAL:
            print(f"not one exponential over the fit's range: the rms residual of ln A is {rms:.3g} "
                  f"(above {ONE_EXPONENTIAL:g}): the rate above is no growth rate")
        return 0
    except ColumnError as e:
        print(f"jet_column.py: {e}", file=sys.stderr)
        return 1
    finally:
        if a.out is None:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
