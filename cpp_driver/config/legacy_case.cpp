#include "config/legacy_case.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string_view>
#include <vector>

#include "model/errors.hpp"

namespace sphjet {
namespace {

// One answer of the case file: the values it needs, as text, and where it was.
struct Answer {
    std::vector<std::string> values;
    std::size_t line = 0;
};

// Splits a line the way a Fortran list-directed read does: values separated by commas
// and/or blanks. A value ends at the first separator; what follows the values an answer
// needs is a comment and is not split further by the caller.
std::vector<std::string> split_values(std::string_view line) {
    std::vector<std::string> out;
    std::size_t i = 0;
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    while (i < line.size()) {
        while (i < line.size() && blank(line[i])) ++i;
        if (i >= line.size()) break;
        if (line[i] == ',') {  // a comma right after a separator: an empty (null) value
            out.emplace_back();
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < line.size() && !blank(line[j]) && line[j] != ',') ++j;
        out.emplace_back(line.substr(i, j - i));
        i = j;
        while (i < line.size() && blank(line[i])) ++i;
        if (i < line.size() && line[i] == ',') ++i;  // the comma closing this value
    }
    return out;
}

std::string in_quotes(std::string_view s) { return "'" + std::string(s) + "'"; }

std::string join(std::initializer_list<std::string_view> names) {
    std::string s;
    for (auto n : names) s += (s.empty() ? "" : ", ") + std::string(n);
    return s;
}

// Walks the answers of a case file in order.
class Answers {
public:
    Answers(const std::string& text, std::string source) : source_(std::move(source)) {
        std::istringstream in(text);
        std::string line;
        while (std::getline(in, line)) lines_.push_back(line);
    }

    [[nodiscard]] std::string where() const { return where(line_); }
    [[nodiscard]] std::string where(std::size_t line) const {
        return source_ + ":" + std::to_string(line);
    }
    [[nodiscard]] const std::string& source() const { return source_; }
    [[nodiscard]] std::size_t line() const { return line_; }

    // The next non-blank line, holding at least names.size() values.
    Answer next(std::string_view what, std::initializer_list<std::string_view> names) {
        while (next_ < lines_.size() && split_values(lines_[next_]).empty()) ++next_;
        if (next_ >= lines_.size())
            throw InputError(where(lines_.size() + 1), "the case file ends before the " +
                                                           std::string(what) + " line",
                             std::to_string(names.size()) + " value(s): " + join(names),
                             "end of file");
        line_ = ++next_;  // 1-based number of the line just taken
        Answer a;
        a.line = line_;
        const auto all = split_values(lines_[line_ - 1]);
        std::size_t k = 0;
        for (auto name : names) {
            if (k >= all.size() || all[k].empty())
                throw InputError(where(), std::string(what) + ": value " +
                                              std::to_string(k + 1) + " (" + std::string(name) +
                                              ") is missing",
                                 std::to_string(names.size()) + " comma-separated values (" +
                                     join(names) + ")",
                                 in_quotes(trimmed(lines_[line_ - 1])));
            a.values.push_back(all[k++]);
        }
        return a;
    }

    long integer(std::string_view what) { return integers(what, {what})[0]; }

    std::vector<long> integers(std::string_view what, std::initializer_list<std::string_view> names) {
        const Answer a = next(what, names);
        std::vector<long> out;
        std::size_t k = 0;
        for (auto name : names) out.push_back(to_integer(a.values[k++], what, name));
        return out;
    }

    double real(std::string_view what) { return reals(what, {what})[0]; }

    std::vector<double> reals(std::string_view what, std::initializer_list<std::string_view> names) {
        const Answer a = next(what, names);
        std::vector<double> out;
        std::size_t k = 0;
        for (auto name : names) out.push_back(to_real(a.values[k++], what, name));
        return out;
    }

    // A 0/1 answer ("Add wall", "Fill a new region", ...).
    bool flag(std::string_view what) {
        const long v = integer(what);
        if (v != 0 && v != 1)
            throw InputError(where(), std::string(what) + ": not a yes/no answer", "0 (no) or 1 (yes)",
                             std::to_string(v));
        return v == 1;
    }

    [[noreturn]] void refuse(std::string_view option, long found, std::string_view found_meaning,
                             std::string_view supported) const {
        std::string f = std::to_string(found);
        if (!found_meaning.empty()) f += " (" + std::string(found_meaning) + ")";
        throw InputError(where(), "unsupported " + std::string(option) + " (sphjet does not implement it)",
                         std::string(supported), f);
    }

    [[noreturn]] void invalid(std::string_view option, const std::string& found,
                              std::string_view expected) const {
        throw InputError(where(), "invalid " + std::string(option), std::string(expected), found);
    }

private:
    static std::string label(std::string_view what, std::string_view name) {
        return what == name ? std::string(what) : std::string(what) + ": " + std::string(name);
    }

    static std::string trimmed(const std::string& s) {
        const auto b = s.find_first_not_of(" \t\r");
        if (b == std::string::npos) return {};
        return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
    }

public:
    long to_integer(const std::string& t, std::string_view what, std::string_view name) const {
        std::size_t i = (t[0] == '+' || t[0] == '-') ? 1 : 0;
        bool ok = i < t.size();
        for (; i < t.size(); ++i) ok = ok && (t[i] >= '0' && t[i] <= '9');
        if (!ok)
            throw InputError(where(), label(what, name) + " is not an integer",
                             "an integer", in_quotes(t));
        // A Fortran default INTEGER: 32 bits (a longer one would wrap when stored as int).
        errno = 0;
        const long v = std::strtol(t.c_str(), nullptr, 10);
        if (errno == ERANGE || v < INT32_MIN || v > INT32_MAX)
            throw InputError(where(), label(what, name) + " is out of range",
                             "an integer from -2147483648 to 2147483647", in_quotes(t));
        return v;
    }

    double to_real(const std::string& t, std::string_view what, std::string_view name) const {
        std::string s = t;
        for (char& c : s)
            if (c == 'd' || c == 'D') c = 'e';  // Fortran double-precision exponent
        bool ok = !s.empty() && s.find_first_not_of("+-.0123456789eE") == std::string::npos;
        char* end = nullptr;
        const double v = ok ? std::strtod(s.c_str(), &end) : 0.0;
        if (!ok || end != s.c_str() + s.size() || !std::isfinite(v))
            throw InputError(where(), label(what, name) + " is not a number",
                             "a real number", in_quotes(t));
        return v;
    }

private:
    std::string source_;
    std::vector<std::string> lines_;
    std::size_t next_ = 0;  // index of the next line to look at
    std::size_t line_ = 0;  // 1-based number of the last line taken
};

std::string num(double v) {
    std::ostringstream s;
    s.precision(10);
    s << v;
    return s.str();
}

// Single-precision value, as the legacy generator holds most of its reals.
double f32(double v) { return static_cast<double>(static_cast<float>(v)); }

// More spacings across the box than this would not fit the generator's 32-bit particle
// indices (nor any memory).
constexpr double kMaxSpacings = 1e9;
constexpr double kPi = 3.14159265358979323846;

void require_positive(const Answers& a, std::string_view what, double v) {
    if (!(v > 0)) a.invalid(what, num(v), "a number > 0");
}

// A rectangle read from two lines ("XMin, XMax" then "ZMin, ZMax") and their line numbers.
struct RectAnswer {
    Rect r;
    std::size_t x_line = 0, z_line = 0;
};

RectAnswer read_rect(Answers& a, std::string_view what) {
    RectAnswer ra;
    const auto x = a.reals(std::string(what) + " XMin,XMax", {"XMin", "XMax"});
    ra.x_line = a.line();
    const auto z = a.reals(std::string(what) + " ZMin,ZMax", {"ZMin", "ZMax"});
    ra.z_line = a.line();
    ra.r = {x[0], x[1], z[0], z[1]};
    return ra;
}

// The rectangle must be non-empty and inside the box; the message names the line at fault.
void check_rect_in_box(const Answers& a, std::string_view what, const RectAnswer& ra, double lx, double lz) {
    const Rect& r = ra.r;
    const auto fail = [&](bool x_fault, const std::string& problem, const std::string& expected) {
        throw InputError(a.where(x_fault ? ra.x_line : ra.z_line), std::string(what) + " " + problem, expected,
                         x_fault ? "XMin,XMax = " + num(r.xmin) + ", " + num(r.xmax)
                                 : "ZMin,ZMax = " + num(r.zmin) + ", " + num(r.zmax));
    };
    if (!(r.xmin < r.xmax)) fail(true, "is empty or inverted", "XMin < XMax");
    if (r.xmin < 0 || r.xmax > lx) fail(true, "reaches outside the box", "0 <= XMin < XMax <= LX = " + num(lx));
    if (!(r.zmin < r.zmax)) fail(false, "is empty or inverted", "ZMin < ZMax");
    if (r.zmin < 0 || r.zmax > lz) fail(false, "reaches outside the box", "0 <= ZMin < ZMax <= LZ = " + num(lz));
}

bool overlaps(const Rect& a, const Rect& b) {
    return a.xmin < b.xmax && b.xmin < a.xmax && a.zmin < b.zmax && b.zmin < a.zmax;
}

// The questions of SPHYSICSgen2D in its order, a group to a function (parse_legacy_case).

// Starting option to the fluid lattice: the numerics, the equation of state, the boundaries.
void read_numerics(Answers& a, CaseSpec& spec) {
    [[maybe_unused]] SimParams& p = spec.params;
    [[maybe_unused]] LegacyRunInfo& info = spec.legacy;

    // Fixed by the legacy generator.
    p.integrator = Integrator::PredictorCorrector;
    p.rho0 = 1000.0;
    p.gamma = 7.0;
    p.xsph_eps = 0.5;
    p.gx = 0.0;
    p.gz = -9.81;
    p.sigma = 0.0;

    const long restart = a.integer("starting option");
    if (restart != 0)
        a.refuse("starting option", restart,
                 restart == 1 ? "restart" : restart == 2 ? "new run with checkpointing"
                                          : restart == 3 ? "restart with checkpointing" : "unknown",
                 "0 (new run)");
    info.restart = 0;

    const long kernel = a.integer("kernel");
    if (kernel == 4 || kernel < 1 || kernel > 5)
        a.invalid("kernel", std::to_string(kernel),
                  "1 (Gaussian), 2 (quadratic), 3 (cubic spline) or 5 (Wendland)");
    p.kernel = static_cast<KernelType>(kernel);

    const long algorithm = a.integer("time-stepping algorithm");
    if (algorithm != 1)
        a.refuse("time-stepping algorithm", algorithm,
                 algorithm == 2 ? "Verlet" : algorithm == 3 ? "symplectic" : algorithm == 4 ? "Beeman" : "unknown",
                 "1 (predictor-corrector)");

    const long filter = a.integer("density filter");
    if (filter < 0 || filter > 2)
        a.invalid("density filter", std::to_string(filter), "0 (none), 1 (Shepard) or 2 (MLS)");
    p.density_filter = static_cast<DensityFilter>(filter);
    if (filter > 0) {
        const long period = a.integer("ndt_FilterPerform (steps between density filters)");
        if (period < 1)
            a.invalid("ndt_FilterPerform (the line after a density filter 1 or 2)", std::to_string(period),
                      "an integer >= 1");
        p.filter_period = static_cast<int>(period);
    }

    const long correction = a.integer("kernel correction");
    if (correction != 0)
        a.refuse("kernel correction", correction,
                 correction == 1 ? "kernel correction" : correction == 2 ? "gradient kernel correction" : "unknown",
                 "0 (none)");

    const long viscosity = a.integer("viscosity treatment");
    if (viscosity == 3) a.refuse("viscosity treatment", viscosity, "laminar + SPS", "1 (artificial) or 2 (laminar)");
    if (viscosity < 1 || viscosity > 3)
        a.invalid("viscosity treatment", std::to_string(viscosity), "1 (artificial) or 2 (laminar)");
    p.viscosity = static_cast<ViscosityModel>(viscosity);
    p.visc_value = a.real(viscosity == 1 ? "viscosity value (alpha)" : "viscosity value (nu)");
    if (p.visc_value < 0) a.invalid("viscosity value", num(p.visc_value), "a number >= 0");

    const long vort = a.integer("vorticity printing");
    if (vort != 0 && vort != 1) a.invalid("vorticity printing", std::to_string(vort), "0 or 1");
    info.vorticity = static_cast<int>(vort);
    if (vort == 1)
        spec.warnings.push_back(a.where() + ": vorticity printing is recorded in INDAT but sphjet does "
                                            "not write vorticity files");

    const long eos = a.integer("equation of state");
    if (eos != 1)
        a.refuse("equation of state", eos, eos == 2 ? "ideal gas" : eos == 3 ? "Morris" : "unknown",
                 "1 (Tait)");
    p.h_swl = a.real("maximum depth h_SWL");
    require_positive(a, "maximum depth h_SWL", p.h_swl);
    p.coef = a.real("coefficient of speed of sound");
    require_positive(a, "coefficient of speed of sound", p.coef);
    {
        // SPHYSICSgen_2D: all single precision, evaluated left to right.
        const float coef = static_cast<float>(p.coef);
        const float coef2 = coef * coef;
        float b = coef2 * 1000.0f;
        b = b * 9.81f;
        b = b * static_cast<float>(p.h_swl);
        b = b / 7.0f;
        p.B = b;
        // Single precision overflows above 3.4e38 (coef 1e20 with h_SWL 1 does).
        if (!(std::isfinite(b) && b > 0))
            a.invalid("coefficient of speed of sound (with h_SWL)", num(p.coef) + " (B = " + num(b) + ")",
                      "B = coef^2 rho0 g h_SWL / 7 finite and > 0 in single precision");
    }

    const long ibc = a.integer("boundary conditions");
    if (ibc != 1 && ibc != 2) a.invalid("boundary conditions", std::to_string(ibc), "1 (repulsive force) or 2 (dynamic)");
    p.boundary = static_cast<BoundaryType>(ibc);
    if (ibc == 1) {
        p.wall_viscosity = a.real("wall viscosity value");
        if (p.wall_viscosity < 0) a.invalid("wall viscosity value", num(p.wall_viscosity), "a number >= 0");
        p.dbc_period = 1;
    } else {
        p.wall_viscosity = 0.0;
        const long period = a.integer("ndt_DBCPerform (steps between boundary density updates)");
        if (period < 0) a.invalid("ndt_DBCPerform", std::to_string(period), "an integer >= 0 (0 and 1: every step)");
        p.dbc_period = period == 0 ? 1 : static_cast<int>(period);
    }

    const long geometry = a.integer("geometry of the zone");
    if (geometry != 1)
        a.refuse("geometry of the zone", geometry,
                 geometry == 2 ? "BEACH" : geometry == 3 ? "external geometry" : "unknown", "1 (BOX)");

    const long lattice = a.integer("fluid particle lattice");
    if (lattice != 1 && lattice != 2) a.invalid("fluid particle lattice", std::to_string(lattice), "1 (SC) or 2 (BCC)");
    p.lattice = static_cast<Lattice>(lattice);
}

// The box, the spacing, the floor and the periodic boundaries.
void read_box(Answers& a, CaseSpec& spec) {
    [[maybe_unused]] SimParams& p = spec.params;
    [[maybe_unused]] LegacyRunInfo& info = spec.legacy;

    const auto box = a.reals("box dimension LX,LZ", {"LX", "LZ"});
    if (!(box[0] > 0) || !(box[1] > 0))
        a.invalid("box dimension LX,LZ", num(box[0]) + ", " + num(box[1]), "two lengths > 0");
    p.lx = box[0], p.lz = box[1];
    const std::size_t box_line = a.line();

    const auto spacing = a.reals("spacing dx,dz", {"dx", "dz"});
    if (!(spacing[0] > 0) || !(spacing[1] > 0))
        a.invalid("spacing dx,dz", num(spacing[0]) + ", " + num(spacing[1]), "two spacings > 0");
    p.dx = spacing[0], p.dz = spacing[1];
    // The box holds N x L spacings (legacy rounds f32(LX)/dx to the nearest integer; LX is
    // single precision there, so above 3.4e38 it is infinite).
    const double r_x = f32(p.lx) / p.dx, r_z = f32(p.lz) / p.dz;
    if (!(r_x <= kMaxSpacings && r_z <= kMaxSpacings))
        throw InputError(a.where(), "spacing too fine for the box (line " + std::to_string(box_line) + ")",
                         "at most " + num(kMaxSpacings) + " spacings across LX and LZ (LX, LZ below 3.4e38)",
                         num(r_x) + " x " + num(r_z));
    const long n_x = std::lround(r_x), n_z = std::lround(r_z);
    if (n_x < 2 || n_z < 2)
        throw InputError(a.where(), "spacing too coarse for the box (line " + std::to_string(box_line) + ")",
                         "at least 2 spacings across LX and LZ",
                         std::to_string(n_x) + " x " + std::to_string(n_z));

    spec.floor_beta_deg = a.real("inclination of floor (beta)");
    if (spec.floor_beta_deg != 0)
        throw InputError(a.where(), "unsupported inclination of floor (sphjet does not implement it)",
                         "0 (flat floor)", num(spec.floor_beta_deg));

    const auto periodic = a.integers("periodic lateral boundaries", {"X", "Y", "Z"});
    for (long v : periodic) {
        if (v == 1) a.refuse("periodic lateral boundaries", v, "periodic", "0,0,0 (no periodicity)");
        if (v != 0) a.invalid("periodic lateral boundaries", std::to_string(v), "0,0,0 (no periodicity)");
    }
    spec.wall_left = spec.wall_right = spec.wall_bottom = true;
    spec.wall_top = false;
}

// Walls, obstacles, wavemaker, gate and floating body; returns the line of each obstacle.
std::vector<std::size_t> read_structures(Answers& a, CaseSpec& spec) {
    [[maybe_unused]] SimParams& p = spec.params;
    [[maybe_unused]] LegacyRunInfo& info = spec.legacy;

    // Walls inside the box.
    while (a.flag("add wall")) {
        if (p.boundary == BoundaryType::Repulsive)
            throw InputError(a.where(), "unsupported add wall with repulsive boundaries (the legacy "
                                        "generator gives such a wall no neighbour links)",
                             "0 (no wall) with boundary conditions 1, or boundary conditions 2", "1");
        WallSpec w;
        w.x = a.real("wall position XWall");
        if (!(w.x >= 0 && w.x <= p.lx)) a.invalid("wall position XWall", num(w.x), "0 <= XWall <= LX = " + num(p.lx));
        w.height = a.real("wall height ZWall");
        if (!(w.height > 0 && w.height <= p.lz))
            a.invalid("wall height ZWall", num(w.height), "0 < ZWall <= LZ = " + num(p.lz));
        spec.walls.push_back(w);
    }

    // Obstacles.
    std::vector<std::size_t> obstacle_lines;
    bool another = a.flag("add obstacle");
    while (another) {
        ObstacleSpec o;
        const long shape = a.integer("obstacle shape");
        if (shape == 2) a.refuse("obstacle shape", shape, "trapezoid", "1 (rectangular)");
        if (shape != 1) a.invalid("obstacle shape", std::to_string(shape), "1 (rectangular)");
        o.shape = 1;
        const long kind = a.integer("kind of obstacle");
        if (kind != 1 && kind != 2) a.invalid("kind of obstacle", std::to_string(kind), "1 (solid) or 2 (with solid walls)");
        if (kind == 1 && p.boundary == BoundaryType::Repulsive)
            throw InputError(a.where(), "unsupported solid obstacle with repulsive boundaries (the "
                                        "legacy generator stops here too)",
                             "2 (with solid walls) with boundary conditions 1", "1 (solid)");
        o.kind = static_cast<int>(kind);
        const long ndens = a.integer("obstacle density of points (ndens)");
        if (ndens < 1) a.invalid("obstacle density of points (ndens)", std::to_string(ndens), "an integer >= 1");
        o.density = static_cast<int>(ndens);
        const RectAnswer ra = read_rect(a, "obstacle");
        check_rect_in_box(a, "obstacle", ra, p.lx, p.lz);
        o.r = ra.r;
        obstacle_lines.push_back(a.line());
        o.beta_deg = a.real("obstacle inclination (beta)");
        if (!(o.beta_deg > 0 && o.beta_deg < 180))
            a.invalid("obstacle inclination (beta)", num(o.beta_deg), "an angle in (0, 180) degrees (90: upright)");
        if (o.beta_deg != 90) {  // the inclined sides shift the top by height / tan(beta)
            const double shift = (o.r.zmax - std::max(o.r.zmin, 0.0)) / std::tan(o.beta_deg * kPi / 180);
            if (!(o.r.xmin + std::min(shift, 0.0) >= 0 && o.r.xmax + std::max(shift, 0.0) <= p.lx))
                a.invalid("obstacle inclination (beta)", num(o.beta_deg) + " (the top shifted by " + num(shift) + ")",
                          "inclined sides that stay inside the box 0 <= x <= LX = " + num(p.lx));
        }
        spec.obstacles.push_back(o);
        another = a.flag("add another obstacle");
    }

    if (const long v = a.integer("add wavemaker"); v != 0)
        a.refuse("add wavemaker", v, v == 1 ? "wavemaker" : "", "0 (no wavemaker)");
    // Gate: SPHYSICSgen2D's "Add gate inside the box", then X, "ZZmin,ZZmax", "Vx,Vz", tgate,
    // then "Add another gate". Legacy SPHysics moves only the first gate (its solver reads
    // one gate record), so a second one is refused rather than silently frozen.
    if (a.flag("add gate")) {
        if (p.boundary == BoundaryType::Repulsive)
            throw InputError(a.where(), "unsupported add gate with repulsive boundaries (the legacy "
                                        "generator gives a gate no neighbour links)",
                             "0 (no gate) with boundary conditions 1, or boundary conditions 2", "1");
        GateSpec g;
        g.x = a.real("gate position X");
        if (!(g.x >= 0 && g.x <= p.lx)) a.invalid("gate position X", num(g.x), "0 <= X <= LX = " + num(p.lx));
        const auto z = a.reals("gate ZZmin,ZZmax", {"ZZmin", "ZZmax"});
        g.zmin = z[0], g.zmax = z[1];
        if (!(g.zmin >= 0 && g.zmin <= g.zmax && g.zmax <= p.lz))
            a.invalid("gate ZZmin,ZZmax", num(g.zmin) + ", " + num(g.zmax), "0 <= ZZmin <= ZZmax <= LZ = " + num(p.lz));
        const auto v = a.reals("gate velocity Vx,Vz", {"Vx", "Vz"});
        g.vx = v[0], g.vz = v[1];
        if (!(std::isfinite(g.vx) && std::isfinite(g.vz)))
            a.invalid("gate velocity Vx,Vz", num(g.vx) + ", " + num(g.vz), "finite velocities [m/s]");
        g.t_start = a.real("gate start time tgate");
        if (!(g.t_start >= 0)) a.invalid("gate start time tgate", num(g.t_start), "a time >= 0 [s]");
        spec.gates.push_back(g);
        if (const long more = a.integer("add another gate"); more != 0)
            a.refuse("add another gate", more, more == 1 ? "a second gate; legacy SPHysics moves only the first" : "",
                     "0 (one gate)");
    }
    if (const long v = a.integer("add floating body"); v != 0)
        a.refuse("add floating body", v, v == 1 ? "floating bodies" : "", "0 (no floating body)");
    return obstacle_lines;
}

// The initial conditions and the regions of fluid.
void read_fill(Answers& a, CaseSpec& spec, const std::vector<std::size_t>& obstacle_lines) {
    [[maybe_unused]] SimParams& p = spec.params;
    [[maybe_unused]] LegacyRunInfo& info = spec.legacy;

    const long initial = a.integer("initial conditions");
    if (initial != 2)
        a.refuse("initial conditions", initial,
                 initial == 1 ? "set of particles" : initial == 3 ? "round drop" : "unknown",
                 "2 (fill square regions on the lattice)");
    if (const long v = a.integer("correct pressure at boundaries"); v != 0)
        a.refuse("correct pressure at boundaries", v, v == 1 ? "hydrostatic boundary pressure" : "", "0 (no)");

    // Fill regions: at least one, then "Fill a new region" until 0.
    do {
        FluidBlock b;
        const RectAnswer ra = read_rect(a, "fill region");
        check_rect_in_box(a, "fill region", ra, p.lx, p.lz);
        b.r = ra.r;
        const std::string here = a.where();
        if (b.r.zmin > 1.5 * p.dz)
            spec.warnings.push_back(here + ": fill region ZMin = " + num(b.r.zmin) +
                                    " is ignored, as in SPHYSICSgen2D: a flat-floor box is filled "
                                    "from the floor up");
        if (std::lround(b.r.zmin / p.dz) <= 0)
            spec.warnings.push_back(here + ": fill region ZMin = " + num(b.r.zmin) +
                                    " is below dz/2: SPHYSICSgen2D then starts the fill from an "
                                    "uninitialised variable (its result varies from run to run); "
                                    "sphjet starts it at the floor, legacy's usual result");
        if (b.r.zmax > f32(p.h_swl) + 0.5 * p.dz)
            spec.warnings.push_back(here + ": fill region ZMax = " + num(b.r.zmax) +
                                    " is above h_SWL = " + num(p.h_swl) +
                                    "; as in SPHYSICSgen2D, the fluid stops at h_SWL");
        for (std::size_t k = 0; k < spec.obstacles.size(); ++k)
            if (overlaps(b.r, spec.obstacles[k].r))
                spec.warnings.push_back(here + ": fill region overlaps the obstacle of line " +
                                        std::to_string(obstacle_lines[k]) +
                                        "; as in SPHYSICSgen2D, fluid particles are placed inside it");
        spec.fluid_blocks.push_back(b);
    } while (a.flag("fill a new region"));
}

// Times, time step, smoothing length and the solver's options.
void read_run(Answers& a, CaseSpec& spec) {
    [[maybe_unused]] SimParams& p = spec.params;
    [[maybe_unused]] LegacyRunInfo& info = spec.legacy;

    const auto times = a.reals("tmax and out", {"tmax", "out"});
    if (!(times[0] > 0) || !(times[1] > 0)) a.invalid("tmax and out", num(times[0]) + ", " + num(times[1]), "two times > 0");
    p.tmax = times[0], p.out = times[1];

    p.trec_ini = a.real("initial time of outputting");
    if (p.trec_ini < 0) a.invalid("initial time of outputting", num(p.trec_ini), "a time >= 0");

    const auto detail = a.reals("detailed recording", {"out_detail", "start", "end"});
    info.detail_out = detail[0], info.detail_start = detail[1], info.detail_end = detail[2];

    const Answer dt_line = a.next("dt and i_var_dt", {"dt", "i_var_dt"});
    p.dt = a.to_real(dt_line.values[0], "dt and i_var_dt", "dt");
    const long ivar = a.to_integer(dt_line.values[1], "dt and i_var_dt", "i_var_dt");
    require_positive(a, "initial time step dt", p.dt);
    if (ivar != 0 && ivar != 1) a.invalid("variable time step i_var_dt", std::to_string(ivar), "0 or 1");
    p.variable_dt = ivar == 1;

    p.cfl = a.real("CFL number");
    require_positive(a, "CFL number", p.cfl);

    info.h_coefficient = a.real("h coefficient");
    require_positive(a, "h coefficient", info.h_coefficient);
    // SPHYSICSgen_2D: single coefficient times a double root, kept in single.
    p.h = f32(static_cast<double>(static_cast<float>(info.h_coefficient)) *
              std::sqrt(p.dx * p.dx + p.dz * p.dz));
    if (!(std::isfinite(p.h) && p.h > 0))
        a.invalid("h coefficient", num(info.h_coefficient) + " (h = " + num(p.h) + ")",
                  "h = coefficient sqrt(dx^2 + dz^2) finite and > 0 in single precision");

    const long riemann = a.integer("Riemann solver");
    if (riemann != 0)
        a.refuse("Riemann solver", riemann,
                 riemann == 1 ? "conservative (Vila)" : riemann == 2 ? "non-conservative (Parshikov)" : "unknown",
                 "0 (none)");

    const long compiler = a.integer("compiler choice");
    if (compiler < 1 || compiler > 4)
        a.invalid("compiler choice", std::to_string(compiler), "1 (gfortran), 2 (ifort), 3 (win ifort) or 4 (FTN95)");
    info.compiler = static_cast<int>(compiler);

    const long precision = a.integer("precision of XYZ variables");
    if (precision != 1 && precision != 2)
        a.invalid("precision of XYZ variables", std::to_string(precision), "1 (single) or 2 (double)");
    info.xz_precision = static_cast<int>(precision);
}

}  // namespace

CaseSpec parse_legacy_case(const std::string& text, const std::string& source_name) {
    Answers a(text, source_name);
    CaseSpec spec;
    spec.source = source_name;
    spec.legacy_fill = true;

    read_numerics(a, spec);
    read_box(a, spec);
    const std::vector<std::size_t> obstacle_lines = read_structures(a, spec);
    read_fill(a, spec, obstacle_lines);
    read_run(a, spec);
    return spec;
}

CaseSpec read_legacy_case(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in || std::filesystem::is_directory(path))
        throw InputError(path.string(), "cannot open the legacy case file", "a readable file",
                         std::filesystem::is_directory(path) ? "a directory"
                         : std::filesystem::exists(path)     ? "a file that cannot be read"
                                                             : "no such file");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_legacy_case(text.str(), path.string());
}

}  // namespace sphjet
