#include "analysis/front.hpp"

#include <algorithm>

namespace sphjet::analysis {

std::optional<double> surge_front(const ParticleSet& ps, const Bounds& bounds, double z_below) {
    std::optional<double> front;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (!selected(ps, i, bounds) || !(ps.z[i] < z_below)) continue;
        front = front ? std::max(*front, ps.x[i]) : ps.x[i];
    }
    return front;
}

HighestPoint highest_over(const ParticleSet& ps, double x0, double x1, const Bounds& bounds) {
    HighestPoint hp;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (!selected(ps, i, bounds) || ps.x[i] < x0 || ps.x[i] > x1) continue;
        ++hp.count;
        hp.z = hp.z ? std::max(*hp.z, ps.z[i]) : ps.z[i];
    }
    return hp;
}

std::optional<double> column_height(const ParticleSet& ps, double x_below, const Bounds& bounds) {
    std::optional<double> h;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (!selected(ps, i, bounds) || !(ps.x[i] < x_below)) continue;
        h = h ? std::max(*h, ps.z[i]) : ps.z[i];
    }
    return h;
}

std::size_t fluid_out(const ParticleSet& ps, const Bounds& bounds) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < ps.size(); ++i)
        if (ps.kind[i] == static_cast<int>(ParticleKind::Fluid) && !selected(ps, i, bounds)) ++n;
    return n;
}

}  // namespace sphjet::analysis
