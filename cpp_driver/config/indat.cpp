#include "config/indat.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/file_write.hpp"
#include "model/errors.hpp"

namespace sphjet {
namespace {

namespace fs = std::filesystem;

// s right-justified in w columns, after `lead` blanks.
std::string rjust(const std::string& s, std::size_t w, std::size_t lead = 0) {
    std::string out(lead + (s.size() >= w ? 0 : w - s.size()), ' ');
    out += s;
    return out;
}

// gfortran list-directed output of a default INTEGER: a blank, then I11.
std::string list_int(long v) { return rjust(std::to_string(v), 11, 1); }

// gfortran list-directed output of a default REAL: a blank, then G16.9 with the exponent
// field blanked for fixed-point values (0.1 <= |v| < 1e9 and zero), 1P E form otherwise.
std::string list_real(double value) {
    const float v = static_cast<float>(value);
    char buf[64];
    std::string out;
    if (v == 0.0f) {
        out = rjust(std::signbit(v) ? "-0.00000000" : "0.00000000", 12, 1);
        out.append(4, ' ');
        return out;
    }
    std::snprintf(buf, sizeof buf, "%.8e", static_cast<double>(v));
    const int ex = std::atoi(std::strchr(buf, 'e') + 1);
    if (ex >= -1 && ex <= 8) {
        std::snprintf(buf, sizeof buf, "%.*f", 8 - ex, static_cast<double>(v));
        out = rjust(buf, 12, 1);
        out.append(4, ' ');
        return out;
    }
    std::snprintf(buf, sizeof buf, "%.8E", static_cast<double>(v));
    return rjust(buf, 16, 1);
}

// Fortran ES13.7.
std::string es13_7(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.7E", v);
    return rjust(buf, 13);
}

// Fortran E16.8: [-]0.dddddddd E+xx, right-justified in 16 columns.
std::string e16_8(double v) {
    const bool neg = std::signbit(v);
    std::string digits = "00000000";
    int ex = 0;
    if (v != 0.0) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.7e", std::fabs(v));  // d.ddddddde+xx
        digits = std::string(1, buf[0]) + std::string(buf + 2, 7);
        ex = std::atoi(std::strchr(buf, 'e') + 1) + 1;
    }
    char e[16];
    if (std::abs(ex) <= 99)
        std::snprintf(e, sizeof e, "E%c%02d", ex < 0 ? '-' : '+', std::abs(ex));
    else
        std::snprintf(e, sizeof e, "%c%03d", ex < 0 ? '-' : '+', std::abs(ex));
    return rjust(std::string(neg ? "-" : "") + "0." + digits + e, 16);
}

// Through a temporary file (io/file_write.hpp); ".tmp-sphjet", not ".tmp": sphjet gen writes
// into directories of the user's, where an INDAT.tmp may be someone else's.
void write_atomically(const fs::path& path, const std::string& content) {
    write_file_atomically(path, content, "the legacy input file", ".tmp-sphjet");
}

// Lines of a text file; a missing file is an InputError naming it and what needs it.
std::vector<std::string> read_lines(const fs::path& path, const std::string& needed_by) {
    std::ifstream in(path, std::ios::binary);
    if (!in || fs::is_directory(path))
        throw InputError(path.string(), "cannot open the file" + needed_by, "a readable file",
                         fs::exists(path) ? "a file that cannot be read" : "no such file");
    std::vector<std::string> lines;
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    return lines;
}

std::vector<std::string> tokens(const std::string& line) {
    std::istringstream s(line);
    std::vector<std::string> out;
    std::string t;
    while (s >> t) out.push_back(t);
    return out;
}

double parse_real(const std::string& text, const std::string& where, const std::string& what) {
    std::string s = text;
    for (char& c : s)
        if (c == 'd' || c == 'D') c = 'e';
    char* end = nullptr;
    errno = 0;
    const double v = s.empty() ? 0.0 : std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v))
        throw InputError(where, what + " is not a number", "a real number", "'" + text + "'");
    return v;
}

// A Fortran default INTEGER (32 bits), as legacy writes and reads every integer of these
// files; a longer one would wrap (or, through a double, be undefined) when stored as int.
long parse_int(const std::string& text, const std::string& where, const std::string& what) {
    char* end = nullptr;
    errno = 0;
    const long v = text.empty() ? 0 : std::strtol(text.c_str(), &end, 10);
    if (text.empty() || end != text.c_str() + text.size())
        throw InputError(where, what + " is not an integer", "an integer", "'" + text + "'");
    if (errno == ERANGE || v < INT32_MIN || v > INT32_MAX)
        throw InputError(where, what + " is out of range", "an integer from -2147483648 to 2147483647",
                         "'" + text + "'");
    return v;
}

// The 47 INDAT entries, in order: name and whether it is an integer.
struct Entry {
    const char* name;
    bool integer;
};
constexpr Entry kIndat[47] = {
    {"kernel", true}, {"time-stepping algorithm", true}, {"density filter", true},
    {"viscosity treatment", true}, {"boundary conditions", true}, {"periodicity X", true},
    {"periodicity Y", true}, {"periodicity Z", true}, {"lattice", true},
    {"equation of state", true}, {"h_SWL", false}, {"B", false}, {"gamma", false},
    {"coef", false}, {"XSPH eps", false}, {"rho0", false}, {"viscosity value", false},
    {"wall viscosity", false}, {"vlx", false}, {"vly", false}, {"vlz", false}, {"dx", false},
    {"dy", false}, {"dz", false}, {"h", false}, {"np", true}, {"nb", true}, {"nbf", true},
    {"i_var_dt", true}, {"dt", false}, {"tmax", false}, {"out", false}, {"trec_ini", false},
    {"detail output interval", false}, {"detail output start", false},
    {"detail output end", false}, {"restart flag", true}, {"CFL", false}, {"TE0", false},
    {"kernel correction", true}, {"Riemann solver", true}, {"TVD flag", true},
    {"beta_lim", false}, {"vorticity flag", true}, {"Verlet period", true},
    {"filter period", true}, {"boundary-density period", true}};

// IPART beside INDAT: np particle lines, the first nbf fixed and up to nb moving boundary.
void read_ipart(const fs::path& indat, const std::string& file, long np, long nb, long nbf, ParticleSet& ps) {
    const fs::path ipart = indat.parent_path() / "IPART";
    const auto pl = read_lines(ipart, " (IPART, needed beside " + file + ")");
    ps.x.reserve(std::min(static_cast<std::size_t>(np), pl.size()));  // np is checked below
    for (long k = 0; k < np; ++k) {
        const std::string where = ipart.string() + ":" + std::to_string(k + 1);
        if (static_cast<std::size_t>(k) >= pl.size())
            throw InputError(where, "IPART ends early", std::to_string(np) + " particle lines (np in INDAT)",
                             std::to_string(pl.size()) + " lines");
        const auto t = tokens(pl[static_cast<std::size_t>(k)]);
        if (t.size() != 7)
            throw InputError(where, "malformed IPART line", "7 values: x z u w rho p m",
                             std::to_string(t.size()) + " values");
        double f[7];
        static const char* names[7] = {"x", "z", "u", "w", "rho", "p", "m"};
        for (int c = 0; c < 7; ++c) f[c] = parse_real(t[static_cast<std::size_t>(c)], where, names[c]);
        const ParticleKind kind = k < nbf ? ParticleKind::FixedBoundary
                                  : k < nb ? ParticleKind::MovingBoundary
                                           : ParticleKind::Fluid;
        ps.push(f[0], f[1], f[2], f[3], f[4], f[5], f[6], kind);
    }
    for (std::size_t k = static_cast<std::size_t>(np); k < pl.size(); ++k)
        if (!tokens(pl[k]).empty())
            throw InputError(ipart.string() + ":" + std::to_string(k + 1), "IPART has more particles than INDAT says",
                             "np = " + std::to_string(np) + " lines", "more");
    ps.nb = static_cast<std::size_t>(nb);
    ps.nbf = static_cast<std::size_t>(nbf);
}

// The gate record beside INDAT (moving boundary particles nbf+1..nb): the legacy generator's.
void read_gate_record(const fs::path& indat, const std::string& file, long nb, long nbf, const ParticleSet& ps,
                      SimParams& p) {
    if (nbf < nb) {
        const fs::path gate = indat.parent_path() / "gate";
        const std::string needed = " (gate, needed beside " + file + " when nbf = " + std::to_string(nbf) +
                                   " < nb = " + std::to_string(nb) + ": the moving boundary particles of a gate)";
        const auto gl = read_lines(gate, needed);
        std::vector<std::vector<std::string>> rec;
        for (const auto& l : gl)
            if (auto t = tokens(l); !t.empty()) rec.push_back(t);
        const auto g_at = [&](std::size_t r) { return gate.string() + ": record " + std::to_string(r + 1); };
        const std::size_t sizes[5] = {1, 1, 1, 2, 1};
        for (std::size_t r = 0; r < 5; ++r)
            if (r >= rec.size() || rec[r].size() < sizes[r])
                throw InputError(g_at(r), "malformed gate file", "5 records: 1, ngate_ini, ngate_end, \"Vx Vz\", tgate",
                                 r >= rec.size() ? "end of file" : std::to_string(rec[r].size()) + " value(s)");
        const long opt = parse_int(rec[0][0], g_at(0), "iopt_gate");
        const long g0 = parse_int(rec[1][0], g_at(1), "ngate_ini");
        const long g1 = parse_int(rec[2][0], g_at(2), "ngate_end");
        if (opt != 1 || g0 != nbf + 1 || g1 != nb)
            throw InputError(gate.string(), "unsupported moving boundary particles (only one gate, the particles "
                                            "nbf+1..nb, is implemented)",
                             "1, " + std::to_string(nbf + 1) + ", " + std::to_string(nb),
                             std::to_string(opt) + ", " + std::to_string(g0) + ", " + std::to_string(g1));
        p.gate_vx = parse_real(rec[3][0], g_at(3), "VXgate");
        p.gate_vz = parse_real(rec[3][1], g_at(3), "VZgate");
        p.gate_t_start = parse_real(rec[4][0], g_at(4), "tgate");
        if (!(std::isfinite(p.gate_vx) && std::isfinite(p.gate_vz) && p.gate_t_start >= 0))
            throw InputError(gate.string(), "invalid gate motion", "finite Vx, Vz and tgate >= 0",
                             rec[3][0] + ", " + rec[3][1] + ", " + rec[4][0]);
        p.gate_z_cap = gate_z_cap(ps, p.h);
    }
}

// NORMALS.init beside INDAT (repulsive boundaries): the wall links.
void read_normals(const fs::path& indat, long nb, const SimParams& p, ParticleSet& ps) {
    if (p.boundary == BoundaryType::Repulsive) {
        const fs::path normals = indat.parent_path() / "NORMALS.init";
        const auto nl = read_lines(normals, " (NORMALS.init, needed for repulsive boundaries)");
        ps.wall.resize(static_cast<std::size_t>(nb));
        for (long k = 0; k < nb; ++k) {
            const std::string where = normals.string() + ":" + std::to_string(k + 1);
            if (static_cast<std::size_t>(k) >= nl.size())
                throw InputError(where, "NORMALS.init ends early", std::to_string(nb) + " lines (nb in INDAT)",
                                 std::to_string(nl.size()) + " lines");
            const auto t = tokens(nl[static_cast<std::size_t>(k)]);
            if (t.size() != 8)
                throw InputError(where, "malformed NORMALS.init line", "8 values: nx nz i rank prev next x z",
                                 std::to_string(t.size()) + " values");
            const long idx = parse_int(t[2], where, "particle index");
            const long prev = parse_int(t[4], where, "previous neighbour");
            const long nxt = parse_int(t[5], where, "next neighbour");
            if (idx != k + 1)
                throw InputError(where, "NORMALS.init out of order", "particle index " + std::to_string(k + 1),
                                 std::to_string(idx));
            if (prev < 1 || prev > nb || nxt < 1 || nxt > nb)
                throw InputError(where, "wall neighbour outside the boundary particles",
                                 "indices in 1.." + std::to_string(nb),
                                 std::to_string(prev) + ", " + std::to_string(nxt));
            ps.wall[static_cast<std::size_t>(k)] = {static_cast<int>(prev - 1), static_cast<int>(nxt - 1)};
        }
    }
}

}  // namespace

void write_indat(const fs::path& path, const SimParams& p, std::size_t np, std::size_t nb,
                 std::size_t nbf, const LegacyRunInfo& info) {
    const bool repulsive = p.boundary == BoundaryType::Repulsive;
    const bool filter = p.density_filter != DensityFilter::None;
    std::string s;
    const auto i = [&](long v) { s += list_int(v) + "\n"; };
    const auto r = [&](double v) { s += list_real(v) + "\n"; };
    i(static_cast<int>(p.kernel));
    i(static_cast<int>(p.integrator));
    i(static_cast<int>(p.density_filter));
    i(static_cast<int>(p.viscosity));
    i(static_cast<int>(p.boundary));
    i(0), i(0), i(0);  // periodicity
    i(static_cast<int>(p.lattice));
    i(1);  // Tait
    r(p.h_swl), r(p.B), r(p.gamma), r(p.coef), r(p.xsph_eps), r(p.rho0), r(p.visc_value);
    r(repulsive ? p.wall_viscosity : 0.0);
    r(p.lx), r(0.0), r(p.lz);
    s += es13_7(p.dx) + "\n" + es13_7(0.0) + "\n" + es13_7(p.dz) + "\n";
    r(p.h);
    i(static_cast<long>(np)), i(static_cast<long>(nb)), i(static_cast<long>(nbf));
    i(p.variable_dt ? 1 : 0);
    r(p.dt), r(p.tmax), r(p.out), r(p.trec_ini);
    r(info.detail_out), r(info.detail_start), r(info.detail_end);
    i(info.restart);
    r(p.cfl);
    r(0.0);  // TE0 (ideal gas only)
    i(0), i(0), i(0);  // kernel correction, Riemann solver, TVD
    r(0.0);            // beta_lim
    i(info.vorticity);
    i(0);  // Verlet period
    i(filter ? p.filter_period : 0);
    i(repulsive ? 0 : p.dbc_period);
    write_atomically(path, s);
}

void write_ipart(const fs::path& path, const ParticleSet& ps) {
    std::string s;
    s.reserve(ps.size() * 113);
    for (std::size_t k = 0; k < ps.size(); ++k) {
        for (double v : {ps.x[k], ps.z[k], ps.u[k], ps.w[k], ps.rho[k], ps.p[k], ps.m[k]}) s += e16_8(v);
        s += '\n';
    }
    write_atomically(path, s);
}

void write_normals(const fs::path& path, const ParticleSet& ps) {
    if (ps.wall.size() != ps.nb)
        throw InputError(path.string(), "no wall links for the boundary particles",
                         std::to_string(ps.nb) + " links (repulsive boundaries)", std::to_string(ps.wall.size()));
    std::string s;
    char buf[16];
    for (std::size_t k = 0; k < ps.nb; ++k) {
        const int prev = ps.wall[k].prev, next = ps.wall[k].next;
        if (prev < 0 || next < 0 || static_cast<std::size_t>(prev) >= ps.nb ||
            static_cast<std::size_t>(next) >= ps.nb)
            throw InputError(path.string(), "wall link of boundary particle " + std::to_string(k + 1) +
                                                " outside the boundary particles",
                             "neighbours in 1.." + std::to_string(ps.nb),
                             std::to_string(prev + 1) + ", " + std::to_string(next + 1));
        // The legacy normal: from the neighbours (a missing one mirrored through the
        // particle), in single precision, perpendicular to the wall direction.
        const double xi = ps.x[k], zi = ps.z[k];
        float xprev, zprev, xnext, znext;
        if (static_cast<std::size_t>(prev) == k) {
            xprev = static_cast<float>(xi - (ps.x[next] - xi));
            zprev = static_cast<float>(zi - (ps.z[next] - zi));
            xnext = static_cast<float>(ps.x[next]);
            znext = static_cast<float>(ps.z[next]);
        } else if (static_cast<std::size_t>(next) == k) {
            xprev = static_cast<float>(ps.x[prev]);
            zprev = static_cast<float>(ps.z[prev]);
            xnext = static_cast<float>(xi + (xi - ps.x[prev]));
            znext = static_cast<float>(zi + (zi - ps.z[prev]));
        } else {
            xprev = static_cast<float>(ps.x[prev]);
            zprev = static_cast<float>(ps.z[prev]);
            xnext = static_cast<float>(ps.x[next]);
            znext = static_cast<float>(ps.z[next]);
        }
        const float xf = static_cast<float>(xi), zf = static_cast<float>(zi);
        const float dxn = (xnext - xf) + (xf - xprev);
        const float dzn = (znext - zf) + (zf - zprev);
        const float len = std::sqrt(dxn * dxn + dzn * dzn);
        const float nx = len > 0 ? -dzn / len : 0.0f, nz = len > 0 ? dxn / len : 0.0f;
        s += e16_8(nx) + " " + e16_8(nz) + " ";
        for (long v : {static_cast<long>(k + 1), 0L, static_cast<long>(prev + 1), static_cast<long>(next + 1)}) {
            std::snprintf(buf, sizeof buf, "%6ld ", v);
            s += buf;
        }
        s += e16_8(xf) + " " + e16_8(zf) + " \n";
    }
    write_atomically(path, s);
}

void write_legacy_inputs(const fs::path& dir, const SimParams& params, const ParticleSet& ps,
                         const LegacyRunInfo& info) {
    std::error_code ec;
    write_ipart(dir / "IPART", ps);
    if (params.boundary == BoundaryType::Repulsive) {
        write_normals(dir / "NORMALS.init", ps);
    } else {
        fs::remove(dir / "NORMALS.init", ec);  // a stale one from an earlier repulsive case
    }
    write_indat(dir / "INDAT", params, ps.size(), ps.nb, ps.nbf, info);
    if (ps.nbf < ps.nb) {  // the gate record, as SPHYSICSgen2D writes it (1-based particles)
        write_atomically(dir / "gate", fmt::format("1\n{}\n{}\n{:.17g} {:.17g}\n{:.17g}\n", ps.nbf + 1, ps.nb,
                                                   params.gate_vx, params.gate_vz, params.gate_t_start));
    } else {
        fs::remove(dir / "gate", ec);  // a stale one from an earlier case with a gate
    }
}

InitialState read_indat(const fs::path& indat) {
    const std::string file = indat.string();
    const auto lines = read_lines(indat, "");
    std::vector<double> v(47);
    std::size_t next = 0;
    for (std::size_t e = 0; e < 47; ++e) {
        while (next < lines.size() && tokens(lines[next]).empty()) ++next;
        if (next >= lines.size())
            throw InputError(file + ":" + std::to_string(lines.size() + 1),
                             "INDAT ends before entry " + std::to_string(e + 1) + " (" + kIndat[e].name + ")",
                             "47 entries", std::to_string(e));
        const std::string where = file + ":" + std::to_string(next + 1);
        const std::string t = tokens(lines[next])[0];
        v[e] = kIndat[e].integer ? static_cast<double>(parse_int(t, where, kIndat[e].name))
                                 : parse_real(t, where, kIndat[e].name);
        ++next;
    }
    // Line of entry e (1-based) for messages: entries sit one per line from the top.
    const auto at = [&](int e) { return file + ":" + std::to_string(e); };
    const auto get = [&](int e) { return v[static_cast<std::size_t>(e - 1)]; };
    const auto refuse = [&](int e, const std::string& supported) {
        throw InputError(at(e), std::string("unsupported ") + kIndat[e - 1].name + " (sphjet does not implement it)",
                         supported, std::to_string(static_cast<long>(get(e))));
    };
    const auto one_of = [&](int e, std::initializer_list<int> ok, const std::string& supported) {
        for (int o : ok)
            if (get(e) == o) return static_cast<int>(get(e));
        refuse(e, supported);
        return -1;  // not reached: refuse throws
    };
    const auto positive = [&](int e) {
        if (!(get(e) > 0))
            throw InputError(at(e), std::string("invalid ") + kIndat[e - 1].name, "a value > 0",
                             std::to_string(get(e)));
        return get(e);
    };

    InitialState st;
    SimParams& p = st.params;
    p.kernel = static_cast<KernelType>(one_of(1, {1, 2, 3, 5}, "1, 2, 3 or 5"));
    one_of(2, {1}, "1 (predictor-corrector)");
    p.density_filter = static_cast<DensityFilter>(one_of(3, {0, 1, 2}, "0, 1 or 2"));
    p.viscosity = static_cast<ViscosityModel>(one_of(4, {1, 2}, "1 (artificial) or 2 (laminar)"));
    p.boundary = static_cast<BoundaryType>(one_of(5, {1, 2}, "1 (repulsive) or 2 (dynamic)"));
    for (int e = 6; e <= 8; ++e) one_of(e, {0}, "0 (no periodicity)");
    p.lattice = static_cast<Lattice>(one_of(9, {1, 2}, "1 (SC) or 2 (BCC)"));
    one_of(10, {1}, "1 (Tait)");
    p.h_swl = get(11);
    p.B = positive(12);
    p.gamma = positive(13);
    p.coef = get(14);
    p.xsph_eps = get(15);
    p.rho0 = positive(16);
    p.visc_value = get(17);
    p.wall_viscosity = get(18);
    p.lx = positive(19);
    p.lz = positive(21);
    p.dx = positive(22);
    p.dz = positive(24);
    p.h = positive(25);
    const long np = static_cast<long>(get(26)), nb = static_cast<long>(get(27)), nbf = static_cast<long>(get(28));
    if (np < 1 || nb < 0 || nb > np)
        throw InputError(at(27), "invalid particle counts", "0 <= nb <= np and np >= 1",
                         "np = " + std::to_string(np) + ", nb = " + std::to_string(nb));
    if (nbf < 0 || nbf > nb)
        throw InputError(at(28), "invalid particle counts", "0 <= nbf <= nb = " + std::to_string(nb),
                         "nbf = " + std::to_string(nbf));
    p.variable_dt = one_of(29, {0, 1}, "0 or 1") == 1;
    p.dt = positive(30);
    p.tmax = positive(31);
    p.out = positive(32);
    p.trec_ini = get(33);
    st.legacy.detail_out = get(34);
    st.legacy.detail_start = get(35);
    st.legacy.detail_end = get(36);
    st.legacy.restart = one_of(37, {0}, "0 (new run)");
    p.cfl = positive(38);
    one_of(40, {0}, "0 (no kernel correction)");
    one_of(41, {0}, "0 (no Riemann solver)");
    st.legacy.vorticity = one_of(44, {0, 1}, "0 or 1");
    one_of(45, {0}, "0 (no Verlet)");
    if (p.density_filter != DensityFilter::None) {
        if (get(46) < 1)
            throw InputError(at(46), "invalid filter period", "an integer >= 1 with a density filter",
                             std::to_string(static_cast<long>(get(46))));
        p.filter_period = static_cast<int>(get(46));
    }
    if (p.boundary == BoundaryType::Dynamic) p.dbc_period = std::max(1, static_cast<int>(get(47)));
    st.legacy.h_coefficient = p.h / std::sqrt(p.dx * p.dx + p.dz * p.dz);
    p.gx = 0.0;
    p.gz = -9.81;

    read_ipart(indat, file, np, nb, nbf, st.particles);
    read_gate_record(indat, file, nb, nbf, st.particles, p);
    read_normals(indat, nb, p, st.particles);
    return st;
}

}  // namespace sphjet
