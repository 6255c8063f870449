// The derived quantities of the case format (config/case_derived.hpp, config/modern_case.hpp).
#include "config/case_derived.hpp"

#include <cmath>

#include "config/modern_case.hpp"

namespace sphjet {

double tait_B_from_c0(double rho0, double c0, double gamma) { return rho0 * c0 * c0 / gamma; }

double tait_B_from_coef(double coef, double rho0, double g, double h_swl, double gamma) {
    return coef * coef * rho0 * g * h_swl / gamma;
}

double alpha_from_nu(double nu, double h, double c0) { return 8.0 * nu / (h * c0); }

namespace {

double f32(double v) { return static_cast<double>(static_cast<float>(v)); }

}  // namespace

double tait_B_from_coef_single(double coef, double rho0, double g, double h_swl, double gamma) {
    const float c = static_cast<float>(coef);
    float b = c * c;
    b = b * static_cast<float>(rho0);
    b = b * static_cast<float>(g);
    b = b * static_cast<float>(h_swl);
    b = b / static_cast<float>(gamma);
    return b;
}

double h_from_coefficient(double coefficient, double dx, double dz, bool single) {
    const double root = std::sqrt(dx * dx + dz * dz);
    return single ? f32(f32(coefficient) * root) : coefficient * root;
}


}  // namespace sphjet
