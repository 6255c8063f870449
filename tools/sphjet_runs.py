"""Reading run directories from Python (plot scripts): legacy SPHysics runs and sphjet runs.

A run directory is one of
  - a legacy SPHysics run: PART_nnnn (7e16.8: x z u w rho p m), IPART, EPART, INDAT (np, nb on
    lines 26-27), DT (the time of PART_k is data row k);
  - a sphjet run with legacy output: PART_nnnn, EPART, steps.txt ("# output step time"),
    run.log (its "particles N (boundary NB, fluid NF)" line gives nb);
  - a sphjet run with HDF5 output: snap_nnnnnn.h5 (needs h5py).
Fluid that left the domain (removed, or parked outside the extent of the boundary particles,
as legacy does) is flagged out, as in cpp_driver/io/legacy_output.hpp: mark_outside_container.

Only numpy is needed (h5py for HDF5 runs). Errors are RunError with a message naming the path.
"""
import os
import re

import numpy as np


class RunError(Exception):
    pass


def label_and_file(spec):
    """A command-line 'LABEL:FILE' (a curve's legend and the CSV behind it) -> (label, file);
    split at the first ':'. RunError naming the spec when it is malformed or the file missing."""
    label, sep, path = spec.partition(":")
    if not sep or not label or not path:
        raise RunError(f"{spec!r}: expected LABEL:CSV")
    if not os.path.isfile(path):
        raise RunError(f"{label}: {path}: no such file")
    return label, path


def _read_part(path):
    """PART file -> (n, 7) array. Fixed width 16, so '-0.1E-01-0.2E+00' still parses."""
    rows = []
    with open(path) as f:
        for ln, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line.strip():
                continue
            try:
                vals = [float(line[i:i + 16].replace("D", "E")) for i in range(0, 7 * 16, 16)]
            except ValueError:
                # 3-digit exponents are written without the E ("0.1+100"): fall back to split
                try:
                    vals = [float(v) for v in line.split()][:7]
                except ValueError:
                    raise RunError(f"{path}:{ln}: not 7 numbers of width 16: {line!r}")
            rows.append(vals)
    if not rows:
        raise RunError(f"{path}: empty particle file")
    return np.asarray(rows)


class Run:
    """The outputs of one run directory: .frames = [(number, time, path)], .nb."""

    def __init__(self, path, label=None):
        self.dir = path
        self.label = label or os.path.basename(os.path.normpath(path))
        if not os.path.isdir(path):
            raise RunError(f"{path}: run directory not found (expected PART_nnnn or snap_*.h5 files)")
        names = os.listdir(path)
        parts = sorted((int(m.group(1)), n) for n in names for m in [re.fullmatch(r"PART_(\d+)", n)] if m)
        snaps = sorted((int(m.group(1)), n) for n in names for m in [re.fullmatch(r"snap_(\d+)\.h5", n)] if m)
        self.frames = []
        if parts:
            self.kind = "part"
            self.nb = self._nb()
            times = self._times(len(parts))
            if "IPART" in names:
                self.frames.append((0, 0.0, os.path.join(path, "IPART")))
            for k, n in parts:
                self.frames.append((k, times.get(k), os.path.join(path, n)))
            if "EPART" in names:
                # legacy: the DT row after the last PART file; sphjet: the end time in run.log
                t_end = times.get(len(parts) + 1, self._end_time())
                self.frames.append((-1, t_end, os.path.join(path, "EPART")))
        elif snaps:
            self.kind = "hdf5"
            try:
                import h5py
            except ImportError:
                raise RunError(f"{path}: HDF5 run but h5py is missing (apt-get install -y python3-h5py)")
            for k, n in snaps:
                with h5py.File(os.path.join(path, n), "r") as f:
                    self.frames.append((k, float(f.attrs["time"]), os.path.join(path, n)))
            self.nb = None
        else:
            raise RunError(f"{path}: no PART_nnnn or snap_*.h5 files in the run directory")
        self.removed = self._legacy_removed()

    def _legacy_removed(self):
        """Legacy stdout.txt: output number -> ids (0-based) reported out of limits before it."""
        out = {}
        path = os.path.join(self.dir, "stdout.txt")
        if not os.path.isfile(path):
            return out
        removed, k = [], 0
        with open(path) as f:
            for line in f:
                if "In poute_2D" in line:
                    k += 1
                    out[k] = list(removed)
                else:
                    m = re.search(r"Particle out of limits:\s*(\d+)", line)
                    if m:
                        removed.append(int(m.group(1)) - 1)
        if out:
            out[-1] = out[max(out)]  # EPART: the last poute call
        return out

    def _nb(self):
        indat = os.path.join(self.dir, "INDAT")
        if os.path.isfile(indat):
            with open(indat) as f:
                lines = f.read().split("\n")
            return int(lines[26].split()[0])
        log = os.path.join(self.dir, "run.log")
        if os.path.isfile(log):
            with open(log) as f:
                m = re.search(r"particles \d+ \(boundary (\d+), fluid \d+\)", f.read())
            if m:
                return int(m.group(1))
        raise RunError(f"{self.dir}: boundary count unknown: neither INDAT (legacy) nor run.log (sphjet)")

    def _end_time(self):
        log = os.path.join(self.dir, "run.log")
        if os.path.isfile(log):
            with open(log) as f:
                m = re.findall(r"done: .* to t = ([-+0-9.eE]+) s", f.read())
            if m:
                return float(m[-1])
        return None

    def _times(self, n):
        steps = os.path.join(self.dir, "steps.txt")
        if os.path.isfile(steps):
            out = {}
            with open(steps) as f:
                for line in f:
                    if line.startswith("#") or not line.strip():
                        continue
                    k, _, t = line.split()[:3]
                    out[int(k)] = float(t)
            return out
        dt = os.path.join(self.dir, "DT")
        if os.path.isfile(dt):
            out = {}
            with open(dt) as f:
                rows = [l.split() for l in f if l.strip()]
            rows = [r for r in rows if re.match(r"^[-+0-9.]", r[0])]
            for k, r in enumerate(rows, 1):
                out[k] = float(r[0])
            return out
        raise RunError(f"{self.dir}: output times unknown: neither steps.txt (sphjet) nor DT (legacy)")

    def nearest(self, t, tol):
        best = None
        for k, tk, p in self.frames:
            if tk is None:
                continue
            if abs(tk - t) <= tol and (best is None or abs(tk - t) < abs(best[1] - t)):
                best = (k, tk, p)
        return best

    def load(self, frame):
        """-> dict of arrays x z u w rho p m, boundary (bool), active (bool)."""
        k, t, path = frame
        if self.kind == "part":
            a = _read_part(path)
            d = dict(zip("x z u w rho p m".split(), a.T))
            n = len(a)
            bnd = np.zeros(n, bool)
            bnd[: self.nb] = True
            active = np.ones(n, bool)
            for i in self.removed.get(k, []):
                if self.nb <= i < n:
                    active[i] = False
        else:
            import h5py
            with h5py.File(path, "r") as f:
                g = f["particles"]
                d = {c: g[c][()] for c in "x z u w rho p m".split()}
                bnd = g["kind"][()] != 2
                active = g["active"][()] != 0
        if bnd.any():
            bx, bz = d["x"][bnd], d["z"][bnd]
            inside = (d["x"] <= bx.max()) & (d["x"] >= bx.min()) & (d["z"] >= bz.min())
            active &= inside | bnd
        d["boundary"] = bnd
        d["active"] = active
        d["time"] = t
        return d
