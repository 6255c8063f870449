// The outputs of any run directory as particle sets, whatever wrote it:
//   - a legacy SPHysics run: PART_nnnn (+ IPART, EPART), INDAT (nb), DT / stdout.txt (times,
//     steps, removed particles);
//   - a sphjet run with legacy output: PART_nnnn, EPART, steps.txt, and case.toml, from which
//     the boundary count nb (and the initial state, output 0) is regenerated;
//   - a sphjet run with HDF5 output: snap_nnnnnn.h5 (each holds nb, time, step, active flags).
// A directory holding both PART and snapshot files is read through its PART files unless
// HDF5 is asked for. Analyses then look at the fluid that is active and inside the container
// (io/legacy_output.hpp: mark_outside_container), so particles that left the domain are
// ignored the same way for legacy runs and ours.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "model/particles.hpp"

namespace sphjet::analysis {

enum class RunSource { LegacyPart, Hdf5 };

struct Frame {
    int number = 0;                    // PART_k: k; IPART / initial state: 0; EPART: -1;
                                       // HDF5: the snapshot index
    std::optional<double> time;        // [s]
    std::optional<std::int64_t> step;
    std::filesystem::path file;        // empty for the initial state regenerated from case.toml
};

struct RunFrameOptions {
    std::optional<std::size_t> nb, nbf;  // override the boundary counts (legacy files)
    bool prefer_hdf5 = false;             // read snap_*.h5 even where PART files exist
    bool include_initial = true;          // output 0 (IPART, or regenerated from case.toml)
};

class RunFrames {
public:
    // Throws InputError (naming the directory) when it holds neither PART nor snap_*.h5
    // files, or when the boundary count of PART files can be found nowhere (no INDAT, no
    // case.toml, no --nb).
    explicit RunFrames(const std::filesystem::path& dir, RunFrameOptions opts = {});

    [[nodiscard]] const std::vector<Frame>& frames() const { return frames_; }
    [[nodiscard]] RunSource source() const { return source_; }
    [[nodiscard]] const std::filesystem::path& dir() const { return dir_; }
    // Particle spacing when known (INDAT, case.toml or snapshot parameters).
    [[nodiscard]] std::optional<double> dx() const { return dx_; }
    [[nodiscard]] std::optional<std::size_t> nb() const { return nb_; }
    // Where nb came from, for messages: "INDAT", "case.toml", "--nb", "snapshot".
    [[nodiscard]] const std::string& nb_source() const { return nb_source_; }

    // Frame i (an index into frames()) with removed and out-of-container fluid inactive.
    [[nodiscard]] ParticleSet load(std::size_t i) const;

    // The frame whose time is nearest t (within tol), if any.
    [[nodiscard]] std::optional<std::size_t> nearest(double t, double tol) const;

private:
    std::filesystem::path dir_;
    RunFrameOptions opts_;
    RunSource source_ = RunSource::LegacyPart;
    std::vector<Frame> frames_;
    std::vector<std::vector<std::int64_t>> removed_;  // legacy stdout: ids removed before frame
    std::optional<double> dx_;
    std::optional<std::size_t> nb_, nbf_;
    std::optional<std::size_t> np_;  // INDAT np, checked on load
    std::string nb_source_;
    std::optional<ParticleSet> initial_;  // regenerated from case.toml
};

}  // namespace sphjet::analysis
