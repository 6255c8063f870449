// sphjet bench: particle-steps per second of the core on a case, for a list of thread
// counts. No output is written, so this measures the particle loops (and the density filter
// at the case's cadence), not the disk.
#include <chrono>
#include <iostream>
#include <memory>
#include <sstream>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "config/load_case.hpp"
#include "core/simulation.hpp"
#include "core/solver.hpp"
#include "model/errors.hpp"

namespace sphjet::cli {

namespace {

struct BenchArgs {
    std::string case_path;
    long steps = 200;
    long warmup = 10;
    std::string threads = "1,2";
    std::vector<std::string> sets;
};

}  // namespace

void register_bench(CLI::App& app) {
    auto args = std::make_shared<BenchArgs>();
    auto* cmd = app.add_subcommand(
        "bench", "Benchmark: particle-steps per second of a case for several thread counts "
                 "(no output written).");
    cmd->add_option("case", args->case_path, "case file (legacy case, INDAT or .toml)")
        ->required();
    cmd->add_option("-n,--steps", args->steps, "timed steps per thread count")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--warmup", args->warmup, "untimed steps first")->check(CLI::NonNegativeNumber);
    cmd->add_option("-j,--threads", args->threads, "comma-separated thread counts, e.g. 1,2");
    cmd->add_option("--set", args->sets, "override a key of a modern case (repeatable)");
    cmd->callback([args]() {
        std::vector<int> counts;
        std::stringstream ss(args->threads);
        for (std::string tok; std::getline(ss, tok, ',');) {
            try {
                counts.push_back(std::stoi(tok));
            } catch (const std::exception&) {
                throw InputError("sphjet bench --threads", "not a list of thread counts",
                                 "e.g. 1,2", args->threads);
            }
            if (counts.back() < 1)
                throw InputError("sphjet bench --threads", "thread count below 1", ">= 1", tok);
        }
        const LoadedCase lc = load_case(args->case_path, args->sets);
        std::cout << fmt::format("case {}: {} particles ({} fluid), kernel {}, filter {} every {} "
                                 "steps, {} warm-up + {} timed steps, OpenMP waits: {}\n",
                                 args->case_path, lc.particles.size(), lc.particles.n_fluid(),
                                 to_string(lc.spec.params.kernel),
                                 to_string(lc.spec.params.density_filter),
                                 lc.spec.params.filter_period, args->warmup, args->steps,
                                 Solver::openmp_waits());
        if (const std::string note = initial_step_note(lc.spec.params); !note.empty())
            std::cout << note << '\n';
        for (int nt : counts) {
            Solver::set_threads(nt);
            Solver s(lc.spec.params, lc.spec.output, lc.particles);
            auto advance = [&](long n) {
                for (long k = 0; k < n; ++k) {
                    s.step(false);   // as a run's steps between outputs
                    s.density_filter_if_due();
                }
            };
            advance(args->warmup);
            const auto t0 = std::chrono::steady_clock::now();
            const auto c0 = std::clock();
            advance(args->steps);
            const double wall =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
            const double ps = static_cast<double>(lc.particles.size()) *
                              static_cast<double>(args->steps);
            // The predictor-corrector evaluates the forces (the rates pair loop) twice a step,
            // the leapfrog once.
            const double force_evals_per_step = lc.spec.params.integrator == Integrator::Leapfrog ? 1.0 : 2.0;
            // a small case runs on fewer threads than asked (Solver::threads_for): say so
            const int used = Solver::threads_for(lc.particles.size());
            std::cout << fmt::format(
                "threads {}: {:.4g} particle-steps/s, {:.4g} force evaluations/s ({:.3f} s "
                "wall, {:.3f} s cpu, {:.1f} steps/s){}\n",
                nt, ps / wall, force_evals_per_step * ps / wall, wall, cpu,
                static_cast<double>(args->steps) / wall,
                used == nt ? std::string()
                           : fmt::format("; ran on {} (a step of {} particles)",
                                         used == 1 ? "1 thread" : fmt::format("{} threads", used),
                                         lc.particles.size()));
        }
    });
}

}  // namespace sphjet::cli
