// sphjet run: run (or resume) a case.
#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "core/simulation.hpp"
#include "model/errors.hpp"

namespace sphjet::cli {

namespace {

struct RunArgs {
    std::string case_path;
    std::string out_dir;
    std::string resume_dir;
    double tmax = -1;
    long max_steps = -1;
    int threads = 0;
    bool force = false;
    bool legacy_clock = false;
    bool quiet = false;
    std::string format;
    std::vector<std::string> sets;
};

std::string joined_command_line(int argc, char** argv) {
    std::string s;
    for (int i = 0; i < argc; ++i) {
        if (i) s += ' ';
        s += argv[i];
    }
    return s;
}

}  // namespace

std::string g_command_line;

void set_command_line(int argc, char** argv) { g_command_line = joined_command_line(argc, argv); }

void register_run(CLI::App& app) {
    auto args = std::make_shared<RunArgs>();
    auto* cmd = app.add_subcommand(
        "run", "Run a case: a legacy SPHysics case file, an INDAT file (IPART beside it) or a "
               "modern .toml case; or resume a stopped run with --resume DIR.");
    cmd->add_option("case", args->case_path, "case file (legacy case, INDAT or .toml)");
    cmd->add_option("-o,--out", args->out_dir, "output directory");
    cmd->add_option("--resume", args->resume_dir,
                    "continue the run in this directory from its checkpoint.h5");
    cmd->add_option("--tmax", args->tmax, "end time [s] (overrides the case)");
    cmd->add_option("--max-steps", args->max_steps, "stop after this many steps");
    cmd->add_option("-j,--threads", args->threads, "OpenMP threads (default: all cores)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--format", args->format, "output format (default: the case's, else both)")
        ->check(CLI::IsMember({"legacy", "hdf5", "both"}));
    cmd->add_option("--set", args->sets,
                    "override a key of a modern case, e.g. --set surface_tension.sigma=0.05 "
                    "(repeatable); with --resume, a key of time, surface_tension, breakup or "
                    "numerics that does not build the particles, from the checkpoint on");
    cmd->add_flag("--force", args->force, "allow writing into a non-empty output directory");
    cmd->add_flag("--legacy-clock", args->legacy_clock,
                  "output cadence on SPHysics' clock (which adds the new dt after each step), "
                  "so outputs fall on the same steps as a legacy run");
    cmd->add_flag("-q,--quiet", args->quiet, "no progress line (the log file is still written)");
    cmd->callback([args]() {
        RunOptions o;
        if (!args->resume_dir.empty()) {
            o.resume = true;
            o.out_dir = args->resume_dir;
            if (!args->out_dir.empty() && args->out_dir != args->resume_dir)
                throw InputError("sphjet run", "--resume DIR and --out name different directories",
                                 "one run directory", args->out_dir);
            // a resumed run continues with its checkpoint's parameters (so that it ends
            // bitwise as the uninterrupted run), but for the keys --set changes (those of
            // time, surface_tension, breakup and numerics that do not build the particles:
            // core/simulation.cpp); a case would be ignored
            if (!args->case_path.empty())
                throw InputError("sphjet run", "a case with --resume",
                                 "no case: a resumed run keeps the case of its checkpoint",
                                 args->case_path);
            // and the format of its case copy (its clock: run_simulation, from the checkpoint)
            if (!args->format.empty())
                throw InputError("sphjet run", "--format with --resume",
                                 "no --format: a resumed run writes the format it started with",
                                 "--format " + args->format);
        } else {
            if (args->case_path.empty())
                throw InputError("sphjet run", "no case given", "a case file (or --resume DIR)",
                                 "nothing");
            if (args->out_dir.empty())
                throw InputError("sphjet run", "no output directory", "--out DIR", "nothing");
            o.case_path = args->case_path;
            o.out_dir = args->out_dir;
        }
        if (args->tmax > 0) o.tmax = args->tmax;
        if (args->max_steps >= 0) o.max_steps = args->max_steps;
        o.threads = args->threads;
        o.force = args->force;
        o.legacy_clock = args->legacy_clock;
        o.quiet = args->quiet;
        o.overrides = args->sets;
        o.command_line = g_command_line;
        if (args->format == "legacy") o.format = OutputFormat::Legacy;
        if (args->format == "hdf5") o.format = OutputFormat::Hdf5;
        if (args->format == "both") o.format = OutputFormat::Both;
        const RunSummary s = run_simulation(o);
        std::cout << fmt::format(
            "run summary: {} particles ({} fluid) at the start, {} steps to t = {:.6g} s, "
            "wall {:.2f} s, {:.4g} particle-steps/s, {} outputs, {} left the domain{}{}\n",
            s.particles, s.fluid, s.steps, s.time, s.wall_seconds, s.particle_steps_per_second(),
            s.outputs, s.removed,
            s.removed_drops > 0 ? fmt::format(", {} drop(s) ({} particles) removed", s.removed_drops,
                                              s.removed_drop_particles)
                                : std::string(),
            s.interrupted ? " (interrupted; resume with --resume)" : "");
        if (s.interrupted) throw CLI::RuntimeError(130);
    });
}

}  // namespace sphjet::cli
