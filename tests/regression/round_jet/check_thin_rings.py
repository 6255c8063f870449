#!/usr/bin/env python3
"""surface_tension.thin_rings_normals (fortran_core/loops/free_body_loops.f90): a free ring
narrower than a tube of radius 1.5 h takes the normals' curvature instead of the surface fit;
every other particle keeps the fit.

cases/round_jet/torus_fragment.toml (h = 2 dx = 0.119 mm, so 1.5 h = 0.179 mm) with its torus's
tube radius b set, the curvature of the first snapshot (t = 0) compared bitwise:
- b = 0.15 mm (a thin ring): with the key, the normals' curvature (surface_tension.curvature =
  "normals") at every particle; without it the fit's, which differs;
- b = 0.2 mm (its own, wider than 1.5 h): with the key, the fit's;
- b = 0.15 mm on the axis (xc = 0: a drop, not a ring): with the key, the fit's.

usage: check_thin_rings.py SPHJET SOURCE_DIR WORK_DIR
"""
import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from summary_checks import h5_particles, sphjet_run, with_h5py  # noqa: E402  (tests/regression/)

THIN, AXIS, KEY = "fluid.disc[0].radius=0.00015", "fluid.disc[0].xc=0", "surface_tension.thin_rings_normals=true"
NORMALS = "surface_tension.curvature=normals"


def main():
    with_h5py()
    import numpy as np
    sphjet, src, work = sys.argv[1:4]
    case = os.path.join(src, "cases", "round_jet", "torus_fragment.toml")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)

    def curvature(name, sets):
        out = os.path.join(work, name)
        sphjet_run(sphjet, case, out, sets, max_steps=1)
        return h5_particles(os.path.join(out, "snap_000000.h5"))["curvature"]

    k = {name: curvature(name, sets) for name, sets in (
        ("thin_fit", [THIN]), ("thin_normals", [THIN, NORMALS]), ("thin_key", [THIN, KEY]),
        ("wide_fit", []), ("wide_key", [KEY]),
        ("axis_fit", [THIN, AXIS]), ("axis_key", [THIN, AXIS, KEY]))}
    checks = [
        ("thin ring, the key: the normals' curvature", np.array_equal(k["thin_key"], k["thin_normals"])),
        ("thin ring, no key: the fit's, not the normals'", not np.array_equal(k["thin_fit"], k["thin_normals"])),
        ("wide ring, the key: the fit's", np.array_equal(k["wide_key"], k["wide_fit"])),
        ("thin drop on the axis, the key: the fit's", np.array_equal(k["axis_key"], k["axis_fit"])),
    ]
    for what, ok in checks:
        print(f"{what}: {'ok' if ok else 'FAILED'}")
    bad = sum(1 for _w, ok in checks if not ok)
    print(f"{len(checks) - bad} passed, {bad} failed")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
