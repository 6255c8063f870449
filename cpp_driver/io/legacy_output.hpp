// Legacy SPHysics 2D output files: PART_nnnn / IPART / EPART (one particle per line, Fortran
// 7e16.8: x z u w rho p m), DT (time dt1 dt2 dt_new per output), the step numbers the legacy
// solver prints to stdout, and this fork's steps.txt (output number, step, time).
//
// Output numbering used throughout: k >= 1 is PART_k, 0 is IPART (the initial state), -1 is
// EPART (the final record, written once more after the last PART file). The legacy solver
// writes DT row k and prints "In poute_2D, itime = N" for the k-th output; EPART is the last.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/file_write.hpp"
#include "model/particles.hpp"

namespace sphjet {

inline constexpr int kInitialOutput = 0;  // IPART
inline constexpr int kFinalOutput = -1;   // EPART

// One value as Fortran E16.8 writes it (gfortran): "  0.10000000E+01", " -0.12345679E-03",
// "  0.10000000+100" for three-digit exponents, right-justified NaN / Infinity.
[[nodiscard]] std::string fortran_e16_8(double v);

// Writes a PART file in legacy order: the particle with id k on line k+1 (ids must be a
// permutation of 0..n-1; an empty id array means the stored order). Written atomically
// (io/file_write.hpp: a temporary file beside `path`, fsync, rename), so an existing file is
// never left half-written; WriteError names the file and the cause when the disk is full.
void write_part(const std::filesystem::path& path, const ParticleSet& ps);

// Reads a PART/IPART/EPART file. Lines 1..nbf are fixed boundary, nbf+1..nb moving boundary,
// the rest fluid (nbf > nb means nbf = nb). id = line index (0-based), all active.
// Throws InputError naming the file and line for a malformed line or fewer than nb lines.
[[nodiscard]] ParticleSet read_part(const std::filesystem::path& path, std::size_t nb,
                                    std::size_t nbf = static_cast<std::size_t>(-1));

struct DtRow {
    double time = 0.0;
    double dt1 = 0.0;     // CFL limit from the forces
    double dt2 = 0.0;     // CFL limit from the sound speed / viscosity
    double dt_new = 0.0;  // the step chosen for the next step
};

// Writes a DT file as legacy does: header " time dt1 dt2 dt_new", then one row per output.
// Each row is written with one write() and, when that fails (a full disk), the file is cut
// back to the rows before it and WriteError is thrown: the file only ever holds whole rows.
class DtFile {
public:
    // append: keep an existing file's rows (resume); otherwise start a new file.
    explicit DtFile(const std::filesystem::path& path, bool append = false);
    void append(const DtRow& row);

private:
    AppendFile out_;
};

// Reads a DT file (the header line is optional); InputError on a malformed row.
[[nodiscard]] std::vector<DtRow> read_dt(const std::filesystem::path& path);

struct StepsRow {
    int output = 0;          // k of PART_k; 0 = IPART; -1 = EPART
    std::int64_t step = 0;   // time step after which the output was written
    double time = 0.0;       // [s]
};

// This fork's steps.txt: "# output step time", then one row per output (whole rows only, as
// DtFile).
class StepsFile {
public:
    // append: keep an existing file's rows (resume); otherwise start a new file.
    explicit StepsFile(const std::filesystem::path& path, bool append = false);
    void append(const StepsRow& row);

private:
    AppendFile out_;
};

[[nodiscard]] std::vector<StepsRow> read_steps(const std::filesystem::path& path);

// The numbers of a legacy INDAT file that the post-processing needs (lines as in the legacy
// README: vlx = line 19, vlz = 21, dx = 22, dz = 24, h = 25, np = 26, nb = 27, nbf = 28,
// out = 32).
struct IndatSummary {
    double lx = 0.0, lz = 0.0;  // box size [m]
    double dx = 0.0, dz = 0.0;  // particle spacing [m]
    double h = 0.0;             // smoothing length [m]
    std::size_t np = 0, nb = 0, nbf = 0;
    double out = 0.0;           // output interval [s]
};
[[nodiscard]] IndatSummary read_indat_summary(const std::filesystem::path& path);

// One output of a run directory.
struct RunOutput {
    int number = 0;                       // k of PART_k; 0 = IPART; -1 = EPART
    std::filesystem::path file;
    std::optional<double> time;           // from steps.txt, else DT (IPART: 0)
    std::optional<std::int64_t> step;     // from steps.txt, else stdout.txt (IPART: 0)
    std::vector<std::int64_t> removed;    // ids (0-based) the legacy stdout reports as having
                                          // left the domain before this output
};

// A run directory, legacy or ours: IPART, PART_k (sorted by k) and EPART when present.
struct LegacyRun {
    std::filesystem::path dir;
    std::optional<IndatSummary> indat;    // when INDAT is present
    std::vector<DtRow> dt;                // when DT is present
    std::vector<StepsRow> steps;          // when steps.txt is present (ours)
    std::vector<std::int64_t> stdout_steps;  // "In poute_2D, itime = N", in order
    std::vector<RunOutput> outputs;

    [[nodiscard]] bool has_steps() const;  // every output has a step number
    [[nodiscard]] bool has_times() const;  // every output has a time
};

// Throws InputError when dir is not a directory or holds no PART/IPART/EPART file.
[[nodiscard]] LegacyRun read_legacy_run(const std::filesystem::path& dir);

// Reads one output with nb/nbf from INDAT (or the overrides, which win), and marks a fluid
// particle inactive when the legacy stdout reports it removed before this output, or when it
// lies outside the container the legacy solver uses (the extent of the boundary particles:
// x beyond the boundary's min/max x, z below its min z), which is where removed particles
// are parked (x = 2 xmax). Throws InputError when nb is known from neither.
[[nodiscard]] ParticleSet load_output(const LegacyRun& run, const RunOutput& out,
                                      std::optional<std::size_t> nb_override = {},
                                      std::optional<std::size_t> nbf_override = {});

// Marks fluid particles outside legacy_domain (the fixed boundary particles' extent) inactive.
void mark_outside_container(ParticleSet& ps);

}  // namespace sphjet
