#include "io/checkpoint.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <system_error>

#include "io/h5_util.hpp"
#include "io/particle_group.hpp"
#include "model/errors.hpp"

namespace sphjet {

namespace fs = std::filesystem;

namespace {

constexpr std::int64_t kFormatVersion = 1;
constexpr auto kSum = h5::Layout::Checksummed;

// Calls f(name, field, later) for every field of RunState, in declaration order; later: the
// field came after format version 1's first files, which lack it (read as RunState's default).
template <class S, class F>
void visit_state(S& s, F&& f) {
    f("time", s.time, false);
    f("legacy_time", s.legacy_time, false);
    f("step", s.step, false);
    f("dt", s.dt, false);
    f("dt_f", s.dt_f, false);
    f("dt_cv", s.dt_cv, false);
    f("dt_new", s.dt_new, false);
    f("dbc_counter", s.dbc_counter, false);
    f("n_outputs", s.n_outputs, false);
    f("n_removed", s.n_removed, false);
    f("renormalise_reach", s.renormalise_reach, true);
}

void check_sizes(const ParticleSet& ps, std::span<const ExtraField> extra) {
    particle_group::check_lengths(ps, "write_checkpoint");
    for (const ExtraField& e : extra) {
        if (e.name.empty() || e.name.find_first_of("/.") != std::string::npos) {
            throw std::invalid_argument("write_checkpoint: bad extra array name '" + e.name + "'");
        }
    }
}

}  // namespace

const std::vector<double>* Checkpoint::array(std::string_view name) const {
    for (const CheckpointArray& a : extra) {
        if (a.name == name) return &a.values;
    }
    return nullptr;
}

fs::path checkpoint_path(const fs::path& dir) { return dir / "checkpoint.h5"; }

void write_checkpoint(const fs::path& dir, const ParticleSet& ps, const RunState& state,
                      const SimParams& params, std::span<const ExtraField> extra,
                      bool legacy_clock) {
    check_sizes(ps, extra);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) {
        throw InputError(dir.string(), "cannot create the checkpoint directory: " + ec.message());
    }
    const fs::path final_path = checkpoint_path(dir);
    {
        std::size_t bytes = ps.size() * 64 + ps.wall.size() * 8;  // raw data
        for (const ExtraField& e : extra) bytes += e.values.size() * 8;
        h5::File f = h5::create_file(final_path, bytes);
        h5::write_attr(f, "format", std::string("sphjet-checkpoint"));
        h5::write_attr(f, "format_version", kFormatVersion);
        h5::write_attr(f, "code_version", h5::code_version());
        h5::write_attr(f, "git_hash", h5::git_hash());
        h5::write_attr(f, "written_utc", h5::utc_now());
        h5::write_attr(f, "output_clock", std::string(legacy_clock ? "legacy" : "time"));
        {
            h5::Group g = h5::create_group(f, "particles");
            h5::write_attr(g, "n", static_cast<std::int64_t>(ps.size()));
            h5::write_attr(g, "nb", static_cast<std::int64_t>(ps.nb));
            h5::write_attr(g, "nbf", static_cast<std::int64_t>(ps.nbf));
            h5::write_attr(g, "n_wall", static_cast<std::int64_t>(ps.wall.size()));
            particle_group::write(g, ps, kSum);
            std::vector<std::int32_t> prev(ps.wall.size()), next(ps.wall.size());
            for (std::size_t i = 0; i < ps.wall.size(); ++i) {
                prev[i] = ps.wall[i].prev;
                next[i] = ps.wall[i].next;
            }
            h5::write_array(g, "wall_prev", std::span<const std::int32_t>(prev), "1", kSum);
            h5::write_array(g, "wall_next", std::span<const std::int32_t>(next), "1", kSum);
        }
        {
            h5::Group g = h5::create_group(f, "run_state");
            visit_state(state,
                        [&g](const char* name, const auto& v, bool) { h5::write_attr(g, name, v); });
        }
        {
            h5::Group g = h5::create_group(f, "parameters");
            h5::write_params(g, params);
        }
        {
            h5::Group g = h5::create_group(f, "extra");
            for (const ExtraField& e : extra) {
                h5::write_array(g, e.name, e.values, e.units.empty() ? nullptr : e.units.c_str(),
                                kSum);
            }
        }
        h5::write_file(f, final_path, "the checkpoint");
    }
}

Checkpoint read_checkpoint(const fs::path& dir_or_file) {
    std::error_code ec;
    const fs::path path =
        fs::is_directory(dir_or_file, ec) ? checkpoint_path(dir_or_file) : dir_or_file;
    h5::File f = h5::open_file(path);
    Checkpoint c;
    const std::string format = h5::read_attr_string(f, "format");
    if (format != "sphjet-checkpoint") {
        throw InputError(path.string() + ": attribute format", "not a checkpoint",
                         "sphjet-checkpoint", format);
    }
    const std::int64_t version = h5::read_attr_int64(f, "format_version");
    if (version != kFormatVersion) {
        throw InputError(path.string() + ": attribute format_version",
                         "unsupported checkpoint version", std::to_string(kFormatVersion),
                         std::to_string(version));
    }
    c.code_version = h5::read_attr_string(f, "code_version");
    if (h5::has_attr(f, "output_clock")) {
        const std::string clock = h5::read_attr_string(f, "output_clock");
        if (clock != "legacy" && clock != "time")
            throw InputError(path.string() + ": attribute output_clock", "unknown output clock",
                             "\"time\" or \"legacy\"", clock);
        c.legacy_clock = clock == "legacy";
    }
    {
        h5::Group g = h5::open_group(f, "particles");
        ParticleSet& ps = c.particles;
        const auto n = static_cast<std::size_t>(h5::read_attr_int64(g, "n"));
        const auto n_wall = static_cast<std::size_t>(h5::read_attr_int64(g, "n_wall"));
        ps.nb = static_cast<std::size_t>(h5::read_attr_int64(g, "nb"));
        ps.nbf = static_cast<std::size_t>(h5::read_attr_int64(g, "nbf"));
        particle_group::read(g, ps, n);
        const auto prev = h5::read_int32(g, "wall_prev", n_wall);
        const auto next = h5::read_int32(g, "wall_next", n_wall);
        ps.wall.resize(n_wall);
        for (std::size_t i = 0; i < n_wall; ++i) ps.wall[i] = {prev[i], next[i]};
        if (ps.nbf > ps.nb || ps.nb > n) {
            throw InputError(h5::where(g), "inconsistent particle counts", "nbf <= nb <= n",
                             fmt::format("nbf = {}, nb = {}, n = {}", ps.nbf, ps.nb, n));
        }
    }
    {
        h5::Group g = h5::open_group(f, "run_state");
        visit_state(c.state, [&g](const char* name, auto& v, bool later) {
            using T = std::decay_t<decltype(v)>;
            if (later && !h5::has_attr(g, name)) return;
            if constexpr (std::is_same_v<T, double>) {
                v = h5::read_attr_double(g, name);
            } else {
                v = h5::read_attr_int64(g, name);
            }
        });
    }
    {
        h5::Group g = h5::open_group(f, "parameters");
        c.params = h5::read_params(g);
    }
    {
        h5::Group g = h5::open_group(f, "extra");
        for (const std::string& name : h5::link_names(g)) {
            c.extra.push_back({name, h5::read_doubles(g, name)});
        }
    }
    return c;
}

}  // namespace sphjet
