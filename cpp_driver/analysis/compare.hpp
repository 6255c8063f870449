// Differences between two states of the same particles (legacy vs ours, or two of our runs):
// particles are matched by index (both in legacy order), and only fluid particles active in
// both are compared.
#pragma once

#include <cstddef>
#include <optional>

#include "analysis/selection.hpp"

namespace sphjet::analysis {

struct StateDiff {
    std::size_t compared = 0;            // fluid particles active (and in bounds) in both
    std::size_t only_ref = 0;            // selected in ref but not in test (removed in test)
    std::size_t only_test = 0;           // selected in test but not in ref
    double rms_pos = 0.0, max_pos = 0.0; // |r_test - r_ref| [m]
    double rms_vel = 0.0, max_vel = 0.0; // |v_test - v_ref| [m/s]
    double max_rel_rho = 0.0;            // max |rho_test - rho_ref| / rho_ref
    std::optional<double> front_ref, front_test;  // surge front (max x of the selected fluid)
    // |front_test - front_ref| / |front_ref|; none when either front is missing.
    [[nodiscard]] std::optional<double> front_rel() const;
};

// Throws std::invalid_argument when the sets differ in size or boundary count.
[[nodiscard]] StateDiff compare_states(const ParticleSet& ref, const ParticleSet& test,
                                       const Bounds& bounds = {});

}  // namespace sphjet::analysis
