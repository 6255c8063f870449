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
// The predictor-corrector the same way, with the ring at r = 0.05 dx: it crosses in the
// predictor's half step (to r = -0.05 dx), and the corrector's rates, which the step leaves in
// the state, must be those of the half-step state reflected, ((x + xo)/2, (u + uo)/2) of the
// state after the step, the ring at r = 0.05 dx moving out; the step leaves it at 0.15 dx.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core_fixture.hpp"

using sphjet_test::CoreParticles;

namespace {

constexpr double kDx = 1e-4, kRho0 = 1000, kSpeed = 0.5, kDt = 4e-5;
constexpr std::size_t kRing = 5;   // column 0, row 5

// The lattice at rest with ring kRing at r = r0 running to the axis at kSpeed, and its params.
CoreParticles lattice(double r0) {
    CoreParticles ps;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 10; ++j) {
            const double r = (i + 0.5) * kDx, z = (j + 0.5) * kDx;
            const double m = 2 * std::numbers::pi * r * kRho0 * kDx * kDx;
            const bool crossing = i == 0 && j == 5;
            ps.add(crossing ? r0 : r, z, crossing ? -kSpeed : 0.0, 0.0, kRho0, m, 2);
        }
    return ps;
}

sph_params_t params(int integrator) {
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
    prm.numerics.integrator = integrator;
    prm.time_step.variable_dt = 0;
    return prm;
}

void one_step(CoreParticles& ps, const sph_params_t& prm) {
    auto arr = ps.bind();
    sph_params_t p = prm;
    ASSERT_EQ(sph_prepare(&p, &arr), SPH_OK);
    void* ws = sph_workspace_create();
    sph_step_info_t info{};
    info.dt = kDt;
    ASSERT_EQ(sph_step(ws, &p, &arr, &info), SPH_OK);
    sph_workspace_destroy(ws);
}

// Every ring's density rate in ps against a fresh evaluation of `state`, within 1e-6 of the
// largest.
void expect_rates_of(const CoreParticles& ps, CoreParticles state, const sph_params_t& prm) {
    sphjet_test::compute_rates(state, prm);
    double most = 0;
    for (const double a : state.ar) most = std::max(most, std::abs(a));
    ASSERT_GT(most, 0);
    for (std::size_t q = 0; q < ps.ar.size(); ++q)
        EXPECT_NEAR(ps.ar[q], state.ar[q], 1e-6 * most) << "ring " << q << (q == kRing ? " (the crossing one)" : "");
}

}  // namespace

TEST(CoreAxisCrossing, LeapfrogKeepsTheRatesOfTheReflectedRing) {
    CoreParticles ps = lattice(0.1 * kDx);
    const sph_params_t prm = params(2);
    one_step(ps, prm);
    ASSERT_NEAR(ps.x[kRing], 0.1 * kDx, 1e-6 * kDx) << "the ring crossed and was reflected";
    ASSERT_NEAR(ps.u[kRing], kSpeed, 1e-6 * kSpeed);
    expect_rates_of(ps, ps, prm);
}

TEST(CoreAxisCrossing, CorrectorEvaluatesTheReflectedRing) {
    CoreParticles ps = lattice(0.05 * kDx);
    const sph_params_t prm = params(1);
    one_step(ps, prm);
    ASSERT_NEAR(ps.x[kRing], 0.15 * kDx, 1e-6 * kDx);
    ASSERT_NEAR(ps.u[kRing], kSpeed, 1e-6 * kSpeed);
    CoreParticles half = ps;
    for (std::size_t q = 0; q < half.x.size(); ++q) {
        half.x[q] = 0.5 * (ps.x[q] + ps.xo[q]);
        half.z[q] = 0.5 * (ps.z[q] + ps.zo[q]);
        half.u[q] = 0.5 * (ps.u[q] + ps.uo[q]);
        half.w[q] = 0.5 * (ps.w[q] + ps.wo[q]);
    }
    ASSERT_NEAR(half.x[kRing], 0.05 * kDx, 1e-6 * kDx) << "the half step's ring, reflected";
    expect_rates_of(ps, half, prm);
}
