#include "io/hdf5_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <regex>
#include <stdexcept>
#include <system_error>

#include "io/h5_util.hpp"
#include "io/particle_group.hpp"
#include "io/xdmf.hpp"
#include "model/case_spec.hpp"
#include "model/errors.hpp"

namespace sphjet {

namespace fs = std::filesystem;

namespace {

constexpr std::int64_t kFormatVersion = 1;
const char* const kRunName = "run.h5";

bool is_std_field(std::string_view name) { return particle_group::find(name) != nullptr; }

void check_sizes(const ParticleSet& ps, std::span<const ExtraField> extra) {
    particle_group::check_lengths(ps, "Hdf5Writer");
    const std::size_t n = ps.size();
    for (const ExtraField& e : extra) {
        if (e.name.empty() || e.name.find_first_of("/.") != std::string::npos ||
            is_std_field(e.name)) {
            throw std::invalid_argument("Hdf5Writer: bad extra field name '" + e.name + "'");
        }
        if (e.values.size() != n) {
            throw std::invalid_argument(
                fmt::format("Hdf5Writer: extra field {} has {} values, expected {}", e.name,
                            e.values.size(), n));
        }
    }
}

// Snapshot files in dir, by index.
std::map<std::int64_t, std::string> list_snapshots(const fs::path& dir) {
    static const std::regex re(R"(snap_(\d+)\.h5)");
    std::map<std::int64_t, std::string> out;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        const std::string name = e.path().filename().string();
        std::smatch m;
        if (std::regex_match(name, m, re)) out[std::stoll(m[1].str())] = name;
    }
    return out;
}

SnapshotInfo read_info(const fs::path& dir, std::int64_t index, const std::string& name) {
    h5::File f = h5::open_file(dir / name);
    SnapshotInfo s;
    s.index = index;
    s.file = name;
    s.time = h5::read_attr_double(f, "time");
    s.step = h5::read_attr_int64(f, "step");
    s.n = static_cast<std::size_t>(h5::read_attr_int64(f, "n_particles"));
    h5::Group g = h5::open_group(f, "particles");
    for (const std::string& l : h5::link_names(g)) {
        if (!is_std_field(l)) s.extra.push_back(l);
    }
    if (h5::has_link(f, "revolved")) {
        h5::Group r = h5::open_group(f, "revolved");
        const std::int64_t sectors = h5::read_attr_int64(r, "sectors");
        if (sectors < 1 || sectors > kMaxRevolutionSectors) {
            throw InputError(h5::where(r) + " attribute 'sectors'", "out of range",
                             fmt::format("1 to {}", kMaxRevolutionSectors),
                             std::to_string(sectors));
        }
        s.revolution_sectors = static_cast<int>(sectors);
    }
    return s;
}

bool has_extra(const SnapshotInfo& s, std::string_view name) {
    return std::find(s.extra.begin(), s.extra.end(), name) != s.extra.end();
}

bool has_normal(const SnapshotInfo& s) {
    return has_extra(s, "normal_x") && has_extra(s, "normal_z");
}

xdmf::NumberType number_type(particle_group::Type t) {
    return t == particle_group::Type::Int64   ? xdmf::NumberType::Int64
           : t == particle_group::Type::Int32 ? xdmf::NumberType::Int32
                                              : xdmf::NumberType::Float64;
}

// The grid of one snapshot: its points, vectors and connectivity in group `views`, its
// scalars in group `scalars` ("/xdmf" and "/particles" for the (r, z) or planar particles,
// "/revolved" for both in the revolved copies).
xdmf::Grid grid_of(const SnapshotInfo& s, const std::string& name, std::size_t n,
                   const std::string& views, const std::string& scalars) {
    xdmf::Grid g;
    g.name = name;
    g.h5_file = s.file;
    g.time = s.time;
    g.n = n;
    g.connectivity = views + "/vertices";
    g.points = views + "/points";
    g.fields.push_back({"velocity", views + "/velocity", xdmf::NumberType::Float64, true});
    if (has_normal(s))
        g.fields.push_back({"normal", views + "/normal", xdmf::NumberType::Float64, true});
    for (const particle_group::Field& f : particle_group::fields()) {
        g.fields.push_back({f.name, scalars + "/" + f.name, number_type(f.type), false});
    }
    for (const std::string& e : s.extra) {
        g.fields.push_back({e, scalars + "/" + e, xdmf::NumberType::Float64, false});
    }
    return g;
}

xdmf::Grid grid_of(const SnapshotInfo& s) {
    return grid_of(s, fmt::format("snap_{:06d}", s.index), s.n, "/xdmf", "/particles");
}

xdmf::Grid revolved_grid_of(const SnapshotInfo& s) {
    return grid_of(s, fmt::format("snap_{:06d}_revolved", s.index),
                   s.n * static_cast<std::size_t>(s.revolution_sectors), "/revolved",
                   "/revolved");
}

// The index of these snapshots: the collection "particles", and "revolved" when a snapshot
// has revolved copies.
void write_index(const fs::path& path, const std::vector<SnapshotInfo>& snapshots) {
    std::vector<xdmf::Collection> c(1);
    c[0].name = "particles";
    c[0].grids.reserve(snapshots.size());
    for (const SnapshotInfo& s : snapshots) c[0].grids.push_back(grid_of(s));
    for (const SnapshotInfo& s : snapshots) {
        if (s.revolution_sectors <= 0) continue;
        if (c.size() == 1) c.push_back({"revolved", {}});
        c[1].grids.push_back(revolved_grid_of(s));
    }
    xdmf::write(path, std::span<const xdmf::Collection>(c));
}

// Rows k n + i of an [N n x 3] array: (a_i cos phi_k, a_i sin phi_k, b_i).
std::vector<double> revolve(std::span<const double> a, std::span<const double> b,
                            std::span<const double> cos_phi, std::span<const double> sin_phi) {
    const std::size_t n = a.size();
    std::vector<double> out(3 * n * cos_phi.size());
    double* o = out.data();
    for (std::size_t k = 0; k < cos_phi.size(); ++k) {
        for (std::size_t i = 0; i < n; ++i, o += 3) {
            o[0] = a[i] * cos_phi[k];
            o[1] = a[i] * sin_phi[k];
            o[2] = b[i];
        }
    }
    return out;
}

// The group /revolved of a snapshot (layout in hdf5_output.hpp).
void write_revolved(hid_t file, const ParticleSet& ps, std::span<const ExtraField> extra,
                    int sectors, bool normal) {
    const std::size_t n = ps.size(), copies = static_cast<std::size_t>(sectors);
    std::vector<double> cos_phi(copies), sin_phi(copies);
    for (std::size_t k = 0; k < copies; ++k) {
        const double phi = 2.0 * std::numbers::pi * static_cast<double>(k) / sectors;
        cos_phi[k] = std::cos(phi);
        sin_phi[k] = std::sin(phi);
    }
    h5::Group g = h5::create_group(file, "revolved");
    h5::write_attr(g, "sectors", static_cast<std::int64_t>(sectors));
    h5::write_attr(g, "n_points", static_cast<std::int64_t>(n * copies));
    h5::write_vec3_array(g, "points", revolve(ps.x, ps.z, cos_phi, sin_phi), "m");
    h5::write_vec3_array(g, "velocity", revolve(ps.u, ps.w, cos_phi, sin_phi), "m/s");
    if (normal) {
        std::span<const double> nx, nz;
        for (const ExtraField& e : extra) {
            if (e.name == "normal_x") nx = e.values;
            if (e.name == "normal_z") nz = e.values;
        }
        h5::write_vec3_array(g, "normal", revolve(nx, nz, cos_phi, sin_phi), "1");
    }
    std::vector<double> m_copy(ps.m);
    for (double& m : m_copy) m /= sectors;
    h5::write_array(g, "m_copy", std::span<const double>(m_copy), "kg");
    for (const particle_group::Field& f : particle_group::fields()) {
        const std::string name = f.name;
        const std::string source = name == "m" ? "/revolved/m_copy" : "/particles/" + name;
        h5::write_repeat_view(g, name, source, particle_group::h5_type(f.type), n, copies);
    }
    for (const ExtraField& e : extra) {
        h5::write_repeat_view(g, e.name, "/particles/" + e.name, H5T_IEEE_F64LE, n, copies);
    }
    h5::write_iota(g, "vertices", n * copies);
}

void remove_quietly(const fs::path& p) {
    std::error_code ec;
    fs::remove(p, ec);
}

// Writes run.h5 (built in memory, then run.h5.tmp, fsync and rename).
void write_run_file(const fs::path& dir, const SimParams& params, const std::string& command_line,
                    const std::string& history) {
    const fs::path final_path = dir / kRunName;
    h5::File f = h5::create_file(final_path);
    h5::write_attr(f, "format", std::string("sphjet-run"));
    h5::write_attr(f, "format_version", kFormatVersion);
    h5::write_attr(f, "code_version", h5::code_version());
    h5::write_attr(f, "git_hash", h5::git_hash());
    h5::write_attr(f, "hdf5_version",
                   fmt::format("{}.{}.{}", H5_VERS_MAJOR, H5_VERS_MINOR, H5_VERS_RELEASE));
    h5::write_attr(f, "command_line", command_line);
    h5::write_attr(f, "started_utc", h5::utc_now());
    h5::write_attr(f, "history", history);
    h5::Group g = h5::create_group(f, "parameters");
    h5::write_params(g, params);
    g.reset();
    h5::write_file(f, final_path, "the run file");
}

}  // namespace

std::string default_units(std::string_view field) {
    if (field == "curvature") return "1/m";
    if (const particle_group::Field* f = particle_group::find(field)) return f->units;
    return "1";  // colour, normal_x, normal_z and anything else
}

std::string snapshot_file_name(std::int64_t index) { return fmt::format("snap_{:06d}.h5", index); }

Hdf5Writer::Hdf5Writer(fs::path dir, const SimParams& params, std::string command_line, Mode mode,
                       std::int64_t resume_step)
    : dir_(std::move(dir)), params_(params) {
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec || !fs::is_directory(dir_)) {
        throw InputError(dir_.string(), "cannot create the output directory: " + ec.message());
    }
    const auto existing = list_snapshots(dir_);
    std::string history;
    const std::string line = h5::utc_now() + " " + command_line;
    switch (mode) {
        case Mode::Fresh:
            if (!existing.empty()) {
                throw InputError(dir_.string(), "the output directory already holds snapshots",
                                 "an empty directory (or overwrite / resume)",
                                 existing.begin()->second);
            }
            history = line;
            break;
        case Mode::Overwrite:
            for (const auto& [index, name] : existing) remove_quietly(dir_ / name);
            remove_quietly(xdmf_path());
            remove_quietly(dir_ / kRunName);
            history = line;
            break;
        case Mode::Resume: {
            for (std::int64_t k = 0;; ++k) {
                const auto it = existing.find(k);
                if (it == existing.end()) break;
                SnapshotInfo s = read_info(dir_, k, it->second);
                if (s.step > resume_step) break;
                snapshots_.push_back(std::move(s));
            }
            if (fs::exists(dir_ / kRunName)) {
                try {
                    h5::File f = h5::open_file(dir_ / kRunName);
                    history = h5::read_attr_string(f, "history") + "\n";
                } catch (const InputError&) {
                    // An unreadable run.h5 is replaced; the history starts again.
                }
            }
            history += line + fmt::format(" (resumed at step {})", resume_step);
            break;
        }
    }
    write_run_file(dir_, params_, command_line, history);
    if (mode == Mode::Resume) {
        if (snapshots_.empty()) {
            remove_quietly(xdmf_path());
        } else {
            write_index(xdmf_path(), snapshots_);
        }
    }
}

void Hdf5Writer::set_revolution_sectors(int sectors) {
    if (sectors < 0 || sectors > kMaxRevolutionSectors) {
        throw std::invalid_argument(fmt::format(
            "Hdf5Writer: {} revolution sectors, expected 0 to {}", sectors, kMaxRevolutionSectors));
    }
    if (sectors > 0 && params_.geometry != Geometry::Axisymmetric) {
        throw std::invalid_argument("Hdf5Writer: revolution sectors need the axisymmetric geometry");
    }
    revolution_sectors_ = sectors;
}

fs::path Hdf5Writer::write(const ParticleSet& ps, const RunState& state,
                           std::span<const ExtraField> extra) {
    check_sizes(ps, extra);
    SnapshotInfo info;
    info.index = snapshots_.empty() ? 0 : snapshots_.back().index + 1;
    info.file = snapshot_file_name(info.index);
    info.time = state.time;
    info.step = state.step;
    info.n = ps.size();
    for (const ExtraField& e : extra) info.extra.push_back(e.name);
    info.revolution_sectors = revolution_sectors_;

    const fs::path final_path = dir_ / info.file;
    {
        // Raw data: 7 float64 + 1 int64 + 2 int32 per particle, and the extra fields; revolved
        // copies: 2 or 3 float64 [N n x 3] and m / N.
        const std::size_t sectors = static_cast<std::size_t>(revolution_sectors_);
        const std::size_t bytes = ps.size() * (8 * (8 + extra.size()) + 8) +
                                  ps.size() * sectors * 24 * (has_normal(info) ? 3 : 2) +
                                  (sectors > 0 ? 8 * ps.size() : 0);
        h5::File f = h5::create_file(final_path, bytes);
        h5::write_attr(f, "format", std::string("sphjet-snapshot"));
        h5::write_attr(f, "format_version", kFormatVersion);
        h5::write_attr(f, "index", info.index);
        h5::write_attr(f, "time", state.time);
        h5::write_attr(f, "time_units", std::string("s"));
        h5::write_attr(f, "legacy_time", state.legacy_time);
        h5::write_attr(f, "step", state.step);
        h5::write_attr(f, "dt", state.dt);
        h5::write_attr(f, "dt_units", std::string("s"));
        h5::write_attr(f, "n_particles", static_cast<std::int64_t>(ps.size()));
        h5::write_attr(f, "nb", static_cast<std::int64_t>(ps.nb));
        h5::write_attr(f, "nbf", static_cast<std::int64_t>(ps.nbf));
        h5::write_attr(f, "code_version", h5::code_version());
        h5::write_attr(f, "git_hash", h5::git_hash());
        h5::write_attr(f, "written_utc", h5::utc_now());
        {
            h5::Group g = h5::create_group(f, "particles");
            particle_group::write(g, ps);
            for (const ExtraField& e : extra) {
                const std::string u = e.units.empty() ? default_units(e.name) : e.units;
                h5::write_array(g, e.name, e.values, u.c_str());
            }
        }
        {
            h5::Group g = h5::create_group(f, "parameters");
            h5::write_params(g, params_);
        }
        {
            // What the XDMF index reads: points (x, 0, z), vectors (u, 0, w) and
            // (normal_x, 0, normal_z) as views of the arrays above, and the connectivity.
            h5::Group g = h5::create_group(f, "xdmf");
            const std::size_t n = ps.size();
            h5::write_vec3_view(g, "points", {"/particles/x", "", "/particles/z"}, n);
            h5::write_vec3_view(g, "velocity", {"/particles/u", "", "/particles/w"}, n);
            if (has_normal(info)) {
                h5::write_vec3_view(g, "normal", {"/particles/normal_x", "", "/particles/normal_z"},
                                    n);
            }
            h5::write_iota(g, "vertices", n);
        }
        if (revolution_sectors_ > 0)
            write_revolved(f, ps, extra, revolution_sectors_, has_normal(info));
        h5::write_file(f, final_path, "the snapshot");
    }

    snapshots_.push_back(std::move(info));
    write_index(xdmf_path(), snapshots_);
    return final_path;
}

const std::vector<double>* Snapshot::field(std::string_view name) const {
    for (const auto& [n, v] : extra) {
        if (n == name) return &v;
    }
    return nullptr;
}

Snapshot read_snapshot(const fs::path& path) {
    h5::File f = h5::open_file(path);
    Snapshot s;
    s.index = h5::read_attr_int64(f, "index");
    s.time = h5::read_attr_double(f, "time");
    s.legacy_time = h5::read_attr_double(f, "legacy_time");
    s.dt = h5::read_attr_double(f, "dt");
    s.step = h5::read_attr_int64(f, "step");
    const auto n = static_cast<std::size_t>(h5::read_attr_int64(f, "n_particles"));
    ParticleSet& ps = s.particles;
    ps.nb = static_cast<std::size_t>(h5::read_attr_int64(f, "nb"));
    ps.nbf = static_cast<std::size_t>(h5::read_attr_int64(f, "nbf"));
    h5::Group g = h5::open_group(f, "particles");
    particle_group::read(g, ps, n);
    for (const std::string& name : h5::link_names(g)) {
        if (!is_std_field(name)) s.extra.emplace_back(name, h5::read_doubles(g, name, n));
    }
    return s;
}

SimParams read_run_params(const fs::path& path) {
    h5::File f = h5::open_file(path);
    h5::Group g = h5::open_group(f, "parameters");
    return h5::read_params(g);
}

}  // namespace sphjet
