// A fixed step against the step the CFL and force conditions give (Solver::fixed_step_record,
// the line a fixed-step run ends its run.log with): over the steps a Solver takes with
// time.variable_dt = false, how many took more than that step (RunState::dt_new after each)
// and the smallest of those; nothing is recorded with the variable step, nor by the
// predictor-corrector, which with a fixed step evaluates no CFL step (as legacy SPHysics).
// And the variable step's cap time.dt_max (time_step.f90 capped_step).
#include <algorithm>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "config/load_case.hpp"
#include "core/solver.hpp"
#include "model/errors.hpp"

using namespace sphjet;

namespace {

const std::filesystem::path kSphere =
    std::filesystem::path(SPHJET_SOURCE_DIR) / "cases" / "axisymmetric" / "sphere_oscillation.toml";

// The leapfrog (which needs the bulk viscosity) with a fixed step dt [s].
LoadedCase leapfrog_fixed(double dt) {
    return load_case(kSphere, {"numerics.integrator=leapfrog", "numerics.bulk_viscosity=0.5",
                               "time.variable_dt=false", fmt::format("time.dt={:.17g}", dt)});
}

// The CFL step cfl h / c0 of the case's fluid at rest [s].
double rest_step() {
    const SimParams p = load_case(kSphere, {}).spec.params;
    return p.cfl * p.h / p.c0();
}

}  // namespace

// Half the CFL step at rest: three steps, none above, the smallest CFL step the least of the
// three RunState::dt_new (compared exactly: the record keeps that value) and above the step.
// Four times it: the one step taken is above.
TEST(FixedStep, RecordsTheStepsAboveTheCflStep) {
    const double dt = 0.5 * rest_step();
    LoadedCase lc = leapfrog_fixed(dt);
    Solver s(lc.spec.params, lc.spec.output, lc.particles);
    double smallest = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        (void)s.step(false);
        smallest = std::min(smallest, s.state().dt_new);
    }
    EXPECT_EQ(s.fixed_step_record().steps, 3);
    EXPECT_EQ(s.fixed_step_record().above, 0);
    EXPECT_EQ(s.fixed_step_record().smallest, smallest);
    EXPECT_GT(smallest, s.state().dt);

    LoadedCase big = leapfrog_fixed(4.0 * rest_step());
    Solver b(big.spec.params, big.spec.output, big.particles);
    (void)b.step(false);
    EXPECT_EQ(b.fixed_step_record().steps, 1);
    EXPECT_EQ(b.fixed_step_record().above, 1);
    EXPECT_LT(b.fixed_step_record().smallest, b.state().dt);
}

TEST(FixedStep, NothingWithTheVariableStepOrThePredictorCorrector) {
    for (const auto& sets : {std::vector<std::string>{"numerics.integrator=leapfrog", "numerics.bulk_viscosity=0.5"},
                             std::vector<std::string>{"time.variable_dt=false",
                                                      fmt::format("time.dt={:.17g}", 0.5 * rest_step())}}) {
        LoadedCase lc = load_case(kSphere, sets);
        Solver s(lc.spec.params, lc.spec.output, lc.particles);
        (void)s.step(false);
        (void)s.step(false);
        EXPECT_EQ(s.fixed_step_record().steps, 0) << sets[0];
        EXPECT_EQ(s.fixed_step_record().above, 0) << sets[0];
    }
}

// A cap below the CFL step: every step after the first (which takes time.dt) takes the cap,
// exactly, while the CFL step (RunState::dt_new) stays above it, in the leapfrog and the
// predictor-corrector. A cap above every CFL step changes nothing: the same states, bitwise.
TEST(StepCap, HoldsTheVariableStepBelowTheCflStep) {
    const double cap = 0.5 * rest_step();
    for (const char* integrator : {"leapfrog", "predictor_corrector"}) {
        LoadedCase lc = load_case(kSphere, {fmt::format("numerics.integrator={}", integrator),
                                            "numerics.bulk_viscosity=0.5", fmt::format("time.dt_max={:.17g}", cap)});
        Solver s(lc.spec.params, lc.spec.output, lc.particles);
        for (int k = 0; k < 4; ++k) {
            (void)s.step(false);
            EXPECT_EQ(s.state().dt, cap) << integrator << " step " << k;
            EXPECT_GT(s.state().dt_new, cap) << integrator << " step " << k;
        }
    }
    LoadedCase a = load_case(kSphere, {fmt::format("time.dt_max={:.17g}", 10.0 * rest_step())});
    LoadedCase b = load_case(kSphere, {});
    Solver sa(a.spec.params, a.spec.output, a.particles), sb(b.spec.params, b.spec.output, b.particles);
    for (int k = 0; k < 4; ++k) (void)sa.step(false), (void)sb.step(false);
    EXPECT_EQ(sa.state().dt, sb.state().dt);
    EXPECT_EQ(sa.particles().x, sb.particles().x);
    EXPECT_EQ(sa.particles().rho, sb.particles().rho);
}

// A cap with a fixed step is refused, naming the key.
TEST(StepCap, RefusedWithAFixedStep) {
    try {
        (void)load_case(kSphere, {"time.variable_dt=false", "time.dt_max=1e-6"});
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("time.dt_max"), std::string::npos) << what;
        EXPECT_NE(what.find("time.variable_dt = false"), std::string::npos) << what;
    }
}
