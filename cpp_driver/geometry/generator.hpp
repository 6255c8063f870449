// Building the initial particles of a case: what SPHYSICSgen2D does for a BOX, plus the
// shapes of the modern format.
//
// Order and placement follow SPHYSICSgen2D exactly (legacy order: fixed boundary particles,
// then the moving ones of a gate, then fluid; nbf = nb without a gate):
//   1. box walls: left (x = 0), right (x = N dx), bottom (z = 0), where N = nint(LX/dx).
//      Dynamic boundaries: two staggered layers per wall (inner layer on the wall line, outer
//      layer half a spacing outside and half a spacing lower / further). Repulsive boundaries:
//      one line of particles per wall, each with its neighbours along the wall (WallLink, as
//      in NORMALS.init; the corners appear in two walls, as in legacy).
//      A top wall (modern format only) mirrors the bottom one at z = L dz, L = nint(LZ/dz).
//   2. legacy "Add wall" walls (dynamic boundaries: two layers).
//   3. obstacles: rectangles (optionally with inclined sides) on a lattice of dx/ndens;
//      solid (dynamic) or outline walls (two staggered layers for dynamic, one line with
//      links for repulsive boundaries).
//   4. a gate (legacy "Add gate"): one column of moving boundary particles (nbf < nb), and
//      the gate's motion into SimParams (gate_z_cap = top of the initial particles + 0.1 h,
//      SPHysics' zmax_ini); with repulsive walls one wall line with links (modern format).
//   5. fluid: per region, columns in x, and per column rows in z; at each lattice node the
//      SC point and then (BCC) the point offset by (dx/2, dz/2).
// Density and mass: boundaries rho0 with p = 0 and mass 0.5 rho0 dx dz (dynamic, two layers)
// or rho0 dx dz (repulsive). Fluid: hydrostatic rho = rho0 (1 + rho0 g (zref - z)/B)^(1/gamma),
// p = B((rho/rho0)^gamma - 1), mass = lattice factor (1 SC, 0.5 BCC) x rho x dx x dz, where
// zref is the top of the region (for a legacy fill region min(top lattice row, h_SWL)).
//
// Legacy precision, on purpose. SPHYSICSgen2D holds x, z, dx, dz and the fill bounds in
// double precision and nearly everything else in single (implicit typing): the box size,
// h_SWL, g, B, rho, p and mass, the thresholds that decide which lattice points are kept
// (0.999*XMax, 1.001*ZMax, ...), and the obstacle spacing dx/ndens and its offsets. The
// generator rounds through float at exactly those places, and nowhere else, so that a legacy
// case gives the legacy IPART: positions to the last printed digit, and rho, p, m as the
// float values legacy prints. Where legacy computes in double we compute in double (the
// fluid lattice x = XMin + i dx, z = k dz), so the float emulation never accumulates.
//
// Legacy fill-region quirks, reproduced when CaseSpec::legacy_fill is true (the legacy
// reader sets it): with a flat floor the fill starts at the floor whatever ZMin says; the
// fluid never goes above h_SWL; the SC column at x = XMin is dropped when XMin = 0; fluid is
// not kept out of obstacles. The legacy reader warns about each of these.
//
// Modern shapes (legacy_fill false: every block, and all FluidSquare and FluidDisc): the
// lattice points (i dx, k dz) and, for BCC, ((i + 1/2) dx, (k + 1/2) dz) that lie inside
// the closed shape (tolerance 1e-6 spacings), are more than dx/4 (dz/4) from a wall line
// that is present, and are not within half a spacing of an obstacle's bounding rectangle.
// Density: hydrostatic from the shape's top when gravity is not zero (a column at rest, the
// state a legacy run starts from), rho0 when it is zero (a drop without gravity is at rest
// at rho0; its surface-tension pressure is left to the solver's first steps). Computed in
// double. Velocity: the shape's (u0, w0).
// A disc may instead be built of concentric rings (FluidDisc::rings, case key
// fluid.disc.lattice = "rings"): a centre particle and N = round(R/dx - 1/2) rings at spacing
// ds = R / (N + 1/2), ring j at radius j ds with round(2 pi j) particles, each with the mass
// rho x its share of the annulus, so that the volumes sum to pi R^2 (Builder::ring_disc). A disc with an
// elongation e (either lattice) is the ellipse of semi-axes R (1 + e), R / (1 + e).
// Axisymmetric geometry (SimParams::geometry): shapes on the lattice ((i + 1/2) dx, k dz), no
// particle on the axis; a rings disc centred on the axis is a sphere of half rings
// (Builder::sphere_rings), FluidCylinder a perturbed liquid cylinder (Builder::cylinder), both
// at the Laplace pressure of the unperturbed shape without gravity; every mass is the ring's,
// rho x area x 2 pi x (build()).
#pragma once

#include "model/case_spec.hpp"
#include "model/params.hpp"
#include "model/particles.hpp"

namespace sphjet {

struct InitialState {
    SimParams params;
    ParticleSet particles;
    LegacyRunInfo legacy;  // what INDAT carries beyond SimParams
};

// Places the particles of spec. Throws InputError (where = spec.source) for a spec it
// cannot build: non-positive spacing or box, no fluid, B <= 0 with gravity, an unsupported
// obstacle shape, a floor inclination, a legacy wall with repulsive boundaries.
[[nodiscard]] InitialState generate(const CaseSpec& spec);

}  // namespace sphjet
