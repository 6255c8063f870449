#include "config/params.hpp"

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

std::string to_string(RingsCurvature c) {
    switch (c) {
        case RingsCurvature::NeighbourMean: return "neighbour_mean";
        case RingsCurvature::Own: return "own";
    }
    return "unknown";
}

std::string to_string(AxisPair a) {
    switch (a) {
        case AxisPair::SmoothedRadius: return "smoothed_radius";
        case AxisPair::Rings: return "rings";
    }
    return "unknown";
}

}  // namespace sphjet
