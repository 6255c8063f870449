// HDF5 snapshots of a run, indexed for ParaView by one XDMF file.
//
// A run directory holds
//   run.h5             the case parameters, code version and command line of the run
//   snap_000000.h5 ... one file per snapshot (every particle array, with units; time, step,
//                      dt; a copy of the parameters, so one snapshot stands on its own)
//   sphjet.xmf         the XDMF temporal collection of all snapshots written so far
// Each file is built in memory, written under a temporary name, fsynced and renamed into place
// (io/file_write.hpp), and the index is rewritten the same way after each snapshot: a run
// killed at any moment, or stopped by a full disk, leaves every earlier snapshot readable, an
// index that opens in ParaView and no temporary file.
//
// Snapshot layout (h5dump -H):
//   /                 attrs format = "sphjet-snapshot", format_version, index, time, step, dt,
//                     legacy_time, n_particles, nb, nbf, code_version, git_hash, written_utc
//   /particles/x z u w rho p m     float64 [n], attr units (m, m/s, kg/m^3, Pa, kg)
//   /particles/id                  int64 [n]  (stable id = initial index)
//   /particles/kind active         int32 [n]  (ParticleKind; 1 in the domain, 0 removed)
//   /particles/<extra>             float64 [n], e.g. colour normal_x normal_z curvature
//   /parameters                    attrs: every SimParams field (see h5_util.hpp)
//   /xdmf/points velocity [normal] float64 [n x 3]: (x, 0, z), (u, 0, w), (normal_x, 0,
//                                  normal_z) as HDF5 virtual datasets over the arrays above
//                                  (no extra space; need HDF5 >= 1.10 to read)
//   /xdmf/vertices                 int64 [n] 0..n-1, compressed: Polyvertex connectivity
//
// With Hdf5Writer::set_revolution_sectors(N), N > 0 (an axisymmetric run, [output]
// revolution_sectors), a snapshot also holds its rings revolved about the axis: N copies of
// each particle at phi_k = 2 pi k / N, k = 0..N-1, copy k of particle i in row k n + i:
//   /revolved                      attrs sectors = N, n_points = N n
//   /revolved/points               float64 [N n x 3]: (x cos phi_k, x sin phi_k, z), units m
//   /revolved/velocity             float64 [N n x 3]: (u cos phi_k, u sin phi_k, w), m/s
//   /revolved/normal               float64 [N n x 3]: (normal_x cos phi_k, normal_x sin phi_k,
//                                  normal_z), with the normal fields only
//   /revolved/m_copy               float64 [n]: m / N, kg: a ring's m is its 3D mass, so a
//                                  copy carries m / N and the copies sum to the true mass
//   /revolved/m                    float64 [N n]: m_copy N times over (virtual, no space)
//   /revolved/x z u w rho p id kind active <extra>
//                                  [N n]: the /particles array N times over (virtual, no
//                                  space; x is the radius r, u the radial velocity)
//   /revolved/vertices             int64 [N n] 0..N n-1, compressed
// and the index gets a second temporal collection, "revolved", whose grid at each time shows
// these points; the first collection, "particles", is the same with or without it. Space
// per snapshot: 48 N n bytes (72 N n with the normal) plus 8 n, and about 130 bytes of
// metadata per virtual mapping (one per copy and repeated field).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "model/params.hpp"
#include "model/particles.hpp"
#include "model/run_state.hpp"

namespace sphjet {

// An extra per-particle field written beside the standard ones (the surface-tension fields
// colour, normal_x, normal_z, curvature). Empty units: default_units(name).
struct ExtraField {
    std::string name;
    std::span<const double> values;
    std::string units;
};

// Units of the fields this code knows: colour, normal_x, normal_z -> "1", curvature -> "1/m";
// "1" for any other name.
[[nodiscard]] std::string default_units(std::string_view field);

// "snap_000042.h5"
[[nodiscard]] std::string snapshot_file_name(std::int64_t index);

// What the index needs to know of one snapshot already on disk.
struct SnapshotInfo {
    std::int64_t index = 0;
    std::string file;   // name inside the run directory
    double time = 0.0;  // [s]
    std::int64_t step = 0;
    std::size_t n = 0;               // particles
    std::vector<std::string> extra;  // names of the extra fields, in name order
    int revolution_sectors = 0;      // copies in /revolved (0: none)
};

class Hdf5Writer {
public:
    enum class Mode {
        Fresh,      // the directory must not hold snapshots yet (it is created if missing)
        Overwrite,  // removes earlier snapshots, run.h5 and the index first
        Resume,     // keeps snapshots up to resume_step and continues numbering after them
    };

    // Writes DIR/run.h5 (parameters, code version, command line). Throws InputError when the
    // directory cannot be made or (Fresh) already holds snapshots. In Resume mode the leading
    // snapshots with step <= resume_step are kept and indexed; later ones stay on disk, are
    // left out of the index and are replaced as the resumed run writes them again.
    Hdf5Writer(std::filesystem::path dir, const SimParams& params, std::string command_line,
               Mode mode = Mode::Fresh, std::int64_t resume_step = 0);

    // Writes the next snapshot and rewrites the index; returns the snapshot's path. Every
    // particle array must have ps.size() values, and so must each extra field (whose name
    // must not be a standard field's). Throws WriteError (an InputError) naming the file and
// the cause when the snapshot or the index cannot be written (a snapshot that was written
// stays, even if the index could not be rewritten to list it).
    std::filesystem::path write(const ParticleSet& ps, const RunState& state,
                                std::span<const ExtraField> extra = {});

    // From the next snapshot on, also write the rings revolved into sectors copies (0: off;
    // the layout above). Throws std::invalid_argument unless 0 <= sectors <=
    // kMaxRevolutionSectors (model/case_spec.hpp), and for sectors > 0 unless the parameters'
    // geometry is axisymmetric.
    void set_revolution_sectors(int sectors);
    [[nodiscard]] int revolution_sectors() const { return revolution_sectors_; }

    [[nodiscard]] const std::filesystem::path& dir() const { return dir_; }
    [[nodiscard]] std::filesystem::path xdmf_path() const { return dir_ / "sphjet.xmf"; }
    [[nodiscard]] const std::vector<SnapshotInfo>& snapshots() const { return snapshots_; }

private:
    std::filesystem::path dir_;
    SimParams params_;
    std::vector<SnapshotInfo> snapshots_;
    int revolution_sectors_ = 0;
};

// One snapshot read back.
struct Snapshot {
    ParticleSet particles;  // wall links are not part of a snapshot (see checkpoint.hpp)
    std::int64_t index = 0;
    double time = 0.0, legacy_time = 0.0, dt = 0.0;
    std::int64_t step = 0;
    std::vector<std::pair<std::string, std::vector<double>>> extra;  // in name order

    // The extra field of that name, or nullptr.
    [[nodiscard]] const std::vector<double>* field(std::string_view name) const;
};

// Reads a snapshot written by Hdf5Writer. InputError names the file and the missing or
// malformed dataset.
[[nodiscard]] Snapshot read_snapshot(const std::filesystem::path& path);

// Reads the parameters of a run from run.h5 or any snapshot.
[[nodiscard]] SimParams read_run_params(const std::filesystem::path& path);

}  // namespace sphjet
