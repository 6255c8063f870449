// Pair forces conserve momentum: for a random cloud of fluid particles (random velocities and
// densities, so pressure, artificial or laminar viscosity and the tensile term all act),
// sum_a m_a a_a = 0 to round-off, and so does sum_a drho_a/dt V_a... (mass is conserved by
// construction: masses are constant). Also checks that rates do not depend on the thread count.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core_fixture.hpp"

using sphjet_test::CoreParticles;
using sphjet_test::compute_rates;

namespace {

CoreParticles cloud(unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> pos(0, 0.2), vel(-1, 1), drho(-5, 5);
    CoreParticles ps;
    const double dx = 0.01;
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j)
            ps.add(i * dx + 0.3 * dx * (pos(rng) / 0.2 - 0.5), j * dx + 0.3 * dx * (pos(rng) / 0.2 - 0.5),
                   vel(rng), vel(rng), 1000 + drho(rng), 1000 * dx * dx, 2);
    return ps;
}

}  // namespace

class CorePairs : public ::testing::TestWithParam<std::tuple<int, int, int>> {};

TEST_P(CorePairs, MomentumIsConserved) {
    const auto [kernel, visc, tensile] = GetParam();
    auto ps = cloud(7);
    auto prm = sphjet_test::water_params(kernel, 1.3 * 0.01);
    prm.viscosity.model = visc;
    prm.viscosity.value = visc == 1 ? 0.3 : 1e-3;
    prm.numerics.tensile = tensile;
    const double vmax = compute_rates(ps, prm);
    double px = 0, pz = 0, scale = 0;
    for (std::size_t i = 0; i < ps.x.size(); ++i) {
        px += ps.m[i] * ps.ax[i];
        pz += ps.m[i] * ps.az[i];
        scale += ps.m[i] * std::hypot(ps.ax[i], ps.az[i]);
    }
    ASSERT_GT(scale, 0.0);
    // Each pair adds equal and opposite terms; round-off of N ~ 400 sums: 1e-12 of the total.
    EXPECT_LT(std::abs(px), 1e-12 * scale);
    EXPECT_LT(std::abs(pz), 1e-12 * scale);
    EXPECT_GT(vmax, 0.0);
}

INSTANTIATE_TEST_SUITE_P(KernelsAndViscosity, CorePairs,
                         ::testing::Combine(::testing::Values(1, 2, 3, 5), ::testing::Values(1, 2),
                                            ::testing::Values(0, 1)));

// A step of a small case runs on fewer threads than set: one per 400 particles, at least one,
// never more than set (sph_threads_for, what the run log and the bench report).
TEST(CorePairsThreads, SmallCasesUseFewerThreads) {
    const int old = sph_get_threads();
    sph_set_threads(2);
    EXPECT_EQ(sph_threads_for(0), 1);
    EXPECT_EQ(sph_threads_for(799), 1);
    EXPECT_EQ(sph_threads_for(800), 2);
    EXPECT_EQ(sph_threads_for(1000000), 2);
    sph_set_threads(1);
    EXPECT_EQ(sph_threads_for(1000000), 1);
    sph_set_threads(old);
}

// The traversal gives each particle its contributions in a fixed order: rates are bitwise the
// same with 1 and 2 threads.
TEST(CorePairsThreads, RatesIndependentOfThreadCount) {
    auto a = cloud(3), b = cloud(3);
    auto arr_a = a.bind(), arr_b = b.bind();
    auto prm = sphjet_test::water_params(5, 0.013);
    ASSERT_EQ(sph_prepare(&prm, &arr_a), SPH_OK);
    ASSERT_EQ(sph_prepare(&prm, &arr_b), SPH_OK);
    void* ws = sph_workspace_create();
    double v1 = 0, v2 = 0;
    const int old = sph_get_threads();
    sph_set_threads(1);
    ASSERT_EQ(sph_compute_rates(ws, &prm, &arr_a, &v1), SPH_OK);
    sph_set_threads(2);
    ASSERT_EQ(sph_compute_rates(ws, &prm, &arr_b, &v2), SPH_OK);
    sph_set_threads(old);
    sph_workspace_destroy(ws);
    EXPECT_EQ(v1, v2);
    for (std::size_t i = 0; i < a.ax.size(); ++i) {
        ASSERT_EQ(a.ax[i], b.ax[i]) << i;
        ASSERT_EQ(a.az[i], b.az[i]) << i;
        ASSERT_EQ(a.ar[i], b.ar[i]) << i;
    }
}

// numerics.artificial_alpha (rates.f90): with laminar viscosity, Monaghan's Pi is added as it
// is, so that the accelerations of laminar + alpha less those of laminar alone are those of
// the artificial viscosity alpha less the artificial viscosity 0 (the pressure cancels in both
// differences), on the random cloud, to round-off: 1e-12 of the largest artificial term (each
// particle's sums hold a few dozen pair terms; the differences agree to 1e-13 of it).
// The density rates do not move: Pi enters the momentum equation only.
TEST(CorePairsArtificialAlpha, AddsThePiTermToTheLaminarViscosity) {
    const auto cloud_rates = [](int model, double value, double extra) {
        auto ps = cloud(11);
        auto prm = sphjet_test::water_params(5, 1.3 * 0.01);
        prm.viscosity.model = model;
        prm.viscosity.value = value;
        prm.viscosity.artificial_alpha = extra;
        (void)compute_rates(ps, prm);
        return ps;
    };
    const auto lam = cloud_rates(2, 1e-3, 0.0);
    const auto both = cloud_rates(2, 1e-3, 0.1);
    const auto art = cloud_rates(1, 0.1, 0.0), art0 = cloud_rates(1, 0.0, 0.0);
    double big = 0;
    for (std::size_t i = 0; i < art.x.size(); ++i)
        big = std::max(big, std::hypot(art.ax[i] - art0.ax[i], art.az[i] - art0.az[i]));
    ASSERT_GT(big, 0.0);
    for (std::size_t i = 0; i < art.x.size(); ++i) {
        EXPECT_NEAR(both.ax[i] - lam.ax[i], art.ax[i] - art0.ax[i], 1e-12 * big) << i;
        EXPECT_NEAR(both.az[i] - lam.az[i], art.az[i] - art0.az[i], 1e-12 * big) << i;
        EXPECT_EQ(both.ar[i], lam.ar[i]) << i;
    }
}
