#include "analysis/overlap.hpp"

#include <stdexcept>
#include <unordered_set>

#include "analysis/cell_grid.hpp"

namespace sphjet::analysis {

namespace {
using Cells = std::unordered_set<detail::CellIndex, detail::CellHash>;

Cells occupied(const ParticleSet& ps, double cell, const Bounds& bounds) {
    Cells cells;
    for (std::size_t i = 0; i < ps.size(); ++i)
        if (selected(ps, i, bounds)) cells.insert(detail::cell_of(ps.x[i], ps.z[i], cell));
    return cells;
}
}  // namespace

Overlap grid_overlap(const ParticleSet& a, const ParticleSet& b, double cell, const Bounds& bounds) {
    if (!(cell > 0.0)) throw std::invalid_argument("grid_overlap: cell size must be positive");
    const Cells ca = occupied(a, cell, bounds);
    const Cells cb = occupied(b, cell, bounds);
    Overlap o;
    for (const auto& c : ca) (cb.count(c) ? o.both : o.only_a)++;
    o.only_b = cb.size() - o.both;
    o.either = o.both + o.only_a + o.only_b;
    return o;
}

}  // namespace sphjet::analysis
