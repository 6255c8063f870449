#include "analysis/drop.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace sphjet::analysis {

MeanSd mean_sd(std::span<const double> v) {
    MeanSd s;
    s.n = v.size();
    if (v.empty()) return s;
    for (double x : v) s.mean += x;
    s.mean /= static_cast<double>(v.size());
    for (double x : v) s.sd += (x - s.mean) * (x - s.mean);
    s.sd = std::sqrt(s.sd / static_cast<double>(v.size()));
    return s;
}

DropMeasures measure_drop(const ParticleSet& ps, std::span<const double> curvature,
                          double inner_fraction) {
    if (!curvature.empty() && curvature.size() != ps.size())
        throw std::invalid_argument("measure_drop: curvature field size differs from the particles");
    std::vector<std::size_t> fluid;
    for (std::size_t i = ps.nb; i < ps.size(); ++i)
        if (ps.kind[i] == static_cast<int>(ParticleKind::Fluid) &&
            (ps.active.empty() || ps.active[i] != 0))
            fluid.push_back(i);
    if (fluid.empty()) throw std::invalid_argument("measure_drop: no active fluid particle");

    DropMeasures d;
    d.n_fluid = fluid.size();
    double mass = 0, xmin = ps.x[fluid[0]], xmax = xmin, zmin = ps.z[fluid[0]], zmax = zmin;
    for (std::size_t i : fluid) {
        mass += ps.m[i];
        d.xc += ps.m[i] * ps.x[i];
        d.zc += ps.m[i] * ps.z[i];
        d.area += ps.m[i] / ps.rho[i];
        d.speed_max = std::max(d.speed_max, std::hypot(ps.u[i], ps.w[i]));
        xmin = std::min(xmin, ps.x[i]);
        xmax = std::max(xmax, ps.x[i]);
        zmin = std::min(zmin, ps.z[i]);
        zmax = std::max(zmax, ps.z[i]);
    }
    d.xc /= mass;
    d.zc /= mass;
    d.extent_x = xmax - xmin;
    d.extent_z = zmax - zmin;
    d.r_eq = std::sqrt(d.area / std::numbers::pi);
    d.spacing = std::sqrt(d.area / static_cast<double>(fluid.size()));

    // sectors of about two spacings of arc at r_eq (one spacing leaves some sectors without a
    // particle of the outer row)
    const auto nsec = static_cast<std::size_t>(
        std::max(8.0, std::floor(std::numbers::pi * d.r_eq / d.spacing)));
    std::vector<double> r(fluid.size());
    std::vector<std::size_t> sec(fluid.size());
    std::vector<double> edge(nsec, -1.0);
    for (std::size_t k = 0; k < fluid.size(); ++k) {
        const std::size_t i = fluid[k];
        const double dx = ps.x[i] - d.xc, dz = ps.z[i] - d.zc;
        r[k] = std::hypot(dx, dz);
        double th = std::atan2(dz, dx) / (2 * std::numbers::pi);
        if (th < 0) th += 1.0;
        sec[k] = std::min(nsec - 1, static_cast<std::size_t>(th * static_cast<double>(nsec)));
        edge[sec[k]] = std::max(edge[sec[k]], r[k]);
        d.ixx += ps.m[i] * dx * dx;
        d.izz += ps.m[i] * dz * dz;
        d.ixz += ps.m[i] * dx * dz;
    }
    d.deformation = d.ixx + d.izz > 0 ? (d.ixx - d.izz) / (d.ixx + d.izz) : 0.0;
    d.r_max = 0;
    d.r_min = std::numeric_limits<double>::infinity();
    for (double e : edge)
        if (e >= 0) {
            d.r_max = std::max(d.r_max, e);
            d.r_min = std::min(d.r_min, e);
        }

    std::vector<double> p_in, p_s, k_s;
    for (std::size_t k = 0; k < fluid.size(); ++k) {
        const std::size_t i = fluid[k];
        if (r[k] < inner_fraction * d.r_eq) p_in.push_back(ps.p[i]);
        if (r[k] >= edge[sec[k]] - 0.5 * d.spacing) {
            p_s.push_back(ps.p[i]);
            if (!curvature.empty()) k_s.push_back(curvature[i]);
        }
        if (!curvature.empty() && curvature[i] != 0.0) ++d.n_with_normal;
    }
    d.p_inner = mean_sd(p_in);
    d.p_surface = mean_sd(p_s);
    if (!curvature.empty()) d.kappa_surface = mean_sd(k_s);
    return d;
}

Oscillation oscillation(std::span<const double> t, std::span<const double> d, double skip_before,
                        double noise_fraction) {
    if (t.size() != d.size()) throw std::invalid_argument("oscillation: t and d differ in size");
    std::vector<double> tt, dd;
    for (std::size_t k = 0; k < t.size(); ++k)
        if (t[k] >= skip_before) {
            tt.push_back(t[k]);
            dd.push_back(d[k]);
        }
    Oscillation o;
    if (tt.size() < 3) return o;
    o.mean = mean_sd(dd).mean;
    for (double& v : dd) v -= o.mean;
    std::vector<double> cross;
    std::vector<std::size_t> cross_at;  // index of the sample after the crossing
    for (std::size_t k = 1; k < tt.size(); ++k) {
        if ((dd[k - 1] < 0) != (dd[k] < 0)) {
            const double f = dd[k - 1] / (dd[k - 1] - dd[k]);
            cross.push_back(tt[k - 1] + f * (tt[k] - tt[k - 1]));
            cross_at.push_back(k);
        }
    }
    // extrema between successive crossings (and before the first one); half-cycle c ends at
    // crossing c
    std::vector<double> te, la;
    std::vector<std::size_t> te_cycle;
    std::size_t begin = 0;
    for (std::size_t c = 0; c < cross_at.size(); ++c) {  // the last half-cycle may be incomplete
        const std::size_t end = cross_at[c];
        std::size_t best = begin;
        for (std::size_t k = begin; k < end; ++k)
            if (std::abs(dd[k]) > std::abs(dd[best])) best = k;
        // an extremum on the edge of the series is not a peak
        if (best > 0 && std::abs(dd[best]) > 0) {
            te.push_back(tt[best]);
            la.push_back(std::log(std::abs(dd[best])));
            te_cycle.push_back(c);
        }
        begin = end;
    }
    // Noise floor: a crossing is the oscillation's only while the half-cycles on both sides of
    // it reach noise_fraction of the first extremum (the trailing, incomplete half-cycle
    // included); from the first crossing that fails on, the oscillation has decayed into the
    // noise, and that crossing, the later ones and their extrema are dropped.
    if (!la.empty() && noise_fraction > 0) {
        const double floor = noise_fraction * std::exp(la.front());
        std::vector<double> amp(cross_at.size() + 1, 0.0);  // largest |d| per half-cycle
        for (std::size_t c = 0, k = 0; c <= cross_at.size(); ++c) {
            const std::size_t end = c < cross_at.size() ? cross_at[c] : tt.size();
            for (; k < end; ++k) amp[c] = std::max(amp[c], std::abs(dd[k]));
        }
        for (std::size_t c = 0; c < cross_at.size(); ++c) {
            if (amp[c] < floor || amp[c + 1] < floor) {
                cross.resize(c);
                std::size_t keep = 0;
                while (keep < te_cycle.size() && te_cycle[keep] < c) ++keep;
                te.resize(keep);
                la.resize(keep);
                break;
            }
        }
    }
    o.crossings = cross.size();
    if (cross.size() >= 2)
        o.period = 2.0 * (cross.back() - cross.front()) / static_cast<double>(cross.size() - 1);
    if (!la.empty()) o.amplitude0 = std::exp(la.front());
    if (te.size() >= 2) {
        double mt = 0, ml = 0;
        for (std::size_t k = 0; k < te.size(); ++k) {
            mt += te[k];
            ml += la[k];
        }
        mt /= static_cast<double>(te.size());
        ml /= static_cast<double>(te.size());
        double num = 0, den = 0;
        for (std::size_t k = 0; k < te.size(); ++k) {
            num += (te[k] - mt) * (la[k] - ml);
            den += (te[k] - mt) * (te[k] - mt);
        }
        if (den > 0) o.decay_rate = -num / den;
    }
    return o;
}

}  // namespace sphjet::analysis
