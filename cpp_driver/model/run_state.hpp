// Integrator state that is not per particle: what a checkpoint must hold besides the arrays.
#pragma once

#include <cstdint>

namespace sphjet {

struct RunState {
    double time = 0.0;            // simulated time actually integrated [s]
    double legacy_time = 0.0;     // time as legacy SPHysics counts it (adds the new dt) [s]
    std::int64_t step = 0;        // steps taken
    double dt = 0.0;              // step to be used next [s]
    double dt_f = 0.0, dt_cv = 0.0, dt_new = 0.0;  // last time-step diagnostics [s]
    std::int64_t dbc_counter = 0; // steps since the last dynamic-boundary density update
    std::int64_t n_outputs = 0;   // snapshots written (legacy ngrab)
    std::int64_t n_removed = 0;   // particles removed for leaving the domain
    // domain.renormalise_ring_continuity along a jet: the jet's intact length at its latest
    // breakup check [m] (the core's geometry.renormalise_reach); 0 before its first breakup or
    // without a jet: everywhere
    double renormalise_reach = 0.0;
};

}  // namespace sphjet
