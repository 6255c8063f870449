#!/usr/bin/env python3
"""The rings pair's density of a ring lattice stretched along its axis: what a round jet's
lattice does to its own pressure as it stretches.

    /usr/bin/python3 tools/ring_lattice_sums.py [--h-over-dx 2] [--stretch 1.05 1.1 1.27] [--c0 12]

The lattice is the nozzle's (geometry/nozzle.cpp): rings at r = (j + 1/2) dx, one every dx along
the axis, each of the mass of its ring, 2 pi r rho0 dx^2 (the first column's counted at 11/12 in
the sums, as the rings pair does: loops/axisymmetric_loops.f90). Stretched by lam it keeps every
ring's mass and its volume: the rings sit lam dx apart along the axis and at r/sqrt(lam), as in a
jet that speeds up by lam (a falling jet). Each ring's density is the rings pair's,
rho_a = sum_b m_b Wr_ab, the 3D Wendland kernel of support 2h averaged over the azimuth of ring b
(numerically, 1440 points), over ROWS rows and every ring within reach along the axis; the rows
printed (the first SHOW, from the axis out) are far enough inside the outermost that no kernel
reaches past it (ROWS - SHOW >= 2 h/dx), so the numbers are the lattice's alone, with no surface.

In the continuum a stretch that keeps the volume keeps the density; on a lattice at h = 2 dx the
sums move. Printed per row: rho - rho0 of the lattice (lam = 1), then for each lam the change of
that density and the pressure change it makes through the equation of state, c0^2 drho (the Tait
slope at rho0), in Pa and in units of sigma/a (--sigma, --d0: the study's water jet). Prints
`SUMMARY` with the axis row's and the next row's pressure change at the largest lam, in sigma/a.
"""
import argparse
import math
import sys

import numpy as np

PHI_POINTS = 1440


def wendland3(q, h):
    """The 3D Wendland C2 kernel of support 2h at q = distance / h."""
    return np.where(q < 2.0, 21.0 / (16.0 * math.pi * h ** 3) * (1.0 - 0.5 * q) ** 4 * (2.0 * q + 1.0), 0.0)


def row_densities(lam, h_over_dx, rows, show, rho0=1000.0):
    """rho of a ring in each of the first `show` rows of the lattice stretched by lam (dx = 1)."""
    h = h_over_dx
    phi = (np.arange(PHI_POINTS) + 0.5) * 2.0 * math.pi / PHI_POINTS
    cos = np.cos(phi)
    r = (np.arange(rows) + 0.5) / math.sqrt(lam)
    m = 2.0 * math.pi * (np.arange(rows) + 0.5) * rho0
    m[0] *= 11.0 / 12.0
    dz = lam
    reach = int(math.ceil(2.0 * h / dz)) + 1
    out = []
    for a in range(show):
        total = 0.0
        for b in range(rows):
            ring2 = r[a] ** 2 + r[b] ** 2 - 2.0 * r[a] * r[b] * cos
            for k in range(-reach, reach + 1):
                total += m[b] * wendland3(np.sqrt(ring2 + (k * dz) ** 2) / h, h).mean()
        out.append(total)
    return np.array(out)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--h-over-dx", type=float, default=2.0, help="h / dx (default 2, the round jets')")
    ap.add_argument("--stretch", type=float, nargs="+", default=[1.05, 1.1, 1.27], metavar="LAM",
                    help="stretches along the axis (default 1.05 1.1 1.27)")
    ap.add_argument("--rows", type=int, default=16, help="rows in the lattice (default 16)")
    ap.add_argument("--show", type=int, default=6, help="rows printed, from the axis out (default 6)")
    ap.add_argument("--c0", type=float, default=12.0, help="sound speed [m/s] (default 12, the quiet study's)")
    ap.add_argument("--sigma", type=float, default=0.072, help="surface tension [N/m] (default 0.072)")
    ap.add_argument("--d0", type=float, default=0.001194, help="jet diameter [m] (default 0.001194)")
    args = ap.parse_args(argv)
    if not args.h_over_dx > 0:
        ap.error(f"--h-over-dx must be > 0, got {args.h_over_dx:g}")
    if any(not lam > 0 for lam in args.stretch):
        ap.error(f"--stretch values must be > 0, got {' '.join(f'{v:g}' for v in args.stretch)}")
    if not 1 <= args.show <= args.rows - 2.0 * args.h_over_dx:
        ap.error(f"--show {args.show} needs 1 <= SHOW <= ROWS - 2 h/dx = {args.rows - 2.0 * args.h_over_dx:g} "
                 "(the printed rows clear of the outermost by the kernel's reach)")
    rho0 = 1000.0
    p_unit = args.sigma / (0.5 * args.d0)
    base = row_densities(1.0, args.h_over_dx, args.rows, args.show, rho0)
    print(f"h = {args.h_over_dx:g} dx, {args.rows} rows, c0 = {args.c0:g} m/s, sigma/a = {p_unit:.4g} Pa")
    print("lattice: rho - rho0 [kg/m^3] by row from the axis: " + " ".join(f"{v - rho0:.4f}" for v in base))
    dp_last = None
    for lam in args.stretch:
        d = row_densities(lam, args.h_over_dx, args.rows, args.show, rho0) - base
        dp_last = d * args.c0 ** 2
        print(f"stretch {lam:g}: drho [kg/m^3] " + " ".join(f"{v:.4f}" for v in d)
              + " | c0^2 drho [Pa] " + " ".join(f"{v:.1f}" for v in dp_last)
              + " | / (sigma/a) " + " ".join(f"{v / p_unit:.3f}" for v in dp_last))
    print(f"SUMMARY h_over_dx={args.h_over_dx:g} stretch={args.stretch[-1]:g} "
          f"dp_row0_over_sigma_a={dp_last[0] / p_unit:.6g} dp_row1_over_sigma_a={dp_last[1] / p_unit:.6g}"
          if args.show > 1 else f"SUMMARY dp_row0_over_sigma_a={dp_last[0] / p_unit:.6g}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
