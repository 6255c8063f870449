#!/usr/bin/env python3
"""tools/axisymmetric.py roughness on synthetic snapshots (no sphjet): a periodic column of
rings on the square lattice (rows at r = (i + 1/2) dx, i = 0..9, a = 10 dx, period 80 dx,
snapshots every 1 ms to 44 ms).

Every particle is moved radially by r -> r (1 + e(t) cos kz), k = 2 pi / period (the n = 1 mode,
e = 1e-6 exp(200 t): the surface's n = 1 amplitude, 0.95 e, passes 1e-3 a at 34.8 ms), and the
particles of every row but the outermost also by B exp(q t) (none at t = 0) times a fixed random
pattern in r and z, from which each row's n = 0 and n = 1 parts along z are taken out and whose
rms over those particles is dx (B = 1e-5, q = 80 1/s). From 35 ms on the pattern's amplitude is
ten times larger (what the n = 1 mode's harmonics do to a real column past 1e-3 a). The
outermost row alone carries an n = 3 mode, 1e-7 exp(30 t), 100 times larger from 35 ms on.

Known by construction: the n = 1 mode's growth is 200 1/s, over the whole run and from 1e-4 a
(its settled fit, 24-34 ms); the interior's rms is B exp(q t) dx
until 35 ms, so interior_start_over_dx = B exp(q 1 ms), the growth fitted while the n = 1 mode
is below 1e-3 a is q, and that fit ends at 34 ms, the last snapshot before 34.8 ms; the last
value is 10 B exp(q 44 ms); the rest of r_s's modes, fitted while n = 1 is below 1e-3 a, grows
at 30 1/s. Tolerances: 5e-4 relative on the interior's values and rate (exact by construction;
the summary prints four digits); 1% on the n = 1 and n = 3 rates (their Fourier amplitudes are e
and e3 times the outermost row's radius to first order).

usage: test_roughness_tool.py   (exit 0 on success, 1 with a message on failure)
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

DX, NROW, NZ = 1e-4, 10, 80
PERIOD = NZ * DX
S1, E0 = 200.0, 1e-6          # the n = 1 mode: e(t) = E0 exp(S1 t)
B, Q, T_JUMP = 1e-5, 80.0, 0.035
E3, S3 = 1e-7, 30.0           # the outermost row's n = 3 mode
TIMES = [k * 1e-3 for k in range(45)]


def interior(t):
    """The interior's displacement from the first snapshot (none at t = 0), rms in dx."""
    if t <= 0.0:
        return 0.0
    return B * math.exp(Q * t) * (10.0 if t >= T_JUMP - 1e-12 else 1.0)


def short(t):
    """The outermost row's n = 3 mode (capillary-stable): E3 exp(S3 t), 100 times larger from
    35 ms on (the n = 1 mode's harmonics past 1e-3 a)."""
    return E3 * math.exp(S3 * t) * (100.0 if t >= T_JUMP - 1e-12 else 1.0)


def write_snapshots(d):
    import h5py
    import numpy as np
    r0 = np.repeat((np.arange(NROW) + 0.5) * DX, NZ)
    z0 = np.tile((np.arange(NZ) + 0.5) * DX, NROW)
    ids = np.arange(len(r0))
    k = 2.0 * math.pi / PERIOD
    rng = np.random.default_rng(7)
    pr, pz = rng.standard_normal(len(r0)), rng.standard_normal(len(r0))
    inner = r0 < (NROW - 1) * DX
    outer = (~inner).astype(float)
    for i in range(NROW - 1):   # each interior row's n = 0 and 1 parts taken out
        m = np.flatnonzero(np.isclose(r0, (i + 0.5) * DX))
        b = np.stack([np.ones(len(m)), np.cos(k * z0[m]), np.sin(k * z0[m])], 1)
        for p in (pr, pz):
            p[m] -= b @ np.linalg.lstsq(b, p[m], rcond=None)[0]
    pr[~inner] = pz[~inner] = 0.0
    norm = math.sqrt(float(np.sum(pr ** 2 + pz ** 2)) / int(inner.sum()))
    pr, pz = pr / norm * DX, pz / norm * DX
    m = 2.0 * math.pi * r0 * DX * DX * 1000.0
    order = rng.permutation(len(r0))   # the snapshots' order is not the ids'
    for n, t in enumerate(TIMES):
        e = E0 * math.exp(S1 * t)
        x = r0 * (1.0 + e * np.cos(k * z0) + outer * short(t) * np.cos(3.0 * k * z0)) + interior(t) * pr
        z = np.mod(z0 + interior(t) * pz, PERIOD)
        with h5py.File(os.path.join(d, f"snap_{n:06d}.h5"), "w") as h:
            h.attrs["time"] = float(t)
            g = h.create_group("particles")
            g["x"], g["z"], g["id"], g["m"] = x[order], z[order], ids[order], m[order]
            g["rho"] = np.full(len(r0), 1000.0)
            g["u"] = g["w"] = g["p"] = np.zeros(len(r0))


def main():
    with_h5py()   # numpy and h5py: Debian's interpreter, which then runs the tool too
    with tempfile.TemporaryDirectory() as d:
        write_snapshots(d)
        v = summary_of([sys.executable, TOOL, "roughness", d, "--radius", str(NROW * DX), "--period",
                        str(PERIOD), "--dx", str(DX)])
    t_lin = 0.034   # the n = 1 amplitude, 0.95 e (the outermost row at 9.5 dx), passes 1e-3 at 34.8 ms
    checks = [
        ("mode1_growth", v["mode1_growth"], S1, 0.01 * S1),
        ("mode1_settled_growth", v["mode1_settled_growth"], S1, 0.01 * S1),
        ("rest_linear_growth", v["rest_linear_growth"], S3, 0.01 * S3),
        ("interior_start_over_dx", v["interior_start_over_dx"], interior(1e-3), 5e-4 * interior(1e-3)),
        ("interior_end_over_dx", v["interior_end_over_dx"], interior(TIMES[-1]), 5e-4 * interior(TIMES[-1])),
        ("interior_growth", v["interior_growth"], Q, 5e-4 * Q),
        ("interior_fit_to", v["interior_fit_to"], t_lin, 1e-9),
    ]
    known_answers(checks)


if __name__ == "__main__":
    main()
