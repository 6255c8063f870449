// The Tait equation of state of a run's parameters, p = B [(rho / rho0)^gamma - 1], both ways:
// the densities the generator gives fluid at a known pressure (a drop's, a cylinder's, a round
// jet's plug at its Laplace pressure) and their pressures.
#pragma once

#include <cmath>

#include "model/params.hpp"

namespace sphjet {

// The density at which the EoS gives the pressure p (rho0 when B = 0 or p = 0).
[[nodiscard]] inline double tait_density(const SimParams& prm, double p) {
    if (!(prm.B > 0) || p == 0) return prm.rho0;
    return prm.rho0 * std::pow(1.0 + p / prm.B, 1.0 / prm.gamma);
}

// The pressure at the density rho (0 when B = 0), the inverse of tait_density.
[[nodiscard]] inline double tait_pressure(const SimParams& prm, double rho) {
    return prm.B > 0 ? prm.B * (std::pow(rho / prm.rho0, prm.gamma) - 1.0) : 0.0;
}

}  // namespace sphjet
