#include "core/jet_run.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "geometry/nozzle.hpp"
#include "io/file_write.hpp"
#include "io/jet_output.hpp"
#include "model/errors.hpp"

namespace fs = std::filesystem;

namespace sphjet {

namespace {

// Splits a CSV line into fields.
std::vector<std::string> fields(const std::string& line) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
    return f;
}

// Keeps the header and the whole rows (ended by a newline, as many fields as the header)
// whose step (column 2) is at most `step`; returns the kept rows.
std::vector<std::vector<std::string>> keep_until(const fs::path& file, std::int64_t step) {
    std::vector<std::vector<std::string>> rows;
    if (!fs::exists(file)) return rows;
    std::ifstream in(file, std::ios::binary);
    std::string header, line;
    std::getline(in, header);
    const std::size_t nfields = fields(header).size();
    std::string kept = header + "\n";
    while (std::getline(in, line)) {
        if (in.eof()) break;  // no newline after it: a torn last row
        const auto f = fields(line);
        if (f.size() != nfields) break;
        try {
            if (std::stoll(f[1]) > step) break;
        } catch (const std::exception&) {
            break;
        }
        kept += line + "\n";
        rows.push_back(f);
    }
    in.close();
    write_file_atomically(file, kept, "the jet table");
    return rows;
}

}  // namespace

JetRun::JetRun(const CaseSpec& spec, const fs::path& dir, bool resume, const ParticleSet& ps, double time,
               std::int64_t step, Log log)
    : spec_(spec), dir_(dir),
      mon_(*spec.nozzle, spec.breakup.value_or(BreakupSpec{}), spec.params.h, spec.params.rho0,
           spec.nozzle->ex == 0 ? spec.params.dz : spec.params.dx, spec.params.geometry == Geometry::Axisymmetric),
      log_(std::move(log)) {
    if (spec.breakup) {
        remove_below_ = spec.breakup->remove_drops_below_h * spec.params.h;
        remove_beyond_ = spec.breakup->remove_drops_beyond_d0 * spec.nozzle->d0;
    }
    if (resume) {
        const auto rows = keep_until(dir_ / "jet.csv", step);
        (void)keep_until(dir_ / "drops.csv", step);
        (void)keep_until(dir_ / "jet_surface.csv", step);
        for (const auto& r : rows) {
            if (!first_time_ && r.at(6) == "1") first_time_ = std::stod(r.at(0)), first_length_ = std::stod(r.at(7));
            count_orifice_speed(std::stod(r.at(4)), std::stod(r.at(9)) >= 1.0 || r.at(6) == "1");
        }
        if (!rows.empty()) last_row_ = std::pair{std::stod(rows.back().at(2)), std::stod(rows.back().at(0))};
        if (removes())
            for (const auto& r : keep_until(dir_ / "removed_drops.csv", step)) {
                const bool sunk = r.size() > 7 && r.at(7) == "beyond_d0";
                ++(sunk ? sunk_drops_ : small_drops_);
                removed_particles_ += std::stoll(r.at(2));
            }
    }
    jet_csv_.emplace(dir_ / "jet.csv", "the jet table", resume, analysis::jet_csv_header() + "\n");
    drops_csv_.emplace(dir_ / "drops.csv", "the drops table", resume, analysis::drops_csv_header(mon_.round()) + "\n");
    surface_csv_.emplace(dir_ / "jet_surface.csv", "the jet surface table", resume,
                         analysis::surface_csv_header() + "\n");
    if (removes())
        removed_csv_.emplace(dir_ / "removed_drops.csv", "the removed drops table", resume,
                             std::string(mon_.round() ? "time,step,particles,volume,d_eq_over_d0,xc,zc,rule"
                                                      : "time,step,particles,area,d_eq_over_d0,xc,zc,rule") +
                                 "\n");
    mon_.start(ps, time);
    if (last_row_) mon_.restore(last_row_->first, last_row_->second);
    next_check_ = next_check_after(time);
}

double JetRun::next_check_after(double time) const {
    const double every = spec_.breakup ? spec_.breakup->check_every : 0.0;
    return every > 0 ? (std::floor(time / every + 1e-9) + 1) * every : 0.0;
}

// The orifice speed counts once the jet has left the nozzle by d0 (or has broken).
void JetRun::count_orifice_speed(double u_flux, bool out) {
    if (!out) return;
    u_sum_ += u_flux;
    ++u_n_;
    u_dev_max_ = std::max(u_dev_max_, std::abs(u_flux / spec_.nozzle->u0 - 1.0));
}

JetRun::Check JetRun::sample(const ParticleSet& ps, double time, std::int64_t step) {
    const double d0 = spec_.nozzle->d0;
    const analysis::JetSample s = mon_.sample(ps, time, step);
    jet_csv_->append(analysis::jet_csv_row(s, d0) + "\n");
    if (!s.drops.empty()) drops_csv_->append(analysis::drops_csv_rows(s, d0));
    if (!s.surface.empty()) surface_csv_->append(analysis::surface_csv_rows(s, d0, mon_.slice()));
    count_orifice_speed(s.u_flux, s.jet_tip >= d0 || s.length);
    if (s.in_nozzle == 0 && !dry_time_) dry_time_ = time;
    if (s.length && !first_time_) {
        first_time_ = time;
        first_length_ = *s.length;
        log_(fmt::format("jet broken at t = {:.6g} s (step {}): L = {:.6g} m, L/D0 = {:.4g}; {}", time, step,
                         *s.length, *s.length / d0,
                         s.drops.empty() ? std::string("no detached cluster (the gap is bridged off the axis)")
                                         : fmt::format("{} drop(s), the head drop {:.3g} D0 across", s.drops.size(),
                                                       s.drops.front().d_eq / d0)));
    }
    // Drops below remove_below_, and once the jet is broken those wholly beyond its end by
    // remove_beyond_ (never the jet: s.drops holds the other clusters only). The choice reads
    // the state at this check alone, which a checkpoint holds: a resumed run removes the same
    // drops at the same steps.
    Check c{.sampled = true, .length = s.length,
            .reach = renormalise_reach(s.length, spec_.params.renormalise_margin_d0, d0), .gone = {}};
    std::vector<std::size_t>& gone = c.gone;
    const double h = spec_.params.h;
    for (const analysis::Drop& q : s.drops) {
        const bool small = remove_below_ > 0 && q.d_eq < remove_below_;
        const bool beyond = remove_beyond_ > 0 && s.length && q.s_min > *s.length + remove_beyond_;
        if (!small && !beyond) continue;
        removed_csv_->append(fmt::format("{:.9g},{},{},{:.9g},{:.9g},{:.9g},{:.9g},{}\n", time, step, q.particles,
                                         q.size, q.d_eq / d0, q.xc, q.zc, small ? "below_h" : "beyond_d0"));
        // The sink removes a drop at nearly every pinch-off: counted at the end, not logged.
        if (small)
            log_(fmt::format("step {} t = {:.6g} s: removed a drop of {} particles, d_eq = {:.3g} D0 = {:.3g} h "
                             "< {:g} h, at x = {:.6g} m, z = {:.6g} m ({:.3g} D0 from the orifice)",
                             step, time, q.particles, q.d_eq / d0, q.d_eq / h, spec_.breakup->remove_drops_below_h,
                             q.xc, q.zc, q.s_max / d0));
        ++(small ? small_drops_ : sunk_drops_);
        removed_particles_ += static_cast<std::int64_t>(q.particles);
        gone.insert(gone.end(), q.members.begin(), q.members.end());
    }
    return c;
}

JetRun::Check JetRun::after_step(const ParticleSet& ps, double time, std::int64_t step, bool output_written) {
    const double every = spec_.breakup ? spec_.breakup->check_every : 0.0;
    if (every > 0) {
        if (time + 1e-12 >= next_check_) {
            next_check_ = next_check_after(time);
            return sample(ps, time, step);
        }
    } else if (output_written) {
        return sample(ps, time, step);
    }
    return {};
}

ParticleSet JetRun::refill(const ParticleSet& ps) const {
    if (!spec_.nozzle->refill) return {};
    const SimParams& p = spec_.params;
    return nozzle_refill_rows(*spec_.nozzle, p.dx, p.dz, p.drive_half_width, plug_state(p, *spec_.nozzle), ps);
}

std::string JetRun::stop_due(double time) const {
    if (spec_.breakup && spec_.breakup->stop_after >= 0 && first_time_ &&
        time >= *first_time_ + spec_.breakup->stop_after)
        return fmt::format("[breakup] stop_after = {:g} s after the first breakup (t = {:.6g} s)",
                           spec_.breakup->stop_after, *first_time_);
    if (dry_time_)
        return fmt::format("the nozzle ran dry at t = {:.6g} s (its {:g} d0 of fluid have left at u0 = {:g} m/s)",
                           *dry_time_, spec_.nozzle->length_over_d0, spec_.nozzle->u0);
    return {};
}

void JetRun::finish(bool hdf5) {
    const NozzleSpec& nz = *spec_.nozzle;
    if (u_n_ > 0)
        log_(fmt::format("jet: orifice speed (flux / {}) {:.5g} m/s on average over {} samples, u0 = {:.5g} m/s "
                         "requested ({:+.2f}%; largest sample deviation {:.2f}%)",
                         mon_.round() ? "orifice area" : "D0", u_sum_ / static_cast<double>(u_n_), u_n_, nz.u0,
                         100.0 * (u_sum_ / static_cast<double>(u_n_) / nz.u0 - 1.0), 100.0 * u_dev_max_));
    const SimParams& p = spec_.params;
    const double mu = p.viscosity == ViscosityModel::Laminar ? p.visc_value * p.rho0 : 0.0;
    const auto g = analysis::jet_groups(p.rho0, nz.u0, nz.d0, p.sigma, mu, std::hypot(p.gx, p.gz));
    // A round jet is compared with the diameter-based form as well (jet_monitor.hpp).
    const std::string eq37 =
        mon_.round() ? fmt::format("eq 37 (We = {:.3g}, Oh = {:.3g}) gives {:.4g}; with We_d = {:.3g}, Oh_d = {:.3g} "
                                   "13 sqrt(We_d)(1 + 3 Oh_d) = {:.4g}",
                                   g.we, g.oh, g.eq37, g.we_d, g.oh_d, g.eq37_d)
                     : fmt::format("eq 37 (We = {:.3g}, Oh = {:.3g}) gives {:.4g}", g.we, g.oh, g.eq37);
    if (removes()) {
        std::vector<std::string> by;
        if (remove_below_ > 0)
            by.push_back(fmt::format("{} with d_eq < {:g} h", small_drops_, spec_.breakup->remove_drops_below_h));
        if (remove_beyond_ > 0)
            by.push_back(fmt::format("{} wholly beyond the jet's end by {:g} D0", sunk_drops_,
                                     spec_.breakup->remove_drops_beyond_d0));
        log_(fmt::format("jet: {} drop(s) removed ({} particles): {}", removed_drops(), removed_particles_,
                         fmt::join(by, ", ")));
    }
    if (first_time_)
        log_(fmt::format("jet: first breakup at t = {:.6g} s, L/D0 = {:.4g}; {}", *first_time_,
                         *first_length_ / nz.d0, eq37));
    else
        log_(fmt::format("jet: not broken; {}", eq37));
    if (hdf5) write_jet_table(dir_, first_time_, first_length_, g.eq37, mon_.round());
}

}  // namespace sphjet
