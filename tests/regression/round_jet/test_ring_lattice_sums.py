#!/usr/bin/env python3
"""tools/ring_lattice_sums.py: the rings pair's density of the nozzle's ring lattice, unstretched and
stretched along the axis.

- Unstretched at h = 2 dx, the rows clear of the axis (rows 3-5 of 16) must sum to rho0 within
  1e-3 rho0: the midpoint quadrature of a smooth kernel on a lattice at h = 2 dx is good to a few
  1e-4 there, and a wrong kernel normalisation or ring mass would be off by whole per cent.
- A stretch that keeps the volume keeps the continuum's density, so the lattice's change must
  fall as the kernel covers more rings: at lam = 1.27 each of rows 3-5 must change by less than
  a fifth at h = 4 dx of what it changes at h = 2 dx (its quadrature error falls faster than h^-2).
- --show beyond ROWS - 2 h/dx (printed rows a kernel's reach from the outermost) is refused.

usage: test_ring_lattice_sums.py   (exit 0 on success, 1 with a message on failure)
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
TOOL = os.path.join(REPO, "tools", "ring_lattice_sums.py")
PY = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable


def rows_of(out, prefix):
    line = next(l for l in out.splitlines() if l.startswith(prefix))
    return [float(v) for v in line.split(":", 1)[1].split("|")[0].split()[-6:]]


def run(*args):
    out = subprocess.run([PY, TOOL, *args], capture_output=True, text=True)
    print(out.stdout + out.stderr)
    return out


def main():
    failures = []
    got = {}
    for h in ("2", "4"):
        out = run("--h-over-dx", h, "--stretch", "1.27")
        if out.returncode != 0:
            print(f"FAIL: ring_lattice_sums.py --h-over-dx {h} exited {out.returncode}")
            return 1
        got[h] = (rows_of(out.stdout, "lattice"), rows_of(out.stdout, "stretch 1.27"))
    base = got["2"][0]
    if not all(abs(v) < 1.0 for v in base[3:6]):
        failures.append(f"unstretched rows 3-5 at h = 2 dx: rho - rho0 {base[3:6]} kg/m^3, want |.| < 1 (1e-3 rho0)")
    for j in range(3, 6):
        d2, d4 = abs(got["2"][1][j]), abs(got["4"][1][j])
        if not d4 < 0.2 * d2:
            failures.append(f"row {j} at stretch 1.27: |drho| {d4:.4g} at h = 4 dx against {d2:.4g} at 2 dx, "
                            "want under a fifth")
    out = run("--rows", "8", "--show", "6")
    if out.returncode == 0 or "--show 6 needs" not in out.stderr:
        failures.append(f"--rows 8 --show 6 at h = 2 dx: exit {out.returncode}, want a refusal naming --show")
    for f in failures:
        print("FAIL: " + f)
    print("OK" if not failures else f"{len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
