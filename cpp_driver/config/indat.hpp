// The legacy SPHysics 2D start files, as SPHYSICSgen_2D writes them and SPHYSICS_2D reads them:
//   INDAT         47 values, one per line, in the legacy order: integers and single-precision
//                 reals in gfortran list-directed form, dx, dy, dz as ES13.7
//   IPART         one line per particle, Fortran 7E16.8: x z u w rho p m
//   NORMALS.init  repulsive boundaries only, one line per boundary particle:
//                 nx nz i 0 prev next x z  (format 2(E16.8,1X),4(I6,1X),2(E16.8,1X);
//                 indices 1-based; the normal from the neighbours, in single precision)
// Writers replace a file only once its new content is complete (written to a temporary file
// beside it, then renamed).
#pragma once

#include <cstddef>
#include <filesystem>

#include "geometry/generator.hpp"
#include "model/case_spec.hpp"
#include "model/params.hpp"
#include "model/particles.hpp"

namespace sphjet {

// INDAT. Reals are written as legacy writes them, rounded to single precision (dt = 1e-4
// appears as 9.99999975E-05). Periods of options that are off are written as legacy writes
// them: the filter period is 0 without a filter, the boundary-density period 0 for
// repulsive boundaries.
void write_indat(const std::filesystem::path& path, const SimParams& params, std::size_t np,
                 std::size_t nb, std::size_t nbf, const LegacyRunInfo& info = {});

// IPART (all particles, in their order).
void write_ipart(const std::filesystem::path& path, const ParticleSet& particles);

// NORMALS.init from the boundary particles' wall links (particles.wall, size nb).
void write_normals(const std::filesystem::path& path, const ParticleSet& particles);

// What the legacy generator writes for a case, into dir: IPART, INDAT, NORMALS.init for
// repulsive walls and, with a gate (nbf < nb), the `gate` file (the lines 1, nbf + 1 and nb:
// its first and last particle, 1-based, "vx vz", t_start). A NORMALS.init or gate left by an
// earlier case that this one does not have is removed.
void write_legacy_inputs(const std::filesystem::path& dir, const SimParams& params, const ParticleSet& particles,
                         const LegacyRunInfo& info);

// Reads INDAT, the IPART beside it and, for repulsive boundaries, the NORMALS.init beside it;
// with moving boundary particles (nbf < nb, a legacy gate) the `gate` file beside it, and
// gate_z_cap = the top of the IPART particles + 0.1 h, as SPHysics sets its zmax_ini.
// Options sphjet does not implement (other integrators, EoS, Riemann solvers, kernel
// correction, periodicity, restart, moving boundaries that are not one gate) are refused like the
// legacy case reader refuses them; missing, short or malformed files give an InputError
// naming the file and line. Values are taken as printed (0.3 reads as 0.300000012).
// Particles: kinds from nb and nbf, ids 0..np-1, all active.
[[nodiscard]] InitialState read_indat(const std::filesystem::path& indat);

}  // namespace sphjet
