// sphjet drop RUN_DIR [--radius R] [--sigma S]: the surface-tension measures of a free drop
// (analysis/drop.hpp) per HDF5 snapshot, and one line `SUMMARY key=value ...` for tests.
//
// Summary keys (SI units):
//   snapshots, t_end, n_fluid
//   radius, sigma, rho0           the reference R (--radius, else r_eq of the first
//                                 snapshot), sigma (--sigma, else the run's) and rho0
//   area0, area_end, area_change  sum m/rho at the first and last snapshot, relative change
//   ratio_end                     r_max / r_min of the outline at the last snapshot
//   window_from                   start of the averaging window (--from, else half of t_end)
//   p_inner, p_surface            means over the window of the inner / surface means [Pa]
//   laplace                       sigma / R [Pa]; laplace_ratio = p_inner / laplace
//                                 (ambient pressure 0: the free-surface condition of the
//                                 weakly compressible model)
//   speed_max_window              largest fluid speed in the window [m/s]
//   kappa_R_mean, kappa_R_sd      surface curvature x R at the last snapshot (with the field)
//   kappa0_R_mean, kappa0_R_sd    the same at the first snapshot (the initial drop, t = 0)
//   period, omega                 mode-2 oscillation from D(t) (see drop.hpp); omega_theory
//                                 = sqrt(6 sigma / (rho0 R^3)); period_error relative to
//                                 2 pi / omega_theory; decay_rate [1/s]
// A key whose value cannot be computed is written as nan.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analysis/drop.hpp"
#include "cli/commands.hpp"
#include "io/file_write.hpp"
#include "io/hdf5_output.hpp"
#include "model/errors.hpp"

namespace sphjet::cli {

namespace {

struct DropOptions {
    std::string run_dir;
    std::optional<double> radius, sigma, from, skip;
    std::string csv;
    bool quiet = false;
};

std::string num(std::optional<double> v) {
    return v && std::isfinite(*v) ? fmt::format("{:.6g}", *v) : std::string("nan");
}

void run_drop(const DropOptions& o) {
    namespace fs = std::filesystem;
    const fs::path dir(o.run_dir);
    if (!fs::is_directory(dir))
        throw InputError(o.run_dir, "not a run directory", "a directory written by `sphjet run`",
                         "no such directory");
    std::vector<fs::path> snaps;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string n = e.path().filename().string();
        if (n.rfind("snap_", 0) == 0 && e.path().extension() == ".h5") snaps.push_back(e.path());
    }
    std::sort(snaps.begin(), snaps.end());
    if (snaps.empty())
        throw InputError(o.run_dir, "no HDF5 snapshots", "snap_NNNNNN.h5 (output format hdf5 or both)",
                         "none");
    const SimParams prm = read_run_params(snaps.front());
    const double sigma = o.sigma ? *o.sigma : prm.sigma;
    const double rho0 = prm.rho0;

    std::vector<double> t, dfm;
    std::vector<analysis::DropMeasures> ms;
    std::vector<std::string> rows;
    const std::string header =
        "time,step,n_fluid,area,r_eq,r_max,r_min,r_ratio,p_inner,p_inner_sd,p_surface,p_surface_sd,"
        "kappa_surface,kappa_surface_sd,n_surface,n_with_normal,speed_max,deformation,extent_x,"
        "extent_z";
    for (const auto& f : snaps) {
        const Snapshot s = read_snapshot(f);
        const std::vector<double>* k = s.field("curvature");
        const auto m = k ? analysis::measure_drop(s.particles, *k) : analysis::measure_drop(s.particles);
        t.push_back(s.time);
        dfm.push_back(m.deformation);
        ms.push_back(m);
        rows.push_back(fmt::format(
            "{:.6g},{},{},{:.9g},{:.6g},{:.6g},{:.6g},{:.5f},{:.6g},{:.4g},{:.6g},{:.4g},{},{},{},{},"
            "{:.4g},{:.6g},{:.6g},{:.6g}",
            s.time, s.step, m.n_fluid, m.area, m.r_eq, m.r_max, m.r_min, m.r_ratio(), m.p_inner.mean,
            m.p_inner.sd, m.p_surface.mean, m.p_surface.sd,
            m.kappa_surface ? fmt::format("{:.6g}", m.kappa_surface->mean) : "",
            m.kappa_surface ? fmt::format("{:.4g}", m.kappa_surface->sd) : "", m.p_surface.n,
            m.n_with_normal, m.speed_max, m.deformation, m.extent_x, m.extent_z));
    }
    if (!o.quiet) {
        std::cout << header << "\n";
        for (const auto& r : rows) std::cout << r << "\n";
    }
    if (!o.csv.empty()) {
        std::string csv = header + "\n";
        for (const auto& r : rows) csv += r + "\n";
        write_file_atomically(o.csv, csv, "the CSV file");
    }

    const double R = o.radius ? *o.radius : ms.front().r_eq;
    const double t_end = t.back();
    const double from = o.from ? *o.from : 0.5 * t_end;
    double pin = 0, psurf = 0, vmax = 0;
    int nw = 0;
    for (std::size_t k = 0; k < ms.size(); ++k) {
        if (t[k] < from) continue;
        pin += ms[k].p_inner.mean;
        psurf += ms[k].p_surface.mean;
        vmax = std::max(vmax, ms[k].speed_max);
        ++nw;
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::optional<double> p_inner, p_surface, ratio;
    if (nw > 0) {
        p_inner = pin / nw;
        p_surface = psurf / nw;
    }
    const double laplace = sigma > 0 && R > 0 ? sigma / R : nan;
    if (p_inner && std::isfinite(laplace)) ratio = *p_inner / laplace;
    const auto osc = analysis::oscillation(t, dfm, o.skip ? *o.skip : 0.0);
    const double omega_th = sigma > 0 ? std::sqrt(6 * sigma / (rho0 * R * R * R)) : nan;
    std::optional<double> omega, perr;
    if (osc.period) {
        omega = 2 * std::numbers::pi / *osc.period;
        if (std::isfinite(omega_th)) perr = *osc.period / (2 * std::numbers::pi / omega_th) - 1;
    }
    const auto& last = ms.back();
    std::optional<double> kr, krsd, kr0, krsd0;
    if (last.kappa_surface) {
        kr = last.kappa_surface->mean * R;
        krsd = last.kappa_surface->sd * R;
    }
    if (ms.front().kappa_surface) {
        kr0 = ms.front().kappa_surface->mean * R;
        krsd0 = ms.front().kappa_surface->sd * R;
    }
    std::cout << fmt::format(
        "SUMMARY snapshots={} t_end={} n_fluid={} radius={} sigma={} rho0={} area0={} area_end={} "
        "area_change={} ratio_end={} window_from={} p_inner={} p_surface={} laplace={} "
        "laplace_ratio={} speed_max_window={} kappa_R_mean={} kappa_R_sd={} kappa0_R_mean={} "
        "kappa0_R_sd={} crossings={} period={} omega={} omega_theory={} period_error={} "
        "decay_rate={}\n",
        snaps.size(), num(t_end), last.n_fluid, num(R), num(sigma), num(rho0), num(ms.front().area),
        num(last.area), num(last.area / ms.front().area - 1), num(last.r_ratio()), num(from),
        num(p_inner), num(p_surface), num(laplace), num(ratio), num(nw > 0 ? std::optional(vmax) : std::nullopt),
        num(kr), num(krsd), num(kr0), num(krsd0), osc.crossings, num(osc.period), num(omega), num(omega_th), num(perr),
        num(osc.decay_rate));
}

}  // namespace

void register_drop(CLI::App& app) {
    auto o = std::make_shared<DropOptions>();
    auto* sub = app.add_subcommand(
        "drop", "Surface-tension measures of a free drop per HDF5 snapshot (Laplace pressure, "
                "curvature, outline, area, mode-2 oscillation) and a SUMMARY line");
    sub->add_option("RUN_DIR", o->run_dir, "run directory with snap_NNNNNN.h5")->required();
    sub->add_option("--radius", o->radius, "reference radius R [m] (default: sqrt(area/pi) at the "
                                           "first snapshot)")
        ->check(CLI::PositiveNumber);
    sub->add_option("--sigma", o->sigma, "surface tension [N/m] (default: the run's)")
        ->check(CLI::NonNegativeNumber);
    sub->add_option("--from", o->from, "start of the averaging window for the pressure [s] "
                                       "(default: half the run)");
    sub->add_option("--skip", o->skip, "ignore snapshots before this time for the oscillation [s]");
    sub->add_option("--csv", o->csv, "also write the per-snapshot table to this CSV file");
    sub->add_flag("-q,--quiet", o->quiet, "print only the SUMMARY line");
    sub->callback([o] { run_drop(*o); });
}

}  // namespace sphjet::cli
