#include "model/params.hpp"

#include <cmath>

#include <fmt/format.h>

namespace sphjet {

double SimParams::c0() const { return std::sqrt(gamma * B / rho0); }

std::string initial_step_note(const SimParams& p) {
    const double c0 = p.c0();
    if (!(c0 > 0.0) || !(p.h > 0.0) || !(p.cfl > 0.0)) return {};
    const double cfl_step = p.cfl * p.h / c0;
    if (!(p.dt > cfl_step)) return {};
    if (p.variable_dt)
        return fmt::format("note: the first step takes time.dt = {:.6g} s, {:.3g} times the CFL "
                           "step cfl h / c0 = {:.3g} s of the fluid at rest (as legacy SPHysics; "
                           "the steps after it are the CFL's); a case refined from a coarser one "
                           "needs its time.dt scaled with the spacing",
                           p.dt, p.dt / cfl_step, cfl_step);
    return fmt::format("note: time.dt = {:.6g} s, fixed for the whole run (variable_dt = false), "
                       "is {:.3g} times the CFL step cfl h / c0 = {:.3g} s of the fluid at rest",
                       p.dt, p.dt / cfl_step, cfl_step);
}

bool SimParams::tensile_on() const {
    if (tensile_correction >= 0) return tensile_correction == 1;
    return kernel == KernelType::CubicSpline || kernel == KernelType::CubicSplineTC ||
           kernel == KernelType::Gaussian;
}

}  // namespace sphjet
