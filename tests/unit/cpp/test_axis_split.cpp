// domain.split_axis_rings (Solver::split_heavy_rings, physics/axisymmetric.f90 ring_too_heavy):
// a ring heavier than max(2 x the lattice ring at its radius, 2 x the first column's) becomes
// two of half its mass dz/2 either side of it along the axis.
#include <cmath>
#include <filesystem>
#include <numbers>
#include <numeric>

#include <gtest/gtest.h>

#include "config/load_case.hpp"
#include "core/solver.hpp"
#include "model/errors.hpp"

using namespace sphjet;

namespace {

const std::filesystem::path kSphere =
    std::filesystem::path(SPHJET_SOURCE_DIR) / "cases" / "axisymmetric" / "sphere_oscillation.toml";

struct Totals {
    double m = 0, mz = 0, mu = 0, mw = 0;
};

Totals totals(const ParticleSet& ps) {
    Totals t;
    for (std::size_t i = ps.nb; i < ps.size(); ++i) {
        if (ps.active[i] == 0) continue;
        t.m += ps.m[i], t.mz += ps.m[i] * ps.z[i], t.mu += ps.m[i] * ps.u[i], t.mw += ps.m[i] * ps.w[i];
    }
    return t;
}

}  // namespace

// The sphere as built (every ring at its lattice mass) splits nothing. A ring given five times
// the first column's mass at r = dx/4 (a ring from r = 2.5 dx that reached the axis) splits
// into two of 2.5, then four of 1.25 first-column masses (the limit there is 2), then stops;
// the others are untouched. Mass, axial momentum and centre of mass are kept to round-off
// (1e-12 relative); the quarters keep the ring's radius, velocity and density, at z0 - dz, z0
// (twice) and z0 + dz: each split puts its halves dz/2 either side.
TEST(AxisSplit, HeavyRingNearTheAxisSplitsUntilLightEnough) {
    LoadedCase lc = load_case(kSphere, {"domain.axis_pair=\"rings\"", "resolution.h_over_dx=2.0",
                                        "domain.split_axis_rings=true"});
    const SimParams& p = lc.spec.params;
    Solver s(p, lc.spec.output, lc.particles);
    EXPECT_EQ(s.split_heavy_rings(), 0u);

    const double m1 = std::numbers::pi * p.rho0 * p.dx * p.dx * p.dz;
    ParticleSet& ps = s.particles_to_edit();
    const std::size_t n0 = ps.size(), k = ps.nb + n0 / 2;
    ps.m[k] = 5 * m1;
    ps.x[k] = 0.25 * p.dx;
    ps.u[k] = 0.01, ps.w[k] = -0.02;
    const double z0 = ps.z[k], rho = ps.rho[k];
    const Totals before = totals(ps);

    EXPECT_EQ(s.split_heavy_rings(), 1u);
    EXPECT_EQ(s.split_heavy_rings(), 2u);
    EXPECT_EQ(s.split_heavy_rings(), 0u);
    const ParticleSet& after = s.particles();
    ASSERT_EQ(after.size(), n0 + 3);
    const Totals t = totals(after);
    EXPECT_NEAR(t.m, before.m, 1e-12 * before.m);
    EXPECT_NEAR(t.mz, before.mz, 1e-12 * std::abs(before.mz));
    EXPECT_NEAR(t.mu, before.mu, 1e-12 * before.m * 0.01);
    EXPECT_NEAR(t.mw, before.mw, 1e-12 * before.m * 0.02);
    std::vector<double> zs;
    for (const std::size_t i : {k, n0, n0 + 1, n0 + 2}) {
        EXPECT_NEAR(after.m[i], 1.25 * m1, 1e-12 * m1) << i;
        EXPECT_EQ(after.x[i], 0.25 * p.dx) << i;
        EXPECT_EQ(after.u[i], 0.01) << i;
        EXPECT_EQ(after.w[i], -0.02) << i;
        EXPECT_EQ(after.rho[i], rho) << i;
        EXPECT_EQ(after.active[i], 1) << i;
        zs.push_back(after.z[i] - z0);
    }
    std::sort(zs.begin(), zs.end());
    const double dz = p.dz;
    const std::vector<double> expected{-dz, 0.0, 0.0, dz};  // z0 -+ dz/2, each -+ dz/2 again
    for (std::size_t j = 0; j < 4; ++j) EXPECT_NEAR(zs[j], expected[j], 1e-12 * dz) << j;
}

// The key needs the rings pair: refused otherwise, naming it.
TEST(AxisSplit, NeedsTheRingsPair) {
    try {
        (void)load_case(kSphere, {"domain.split_axis_rings=true"});
        FAIL() << "accepted without the rings pair";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("domain.split_axis_rings"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("axis_pair"), std::string::npos) << e.what();
    }
}
