#!/usr/bin/env python3
"""tools/forced_jet_study.py and the jet theory it uses, on numbers known by construction (no sphjet).

1. The spatial growth (tools/axisymmetric.py spatial_growth): for a fast jet (We_a = 1e4) it is
   the temporal rate over U (Gaster's limit) within 1e-3; at We_a = 5.06 (the 0.78 m/s jet),
   inviscid, it is 1.10273 x that, the root of (omega - k U)^2 + k I1(k)/I0(k) (1 - k^2) = 0
   found independently with scipy.optimize.fsolve and scipy.special.iv (to 1e-4: the digits
   quoted). Newton's method should meet both to far better than these tolerances.
2. The forcing from the target (theory): eps u0 k / (4 omega) gives back delta0 / a to 1e-12,
   L = u0 ln(a/delta0) / omega, and one wavelength's drop (3/2 d0^2 lambda)^(1/3) = 1.891 d0 at
   k a = 0.697 (Rayleigh's 1.89) to 1e-3.
3. fit_sinh on the envelope A = 2 delta0 sinh(omega s / u0) sampled every 0.05 d0: delta0 and
   omega within 0.3% (its grid of omega has steps of 0.1%, delta0 follows in closed form), and
   only the points below 0.1 a are used (a point above, made 10x too big, must not move it).
4. pinch_lengths on a sawtooth intact length, L_p + (t mod T) u0 with L_p = 16 d0: every pinch
   is found (one per period) and each is L_p to the sampling's step.
5. `run --dry-run` lists the six runs with their eps; `report` on a fake study of one run
   (synthetic jet.csv, jet_surface.csv, drops.csv, run.log) gives its delta0, pinch length and
   drop median.

usage: test_forced_jet_study.py   (exit 0 on success, 1 with a message on failure)
"""
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, os.path.join(REPO, "tools"))
PY = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable

import forced_jet_study as fj  # noqa: E402
from axisymmetric import spatial_growth, weber_omega  # noqa: E402

fails = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        fails.append(what)


# 1. spatial growth
for we, oh, want, tol in ((1e4, 0.0048, 1.0, 1e-3), (5.06, 0.0, 1.10273, 1e-4)):
    got = spatial_growth(0.697, we, oh) * math.sqrt(we) / weber_omega(0.697, oh)
    check(abs(got - want) < tol, f"spatial growth / (temporal / U) at We_a = {we:g}, Oh = {oh:g}: "
          f"{got:.6f} (expected {want} within {tol:g})")

# 2. the forcing from the target
u, d0, delta = 0.7814, 0.001194, 1e-3
th = fj.theory(u, d0, delta)
k = fj.KA / (0.5 * d0)
check(abs(th["eps"] * u * k / (4.0 * th["omega"]) - delta) < 1e-12 * delta,
      f"eps = {th['eps']:.6g} gives delta0/a = {delta:g} back")
check(abs(th["L_d0"] - u * math.log(1.0 / delta) / th["omega"] / d0) < 1e-12,
      f"L/d0 = {th['L_d0']:.4f} = u0 ln(a/delta0) / omega")
check(abs(fj.DROP_D0 - 1.891) < 1e-3, f"one wavelength's drop {fj.DROP_D0:.4f} d0 (1.891)")

# 3. fit_sinh
omega, d_true = 230.0, 6e-3
env = []
s = 0.05
while s < 25.0:
    amp = 2.0 * d_true * math.sinh(omega * s * d0 / u)
    env.append((s, amp if amp < fj.A_LINEAR else 10.0 * amp, 100))
    s += 0.05
fit = fj.fit_sinh(env, u, d0)
check(fit is not None and abs(fit[0] / d_true - 1) < 3e-3 and abs(fit[1] / omega - 1) < 3e-3,
      f"fit_sinh: delta0 {fit and fit[0]:.5g} ({d_true}), omega {fit and fit[1]:.5g} ({omega})")

# 4. pinch_lengths
lam = fj.LAMBDA_D0
period = th["period"]
dt = period / 40
rows = []
for i in range(400):
    t = i * dt
    rows.append({"time": f"{t}", "broken": "1",
                 "L_over_d0": f"{16.0 + ((t + 1e-9) % period) * u / d0}"})
pinches = fj.pinch_lengths(rows, lam)
step = dt * u / d0
check(len(pinches) == 9 and all(abs(p - 16.0) <= step + 1e-9 for p in pinches),
      f"pinch_lengths: {len(pinches)} pinches (9), at {min(pinches):.3f}-{max(pinches):.3f} d0 (16)")

# 5. the command line
out = subprocess.run([PY, os.path.join(REPO, "tools", "forced_jet_study.py"), "run", "--dry-run"],
                     capture_output=True, text=True)
names = [n for _s, n, _x, _i in fj.plan(10)]
check(out.returncode == 0 and all(n in out.stdout for n in names) and "nozzle.disturbance=" in out.stdout,
      f"run --dry-run lists {len(names)} runs (exit {out.returncode})")
out = subprocess.run([PY, os.path.join(REPO, "tools", "forced_jet_study.py"), "run", "--dry-run", "--root", "/r",
                      "--artificial-alpha", "0.02"], capture_output=True, text=True)
check(out.returncode == 0 and out.stdout.count("numerics.artificial_alpha=0.02") == len(names)
      and os.path.join("/r", "n10_alpha0.02", names[0]) in out.stdout,
      f"run --artificial-alpha 0.02 --dry-run: the key in all {len(names)} runs, in ROOT/n10_alpha0.02 "
      f"(exit {out.returncode})")
out = subprocess.run([PY, os.path.join(REPO, "tools", "forced_jet_study.py"), "run", "--dry-run",
                      "--artificial-alpha", "2"], capture_output=True, text=True)
check(out.returncode == 2 and "--artificial-alpha" in out.stderr, f"--artificial-alpha 2 refused (exit {out.returncode})")
out = subprocess.run([PY, os.path.join(REPO, "tools", "forced_jet_study.py"), "run", "--dry-run", "--root", "/r",
                      "--artificial-alpha", "0.02", "--reconstruct"], capture_output=True, text=True)
check(out.returncode == 0 and out.stdout.count("numerics.artificial_reconstruction=true") == len(names)
      and os.path.join("/r", "n10_alpha0.02_rec", names[0]) in out.stdout,
      f"run --artificial-alpha 0.02 --reconstruct --dry-run: the key in all {len(names)} runs, in "
      f"ROOT/n10_alpha0.02_rec (exit {out.returncode})")
out = subprocess.run([PY, os.path.join(REPO, "tools", "forced_jet_study.py"), "run", "--dry-run", "--reconstruct"],
                     capture_output=True, text=True)
check(out.returncode == 2 and "--artificial-alpha" in out.stderr, f"--reconstruct alone refused (exit {out.returncode})")

with tempfile.TemporaryDirectory() as root:
    name, info = names[0], fj.plan(10)[0][3]
    d = os.path.join(root, "n10", name)
    os.makedirs(d)
    t_head, t_end = info["t_head"], info["t_end"]
    with open(os.path.join(d, "run.log"), "w") as f:
        f.write("sphjet 1 starting\ncase: x | particles 100 (boundary 0, fluid 100)\n"
                f"done: 1000 steps (1000 in all) to t = {t_end} s (SPHysics clock {t_end} s) in 10.00 s "
                "wall; 10000 particle-steps/s\n")
    jet = ["time,step,broken,L_over_d0"]
    surf = ["step,s_over_d0,r_over_d0"]
    drops = ["time,step,drop,particles,volume,d_eq_over_d0,xc,zc,s_max_over_d0,satellite"]
    n = 0
    t = 0.0
    om = info["omega"]
    while t <= t_end:
        step = str(n)
        jet.append(f"{t},{step},1,{16.0 + (t % info['period']) * u / d0}")
        if t >= t_head:
            x = 0.05
            while x < 12.0:
                amp = 2.0 * delta * math.sinh(om * x * d0 / u)
                surf.append(f"{step},{x:.2f},{0.5 + 0.5 * amp * math.sin(2 * math.pi * (t / info['period'] - x / lam))}")
                x += 0.1
            drops.append(f"{t},{step},0,100,1e-9,1.89,0,0,20,0")
            drops.append(f"{t},{step},1,5,1e-11,0.4,0,0,22,1")
        t += info["period"] / 40
        n += 1
    for fname, lines in (("jet.csv", jet), ("jet_surface.csv", surf), ("drops.csv", drops)):
        with open(os.path.join(d, fname), "w") as f:
            f.write("\n".join(lines) + "\n")
    r = fj.read_run(d, info)
    check(r["status"] == "finished", f"fake run: status {r['status']} {r['notes']}")
    check(r.get("delta0") is not None and abs(r["delta0"] / delta - 1) < 0.05,
          f"fake run: delta0 {r.get('delta0')} ({delta}; within 5%: the envelope is sampled over a whole "
          "number of periods only approximately)")
    check(r.get("L_pinch") is not None and abs(r["L_pinch"] - 16.0) < 0.12,
          f"fake run: pinch-off length {r.get('L_pinch')} (16, within one sample's 0.11 d0)")
    check(r.get("drop_median") == 1.89 and abs(r["sat_share"] - 0.4 ** 3 / (0.4 ** 3 + 1.89 ** 3)) < 1e-9,
          f"fake run: drop median {r.get('drop_median')}, satellite share {r.get('sat_share')}")
    out = subprocess.run([PY, os.path.join(REPO, "tools", "forced_jet_study.py"), "report", "--root", root,
                          "--out", os.path.join(root, "report")], capture_output=True, text=True)
    check(out.returncode == 0 and name in out.stdout and "Missing runs (5)" in out.stdout,
          f"report: exit {out.returncode}, lists {name} and 5 missing runs\n{out.stderr}")

if fails:
    print(f"FAILED: {len(fails)} check(s)")
    sys.exit(1)
print("PASS")
