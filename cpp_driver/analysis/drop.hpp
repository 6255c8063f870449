// Measures of a free 2D drop, for the surface-tension checks (cases/laplace_disc,
// cases/square_drop, cases/oscillating_drop): Laplace pressure, curvature, shape, area and the
// mode-2 oscillation. Only active fluid particles count.
//
// One snapshot (measure_drop):
//   centroid   mass-weighted (xc, zc); r = distance of a particle from it
//   area       sum m/rho (2D: m is mass per unit depth); r_eq = sqrt(area / pi)
//   outline    the fluid divided into angular sectors about the centroid, about two particle
//              spacings s = sqrt(area / n) of arc each at r_eq (at least 8); r_edge(sector) = the largest
//              r in the sector. r_max / r_min = max / min of r_edge over the sectors that hold
//              particles: 1 for a circle up to the lattice roughness
//   surface    particles with r >= r_edge(their sector) - s/2: the outer row
//   inner      particles with r < inner_fraction r_eq (default 1/2)
//   pressure   mean and standard deviation of p over the inner and the surface particles
//   curvature  mean and standard deviation over the surface particles (when the run wrote
//              the field), and the count of fluid particles with a normal (kappa != 0)
//   speed      the largest |u| of the fluid
//   moments    Ixx, Izz, Ixz = sum m (x - xc)^2 ... ; deformation D = (Ixx - Izz)/(Ixx + Izz)
//              (signed along the axes: the mode-2 oscillation of an ellipse set on the axes)
//   extent     max - min of x and of z
// A series (oscillation): the period from the zero crossings of D(t) - mean D (linear
// interpolation between frames; period = 2 x the mean spacing of successive crossings), and
// the decay rate from a least-squares fit of ln |D - mean D| at the extrema between
// crossings. A crossing counts only while the half-cycles on both sides of it reach
// noise_fraction (default 0.1) of the first extremum; from the first one that does not, the
// oscillation has decayed into the noise and later crossings and extrema are dropped.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "model/particles.hpp"

namespace sphjet::analysis {

struct MeanSd {
    double mean = 0, sd = 0;
    std::size_t n = 0;
};

[[nodiscard]] MeanSd mean_sd(std::span<const double> v);

struct DropMeasures {
    std::size_t n_fluid = 0;
    double xc = 0, zc = 0;
    double area = 0, r_eq = 0, spacing = 0;
    double r_max = 0, r_min = 0;
    MeanSd p_inner, p_surface;
    std::optional<MeanSd> kappa_surface;  // only with a curvature field
    std::size_t n_with_normal = 0;        // fluid particles with kappa != 0
    double speed_max = 0;
    double ixx = 0, izz = 0, ixz = 0, deformation = 0;
    double extent_x = 0, extent_z = 0;
    [[nodiscard]] double r_ratio() const { return r_min > 0 ? r_max / r_min : 0.0; }
};

// Measures one particle set; curvature is the snapshot's field (empty: none).
// Throws std::invalid_argument when there is no active fluid particle or curvature has the
// wrong size.
[[nodiscard]] DropMeasures measure_drop(const ParticleSet& ps,
                                        std::span<const double> curvature = {},
                                        double inner_fraction = 0.5);

struct Oscillation {
    std::size_t crossings = 0;          // zero crossings of D - mean D (above the noise floor)
    std::optional<double> period;       // [s], needs at least 2 crossings
    std::optional<double> decay_rate;   // [1/s], of the amplitude; needs 2 extrema
    double mean = 0;                    // mean of D over the series
    double amplitude0 = 0;              // |D - mean| at the first extremum
};

// Period and decay of a signal d(t) sampled at increasing times t. skip_before: samples
// with t < skip_before are ignored (start-up transient). noise_fraction: see above.
[[nodiscard]] Oscillation oscillation(std::span<const double> t, std::span<const double> d,
                                      double skip_before = 0.0, double noise_fraction = 0.1);

}  // namespace sphjet::analysis
