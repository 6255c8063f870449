// sphjet compare LEGACY_DIR OURS_DIR: per matched output, how far our particles are from the
// legacy ones (positions in units of dx, velocities, densities, surge front), then one
// machine-readable SUMMARY line.
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analysis/compare.hpp"
#include "cli/commands.hpp"
#include "io/legacy_output.hpp"
#include "model/errors.hpp"

namespace sphjet::cli {

namespace {

struct CompareOptions {
    std::string legacy_dir, ours_dir;
    std::optional<double> dx;
    std::string by;  // "", "step" or "time"
    std::optional<std::size_t> nb, nbf;
};

std::string output_name(int number) {
    if (number == kInitialOutput) return "I";
    if (number == kFinalOutput) return "E";
    return std::to_string(number);
}

std::string opt(const std::optional<double>& v, const char* spec = "{:.6f}") {
    return v ? fmt::format(fmt::runtime(spec), *v) : std::string("-");
}

struct Match {
    const RunOutput* legacy;
    const RunOutput* ours;
};

std::vector<Match> match_outputs(const LegacyRun& leg, const LegacyRun& ours, const std::string& by) {
    std::vector<Match> m;
    if (by == "step") {
        for (const auto& a : leg.outputs) {
            if (!a.step) continue;
            for (const auto& b : ours.outputs)
                if (b.step && *b.step == *a.step) {
                    m.push_back({&a, &b});
                    break;
                }
        }
    } else {
        // Mutual nearest neighbours in time: each legacy output pairs with the closest of ours
        // and only if it is also the legacy output closest to that one, so no output is used twice.
        auto nearest = [](const RunOutput& x, const LegacyRun& in) -> const RunOutput* {
            const RunOutput* best = nullptr;
            double best_dt = std::numeric_limits<double>::infinity();
            for (const auto& y : in.outputs)
                if (y.time && std::fabs(*y.time - *x.time) < best_dt) {
                    best_dt = std::fabs(*y.time - *x.time);
                    best = &y;
                }
            return best;
        };
        for (const auto& a : leg.outputs) {
            if (!a.time) continue;
            const RunOutput* b = nearest(a, ours);
            if (b && nearest(*b, leg) == &a) m.push_back({&a, b});
        }
    }
    return m;
}

bool any_step(const LegacyRun& r) {
    for (const auto& o : r.outputs)
        if (o.step) return true;
    return false;
}

bool any_time(const LegacyRun& r) {
    for (const auto& o : r.outputs)
        if (o.time) return true;
    return false;
}

int run_compare(const CompareOptions& o) {
    const LegacyRun leg = read_legacy_run(o.legacy_dir);
    const LegacyRun ours = read_legacy_run(o.ours_dir);

    double dx = 0.0;
    if (o.dx) dx = *o.dx;
    else if (leg.indat) dx = leg.indat->dx;
    else if (ours.indat) dx = ours.indat->dx;
    else
        throw InputError(o.legacy_dir, "the particle spacing is unknown",
                         "INDAT in " + o.legacy_dir + " or " + o.ours_dir + ", or --dx", "neither");
    if (!(dx > 0.0)) throw InputError("--dx", "bad particle spacing", "a positive number", fmt::format("{}", dx));

    std::string by = o.by;
    if (by.empty()) by = (any_step(leg) && any_step(ours)) ? "step" : "time";
    if (by == "step" && !(any_step(leg) && any_step(ours)))
        throw InputError(!any_step(leg) ? o.legacy_dir : o.ours_dir, "cannot match outputs by step",
                         "step numbers (stdout.txt for legacy, steps.txt for ours)", "none");

    if (by == "time" && !(any_time(leg) && any_time(ours)))
        throw InputError(!any_time(leg) ? o.legacy_dir : o.ours_dir, "cannot match outputs by time",
                         "output times (DT or steps.txt)", "none");

    // Our run may lack INDAT: it is the same case, so the legacy counts apply.
    auto ours_nb = o.nb;
    auto ours_nbf = o.nbf;
    if (!ours_nb && !ours.indat && leg.indat) {
        ours_nb = leg.indat->nb;
        if (!ours_nbf) ours_nbf = leg.indat->nbf;
    }

    const auto matches = match_outputs(leg, ours, by);
    if (matches.empty())
        throw InputError(o.ours_dir, fmt::format("no output matches the legacy run by {}", by),
                         "at least one common output", "none");

    std::ostringstream table;
    table << fmt::format("compare {} (legacy) with {} (ours), matched by {}, dx = {}\n", o.legacy_dir,
                             o.ours_dir, by, dx);
    table << fmt::format("{:>4} {:>8} {:>8} {:>11} {:>11} {:>6} {:>10} {:>10} {:>10} {:>10} {:>10} {:>9} {:>9} {:>9}\n",
                             "out", "step_leg", "step_our", "t_leg", "t_our", "n", "rms/dx", "max/dx",
                             "rms_vel", "max_vel", "max_drho", "front_lg", "front_our", "front_rel");
    std::size_t n_out = 0;
    analysis::StateDiff last;
    double max_dx_max = 0.0, max_vel_max = 0.0, rho_max = 0.0, front_rel_max = 0.0;
    for (const auto& m : matches) {
        const ParticleSet a = load_output(leg, *m.legacy, o.nb, o.nbf);
        const ParticleSet b = load_output(ours, *m.ours, ours_nb, ours_nbf);
        analysis::StateDiff d;
        try {
            d = analysis::compare_states(a, b);
        } catch (const std::invalid_argument& e) {
            throw InputError(m.ours->file.string(), "cannot compare with " + m.legacy->file.string(), "the same particles",
                             e.what());
        }
        ++n_out;
        last = d;
        max_dx_max = std::max(max_dx_max, d.max_pos / dx);
        max_vel_max = std::max(max_vel_max, d.max_vel);
        rho_max = std::max(rho_max, d.max_rel_rho);
        if (d.front_rel()) front_rel_max = std::max(front_rel_max, *d.front_rel());
        auto step_s = [](const RunOutput& r) { return r.step ? std::to_string(*r.step) : std::string("-"); };
        table << fmt::format("{:>4} {:>8} {:>8} {:>11} {:>11} {:>6} {:>10.3e} {:>10.3e} {:>10.3e} {:>10.3e} {:>10.3e} {:>9} {:>9} {:>9}\n",
                                 output_name(m.legacy->number), step_s(*m.legacy), step_s(*m.ours),
                                 opt(m.legacy->time, "{:.5e}"), opt(m.ours->time, "{:.5e}"), d.compared,
                                 d.rms_pos / dx, d.max_pos / dx, d.rms_vel, d.max_vel, d.max_rel_rho,
                                 opt(d.front_ref), opt(d.front_test), opt(d.front_rel(), "{:.2e}"));
        if (d.only_ref + d.only_test > 0)
            table << fmt::format("     ({} fluid particles removed only in ours, {} only in legacy)\n",
                                     d.only_ref, d.only_test);
    }
    std::cout << table.str();
    std::cout << fmt::format(
        "SUMMARY outputs={} by={} dx={} n_last={} rms_dx_last={:.6e} max_dx_last={:.6e} max_dx_max={:.6e} "
        "rms_vel_last={:.6e} max_vel_last={:.6e} max_vel_max={:.6e} max_rel_rho_max={:.6e} "
        "front_rel_last={:.6e} max_front_rel={:.6e}\n",
        n_out, by, dx, last.compared, last.rms_pos / dx, last.max_pos / dx, max_dx_max, last.rms_vel,
        last.max_vel, max_vel_max, rho_max, last.front_rel().value_or(std::nan("")), front_rel_max);
    return 0;
}

}  // namespace

void register_compare(CLI::App& app) {
    auto o = std::make_shared<CompareOptions>();
    auto* sub = app.add_subcommand("compare", "Compare a run with a legacy SPHysics run, output by output");
    sub->add_option("LEGACY_DIR", o->legacy_dir, "legacy run directory (PART_nnnn, DT, INDAT, stdout.txt)")
        ->required();
    sub->add_option("OURS_DIR", o->ours_dir, "our run directory (PART_nnnn, steps.txt)")->required();
    sub->add_option("--dx", o->dx, "particle spacing [m] (default: from INDAT)");
    sub->add_option("--by", o->by, "match outputs by step number or by nearest time (default: step when both "
                                   "runs have step numbers)")
        ->check(CLI::IsMember({"step", "time"}));
    sub->add_option("--nb", o->nb, "boundary particles (default: from INDAT)");
    sub->add_option("--nbf", o->nbf, "fixed boundary particles (default: from INDAT, else nb)");
    sub->callback([o] {
        const int rc = run_compare(*o);
        if (rc != 0) throw CLI::RuntimeError(rc);
    });
}

}  // namespace sphjet::cli
