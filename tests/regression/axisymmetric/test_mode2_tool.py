#!/usr/bin/env python3
"""tools/axisymmetric.py mode2 on synthetic snapshots (no sphjet): a drop of rings whose
shape is the spheroid z -> (1 + e) z, r -> r / sqrt(1 + e) (volume kept) with
e(t) = A exp(-gamma t) cos(omega t), omega = 31.6 rad/s (the case's 8 sigma/(rho R^3) with
sigma = 1, rho = 1000, R = 0.02 m), gamma = 3 1/s, A = 0.02, snapshots every 5 ms to 0.6 s.
From 0.40 s on one particle stands 1.5 R from the centre (a particle thrown out at a pole).

Known by construction: the window ends at the first snapshot with that particle
(intact_until = 0.40), the fit returns omega and gamma of e(t) (the deformation measure is
e's image under a smooth map, odd to first order: its harmonics do not move the frequency;
tolerances 0.5% on omega, 5% on gamma, measured well within), and the zero crossings' period
is within 2% of 2 pi / omega (the window ends at a partial period, which moves the mean).

usage: test_mode2_tool.py   (exit 0 on success, 1 with a message on failure)
"""
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
TOOL = os.path.join(REPO, "tools", "axisymmetric.py")
PY = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable

OMEGA, GAMMA, AMP, R = math.sqrt(8.0 / (1000.0 * 0.02 ** 3)), 3.0, 0.02, 0.02
T_OUT = 0.40


def write_snapshots(d):
    import h5py
    import numpy as np
    dx = R / 10.0
    g = (np.arange(-12, 13) + 0.5) * dx
    x, z = np.meshgrid(g[g > 0], g, indexing="ij")
    inside = x ** 2 + z ** 2 < R ** 2
    x0, z0 = x[inside], z[inside]
    m = 2.0 * math.pi * x0 * dx * dx * 1000.0   # ring masses at rho = 1000
    for k, t in enumerate(np.arange(0.0, 0.6 + 1e-9, 0.005)):
        e = AMP * math.exp(-GAMMA * t) * math.cos(OMEGA * t)
        xs, zs = x0 / math.sqrt(1.0 + e), 0.05 + z0 * (1.0 + e)
        if t >= T_OUT - 1e-9:   # a particle out at the top pole
            zs = zs.copy()
            zs[np.argmax(zs)] = 0.05 + 1.5 * R
        with h5py.File(os.path.join(d, f"snap_{k:06d}.h5"), "w") as h:
            h.attrs["time"] = float(t)
            p = h.create_group("particles")
            p["x"], p["z"], p["m"] = xs, zs, m
            p["rho"] = np.full_like(m, 1000.0)
            p["u"] = p["w"] = p["p"] = np.zeros_like(m)


def main():
    if os.path.realpath(sys.executable) != os.path.realpath(PY):   # h5py and numpy are Debian's
        os.execv(PY, [PY, os.path.abspath(__file__)])
    failures = []
    with tempfile.TemporaryDirectory() as d:
        write_snapshots(d)
        r = subprocess.run([PY, TOOL, "mode2", d, "--sigma", "1", "--rho", "1000", "--nu", "1e-4"],
                           capture_output=True, text=True)
        line = [s for s in r.stdout.splitlines() if s.startswith("SUMMARY")]
        if r.returncode != 0 or not line:
            sys.exit(f"FAIL: the tool exited {r.returncode}: {r.stdout}{r.stderr}")
        print(line[0])
        v = dict(kv.split("=") for kv in line[0].split()[1:])
    checks = [
        ("intact_until", float(v["intact_until"]), T_OUT, 1e-9),
        ("intact", float(v["intact"]), 0.0, 0.0),
        ("omega_fit", float(v["omega_fit"]), OMEGA, 0.005 * OMEGA),
        ("gamma_fit", float(v["gamma_fit"]), GAMMA, 0.05 * GAMMA),
        ("period", float(v["period"]), 2.0 * math.pi / OMEGA, 0.02 * 2.0 * math.pi / OMEGA),
    ]
    for name, got, want, tol in checks:
        ok = abs(got - want) <= tol
        print(f"{'ok  ' if ok else 'FAIL'} {name} = {got:.6g} (expected {want:.6g} +- {tol:.3g})")
        if not ok:
            failures.append(name)
    if failures:
        sys.exit(f"FAIL: {', '.join(failures)}")
    print("PASS")


if __name__ == "__main__":
    main()
