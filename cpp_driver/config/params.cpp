#include "config/params.hpp"

#include <cmath>

namespace sphjet {

double SimParams::c0() const { return std::sqrt(gamma * B / rho0); }

bool SimParams::tensile_on() const {
    if (tensile_correction >= 0) return tensile_correction == 1;
    return kernel == KernelType::CubicSpline || kernel == KernelType::Gaussian;
}

std::string to_string(KernelType k) {
    switch (k) {
        case KernelType::Gaussian: return "gaussian";
        case KernelType::Quadratic: return "quadratic";
        case KernelType::CubicSpline: return "cubic_spline";
        case KernelType::Wendland: return "wendland";
    }
    return "unknown";
}

std::string to_string(DensityFilter f) {
    switch (f) {
        case DensityFilter::None: return "none";
        case DensityFilter::Shepard: return "shepard";
        case DensityFilter::MLS: return "mls";
    }
    return "unknown";
}

std::string to_string(ViscosityModel v) {
    switch (v) {
        case ViscosityModel::Artificial: return "artificial";
        case ViscosityModel::Laminar: return "laminar";
    }
    return "unknown";
}

std::string to_string(BoundaryType b) {
    switch (b) {
        case BoundaryType::Repulsive: return "repulsive";
        case BoundaryType::Dynamic: return "dynamic";
    }
    return "unknown";
}

std::string to_string(SurfaceTensionDelta d) {
    switch (d) {
        case SurfaceTensionDelta::PressureConsistent: return "pressure_consistent";
        case SurfaceTensionDelta::ColourGradient: return "colour_gradient";
    }
    return "unknown";
}

std::string to_string(Geometry g) {
    switch (g) {
        case Geometry::Planar: return "planar";
        case Geometry::Axisymmetric: return "axisymmetric";
    }
    return "unknown";
}

}  // namespace sphjet
