// Jet breakup: the intact length along the jet axis, and the droplets (connected clusters).
// Two fluid particles are connected when they are at most `link` apart (the project uses
// link = 1.5 h).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "analysis/selection.hpp"

namespace sphjet::analysis {

// The jet axis: the nozzle exit (x0, z0) and the flow direction (need not be unit length).
struct Axis {
    double x0 = 0.0, z0 = 0.0;
    double dir_x = 1.0, dir_z = 0.0;
};

// Breakup length: the fluid particles within `band` (perpendicular distance) of the axis and
// downstream of the origin (axial coordinate s >= 0) are sorted by s; at the first gap between
// consecutive particles larger than `link`, the breakup length is the s of the particle before
// the gap (its distance from the origin along the axis). None when the band holds no particle
// or no gap exists (the jet is intact). Throws std::invalid_argument for a zero direction or
// non-positive band / link.
[[nodiscard]] std::optional<double> breakup_length(const ParticleSet& ps, const Axis& axis, double band,
                                                   double link, const Bounds& bounds = {});

struct Cluster {
    std::size_t size = 0;        // particles
    double xc = 0.0, zc = 0.0;   // centroid (plain mean of positions) [m]
};

// Connected components of the selected fluid particles with links of length <= `link`, found
// with a cell grid of cell size `link`. Clusters are sorted by size (largest first; ties by
// centroid x, then z). When `labels` is given it receives, per particle, the index of its
// cluster in the returned vector, or -1 for particles not selected.
[[nodiscard]] std::vector<Cluster> label_clusters(const ParticleSet& ps, double link,
                                                  const Bounds& bounds = {},
                                                  std::vector<int>* labels = nullptr);

}  // namespace sphjet::analysis
