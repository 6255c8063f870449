#include "fuzz_harness.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>

#include "config/indat.hpp"
#include "config/legacy_case.hpp"
#include "config/modern_case.hpp"
#include "geometry/generator.hpp"
#include "model/errors.hpp"

namespace sphjet::fuzz {
namespace {

namespace fs = std::filesystem;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Lattice points of a w x h rectangle at spacing dx, dz (both lattices, with the margin the
// generator's loops take).
double points(double w, double h, double dx, double dz) {
    const double n = (std::abs(w) / dx + 4) * (std::abs(h) / dz + 4) * 2;
    return std::isfinite(n) ? n : kInf;
}

void require(bool ok, const std::string& what) {
    if (!ok) throw HarnessViolation(what);
}

void require_finite(double v, const char* name) {
    require(std::isfinite(v), std::string("accepted, but ") + name + " = " + std::to_string(v) +
                                  " is not finite");
}

// What the solver and the writers assume of the parameters of any accepted case.
void check_params(const SimParams& p) {
    const std::pair<const char*, double> reals[] = {
        {"visc_value", p.visc_value}, {"wall_viscosity", p.wall_viscosity}, {"xsph_eps", p.xsph_eps},
        {"rho0", p.rho0}, {"gamma", p.gamma}, {"h_swl", p.h_swl}, {"coef", p.coef}, {"B", p.B},
        {"lx", p.lx}, {"lz", p.lz}, {"dx", p.dx}, {"dz", p.dz}, {"h", p.h}, {"dt", p.dt},
        {"cfl", p.cfl}, {"tmax", p.tmax}, {"out", p.out}, {"trec_ini", p.trec_ini},
        {"gx", p.gx}, {"gz", p.gz}, {"sigma", p.sigma}};
    for (const auto& [name, v] : reals) require_finite(v, name);
    for (const auto& [name, v] : {std::pair{"dx", p.dx}, {"dz", p.dz}, {"lx", p.lx}, {"lz", p.lz},
                                  {"h", p.h}, {"dt", p.dt}, {"rho0", p.rho0}})
        require(v > 0, std::string("accepted, but ") + name + " = " + std::to_string(v) + " is not > 0");
    require(p.filter_period >= 1, "accepted, but filter_period = " + std::to_string(p.filter_period) + " < 1");
    require(p.dbc_period >= 1, "accepted, but dbc_period = " + std::to_string(p.dbc_period) + " < 1");
}

void check_spec(const CaseSpec& s) {
    check_params(s.params);
    for (const auto& o : s.obstacles) {
        require(o.density >= 1, "accepted, but obstacle density = " + std::to_string(o.density) + " < 1");
        for (double v : {o.r.xmin, o.r.xmax, o.r.zmin, o.r.zmax, o.beta_deg}) require_finite(v, "obstacle");
    }
    for (const auto& b : s.fluid_blocks)
        for (double v : {b.r.xmin, b.r.xmax, b.r.zmin, b.r.zmax, b.u0, b.w0}) require_finite(v, "fluid block");
    for (const auto& w : s.walls)
        for (double v : {w.x, w.height}) require_finite(v, "wall");
}

// What the core assumes of the initial particles.
void check_state(const InitialState& st) {
    check_params(st.params);
    const ParticleSet& ps = st.particles;
    require(ps.nb <= ps.size() && ps.nbf <= ps.nb, "particle counts out of order");
    for (const auto* v : {&ps.z, &ps.u, &ps.w, &ps.rho, &ps.p, &ps.m})
        require(v->size() == ps.size(), "particle arrays of different sizes");
    for (std::size_t i = 0; i < ps.size(); ++i) {
        bool finite = true;
        for (double v : {ps.x[i], ps.z[i], ps.u[i], ps.w[i], ps.rho[i], ps.p[i], ps.m[i]}) finite = finite && std::isfinite(v);
        if (!finite)  // the message only when it fails: this loop runs for every particle
            throw HarnessViolation("accepted, but particle " + std::to_string(i) + " is not finite: x z u w rho p m = " +
                                   std::to_string(ps.x[i]) + " " + std::to_string(ps.z[i]) + " " +
                                   std::to_string(ps.u[i]) + " " + std::to_string(ps.w[i]) + " " +
                                   std::to_string(ps.rho[i]) + " " + std::to_string(ps.p[i]) + " " +
                                   std::to_string(ps.m[i]));
    }
    if (!ps.wall.empty()) {
        require(ps.wall.size() == ps.nb, "wall links not one per boundary particle");
        for (const WallLink& w : ps.wall)
            require(w.prev >= 0 && w.next >= 0 && static_cast<std::size_t>(w.prev) < ps.nb &&
                        static_cast<std::size_t>(w.next) < ps.nb,
                    "wall link outside the boundary particles");
    }
}

Outcome generate_capped(const CaseSpec& spec, double cap) {
    check_spec(spec);
    if (!(estimate_particles(spec) <= cap)) return Outcome::Accepted;
    try {
        check_state(generate(spec));
    } catch (const InputError&) {
        return Outcome::Rejected;  // the generator refusing what the reader let through is fine
    }
    return Outcome::Generated;
}

void write_file(const fs::path& path, std::string_view content) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    if (!out) throw std::runtime_error("harness: cannot write " + path.string());
}

// The part of data before the marker line, and what follows it (npos when absent).
std::size_t find_marker(std::string_view data, std::string_view marker, std::size_t from) {
    for (std::size_t pos = data.find(marker, from); pos != std::string_view::npos;
         pos = data.find(marker, pos + 1)) {
        const bool line_start = pos == 0 || data[pos - 1] == '\n';
        const std::size_t end = pos + marker.size();
        const bool line_end = end == data.size() || data[end] == '\n';
        if (line_start && line_end) return pos;
    }
    return std::string_view::npos;
}

}  // namespace

double estimate_particles(const CaseSpec& s) {
    const SimParams& p = s.params;
    if (!(p.dx > 0 && p.dz > 0 && p.lx > 0 && p.lz > 0)) return 0;  // generate refuses it
    const double nx = p.lx / p.dx + 4, nz = p.lz / p.dz + 4;
    double n = 4 * (nx + nz);  // box walls: two layers, four sides at most
    for (const auto& b : s.fluid_blocks) n += points(b.r.xmax - b.r.xmin, b.r.zmax, p.dx, p.dz);
    for (const auto& q : s.fluid_squares) n += points(q.side, q.side, p.dx, p.dz);
    for (const auto& d : s.fluid_discs) {
        const double a = 2 * d.radius * (1 + std::abs(d.elongation)) + 2 * p.dx;
        n += points(a, a, std::min(p.dx, p.dz), std::min(p.dx, p.dz));
    }
    for (const auto& c : s.fluid_cylinders)
        n += (std::abs(c.radius) / p.dx + 2) * (std::abs(c.zmax - c.zmin) / p.dz + 2);
    if (s.nozzle) {  // the plug and up to four wall lines along it
        const double d = std::min(p.dx, p.dz);
        n += points(s.nozzle->d0, s.nozzle->length(), d, d) + 4 * (std::abs(s.nozzle->length()) / d + 4);
    }
    for (const auto& g : s.gates) n += std::abs(g.zmax - g.zmin) / p.dz + 4;
    for (const auto& w : s.walls) n += 2 * (std::abs(w.height) / p.dz + 4);
    for (const auto& o : s.obstacles) {
        const double k = std::max(1, o.density);
        n += points(o.r.xmax - o.r.xmin, std::max(o.r.zmax, o.r.zmax - o.r.zmin), p.dx / k, p.dz / k);
    }
    return std::isfinite(n) ? n : kInf;
}

Outcome run_legacy(std::string_view data, double generate_cap) {
    CaseSpec spec;
    try {
        spec = parse_legacy_case(std::string(data), "fuzz_case.txt");
    } catch (const InputError&) {
        return Outcome::Rejected;
    }
    return generate_capped(spec, generate_cap);
}

Outcome run_indat(std::string_view data, const fs::path& dir) {
    fs::create_directories(dir);
    // Each marker searched after the previous one found; a section runs to the next marker found.
    const std::string_view markers[3] = {kIpartMarker, kNormalsMarker, kGateMarker};
    const char* files[3] = {"IPART", "NORMALS.init", "gate"};
    std::size_t at[3];
    std::size_t from = 0;
    for (int k = 0; k < 3; ++k) {
        at[k] = find_marker(data, markers[k], from);
        if (at[k] != std::string_view::npos) from = at[k];
    }
    const auto next_after = [&](int k) {
        for (int j = k + 1; j < 3; ++j)
            if (at[j] != std::string_view::npos) return at[j];
        return std::string_view::npos;
    };
    write_file(dir / "INDAT", data.substr(0, std::min({at[0], at[1], at[2]})));
    std::error_code ec;
    for (int k = 0; k < 3; ++k) {
        if (at[k] == std::string_view::npos) {
            fs::remove(dir / files[k], ec);
            continue;
        }
        const std::size_t b = std::min(data.size(), at[k] + markers[k].size() + 1);
        const std::size_t e = next_after(k);
        write_file(dir / files[k], data.substr(b, e == std::string_view::npos ? std::string_view::npos : e - b));
    }
    InitialState st;
    try {
        st = read_indat(dir / "INDAT");
    } catch (const InputError&) {
        return Outcome::Rejected;
    }
    check_state(st);
    return Outcome::Generated;
}

void split_modern(std::string_view data, std::string& toml, std::vector<std::string>& overrides) {
    overrides.clear();
    const std::size_t m = find_marker(data, kOverridesMarker, 0);
    toml.assign(data.substr(0, m));
    if (m == std::string_view::npos) return;
    std::string_view rest = data.substr(std::min(data.size(), m + kOverridesMarker.size() + 1));
    while (!rest.empty()) {
        const std::size_t nl = rest.find('\n');
        std::string o(rest.substr(0, nl));
        for (auto p = o.find("\\n"); p != std::string::npos; p = o.find("\\n", p + 1)) o.replace(p, 2, "\n");
        overrides.push_back(std::move(o));
        if (nl == std::string_view::npos) break;
        rest.remove_prefix(nl + 1);
    }
}

Outcome run_modern(std::string_view data, double generate_cap) {
    std::string toml;
    std::vector<std::string> overrides;
    split_modern(data, toml, overrides);
    CaseSpec spec;
    try {
        spec = parse_modern_case(toml, "fuzz_case.toml", overrides);
    } catch (const InputError&) {
        return Outcome::Rejected;
    }
    return generate_capped(spec, generate_cap);
}

void report_finding(const char* parser, const char* type, const char* what) {
    std::fprintf(stderr, "sphjet-fuzz FINDING (%s): %s: %s\n", parser, type, what);
    std::fflush(stderr);
    std::abort();
}

}  // namespace sphjet::fuzz
