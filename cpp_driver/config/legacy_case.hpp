// The legacy SPHysics 2D case file: the answers SPHYSICSgen_2D reads from stdin, one value
// (or comma-separated values) per line, the rest of each line a comment. Which lines exist
// depends on earlier answers (a filter period only when a filter is on, an obstacle's lines
// only after "Add obstacle = 1", ...), so the reader follows the generator's question
// sequence for BOX geometry.
//
// Supported: new runs; kernels 1, 2, 3, 5; predictor-corrector; filters 0, 1, 2; artificial
// and laminar viscosity; Tait EoS; repulsive (1) and dynamic (2) boundaries; BOX geometry
// with a flat floor and no periodicity; "Add wall" (dynamic boundaries); rectangular
// obstacles (solid with dynamic boundaries, with walls with either); one gate (dynamic
// boundaries); fill regions on an SC or BCC lattice. Everything else (restart, BEACH or
// external geometry, wavemaker, a second gate,
// floating bodies, Riemann solvers, kernel correction, SPS, other EoS and integrators,
// trapezoids, an inclined floor, boundary pressure correction, particle sets or drops as
// initial condition) is refused with an InputError naming file:line, the option, what was
// found and what is supported.
//
// Differences from the legacy reader, on purpose: all values an answer needs must be on its
// line (Fortran would read on into the next line), flags must be 0 or 1, and impossible
// values (dx <= 0, a fill region outside the box, ...) are errors instead of odd output.
#pragma once

#include <filesystem>
#include <string>

#include "model/case_spec.hpp"

namespace sphjet {

// Reads a legacy case file. The derived values are computed as SPHYSICSgen_2D computes them,
// in single precision, and stored rounded to single: h = coefficient sqrt(dx^2 + dz^2),
// B = coef^2 rho0 g h_SWL / 7 with g = 9.81 (so INDAT matches the legacy one digit for digit).
// Read values are stored as written in the file (0.3 stays 0.3). Sets spec.legacy_fill.
[[nodiscard]] CaseSpec read_legacy_case(const std::filesystem::path& path);

// The same from text in memory; source_name stands for the file in messages.
[[nodiscard]] CaseSpec parse_legacy_case(const std::string& text, const std::string& source_name);

}  // namespace sphjet
