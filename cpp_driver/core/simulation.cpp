#include "core/simulation.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "config/indat.hpp"
#include "config/legacy_case.hpp"
#include "config/load_case.hpp"
#include "config/modern_case.hpp"
#include "core/jet_run.hpp"
#include "core/solver.hpp"
#include "geometry/generator.hpp"
#include "io/checkpoint.hpp"
#include "io/file_write.hpp"
#include "io/h5_util.hpp"
#include "io/hdf5_output.hpp"
#include "io/legacy_output.hpp"
#include "model/case_params.hpp"
#include "model/errors.hpp"

namespace fs = std::filesystem;

namespace sphjet {

double RunSummary::particle_steps_per_second() const {
    return wall_seconds > 0 ? particle_steps / wall_seconds : 0.0;
}

namespace {

std::atomic<int> g_stop_signal{0};

extern "C" void on_stop_signal(int sig) { g_stop_signal.store(sig); }

// Log lines go to DIR/run.log always, and to stderr. A line that cannot be written (a full
// disk) is left out of the file whole, with one warning on stderr: a full disk never stops a
// run through its log, and the log goes on when space comes back.
class RunLog {
public:
    RunLog(const fs::path& file, bool append) : out_(file, "the run log", append) {}
    void line(const std::string& s, bool echo = true) {
        try {
            out_.append(s + '\n');
        } catch (const WriteError& e) {
            if (!warned_) {
                clear_progress();
                std::cerr << "sphjet: warning: " << e.what()
                          << "; run.log leaves out the lines it cannot take\n";
            }
            warned_ = true;
        }
        if (echo) {
            clear_progress();
            std::cerr << s << '\n';
        }
    }
    // One updating line on a terminal.
    void progress(const std::string& s) {
        std::cerr << '\r' << s << "\x1b[K" << std::flush;
        progress_shown_ = true;
    }
    void clear_progress() {
        if (progress_shown_) std::cerr << "\r\x1b[K" << std::flush;
        progress_shown_ = false;
    }

private:
    AppendFile out_;
    bool warned_ = false;
    bool progress_shown_ = false;
};

// Keeps the first n data rows of a text file with one header line (DT) or none (steps.txt
// has a '#' header): used on resume so that rows written after the checkpoint go away. The
// file is cut (which needs no free space) rather than rewritten; a last line without its
// newline is a half-written row and goes too.
void truncate_rows(const fs::path& file, std::int64_t keep_rows) {
    if (!fs::exists(file)) return;
    std::ifstream in(file, std::ios::binary);
    std::string line;
    std::int64_t rows = 0;
    std::uintmax_t keep_bytes = 0;
    while (std::getline(in, line)) {
        if (in.eof()) break;  // no newline after it
        const bool header = line.find_first_not_of(" \t") == std::string::npos || line[0] == '#' ||
                            line.find("time") != std::string::npos;
        if (!header) {
            if (rows >= keep_rows) break;
            ++rows;
        }
        keep_bytes += line.size() + 1;
    }
    in.close();
    std::error_code ec;
    if (keep_bytes < fs::file_size(file, ec) && !ec) fs::resize_file(file, keep_bytes, ec);
    if (ec)
        throw WriteError(file.string(), ec.value(),
                         fmt::format("cannot cut back to {} rows: {}", keep_rows, ec.message()));
}

bool dir_has_files(const fs::path& dir) {
    return fs::exists(dir) && fs::is_directory(dir) && !fs::is_empty(dir);
}

std::vector<ExtraField> extra_fields(const Solver& s) {
    std::vector<ExtraField> f;
    if (s.colour().empty()) return f;
    f.push_back({"colour", s.colour(), ""});
    f.push_back({"normal_x", s.st_nx(), ""});
    f.push_back({"normal_z", s.st_nz(), ""});
    f.push_back({"curvature", s.curvature(), ""});
    return f;
}

std::string hms(double seconds) {
    if (!(seconds >= 0) || seconds > 1e7) return "--:--:--";
    const auto s = static_cast<long>(seconds + 0.5);
    return fmt::format("{:02d}:{:02d}:{:02d}", s / 3600, (s / 60) % 60, s % 60);
}

// What a run has on disk, for the message after a failed write.
struct SavedSoFar {
    std::int64_t output = -1;  // the last output written whole (-1: none)
    double output_time = std::numeric_limits<double>::quiet_NaN();  // its time [s], NaN unknown
    bool checkpoint = false;  // DIR/checkpoint.h5 holds a good checkpoint
    std::int64_t checkpoint_step = 0;
    double checkpoint_time = 0.0;
};

// After an output file could not be written (a full disk): removes the temporary files
// (each writer removes its own; this catches any other), logs where the run stands, what is
// kept and how to go on, and rethrows. The log itself may fail to write: RunLog copes.
[[noreturn]] void stop_on_write_error(RunLog& log, const fs::path& dir, const RunState& st,
                                      const SavedSoFar& saved, const WriteError& e) {
    const auto leftovers = remove_temporaries(dir);
    log.clear_progress();
    log.line(fmt::format("FAILED: {}", e.what()));
    std::string kept;
    if (saved.output >= 0) {
        kept = fmt::format("outputs up to number {}", saved.output);
        if (std::isfinite(saved.output_time))
            kept += fmt::format(" (t = {:.6g} s)", saved.output_time);
        kept += " are complete";
    } else {
        kept = "no output is complete";
    }
    kept += saved.checkpoint ? fmt::format("; the checkpoint {} is at step {} (t = {:.6g} s)",
                                           checkpoint_path(dir).string(), saved.checkpoint_step,
                                           saved.checkpoint_time)
                             : "; no checkpoint was written yet";
    log.line(fmt::format("the run stopped at step {} (t = {:.6g} s) because {} could not be "
                         "written; {}{}",
                         st.step, st.time, e.path(), kept,
                         leftovers.empty() ? ""
                                           : fmt::format("; removed the temporary files {}",
                                                         fmt::join(leftovers, " "))));
    if (saved.checkpoint)
        log.line(fmt::format("free some space (or move {} to a larger disk) and continue with "
                             "`sphjet run --resume {}`",
                             dir.string(), dir.string()));
    else
        log.line("free some space and run the case again (with --force)");
    throw e;
}

// ---- the start of a run ----

// The case a run starts from: read afresh, or the state a checkpoint holds.
struct RunStart {
    CaseSpec spec;
    ParticleSet particles;
    RunState resumed;  // with the core's state that the checkpoint kept (Solver::kept_state)
    std::vector<CheckpointArray> kept;
    std::optional<bool> legacy_clock;  // the checkpoint's output clock, where it says
};

// The keys a resumed run may change (--set with --resume): those that set how the particles
// move and what the run reads of them, not what particles there are or how they were laid
// out. The rest (the fluid, the nozzle, the resolution, the domain, the walls) built the
// particles the checkpoint holds, and the kernel, the lattice, the boundary and the
// integrator fix the arrays and the kept state the core resumes from.
bool changes_on_resume(std::string_view key) {
    static constexpr std::string_view kept[] = {"numerics.kernel", "numerics.lattice",
                                                "numerics.boundary", "numerics.integrator"};
    const std::string_view section = section_of(key);
    if (section == "time" || section == "surface_tension" || section == "breakup") return true;
    return section == "numerics" && std::find(std::begin(kept), std::end(kept), key) == std::end(kept);
}

// --set with --resume: each key is checked as above, the case copy read with and without the
// changes, and every parameter the changes move (a derived one too, as the Tait B of c0)
// taken into the checkpoint's parameters; the others stay the checkpoint's, bit for bit.
void change_on_resume(RunStart& s, SimParams& params, std::int64_t n_outputs,
                      const fs::path& case_copy, const std::vector<std::string>& sets) {
    if (!fs::exists(case_copy))
        throw InputError(case_copy.string(), "--set with --resume needs the run's case copy",
                         "the case.toml that `sphjet run` wrote beside the checkpoint", "none");
    // (the sections that may change hold no arrays of tables: "fluid.block[0].u0" is refused
    // as it stands; an unknown key of those sections is left to the case reader's message)
    for (const std::string& text : sets) {
        std::string key = text.substr(0, text.find('='));
        key.erase(std::remove_if(key.begin(), key.end(), [](char c) { return c == ' ' || c == '\t'; }),
                  key.end());
        if (!changes_on_resume(key))
            throw InputError("--set " + text, "a key that a resumed run cannot change",
                             "a key of [time], [surface_tension], [breakup] or [numerics] other "
                             "than numerics.kernel, lattice, boundary and integrator (the others "
                             "built the particles the checkpoint holds)",
                             key);
    }
    const CaseSpec before = read_modern_case(case_copy, {});
    CaseSpec after = read_modern_case(case_copy, sets);
    for (const Param& r : case_params()) {
        if (r.attr.empty()) continue;
        const Member& m = r.member;
        if (m.store == Member::Store::Float) {
            const double v = m.get_f(&after.params);
            if (v != m.get_f(&before.params)) m.set_f(&params, v);
        } else if (m.store != Member::Store::None) {
            const std::int64_t v = m.get_i(&after.params);
            if (v != m.get_i(&before.params)) m.set_i(&params, v);
        }
    }
    // A new output interval starts from the last output: output n + 1 is due at trec_ini +
    // out (n + 1) (step_until_done), so trec_ini moves by (out_before - out_after) n.
    if (after.params.out != before.params.out && after.params.trec_ini == before.params.trec_ini)
        params.trec_ini += (before.params.out - after.params.out) * static_cast<double>(n_outputs);
    s.spec = std::move(after);
}

RunStart start_from_checkpoint(const fs::path& dir, const std::vector<std::string>& sets) {
    if (!fs::exists(checkpoint_path(dir)))
        throw InputError(checkpoint_path(dir).string(), "cannot resume: no checkpoint",
                         "a run directory written by `sphjet run`", "no checkpoint.h5");
    Checkpoint cp = read_checkpoint(dir);
    RunStart s;
    const fs::path case_copy = dir / "case.toml";
    if (!sets.empty())
        change_on_resume(s, cp.params, cp.state.n_outputs, case_copy, sets);
    else if (fs::exists(case_copy))
        s.spec = read_modern_case(case_copy, {});
    s.spec.params = cp.params;
    s.particles = std::move(cp.particles);
    s.resumed = cp.state;
    s.legacy_clock = cp.legacy_clock;
    s.kept = std::move(cp.extra);
    return s;
}

// --force: removes the files an earlier run wrote into dir (and nothing else).
void remove_run_files(const fs::path& dir) {
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (name.rfind("PART_", 0) == 0 || name.rfind("case.to_step", 0) == 0 ||
            name == "DT" || name == "steps.txt" ||
            name == "EPART" || name == "run.log" || name == "checkpoint.h5" ||
            name == "case.toml" || name == "INDAT" || name == "IPART" ||
            name == "NORMALS.init" || name == "gate" || name == "jet.csv" || name == "drops.csv" ||
            name == "removed_drops.csv")
            fs::remove(e.path());
    }
}

RunStart start_fresh(const RunOptions& opts) {
    const fs::path& dir = opts.out_dir;
    if (dir_has_files(dir) && !opts.force)
        throw InputError(dir.string(), "output directory exists and is not empty",
                         "a new or empty directory (or --force to overwrite, --resume to "
                         "continue)",
                         "existing files");
    LoadedCase lc = load_case(opts.case_path, opts.overrides);
    RunStart s;
    s.spec = std::move(lc.spec);
    s.particles = std::move(lc.particles);
    if (opts.force && fs::exists(dir)) remove_run_files(dir);
    fs::create_directories(dir);
    return s;
}

// The core's state as the checkpoint left it: a resumed run lists the pairs as the first
// run did (bitwise resume), starts from its kept rates and uses its repulsive-wall geometry.
void restore_core_state(Solver& solver, const RunStart& start) {
    solver.state() = start.resumed;
    solver.restore_kept_state([&start](std::string_view name) -> const std::vector<double>* {
        for (const CheckpointArray& a : start.kept)
            if (a.name == name) return &a.values;
        return nullptr;
    });
}

// The log's first lines: version, command, the case and its size, and where the run starts.
void log_start(RunLog& log, const RunOptions& opts, const SimParams& prm, const Solver& solver) {
    const RunState& st = solver.state();
    const fs::path& dir = opts.out_dir;
    const std::size_t np = solver.particles().size();
    const int used_threads = Solver::threads_for(np);   // fewer than asked for a small case
    log.line(fmt::format("sphjet {} ({}) {}", SPHJET_VERSION, h5::git_hash(),
                         opts.resume ? "resuming" : "starting"));
    log.line(fmt::format("command: {}", opts.command_line), false);
    log.line(fmt::format("case: {} | particles {} (boundary {}, fluid {}) | h = {:.6g} m, "
                         "c0 = {:.6g} m/s | kernel {} | threads {}{} (waits: {})",
                         opts.resume ? (dir / "case.toml").string() : opts.case_path.string(), np,
                         solver.particles().nb, solver.particles().n_fluid(), prm.h, prm.c0(),
                         to_string(prm.kernel), Solver::threads(),
                         used_threads == Solver::threads()
                             ? std::string()
                             : fmt::format(", a step of {} particles uses {}", np, used_threads),
                         Solver::openmp_waits()));
    if (opts.resume)
        log.line(fmt::format("resuming at step {} t = {:.6g} s from {}", st.step, st.time,
                             checkpoint_path(dir).string()));
    else if (const std::string note = initial_step_note(prm); !note.empty())
        log.line(note);
}

// ---- outputs ----

// What a run writes as it goes: snapshots (legacy PART/DT/steps.txt and/or HDF5) and
// checkpoints, with what is on disk so far for the message after a failed write.
class RunOutputs {
public:
    RunOutputs(const RunOptions& opts, const CaseSpec& spec, Solver& solver, RunLog& log)
        : opts_(opts), dir_(opts.out_dir), prm_(spec.params), solver_(solver), log_(log),
          legacy_(spec.output.format != OutputFormat::Hdf5),
          hdf5_(spec.output.format != OutputFormat::Legacy) {
        RunState& st = solver.state();
        if (hdf5_) {
            h5_.emplace(dir_, prm_, opts.command_line,
                        opts.resume ? Hdf5Writer::Mode::Resume : Hdf5Writer::Mode::Overwrite,
                        st.step);
            h5_->set_revolution_sectors(spec.output.revolution_sectors);
        }
        if (opts.resume) {
            truncate_rows(dir_ / "DT", st.n_outputs);
            truncate_rows(dir_ / "steps.txt", st.n_outputs);
        }
        if (legacy_) {
            dtfile_.emplace(dir_ / "DT", opts.resume);
            stepsfile_.emplace(dir_ / "steps.txt", opts.resume);
        }
        // the start's snapshot: a failed write stops the run as one in the loop does (nothing
        // complete yet, no checkpoint: run the case again)
        if (h5_ && !opts.resume) or_stop([&] { h5_->write(solver.particles(), st, extra_fields(solver)); });
        saved_.output = st.n_outputs;
        if (!opts.resume) saved_.output_time = st.time;
        if (opts.resume) {
            saved_.checkpoint = true;
            saved_.checkpoint_step = st.step;
            saved_.checkpoint_time = st.time;
        }
    }

    [[nodiscard]] bool legacy() const { return legacy_; }
    [[nodiscard]] bool hdf5() const { return hdf5_; }

    // The next snapshot.
    void snapshot() {
        RunState& st = solver_.state();
        st.n_outputs += 1;
        const double t = opts_.legacy_clock ? st.legacy_time : st.time;
        if (legacy_) {
            write_part(dir_ / fmt::format("PART_{:04d}", st.n_outputs), solver_.particles());
            dtfile_->append({t, st.dt_f, st.dt_cv, st.dt_new});
            stepsfile_->append({static_cast<int>(st.n_outputs), st.step, t});
        }
        // the fields taken afresh: a refilled nozzle (nozzle.refill) grows the arrays
        if (h5_) h5_->write(solver_.particles(), st, extra_fields(solver_));
        saved_.output = st.n_outputs, saved_.output_time = t;
    }

    // The state and the core's state beyond the particles (Solver::kept_state: a resumed run
    // goes on bitwise).
    void checkpoint() {
        const RunState& st = solver_.state();
        const std::vector<ExtraField> kept = solver_.kept_state();
        write_checkpoint(dir_, solver_.particles(), st, prm_, kept, opts_.legacy_clock);
        saved_.checkpoint = true, saved_.checkpoint_step = st.step,
        saved_.checkpoint_time = st.time;
    }

    [[noreturn]] void stop(const WriteError& e) {
        stop_on_write_error(log_, dir_, solver_.state(), saved_, e);
    }

    // A write that fails after the loop stops the run as one inside it does.
    template <class Write>
    void or_stop(Write&& write) {
        try {
            write();
        } catch (const WriteError& e) {
            stop(e);
        }
    }

private:
    const RunOptions& opts_;
    fs::path dir_;
    const SimParams& prm_;
    Solver& solver_;
    RunLog& log_;
    bool legacy_, hdf5_;
    std::optional<Hdf5Writer> h5_;
    std::optional<DtFile> dtfile_;
    std::optional<StepsFile> stepsfile_;
    SavedSoFar saved_;
};

// ---- the loop ----

// SIGINT and SIGTERM stop the run cleanly (with a checkpoint) while this lives.
class StopSignals {
public:
    StopSignals() {
        g_stop_signal.store(0);
        old_int_ = std::signal(SIGINT, on_stop_signal);
        old_term_ = std::signal(SIGTERM, on_stop_signal);
    }
    ~StopSignals() {
        std::signal(SIGINT, old_int_);
        std::signal(SIGTERM, old_term_);
    }
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

private:
    void (*old_int_)(int) = nullptr;
    void (*old_term_)(int) = nullptr;
};

using Clock = std::chrono::steady_clock;

// The progress line: every 0.25 s on a terminal, every 10 s into a log otherwise.
class Progress {
public:
    Progress(const RunOptions& opts, const RunState& st, Clock::time_point t0)
        : opts_(opts), tty_(isatty(fileno(stderr)) && !opts.quiet), t0_(t0), last_(t0),
          step0_(st.step), time0_(st.time) {}

    void maybe_report(RunLog& log, const RunState& st, const SimParams& prm, std::size_t np,
                      Clock::time_point now) {
        const double wall = std::chrono::duration<double>(now - t0_).count();
        const double since_report = std::chrono::duration<double>(now - last_).count();
        if (!((tty_ && since_report > 0.25) || (!tty_ && !opts_.quiet && since_report > 10.0)))
            return;
        last_ = now;
        const double clock = opts_.legacy_clock ? st.legacy_time : st.time;
        const double sps = static_cast<double>(st.step - step0_) / std::max(wall, 1e-9);
        const double rate = (st.time - time0_) / std::max(wall, 1e-9);
        const double eta = rate > 0 ? (prm.tmax - clock) / rate : -1;
        const std::string msg =
            fmt::format("t = {:.5f}/{:.5g} s | step {} | dt {:.3e} s | {:.1f} steps/s | "
                        "{:.3g} particle-steps/s | ETA {}",
                        clock, prm.tmax, st.step, st.dt, sps, sps * static_cast<double>(np),
                        hms(eta));
        if (tty_) log.progress(msg);
        else log.line(msg);
    }

private:
    const RunOptions& opts_;
    bool tty_;
    Clock::time_point t0_, last_;
    std::int64_t step0_;
    double time0_;
};

// Whether a checkpoint is due: every checkpoint_every_steps steps, or every
// checkpoint_every_minutes of wall time since the last one.
class CheckpointClock {
public:
    CheckpointClock(const OutputSpec& out, Clock::time_point t0) : out_(out), last_(t0) {}
    bool due(std::int64_t step, Clock::time_point now) {
        const double since = std::chrono::duration<double>(now - last_).count();
        const bool by_steps =
            out_.checkpoint_every_steps > 0 && step % out_.checkpoint_every_steps == 0;
        const bool by_time = out_.checkpoint_every_minutes > 0 &&
                             since > 60.0 * out_.checkpoint_every_minutes;
        if (by_steps || by_time) last_ = now;
        return by_steps || by_time;
    }

private:
    const OutputSpec& out_;
    Clock::time_point last_;
};

// One step and what follows it: removed particles logged, the snapshot when due, the jet's
// sample (and its drops removed), the density filter when due. Returns why the run stops now
// (empty: go on).
std::string step_once(Solver& solver, RunOutputs& out, std::optional<JetRun>& jet, RunLog& log,
                      bool output_due) {
    RunState& st = solver.state();
    const StepReport r = solver.step(output_due);  // the CSF fields only for outputs
    solver.check_state();
    if (r.removed > 0)
        log.line(fmt::format("step {} t = {:.6g} s: {} particle(s) left the domain and "
                             "were removed ({} in all); ids {}",
                             st.step, st.time, r.removed, st.n_removed,
                             fmt::join(r.removed_ids, " ")));
    if (output_due) out.snapshot();
    if (jet) {
        const JetRun::Check c = jet->after_step(solver.particles(), st.time, st.step, output_due);
        if (!c.gone.empty()) (void)solver.deactivate(c.gone);
        // the renormalised continuity along the intact jet alone, short of its end by
        // domain.renormalise_margin_d0 (RunState::renormalise_reach); a gap at the orifice itself,
        // or a jet no longer than the margin, leaves none
        if (c.sampled)
            st.renormalise_reach = c.reach ? std::max(*c.reach, std::numeric_limits<double>::min()) : 0.0;
        (void)solver.append_fluid(jet->refill(solver.particles()), /*plug_rows=*/true);
    }
    (void)solver.split_heavy_rings();
    if (output_due)
        if (const std::size_t split = solver.rings_split_since_asked(); split > 0)
            log.line(fmt::format("step {} t = {:.6g} s: {} ring(s) too heavy for their radius split in two "
                                 "since the last output",
                                 st.step, st.time, split));
    if (jet) {
        if (std::string why = jet->stop_due(st.time); !why.empty()) return why;
    }
    solver.density_filter_if_due();
    return {};
}

// The step loop up to tmax, max_steps, a stop signal (StopSignals) or the jet's stop. Fills the summary's
// step counts and times. A blow-up is logged (with the jet's record up to it) and rethrown; a
// failed write stops the run (stop_on_write_error).
void step_until_done(const RunOptions& opts, const CaseSpec& spec, Solver& solver,
                     RunOutputs& out, std::optional<JetRun>& jet, RunLog& log, RunSummary& sum) {
    RunState& st = solver.state();
    const SimParams& prm = spec.params;
    const auto t0 = Clock::now();
    Progress progress(opts, st, t0);
    CheckpointClock checkpoints(spec.output, t0);
    const std::int64_t step0 = st.step;
    auto sim_clock = [&]() { return opts.legacy_clock ? st.legacy_time : st.time; };
    try {
        while (sim_clock() < prm.tmax) {
            if (opts.max_steps && st.step - step0 >= *opts.max_steps) break;
            if (g_stop_signal.load() != 0) {
                sum.interrupted = true;
                break;
            }
            const bool output_due = (sim_clock() - prm.trec_ini) -
                                        prm.out * static_cast<double>(st.n_outputs) >=
                                    prm.out;
            if (const std::string why = step_once(solver, out, jet, log, output_due);
                !why.empty()) {
                log.line(fmt::format("stopping at t = {:.6g} s: {}", st.time, why));
                break;
            }
            const std::size_t in_domain = solver.particles().n_active();
            sum.particle_steps += static_cast<double>(in_domain);
            const auto now = Clock::now();
            progress.maybe_report(log, st, prm, in_domain, now);
            if (checkpoints.due(st.step, now)) out.checkpoint();
        }
    } catch (const SimulationError& e) {
        log.clear_progress();
        log.line(fmt::format("FAILED: {}", e.what()));
        if (jet) {  // the jet's record up to the blow-up (its summary and run.h5 /jet)
            try {
                jet->finish(out.hdf5());
            } catch (const std::exception& w) {
                log.line(fmt::format("the jet table could not be written: {}", w.what()));
            }
        }
        log.line(fmt::format("the last good snapshot is output {} (nothing was written from the "
                             "failed state)",
                             st.n_outputs));
        throw;
    } catch (const WriteError& e) {
        out.stop(e);
    }
    log.clear_progress();
    sum.wall_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    sum.steps = st.step - step0;
    sum.total_steps = st.step;
    sum.time = st.time;
    sum.legacy_time = st.legacy_time;
    sum.removed = st.n_removed;
}

// ---- the end of a run ----

// The last checkpoint, EPART (legacy output, not after a signal), the jet's record and the
// summary line.
void finish_run(const RunOptions& opts, const CaseSpec& spec, Solver& solver, RunOutputs& out,
                std::optional<JetRun>& jet, RunLog& log, RunSummary& sum) {
    const RunState& st = solver.state();
    if (jet)
        sum.removed_drops = jet->removed_drops(),
        sum.removed_drop_particles = jet->removed_drop_particles();
    out.or_stop([&] { out.checkpoint(); });
    if (sum.interrupted) {
        log.line(fmt::format("stopped by signal {} at step {} t = {:.6g} s; checkpoint written: "
                             "continue with `sphjet run --resume {}`",
                             g_stop_signal.load(), st.step, st.time, opts.out_dir.string()));
    } else if (out.legacy()) {
        out.or_stop([&] { write_part(opts.out_dir / "EPART", solver.particles()); });
    }
    sum.outputs = st.n_outputs;
    if (jet) out.or_stop([&] { jet->finish(out.hdf5()); });
    if (const Solver::FixedStepRecord& f = solver.fixed_step_record(); f.steps > 0)
        log.line(fmt::format("fixed step: time.dt = {:.6g} s was above the step of the CFL and force conditions "
                             "at {} of these {} steps; that step was {:.6g} s at its smallest ({:.3g} times "
                             "time.dt)",
                             st.dt, f.above, f.steps, f.smallest, f.smallest / st.dt));
    log.line(fmt::format("done: {} steps ({} in all) to t = {:.6g} s (SPHysics clock {:.6g} s) in "
                         "{:.2f} s wall; {:.3g} particle-steps/s; {} outputs; {} particles left "
                         "the domain{}",
                         sum.steps, sum.total_steps, sum.time, sum.legacy_time, sum.wall_seconds,
                         sum.particle_steps_per_second(), sum.outputs, sum.removed,
                         jet && jet->removes()
                             ? fmt::format("; {} drop(s) ({} particles) removed", sum.removed_drops,
                                           sum.removed_drop_particles)
                             : std::string()));
}

}  // namespace

RunSummary run_simulation(const RunOptions& options) {
    const fs::path dir = options.out_dir;
    RunStart start = options.resume ? start_from_checkpoint(dir, options.overrides)
                                     : start_fresh(options);
    RunOptions opts = options;   // a resumed run writes on its checkpoint's output clock
    if (opts.resume && start.legacy_clock) {
        if (opts.legacy_clock && !*start.legacy_clock)
            throw InputError(checkpoint_path(dir).string(), "--legacy-clock with --resume",
                             "no --legacy-clock: the run writes on the simulated time",
                             "--legacy-clock");
        opts.legacy_clock = *start.legacy_clock;
    }
    CaseSpec& spec = start.spec;
    if (opts.tmax) spec.params.tmax = *opts.tmax;
    if (opts.format) spec.output.format = *opts.format;   // refused with --resume (cmd_run.cpp)
    if (spec.output.format != OutputFormat::Hdf5 && !opts.resume) {
        // The legacy post-processing chain reads INDAT and IPART beside the PART files.
        write_legacy_inputs(dir, spec.params, start.particles, spec.legacy);
    }

    if (opts.threads > 0) Solver::set_threads(opts.threads);
    Solver solver(spec.params, spec.output, std::move(start.particles));
    if (opts.resume) restore_core_state(solver, start);

    RunLog log(dir / "run.log", opts.resume);
    fs::path before_changes;   // the case copy a resume with --set replaced
    if (!opts.resume) {
        write_file_atomically(dir / "case.toml", write_modern_case(spec), "the case copy");
    } else if (!opts.overrides.empty()) {
        // the case copy says what the run does from here on; the one it did so far is kept
        before_changes = dir / fmt::format("case.to_step{}.toml", solver.state().step);
        fs::copy_file(dir / "case.toml", before_changes, fs::copy_options::overwrite_existing);
        write_file_atomically(dir / "case.toml", write_modern_case(spec), "the case copy");
    }
    log_start(log, opts, spec.params, solver);
    if (!before_changes.empty())
        log.line(fmt::format("changed from here on: {} (the case copy up to here: {})",
                             fmt::join(opts.overrides, ", "), before_changes.filename().string()));

    RunOutputs out(opts, spec, solver, log);
    std::optional<JetRun> jet;
    if (spec.nozzle)
        jet.emplace(spec, dir, opts.resume, solver.particles(), solver.state().time,
                    solver.state().step, [&log](const std::string& s) { log.line(s); });

    const StopSignals signals;  // until the last checkpoint and the summary are written
    RunSummary sum;
    sum.particles = solver.particles().size();
    sum.fluid = solver.particles().n_fluid();
    step_until_done(opts, spec, solver, out, jet, log, sum);
    finish_run(opts, spec, solver, out, jet, log, sum);
    return sum;
}

}  // namespace sphjet
