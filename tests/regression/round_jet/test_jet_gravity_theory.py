#!/usr/bin/env python3
"""tools/jet_gravity_theory.py against closed forms.

- Without gravity the jet is uniform, so N(z) = omega_max(a0) z / U: the grid's N at the 0.78 m/s
  jet's measured length must be that to 1e-9 relative (a sum of equal terms; rounding only).
- With gravity, a jet whose fastest rate scaled exactly as a^(-3/2) (Rayleigh's, no viscosity)
  would grow per length as (U / U(z))^(1/4) k0 and reach
  N(L) = k0 l (8/7) [(1 + L/l)^(7/8) - 1], l = U^2 / (2 g), k0 = omega_max(a0) / U.
  Weber's viscous term makes omega_max a^(3/2) fall slowly as the jet thins: Oh(a) =
  mu / sqrt(rho sigma a) grows from 0.0048 to 0.0062 over the 0.34 m/s jet's measured length,
  and the viscous term takes about 1.1% of omega at the first and 1.3% at the second. So the
  tool's N must lie below the closed form and within 1% of it: a sign or a factor error in the
  radius or the speed moves N by tens of per cent.
- length() must invert exponent(): the z at which N reaches N(z) is z to 1e-6 relative (the
  linear interpolation of a linear function between grid points).
- critical_weber() (Clanet & Lasheras's dripping-to-jetting Weber number) against its expansion
  in eps = K Bo Bo_o, written out by hand: We_c / (4 d_in / d_out) = 1 - 2 sqrt(2 eps) + 4 eps
  + O(eps^(3/2)). At eps = 1e-4 the dropped terms are about 1e-6, so 1e-5 relative separates the
  formula from a slip in a factor (a factor 2 in eps moves it by about 1e-2). At eps = 1e-12
  (g -> 0) it must be 4 d_in / d_out less the expansion's 2.8e-6, within 1e-6; it must fall as
  g grows, and refuse d_out < d_in.
- unstable_reach() (the pocket of local absolute instability below the orifice): at its z_a the
  falling jet's local Weber number, from the speed and radius Jet integrates over, U(z) =
  sqrt(U^2 + 2 g z) and a(z) = a0 sqrt(U / U(z)), must be 2 pi to 1e-12 relative (rounding
  only; a slip in the exponent 4/3 moves it by tens of per cent), at 0.3441 and 0.4946 m/s; 0 for
  a jet that leaves at We_d >= 2 pi (0.7814 m/s); inf without gravity for one that leaves below.
- one_c() (one C for every length within 20%) on jets without gravity, whose N = k z is linear:
  each asks for 0.8 k L <= C <= 1.2 k L, so for two jets the answer is max of the lower ends and
  min of the upper ends, to 1e-9 relative (the grid's N is exact for a linear N, above), with
  the speeds that set them; two lengths 1.6 times apart in N leave none (lower end above the
  upper).
- table(relaxed=True) (--relaxed): the 0.3441 m/s row must carry the relaxed plug's numbers,
  the falling C its Jet's N at the measured length and the pocket its unstable_reach (16.2 d0,
  against the tube's plug's 18.8), to the digits printed; its one-C line must read "none".
- one_frequency (--one-frequency: N of the frequency that has grown most, each carried down at its
  own frequency). Without gravity every wave keeps its ka, so it must be the fastest rate's N,
  within 1e-5 relative along the whole grid (the parabola through a grid of 2% steps; measured
  7.1e-6). With gravity (0.3441 and 1.5699 m/s, the relaxed plugs) a wave's ka drifts off the
  fastest, so it must lie at or below the fastest rate's N at every grid point, and by the
  measured length below it by more than 1% (by 21% and 1.5%: the check only that the drift is
  there, not its size). Its value at the measured length must be the best grid frequency's N
  from an independent Simpson quadrature of that frequency's rate (4000 intervals) or up to 1e-3
  above it (the parabola's step between grid frequencies; the lower end holds while that step
  exceeds the tool's trapezoid error, by 6.3e-4 and 1.4e-4 relative as measured), and a grid of
  steps 1.005 must give it within 1e-3 (the module's ONE_KA0_* comment). best_frequency() there
  must be that grid wave's omega, and the waves two grid steps either side of it (exit ka 4% apart)
  must reach a smaller N by the same quadrature (1000 intervals): it is the one that has grown most.
- spatial (--spatial: each frequency grown at its spatial rate, -Im k of Keller, Rubinow & Tu's
  problem). spatial_wavenumbers (Newton with the closed-form derivative, numpy) must give
  axisymmetric.spatial_growth's roots (Newton with a numerical derivative, one at a time) to 1e-10
  per radius at We_d 6.4, 10.1 and 41.6, ka 0.3-1.2 (measured 6e-16). Without gravity at We_d 10.1
  (0.7814 m/s) every wave keeps its ka, so N must be z times the largest -Im k over ka (a golden
  section on spatial_growth) within 1e-4 relative along the grid: the parabola through frequencies
  2% apart, measured 1.4e-5 (the temporal picture's 7.1e-6); the spatial rate there is 1.115
  times the temporal one, so a slip to Gaster's relation is 11% off. Without gravity below We_d =
  2 pi (0.3441 m/s) the whole jet is the pocket, where the temporal rate over U stands in: N must
  be --one-frequency's exactly. Falling at 1.5699 m/s (the relaxed plug, We_d 62) the spatial rate
  is at or above the temporal one, so N must be at or above --one-frequency's at every grid point,
  and within 3% of it at the measured length (Gaster's limit; measured 1.2%).
"""
import math
import os
import sys

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
sys.path.insert(0, os.path.join(REPO, "tools"))
import jet_gravity_theory as jgt  # noqa: E402

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


a0 = 0.5 * jgt.D0_MC
u, l_d0 = 0.7814, 67.52
z = l_d0 * jgt.D0_MC
flat = jgt.Jet(u, a0, 0.0)
exact = jgt.omega_max(a0) / u * z
check(abs(flat.exponent(z) / exact - 1.0) < 1e-9,
      f"no gravity: N = omega_max L / U ({flat.exponent(z):.9g} against {exact:.9g})")

for u, l_d0 in ((0.3441, 31.85), (0.7814, 67.52), (1.5699, 94.96)):
    g = 9.81
    z = l_d0 * jgt.D0_MC
    jet = jgt.Jet(u, a0, g)
    ell = u * u / (2.0 * g)
    k0 = jgt.omega_max(a0) / u
    closed = k0 * ell * (8.0 / 7.0) * ((1.0 + z / ell) ** 0.875 - 1.0)
    n = jet.exponent(z)
    check(0.99 * closed < n < closed,
          f"gravity, {u} m/s: N = {n:.4f} within 1% below the inviscid scaling's {closed:.4f}")
    back = jet.length(n)
    check(abs(back / z - 1.0) < 1e-6, f"gravity, {u} m/s: length(N(L)) = L ({back:.9g} against {z:.9g})")

d = jgt.D0_MC
for ratio in (1.0, 1.383):
    for eps in (1e-12, 1e-4):
        # eps = K Bo Bo_o = K d^2 ratio rho g / (2 sigma): the g that gives it
        g = eps * 2.0 * jgt.SIGMA / (jgt.K_CL * d * d * ratio * jgt.RHO)
        got = jgt.critical_weber(d, ratio * d, g) / (4.0 / ratio)
        series = 1.0 - 2.0 * (2.0 * eps) ** 0.5 + 4.0 * eps
        tol = 1e-6 if eps < 1e-6 else 1e-5
        check(abs(got - series) < tol,
              f"We_c, d_out/d_in {ratio}, eps {eps:g}: {got:.8f} of 4 d_in/d_out against the "
              f"expansion's {series:.8f}")
wcs = [jgt.critical_weber(d, 1.383 * d, g) for g in (0.1, 1.0, 9.81, 100.0)]
check(all(a > b for a, b in zip(wcs, wcs[1:])), f"We_c falls as g grows: {', '.join(f'{w:.3f}' for w in wcs)}")
try:
    jgt.critical_weber(d, 0.9 * d, 9.81)
    check(False, "d_out < d_in refused")
except ValueError as e:
    check("d_in <= d_out" in str(e), f"d_out < d_in refused: {e}")

for u in (0.3441, 0.4946):
    g = 9.81
    za = jgt.unstable_reach(u, jgt.D0_MC, g)
    uz = math.sqrt(u * u + 2.0 * g * za)
    we_local = jgt.RHO * uz * uz * jgt.D0_MC * math.sqrt(u / uz) / jgt.SIGMA
    check(abs(we_local / (2.0 * math.pi) - 1.0) < 1e-12,
          f"{u} m/s falling: local We_d at z_a = {za / jgt.D0_MC:.2f} d0 is {we_local:.12g} (2 pi)")
check(jgt.unstable_reach(0.7814, jgt.D0_MC, 9.81) == 0.0, "0.7814 m/s (We_d > 2 pi): no pocket")
check(jgt.unstable_reach(0.4946, jgt.D0_MC, 0.0) == math.inf, "0.4946 m/s without gravity: the whole jet")

slow, fast = jgt.Jet(0.5, a0, 0.0), jgt.Jet(1.0, a0, 0.0)
k_slow, k_fast = jgt.omega_max(a0) / 0.5, jgt.omega_max(a0) / 1.0
l_slow, l_fast = 30 * jgt.D0_MC, 50 * jgt.D0_MC   # N(L) = 60 and 50 omega_max d0: C from 48 to 60 of it
lo, u_lo, hi, u_hi = jgt.one_c([(0.5, l_slow, slow), (1.0, l_fast, fast)])
want_lo = max((0.8 * k_slow * l_slow, 0.5), (0.8 * k_fast * l_fast, 1.0))
want_hi = min((1.2 * k_slow * l_slow, 0.5), (1.2 * k_fast * l_fast, 1.0))
check(abs(lo / want_lo[0] - 1) < 1e-9 and abs(hi / want_hi[0] - 1) < 1e-9 and (u_lo, u_hi) == (want_lo[1], want_hi[1]),
      f"one C: {lo:.6g} ({u_lo}) to {hi:.6g} ({u_hi}), closed form {want_lo[0]:.6g} ({want_lo[1]}) "
      f"to {want_hi[0]:.6g} ({want_hi[1]})")
lo, _u, hi, _v = jgt.one_c([(0.5, l_slow, slow), (1.0, 1.6 * l_slow * k_slow / k_fast, fast)])
check(lo > hi and "none" in jgt.one_c_line([(0.5, l_slow, slow), (1.0, 1.6 * l_slow * k_slow / k_fast, fast)]),
      f"lengths 1.6 times apart in N: no one C ({lo:.4g} > {hi:.4g})")

text = jgt.table(9.81, relaxed=True)
row = next(line for line in text.splitlines() if line.startswith("| 0.3441 |"))
cells = [c.strip() for c in row.strip("|").split("|")]
_x, u_r, d_r = jgt.relaxed_exit(0.3441, jgt.D0_MC)
want_c = jgt.Jet(u_r, 0.5 * d_r, 9.81).exponent(31.85 * jgt.D0_MC)
want_pocket = jgt.unstable_reach(u_r, d_r, 9.81) / jgt.D0_MC
check(cells[4] == f"{want_c:.2f}" and cells[5] == f"{want_pocket:.1f}",
      f"--relaxed 0.3441 m/s: falling C {cells[4]} (relaxed plug {want_c:.2f}), pocket {cells[5]} d0 "
      f"(relaxed plug {want_pocket:.1f}, the tube's plug {jgt.unstable_reach(0.3441, jgt.D0_MC, 9.81) / jgt.D0_MC:.1f})")
check("  with gravity:    none" in text, "--relaxed: no one C with gravity")

flat_one, flat_max = jgt.Jet(0.7814, a0, 0.0, one_frequency=True), jgt.Jet(0.7814, a0, 0.0)
worst = max(abs(x / y - 1.0) for x, y in zip(flat_one.n[1:], flat_max.n[1:]))
check(worst < 1e-5, f"one frequency without gravity: the fastest rate's N to {worst:.2g} relative")


def one_wave(u, a, g, ka0, z, intervals=4000):
    """N at z of the wave that leaves a plug of speed u and radius a at ka0: Simpson's rule."""
    omega = ka0 * u / a
    h = z / intervals

    def rate(s):
        uz = math.sqrt(u * u + 2.0 * g * s)
        r = a * math.sqrt(u / uz)
        oh = jgt.MU / math.sqrt(jgt.RHO * jgt.SIGMA * r)
        return jgt.weber_omega(omega * r / uz, oh) * math.sqrt(jgt.SIGMA / (jgt.RHO * r ** 3)) / uz
    return h / 3.0 * sum((1 if i in (0, intervals) else 4 if i % 2 else 2) * rate(i * h)
                         for i in range(intervals + 1))


for u, l_d0 in ((0.3441, 31.85), (1.5699, 94.96)):
    _x, u_r, d_r = jgt.relaxed_exit(u, jgt.D0_MC)
    one, fastest = jgt.Jet(u_r, 0.5 * d_r, 9.81, one_frequency=True), jgt.Jet(u_r, 0.5 * d_r, 9.81)
    z = l_d0 * jgt.D0_MC
    i = round(z / one.dz)
    z = i * one.dz   # on the grid, where N is the parabola's and best_ka0 its frequency
    check(all(x <= y * (1 + 1e-9) for x, y in zip(one.n, fastest.n)) and one.n[i] < 0.99 * fastest.n[i],
          f"{u} m/s falling: one frequency's N at or below the fastest rate's everywhere; at the measured "
          f"length {one.n[i]:.3f} against {fastest.n[i]:.3f}")
    single = one_wave(u_r, 0.5 * d_r, 9.81, one.best_ka0[i], z)
    check(single <= one.n[i] <= single * (1 + 1e-3),
          f"{u} m/s falling: N {one.n[i]:.5f} at or up to 1e-3 above its best grid wave's (exit ka "
          f"{one.best_ka0[i]:.3f}) by Simpson's rule, {single:.5f}")
    omega = one.best_frequency(z)
    beside = [one_wave(u_r, 0.5 * d_r, 9.81, one.best_ka0[i] * f, z, 1000) for f in (1.02 ** -2, 1.02 ** 2)]
    check(omega == one.best_ka0[i] * u_r / (0.5 * d_r) and max(beside) < single,
          f"{u} m/s falling: best_frequency {omega:.1f} 1/s is the best grid wave's, and waves two grid steps "
          f"either side grow less by Simpson's rule ({beside[0]:.5f}, {beside[1]:.5f} < {single:.5f})")
    step = jgt.ONE_KA0_STEP
    jgt.ONE_KA0_STEP = 1.005
    fine = jgt.Jet(u_r, 0.5 * d_r, 9.81, one_frequency=True)
    jgt.ONE_KA0_STEP = step
    worst = max(abs(x / y - 1.0) for x, y in zip(one.n[1:], fine.n[1:]))
    check(worst < 1e-3, f"{u} m/s falling: a grid of steps 1.005 gives N within {worst:.2g} relative")

# spatial (--spatial): each frequency at its spatial rate
from axisymmetric import spatial_growth  # noqa: E402
for we_d in (6.4, 10.1, 41.6):
    kas = [0.3 + 0.1 * i for i in range(10)]
    oh = jgt.MU / math.sqrt(jgt.RHO * jgt.SIGMA * a0)
    guess = [complex(x, -jgt.weber_omega(x, oh) / math.sqrt(0.5 * we_d)) for x in kas]
    roots = jgt.spatial_wavenumbers(kas, 0.5 * we_d, oh, guess)
    worst = max(abs(-k.imag - spatial_growth(x, 0.5 * we_d, oh)) for k, x in zip(roots, kas))
    check(worst < 1e-10, f"spatial_wavenumbers at We_d {we_d}: axisymmetric.spatial_growth's roots to {worst:.2g}")


def fastest_spatial(we_a, oh):
    """The largest spatial growth per radius over ka (golden section on axisymmetric.spatial_growth)."""
    lo, hi = 0.3, 0.99
    r = (math.sqrt(5.0) - 1.0) / 2.0
    while hi - lo > 1e-8:
        x1, x2 = hi - r * (hi - lo), lo + r * (hi - lo)
        if spatial_growth(x1, we_a, oh) < spatial_growth(x2, we_a, oh):
            lo = x1
        else:
            hi = x2
    return spatial_growth(0.5 * (lo + hi), we_a, oh)


flat_sp = jgt.Jet(0.7814, a0, 0.0, spatial=True)
oh0 = jgt.MU / math.sqrt(jgt.RHO * jgt.SIGMA * a0)
k_sp = fastest_spatial(jgt.RHO * 0.7814 ** 2 * a0 / jgt.SIGMA, oh0) / a0
worst = max(abs(n / (k_sp * i * flat_sp.dz) - 1.0) for i, n in enumerate(flat_sp.n) if i > 0)
check(worst < 1e-4, f"spatial without gravity (0.7814 m/s, We_d 10.1): N = z max_ka(-Im k) to {worst:.2g} relative "
                    f"({k_sp * a0 / (jgt.omega_max(a0) * a0 / 0.7814):.4f} times the fastest temporal rate over U)")
slow_sp, slow_one = jgt.Jet(0.3441, a0, 0.0, spatial=True), jgt.Jet(0.3441, a0, 0.0, one_frequency=True)
check(slow_sp.n == slow_one.n, "spatial without gravity below We_d = 2 pi (0.3441 m/s): the pocket's temporal N")
_x, u_r, d_r = jgt.relaxed_exit(1.5699, jgt.D0_MC)
fast_sp, fast_one = jgt.Jet(u_r, 0.5 * d_r, 9.81, spatial=True), jgt.Jet(u_r, 0.5 * d_r, 9.81, one_frequency=True)
i = round(94.96 * jgt.D0_MC / fast_sp.dz)
check(all(x >= y * (1 - 1e-9) for x, y in zip(fast_sp.n, fast_one.n)) and fast_sp.n[i] <= 1.03 * fast_one.n[i],
      f"1.5699 m/s falling (We_d 62 at its relaxed exit): spatial N at or above the temporal one-frequency N "
      f"everywhere, within 3% at the measured length ({fast_sp.n[i]:.3f} against {fast_one.n[i]:.3f})")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all checks passed")
