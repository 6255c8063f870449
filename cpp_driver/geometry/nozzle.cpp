#include "geometry/nozzle.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "model/tait.hpp"

namespace sphjet {

NozzleLayout nozzle_layout(const NozzleSpec& nz, double dx, double dz, bool dynamic, double recess,
                           bool axisymmetric) {
    // Spacings along and across the axis: the axis is one of the lattice directions.
    const bool vertical = nz.ex == 0.0;
    if (axisymmetric && (!vertical || nz.x0 != 0.0))
        throw std::invalid_argument("nozzle_layout: a round nozzle runs along the axis x = 0");
    const double ds = vertical ? dz : dx;
    const double dl_lattice = vertical ? dx : dz;
    // Particles across the orifice (planar) or across its radius (axisymmetric).
    const double span = axisymmetric ? 0.5 * nz.d0 : nz.d0;
    const long n_across = std::max(1L, std::lround(span / dl_lattice));
    const long m_along = std::max(1L, std::lround(nz.length() / ds));
    const double dl = span / static_cast<double>(n_across);
    const double lx = -nz.ez, lz = nz.ex;  // CCW(e)
    const auto at = [&](double s, double l) {
        return NozzlePoint{nz.x0 + s * nz.ex + l * lx, nz.z0 + s * nz.ez + l * lz};
    };

    NozzleLayout out;
    out.spacing_across = dl;
    out.spacing_along = ds;
    // The starting column's rows (nozzle.column_over_d0), past the orifice on the plug's lattice.
    const long c_along = std::lround(nz.column() / ds);
    out.fluid.reserve(static_cast<std::size_t>(n_across * (m_along + c_along)));
    // l of the first column: the edge of the orifice (planar) or the axis (axisymmetric).
    // The axis's direction CCW(e) is +x for a jet going up and -x going down: the rings
    // stand on the side r = x >= 0.
    const double side_r = axisymmetric ? (lx > 0 ? 1.0 : -1.0) : 1.0;
    const double l_first = axisymmetric ? 0.0 : -0.5 * nz.d0;
    const auto row = [&](double s) {
        for (long j = 0; j < n_across; ++j)
            out.fluid.push_back(at(s, side_r * (l_first + (static_cast<double>(j) + 0.5) * dl)));
    };
    // The plug's rows at s = -(k + 1/2) ds, then the column's at s = +(k + 1/2) ds.
    for (long k = 0; k < m_along; ++k) row(-(static_cast<double>(k) + 0.5) * ds);
    for (long k = 0; k < c_along; ++k) row((static_cast<double>(k) + 0.5) * ds);
    if (!nz.walls) return out;

    const double off = 0.5 * nz.d0 + 0.5 * dl;
    const long k0 = std::min(m_along, static_cast<long>(std::ceil(recess / ds - 1e-9)));
    for (const double side : {1.0, -1.0}) {
        if (axisymmetric && side != side_r) continue;  // the other side is the mirror image
        NozzleWall inner;
        // The +l wall's normal must point to -l: its points run along e, whose CCW is +l,
        // so its links are reversed (Builder::link_line); the -l wall's are not.
        inner.reversed = side > 0;
        for (long k = m_along; k >= k0; --k) inner.points.push_back(at(-static_cast<double>(k) * ds, side * off));
        out.walls.push_back(std::move(inner));
        if (dynamic) {
            NozzleWall outer;
            for (long k = m_along; k >= k0; --k)
                outer.points.push_back(at(-(static_cast<double>(k) + 0.5) * ds, side * (off + 0.5 * dl)));
            out.walls.push_back(std::move(outer));
        }
    }
    return out;
}

double nozzle_profile_k(const NozzleSpec& nz, double dx, double dz, bool axisymmetric) {
    const NozzleLayout lay = nozzle_layout(nz, dx, dz, false, 0.0, axisymmetric);
    const double a = 0.5 * nz.d0;
    const long n_across = std::lround((axisymmetric ? a : nz.d0) / lay.spacing_across);
    double flux = 0, shaped = 0;
    for (long j = 0; j < n_across; ++j) {
        const double l = std::abs((axisymmetric ? 0.0 : -a) + (static_cast<double>(j) + 0.5) * lay.spacing_across);
        const double w = axisymmetric ? l : 1.0;
        flux += w;
        shaped += w * (1.0 - (l / a) * (l / a));
    }
    return flux / shaped;
}

PlugState plug_state(const SimParams& prm, const NozzleSpec& nz) {
    const double rho = prm.geometry == Geometry::Axisymmetric ? tait_density(prm, 2 * prm.sigma / nz.d0) : prm.rho0;
    return {rho, tait_pressure(prm, rho)};
}

ParticleSet nozzle_refill_rows(const NozzleSpec& nz, double dx, double dz, double half_width, const PlugState& built,
                               const ParticleSet& ps) {
    const double ds = nz.ex == 0.0 ? dz : dx;
    const double s_back = -(static_cast<double>(std::max(1L, std::lround(nz.length() / ds))) - 0.5) * ds;
    const auto axial = [&](std::size_t i) { return (ps.x[i] - nz.x0) * nz.ex + (ps.z[i] - nz.z0) * nz.ez; };
    const double dl = nz.ex == 0.0 ? dx : dz;
    // The line (lattice column) of a plug particle: its signed distance from the axis in half
    // spacings across (the lattice's lines are two apart, whether they sit on integers or not).
    const auto line = [&](std::size_t i) {
        return std::lround(2.0 * ((ps.x[i] - nz.x0) * nz.ez - (ps.z[i] - nz.z0) * nz.ex) / dl);
    };
    std::vector<std::size_t> plug;
    std::vector<std::pair<long, double>> s_min;  // each line's hindmost s
    const auto line_min = [&](long c) -> double* {
        for (auto& [line_c, s] : s_min)
            if (line_c == c) return &s;
        return nullptr;
    };
    for (std::size_t i = ps.nb; i < ps.size(); ++i) {
        if (ps.kind[i] != static_cast<int>(ParticleKind::Fluid) || (!ps.active.empty() && ps.active[i] == 0)) continue;
        const double s = axial(i);
        const double l = std::abs((ps.x[i] - nz.x0) * nz.ez - (ps.z[i] - nz.z0) * nz.ex);
        if (!(s < 0.0) || l > half_width) continue;
        if (double* m = line_min(line(i))) {
            *m = std::min(*m, s);
        } else {
            s_min.emplace_back(line(i), s);
        }
        plug.push_back(i);
    }
    ParticleSet rows;
    if (plug.empty()) return rows;
    // Each line's back: its plug particles within a quarter spacing of its most upstream one,
    // for the lines that reach back to within two spacings of where the back row was built
    // (fluid that came back into the strip near the orifice is not a line of the plug).
    std::vector<std::size_t> back;
    for (const std::size_t i : plug) {
        const double m = *line_min(line(i));
        if (m < s_back + 2.0 * ds && axial(i) < m + 0.25 * ds) back.push_back(i);
    }
    for (int k = 1;; ++k) {
        bool any = false;
        for (const std::size_t i : back) {
            if (!(*line_min(line(i)) - k * ds >= s_back - 1e-6 * ds)) continue;
            any = true;
            (void)rows.push(ps.x[i] - k * ds * nz.ex, ps.z[i] - k * ds * nz.ez, ps.u[i], ps.w[i], built.rho,
                            built.p, ps.m[i], ParticleKind::Fluid);
        }
        if (!any) break;
    }
    return rows;
}

}  // namespace sphjet
