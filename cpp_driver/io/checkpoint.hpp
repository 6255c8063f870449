// Checkpoints: everything a run needs to continue bit for bit, in one HDF5 file.
//
// DIR/checkpoint.h5 is built in memory, written as DIR/checkpoint.h5.tmp, fsynced and renamed
// over the old one (io/file_write.hpp), so a crash or a full disk while checkpointing leaves
// the previous checkpoint intact and no temporary file; the file system needs room for both
// for a moment. Doubles are
// stored as IEEE float64 and come back bitwise identical; every array carries HDF5's
// Fletcher-32 checksum, so a corrupted file fails to read instead of restarting from wrong
// numbers.
//
// Layout (h5dump -H):
//   /              attrs format = "sphjet-checkpoint", format_version, code_version,
//                  git_hash, written_utc
//   /particles     attrs n, nb, nbf, n_wall; the particle arrays as in snapshots
//                  (io/particle_group.hpp), checksummed; wall_prev wall_next (int32 [n_wall])
//   /run_state     attrs: every RunState field
//   /parameters    attrs: every SimParams field (as in run.h5)
//   /extra/<name>  float64 arrays of any length the caller adds (integrator or analysis state)
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "io/hdf5_output.hpp"  // ExtraField
#include "model/params.hpp"
#include "model/particles.hpp"
#include "model/run_state.hpp"

namespace sphjet {

struct CheckpointArray {
    std::string name;
    std::vector<double> values;
};

struct Checkpoint {
    ParticleSet particles;
    RunState state;
    SimParams params;
    std::vector<CheckpointArray> extra;  // in name order
    std::string code_version;            // of the code that wrote it
    // outputs on SPHysics' clock (`sphjet run --legacy-clock`); unset where the file does not
    // say (written before the clock was kept)
    std::optional<bool> legacy_clock;

    // The extra array of that name, or nullptr.
    [[nodiscard]] const std::vector<double>* array(std::string_view name) const;
};

// DIR/checkpoint.h5
[[nodiscard]] std::filesystem::path checkpoint_path(const std::filesystem::path& dir);

// Writes DIR/checkpoint.h5 atomically (temporary file, fsync, rename, fsync of DIR); creates
// DIR when missing. extra: named float64 arrays of any length (units are stored when given).
// Throws std::invalid_argument when the particle arrays differ in length or an extra name is
// empty or holds '/', WriteError (an InputError) naming the file and the cause ("No space left
// on device") when the file cannot be written (the old checkpoint stays). legacy_clock: the
// run's output clock, kept so that a resumed run writes on the same one.
void write_checkpoint(const std::filesystem::path& dir, const ParticleSet& ps,
                      const RunState& state, const SimParams& params,
                      std::span<const ExtraField> extra = {}, bool legacy_clock = false);

// Reads DIR/checkpoint.h5 (or the file itself when given a file). Throws InputError naming
// the file and the missing or unreadable dataset or attribute for a missing, truncated or
// corrupt checkpoint.
[[nodiscard]] Checkpoint read_checkpoint(const std::filesystem::path& dir_or_file);

}  // namespace sphjet
