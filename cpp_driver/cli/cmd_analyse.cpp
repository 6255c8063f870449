// sphjet analyse RUN_DIR --front [--obstacle X0,X1] [--overlap-with OTHER] --csv OUT.csv:
// per output the surge front, the highest fluid point over an x-range and the grid-occupancy
// overlap with another run, for legacy run directories and ours (PART files or HDF5) alike.
#include <algorithm>
#include <cmath>
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
#include "analysis/overlap.hpp"
#include "analysis/run_frames.hpp"
#include "cli/commands.hpp"
#include "io/file_write.hpp"
#include "model/errors.hpp"

namespace sphjet::cli {

namespace {

struct AnalyseOptions {
    std::string run_dir;
    bool front = false;
    std::vector<double> obstacle;  // x0, x1
    std::string overlap_with;
    std::optional<double> cell;
    std::optional<double> match_tol;
    std::optional<double> column_width;
    std::string csv;
    std::optional<double> dx, xmax;
    std::optional<std::size_t> nb, nbf;
    bool hdf5 = false;
};

std::string cell(const std::optional<double>& v) { return v ? fmt::format("{:.6f}", *v) : std::string(); }

void run_analyse(const AnalyseOptions& o) {
    if (!o.front && o.obstacle.empty() && o.overlap_with.empty())
        throw InputError("sphjet analyse", "nothing to analyse",
                         "--front, --obstacle X0,X1 and/or --overlap-with DIR", "none of them");
    if (!o.obstacle.empty() && (o.obstacle.size() != 2 || !(o.obstacle[0] <= o.obstacle[1])))
        throw InputError("--obstacle", "bad x-range", "X0,X1 with X0 <= X1",
                         fmt::format("{}", fmt::join(o.obstacle, ",")));
    if (o.column_width && !(*o.column_width > 0))
        throw InputError("--column-width", "bad column width", "a > 0 [m]", fmt::format("{}", *o.column_width));
    if (o.column_width && !o.front)
        throw InputError("--column-width", "the Martin & Moyce columns need the front", "--front as well",
                         "no --front");

    analysis::RunFrameOptions fo;
    fo.nb = o.nb;
    fo.nbf = o.nbf;
    fo.prefer_hdf5 = o.hdf5;
    const analysis::RunFrames run(o.run_dir, fo);
    std::optional<double> dx = o.dx ? o.dx : run.dx();
    if (o.front && !dx)
        std::cerr << "sphjet analyse: spacing unknown (no INDAT, case.toml or snapshot) and no --dx: the "
                     "near-floor fronts (z < 2 dx, z < 4 dx) are left empty\n";

    std::optional<analysis::RunFrames> other;
    double cell_size = 0.0, tol = 0.0;
    if (!o.overlap_with.empty()) {
        analysis::RunFrameOptions fo2;
        fo2.prefer_hdf5 = o.hdf5;
        other.emplace(o.overlap_with, fo2);
        if (o.cell) cell_size = *o.cell;
        else if (dx) cell_size = 2.0 * *dx;
        else
            throw InputError("--overlap-with", "cell size unknown", "--cell C or a run whose spacing is known",
                             "neither");
        if (!(cell_size > 0)) throw InputError("--cell", "bad cell size", "C > 0 [m]", fmt::format("{}", cell_size));
        // Outputs are matched by time: within a quarter of the smallest output spacing unless told.
        tol = o.match_tol.value_or(0.0);
        if (!o.match_tol) {
            double spacing = 1e300;
            const analysis::RunFrames& oth = *other;
            for (const analysis::RunFrames* r : {&run, &oth}) {
                const auto& fr = r->frames();
                for (std::size_t i = 1; i < fr.size(); ++i)
                    if (fr[i].time && fr[i - 1].time && *fr[i].time > *fr[i - 1].time)
                        spacing = std::min(spacing, *fr[i].time - *fr[i - 1].time);
            }
            tol = spacing < 1e300 ? 0.25 * spacing : 1e-9;
        }
    }

    analysis::Bounds bounds;
    if (o.xmax) bounds.xmax = *o.xmax;

    std::string header = "output,step,time,n_fluid,n_out";
    if (o.front) header += ",xfront_all,xfront_floor,xfront_floor4";
    if (o.column_width) header += ",T,Z";
    if (!o.obstacle.empty()) header += ",zmax_obst,n_obst";
    if (other) header += ",other_output,other_time,overlap,cells_both,cells_either";
    std::vector<std::string> rows;
    for (std::size_t i = 0; i < run.frames().size(); ++i) {
        const auto& fr = run.frames()[i];
        const ParticleSet ps = run.load(i);
        std::string row = fmt::format("{},{},{},{},{}", fr.number, fr.step ? std::to_string(*fr.step) : "",
                                      fr.time ? fmt::format("{:.9e}", *fr.time) : "", ps.n_fluid(),
                                      analysis::fluid_out(ps, bounds));
        if (o.front) {
            const auto xf = analysis::surge_front(ps, bounds);
            row += "," + cell(xf);
            row += "," + (dx ? cell(analysis::surge_front(ps, bounds, 2.0 * *dx)) : "");
            row += "," + (dx ? cell(analysis::surge_front(ps, bounds, 4.0 * *dx)) : "");
            if (o.column_width) {
                const double a = *o.column_width;
                row += "," + (fr.time ? fmt::format("{:.6f}", *fr.time * std::sqrt(2.0 * 9.81 / a)) : "");
                row += "," + (xf ? fmt::format("{:.6f}", *xf / a) : "");
            }
        }
        if (!o.obstacle.empty()) {
            const auto hp = analysis::highest_over(ps, o.obstacle[0], o.obstacle[1], bounds);
            row += fmt::format(",{},{}", cell(hp.z), hp.count);
        }
        if (other) {
            const auto j = fr.time ? other->nearest(*fr.time, tol) : std::nullopt;
            if (j) {
                const ParticleSet qs = other->load(*j);
                const auto ov = analysis::grid_overlap(ps, qs, cell_size, bounds);
                const auto& ofr = other->frames()[*j];
                row += fmt::format(",{},{:.9e},{:.6f},{},{}", ofr.number, *ofr.time, ov.ratio(), ov.both,
                                   ov.either);
            } else {
                row += ",,,,,";
            }
        }
        rows.push_back(row);
    }

    // Written beside the target and renamed, so an old CSV is never left half-overwritten.
    std::string csv = header + "\n";
    for (const auto& r : rows) csv += r + "\n";
    write_file_atomically(o.csv, csv, "the CSV file");

    std::cout << header << "\n";
    for (const auto& r : rows) std::cout << r << "\n";
    std::cout << fmt::format("wrote {} ({} outputs; boundary count from {}{})\n", o.csv, rows.size(),
                             run.nb_source(),
                             other ? fmt::format("; overlap in cells of {:.6g} m, outputs matched within {:.3g} s",
                                                 cell_size, tol)
                                   : std::string());
}

}  // namespace

void register_analyse(CLI::App& app) {
    auto o = std::make_shared<AnalyseOptions>();
    auto* sub = app.add_subcommand(
        "analyse",
        "Surge front, highest point over an x-range and overlap with another run, per output of a run "
        "(legacy SPHysics, or sphjet with PART or HDF5 output)");
    sub->add_option("RUN_DIR", o->run_dir,
                    "run directory: PART_nnnn with INDAT (legacy) or case.toml (sphjet), or snap_*.h5")
        ->required();
    sub->add_flag("--front", o->front, "surge front: max x of all fluid, of fluid with z < 2 dx and z < 4 dx");
    sub->add_option("--obstacle", o->obstacle, "x-range X0,X1 [m]: highest fluid point over it and the count")
        ->delimiter(',')
        ->expected(2);
    sub->add_option("--overlap-with", o->overlap_with,
                    "another run directory: per output, the fraction of cells holding fluid in both runs "
                    "over the cells holding fluid in either (outputs matched by time)");
    sub->add_option("--cell", o->cell, "overlap cell size [m] (default 2 dx)");
    sub->add_option("--match-tol", o->match_tol,
                    "largest time difference [s] of matched outputs (default: a quarter of the output spacing)");
    sub->add_option("--column-width", o->column_width,
                    "dam-break column width a [m]: adds Martin & Moyce's T = t sqrt(2 g / a) and Z = front / a");
    sub->add_option("--csv", o->csv, "CSV file to write (with a header)")->required();
    sub->add_option("--dx", o->dx, "particle spacing [m] (default: from INDAT, case.toml or the snapshots)");
    sub->add_option("--xmax", o->xmax, "ignore fluid with x > XMAX [m] (e.g. leaked particles)");
    sub->add_option("--nb", o->nb, "boundary particles (default: from INDAT or case.toml)");
    sub->add_option("--nbf", o->nbf, "fixed boundary particles (default: from INDAT, else nb)");
    sub->add_flag("--hdf5", o->hdf5, "read snap_*.h5 even where PART files exist");
    sub->callback([o] { run_analyse(*o); });
}

}  // namespace sphjet::cli
