// A fixed step against the step the CFL and force conditions give (Solver::fixed_step_record,
// the line a fixed-step run ends its run.log with): over the steps a Solver takes with
// time.variable_dt = false, how many took more than that step (RunState::dt_new after each)
// and the smallest of those; nothing is recorded with the variable step, nor by the
// predictor-corrector, which with a fixed step evaluates no CFL step (as legacy SPHysics).
#include <algorithm>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "config/load_case.hpp"
#include "core/solver.hpp"

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
