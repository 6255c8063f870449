// Grid-occupancy overlap of two particle sets: how much of the fluid region they share.
#pragma once

#include <cstddef>

#include "analysis/selection.hpp"

namespace sphjet::analysis {

struct Overlap {
    std::size_t both = 0;    // cells holding fluid of both sets
    std::size_t either = 0;  // cells holding fluid of at least one set
    std::size_t only_a = 0, only_b = 0;
    // both / either: 1 for identical footprints, 0 for disjoint ones (1 when both are empty).
    [[nodiscard]] double ratio() const {
        return either == 0 ? 1.0 : static_cast<double>(both) / static_cast<double>(either);
    }
};

// Square cells of side `cell` (the project uses 2 dx), anchored at (0, 0): cell (i, k) is
// [i c, (i+1) c) x [k c, (k+1) c). Throws std::invalid_argument for cell <= 0.
[[nodiscard]] Overlap grid_overlap(const ParticleSet& a, const ParticleSet& b, double cell,
                                   const Bounds& bounds = {});

}  // namespace sphjet::analysis
