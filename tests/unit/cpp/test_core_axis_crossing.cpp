// A ring that crosses the axis within a step (fortran_core/integrate/state_checks.f90,
// reflect_at_axis): the step evaluates its rates where the ring is, reflected, not at x < 0,
// where the rings pair took it for an axis image and gave it no pairs.
// The set: 40 rings of the lattice (four columns, ten rows, spacing dx, h = 2 dx) at rest at
// rho0, the rings pair, no viscosity, no XSPH, c0 = 0.01 m/s (so that the pressures a step
// makes move nothing: the largest acceleration times dt is 1e-7 of the speed below), one
// leapfrog step of 4e-5 s (the first, which evaluates the rates at the start too). Ring
// (0, 5), moved to r = 0.1 dx, runs to the axis at 0.5 m/s and crosses it: the step leaves it
// at r = 0.1 dx again, moving out at 0.5 m/s. The leapfrog keeps the rates of its evaluation
// as those of the state it leaves (leapfrog.f90); they must be that state's: every ring's
// density rate within 1e-6 of the largest of a fresh evaluation of the state after the step
// (the velocities the evaluation saw differ from those after the step by the step's
// accelerations, 1e-7). Evaluated at x < 0 the crossing ring's rate was 22% off, and its
// axial force lost.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core_fixture.hpp"

using sphjet_test::CoreParticles;

TEST(CoreAxisCrossing, LeapfrogKeepsTheRatesOfTheReflectedRing) {
    constexpr double kDx = 1e-4, kRho0 = 1000, kSpeed = 0.5, kDt = 4e-5;
    CoreParticles ps;
    const std::size_t ring = 5;   // column 0, row 5
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 10; ++j) {
            const double r = (i + 0.5) * kDx, z = (j + 0.5) * kDx;
            const double m = 2 * std::numbers::pi * r * kRho0 * kDx * kDx;
            const bool crossing = i == 0 && j == 5;
            ps.add(crossing ? 0.1 * kDx : r, z, crossing ? -kSpeed : 0.0, 0.0, kRho0, m, 2);
        }
    sph_params_t prm = sphjet_test::water_params(5, 2 * kDx);
    prm.viscosity.model = 2;
    prm.viscosity.value = 0;
    prm.numerics.xsph_eps = 0;
    prm.numerics.tensile = 0;
    prm.eos.c0 = 0.01;
    prm.eos.b = kRho0 * prm.eos.c0 * prm.eos.c0 / prm.eos.gamma;
    prm.gravity.gz = 0;
    prm.geometry.kind = 1;
    prm.geometry.axis_pair = 1;
    prm.numerics.integrator = 2;
    prm.time_step.variable_dt = 0;
    auto arr = ps.bind();
    ASSERT_EQ(sph_prepare(&prm, &arr), SPH_OK);
    void* ws = sph_workspace_create();
    sph_step_info_t info{};
    info.dt = kDt;
    ASSERT_EQ(sph_step(ws, &prm, &arr, &info), SPH_OK);
    sph_workspace_destroy(ws);
    ASSERT_NEAR(ps.x[ring], 0.1 * kDx, 1e-6 * kDx) << "the ring crossed and was reflected";
    ASSERT_NEAR(ps.u[ring], kSpeed, 1e-6 * kSpeed);

    CoreParticles fresh = ps;
    sphjet_test::compute_rates(fresh, prm);
    double most = 0;
    for (const double a : fresh.ar) most = std::max(most, std::abs(a));
    ASSERT_GT(most, 0);
    for (std::size_t q = 0; q < ps.ar.size(); ++q)
        EXPECT_NEAR(ps.ar[q], fresh.ar[q], 1e-6 * most) << "ring " << q << (q == ring ? " (the crossing one)" : "");
}
