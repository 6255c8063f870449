// sphjet analyse RUN_DIR --front [--obstacle X0,X1] --csv OUT.csv: per output the surge front
// and the highest fluid point over an x-range, for legacy run directories and ours alike.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "analysis/front.hpp"
#include "cli/commands.hpp"
#include "config/errors.hpp"
#include "io/legacy_output.hpp"

namespace sphjet::cli {

namespace {

struct AnalyseOptions {
    std::string run_dir;
    bool front = false;
    std::vector<double> obstacle;  // x0, x1
    std::string csv;
    std::optional<double> dx, xmax;
    std::optional<std::size_t> nb, nbf;
};

std::string cell(const std::optional<double>& v) { return v ? fmt::format("{:.6f}", *v) : std::string(); }

void run_analyse(const AnalyseOptions& o) {
    if (!o.front && o.obstacle.empty())
        throw InputError("sphjet analyse", "nothing to analyse", "--front and/or --obstacle X0,X1", "neither");
    if (!o.obstacle.empty() && (o.obstacle.size() != 2 || !(o.obstacle[0] <= o.obstacle[1])))
        throw InputError("--obstacle", "bad x-range", "X0,X1 with X0 <= X1",
                         fmt::format("{}", fmt::join(o.obstacle, ",")));
    const LegacyRun run = read_legacy_run(o.run_dir);
    std::optional<double> dx = o.dx;
    if (!dx && run.indat) dx = run.indat->dx;
    if (o.front && !dx)
        std::cerr << "sphjet analyse: no INDAT and no --dx: the near-floor fronts (z < 2 dx, z < 4 dx) are left empty\n";

    analysis::Bounds bounds;
    if (o.xmax) bounds.xmax = *o.xmax;

    std::string header = "output,step,time,n_fluid,n_out";
    if (o.front) header += ",xfront_all,xfront_floor,xfront_floor4";
    if (!o.obstacle.empty()) header += ",zmax_obst,n_obst";
    std::vector<std::string> rows;
    for (const auto& out : run.outputs) {
        const ParticleSet ps = load_output(run, out, o.nb, o.nbf);
        std::string row = fmt::format("{},{},{},{},{}", out.number, out.step ? std::to_string(*out.step) : "",
                                      out.time ? fmt::format("{:.9e}", *out.time) : "", ps.n_fluid(),
                                      analysis::fluid_out(ps, bounds));
        if (o.front) {
            row += "," + cell(analysis::surge_front(ps, bounds));
            row += "," + (dx ? cell(analysis::surge_front(ps, bounds, 2.0 * *dx)) : "");
            row += "," + (dx ? cell(analysis::surge_front(ps, bounds, 4.0 * *dx)) : "");
        }
        if (!o.obstacle.empty()) {
            const auto hp = analysis::highest_over(ps, o.obstacle[0], o.obstacle[1], bounds);
            row += fmt::format(",{},{}", cell(hp.z), hp.count);
        }
        rows.push_back(row);
    }

    // Written beside the target and renamed, so an old CSV is never left half-overwritten.
    const std::filesystem::path path(o.csv);
    std::filesystem::path tmp = path;
    tmp += ".tmp";
    {
        std::ofstream f(tmp, std::ios::trunc);
        if (!f) throw InputError(o.csv, "cannot open for writing");
        f << header << "\n";
        for (const auto& r : rows) f << r << "\n";
        if (!f) throw InputError(o.csv, "write failed");
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) throw InputError(o.csv, "cannot replace the file: " + ec.message());

    std::cout << header << "\n";
    for (const auto& r : rows) std::cout << r << "\n";
    std::cout << fmt::format("wrote {} ({} outputs)\n", o.csv, rows.size());
}

}  // namespace

void register_analyse(CLI::App& app) {
    auto o = std::make_shared<AnalyseOptions>();
    auto* sub = app.add_subcommand("analyse", "Surge front and highest point per output of a run (legacy or ours)");
    sub->add_option("RUN_DIR", o->run_dir, "run directory (PART_nnnn; DT/stdout.txt or steps.txt; INDAT)")->required();
    sub->add_flag("--front", o->front, "surge front: max x of all fluid, of fluid with z < 2 dx and z < 4 dx");
    sub->add_option("--obstacle", o->obstacle, "x-range X0,X1 [m]: highest fluid point over it and the count")
        ->delimiter(',')
        ->expected(2);
    sub->add_option("--csv", o->csv, "CSV file to write (with a header)")->required();
    sub->add_option("--dx", o->dx, "particle spacing [m] (default: from INDAT)");
    sub->add_option("--xmax", o->xmax, "ignore fluid with x > XMAX [m] (e.g. leaked particles)");
    sub->add_option("--nb", o->nb, "boundary particles (default: from INDAT)");
    sub->add_option("--nbf", o->nbf, "fixed boundary particles (default: from INDAT, else nb)");
    sub->callback([o] { run_analyse(*o); });
}

}  // namespace sphjet::cli
