#include "geometry/generator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include "geometry/nozzle.hpp"
#include "model/errors.hpp"
#include "model/tait.hpp"

namespace sphjet {
namespace {

// The value a legacy single-precision variable would hold.
double f32(double v) { return static_cast<double>(static_cast<float>(v)); }

// Fortran NINT: nearest integer, halves away from zero.
long nint(double v) { return std::lround(v); }

class Builder {
public:
    explicit Builder(const CaseSpec& spec) : spec_(spec), p_(spec.params) {
        repulsive_ = p_.boundary == BoundaryType::Repulsive;
        axi_ = p_.geometry == Geometry::Axisymmetric;
        bcc_ = p_.lattice == Lattice::BodyCentred;
        // N and L spacings across the box; legacy holds LX and LZ in single precision.
        n_ = nint(f32(p_.lx) / p_.dx);
        l_ = nint(f32(p_.lz) / p_.dz);
    }

    InitialState build() {
        box_walls();
        for (const WallSpec& w : spec_.walls) inner_wall(w);
        for (const ObstacleSpec& o : spec_.obstacles) obstacle(o);
        for (const GateSpec& g : spec_.gates) gate(g);
        std::optional<NozzleLayout> nozzle;
        if (spec_.nozzle) nozzle = nozzle_layout(*spec_.nozzle, p_.dx, p_.dz, !repulsive_, 2.0 * p_.h,
                                               p_.geometry == Geometry::Axisymmetric);
        if (nozzle) nozzle_walls(*nozzle);
        boundary_density_and_mass();
        if (nozzle) nozzle_fluid(*spec_.nozzle, *nozzle);
        const std::size_t first_shape = ps_.size();  // the shapes' fluid from here (jitter)

        if (spec_.legacy_fill) {
            for (const FluidBlock& b : spec_.fluid_blocks) legacy_fill(b);
        } else {
            for (const FluidBlock& b : spec_.fluid_blocks)
                fill_shape(b.r, b.r.zmax, b.u0, b.w0, [&](double x, double z) {
                    return inside_rect(b.r, x, z);
                });
        }
        for (const FluidSquare& q : spec_.fluid_squares) {
            const Rect r{q.xc - q.side / 2, q.xc + q.side / 2, q.zc - q.side / 2, q.zc + q.side / 2};
            fill_shape(r, r.zmax, q.u0, q.w0, [&](double x, double z) { return inside_rect(r, x, z); });
        }
        for (const FluidCylinder& c : spec_.fluid_cylinders) cylinder(c);
        for (const FluidDisc& d : spec_.fluid_discs) {
            const double sx = 1 + d.elongation, sz = 1 / sx;  // semi-axes R sx, R sz
            if (d.rings && axi_ && d.xc == 0) {
                // an ellipsoid of revolution of the sphere's volume: semi-axes R sx (x, twice)
                // and R / sx^2 (z), r = R (1 - 2 e P2(cos theta)) + O(e^2)
                sphere_rings(d, sx, 1 / (sx * sx));
                continue;
            }
            if (d.rings) {
                ring_disc(d, sx, sz);
                continue;
            }
            const Rect r{d.xc - d.radius * sx, d.xc + d.radius * sx, d.zc - d.radius * sz,
                         d.zc + d.radius * sz};
            const double r2 = d.radius * d.radius + tol() * tol();
            fill_shape(r, r.zmax, d.u0, d.w0, [&](double x, double z) {
                const double ex = (x - d.xc) / sx, ez = (z - d.zc) / sz;
                return ex * ex + ez * ez <= r2;
            });
        }
        // Axisymmetric: every particle so far carries rho x its area in the meridian plane;
        // its mass is that of its ring, 2 pi x times as much (a wall particle on the axis
        // gets none: it has no ring).
        if (axi_)
            for (std::size_t i = 0; i < ps_.size(); ++i) ps_.m[i] *= 2 * std::numbers::pi * ps_.x[i];
        if (p_.jitter > 0) jitter(first_shape);
        if (ps_.n_fluid() == 0)
            throw InputError(spec_.source, "the case places no fluid particle",
                             "fluid regions that hold at least one lattice point", "none");
        // Extreme but finite inputs (gravity 1e308, gamma 1e11, ...) can overflow the
        // hydrostatic state; found by tests/fuzz.
        for (std::size_t i = 0; i < ps_.size(); ++i) {
            if (std::isfinite(ps_.x[i]) && std::isfinite(ps_.z[i]) && std::isfinite(ps_.rho[i]) &&
                std::isfinite(ps_.p[i]) && std::isfinite(ps_.m[i]))
                continue;
            throw InputError(spec_.source, "the initial particles are not all finite numbers",
                             "a finite position, density, pressure and mass for every particle "
                             "(rho = rho0 (1 + rho0 |g| (ztop - z) / B)^(1/gamma), p = B ((rho/rho0)^gamma - 1))",
                             "particle " + std::to_string(i + 1) + " at x = " + std::to_string(ps_.x[i]) +
                                 ", z = " + std::to_string(ps_.z[i]) + ": rho = " + std::to_string(ps_.rho[i]) +
                                 ", p = " + std::to_string(ps_.p[i]) + ", m = " + std::to_string(ps_.m[i]));
        }

        if (!spec_.gates.empty()) {
            const GateSpec& g = spec_.gates.front();
            p_.gate_vx = g.vx, p_.gate_vz = g.vz, p_.gate_t_start = g.t_start;
            p_.gate_z_cap = gate_z_cap(ps_, p_.h);
        }

        InitialState s;
        s.params = p_;
        s.legacy = spec_.legacy;
        if (repulsive_) ps_.wall = links_;
        s.particles = std::move(ps_);
        return s;
    }

private:
    // SimParams::jitter: the shapes' fluid particles from index first moved by uniform random
    // offsets (mt19937_64 seeded with jitter_seed, drawn x then z per particle, so a seed gives
    // the same positions on every machine; the masses stay those of the lattice). A particle
    // the offset takes across the axis is mirrored back (x -> |x|), and with periodic_z its z
    // is wrapped into [0, lz).
    void jitter(std::size_t first) {
        std::mt19937_64 gen(static_cast<std::uint64_t>(p_.jitter_seed));
        const auto offset = [&gen](double a) {
            return a * (2.0 * (static_cast<double>(gen() >> 11) * 0x1.0p-53) - 1.0);
        };
        for (std::size_t i = first; i < ps_.size(); ++i) {
            ps_.x[i] += offset(p_.jitter * p_.dx);
            ps_.z[i] += offset(p_.jitter * p_.dz);
            if (axi_) ps_.x[i] = std::abs(ps_.x[i]);
            if (p_.periodic_z) ps_.z[i] -= p_.lz * std::floor(ps_.z[i] / p_.lz);
        }
    }

    // --- boundaries -------------------------------------------------------------------

    std::size_t boundary(double x, double z) {
        const std::size_t i = ps_.push(x, z, 0, 0, 0, 0, 0, ParticleKind::FixedBoundary);
        ps_.nb = ps_.nbf = ps_.size();
        if (repulsive_) links_.push_back({});
        return i;
    }

    // Neighbour links of the line of repulsive particles first..first+count-1, as legacy
    // sets them: forward lines name the following particle "next", reversed lines the
    // preceding one; a particle at an end names itself for the missing side.
    void link_line(std::size_t first, std::size_t count, bool reversed) {
        for (std::size_t j = 0; j < count; ++j) {
            const int idx = static_cast<int>(first + j);
            const bool start = j == 0, end = j + 1 == count;
            WallLink& w = links_[first + j];
            if (!reversed) {
                w.prev = start ? idx : idx - 1;
                w.next = end ? idx : idx + 1;
            } else {
                w.prev = end ? idx : idx + 1;
                w.next = start ? idx : idx - 1;
            }
        }
    }

    void box_walls() {
        const double dx = p_.dx, dz = p_.dz;
        const long n = n_, l = l_;
        if (!repulsive_) {
            // Two staggered layers; (k - 0.5) and (i + 0.5) are exact, as in legacy's single.
            if (spec_.wall_left) {
                for (long k = 0; k <= l; ++k) boundary(0.0, k * dz);
                for (long k = 0; k <= l; ++k) boundary(-0.5 * dx, (k - 0.5) * dz);
            }
            if (spec_.wall_right) {
                for (long k = 0; k <= l; ++k) boundary(n * dx, k * dz);
                for (long k = 0; k <= l; ++k) boundary((n + 0.5) * dx, (k - 0.5) * dz);
            }
            if (spec_.wall_bottom) {
                for (long i = 1; i <= n - 1; ++i) boundary(i * dx, 0.0);
                for (long i = 0; i <= n - 1; ++i) boundary((i + 0.5) * dx, -0.5 * dz);
            }
            if (spec_.wall_top) {  // sphjet extension: the bottom wall mirrored at z = L dz
                for (long i = 1; i <= n - 1; ++i) boundary(i * dx, l * dz);
                for (long i = 0; i <= n - 1; ++i) boundary((i + 0.5) * dx, (l + 0.5) * dz);
            }
            return;
        }
        // One line per wall; normals (from the links) point into the box.
        if (spec_.wall_left) {
            const std::size_t first = ps_.size();
            for (long k = 0; k <= l; ++k) boundary(0.0, k * dz);
            link_line(first, static_cast<std::size_t>(l + 1), true);
        }
        if (spec_.wall_right) {
            const std::size_t first = ps_.size();
            for (long k = 0; k <= l; ++k) boundary(n * dx, k * dz);
            link_line(first, static_cast<std::size_t>(l + 1), false);
        }
        if (spec_.wall_bottom) {
            const std::size_t first = ps_.size();
            for (long i = 0; i <= n; ++i) boundary(i * dx, 0.0);
            link_line(first, static_cast<std::size_t>(n + 1), false);
        }
        if (spec_.wall_top) {
            const std::size_t first = ps_.size();
            for (long i = 0; i <= n; ++i) boundary(i * dx, l * dz);
            link_line(first, static_cast<std::size_t>(n + 1), true);
        }
    }

    // Legacy "Add wall": a column on the wall line and a staggered one half a spacing right.
    void inner_wall(const WallSpec& w) {
        if (repulsive_)
            throw InputError(spec_.source, "a wall inside the box needs dynamic boundaries",
                             "boundary type dynamic", "repulsive");
        const long l_end = nint(w.height / p_.dz);
        for (long k = 0; k <= l_end; ++k) {
            boundary(w.x, k * p_.dz);
            if ((k + 0.5) * p_.dz <= w.height) boundary(w.x + 0.5 * p_.dx, (k + 0.5) * p_.dz);
        }
    }

    // Legacy "Add gate": one column of moving boundary particles at x, z = k dz for
    // k = nint(zmin/dz) .. nint(zmax/dz) (SPHYSICSgen2D's gate; its staggered second column
    // is empty there, YYmax = 0). Repulsive walls: one wall line, linked so that its normal
    // faces the fluid (bottom to top for facing -1, the right wall's orientation).
    void gate(const GateSpec& g) {
        const std::size_t first = ps_.size();
        const long k0 = nint(g.zmin / p_.dz), k1 = nint(g.zmax / p_.dz);
        for (long k = k0; k <= k1; ++k) {
            ps_.push(g.x, k * p_.dz, 0, 0, 0, 0, 0, ParticleKind::MovingBoundary);
            ps_.nb = ps_.size();
            if (repulsive_) links_.push_back({});
        }
        if (ps_.size() == first)
            throw InputError(spec_.source, "the gate holds no particle", "zmin <= zmax",
                             std::to_string(g.zmin) + ", " + std::to_string(g.zmax));
        if (repulsive_ && ps_.size() - first < 2)
            throw InputError(spec_.source, "a gate with repulsive walls needs two particles or more (its normal "
                                           "comes from its neighbours)",
                             "zmax - zmin >= dz = " + std::to_string(p_.dz),
                             std::to_string(g.zmin) + " .. " + std::to_string(g.zmax));
        if (repulsive_) link_line(first, ps_.size() - first, g.facing > 0);
    }

    // A driven nozzle (geometry/nozzle.hpp): its walls are fixed boundary particles.
    void nozzle_walls(const NozzleLayout& lay) {
        for (const NozzleWall& w : lay.walls) {
            const std::size_t first = ps_.size();
            for (const NozzlePoint& q : w.points) boundary(q.x, q.z);
            if (repulsive_) link_line(first, w.points.size(), w.reversed);
        }
    }

    // The nozzle's plug: fluid moving at u0 along the axis; its mass is rho0 times its share
    // of the nozzle's cross-section, so the plug's volume at rho0 is d0 x length (round:
    // build() then gives each ring its 2 pi r, so the plug's mass is rho0 pi d0^2 / 4 x length).
    // A round jet's plug is at the jet's Laplace pressure 2 sigma / d0 (the density of the Tait
    // EoS), a sheet's at p = 0 (no capillary pressure). The plug is rigid and its density
    // follows continuity, so it keeps that pressure, and a ring leaving it is not compressed
    // from 0 to the jet's 120 Pa (water, d0 = 1.194 mm) at the orifice. (The jet's pressure
    // noise next to the orifice, +-500-1200 Pa at d0/dx = 10, is the same either way.)
    void nozzle_fluid(const NozzleSpec& nz, const NozzleLayout& lay) {
        const double m = p_.rho0 * lay.spacing_across * lay.spacing_along;
        const PlugState plug = plug_state(p_, nz);
        for (const NozzlePoint& q : lay.fluid)
            ps_.push(q.x, q.z, nz.u0 * nz.ex, nz.u0 * nz.ez, plug.rho, plug.p, m, ParticleKind::Fluid);
    }

    void obstacle(const ObstacleSpec& o) {
        if (o.shape != 1)
            throw InputError(spec_.source, "unsupported obstacle shape", "1 (rectangle)", std::to_string(o.shape));
        if (o.kind != 1 && o.kind != 2)
            throw InputError(spec_.source, "invalid obstacle kind", "1 (solid) or 2 (walls)", std::to_string(o.kind));
        if (o.kind == 1 && repulsive_)
            throw InputError(spec_.source, "a solid obstacle needs dynamic boundaries",
                             "obstacle kind 2 (walls) with repulsive boundaries", "kind 1 (solid)");
        if (o.density < 1)
            throw InputError(spec_.source, "invalid obstacle density", "an integer >= 1", std::to_string(o.density));

        // Legacy single-precision quantities of the obstacle.
        const float pi = 4.0f * std::atan(1.0f);
        const float dx1 = static_cast<float>(p_.dx / o.density);
        const float dz1 = static_cast<float>(p_.dz / o.density);
        const double xmin = o.r.xmin, xmax = o.r.xmax, zmin = o.r.zmin, zmax = o.r.zmax;
        float slope = static_cast<float>(o.beta_deg);
        slope = slope * pi;
        slope = slope / 180.0f;
        float cot = 0.0f;  // 1/tan(slope): horizontal shift per row of an inclined side
        float xtop = 0.0f;
        if (slope == pi / 2.0f) {
            xtop = static_cast<float>(static_cast<double>(1.01f) * xmax);
        } else {
            cot = 1.0f / std::tan(slope);
            const long kmax = nint(zmax / dz1);
            const float shift = (static_cast<float>(kmax) * dx1) * cot;
            xtop = static_cast<float>(static_cast<double>(1.01f) * (xmax + shift));
        }
        const long n_ini = nint(xmin / dx1), n_end = nint(xmax / dx1);
        // The floor under the obstacle is flat (hk = 0): the base is at max(ZMin, 0).
        const float zinf = static_cast<float>(std::max(zmin, 0.0));
        long l_ini = nint(zinf / dz1);
        long l_end = nint(zmax / dz1);

        // x of lattice node (i, k): XMin + (i - N_ini) dx1 + (k - L_ini) cot dx1, the two
        // offsets in single precision as in legacy; `half` shifts i by -1/2.
        const auto x_at = [&](long i, long k, bool half) {
            const float di = half ? static_cast<float>(i - n_ini) - 0.5f : static_cast<float>(i - n_ini);
            const float a = di * dx1;
            const float b = (static_cast<float>(k - l_ini) * cot) * dx1;
            return (xmin + static_cast<double>(a)) + static_cast<double>(b);
        };

        if (!repulsive_) {
            const auto z_at = [&](long k, bool half) {
                const float dk = half ? static_cast<float>(k - l_ini) - 0.5f : static_cast<float>(k - l_ini);
                return static_cast<double>(zinf + dk * dz1);
            };
            const double ztop = static_cast<double>(1.01f) * zmax;
            for (long i = n_ini; i <= n_end; ++i) {
                for (long k = l_ini; k <= l_end; ++k) {
                    if (o.kind == 1) {
                        boundary(x_at(i, k, false), z_at(k, false));
                        const double xh = x_at(i, k, true), zh = z_at(k, true);
                        if (xh <= static_cast<double>(xtop) && zh <= ztop) boundary(xh, zh);
                    } else if (i == n_ini || i == n_end || k == l_ini || k == l_end) {
                        boundary(x_at(i, k, false), z_at(k, false));
                        boundary(x_at(i, k, true), z_at(k, true));
                    }
                }
            }
            return;
        }

        // Repulsive: four faces of single lines, each linked along itself.
        const auto z_rep = [&](long k) { return static_cast<double>(static_cast<float>(k) * dz1); };
        for (const long i : {n_ini, n_end}) {  // faces 1 (x = XMin) and 2 (x = XMax)
            l_ini = nint(zinf / dz1);
            l_end = nint(zmax / dz1);
            const std::size_t first = ps_.size();
            for (long k = l_ini; k <= l_end; ++k) boundary(x_at(i, k, false), z_rep(k));
            link_line(first, static_cast<std::size_t>(l_end - l_ini + 1), i == n_end);
        }
        for (const double zface : {zmin, zmax}) {  // faces 3 (z = ZMin) and 4 (z = ZMax)
            const long k = nint(zface / dz1);
            const std::size_t first = ps_.size();
            for (long i = n_ini; i <= n_end; ++i) boundary(x_at(i, k, false), z_rep(k));
            link_line(first, static_cast<std::size_t>(n_end - n_ini + 1), zface == zmin);
        }
    }

    void boundary_density_and_mass() {
        const std::size_t nb = ps_.size();
        for (std::size_t i = 0; i < nb; ++i) {
            ps_.rho[i] = p_.rho0;
            ps_.p[i] = 0.0;
            if (spec_.legacy_fill) {  // legacy: single precision, dr = dx dz rounded to single
                const float rho = static_cast<float>(p_.rho0);
                const float dr = static_cast<float>(p_.dx * p_.dz);
                ps_.m[i] = repulsive_ ? rho * dr : (0.5f * rho) * dr;
            } else {
                ps_.m[i] = (repulsive_ ? 1.0 : 0.5) * p_.rho0 * p_.dx * p_.dz;
            }
        }
    }

    // --- fluid ------------------------------------------------------------------------

    [[nodiscard]] double lattice_factor() const { return bcc_ ? 0.5 : 1.0; }
    [[nodiscard]] double gravity() const { return std::hypot(p_.gx, p_.gz); }

    void require_B() const {
        if (!(p_.B > 0))
            throw InputError(spec_.source, "hydrostatic fluid density needs the Tait constant B",
                             "B > 0", std::to_string(p_.B));
    }

    // A fluid particle as SPHYSICSgen2D's pressure routine sets it: density from the
    // hydrostatic column above it (mixed single/double as in legacy, stored single), then
    // pressure and mass in single precision.
    void legacy_fluid(double x, double z, double zref, double u0, double w0) {
        const float rho0 = static_cast<float>(p_.rho0);
        const float g = static_cast<float>(gravity());
        const float b = static_cast<float>(p_.B);
        const float gamma = static_cast<float>(p_.gamma);
        const float expont = 1.0f / gamma;
        const float vnorm = static_cast<float>(lattice_factor());
        const double base = 1.0 + static_cast<double>(rho0 * g) * (zref - z) / static_cast<double>(b);
        const float rho = static_cast<float>(static_cast<double>(rho0) * std::pow(base, static_cast<double>(expont)));
        const float pr = b * (std::pow(rho / rho0, gamma) - 1.0f);
        const float m = static_cast<float>(static_cast<double>(vnorm * rho) * p_.dx * p_.dz);
        ps_.push(x, z, u0, w0, rho, pr, m, ParticleKind::Fluid);
    }

    // SPHYSICSgen2D's fill of a "cube containing particles" in a BOX with a flat floor.
    void legacy_fill(const FluidBlock& blk) {
        require_B();
        const double dx = p_.dx, dz = p_.dz;
        const float vnorm = static_cast<float>(lattice_factor());
        const double xmin_init = blk.r.xmin;                         // double in legacy
        const float xmax_init = static_cast<float>(blk.r.xmax);      // single in legacy
        const float zmax_init = static_cast<float>(blk.r.zmax);      // single in legacy
        const long n_end = nint(blk.r.xmax / dx), n_ini = nint(blk.r.xmin / dx);
        double xmin = n_ini * dx;
        const double xmax = n_end * dx;
        // Undo the rounding of XMin unless it moved by about a quarter spacing (legacy rule).
        if (xmin > xmin_init + static_cast<double>(vnorm * 0.5f) * dx)
            xmin = xmin_init;
        else if (xmin < xmin_init + static_cast<double>(0.99f * vnorm * 0.5f) * dx)
            xmin = xmin_init;
        double zmax = nint(blk.r.zmax / dz) * dz;
        if (zmax > f32(p_.h_swl)) zmax = f32(p_.h_swl);
        // Flat floor: the column starts at the floor (ZZinf = 0, L_ini = 0) whatever ZMin is.
        // (Legacy takes the start as min(floor height, a value it sets only when the floor is
        // below the rounded ZMin); when it does not set it (ZMin <= 0), we take the floor too.)
        long l_end = static_cast<long>(zmax / dz);
        if (l_end * dz < static_cast<double>(zmax_init)) ++l_end;

        const double zlow = 0.25 * dz;  // 1.001 * hk + 0.25 dz with hk = 0
        const double zhigh = static_cast<double>(1.001f) * zmax;
        const double xlow = static_cast<double>(0.999f) * xmin_init;
        const double xhigh = static_cast<double>(0.999f * xmax_init) + 0.5 * dx;
        const double xbcc_max = static_cast<double>(1.001f) * xmax;
        const auto keep = [&](double x, double z) { return z > zlow && z < zhigh && x > xlow && x < xhigh; };

        for (long i = n_ini; i <= n_end; ++i) {
            for (long k = 0; k <= l_end; ++k) {
                const double x1 = xmin + static_cast<double>(i - n_ini) * dx;
                const double z1 = static_cast<double>(k) * dz;
                if (keep(x1, z1)) legacy_fluid(x1, z1, zmax, blk.u0, blk.w0);
                if (!bcc_) continue;
                const double x2 = xmin + static_cast<double>(static_cast<float>(i - n_ini) + 0.5f) * dx;
                const double z2 = static_cast<double>(static_cast<float>(k) + 0.5f) * dz;
                if (x2 <= xbcc_max && z2 <= zhigh && (!repulsive_ || keep(x2, z2)))
                    legacy_fluid(x2, z2, zmax, blk.u0, blk.w0);
            }
        }
    }

    [[nodiscard]] double tol() const { return 1e-6 * std::min(p_.dx, p_.dz); }

    [[nodiscard]] bool inside_rect(const Rect& r, double x, double z) const {
        const double t = tol();
        return x >= r.xmin - t && x <= r.xmax + t && z >= r.zmin - t && z <= r.zmax + t;
    }

    // Not on or just beside a wall line, nor within half a spacing of an obstacle or a gate.
    [[nodiscard]] bool clear(double x, double z) const {
        const double dx = p_.dx, dz = p_.dz;
        if (x < -tol() || x > n_ * dx + tol() || z < -tol()) return false;
        if (spec_.wall_left && x <= 0.25 * dx) return false;
        if (spec_.wall_right && x >= n_ * dx - 0.25 * dx) return false;
        if (spec_.wall_bottom && z <= 0.25 * dz) return false;
        if (spec_.wall_top && z >= l_ * dz - 0.25 * dz) return false;
        for (const WallSpec& w : spec_.walls)
            if (x > w.x - 0.5 * dx && x < w.x + dx && z < w.height + 0.5 * dz) return false;
        for (const ObstacleSpec& o : spec_.obstacles) {
            const double shift = o.beta_deg == 90 ? 0.0 : (o.r.zmax - o.r.zmin) / std::tan(o.beta_deg * std::numbers::pi / 180);
            const double xlo = std::min(o.r.xmin, o.r.xmin + shift), xhi = std::max(o.r.xmax, o.r.xmax + shift);
            if (x > xlo - 0.5 * dx && x < xhi + 0.5 * dx && z > o.r.zmin - 0.5 * dz && z < o.r.zmax + 0.5 * dz)
                return false;
        }
        for (const GateSpec& g : spec_.gates)
            if (std::abs(x - g.x) < 0.5 * dx && z > g.zmin - 0.5 * dz && z < g.zmax + 0.5 * dz) return false;
        return true;
    }

    // Modern shapes: lattice points inside, hydrostatic from ztop when gravity is on.
    void fill_shape(const Rect& bbox, double ztop, double u0, double w0,
                    const std::function<bool(double, double)>& inside) {
        const double g = gravity();
        if (g != 0) require_B();
        const double dx = p_.dx, dz = p_.dz, rho0 = p_.rho0, gamma = p_.gamma;
        const auto add = [&](double x, double z) {
            if (!inside(x, z) || !clear(x, z)) return;
            const double rho =
                g == 0 ? rho0 : rho0 * std::pow(1.0 + rho0 * g * (ztop - z) / p_.B, 1.0 / gamma);
            const double pr = g == 0 ? 0.0 : p_.B * (std::pow(rho / rho0, gamma) - 1.0);
            ps_.push(x, z, u0, w0, rho, pr, lattice_factor() * rho * dx * dz, ParticleKind::Fluid);
        };
        const long i0 = static_cast<long>(std::floor(bbox.xmin / dx)) - 1;
        const long i1 = static_cast<long>(std::ceil(bbox.xmax / dx)) + 1;
        const long k0 = static_cast<long>(std::floor(bbox.zmin / dz)) - 1;
        const long k1 = static_cast<long>(std::ceil(bbox.zmax / dz)) + 1;
        // axisymmetric: columns at (i + 1/2) dx, none on the axis (the reader refuses BCC)
        const double xoff = axi_ ? 0.5 * dx : 0.0;
        for (long i = i0; i <= i1; ++i) {
            for (long k = k0; k <= k1; ++k) {
                add(i * dx + xoff, k * dz);
                if (bcc_) add((i + 0.5) * dx, (k + 0.5) * dz);
            }
        }
    }

    // A disc of concentric rings (FluidDisc::rings): one particle at the centre and N rings,
    // N = max(1, round(R / dx - 1/2)), at spacing ds = R / (N + 1/2) (= dx when R / dx - 1/2 is a
    // whole number, else within dx / (2 R / dx + 1) of it), ring j = 1..N at radius j ds holding
    // n_j = round(2 pi j) particles (6, 13, 19, 25, ...; odd rings turned by half a particle
    // spacing). The centre particle carries rho pi ds^2 / 4, a particle of ring j the mass of
    // its share of the annulus (j -+ 1/2) ds, m = rho 2 pi j ds^2 / n_j (within 5% of
    // rho ds^2, within 1% from the fourth ring on), so the particle volumes sum to pi R^2
    // exactly and the outer ring lies half a spacing inside R. (A centre particle with a first
    // ring of 6 is a regular hexagonal core; rings at (j - 1/2) ds would start with 3
    // particles, whose colour gradient exceeds the normal filter of eq 20 and gives interior
    // particles a spurious curvature.) Then the area-preserving stretch x -> xc + sx (x - xc),
    // z -> zc + sz (z - zc), sx sz = 1 (the mode-2 ellipse; identity for a round disc).
    // Density as fill_shape.
    void ring_disc(const FluidDisc& d, double sx, double sz) {
        const double g = gravity();
        if (g != 0) require_B();
        const double rho0 = p_.rho0, gamma = p_.gamma, pi = std::numbers::pi;
        const long nrings = std::max(1L, nint(d.radius / p_.dx - 0.5));
        const double ds = d.radius / (static_cast<double>(nrings) + 0.5);
        const double ztop = d.zc + d.radius * sz;
        const auto add = [&](double x, double z, double vol) {
            if (!clear(x, z)) return;
            const double rho =
                g == 0 ? rho0 : rho0 * std::pow(1.0 + rho0 * g * (ztop - z) / p_.B, 1.0 / gamma);
            const double pr = g == 0 ? 0.0 : p_.B * (std::pow(rho / rho0, gamma) - 1.0);
            ps_.push(x, z, d.u0, d.w0, rho, pr, rho * vol, ParticleKind::Fluid);
        };
        add(d.xc, d.zc, 0.25 * pi * ds * ds);
        for (long j = 1; j <= nrings; ++j) {
            const double rj = static_cast<double>(j) * ds;
            const long nj = nint(2 * pi * static_cast<double>(j));
            const double vol = 2 * pi * static_cast<double>(j) * ds * ds / static_cast<double>(nj);
            for (long k = 0; k < nj; ++k) {
                const double th = 2 * pi * (static_cast<double>(k) + 0.5 * static_cast<double>(j % 2)) /
                                  static_cast<double>(nj);
                add(d.xc + sx * rj * std::cos(th), d.zc + sz * rj * std::sin(th), vol);
            }
        }
    }

    // A sphere of concentric half rings (axisymmetric, a FluidDisc with rings and xc = 0):
    // N = max(1, round(R / dx)) rings at radii (j - 1/2) ds, ds = R / N, j = 1..N (no centre
    // particle: it would sit on the axis), ring j holding n_j = 2 round(pi (j - 1/2)) particles
    // on the whole circle (4, 10, 16, 22, ...), of which the n_j / 2 with x > 0 are placed; the
    // angles 2 pi (k + t) / n_j with t = 1/2 when n_j is a multiple of 4, else 0, so that no
    // particle lies on the axis and the placed half is the mirror image of the other. Each
    // carries its share of the annulus ((j - 1) ds, j ds), the area pi (2j - 1) ds^2 / n_j (within
    // 22% of ds^2 on the first ring, 6% on the second, 2% from the fourth; mass: the ring rule
    // in build()), so the outer ring lies half a spacing inside R. (Rings at j ds with no centre
    // particle leave a hole on the axis that the colour function of the CSF sees as a bubble:
    // its curvature pushed the first ring outwards.) Then the stretch of the mode-2 ellipsoid.
    void sphere_rings(const FluidDisc& d, double sx, double sz) {
        const double rho0 = p_.rho0, pi = std::numbers::pi;
        if (gravity() != 0) require_B();
        const long nrings = std::max(1L, nint(d.radius / p_.dx));
        const double ds = d.radius / static_cast<double>(nrings);
        const double ztop = d.zc + d.radius * sz, g = gravity();
        for (long j = 1; j <= nrings; ++j) {
            const double rj = (static_cast<double>(j) - 0.5) * ds;
            const long nj = 2 * nint(pi * (static_cast<double>(j) - 0.5));
            const double area = pi * static_cast<double>(2 * j - 1) * ds * ds / static_cast<double>(nj);
            const double turn = nj % 4 == 0 ? 0.5 : 0.0;
            for (long k = 0; k < nj; ++k) {
                const double th = 2 * pi * (static_cast<double>(k) + turn) / static_cast<double>(nj);
                const double x = sx * rj * std::cos(th), z = d.zc + sz * rj * std::sin(th);
                if (!(x > 0) || !clear(x, z)) continue;
                // without gravity, at the sphere's Laplace pressure 2 sigma / R (0 without
                // surface tension), so that switching the tension on starts no breathing mode
                const double rho = g == 0 ? tait_density(p_, 2 * p_.sigma / d.radius)
                                          : rho0 * std::pow(1.0 + rho0 * g * (ztop - z) / p_.B, 1.0 / p_.gamma);
                const double pr = tait_pressure(p_, rho);
                ps_.push(x, z, d.u0, d.w0, rho, pr, rho * area * sx * sz, ParticleKind::Fluid);
            }
        }
    }

    // A liquid cylinder about the axis (FluidCylinder): N = max(1, round(a / dx)) columns at
    // x_i = (i + 1/2) dr, dr = a / N, and M = max(1, round((zmax - zmin) / dz)) rows at
    // z_k = zmin + (k + 1/2) dzc, dzc = (zmax - zmin) / M (so that a periodic z closes with one
    // spacing across the ends), each column stretched by s(z) = 1 + eps cos(2 pi (z - zmin) /
    // wavelength): x = s x_i, area s dr dzc, the volume per length pi a^2 s^2. At rest, at the
    // unperturbed cylinder's Laplace pressure sigma / radius (the density of the Tait EoS),
    // so that switching the tension on starts no breathing mode: a 100 Pa mode started at
    // p = 0 dephases along z (its frequency follows r(z)) into a z-periodic pressure wave on
    // the axis 50 times the perturbation's own.
    void cylinder(const FluidCylinder& c) {
        const double pi = std::numbers::pi;
        const double rho = tait_density(p_, p_.sigma / c.radius);
        const double pr = tait_pressure(p_, rho);
        const long ncol = std::max(1L, nint(c.radius / p_.dx));
        const long nrow = std::max(1L, nint((c.zmax - c.zmin) / p_.dz));
        const double dr = c.radius / static_cast<double>(ncol);
        const double dzc = (c.zmax - c.zmin) / static_cast<double>(nrow);
        for (long i = 0; i < ncol; ++i) {
            for (long k = 0; k < nrow; ++k) {
                const double z = c.zmin + (static_cast<double>(k) + 0.5) * dzc;
                const double s = c.wavelength > 0 ? 1 + c.eps * std::cos(2 * pi * (z - c.zmin) / c.wavelength) : 1.0;
                const double x = s * (static_cast<double>(i) + 0.5) * dr;
                if (!clear(x, z)) continue;
                ps_.push(x, z, 0.0, 0.0, rho, pr, rho * s * dr * dzc, ParticleKind::Fluid);
            }
        }
    }

    const CaseSpec& spec_;
    SimParams p_;
    ParticleSet ps_;
    std::vector<WallLink> links_;
    bool repulsive_ = false, bcc_ = false, axi_ = false;
    long n_ = 0, l_ = 0;
};

void check_spec(const CaseSpec& spec) {
    const SimParams& p = spec.params;
    const std::string& where = spec.source;
    if (!(p.dx > 0) || !(p.dz > 0))
        throw InputError(where, "invalid particle spacing", "dx > 0 and dz > 0",
                         std::to_string(p.dx) + ", " + std::to_string(p.dz));
    if (!(p.lx > 0) || !(p.lz > 0))
        throw InputError(where, "invalid box size", "lx > 0 and lz > 0",
                         std::to_string(p.lx) + ", " + std::to_string(p.lz));
    // Before anything is allocated: the particles must fit 32-bit indices (the wall links,
    // legacy's files). An upper bound, in double (no overflow): the wall lines, and the
    // lattice points of each region and obstacle (twice, for BCC).
    const double nx = p.lx / p.dx, nz = p.lz / p.dz;
    const auto lattice = [&](double w, double h, double dx, double dz) {
        return (std::abs(w) / dx + 3) * (std::abs(h) / dz + 3) * 2;
    };
    double n = 4 * (nx + nz + 4);
    for (const auto& b : spec.fluid_blocks) n += lattice(b.r.xmax - b.r.xmin, b.r.zmax, p.dx, p.dz);
    for (const auto& q : spec.fluid_squares) n += lattice(q.side, q.side, p.dx, p.dz);
    for (const auto& d : spec.fluid_discs) {
        const double a = 2 * d.radius * (1 + std::abs(d.elongation));
        n += lattice(a, a, std::min(p.dx, p.dz), std::min(p.dx, p.dz));
    }
    for (const auto& c : spec.fluid_cylinders) n += lattice(c.radius, c.zmax - c.zmin, p.dx, p.dz);
    for (const auto& w : spec.walls) n += 2 * (std::abs(w.height) / p.dz + 2);
    for (const auto& g : spec.gates) n += std::abs(g.zmax - g.zmin) / p.dz + 2;
    if (spec.nozzle) n += lattice(spec.nozzle->d0 + 4 * std::max(p.dx, p.dz), spec.nozzle->length(), std::min(p.dx, p.dz), std::min(p.dx, p.dz));
    for (const auto& o : spec.obstacles) {
        const double k = std::max(1, o.density);
        n += lattice(o.r.xmax - o.r.xmin, o.r.zmax, p.dx / k, p.dz / k);
    }
    if (!(n < 2147483647.0))
        throw InputError(where, "too many particles", "at most 2147483647 (the box, regions and obstacles at this spacing)",
                         "up to " + std::to_string(n) + " (dx = " + std::to_string(p.dx) + ", dz = " +
                             std::to_string(p.dz) + ")");
    if (std::lround(static_cast<float>(p.lx) / p.dx) < 2 || std::lround(static_cast<float>(p.lz) / p.dz) < 2)
        throw InputError(where, "spacing too coarse for the box", "at least 2 spacings across lx and lz",
                         "dx = " + std::to_string(p.dx) + ", dz = " + std::to_string(p.dz));
    if (spec.floor_beta_deg != 0)
        throw InputError(where, "unsupported floor inclination", "0", std::to_string(spec.floor_beta_deg));
    if (p.boundary != BoundaryType::Repulsive && p.boundary != BoundaryType::Dynamic)
        throw InputError(where, "invalid boundary type", "repulsive (1) or dynamic (2)",
                         std::to_string(static_cast<int>(p.boundary)));
    if (p.lattice != Lattice::SimpleCubic && p.lattice != Lattice::BodyCentred)
        throw InputError(where, "invalid lattice", "SC (1) or BCC (2)", std::to_string(static_cast<int>(p.lattice)));
    if (spec.gates.size() > 1)
        throw InputError(where, "more than one gate", "at most one gate (legacy moves only the first)",
                         std::to_string(spec.gates.size()));
    for (const GateSpec& g : spec.gates) {
        // A gate that moves more than h in a step jumps over fluid particles; with a variable
        // step the core caps the step at CFL h / |v| instead.
        const double v = std::hypot(g.vx, g.vz);
        if (!p.variable_dt && p.h > 0 && v * p.dt > p.h)
            throw InputError(where, "the gate moves more than h per step at the fixed time step",
                             "|gate velocity| dt <= h = " + std::to_string(p.h) + " m (or a variable time step)",
                             "|v| = " + std::to_string(v) + " m/s, dt = " + std::to_string(p.dt) + " s");
    }
    if (spec.fluid_blocks.empty() && spec.fluid_squares.empty() && spec.fluid_discs.empty() &&
        spec.fluid_cylinders.empty() && !spec.nozzle)
        throw InputError(where, "no fluid in the case", "at least one fluid region or a nozzle", "none");
    if (spec.nozzle) {
        const NozzleSpec& nz = *spec.nozzle;
        if (!(nz.u0 > 0)) throw InputError(where, "nozzle: the jet speed must be positive", "u0 > 0", std::to_string(nz.u0));
        if (!(nz.d0 > 0) || !(nz.length() > 0))
            throw InputError(where, "nozzle: empty nozzle", "d0 > 0 and length > 0",
                             std::to_string(nz.d0) + ", " + std::to_string(nz.length()));
        if (!((nz.ex == 0 && std::abs(nz.ez) == 1) || (nz.ez == 0 && std::abs(nz.ex) == 1)))
            throw InputError(where, "nozzle: the axis must be a lattice direction", "down, up, left or right",
                             std::to_string(nz.ex) + ", " + std::to_string(nz.ez));
        // The plug is a rigid block: at least two particles across it (across its radius for
        // a round jet, whose other half is the mirror image).
        const double dl = nz.ex == 0 ? p.dx : p.dz;
        const bool round = p.geometry == Geometry::Axisymmetric;
        if (std::lround((round ? 0.5 : 1.0) * nz.d0 / dl) < 2)
            throw InputError(where, "nozzle: spacing too coarse for the orifice",
                             round ? "at least 2 particles across d0 / 2 (a round jet)" : "at least 2 particles across d0",
                             "d0 = " + std::to_string(nz.d0) + " m, spacing " + std::to_string(dl) + " m");
        if (round && (nz.ex != 0 || nz.x0 != 0))
            throw InputError(where, "nozzle: a round jet runs along the symmetry axis", "axis down or up, x0 = 0",
                             "x0 = " + std::to_string(nz.x0) + ", axis (" + std::to_string(nz.ex) + ", " +
                                 std::to_string(nz.ez) + ")");
    }
}

}  // namespace

InitialState generate(const CaseSpec& spec) {
    check_spec(spec);
    return Builder(spec).build();
}

}  // namespace sphjet
