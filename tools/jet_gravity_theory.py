#!/usr/bin/python3
"""Weber's linear growth along a round jet that gravity speeds up and thins: what ln(a/delta0)
each measured breakup length of cases/round_jet/mansour_chigier_1994.csv asks for, with and
without gravity along the jet, and the length a given ln(a/delta0) gives.

Usage:
  /usr/bin/python3 tools/jet_gravity_theory.py [--g 9.81] [--c C] [--relaxed] [--one-frequency | --spatial]

A jet leaving at U with radius a0, falling along its axis, moves at U(z) = sqrt(U^2 + 2 g z)
with radius a(z) = a0 sqrt(U / U(z)) (mass flux kept, the pressure and the air left out).
Taking the local growth (the WKB picture of a slowly varying jet), a disturbance grows by
exp(N(z)) with
  N(z) = int_0^z omega_max(a(s), Oh(s)) / U(s) ds,
omega_max Weber's fastest temporal rate (tools/axisymmetric.py, weber_omega) at the local radius
and Ohnesorge number. The jet breaks where N = ln(a/delta0) = C, so each measured length L gives
C = N(L); without gravity N(L) = omega_max(a0) L / U. A uniform jet's temporal rate carried at U
is Weber's law's picture (L/d0 = C sqrt(We_d)(1 + 3 Oh_d) up to the constant of omega_max).
That rate is an upper bound along a jet that speeds up: a disturbance keeps its frequency omega as
it is carried down, so its local wavenumber is omega / U(z) and its ka = omega a(z) / U(z) falls
as the jet stretches, away from the fastest one. --one-frequency takes the WKB picture of a jet
stretched by gravity (Javadi, Eggers, Bonn, Habibi & Ribe 2013, PRL 110, 144501) instead:
  N_omega(z) = int_0^z omega_W(omega a(s) / U(s), Oh(s)) / U(s) ds,
omega_W Weber's temporal rate at that ka and radius, and N(z) = max over omega of N_omega(z), the
frequency that has grown most by z (the frequencies on a geometric grid of their exit ka,
ONE_KA0_LOW, ONE_KA0_STEP and ONE_KA0_PAST, the maximum refined through a parabola; the amplitude factor of
the stretching itself is left out). Without gravity it is the fastest rate's N. --spatial
follows each frequency the same way but grows it at its spatial rate, -Im k of the complex
wavenumber k that the local jet gives a real frequency omega (Keller, Rubinow & Tu 1973, with
Weber's viscous term: tools/axisymmetric.py, spatial_growth), the problem of a jet disturbed at
its orifice and not in time. At a high Weber number it is the temporal rate over U (Gaster's
relation); near We_d = 2 pi it is faster (1.24 times the fastest temporal rate over U at We_d
6.4, 1.05 at 20). Below We_d = 2 pi the two spatial branches have pinched and there is no
downstream wave to follow: in the pocket (below) the temporal rate over U stands in. Absolute
instability near the orifice (We_d < 2 pi without gravity, Leib & Goldstein 1986) is not in
this local picture; where the jet speeds up past it, the convective part is what this
integrates. The table's "absolutely unstable to" is how far below the orifice the local Weber
number rho U(z)^2 d(z) / sigma = We_d (U(z) / U)^(3/2) stays below 2 pi:
  z_a = U^2 [(2 pi / We_d)^(4/3) - 1] / (2 g)
(0 at and above We_d = 2 pi; the whole jet without gravity), the pocket of local absolute
instability of a plug leaving a tube with no face (a local criterion, as N is; whether a pocket
that long makes the jet drip is a global question it does not answer). With --c C it also
prints the lengths that C gives with and without gravity. It prints whether one C puts every
measured length within 20% (each speed asks for N(0.8 L) <= C <= N(1.2 L)), and with --relaxed
it takes each jet as the flat plug its tube's parabolic profile relaxes to (round_jet_study.py's
relaxed_exit, the study's --relaxed-exit).

Whether a slow jet forms at all, or the tube drips, it prints from Clanet & Lasheras (1999, JFM
383, 307): a liquid injected downward jets above the Weber number
  We_c = 4 (Bo / Bo_o) [1 + K Bo Bo_o - sqrt((1 + K Bo Bo_o)^2 - 1)]^2,
Bo = d sqrt(rho g / (2 sigma)) on the tube's inner diameter, Bo_o on its outer one (where the
meniscus holds), K = 0.37 for water in air; We = rho U^2 d_in / sigma, the study's We_d. Its two
rims: the outer diameter at the jet's own (a tube without a wall, as sphjet's nozzle, which has
no face at the orifice), and --d-out (default 1.651 mm, a 16-gauge regular-wall hypodermic
tube, whose bore is the measured tube's 1.194 mm; the data do not state the tube's wall).
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from axisymmetric import bessel_i, weber_omega  # noqa: E402
from round_jet_study import D0_MC, G_FALL, MU, RHO, SIGMA, read_mc, relaxed_exit  # noqa: E402

K_CL = 0.37        # Clanet & Lasheras's constant for water in air
D_OUT_16G = 1.651e-3  # outer diameter of 16-gauge regular-wall hypodermic tubing [m] (bore 1.194 mm)
GRID = 1200        # points along the jet, 0 .. 2 L_max: N by the trapezoid rule (1e-6 relative)
L_MAX_D0 = 400.0   # the longest jet it integrates [d0]
# --one-frequency: the frequencies it follows, by their ka at the exit, from ONE_KA0_LOW in steps
# of ONE_KA0_STEP times to past ONE_KA0_PAST times the fastest ka where the jet is fastest (the end
# of the grid), so that the wave that grows most at any z on it is inside the range. With the
# parabola through the best three, N is within 1e-3 of a grid of steps 1.005 (0.3441 m/s, the
# relaxed plug, falling: 7.6e-4 at most, where the best wave left the exit above ka 1 and
# decayed first; tests/regression/round_jet/test_jet_gravity_theory.py).
ONE_KA0_LOW, ONE_KA0_STEP, ONE_KA0_PAST = 0.3, 1.02, 1.5


def omega_max(a, rho=RHO, sigma=SIGMA, mu=MU):
    """Weber's fastest growth rate [1/s] of a column of radius a [m] (water unless rho [kg/m^3],
    sigma [N/m] and mu [Pa s] say otherwise): golden-section search over ka in [0.3, 0.99] (one
    maximum there)."""
    oh = mu / math.sqrt(rho * sigma * a)  # on the radius, as weber_omega takes it
    lo, hi = 0.3, 0.99
    r = (math.sqrt(5.0) - 1.0) / 2.0
    x1, x2 = hi - r * (hi - lo), lo + r * (hi - lo)
    f1, f2 = weber_omega(x1, oh), weber_omega(x2, oh)
    while hi - lo > 1e-7:
        if f1 < f2:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + r * (hi - lo)
            f2 = weber_omega(x2, oh)
        else:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - r * (hi - lo)
            f1 = weber_omega(x1, oh)
    return max(f1, f2) * math.sqrt(sigma / (rho * a ** 3))


def unstable_reach(u, d0, g):
    """z_a [m]: how far below the orifice a plug jet of speed u [m/s] and diameter d0 [m], falling
    at g [m/s^2], stays locally absolutely unstable (its local We_d below 2 pi; the module's
    docstring has the formula). 0 when it leaves at We_d >= 2 pi; inf when it never gets there
    (g = 0)."""
    we_d = RHO * u * u * d0 / SIGMA
    if we_d >= 2.0 * math.pi:
        return 0.0
    if g <= 0.0:
        return math.inf
    return u * u * ((2.0 * math.pi / we_d) ** (4.0 / 3.0) - 1.0) / (2.0 * g)


def critical_weber(d_in, d_out, g):
    """Clanet & Lasheras's (1999) Weber number rho U^2 d_in / sigma above which a tube of inner
    diameter d_in and outer d_out [m], pointing down under gravity g [m/s^2], jets rather than
    drips (the module's docstring has the formula)."""
    if not 0.0 < d_in <= d_out:
        raise ValueError(f"tube diameters: expected 0 < d_in <= d_out, found {d_in:g}, {d_out:g}")
    scale = math.sqrt(RHO * g / (2.0 * SIGMA))
    bo, bo_out = d_in * scale, d_out * scale
    x = 1.0 + K_CL * bo * bo_out
    # x - sqrt(x^2 - 1) written as 1 / (x + sqrt(x^2 - 1)), which loses no digits as g -> 0
    return 4.0 * (d_in / d_out) / (x + math.sqrt(x * x - 1.0)) ** 2


def spatial_wavenumbers(ka_f, we_a, oh, k):
    """The complex wavenumbers k a (numpy array) that a jet of Weber number we_a = rho U^2 a / sigma
    and Ohnesorge number oh (on its radius) gives the real frequencies omega = U ka_f / a: the roots
    of s^2 + 3 oh (ka)^2 s = rayleigh_omega2(ka), s = -i (omega - k U) in units of
    sqrt(sigma / (rho a^3)) (tools/axisymmetric.py, spatial_growth, whose scalar roots these are),
    by Newton's method from k (one guess per frequency) with the derivative in closed form:
    (I1/I0)' = 1 - (I1/I0)/ka - (I1/I0)^2. The branch is the guess's; -Im k is the growth per
    radius. Raises ArithmeticError if a root is not found to 1e-12 in 50 steps."""
    import numpy as np
    u = math.sqrt(we_a)
    w = u * np.asarray(ka_f, dtype=float)
    k = np.array(k, dtype=complex)
    for _ in range(50):
        q = bessel_i(1, k) / bessel_i(0, k)   # the power series, elementwise on the array
        r = k * (1.0 - k * k) * q
        dr = (1.0 - 3.0 * k * k) * q + k * (1.0 - k * k) * (1.0 - q / k - q * q)
        s, ds = -1j * (w - k * u), 1j * u
        f = s * s + 3.0 * oh * k * k * s - r
        df = 2.0 * s * ds + 3.0 * oh * (2.0 * k * s + k * k * ds) - dr
        step = f / df
        k = k - step
        if np.all(np.abs(step) < 1e-12 * (1.0 + np.abs(k))):
            return k
    raise ArithmeticError(f"spatial_wavenumbers: no root to 1e-12 in 50 steps at We_a = {we_a:g}, Oh = {oh:g}")


def cumulate(rates, dz):
    """The trapezoid rule's running integral of rates on a grid of step dz (0 at the first)."""
    n = [0.0]
    for r0, r1 in zip(rates, rates[1:]):
        n.append(n[-1] + 0.5 * (r0 + r1) * dz)
    return n


def parabola_max(f0, f1, f2):
    """The largest value of the parabola through (-1, f0), (0, f1), (1, f2), f1 the largest of
    the three."""
    curv = f0 - 2.0 * f1 + f2
    return f1 if curv >= 0.0 else f1 - (f2 - f0) ** 2 / (8.0 * curv)


class Jet:
    """N(z) of one jet (speed u [m/s], radius a0 [m], gravity g [m/s^2] along it; water unless
    rho, sigma and mu say otherwise, as omega_max) on a grid: the fastest local rate's, or with
    one_frequency the frequency that has grown most's, or with spatial the same at each
    frequency's spatial rate (the module's docstring)."""

    def __init__(self, u, a0, g, rho=RHO, sigma=SIGMA, mu=MU, one_frequency=False, spatial=False):
        one_frequency = one_frequency or spatial
        self.u, self.a0, self.g, self.rho, self.sigma, self.mu = u, a0, g, rho, sigma, mu
        self.dz = L_MAX_D0 * 2.0 * a0 / (GRID - 1)
        # the grid points' speed and radius (local()'s, on the grid)
        self.speed = speed = [math.sqrt(u * u + 2.0 * g * i * self.dz) for i in range(GRID)]
        self.radius = radius = [a0 * math.sqrt(u / uz) for uz in speed]
        if not one_frequency:
            flat = omega_max(a0, rho, sigma, mu) / u if g == 0.0 else None   # one rate along a jet without gravity
            self.n = cumulate([flat if flat is not None else omega_max(a, rho, sigma, mu) / uz
                               for uz, a in zip(speed, radius)], self.dz)
            return
        # a wave's local ka is its exit ka times (a / a0) (u / U) = (u / U)^(3/2); the fastest is below 0.7
        top = ONE_KA0_PAST * 0.7 * (speed[-1] / u) ** 1.5
        self.ka0 = [ONE_KA0_LOW * ONE_KA0_STEP ** i
                    for i in range(int(math.log(top / ONE_KA0_LOW) / math.log(ONE_KA0_STEP)) + 2)]
        local = self.grid_points()
        omegas = [ka0 * u / a0 for ka0 in self.ka0]
        each = (self.spatial_exponents(omegas, local) if spatial
                else [self.wave_exponent(omega, local) for omega in omegas])
        # best_ka0: the grid's frequency that has grown most (its exit ka); at z = 0, where every N is 0,
        # it is the grid's first, and means nothing
        self.n, self.best_ka0 = [], []
        for i in range(GRID):
            col = [n[i] for n in each]
            j = max(range(len(col)), key=col.__getitem__)
            inner = 0 < j < len(col) - 1
            self.best_ka0.append(self.ka0[j])
            self.n.append(parabola_max(col[j - 1], col[j], col[j + 1]) if inner else col[j])

    def local(self, z):
        """The jet's speed [m/s] and radius [m] at z."""
        uz = math.sqrt(self.u * self.u + 2.0 * self.g * z)
        return uz, self.a0 * math.sqrt(self.u / uz)

    def best_frequency(self, z):
        """The angular frequency omega [1/s] of the grid's frequency that has grown most by z, at the
        grid point nearest z past the orifice (one_frequency only)."""
        i = min(max(int(round(z / self.dz)), 1), GRID - 1)
        return self.best_ka0[i] * self.u / self.a0

    def grid_points(self):
        """Each grid point's speed, radius, Ohnesorge number and capillary rate scale, the same for
        every frequency."""
        rho, sigma, mu = self.rho, self.sigma, self.mu
        return [(uz, a, mu / math.sqrt(rho * sigma * a), math.sqrt(sigma / (rho * a ** 3)))
                for uz, a in zip(self.speed, self.radius)]

    def wave_exponent(self, omega, points=None):
        """N_omega on the grid (a list, 0 at the orifice): the growth of the one wave of angular
        frequency omega [1/s], carried down at that frequency, at Weber's rate at its local ka =
        omega a(z) / U(z) (the one-frequency picture's integrand; below 0 where that ka is stable).
        points: grid_points(), when the caller has them."""
        points = self.grid_points() if points is None else points
        return cumulate([weber_omega(omega * a / uz, oh) * scale / uz for uz, a, oh, scale in points], self.dz)

    def spatial_exponents(self, omegas, points=None):
        """N_omega on the grid for each angular frequency of omegas [1/s] (a list of lists, 0 at the
        orifice), each wave grown at its spatial rate -Im k (spatial_wavenumbers at its local ka_f =
        omega a(z) / U(z), We and Oh), and in the pocket of absolute instability (local We_d below
        2 pi) at its temporal rate over U, as wave_exponent. The root at each grid point is
        continued from the next one down the jet (k a scaled by the radii), starting where the jet
        is fastest from Gaster's guess ka_f - i omega_W / U (the downstream branch at a high Weber
        number). points: grid_points(), when the caller has them."""
        import numpy as np
        points = self.grid_points() if points is None else points
        omegas = np.asarray(omegas, dtype=float)
        rates = np.empty((GRID, len(omegas)))
        k, a_next = None, None
        for i in range(GRID - 1, -1, -1):
            uz, a, oh, scale = points[i]
            we_a = self.rho * uz * uz * a / self.sigma
            ka_f = omegas * a / uz
            if we_a < math.pi:   # the pocket: the local We_d = 2 we_a below 2 pi
                rates[i] = [weber_omega(x, oh) * scale / uz for x in ka_f]
                k = None
                continue
            if k is None:
                guess = ka_f - 1j * np.array([weber_omega(x, oh) for x in ka_f]) / math.sqrt(we_a)
            else:
                guess = k * (a / a_next)
            k, a_next = spatial_wavenumbers(ka_f, we_a, oh, guess), a
            rates[i] = -k.imag / a
        return [cumulate(list(col), self.dz) for col in rates.T]

    def exponent_at(self, n, z):
        """A grid's N (this one's n, or a wave_exponent) at z [1], linear between grid points."""
        i = min(int(z / self.dz), GRID - 2)
        t = z / self.dz - i
        return (1.0 - t) * n[i] + t * n[i + 1]

    def exponent(self, z):
        """N(z) [1], linear between grid points."""
        return self.exponent_at(self.n, z)

    def length(self, c):
        """The z [m] at which N reaches c (None beyond the grid)."""
        for i in range(GRID - 1):
            if self.n[i + 1] >= c:
                return (i + (c - self.n[i]) / (self.n[i + 1] - self.n[i])) * self.dz
        return None


def one_c(jets, band=0.2):
    """The ln(a/delta0) that puts every jet's length within band of its measured one: jets is
    [(U, L [m], Jet)]; each asks for N(L (1 - band)) <= C <= N(L (1 + band)). -> (lowest C, its U,
    highest C, its U): no such C where lowest > highest."""
    lo = max((jet.exponent((1.0 - band) * l), u) for u, l, jet in jets)
    hi = min((jet.exponent((1.0 + band) * l), u) for u, l, jet in jets)
    return lo[0], lo[1], hi[0], hi[1]


def one_c_line(jets, band=0.2):
    """one_c's answer as the table prints it."""
    lo, u_lo, hi, u_hi = one_c(jets, band)
    if lo > hi:
        return (f"none: {u_lo:.4f} m/s asks for at least {lo:.2f}, {u_hi:.4f} m/s for at most {hi:.2f}")
    return f"{lo:.2f} to {hi:.2f} (set by {u_lo:.4f} and {u_hi:.4f} m/s)"


def table(g, c=None, d_out=D_OUT_16G, relaxed=False, one_frequency=False, spatial=False):
    a0 = 0.5 * D0_MC
    head = ("| U [m/s] | We_d | L/d0 measured | C without gravity | C with gravity | "
            "absolutely unstable to [d0], falling |")
    sep = "|---|---|---|---|---|---|"
    if c is not None:
        head += f" L/d0 at C = {c:g} without / with gravity |"
        sep += "---|"
    lines = [head, sep]
    cs0, csg, flats, fallings = [], [], [], []
    for u, l_d0 in read_mc():
        we = RHO * u * u * D0_MC / SIGMA
        u_j, a_j = u, a0
        if relaxed:
            _x, u_j, d_j = relaxed_exit(u, D0_MC)
            a_j = 0.5 * d_j
        # without gravity one frequency's N is the fastest rate's (the module's docstring)
        flat, falling = Jet(u_j, a_j, 0.0), Jet(u_j, a_j, g, one_frequency=one_frequency, spatial=spatial)
        flats.append((u, l_d0 * D0_MC, flat))
        fallings.append((u, l_d0 * D0_MC, falling))
        c0 = flat.exponent(l_d0 * D0_MC)
        cg = falling.exponent(l_d0 * D0_MC)
        cs0.append(c0)
        csg.append(cg)
        reach = unstable_reach(u_j, 2.0 * a_j, g) / D0_MC   # the plug the jet leaves as
        row = f"| {u:.4f} | {we:.2f} | {l_d0:.2f} | {c0:.2f} | {cg:.2f} | {reach:.1f} |"
        if c is not None:
            row += f" {flat.length(c) / D0_MC:.1f} / {falling.length(c) / D0_MC:.1f} |"
        lines.append(row)

    def spread(cs):
        m = sum(cs) / len(cs)
        sd = math.sqrt(sum((x - m) ** 2 for x in cs) / len(cs))
        return f"mean {m:.2f}, std {sd:.2f}, {min(cs):.2f}-{max(cs):.2f}"

    lines.append("")
    picture = ("the frequency that has grown most at its spatial rate" if spatial and g > 0
               else "the frequency that has grown most" if one_frequency and g > 0 else "the fastest local rate")
    lines.append(f"C = ln(a/delta0) the measured lengths ask for (g = {g:g} m/s^2 along the jet; N of {picture}):")
    lines.append(f"  without gravity: {spread(cs0)}")
    lines.append(f"  with gravity:    {spread(csg)}")
    lines.append("One C that puts every measured length within 20% (N(0.8 L) <= C <= N(1.2 L) at every speed):")
    lines.append(f"  without gravity: {one_c_line(flats)}")
    lines.append(f"  with gravity:    {one_c_line(fallings)}")
    if g > 0:
        lines.append("")
        lines.append(f"Dripping or jetting (Clanet & Lasheras 1999, K = {K_CL:g}): a tube jets above We_c")
        speeds = [u for u, _ in read_mc()]
        for what, dout in (("rim at the jet's edge (d_out = d0, no tube wall)", D0_MC),
                           (f"d_out = {d_out * 1e3:.3f} mm", d_out)):
            wc = critical_weber(D0_MC, dout, g)
            drip = [f"{u:.4f}" for u in speeds if RHO * u * u * D0_MC / SIGMA < wc]
            lines.append(f"  {what}: We_c = {wc:.2f}; measured speeds below it: "
                         f"{', '.join(drip) if drip else 'none'}")
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--g", type=float, default=G_FALL, help=f"gravity along the jet [m/s^2] (default {G_FALL:g})")
    ap.add_argument("--c", type=float, default=None, help="also print the lengths this ln(a/delta0) gives")
    ap.add_argument("--relaxed", action="store_true",
                    help="each jet leaves as the flat plug its tube's parabolic profile relaxes to "
                         "(round_jet_study.py --relaxed-exit: speed and diameter), its growth and its "
                         "pocket of absolute instability from there; lengths still over the tube's d0")
    ap.add_argument("--one-frequency", action="store_true",
                    help="the falling jet's N is that of the frequency that has grown most, each carried "
                         "down at its own frequency (WKB, the module's docstring), not the fastest local rate's")
    ap.add_argument("--spatial", action="store_true",
                    help="as --one-frequency, each frequency grown at its spatial rate (Keller, Rubinow & "
                         "Tu; the module's docstring), not its temporal rate over U; 15-60 s a jet")
    ap.add_argument("--d-out", type=float, default=D_OUT_16G,
                    help=f"the tube's outer diameter [m] for the dripping criterion (default {D_OUT_16G:g})")
    args = ap.parse_args(argv)
    if not args.d_out >= D0_MC:
        ap.error(f"--d-out {args.d_out}: expected at least the bore, {D0_MC:g} m")
    if not args.g >= 0:
        ap.error(f"--g {args.g}: expected >= 0 (along the jet)")
    if args.c is not None and not args.c > 0:
        ap.error(f"--c {args.c}: expected a positive number")
    if args.spatial and args.one_frequency:
        ap.error("--spatial and --one-frequency: expected one of them (--spatial follows each frequency too)")
    print(table(args.g, args.c, args.d_out, args.relaxed, args.one_frequency, args.spatial))
    return 0


if __name__ == "__main__":
    sys.exit(main())
