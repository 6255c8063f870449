#include "analysis/compare.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "analysis/front.hpp"

namespace sphjet::analysis {

std::optional<double> StateDiff::front_rel() const {
    if (!front_ref || !front_test) return std::nullopt;
    const double d = std::fabs(*front_test - *front_ref);
    return *front_ref != 0.0 ? d / std::fabs(*front_ref) : d;
}

StateDiff compare_states(const ParticleSet& ref, const ParticleSet& test, const Bounds& bounds) {
    if (ref.size() != test.size() || ref.nb != test.nb)
        throw std::invalid_argument("the two states hold different particles: " + std::to_string(ref.size()) +
                                    " (nb " + std::to_string(ref.nb) + ") vs " + std::to_string(test.size()) +
                                    " (nb " + std::to_string(test.nb) + ")");
    StateDiff d;
    double sum_pos2 = 0.0, sum_vel2 = 0.0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
        const bool a = selected(ref, i, bounds), b = selected(test, i, bounds);
        if (a && !b) ++d.only_ref;
        if (b && !a) ++d.only_test;
        if (!a || !b) continue;
        ++d.compared;
        const double dp2 = std::pow(test.x[i] - ref.x[i], 2) + std::pow(test.z[i] - ref.z[i], 2);
        const double dv2 = std::pow(test.u[i] - ref.u[i], 2) + std::pow(test.w[i] - ref.w[i], 2);
        sum_pos2 += dp2;
        sum_vel2 += dv2;
        d.max_pos = std::max(d.max_pos, std::sqrt(dp2));
        d.max_vel = std::max(d.max_vel, std::sqrt(dv2));
        if (ref.rho[i] != 0.0) d.max_rel_rho = std::max(d.max_rel_rho, std::fabs(test.rho[i] - ref.rho[i]) / std::fabs(ref.rho[i]));
    }
    if (d.compared > 0) {
        d.rms_pos = std::sqrt(sum_pos2 / static_cast<double>(d.compared));
        d.rms_vel = std::sqrt(sum_vel2 / static_cast<double>(d.compared));
    }
    d.front_ref = surge_front(ref, bounds);
    d.front_test = surge_front(test, bounds);
    return d;
}

}  // namespace sphjet::analysis
