// The case format's derived numbers shared by its reader and writer (config/modern_case.hpp
// declares the public ones).
#pragma once

#include <utility>

namespace sphjet {

// SPHYSICSgen_2D's arithmetic (single precision, left to right); the same numbers as
// read_legacy_case (config/legacy_case.cpp) for rho0 = 1000, g = 9.81, gamma = 7.
[[nodiscard]] double tait_B_from_coef_single(double coef, double rho0, double g, double h_swl, double gamma);
// h = coefficient sqrt(dx^2 + dz^2), in single precision as SPHYSICSgen_2D when single.
[[nodiscard]] double h_from_coefficient(double coefficient, double dx, double dz, bool single);

// The jet direction (ex, ez) of each of nozzle.axis's choices, by their numbers
// (model/case_params.cpp).
inline constexpr std::pair<double, double> kNozzleDirections[] = {
    {0.0, -1.0}, {0.0, 1.0}, {-1.0, 0.0}, {1.0, 0.0}};

}  // namespace sphjet
