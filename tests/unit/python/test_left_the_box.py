#!/usr/bin/env python3
"""tools/left_the_box.py on a run made by hand: three particles leave the box, one logged twice
(a part made again), one at an output step (inactive in that snapshot), and each is found in the
snapshot before it left, moved on at its velocity, against the jet's length then (its breakup
length, or an intact jet's tip)."""
import math
import os
import subprocess
import sys
import tempfile
import unittest

try:
    import h5py  # noqa: F401
    HAVE_H5PY = True
except ImportError:
    HAVE_H5PY = False

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "tools")
sys.path.insert(0, TOOLS)
import left_the_box as ltb  # noqa: E402

D0, U0, Z0 = 0.001, 1.0, 0.05


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def snapshot(path, t, ids, active, x, z, u, w, m):
    with h5py.File(path, "w") as f:
        f.attrs["time"] = t
        g = f.create_group("particles")
        for name, v in (("id", ids), ("active", active), ("x", x), ("z", z), ("u", u), ("w", w), ("m", m)):
            g.create_dataset(name, data=v)


@unittest.skipUnless(HAVE_H5PY, "needs h5py (apt-get install -y python3-h5py)")
class LeftTheBoxTests(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="left_the_box_")
        self.run = self.tmp.name
        write(os.path.join(self.run, "case.toml"),
              f'[domain]\ngeometry = "axisymmetric"\n[fluid]\nrho0 = 1000.0\n'
              f'[nozzle]\nd0 = {D0}\nu0 = {U0}\nz0 = {Z0}\ncolumn_over_d0 = 5.0\n')
        # the jet broken at 20 d0 from 0.01 s; from 0.02 s intact to its tip at 30 d0
        write(os.path.join(self.run, "jet.csv"), "time,broken,L_over_d0,jet_tip_over_d0\n0.0,0,0,0\n"
              "0.01,1,20,25\n0.02,0,0,30\n")
        gone = "step 5 t = 0.015 s: 1 particle(s) left the domain and were removed (1 in all); ids 7"
        write(os.path.join(self.run, "run.log"),
              "sphjet 1 starting\n" + gone + "\nsphjet 1 resuming\n" + gone + "\n"
              "step 8 t = 0.02 s: 1 particle(s) left the domain and were removed (2 in all); ids 9\n"
              "step 9 t = 0.025 s: 1 particle(s) left the domain and were removed (3 in all); ids 8\n")
        # id 7 at 0.01 s: 18 d0 below the orifice moving down at 1 m/s and out at 0.1 m/s: at
        # 0.015 s 23 d0 down (3 d0 past the 20 d0 jet), r = 2 + 0.5 = 2.5 d0. id 9 left at 0.02 s,
        # at the output step (inactive in snap_000001): from snap_000000, 10 d0 down, still: 20 d0
        # beside the intact jet then (its tip at 30 d0), r = 2.4 d0. id 8 at 0.02 s: 25 d0 down,
        # still: 5 d0 beside the intact jet, r = 2.6 d0
        snapshot(os.path.join(self.run, "snap_000000.h5"), 0.01, [7, 8, 9], [1, 1, 1], [2 * D0, 0.0, 2.4 * D0],
                 [Z0 - 18 * D0, Z0, Z0 - 10 * D0], [0.1, 0.0, 0.0], [-1.0, 0.0, 0.0], [1e-9, 1e-9, 1e-9])
        snapshot(os.path.join(self.run, "snap_000001.h5"), 0.02, [8, 9], [1, 0], [2.6 * D0, 0.0],
                 [Z0 - 25 * D0, 0.0], [0.0, 0.0], [0.0, 0.0], [2e-9, 1e-9])

    def tearDown(self):
        self.tmp.cleanup()

    def test_where_they_left(self):
        got = ltb.where_they_left(self.run)
        self.assertEqual((got["logged"], got["found"]), (3, 3))
        for value, expected in zip(sorted(got["below_end"]), (-20.0, -5.0, 3.0)):
            self.assertAlmostEqual(value, expected, places=9)
        for value, expected in zip(sorted(got["radius"]), (2.4, 2.5, 2.6)):
            self.assertAlmostEqual(value, expected, places=9)
        # issued by 0.025 s: the 5 d0 column and u0 t
        issued = 1000.0 * math.pi * (D0 / 2) ** 2 * (U0 * 0.025 + 5 * D0)
        self.assertAlmostEqual(got["mass_fraction"], 4e-9 / issued, places=12)

    def test_a_time_range(self):
        got = ltb.where_they_left(self.run, 0.021, 0.03)
        self.assertEqual((got["logged"], got["found"], got["t_first"]), (1, 1, 0.025))

    def test_a_run_without_its_case_is_named(self):
        os.remove(os.path.join(self.run, "case.toml"))
        p = subprocess.run([sys.executable, os.path.join(TOOLS, "left_the_box.py"), self.run],
                           capture_output=True, text=True)
        self.assertEqual(p.returncode, 1)
        self.assertIn("case.toml", p.stderr)


if __name__ == "__main__":
    unittest.main()
