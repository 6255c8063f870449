// The driven nozzle of the jet cases (CaseSpec::nozzle; cases/jet/README.md): where its
// fluid and its walls go. The generator places what this returns.
//
// Frame: s along the jet axis e from the orifice centre (s < 0 inside the nozzle), l across
// it along CCW(e) = (-ez, ex). With N = max(1, round(d0 / dl)) particles across and
// M = max(1, round(length / ds)) along (dl, ds the lattice spacings across and along the
// axis), the plug's particles sit at
//   l = -d0/2 + (j + 1/2) d0/N,  s = -(k + 1/2) ds,   j < N, k < M,
// so the jet leaves symmetric about the axis and exactly d0 wide (a simple lattice; the
// case's BCC points are not used in the nozzle). A starting column (nozzle.column_over_d0)
// continues the lattice past the orifice, s = +(k + 1/2) ds, with the plug's velocity and
// density. Walls (NozzleSpec::walls): a line on each side at l = +-(d0/2 + d0/(2N)), one
// spacing outside the outer fluid rows as the box walls are, with points s = -k ds, k = k0 .. M.
// Dynamic boundaries add a second, staggered layer half a spacing further out and half a
// spacing upstream, as the box walls have.
// Axisymmetric (a round jet; the axis is x = 0, along z): the pipe's half r >= 0 only, with
// N = max(1, round(d0 / (2 dl))) rings at r = (j + 1/2) d0 / (2N), and one wall at
// r = d0/2 + d0/(4N) (the generator gives each particle the mass of its ring). The walls end `recess` upstream of the orifice
// line (s = -k ds from k0 = ceil(recess / ds)): with recess = 2h no fluid past the orifice
// is within a wall particle's reach. (The repulsive force is scaled for hydrostatic columns,
// 0.01 c0^2 / h: about 2000 m/s^2 on the jet's outer rows at c0 = 20 m/s, h = 1.3 mm, a
// hundred times the jet's capillary accelerations; walls reaching the orifice line kicked
// the outer rows inward and the jet splashed apart within 0.01 s.) Repulsive boundaries: one line per side, its
// points ordered from the nozzle's back to the orifice and linked so that its normal faces
// the plug.
#pragma once

#include <vector>

#include "model/case_spec.hpp"
#include "model/particles.hpp"

namespace sphjet {

struct NozzlePoint {
    double x = 0, z = 0;
};

// A straight row of boundary points; `reversed` orders the repulsive wall links so that
// the normal faces the fluid (Builder::link_line).
struct NozzleWall {
    std::vector<NozzlePoint> points;
    bool reversed = false;
};

struct NozzleLayout {
    std::vector<NozzlePoint> fluid;  // the plug, then the starting column (NozzleSpec::column_over_d0)
    std::vector<NozzleWall> walls;   // empty without walls
    double spacing_across = 0;       // d0 / N
    double spacing_along = 0;        // ds
};

// dx, dz: the case's lattice spacings; dynamic: two staggered layers per wall.
// recess: how far upstream of the orifice line the walls end [m] (the generator: 2h).
// axisymmetric: the round pipe's half r = x >= 0 (the axis must be up or down, x0 = 0).
// The density and pressure of the plug as built (and of every row a refill adds): a round
// jet's plug at the jet's Laplace pressure 2 sigma / d0 (the density at which the Tait EoS gives
// it; rho0 when B = 0), a sheet's at rho0 and p = 0.
struct PlugState {
    double rho = 0, p = 0;
};
[[nodiscard]] PlugState plug_state(const SimParams& prm, const NozzleSpec& nz);

// nozzle.refill: the rows to add after a step so that the plug reaches back to where its
// back row was built, s = -(M - 1/2) ds. The plug is the active fluid with s < 0 within
// half_width of the axis (the core's driven strip, fortran_core/integrate/nozzle_drive.f90);
// each line of it along the axis (its particles at one distance from the axis, the lattice's
// column) moves rigidly, so each new particle is a copy of a line's hindmost one's position,
// velocity and mass one spacing ds further back, as many as fit (with a plug every line's
// hindmost is in one back row; with a parabolic profile the lines move at their own speeds),
// at the density and pressure of `built` (the
// plug as built: a rigid plug's density does not change by itself, but fluid passing beside
// it, such as a ring of start-up debris flying upstream, changes the rows it passes, and a
// copy of the back row's density would carry such a change into every later row). Empty when
// none is due. ps must be the particles of the case nz built.
[[nodiscard]] ParticleSet nozzle_refill_rows(const NozzleSpec& nz, double dx, double dz, double half_width,
                                             const PlugState& built, const ParticleSet& ps);

// nozzle.profile = "parabolic": the centre speed / u0, k, that gives the plug's lattice the flux of a
// plug at u0: sum w_j = k sum w_j (1 - l_j^2 / (d0/2)^2) over the particles across (at l_j from the
// axis; w_j = l_j for the rings of a round nozzle, 1 for a sheet's rows). Continuous: 2 round, 1.5
// planar; on 5 rings 1.96.
[[nodiscard]] double nozzle_profile_k(const NozzleSpec& nz, double dx, double dz, bool axisymmetric);

[[nodiscard]] NozzleLayout nozzle_layout(const NozzleSpec& nz, double dx, double dz, bool dynamic, double recess,
                                         bool axisymmetric = false);

}  // namespace sphjet
