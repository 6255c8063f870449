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
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
TOOL = os.path.join(REPO, "tools", "axisymmetric.py")
sys.path.insert(0, os.path.dirname(HERE))
from summary_checks import known_answers, summary_of, with_h5py  # noqa: E402  (tests/regression/)

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
    with_h5py()   # numpy and h5py: Debian's interpreter, which then runs the tool too
    with tempfile.TemporaryDirectory() as d:
        write_snapshots(d)
        v = summary_of([sys.executable, TOOL, "mode2", d, "--sigma", "1", "--rho", "1000", "--nu", "1e-4"])
    checks = [
        ("intact_until", v["intact_until"], T_OUT, 1e-9),
        ("intact", v["intact"], 0.0, 0.0),
        ("omega_fit", v["omega_fit"], OMEGA, 0.005 * OMEGA),
        ("gamma_fit", v["gamma_fit"], GAMMA, 0.05 * GAMMA),
        ("period", v["period"], 2.0 * math.pi / OMEGA, 0.02 * 2.0 * math.pi / OMEGA),
    ]
    known_answers(checks)


if __name__ == "__main__":
    main()
