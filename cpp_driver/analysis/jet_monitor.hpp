// A jet followed while it runs (cases/jet/README.md, cases/round_jet/README.md): what leaves
// the orifice, where the jet breaks, how thin its neck is, and the drops.
//
// Frame: s = (r - r0) . e along the jet axis from the orifice centre r0, l = (r - r0) x e
// across it. A planar jet is a sheet of unit depth; a round (axisymmetric) jet has l = the
// radius r = x >= 0 and particle masses that are those of rings, so that sum m / rho is a
// volume. At each sample:
//   - flux: the volume (m / rho0 per particle: per unit depth in 2D, m^3 round) that crossed
//     the orifice line since the last sample, over the time between them; u_flux is the mean
//     velocity through the orifice, flux / d0 (planar) or flux / (pi d0^2 / 4) (round). A
//     particle crosses gradually, its share out being s / ds + 1/2 clamped to [0, 1] (ds the
//     spacing along the axis), so a rigid plug of rows ds apart gives a volume out exactly
//     linear in time (a count of whole particles would come in steps of a row). u_orifice is
//     the plain mean of the axial velocity of the fluid particles with 0 <= s < h and
//     |l| <= d0/2.
//   - breakup (the paper's rule): the fluid particles with s >= 0 and |l| <= band are sorted
//     by s; at the first gap between consecutive ones longer than link = link_over_h h the
//     jet is broken, and the breakup length L is the s of the particle before the gap
//     (analysis/breakup.hpp).
//   - drops: the fluid downstream of the orifice (s >= 0) in connected clusters (links of at
//     most `link`); the cluster of the particle nearest the orifice within the band is the
//     jet, every other cluster a drop. The jet can be broken (a gap along the axis) with no
//     drop, when the gap is bridged outside the band. A drop's equivalent diameter is that
//     of the disc of its area, d = 2 sqrt(A / pi) (planar), or of the sphere of its volume,
//     d = (6 V / pi)^(1/3) (round), with A or V = sum m / rho. The head drop is the drop whose
//     farthest particle is farthest along the axis. A satellite is a drop with d < d0
//     (Rayleigh's main drops are 1.89 d0; satellites form from the thread between them).
//   - neck: the jet's own cluster in slices of ds along the axis from the orifice to one d0
//     short of its tip (the tip itself is the round cap); a slice's radius is the largest
//     |l| of its particles plus ds / 2 (the particle's half-spacing: the plug gives d0 / 2
//     at the orifice). The neck is the thinnest slice: its radius and where it is. The
//     surface profile r_s(s), from which the disturbance's growth along the jet is read
//     (tools/jet_noise.py), is the straight lines through the slices' widest rings, read at
//     the slices' centres, plus ds / 2; a slice whose widest ring lies more than ds / 2 below
//     the line through its neighbours holds no outer ring (stretched rows) and is passed over.
//   - exit noise: over the jet's own particles within 2 d0 of the orifice (0 <= s < 2 d0),
//     the mean and standard deviation of the pressure and the rms of the velocity across the
//     axis (radial for a round jet). A quiet jet holds p = sigma/a there (round; a = d0/2)
//     with a spread small against it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/case_spec.hpp"
#include "model/particles.hpp"

namespace sphjet::analysis {

struct Drop {
    std::size_t particles = 0;
    double size = 0;         // sum of m / rho: area [m^2] (planar) or volume [m^3] (round)
    double d_eq = 0;         // equivalent diameter [m]
    bool satellite = false;  // d_eq < d0
    double xc = 0, zc = 0;   // centroid (mean position) [m]
    double s_max = 0;        // farthest particle along the axis [m]
    double s_min = 0;        // nearest particle along the axis [m]
    std::vector<std::size_t> members;  // its particles' indices in the particle set (for removal)
};

struct JetSample {
    double time = 0;
    std::int64_t step = 0;
    double volume_out = 0;       // volume that has crossed the orifice since t = 0 [m^2, round m^3]
    double flux = 0;             // since the previous sample [m^2/s, round m^3/s]
    double u_flux = 0;           // flux / d0 [m/s]
    double u_orifice = 0;        // mean axial velocity at the orifice [m/s] (0 when none there)
    std::optional<double> length;  // breakup length [m]; none: intact
    double jet_tip = 0;          // farthest s of the jet's own cluster [m]
    std::optional<double> neck_r, neck_s;  // the jet's thinnest slice: radius and s [m]; none: jet shorter than d0
    std::size_t in_nozzle = 0;   // fluid particles still in the nozzle's strip (0: the nozzle ran dry)
    std::vector<double> surface; // the jet's radius per slice k (s in [k ds, (k + 1) ds)) up to one d0
                                 // short of its tip [m]; NaN: an empty slice
    std::size_t exit_n = 0;      // the jet's particles with 0 <= s < 2 d0
    double exit_p_mean = 0, exit_p_std = 0;  // their pressure: mean and standard deviation [Pa]
    double exit_ul_rms = 0;      // their velocity across the axis: root mean square [m/s]
    std::vector<Drop> drops;     // detached drops, farthest first
};

class JetMonitor {
public:
    // ds: the particle spacing along the axis. round: axisymmetric (ring masses, l = r).
    JetMonitor(const NozzleSpec& nozzle, const BreakupSpec& breakup, double h, double rho0, double ds,
               bool round = false);

    // Marks as already out the fluid past the orifice (a fresh run has none there; a resumed
    // one carries on from its particles; removed particles count as out) and counts the
    // volume out.
    void start(const ParticleSet& ps, double time);
    // After start() on a resume: the volume out and the time of the last sample kept, so
    // that the next flux is taken over the same interval as in a run never stopped.
    void restore(double volume_out, double time);

    [[nodiscard]] JetSample sample(const ParticleSet& ps, double time, std::int64_t step);

    [[nodiscard]] double link() const { return link_; }
    [[nodiscard]] double band() const { return band_; }
    [[nodiscard]] const NozzleSpec& nozzle() const { return nz_; }
    [[nodiscard]] bool round() const { return round_; }
    // The orifice's area (round) or width (planar): u_flux = flux / this.
    [[nodiscard]] double orifice_measure() const;
    // The spacing along the axis: the width of a surface profile's slices [m].
    [[nodiscard]] double slice() const { return ds_; }

private:
    double crossing_volume(const ParticleSet& ps);
    void neck(const std::vector<double>& s, const std::vector<double>& l, const std::vector<int>& labels, int jet,
              JetSample& r) const;
    void exit_noise(const ParticleSet& down, const std::vector<double>& s, const std::vector<int>& labels, int jet,
                    JetSample& r) const;
    // The frame of the axis: s along it from the orifice centre, l across it.
    [[nodiscard]] double axial(double x, double z) const { return (x - nz_.x0) * nz_.ex + (z - nz_.z0) * nz_.ez; }
    [[nodiscard]] double lateral(double x, double z) const { return (x - nz_.x0) * nz_.ez - (z - nz_.z0) * nz_.ex; }

    NozzleSpec nz_;
    double h_, link_, band_, rho0_, ds_;
    bool round_;
    std::vector<char> out_;  // per particle: has crossed the orifice line
    double volume_out_ = 0;
    double last_time_ = 0;
};

// The paper's correlation (eq 37, Ashgriz 2011) with its radius-based groups:
// We = rho u0^2 R / sigma, Re = rho u0 R / mu, Oh = sqrt(We) / Re, R = d0 / 2;
// L / d0 = 13 sqrt(We) (1 + 3 Oh). mu = 0: Oh = 0.
// The theory behind it (Weber 1931; Grant & Middleman 1966) is written with the diameter
// groups We_d = rho u0^2 d0 / sigma = 2 We and Oh_d = Oh / sqrt(2):
// L / d0 = ln(a / delta0) sqrt(We_d) (1 + 3 Oh_d); with ln(a / delta0) = 13 that is eq37_d.
struct JetGroups {
    double we = 0, re = 0, oh = 0, fr = 0;
    double eq37 = 0;        // L / d0, radius groups (the paper's)
    double we_d = 0, oh_d = 0;
    double eq37_d = 0;      // L / d0 = 13 sqrt(We_d) (1 + 3 Oh_d)
};
[[nodiscard]] JetGroups jet_groups(double rho, double u0, double d0, double sigma, double mu, double g);

// CSV header and row of a sample (jet.csv) and of its drops (drops.csv).
[[nodiscard]] std::string jet_csv_header();
[[nodiscard]] std::string jet_csv_row(const JetSample& s, double d0);
[[nodiscard]] std::string drops_csv_header(bool round = false);
[[nodiscard]] std::string drops_csv_rows(const JetSample& s, double d0);
// CSV header and rows of a sample's surface profile (jet_surface.csv): one row per slice
// with time, step, the slice's centre s / d0 and its radius / d0; empty slices left out.
[[nodiscard]] std::string surface_csv_header();
[[nodiscard]] std::string surface_csv_rows(const JetSample& s, double d0, double ds);

}  // namespace sphjet::analysis
