// A whole run: case in, outputs (legacy PART/DT, HDF5 + XDMF), progress, checkpoints,
// resume, and a loud stop on blow-up. The CLI's `run` command is a thin layer over this.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "model/case_spec.hpp"
#include "model/particles.hpp"

namespace sphjet {

struct RunOptions {
    std::filesystem::path case_path;          // legacy case, INDAT, or modern .toml
    std::filesystem::path out_dir;
    std::optional<double> tmax;               // overrides the case's end time [s]
    std::optional<std::int64_t> max_steps;    // stop after this many steps (tests, benchmarks)
    int threads = 0;                          // 0 = OpenMP default
    bool force = false;                       // allow writing into a non-empty directory
    bool resume = false;                      // continue from out_dir/checkpoint.h5
    std::optional<OutputFormat> format;       // overrides the case's output format
    bool legacy_clock = false;                // output cadence on SPHysics' clock (on resume
                                              // the checkpoint's, where it records one)
    std::vector<std::string> overrides;       // --set key=value (modern cases)
    std::string command_line;                 // recorded in the outputs
    bool quiet = false;                       // no progress line (log file still written)
};

struct RunSummary {
    std::int64_t steps = 0;           // steps taken in this invocation
    std::int64_t total_steps = 0;     // steps since t = 0
    double time = 0;                  // simulated time reached [s]
    double legacy_time = 0;           // the same on SPHysics' clock [s]
    double wall_seconds = 0;
    std::size_t particles = 0;        // at the start of this invocation
    std::size_t fluid = 0;
    double particle_steps = 0;        // sum over the steps of the particles in the domain
    std::int64_t outputs = 0;         // snapshots written since t = 0
    std::int64_t removed = 0;         // particles that left the domain
    std::int64_t removed_drops = 0;   // drops removed ([breakup] remove_drops_*), since t = 0
    std::int64_t removed_drop_particles = 0;  // and their particles
    bool interrupted = false;         // stopped by a signal (a checkpoint was written)
    [[nodiscard]] double particle_steps_per_second() const;
};

// Runs (or resumes) a simulation. Throws InputError for bad input and SimulationError for a
// blow-up (after writing the diagnostic to the log).
RunSummary run_simulation(const RunOptions& opts);

}  // namespace sphjet
