#include "analysis/run_frames.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>

#include <fmt/format.h>

#include "config/load_case.hpp"
#include "io/h5_util.hpp"
#include "io/hdf5_output.hpp"
#include "io/legacy_output.hpp"
#include "model/errors.hpp"

namespace fs = std::filesystem;

namespace sphjet::analysis {

namespace {

bool has_snapshots(const fs::path& dir) {
    static const std::regex re(R"(snap_(\d+)\.h5)");
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_regular_file() && std::regex_match(e.path().filename().string(), re)) return true;
    return false;
}

bool has_part_files(const fs::path& dir) {
    static const std::regex re(R"(PART_(\d+))");
    for (const auto& e : fs::directory_iterator(dir)) {
        if (!e.is_regular_file()) continue;
        const std::string name = e.path().filename().string();
        if (std::regex_match(name, re) || name == "IPART" || name == "EPART") return true;
    }
    return false;
}

}  // namespace

RunFrames::RunFrames(const fs::path& dir, RunFrameOptions opts) : dir_(dir), opts_(opts) {
    if (!fs::is_directory(dir))
        throw InputError(dir.string(), "not a run directory",
                         "a directory with PART_nnnn or snap_nnnnnn.h5 files",
                         fs::exists(dir) ? "a file" : "nothing");
    const bool parts = has_part_files(dir);
    const bool snaps = has_snapshots(dir);
    if (!parts && !snaps)
        throw InputError(dir.string(), "no particle files",
                         "PART_nnnn / IPART / EPART (legacy format) or snap_nnnnnn.h5 (HDF5)",
                         "none");
    source_ = (snaps && (opts.prefer_hdf5 || !parts)) ? RunSource::Hdf5 : RunSource::LegacyPart;

    if (source_ == RunSource::Hdf5) {
        static const std::regex re(R"(snap_(\d+)\.h5)");
        std::map<std::int64_t, fs::path> files;
        for (const auto& e : fs::directory_iterator(dir)) {
            std::smatch m;
            const std::string name = e.path().filename().string();
            if (e.is_regular_file() && std::regex_match(name, m, re))
                files[std::stoll(m[1])] = e.path();
        }
        for (const auto& [k, p] : files) {
            // Only the attributes: time and step (and nb/dx once).
            h5::File f = h5::open_file(p);
            Frame fr;
            fr.number = static_cast<int>(k);
            fr.file = p;
            fr.time = h5::read_attr_double(f.get(), "time");
            fr.step = h5::read_attr_int64(f.get(), "step");
            if (!nb_) {
                nb_ = static_cast<std::size_t>(h5::read_attr_int64(f.get(), "nb"));
                nb_source_ = "snapshot";
                const SimParams prm = read_run_params(p);
                dx_ = prm.dx;
            }
            if (fr.number == 0 && !opts.include_initial) continue;
            frames_.push_back(fr);
        }
        return;
    }

    // PART files: a legacy run or ours.
    const LegacyRun run = read_legacy_run(dir);
    if (run.indat) {
        nb_ = run.indat->nb;
        nbf_ = run.indat->nbf;
        np_ = run.indat->np;
        dx_ = run.indat->dx;
        nb_source_ = "INDAT";
    } else if (fs::is_regular_file(dir / "case.toml")) {
        // A sphjet run: regenerate the initial state from the case it recorded.
        LoadedCase lc = load_case(dir / "case.toml", {});
        nb_ = lc.particles.nb;
        nbf_ = lc.particles.nbf;
        np_ = lc.particles.size();
        dx_ = lc.spec.params.dx;
        nb_source_ = "case.toml";
        initial_ = std::move(lc.particles);
    }
    if (opts.nb) {
        nb_ = opts.nb;
        nbf_ = opts.nbf ? opts.nbf : opts.nb;
        nb_source_ = "--nb";
    } else if (opts.nbf) {
        nbf_ = opts.nbf;
    }
    if (!nb_)
        throw InputError(dir.string(), "the number of boundary particles is unknown",
                         "an INDAT (legacy run) or case.toml (sphjet run) in the directory, or --nb",
                         "neither");

    const bool has_ipart = std::any_of(run.outputs.begin(), run.outputs.end(),
                                       [](const RunOutput& o) { return o.number == kInitialOutput; });
    if (opts.include_initial && !has_ipart && initial_) {
        Frame fr;
        fr.number = kInitialOutput;
        fr.time = 0.0;
        fr.step = 0;
        frames_.push_back(fr);
        removed_.emplace_back();
    }
    // A sphjet run (steps.txt) has no steps.txt row for EPART, whose DT-based time would be
    // the last PART file's: its time and step are in run.log's "done:" line instead.
    std::optional<double> end_time;
    std::optional<std::int64_t> end_step;
    if (!run.steps.empty() && fs::is_regular_file(dir / "run.log")) {
        std::ifstream in(dir / "run.log");
        static const std::regex done_re(R"(done: \d+ steps \((\d+) in all\) to t = ([-+0-9.eE]+) s)");
        std::string line;
        while (std::getline(in, line)) {
            std::smatch m;
            if (std::regex_search(line, m, done_re)) {
                end_step = std::stoll(m[1]);
                end_time = std::stod(m[2]);
            }
        }
    }
    for (const auto& o : run.outputs) {
        if (o.number == kInitialOutput && !opts.include_initial) continue;
        Frame fr{o.number, o.time, o.step, o.file};
        if (o.number == kFinalOutput && !run.steps.empty() &&
            std::none_of(run.steps.begin(), run.steps.end(),
                         [](const StepsRow& r) { return r.output == kFinalOutput; })) {
            fr.time = end_time;
            fr.step = end_step;
        }
        frames_.push_back(fr);
        removed_.push_back(o.removed);
    }
}

ParticleSet RunFrames::load(std::size_t i) const {
    const Frame& fr = frames_.at(i);
    ParticleSet ps;
    if (source_ == RunSource::Hdf5) {
        ps = read_snapshot(fr.file).particles;
    } else if (fr.file.empty()) {
        ps = *initial_;
        if (ps.active.size() != ps.size()) ps.active.assign(ps.size(), 1);
    } else {
        ps = read_part(fr.file, *nb_, nbf_ ? *nbf_ : *nb_);
        if (np_ && ps.size() != *np_)
            throw InputError(fr.file.string(), "particle count differs from the case",
                             fmt::format("{} particles ({})", *np_, nb_source_),
                             fmt::format("{} lines", ps.size()));
        for (auto id : removed_.at(i))
            if (id >= 0 && static_cast<std::size_t>(id) < ps.size() &&
                ps.kind[id] == static_cast<int>(ParticleKind::Fluid))
                ps.active[id] = 0;
    }
    mark_outside_container(ps);
    return ps;
}

std::optional<std::size_t> RunFrames::nearest(double t, double tol) const {
    std::optional<std::size_t> best;
    double best_d = tol;
    for (std::size_t i = 0; i < frames_.size(); ++i) {
        if (!frames_[i].time) continue;
        const double d = std::abs(*frames_[i].time - t);
        if (d <= best_d) {
            best_d = d;
            best = i;
        }
    }
    return best;
}

}  // namespace sphjet::analysis
