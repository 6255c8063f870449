// Which particles an analysis looks at: fluid (kind 2), active, inside a box.
#pragma once

#include <cstddef>
#include <limits>

#include "model/particles.hpp"

namespace sphjet::analysis {

// A closed box [xmin, xmax] x [zmin, zmax]; the default holds everything.
struct Bounds {
    double xmin = -std::numeric_limits<double>::infinity();
    double xmax = std::numeric_limits<double>::infinity();
    double zmin = -std::numeric_limits<double>::infinity();
    double zmax = std::numeric_limits<double>::infinity();

    [[nodiscard]] bool contains(double x, double z) const {
        return x >= xmin && x <= xmax && z >= zmin && z <= zmax;
    }
};

// Particle i is analysed: fluid, active (not removed) and inside the bounds.
[[nodiscard]] inline bool selected(const ParticleSet& ps, std::size_t i, const Bounds& b) {
    return ps.kind[i] == static_cast<int>(ParticleKind::Fluid) &&
           (ps.active.empty() || ps.active[i] != 0) && b.contains(ps.x[i], ps.z[i]);
}

}  // namespace sphjet::analysis
