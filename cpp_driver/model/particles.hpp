// The particle arrays, owned by C++ as a structure of arrays and lent to the Fortran core.
// Order is the legacy order: fixed boundary particles, moving boundary particles, fluid.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sphjet {

enum class ParticleKind : int { FixedBoundary = 0, MovingBoundary = 1, Fluid = 2 };

// Wall data of one boundary particle, needed by the repulsive (Monaghan-Kos) walls:
// the neighbours along the wall (0-based indices; a particle at a wall end names itself),
// as SPHysicsgen writes them to NORMALS.init.
struct WallLink {
    int prev = -1;
    int next = -1;
};

// Domain outside which fluid particles leave the simulation.
struct DomainBounds {
    double xmin, xmax, zmin, zmax;
};

struct ParticleSet;

// Legacy rule: the extent of the fixed boundary particles (all boundary particles when none is
// fixed), open at the top; no boundary: unbounded. A gate (moving, nbf..nb) does not count:
// legacy fixes the bounds once, and a moved gate must not shift them on a resume.
[[nodiscard]] DomainBounds legacy_domain(const ParticleSet& ps);

// Where the particles of a gate stop rising: the top of the particles plus 0.1 h, as
// SPHysics sets its zmax_ini (applied to the initial particles).
[[nodiscard]] double gate_z_cap(const ParticleSet& ps, double h);

struct ParticleSet {
    std::vector<double> x, z;      // position [m]
    std::vector<double> u, w;      // velocity [m/s]
    std::vector<double> rho;       // density [kg/m^3]
    std::vector<double> p;         // pressure [Pa]
    std::vector<double> m;         // mass [kg]
    std::vector<int> kind;         // ParticleKind
    std::vector<std::int64_t> id;  // stable id = initial index (0-based)
    std::vector<int> active;       // 1 in the domain, 0 removed (left the domain)
    std::vector<WallLink> wall;    // size nb when the boundary is repulsive, else empty
    std::size_t nb = 0;            // boundary particles (fixed + moving)
    std::size_t nbf = 0;           // fixed boundary particles

    [[nodiscard]] std::size_t size() const { return x.size(); }
    [[nodiscard]] std::size_t n_fluid() const { return size() - nb; }
    [[nodiscard]] std::size_t n_active() const;  // particles still in the domain
    void resize(std::size_t n);
    // Appends one particle; returns its index.
    std::size_t push(double x_, double z_, double u_, double w_, double rho_, double p_, double m_,
                     ParticleKind k);
};

}  // namespace sphjet
