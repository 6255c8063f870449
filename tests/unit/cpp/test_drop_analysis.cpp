// analysis/drop: the measures of a free drop on particle sets whose answers are known.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/drop.hpp"
#include "geometry/generator.hpp"
#include "model/case_spec.hpp"

using sphjet::ParticleKind;
using sphjet::ParticleSet;
namespace an = sphjet::analysis;

namespace {

constexpr double pi = std::numbers::pi;

// Ring disc (centre particle + rings j dx, round(2 pi j) particles each, annulus masses):
// its area is exactly pi ((nr + 1/2) dx)^2 at rho = 1000. Pressure p_in everywhere.
ParticleSet ring_disc(int nr, double dx, double xc, double zc, double p_in,
                      std::vector<double>* kappa = nullptr) {
    ParticleSet ps;
    ps.push(xc, zc, 0, 0, 1000, p_in, 1000 * pi * 0.25 * dx * dx, ParticleKind::Fluid);
    if (kappa) kappa->push_back(0);
    for (int j = 1; j <= nr; ++j) {
        const int nj = static_cast<int>(std::lround(2 * pi * j));
        for (int k = 0; k < nj; ++k) {
            const double th = 2 * pi * (k + 0.5 * (j % 2)) / nj;
            ps.push(xc + j * dx * std::cos(th), zc + j * dx * std::sin(th), 0, 0, 1000, p_in,
                    1000 * 2 * pi * j * dx * dx / nj, ParticleKind::Fluid);
            if (kappa) kappa->push_back(-1.0 / (j * dx));
        }
    }
    return ps;
}

}  // namespace

TEST(DropAnalysis, RingDiscAreaOutlinePressureCurvature) {
    const int nr = 20;
    const double dx = 0.001, R = (nr + 0.5) * dx;
    std::vector<double> kappa;
    ParticleSet ps = ring_disc(nr, dx, 0.3, 0.2, 50.0, &kappa);
    ps.u[5] = 0.003;  // one moving particle
    const auto m = an::measure_drop(ps, kappa);
    EXPECT_NEAR(m.area, pi * R * R, 1e-12 * pi * R * R);
    EXPECT_NEAR(m.r_eq, R, 1e-12);
    EXPECT_NEAR(m.xc, 0.3, 1e-12);
    EXPECT_NEAR(m.zc, 0.2, 1e-12);
    // the outermost ring is a circle of radius nr dx
    EXPECT_NEAR(m.r_max, nr * dx, 1e-12);
    EXPECT_NEAR(m.r_min, nr * dx, 1e-12);
    EXPECT_NEAR(m.p_inner.mean, 50.0, 1e-12);
    EXPECT_NEAR(m.p_surface.mean, 50.0, 1e-12);
    // surface = the outer ring only (the next ring lies a full spacing inside)
    EXPECT_EQ(m.p_surface.n, static_cast<std::size_t>(std::lround(2 * pi * nr)));
    ASSERT_TRUE(m.kappa_surface.has_value());
    EXPECT_NEAR(m.kappa_surface->mean, -1.0 / (nr * dx), 1e-9);
    EXPECT_NEAR(m.speed_max, 0.003, 1e-15);
    // Every ring holds n >= 6 equally spaced particles, for which sum cos^2 = sum sin^2 = n/2
    // and sum sin cos = 0 exactly: the second moments are isotropic and D = 0 up to the
    // round-off of the sums (measured 2e-16; 1e-12 is far above round-off and far
    // below the 1e-3 a single particle moved by 1% of R gives).
    std::printf("ring disc deformation %.3e\n", m.deformation);
    EXPECT_NEAR(m.deformation, 0.0, 1e-12);
}

// An ellipse x = a cos, z = b sin (uniform filling): D = (a^2 - b^2)/(a^2 + b^2), the
// extents 2a and 2b, and r_max / r_min = a / b, to the lattice resolution.
TEST(DropAnalysis, EllipseDeformationAndOutline) {
    const double a = 0.022, b = 0.018, dx = 0.0002;
    ParticleSet ps;
    for (double x = -a; x <= a; x += dx)
        for (double z = -b; z <= b; z += dx)
            if ((x * x) / (a * a) + (z * z) / (b * b) <= 1.0)
                ps.push(x, z, 0, 0, 1000, 0, 1000 * dx * dx, ParticleKind::Fluid);
    const auto m = an::measure_drop(ps);
    EXPECT_NEAR(m.deformation, (a * a - b * b) / (a * a + b * b), 0.01);
    EXPECT_NEAR(m.extent_x, 2 * a, 2 * dx);
    EXPECT_NEAR(m.extent_z, 2 * b, 2 * dx);
    EXPECT_NEAR(m.r_ratio(), a / b, 0.02);
    EXPECT_NEAR(m.area, pi * a * b, 0.01 * pi * a * b);
}

TEST(DropAnalysis, BoundaryAndInactiveParticlesAreIgnored) {
    ParticleSet ps = ring_disc(5, 0.001, 0, 0, 10.0);
    ParticleSet with;
    with.push(1.0, 1.0, 5, 5, 1000, 999, 1, ParticleKind::FixedBoundary);
    with.nb = with.nbf = 1;
    for (std::size_t i = 0; i < ps.size(); ++i)
        with.push(ps.x[i], ps.z[i], 0, 0, 1000, 10.0, ps.m[i], ParticleKind::Fluid);
    with.push(0.5, 0.5, 9, 9, 1000, 999, 1, ParticleKind::Fluid);
    with.active.back() = 0;
    const auto a = an::measure_drop(ps), b = an::measure_drop(with);
    EXPECT_EQ(a.n_fluid, b.n_fluid);
    EXPECT_DOUBLE_EQ(a.area, b.area);
    EXPECT_DOUBLE_EQ(b.speed_max, 0.0);
    EXPECT_DOUBLE_EQ(b.p_inner.mean, 10.0);
}

TEST(DropAnalysis, NoFluidIsAnError) {
    ParticleSet ps;
    EXPECT_THROW((void)an::measure_drop(ps), std::invalid_argument);
}

// d(t) = 0.05 cos(omega t) exp(-gamma t) + 0.001 sampled every 2 ms: the period within 0.5%
// (zero crossings interpolated linearly) and the decay rate within 5%.
TEST(DropAnalysis, OscillationPeriodAndDecay) {
    const double omega = 27.386, gamma = 1.5, dt = 0.002;
    std::vector<double> t, d;
    for (int k = 0; k <= 600; ++k) {
        t.push_back(k * dt);
        d.push_back(0.05 * std::cos(omega * k * dt) * std::exp(-gamma * k * dt) + 0.001);
    }
    const auto o = an::oscillation(t, d);
    ASSERT_TRUE(o.period.has_value());
    EXPECT_NEAR(*o.period, 2 * pi / omega, 0.005 * 2 * pi / omega);
    ASSERT_TRUE(o.decay_rate.has_value());
    EXPECT_NEAR(*o.decay_rate, gamma, 0.05 * gamma);
    EXPECT_GE(o.crossings, 4u);
}

// A strongly damped oscillation that decays into a small fast ripple (the particle noise of
// a run): the ripple's zero crossings are not the oscillation's. Half-cycles whose extremum is
// below 10% of the first one are dropped, so the period stays that of the cosine (within 1%:
// the ripple, half the noise floor, still moves the last kept crossings a little).
TEST(DropAnalysis, OscillationIgnoresCrossingsInTheNoise) {
    const double omega = 27.386, gamma = 8.0, dt = 0.005;
    std::vector<double> t, d;
    for (int k = 0; k <= 160; ++k) {
        t.push_back(k * dt);
        d.push_back(0.1 * std::cos(omega * k * dt) * std::exp(-gamma * k * dt) +
                    0.002 * std::sin(2 * pi * k * dt / 0.03));
    }
    const auto all = an::oscillation(t, d, 0.0, 0.0);  // no noise floor
    const auto o = an::oscillation(t, d);
    ASSERT_TRUE(o.period.has_value());
    EXPECT_NEAR(*o.period, 2 * pi / omega, 0.01 * 2 * pi / omega);
    EXPECT_LT(o.crossings, all.crossings);
    EXPECT_GE(o.crossings, 3u);
}

TEST(DropAnalysis, TooShortSeriesHasNoPeriod) {
    const std::vector<double> t{0, 1}, d{1, -1};
    const auto o = an::oscillation(t, d);
    EXPECT_FALSE(o.period.has_value());
}

// The drops the surface-tension cases start from (geometry/generator, fluid.disc with
// lattice = "rings"), measured by this analysis: a round ring disc has area pi R^2 to
// round-off, a smooth outline and no deformation; with elongation e it is the ellipse of
// semi-axes R (1 + e), R / (1 + e), area kept, D = ((1+e)^2 - (1+e)^-2) / ((1+e)^2 + (1+e)^-2)
// for a uniform ellipse (to the lattice's discreteness: 2%).
TEST(DropAnalysis, GeneratedRingDiscs) {
    sphjet::CaseSpec spec;
    spec.params.lx = spec.params.lz = 0.1;
    spec.params.dx = spec.params.dz = 0.001;
    spec.params.h = 0.0013;
    spec.params.gz = 0;
    spec.wall_left = spec.wall_right = spec.wall_bottom = false;
    sphjet::FluidDisc d;
    d.xc = d.zc = 0.05;
    d.radius = 0.02;
    d.rings = true;
    spec.fluid_discs = {d};
    const auto round = sphjet::generate(spec);
    const auto m = an::measure_drop(round.particles);
    EXPECT_EQ(m.n_fluid, 1321u);  // 1 + sum_{j=1..20} round(2 pi j)
    EXPECT_NEAR(m.area, pi * 0.02 * 0.02, 1e-12);
    EXPECT_NEAR(m.xc, 0.05, 1e-12);
    EXPECT_LT(m.r_ratio(), 1.01);
    EXPECT_NEAR(m.deformation, 0.0, 1e-12);
    // masses: the centre particle rho pi ds^2 / 4, the rings within 5% of rho ds^2
    const double mds2 = 1000 * std::pow(0.02 / 20.5, 2);
    EXPECT_NEAR(round.particles.m[0] / mds2, pi / 4, 1e-12);
    for (std::size_t i = 1; i < round.particles.size(); ++i)
        EXPECT_NEAR(round.particles.m[i] / mds2, 1.0, 0.05) << "particle " << i;

    const double e = 0.05;
    spec.fluid_discs[0].elongation = e;
    const auto ell = an::measure_drop(sphjet::generate(spec).particles);
    const double a2 = (1 + e) * (1 + e), b2 = 1 / a2;
    EXPECT_NEAR(ell.area, m.area, 1e-12);
    EXPECT_NEAR(ell.deformation, (a2 - b2) / (a2 + b2), 0.02 * (a2 - b2) / (a2 + b2));
    EXPECT_NEAR(ell.extent_x / ell.extent_z, a2, 0.01);
}
