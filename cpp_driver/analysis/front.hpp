// Surge front and highest point: the dam-break measures of Martin & Moyce and of the
// obstacle case (legacy front.txt). All look only at selected particles (selection.hpp).
#pragma once

#include <cstddef>
#include <limits>
#include <optional>

#include "analysis/selection.hpp"

namespace sphjet::analysis {

// Surge front: the largest x of the fluid with z < z_below (the whole fluid by default).
// Legacy front.txt: xfront_all (no limit), xfront_floor (z < 2 dx), xfront_floor4 (z < 4 dx).
// None when no particle qualifies.
[[nodiscard]] std::optional<double> surge_front(
    const ParticleSet& ps, const Bounds& bounds = {},
    double z_below = std::numeric_limits<double>::infinity());

// The highest fluid point over the x-range [x0, x1] (closed) and how many fluid particles lie
// in that range (at any height). Legacy front.txt: zmax_obst / n_obst with [x0, x1] the
// obstacle's extent. z is none when count is 0.
struct HighestPoint {
    std::optional<double> z;
    std::size_t count = 0;
};
[[nodiscard]] HighestPoint highest_over(const ParticleSet& ps, double x0, double x1,
                                        const Bounds& bounds = {});

// The largest z of the fluid with x < x_below (legacy case1 front.txt: h_left, x < 0.1 m).
[[nodiscard]] std::optional<double> column_height(const ParticleSet& ps, double x_below,
                                                  const Bounds& bounds = {});

// Count of fluid particles that are not selected: removed (inactive) or outside the bounds.
[[nodiscard]] std::size_t fluid_out(const ParticleSet& ps, const Bounds& bounds = {});

}  // namespace sphjet::analysis
