#include "analysis/jet_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "analysis/breakup.hpp"

namespace sphjet::analysis {

JetMonitor::JetMonitor(const NozzleSpec& nozzle, const BreakupSpec& breakup, double h, double rho0, double ds,
                       bool round)
    : nz_(nozzle), h_(h), link_(breakup.link_over_h * h), band_(breakup.band_over_d0 * nozzle.d0), rho0_(rho0),
      ds_(ds), round_(round) {
    if (!(h > 0) || !(link_ > 0) || !(band_ > 0) || !(nz_.d0 > 0) || !(rho0 > 0) || !(ds > 0))
        throw std::invalid_argument("JetMonitor: h, link, band, d0, rho0 and the spacing must be positive");
}

double JetMonitor::orifice_measure() const {
    return round_ ? 0.25 * std::numbers::pi * nz_.d0 * nz_.d0 : nz_.d0;
}

double JetMonitor::crossing_volume(const ParticleSet& ps) {
    double v = 0;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (ps.kind[i] != static_cast<int>(ParticleKind::Fluid)) continue;
        if (!out_[i]) {
            if (!ps.active.empty() && ps.active[i] == 0) continue;
            const double s = axial(ps.x[i], ps.z[i]);
            const double f = s / ds_ + 0.5;
            if (f <= 0) continue;
            if (f < 1) {
                v += f * ps.m[i] / rho0_;
                continue;
            }
            out_[i] = 1;
        }
        v += ps.m[i] / rho0_;
    }
    return v;
}

void JetMonitor::restore(double volume_out, double time) {
    volume_out_ = volume_out;
    last_time_ = time;
}

void JetMonitor::start(const ParticleSet& ps, double time) {
    out_.assign(ps.size(), 0);
    // A resumed run: the particles already out (removed ones too: they left downstream).
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (ps.kind[i] != static_cast<int>(ParticleKind::Fluid)) continue;
        const double s = axial(ps.x[i], ps.z[i]);
        if (s >= 0.5 * ds_ || (!ps.active.empty() && ps.active[i] == 0)) out_[i] = 1;
    }
    volume_out_ = crossing_volume(ps);
    last_time_ = time;
}

JetSample JetMonitor::sample(const ParticleSet& ps, double time, std::int64_t step) {
    if (out_.empty() || out_.size() > ps.size()) start(ps, time);
    out_.resize(ps.size(), 0);  // particles appended since the last sample (nozzle.refill) are upstream
    JetSample r;
    r.time = time;
    r.step = step;
    const double ex = nz_.ex, ez = nz_.ez;  // for the breakup axis

    double usum = 0;
    std::size_t un = 0;
    ParticleSet down;  // fluid downstream of the orifice, for the clusters
    std::vector<double> down_s, down_l;  // their axial and (absolute) lateral coordinates
    std::vector<std::size_t> down_i;     // their indices in ps
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (ps.kind[i] != static_cast<int>(ParticleKind::Fluid)) continue;
        if (!ps.active.empty() && ps.active[i] == 0) continue;
        const double s = axial(ps.x[i], ps.z[i]);
        const double l = std::abs(lateral(ps.x[i], ps.z[i]));
        if (s < 0) {
            if (l <= 0.5 * nz_.d0 + 0.25 * ds_ && s >= -nz_.length() - ds_) ++r.in_nozzle;
            continue;
        }
        if (s < h_ && l <= 0.5 * nz_.d0) {
            usum += ps.u[i] * ex + ps.w[i] * ez;
            ++un;
        }
        down.push(ps.x[i], ps.z[i], ps.u[i], ps.w[i], ps.rho[i], ps.p[i], ps.m[i], ParticleKind::Fluid);
        down_s.push_back(s);
        down_l.push_back(l);
        down_i.push_back(i);
    }
    const double v = crossing_volume(ps);
    r.volume_out = v;
    const double dt = time - last_time_;
    r.flux = dt > 0 ? (v - volume_out_) / dt : 0.0;
    volume_out_ = v;
    r.u_flux = r.flux / orifice_measure();
    r.u_orifice = un > 0 ? usum / static_cast<double>(un) : 0.0;
    last_time_ = time;

    r.length = breakup_length(down, Axis{nz_.x0, nz_.z0, ex, ez}, band_, link_);

    if (down.size() == 0) return r;
    std::vector<int> labels;
    const std::vector<Cluster> cl = label_clusters(down, link_, {}, &labels);
    std::vector<Drop> d(cl.size());
    for (std::size_t c = 0; c < cl.size(); ++c) d[c].particles = cl[c].size, d[c].xc = cl[c].xc, d[c].zc = cl[c].zc;
    // A round drop's centroid: the rings' centres lie on the axis.
    if (round_)
        for (Drop& q : d) q.xc = nz_.x0;
    std::vector<char> seen(cl.size(), 0);
    std::size_t nearest = 0;
    for (std::size_t k = 0; k < down.size(); ++k) {
        const auto c = static_cast<std::size_t>(labels[k]);
        Drop& q = d[c];
        q.size += down.m[k] / down.rho[k];
        q.s_max = seen[c] ? std::max(q.s_max, down_s[k]) : down_s[k];
        q.s_min = seen[c] ? std::min(q.s_min, down_s[k]) : down_s[k];
        seen[c] = 1;
        // The jet: the cluster of the particle nearest the orifice within the band.
        if (down_l[k] <= band_ && (down_l[nearest] > band_ || down_s[k] < down_s[nearest])) nearest = k;
    }
    const auto jet = static_cast<std::size_t>(labels[nearest]);
    r.jet_tip = d[jet].s_max;
    for (std::size_t k = 0; k < down.size(); ++k)
        if (static_cast<std::size_t>(labels[k]) != jet) d[static_cast<std::size_t>(labels[k])].members.push_back(down_i[k]);
    neck(down_s, down_l, labels, static_cast<int>(jet), r);
    exit_noise(down, down_s, labels, static_cast<int>(jet), r);
    for (std::size_t c = 0; c < d.size(); ++c) {
        Drop& q = d[c];
        q.d_eq = round_ ? std::cbrt(6.0 * q.size / std::numbers::pi) : 2.0 * std::sqrt(q.size / std::numbers::pi);
        q.satellite = q.d_eq < nz_.d0;
        if (c != jet) r.drops.push_back(std::move(q));
    }
    std::sort(r.drops.begin(), r.drops.end(), [](const Drop& a, const Drop& b) { return a.s_max > b.s_max; });
    return r;
}

void JetMonitor::neck(const std::vector<double>& s, const std::vector<double>& l, const std::vector<int>& labels,
                      int jet, JetSample& r) const {
    const double end = r.jet_tip - nz_.d0;
    if (!(end > 0)) return;
    const auto slices = static_cast<std::size_t>(std::floor(end / ds_)) + 1;
    std::vector<double> reach(slices, -1.0);  // largest |l| per slice; < 0: none there
    std::vector<double> at(slices, 0.0);      // s of that particle
    for (std::size_t k = 0; k < s.size(); ++k) {
        if (labels[k] != jet || s[k] > end) continue;
        const auto i = static_cast<std::size_t>(s[k] / ds_);
        if (l[k] > reach[i]) reach[i] = l[k], at[i] = s[k];
    }
    // The surface profile: the straight lines through the slices' widest rings, read at the
    // slices' centres. A slice one spacing wide holds one row of rings or two, or none of the
    // outer ring's when the rows are a little stretched: its widest ring is then an inner one,
    // a ring spacing below the line through its neighbours, and is passed over (below the line
    // by more than half a spacing, again until none is: a surface bends that much between two
    // rings only where it pinches on the particles' scale). Through the rings themselves the
    // profile of a tapering jet is smooth; a largest radius per slice would step by the taper
    // over a spacing as the rows move through the slices, and read that as a disturbance.
    std::vector<std::size_t> keep;
    for (std::size_t i = 0; i < slices; ++i)
        if (reach[i] >= 0) keep.push_back(i);
    for (bool dropped = true; dropped && keep.size() > 2;) {
        dropped = false;
        std::vector<std::size_t> kept{keep.front()};
        for (std::size_t j = 1; j + 1 < keep.size(); ++j) {
            const std::size_t a = kept.back(), i = keep[j], b = keep[j + 1];  // at[a] < at[i] < at[b]
            const double line = reach[a] + (reach[b] - reach[a]) * (at[i] - at[a]) / (at[b] - at[a]);
            if (reach[i] < line - 0.5 * ds_) {
                dropped = true;
                continue;
            }
            kept.push_back(i);
        }
        kept.push_back(keep.back());
        keep = std::move(kept);
    }
    r.surface.assign(slices, std::numeric_limits<double>::quiet_NaN());
    std::size_t j = 0;  // keep[j] is the last kept slice at or before the centre
    for (std::size_t i = 0; i < slices; ++i) {
        const bool near = reach[i] >= 0 || (i > 0 && reach[i - 1] >= 0) || (i + 1 < slices && reach[i + 1] >= 0);
        if (!near) continue;  // a gap the link bridged across (else a ring nearby was kept)
        const double c = (static_cast<double>(i) + 0.5) * ds_;
        while (j + 1 < keep.size() && at[keep[j + 1]] <= c) ++j;
        const std::size_t a = keep[j];
        double widest = reach[a];
        if (at[a] <= c && j + 1 < keep.size()) {
            const std::size_t b = keep[j + 1];
            widest += (reach[b] - reach[a]) * (c - at[a]) / (at[b] - at[a]);
        }
        r.surface[i] = widest + 0.5 * ds_;
    }
    for (std::size_t i = 0; i < slices; ++i) {
        if (reach[i] < 0) continue;  // an empty slice: a gap the link bridged across
        const double radius = reach[i] + 0.5 * ds_;
        if (!r.neck_r || radius < *r.neck_r) {
            r.neck_r = radius;
            r.neck_s = (static_cast<double>(i) + 0.5) * ds_;
        }
    }
}

void JetMonitor::exit_noise(const ParticleSet& down, const std::vector<double>& s, const std::vector<int>& labels,
                            int jet, JetSample& r) const {
    // Two passes (mean, then spread about it): the spread is small against the mean.
    double psum = 0, usum = 0;
    std::size_t n = 0;
    for (std::size_t k = 0; k < s.size(); ++k) {
        if (labels[k] != jet || s[k] >= 2.0 * nz_.d0) continue;
        psum += down.p[k];
        const double ul = down.u[k] * nz_.ez - down.w[k] * nz_.ex;  // across the axis
        usum += ul * ul;
        ++n;
    }
    if (n == 0) return;
    const double mean = psum / static_cast<double>(n);
    double var = 0;
    for (std::size_t k = 0; k < s.size(); ++k)
        if (labels[k] == jet && s[k] < 2.0 * nz_.d0) var += (down.p[k] - mean) * (down.p[k] - mean);
    r.exit_n = n;
    r.exit_p_mean = mean;
    r.exit_p_std = std::sqrt(var / static_cast<double>(n));
    r.exit_ul_rms = std::sqrt(usum / static_cast<double>(n));
}

JetGroups jet_groups(double rho, double u0, double d0, double sigma, double mu, double g) {
    JetGroups j;
    const double r = 0.5 * d0;
    j.we = sigma > 0 ? rho * u0 * u0 * r / sigma : 0.0;
    j.re = mu > 0 ? rho * u0 * r / mu : 0.0;
    j.oh = j.re > 0 ? std::sqrt(j.we) / j.re : 0.0;
    j.fr = g > 0 ? u0 / std::sqrt(g * d0) : 0.0;
    j.eq37 = 13.0 * std::sqrt(j.we) * (1.0 + 3.0 * j.oh);
    j.we_d = 2.0 * j.we;
    j.oh_d = j.oh / std::sqrt(2.0);
    j.eq37_d = 13.0 * std::sqrt(j.we_d) * (1.0 + 3.0 * j.oh_d);
    return j;
}

std::string jet_csv_header() {
    return "time,step,volume_out,flux,u_flux,u_orifice,broken,L,L_over_d0,jet_tip_over_d0,n_drops,"
           "head_drop_d_over_d0,largest_drop_d_over_d0,n_satellites,neck_r_over_d0,neck_s_over_d0,n_exit,p_exit_mean,"
           "p_exit_std,ur_exit_rms";
}

std::string jet_csv_row(const JetSample& s, double d0) {
    double head = 0, largest = 0;
    std::size_t satellites = 0;
    if (!s.drops.empty()) head = s.drops.front().d_eq / d0;
    for (const Drop& q : s.drops) largest = std::max(largest, q.d_eq / d0), satellites += q.satellite ? 1 : 0;
    // No neck (a jet shorter than d0): NaN, which the report and ParaView read as missing.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // No exit particles: NaN pressure and velocity.
    const bool ex = s.exit_n > 0;
    return fmt::format("{:.17g},{},{:.17g},{:.9g},{:.9g},{:.9g},{},{:.9g},{:.9g},{:.9g},{},{:.9g},{:.9g},{},{:.9g},{:.9g},"
                       "{},{:.9g},{:.9g},{:.9g}",
                       s.time, s.step, s.volume_out, s.flux, s.u_flux, s.u_orifice, s.length ? 1 : 0,
                       s.length.value_or(0.0), s.length.value_or(0.0) / d0, s.jet_tip / d0, s.drops.size(), head,
                       largest, satellites, s.neck_r.value_or(nan) / d0, s.neck_s.value_or(nan) / d0, s.exit_n,
                       ex ? s.exit_p_mean : nan, ex ? s.exit_p_std : nan, ex ? s.exit_ul_rms : nan);
}

std::string drops_csv_header(bool round) {
    return round ? "time,step,drop,particles,volume,d_eq_over_d0,xc,zc,s_max_over_d0,satellite"
                 : "time,step,drop,particles,area,d_eq_over_d0,xc,zc,s_max_over_d0,satellite";
}

std::string drops_csv_rows(const JetSample& s, double d0) {
    std::string out;
    for (std::size_t k = 0; k < s.drops.size(); ++k) {
        const Drop& q = s.drops[k];
        out += fmt::format("{:.9g},{},{},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{}\n", s.time, s.step, k, q.particles,
                           q.size, q.d_eq / d0, q.xc, q.zc, q.s_max / d0, q.satellite ? 1 : 0);
    }
    return out;
}

std::string surface_csv_header() { return "time,step,s_over_d0,r_over_d0"; }

std::string surface_csv_rows(const JetSample& s, double d0, double ds) {
    std::string out;
    for (std::size_t i = 0; i < s.surface.size(); ++i) {
        if (std::isnan(s.surface[i])) continue;
        out += fmt::format("{:.9g},{},{:.6g},{:.9g}\n", s.time, s.step, (static_cast<double>(i) + 0.5) * ds / d0,
                           s.surface[i] / d0);
    }
    return out;
}

}  // namespace sphjet::analysis
