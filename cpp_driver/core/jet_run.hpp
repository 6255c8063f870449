// The jet side of a run (a case with a [nozzle]): samples the jet while the run goes
// (analysis/jet_monitor.hpp), writes DIR/jet.csv, DIR/drops.csv and DIR/jet_surface.csv (one
// row per sample, one per drop and sample, one per slice of the jet's surface profile and
// sample), reports the first breakup in the log, says when the run may stop
// ([breakup] stop_after), and at the end copies the samples into DIR/run.h5 (/jet).
// With [breakup] remove_drops_below_h or remove_drops_beyond_d0 it also picks, at each check,
// the drops to remove (their particles' indices: the caller makes them inactive), logs the
// small ones and writes DIR/removed_drops.csv. On resume the rows written after the
// checkpoint's step go away, the first breakup is read back from jet.csv and the removed drops
// are counted from removed_drops.csv.
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/jet_monitor.hpp"
#include "io/file_write.hpp"
#include "model/case_spec.hpp"
#include "model/particles.hpp"

namespace sphjet {

// How far from the orifice the renormalised continuity reaches along a jet of intact length
// `length` [m] (none while the jet is unbroken): margin_d0 nozzle diameters d0 short of its end
// (domain.renormalise_margin_d0), never below 0.
[[nodiscard]] inline std::optional<double> renormalise_reach(std::optional<double> length, double margin_d0,
                                                             double d0) {
    if (!length) return std::nullopt;
    return std::max(*length - margin_d0 * d0, 0.0);
}

class JetRun {
public:
    using Log = std::function<void(const std::string&)>;
    // time, step: where the run starts (0 for a fresh run, the checkpoint's for a resume).
    JetRun(const CaseSpec& spec, const std::filesystem::path& dir, bool resume, const ParticleSet& ps,
           double time, std::int64_t step, Log log);

    // What a step's check found.
    struct Check {
        bool sampled = false;              // a sample was taken
        std::optional<double> length;      // the jet's intact length [m], when broken
        std::optional<double> reach;       // length less domain.renormalise_margin_d0 nozzle
                                           // diameters (at least 0): how far the renormalised
                                           // continuity reaches, when broken
        std::vector<std::size_t> gone;     // the particles of the drops to remove (empty unless
                                           // remove_drops_below_h or remove_drops_beyond_d0 is set
                                           // and the check found such a drop)
    };
    // After a step: samples when due (every check_every, or when output_written with
    // check_every = 0).
    [[nodiscard]] Check after_step(const ParticleSet& ps, double time, std::int64_t step, bool output_written);
    // nozzle.refill: the plug rows to add now (geometry/nozzle.hpp; empty without refill).
    [[nodiscard]] ParticleSet refill(const ParticleSet& ps) const;
    // Why the run should stop now (empty: go on): stop_after past the first breakup, or the
    // nozzle ran dry (no fluid left upstream of the orifice).
    [[nodiscard]] std::string stop_due(double time) const;
    // The end of a run (or its interruption): /jet in run.h5 and the summary line.
    void finish(bool hdf5);

    [[nodiscard]] std::optional<double> first_breakup_time() const { return first_time_; }
    // Drops removed since t = 0 (remove_drops_below_h and remove_drops_beyond_d0), and their
    // particles.
    [[nodiscard]] std::int64_t removed_drops() const { return small_drops_ + sunk_drops_; }
    [[nodiscard]] std::int64_t removed_drop_particles() const { return removed_particles_; }
    // Whether a rule removes drops (remove_drops_below_h or remove_drops_beyond_d0 set).
    [[nodiscard]] bool removes() const { return remove_below_ > 0 || remove_beyond_ > 0; }

private:
    Check sample(const ParticleSet& ps, double time, std::int64_t step);
    [[nodiscard]] double next_check_after(double time) const;
    void count_orifice_speed(double u_flux, bool out);

    const CaseSpec& spec_;
    std::filesystem::path dir_;
    analysis::JetMonitor mon_;
    std::optional<AppendFile> jet_csv_, drops_csv_, surface_csv_, removed_csv_;  // rows land whole or not at all
    Log log_;
    double next_check_ = 0;
    std::optional<double> first_time_, first_length_, dry_time_;
    std::optional<std::pair<double, double>> last_row_;  // resume: volume out and time of the last kept sample
    double u_sum_ = 0;
    double u_dev_max_ = 0;
    std::int64_t u_n_ = 0;
    double remove_below_ = 0;   // d_eq [m] below which a drop is removed; 0: none
    double remove_beyond_ = 0;  // [m] past the jet's end beyond which a drop is removed; 0: none
    std::int64_t small_drops_ = 0, sunk_drops_ = 0, removed_particles_ = 0;
};

}  // namespace sphjet
