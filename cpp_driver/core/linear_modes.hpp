// The linear modes of a state: the particles' equations of motion (positions, velocities,
// densities of the fluid particles) linearised about the state by central differences of the
// core's rates, and the eigenvalues of that Jacobian. A mode whose eigenvalue has a positive real
// part grows as exp(Re(lambda) t) from any disturbance that has a share of it, round-off included:
// the instabilities of the discrete dynamics, each with its shape (where on the particles, how
// radial, which wave along a periodic z), without running the case.
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

#include "core/solver.hpp"

namespace sphjet {

struct LinearModeOptions {
    double dx = 0;          // particle spacing [m]: the position step of the differences is 1e-6 dx
    std::size_t top = 10;   // modes reported, the fastest-growing first
    bool at_rest = true;    // linearise about the state with its velocities set to zero
    double period = 0;      // z period [m]; > 0 gives each mode's wave number along z
};

struct LinearMode {
    std::complex<double> lambda;  // eigenvalue [1/s]: growth rate + i angular frequency
    int n_axial = -1;             // period > 0: the Fourier mode n (k = 2 pi n / period) that holds
                                  // most of the outer layer's radial displacement
    double outer_share = 0;       // share of |displacement|^2 on the outer layer (x >= max x - dx/2)
    double radial_share = 0;      // share of |displacement|^2 along x
};

struct LinearModes {
    std::size_t n_fluid = 0;       // fluid particles linearised
    std::size_t dimension = 0;     // 5 n_fluid
    std::size_t growing = 0;       // eigenvalues with Re(lambda) > 0
    std::vector<LinearMode> modes; // the top ones by Re(lambda), largest first
};

// The linear modes of the solver's current state (its particles are restored afterwards).
[[nodiscard]] LinearModes linear_modes(Solver& s, const LinearModeOptions& opt);

}  // namespace sphjet
