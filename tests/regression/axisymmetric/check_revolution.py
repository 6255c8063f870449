#!/usr/bin/env python3
"""The revolved copies of an axisymmetric run ([output] revolution_sectors; the layout is in
cpp_driver/io/hdf5_output.hpp, the key in cases/CASE_FORMAT.md).

Runs the sphere at rest (cases/axisymmetric/sphere_laplace.toml at R/dx = 10: 158 rings) for
30 steps with an output every few steps, with N = 12 sectors and without, and a third time
stopped after 15 steps and resumed. Checks, each with its reason:
  1. Every snapshot holds N x (particles) revolved points, and the index's "revolved"
     collection says so.
  2. Every revolved point lies on its ring: sqrt(X^2 + Y^2) = r and Z = z of its source
     particle to 1e-12 relative (the writer rounds r cos phi and r sin phi once each: 1e-16),
     at the angle 2 pi k / N of its copy k (to 1e-12 rad), and its velocity is the ring's,
     turned: (u cos phi, u sin phi) and w.
  3. The copies carry m / N: the revolved masses sum to the rings' mass to 1e-12 relative
     (a sum of N n rounded terms), and the repeated scalars equal their source bit for bit.
  4. The XDMF index parses (xml.etree) and every DataItem names a file of the run and a
     dataset in it with the dimensions it states, and NumberOfElements points; "particles"
     and "revolved" list the same times.
  5. Without the key: no /revolved group, one collection, and that collection, the (r, z)
     arrays and the /xdmf views equal those of the run with the key (the key adds, it
     changes nothing).
  6. A run stopped at step 15 and resumed (`--resume`) ends with the same index as the
     uninterrupted one: the same collections, grids, times and references, each grid's
     attributes compared as a set (a resumed writer lists the extra fields of the snapshots it
     kept in name order, a fresh one in the order the solver gives them: colour, normal_x,
     normal_z, curvature; so it was before revolution_sectors), and the same revolved
     points, bit for bit.
  7. The key is refused, exit status 1 naming the file, the key, what was expected and what
     was found, in a planar case and out of range.
Needs numpy and h5py: re-runs itself with /usr/bin/python3 (Debian's, which has them) when the
interpreter that started it lacks them.

usage: check_revolution.py SPHJET SOURCE_DIR WORK_DIR
"""
import math
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from summary_checks import with_h5py  # noqa: E402  (tests/regression/)

N = 12
SETS = ["--set", "resolution.dx=0.002", "--set", "time.out=0.0002"]
STEPS = 30


def main():
    with_h5py()
    import h5py
    import numpy as np

    sphjet, src, work = sys.argv[1:4]
    case = os.path.join(src, "cases", "axisymmetric", "sphere_laplace.toml")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    results = []

    def check(ok, what):
        print(f"{'PASS' if ok else 'FAIL'} {what}", flush=True)
        results.append(bool(ok))

    def run(out, *extra):
        cmd = [sphjet, "run", case, "--out", out, "-q", "-j", "1"] + SETS + list(extra)
        print("$ " + " ".join(cmd), flush=True)
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            print(r.stdout[-2000:], r.stderr[-2000:])
        return r

    on, off, resumed = (os.path.join(work, d) for d in ("on", "off", "resumed"))
    key = ["--set", f"output.revolution_sectors={N}"]
    if run(on, "--max-steps", str(STEPS), *key).returncode != 0 or \
            run(off, "--max-steps", str(STEPS)).returncode != 0:
        print("0 passed, 1 failed")
        return 1

    # 4. the index: well-formed, every reference resolves with the stated dimensions
    def index(run_dir):
        root = ET.parse(os.path.join(run_dir, "sphjet.xmf")).getroot()
        cols = {c.get("Name"): c for c in root.find("Domain").findall("Grid")}
        bad = []
        for c in cols.values():
            for g in c.findall("Grid"):
                n = int(g.find("Topology").get("NumberOfElements"))
                for item in g.iter("DataItem"):
                    fname, _, path = item.text.strip().partition(":")
                    dims = tuple(int(d) for d in item.get("Dimensions").split())
                    with h5py.File(os.path.join(run_dir, fname), "r") as f:
                        if path not in f or f[path].shape != dims or dims[0] != n:
                            bad.append(f"{fname}:{path} {dims}")
        return cols, bad

    cols, bad = index(on)
    check(not bad, f"every DataItem of the index resolves to a dataset of its dimensions "
                   f"({len(bad)} do not: {bad[:3]})")
    check(sorted(cols) == ["particles", "revolved"], f"collections {sorted(cols)}")
    times = {name: [g.find("Time").get("Value") for g in c.findall("Grid")]
             for name, c in cols.items()}
    check(len(times["particles"]) >= 5 and times["particles"] == times.get("revolved"),
          f"{len(times['particles'])} snapshots, the same times in both collections")

    # 1-3. every snapshot
    worst_r = worst_phi = worst_v = worst_m = 0.0
    counts_ok = repeats_ok = True
    for g in cols["revolved"].findall("Grid"):
        fname = g.find("Topology").find("DataItem").text.strip().partition(":")[0]
        with h5py.File(os.path.join(on, fname), "r") as f:
            p, rv = f["particles"], f["revolved"]
            n = p["x"].shape[0]
            sectors = int(rv.attrs["sectors"])
            pts, vel = rv["points"][:], rv["velocity"][:]
            counts_ok &= (sectors == N and pts.shape == (N * n, 3) and
                          int(g.find("Topology").get("NumberOfElements")) == N * n)
            r, z = np.tile(p["x"][:], N), np.tile(p["z"][:], N)
            u, w = np.tile(p["u"][:], N), np.tile(p["w"][:], N)
            rho = np.hypot(pts[:, 0], pts[:, 1])
            worst_r = max(worst_r, float(np.max(np.abs(rho - np.abs(r)) / np.maximum(np.abs(r), 1e-300))),
                          float(np.max(np.abs(pts[:, 2] - z) / np.maximum(np.abs(z), 1e-300))))
            phi = np.repeat(2 * math.pi * np.arange(N) / N, n)
            on_axis = r == 0
            dphi = np.angle(np.exp(1j * (np.arctan2(pts[:, 1], pts[:, 0]) - phi)))
            worst_phi = max(worst_phi, float(np.max(np.abs(dphi[~on_axis]))))
            scale = max(float(np.max(np.abs(u))), float(np.max(np.abs(w))), 1e-300)
            worst_v = max(worst_v, float(np.max(np.abs(vel[:, 0] - u * np.cos(phi)))) / scale,
                          float(np.max(np.abs(vel[:, 1] - u * np.sin(phi)))) / scale,
                          float(np.max(np.abs(vel[:, 2] - w))) / scale)
            m_rings, m_copies = float(np.sum(p["m"][:])), float(np.sum(rv["m"][:]))
            worst_m = max(worst_m, abs(m_copies - m_rings) / m_rings)
            for name in ("x", "z", "u", "w", "rho", "p", "id", "kind", "active", "colour",
                         "normal_x", "normal_z", "curvature"):
                repeats_ok &= bool(np.array_equal(rv[name][:], np.tile(p[name][:], N)))
    check(counts_ok, f"every snapshot: {N} x n revolved points")
    check(worst_r <= 1e-12, f"sqrt(X^2 + Y^2) = r and Z = z: worst relative difference {worst_r:.2e} (<= 1e-12)")
    check(worst_phi <= 1e-12, f"copy k at phi = 2 pi k / N: worst {worst_phi:.2e} rad (<= 1e-12)")
    check(worst_v <= 1e-12, f"velocity (u cos phi, u sin phi, w): worst {worst_v:.2e} of max |v| (<= 1e-12)")
    check(worst_m <= 1e-12, f"revolved mass sum = ring mass sum: worst relative {worst_m:.2e} (<= 1e-12)")
    check(repeats_ok, "repeated scalars equal their (r, z) source bit for bit")

    # 5. without the key: nothing revolved, and nothing else changed
    cols_off, bad_off = index(off)
    check(not bad_off and sorted(cols_off) == ["particles"], "without the key: one collection, resolving")
    text_on = open(os.path.join(on, "sphjet.xmf")).read()
    text_off = open(os.path.join(off, "sphjet.xmf")).read()
    cut = text_on.find('    <Grid Name="revolved"')
    check(cut > 0 and text_on[:cut] + "  </Domain>\n</Xdmf>\n" == text_off,
          "the index without the key is the index with it less the revolved collection")
    same = True
    snaps = sorted(s for s in os.listdir(off) if s.startswith("snap_"))
    for s in snaps:
        with h5py.File(os.path.join(on, s), "r") as a, h5py.File(os.path.join(off, s), "r") as b:
            same &= "revolved" not in b and sorted(a["particles"]) == sorted(b["particles"])
            for grp in ("particles", "xdmf"):
                for name in b[grp]:
                    same &= bool(np.array_equal(a[grp][name][:], b[grp][name][:]))
    check(same and snaps == sorted(s for s in os.listdir(on) if s.startswith("snap_")),
          f"/particles and /xdmf of all {len(snaps)} snapshots equal with and without the key")

    # 6. stopped and resumed
    half = STEPS // 2
    r1 = run(resumed, "--max-steps", str(half), *key)
    cmd = [sphjet, "run", "--resume", resumed, "-q", "-j", "1", "--max-steps", str(STEPS - half)]
    print("$ " + " ".join(cmd), flush=True)
    r2 = subprocess.run(cmd, capture_output=True, text=True)
    if r2.returncode != 0:
        print(r2.stdout[-2000:], r2.stderr[-2000:])
    def canonical(run_dir):
        root = ET.parse(os.path.join(run_dir, "sphjet.xmf")).getroot()
        out = []
        for c in root.find("Domain").findall("Grid"):
            for g in c.findall("Grid"):
                attrs = sorted((a.get("Name"), a.get("AttributeType"), a.find("DataItem").get("Dimensions"),
                                a.find("DataItem").text) for a in g.findall("Attribute"))
                out.append((c.get("Name"), g.get("Name"), g.find("Time").get("Value"),
                            ET.tostring(g.find("Topology")), ET.tostring(g.find("Geometry")), attrs))
        return out

    same_index = r1.returncode == 0 and r2.returncode == 0 and canonical(resumed) == canonical(on)
    check(same_index, "a stopped and resumed run has the uninterrupted run's index")
    last = snaps[-1]
    with h5py.File(os.path.join(on, last), "r") as a, h5py.File(os.path.join(resumed, last), "r") as b:
        check(np.array_equal(a["revolved/points"][:], b["revolved/points"][:]),
              f"and the same revolved points in {last}, bit for bit")

    # 7. bad input
    planar = os.path.join(src, "cases", "quickstart", "dambreak.toml")
    for case_file, value, parts in [
            (planar, "8", ["dambreak.toml", "output.revolution_sectors", "axisymmetric", "expected", "found 8"]),
            (case, "-3", ["sphere_laplace.toml", "output.revolution_sectors", "out of range",
                          "expected an integer in [0, 360]", "found -3"]),
            (case, "1000", ["output.revolution_sectors", "out of range", "found 1000"])]:
        out = os.path.join(work, "refused")
        r = subprocess.run([sphjet, "run", case_file, "--out", out, "-q",
                            "--set", f"output.revolution_sectors={value}"], capture_output=True, text=True)
        msg = r.stderr.strip()
        check(r.returncode == 1 and all(s in msg for s in parts) and not os.path.exists(out),
              f"revolution_sectors = {value} in {os.path.basename(case_file)}: exit {r.returncode}, {msg[:160]}")

    good = sum(results)
    print(f"{good} passed, {len(results) - good} failed")
    return 0 if good == len(results) else 1


if __name__ == "__main__":
    sys.exit(main())
