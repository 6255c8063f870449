#!/usr/bin/env python3
"""Where a jet run's particles left the box, from its run.log, case.toml, jet.csv and snapshots.

    /usr/bin/python3 tools/left_the_box.py RUN [--from T] [--to T1]

sphjet removes a particle that leaves the domain and logs its time and id in run.log (a part
made again from an earlier checkpoint logs an id again; its last time is kept). For each one
that left from T to T1 (default: the whole run), found in the last snapshot before it left:
- its place when it left, estimated from that snapshot's position moved on at its velocity over
  the time between (a snapshot every few ms: within about a d0 at the round jets' speeds);
- below_end: its distance from the orifice along the jet (nozzle.axis "down" or "up") less the
  jet's length (jet.csv's last sample at or before the time it left: the breakup length, or the
  intact jet's tip), in d0: negative beside the intact jet, positive among its drops;
- radius: its distance from the jet's axis (x - nozzle.x0), in d0;
- mass: the found particles' mass over the fluid issued by the last of them, rho pi (d0/2)^2
  (u0 t + nozzle.column_over_d0 d0) for a round jet (domain.geometry = "axisymmetric": a
  particle's mass is its ring's).
Prints `key = value` lines and, last, `SUMMARY key=value ...`. Needs h5py (snap_*.h5).
"""
import argparse
import bisect
import math
import os
import statistics
import sys
import tomllib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from jet_noise import read_case  # noqa: E402  (tools/, beside this script)
from study_runs import is_broken, parse_log, read_csv  # noqa: E402


class LeftError(Exception):
    """A run that cannot be read (the message names the file)."""


def read_run(run):
    """-> (jet_noise.read_case's dict; jet.csv (times, lengths in d0); left_at {id: t})."""
    path = os.path.join(run, "case.toml")
    try:
        info = read_case(run)
    except (OSError, tomllib.TOMLDecodeError, KeyError, TypeError, ValueError) as e:
        raise LeftError(f"{path}: expected a sphjet case with a [nozzle] (d0, u0) and [fluid], found {e!r}")
    if info["axis"] not in ("down", "up"):
        raise LeftError(f"{path}: nozzle.axis: expected \"down\" or \"up\", found {info['axis']!r}")
    path = os.path.join(run, "jet.csv")
    try:
        rows = read_csv(path)
        times = [float(r["time"]) for r in rows]
        lengths = [float(r["L_over_d0"] if is_broken(r) else r["jet_tip_over_d0"]) for r in rows]
    except (OSError, KeyError, ValueError) as e:
        raise LeftError(f"{path}: expected the breakup record with time, broken, L_over_d0 and "
                        f"jet_tip_over_d0, found {e!r}")
    return info, (times, lengths), parse_log(run)["left_at"]


def where_they_left(run, t0=0.0, t1=math.inf):
    """-> dict logged (ids that left from t0 to t1), found, below_end and radius (lists, d0),
    mass_fraction (None for a planar jet or none found), t_first, t_last."""
    try:
        import h5py
    except ImportError:
        raise LeftError("reading snap_*.h5 needs h5py (apt-get install -y python3-h5py)")
    info, (times, lengths), left_at = read_run(run)
    gone = {i: t for i, t in left_at.items() if t0 <= t <= t1}

    def particles(name, fields=("id", "active", "x", "z", "u", "w", "m")):
        path = os.path.join(run, name)
        try:
            with h5py.File(path, "r") as f:
                g = f["particles"]
                return float(f.attrs["time"]), {c: g[c][:] for c in fields}
        except (OSError, KeyError, ValueError) as e:
            raise LeftError(f"{path}: expected a sphjet snapshot (time; particles id, active, x, z, u, w, "
                            f"m), found {e!r}")

    snaps = sorted((particles(n, ())[0], n) for n in os.listdir(run) if n.startswith("snap_") and n.endswith(".h5"))
    snap_times = [s[0] for s in snaps]
    # the last snapshot before it left: run.log's times have 6 digits, so one written at the step
    # it left (where it is already inactive) may read as a little earlier
    wanted = {}   # snapshot name -> {id: time it left}
    for i, t in gone.items():
        k = bisect.bisect_left(snap_times, t * (1.0 - 1e-5)) - 1
        if k >= 0:
            wanted.setdefault(snaps[k][1], {})[i] = t
    d0, sign = info["d0"], (1.0 if info["axis"] == "down" else -1.0)
    below, radius, mass = [], [], 0.0
    for name, ids in wanted.items():
        t_snap, g = particles(name)
        for k, p in enumerate(g["id"]):
            t = ids.get(int(p))
            j = bisect.bisect_right(times, t) - 1 if t is not None else -1
            if j < 0 or g["active"][k] != 1:
                continue
            zl = g["z"][k] + g["w"][k] * (t - t_snap)
            xl = g["x"][k] + g["u"][k] * (t - t_snap)
            below.append(sign * (info["z0"] - zl) / d0 - lengths[j])
            radius.append(abs(xl - info["x0"]) / d0)
            mass += float(g["m"][k])
    t_last = max(gone.values()) if gone else None
    issued = (info["rho"] * math.pi * (d0 / 2) ** 2 * (info["u0"] * t_last + info["column"] * d0)
              if gone else 0.0)
    return {"logged": len(gone), "found": len(below), "below_end": below, "radius": radius,
            "mass_fraction": mass / issued if info["round"] and below and issued > 0 else None,
            "t_first": min(gone.values()) if gone else None, "t_last": t_last}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("run", help="run directory (run.log, case.toml, jet.csv, snap_*.h5)")
    ap.add_argument("--from", dest="t0", type=float, default=0.0, metavar="T", help="from t = T [s]")
    ap.add_argument("--to", dest="t1", type=float, default=math.inf, metavar="T1", help="to t = T1 [s]")
    args = ap.parse_args(argv)
    try:
        got = where_they_left(args.run, args.t0, args.t1)
    except LeftError as e:
        print(f"left_the_box: {e}", file=sys.stderr)
        return 1
    print(f"logged = {got['logged']} particle(s) left the box from t = {args.t0:g} s"
          + ("" if math.isinf(args.t1) else f" to {args.t1:g} s"))
    if got["logged"]:
        print(f"times = {got['t_first']:.6g} to {got['t_last']:.6g} s")
    print(f"found = {got['found']} in a snapshot before they left")
    summary = {"logged": got["logged"], "found": got["found"]}
    if got["found"]:
        b, r = got["below_end"], got["radius"]
        print(f"below_end = {min(b):.1f} to {max(b):.1f} d0, median {statistics.median(b):.1f} "
              f"(distance below the orifice less the jet's length)")
        print(f"radius = {statistics.median(r):.2f} d0 (median)")
        summary.update(below_end_min=f"{min(b):.3g}", below_end_median=f"{statistics.median(b):.3g}",
                       below_end_max=f"{max(b):.3g}", radius_median=f"{statistics.median(r):.3g}")
    if got["mass_fraction"] is not None:
        print(f"mass = {got['mass_fraction']:.3g} of what the orifice issued by t = {got['t_last']:.6g} s")
        summary["mass_fraction"] = f"{got['mass_fraction']:.3g}"
    print("SUMMARY " + " ".join(f"{k}={v}" for k, v in summary.items()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
