#include "config/modern_case.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include <toml++/toml.h>

#include "config/errors.hpp"

namespace sphjet {

// ---------------------------------------------------------------------------------------
// Derived quantities
// ---------------------------------------------------------------------------------------

double tait_B_from_c0(double rho0, double c0, double gamma) { return rho0 * c0 * c0 / gamma; }

double tait_B_from_coef(double coef, double rho0, double g, double h_swl, double gamma) {
    return coef * coef * rho0 * g * h_swl / gamma;
}

double alpha_from_nu(double nu, double h, double c0) { return 8.0 * nu / (h * c0); }

namespace {

double f32(double v) { return static_cast<double>(static_cast<float>(v)); }

// SPHYSICSgen_2D's arithmetic (single precision, left to right); the same numbers as
// read_legacy_case (config/legacy_case.cpp) for rho0 = 1000, g = 9.81, gamma = 7.
double tait_B_from_coef_single(double coef, double rho0, double g, double h_swl, double gamma) {
    const float c = static_cast<float>(coef);
    float b = c * c;
    b = b * static_cast<float>(rho0);
    b = b * static_cast<float>(g);
    b = b * static_cast<float>(h_swl);
    b = b / static_cast<float>(gamma);
    return b;
}

double h_from_coefficient(double coefficient, double dx, double dz, bool single) {
    const double root = std::sqrt(dx * dx + dz * dz);
    return single ? f32(f32(coefficient) * root) : coefficient * root;
}

}  // namespace

bool looks_like_modern_case(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".toml";
}

namespace {

// ---------------------------------------------------------------------------------------
// The schema: every key the format knows, with its TOML type. Sections are the prefixes;
// "name[]" is an array of tables ([[name]] in the file).
// ---------------------------------------------------------------------------------------

enum class Kind { Float, Int, Bool, String };

struct KeySpec {
    std::string_view path;
    Kind kind;
};

constexpr KeySpec kKeys[] = {
    {"format_version", Kind::Int},
    // [numerics]
    {"numerics.kernel", Kind::String},
    {"numerics.integrator", Kind::String},
    {"numerics.density_filter", Kind::String},
    {"numerics.filter_period", Kind::Int},
    {"numerics.viscosity", Kind::String},
    {"numerics.alpha", Kind::Float},
    {"numerics.xsph_eps", Kind::Float},
    {"numerics.tensile_correction", Kind::String},
    {"numerics.boundary", Kind::String},
    {"numerics.dbc_period", Kind::Int},
    {"numerics.wall_viscosity", Kind::Float},
    {"numerics.lattice", Kind::String},
    // [fluid]
    {"fluid.rho0", Kind::Float},
    {"fluid.gamma", Kind::Float},
    {"fluid.c0", Kind::Float},
    {"fluid.coef", Kind::Float},
    {"fluid.h_swl", Kind::Float},
    {"fluid.mu", Kind::Float},
    {"fluid.nu", Kind::Float},
    {"fluid.block[].xmin", Kind::Float},
    {"fluid.block[].xmax", Kind::Float},
    {"fluid.block[].zmin", Kind::Float},
    {"fluid.block[].zmax", Kind::Float},
    {"fluid.block[].u0", Kind::Float},
    {"fluid.block[].w0", Kind::Float},
    {"fluid.disc[].xc", Kind::Float},
    {"fluid.disc[].zc", Kind::Float},
    {"fluid.disc[].radius", Kind::Float},
    {"fluid.disc[].u0", Kind::Float},
    {"fluid.disc[].w0", Kind::Float},
    {"fluid.disc[].lattice", Kind::String},
    {"fluid.disc[].elongation", Kind::Float},
    {"fluid.cylinder[].radius", Kind::Float},
    {"fluid.cylinder[].eps", Kind::Float},
    {"fluid.cylinder[].wavelength", Kind::Float},
    {"fluid.cylinder[].zmin", Kind::Float},
    {"fluid.cylinder[].zmax", Kind::Float},
    {"fluid.square[].xc", Kind::Float},
    {"fluid.square[].zc", Kind::Float},
    {"fluid.square[].side", Kind::Float},
    {"fluid.square[].u0", Kind::Float},
    {"fluid.square[].w0", Kind::Float},
    // [surface_tension]
    {"surface_tension.sigma", Kind::Float},
    {"surface_tension.delta", Kind::String},
    {"surface_tension.rings_curvature", Kind::String},
    // [gravity]
    {"gravity.gx", Kind::Float},
    {"gravity.gz", Kind::Float},
    // [domain]
    {"domain.lx", Kind::Float},
    {"domain.lz", Kind::Float},
    {"domain.wall_left", Kind::Bool},
    {"domain.wall_right", Kind::Bool},
    {"domain.wall_bottom", Kind::Bool},
    {"domain.wall_top", Kind::Bool},
    {"domain.floor_inclination_deg", Kind::Float},
    {"domain.geometry", Kind::String},
    {"domain.periodic_z", Kind::Bool},
    {"domain.axis_pair", Kind::String},
    // [resolution]
    {"resolution.dx", Kind::Float},
    {"resolution.dz", Kind::Float},
    {"resolution.h", Kind::Float},
    {"resolution.h_coefficient", Kind::Float},
    {"resolution.h_over_dx", Kind::Float},
    // [time]
    {"time.tmax", Kind::Float},
    {"time.dt", Kind::Float},
    {"time.variable_dt", Kind::Bool},
    {"time.cfl", Kind::Float},
    {"time.out", Kind::Float},
    {"time.trec_ini", Kind::Float},
    // [[obstacle]]
    {"obstacle[].shape", Kind::String},
    {"obstacle[].kind", Kind::String},
    {"obstacle[].density", Kind::Int},
    {"obstacle[].xmin", Kind::Float},
    {"obstacle[].xmax", Kind::Float},
    {"obstacle[].zmin", Kind::Float},
    {"obstacle[].zmax", Kind::Float},
    {"obstacle[].beta_deg", Kind::Float},
    // [gate]: legacy "Add gate"
    {"gate.x", Kind::Float},
    {"gate.zmin", Kind::Float},
    {"gate.zmax", Kind::Float},
    {"gate.vx", Kind::Float},
    {"gate.vz", Kind::Float},
    {"gate.t_start", Kind::Float},
    {"gate.facing", Kind::String},
    // [nozzle]: a driven nozzle (the jets)
    {"nozzle.x0", Kind::Float},
    {"nozzle.z0", Kind::Float},
    {"nozzle.axis", Kind::String},
    {"nozzle.d0", Kind::Float},
    {"nozzle.length_over_d0", Kind::Float},
    {"nozzle.u0", Kind::Float},
    {"nozzle.walls", Kind::Bool},
    {"nozzle.disturbance", Kind::Float},
    {"nozzle.disturbance_ka", Kind::Float},
    // [breakup]: breakup detection while the run goes
    {"breakup.link_over_h", Kind::Float},
    {"breakup.band_over_d0", Kind::Float},
    {"breakup.check_every", Kind::Float},
    {"breakup.stop_after", Kind::Float},
    {"breakup.remove_drops_below_h", Kind::Float},
    // [[wall]]: legacy "Add wall"
    {"wall[].x", Kind::Float},
    {"wall[].height", Kind::Float},
    // [legacy]: what a converted legacy case carries
    {"legacy.fill", Kind::Bool},
    {"legacy.single_precision", Kind::Bool},
    {"legacy.h_coefficient", Kind::Float},
    {"legacy.detail_out", Kind::Float},
    {"legacy.detail_start", Kind::Float},
    {"legacy.detail_end", Kind::Float},
    {"legacy.vorticity", Kind::Bool},
    {"legacy.compiler", Kind::Int},
    {"legacy.xz_precision", Kind::String},
    // [output]
    {"output.format", Kind::String},
    {"output.checkpoint_every_steps", Kind::Int},
    {"output.checkpoint_every_minutes", Kind::Float},
    {"output.remove_out_of_domain", Kind::Bool},
    {"output.rho_min_factor", Kind::Float},
    {"output.rho_max_factor", Kind::Float},
    {"output.dt_min", Kind::Float},
    {"output.revolution_sectors", Kind::Int},
};

const KeySpec* find_key(std::string_view pattern) {
    for (const auto& k : kKeys)
        if (k.path == pattern) return &k;
    return nullptr;
}

const std::set<std::string>& sections() {
    static const std::set<std::string> s = [] {
        std::set<std::string> out;
        for (const auto& k : kKeys) {
            std::string_view p = k.path;
            for (std::size_t i = 0; i < p.size(); ++i)
                if (p[i] == '.') out.emplace(p.substr(0, i));
        }
        return out;
    }();
    return s;
}

bool is_section(const std::string& pattern) { return sections().count(pattern) > 0; }

std::string join(const std::string& prefix, std::string_view key) {
    return prefix.empty() ? std::string(key) : prefix + "." + std::string(key);
}

// Direct children of a section pattern ("" = top level), as written in a file:
// "kernel", "block" (for "fluid.block[]"), ...
std::vector<std::string> children(const std::string& prefix) {
    std::set<std::string> out;
    const std::string lead = prefix.empty() ? "" : prefix + ".";
    for (const auto& k : kKeys) {
        std::string_view p = k.path;
        if (p.substr(0, lead.size()) != lead) continue;
        std::string_view rest = p.substr(lead.size());
        rest = rest.substr(0, rest.find('.'));
        if (rest.size() > 2 && rest.substr(rest.size() - 2) == "[]") rest.remove_suffix(2);
        out.emplace(rest);
    }
    return {out.begin(), out.end()};
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                              std::tolower(static_cast<unsigned char>(b[j - 1]));
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
        }
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

std::optional<std::string> closest(std::string_view word, const std::vector<std::string>& options) {
    std::optional<std::string> best;
    std::size_t best_d = std::max<std::size_t>(2, word.size() / 3) + 1;
    for (const auto& o : options) {
        std::size_t d = edit_distance(word, o);
        // "cubic" for "cubic_spline": a prefix of three or more letters is a near miss.
        if (word.size() >= 3 && word.size() < o.size() &&
            edit_distance(word, std::string_view(o).substr(0, word.size())) == 0)
            d = std::min<std::size_t>(d, 1);
        if (d < best_d) best_d = d, best = o;
    }
    return best;
}

std::string list(const std::vector<std::string>& items) {
    std::string s;
    for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
    return s;
}

// Shortest text that reads back as the same double, always a TOML float.
std::string num(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    std::array<char, 64> buf{};
    auto res = std::to_chars(buf.data(), buf.data() + buf.size(), v);
    std::string s(buf.data(), res.ptr);
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::string dquote(std::string_view s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) continue;
        out += c;
    }
    return out + "\"";
}

std::string describe(const toml::node& n) {
    std::ostringstream os;
    switch (n.type()) {
        case toml::node_type::table: return "a table";
        case toml::node_type::array: return "an array";
        case toml::node_type::string: os << "the string "; break;
        case toml::node_type::integer: os << "the integer "; break;
        case toml::node_type::floating_point: os << "the float "; break;
        case toml::node_type::boolean: os << "the boolean "; break;
        default: os << "the date/time "; break;
    }
    if (auto str = n.value_exact<std::string>())
        os << dquote(*str);
    else
        n.visit([&os](const auto& v) {
            if constexpr (toml::is_value<decltype(v)>) os << v;
        });
    return os.str();
}


// Array index segment "name[3]" -> ("name", 3); plain "name" -> ("name", nullopt).
std::pair<std::string, std::optional<std::size_t>> split_index(const std::string& seg) {
    const auto open = seg.find('[');
    if (open == std::string::npos || seg.back() != ']') return {seg, std::nullopt};
    const std::string digits = seg.substr(open + 1, seg.size() - open - 2);
    std::size_t idx = 0;
    auto res = std::from_chars(digits.data(), digits.data() + digits.size(), idx);
    if (digits.empty() || res.ec != std::errc{} || res.ptr != digits.data() + digits.size())
        return {seg, std::nullopt};
    return {seg.substr(0, open), idx};
}

// ---------------------------------------------------------------------------------------
// Reading context: the file name and where each overridden key came from.
// ---------------------------------------------------------------------------------------

struct Ctx {
    std::string file;
    std::map<std::string, std::string> overridden;  // actual key path -> override text

    std::string where(const std::string& path, const toml::node* n = nullptr) const {
        std::string w = file + ": " + path;
        if (auto it = overridden.find(path); it != overridden.end())
            w += " (set by override '" + it->second + "')";
        else if (n != nullptr && n->source().begin.line > 0)
            w += " (line " + std::to_string(n->source().begin.line) + ")";
        return w;
    }
};

template <class T>
struct Field {
    T value;
    std::string where;
};

std::string found_text(double v) { return num(v); }
std::string found_text(std::int64_t v) { return std::to_string(v); }
std::string found_text(const std::string& v) { return dquote(v); }

template <class T>
[[noreturn]] void fail(const Field<T>& f, const std::string& problem, const std::string& expected) {
    throw InputError(f.where, problem, expected, found_text(f.value));
}

// A view of one table of the file with its key path ("fluid.block[2]").
class Section {
public:
    Section(const Ctx& ctx, const toml::table* t, std::string path)
        : ctx_(ctx), t_(t), path_(std::move(path)) {}

    [[nodiscard]] const std::string& path() const { return path_; }
    [[nodiscard]] std::string key_path(std::string_view key) const { return join(path_, key); }
    [[nodiscard]] bool has(std::string_view key) const {
        return t_ != nullptr && t_->get(key) != nullptr;
    }

    [[nodiscard]] std::optional<Field<double>> num(std::string_view key) const {
        const toml::node* n = node(key);
        if (n == nullptr) return std::nullopt;
        double v = 0;
        if (auto f = n->value_exact<double>())
            v = *f;
        else if (auto i = n->value_exact<std::int64_t>())
            v = static_cast<double>(*i);
        else
            wrong_type(key, n, "a number");
        Field<double> f{v, ctx_.where(key_path(key), n)};
        if (!std::isfinite(v)) fail(f, "not a finite number", "a finite number");
        return f;
    }
    [[nodiscard]] std::optional<Field<std::int64_t>> integer(std::string_view key) const {
        const toml::node* n = node(key);
        if (n == nullptr) return std::nullopt;
        auto i = n->value_exact<std::int64_t>();
        if (!i) wrong_type(key, n, "an integer");
        return Field<std::int64_t>{*i, ctx_.where(key_path(key), n)};
    }
    [[nodiscard]] std::optional<Field<bool>> boolean(std::string_view key) const {
        const toml::node* n = node(key);
        if (n == nullptr) return std::nullopt;
        auto b = n->value_exact<bool>();
        if (!b) wrong_type(key, n, "a boolean (true or false)");
        return Field<bool>{*b, ctx_.where(key_path(key), n)};
    }
    [[nodiscard]] std::optional<Field<std::string>> string(std::string_view key) const {
        const toml::node* n = node(key);
        if (n == nullptr) return std::nullopt;
        auto s = n->value_exact<std::string>();
        if (!s) wrong_type(key, n, "a string");
        return Field<std::string>{*s, ctx_.where(key_path(key), n)};
    }

    [[nodiscard]] Field<double> required_num(std::string_view key, const std::string& expected) const {
        if (auto f = num(key)) return *f;
        throw InputError(ctx_.where(key_path(key)), "missing required key", expected, "nothing");
    }

    // Sets `out` when the key is present.
    void get(std::string_view key, double& out) const {
        if (auto f = num(key)) out = f->value;
    }
    void get(std::string_view key, bool& out) const {
        if (auto f = boolean(key)) out = f->value;
    }

    [[nodiscard]] std::vector<Section> array_of_tables(std::string_view key) const {
        std::vector<Section> out;
        const toml::node* n = node(key);
        if (n == nullptr) return out;
        const toml::array* arr = n->as_array();
        for (std::size_t i = 0; i < arr->size(); ++i)
            out.emplace_back(ctx_, arr->get(i)->as_table(),
                             key_path(key) + "[" + std::to_string(i) + "]");
        return out;
    }
    [[nodiscard]] Section sub(std::string_view key) const {
        const toml::node* n = node(key);
        return {ctx_, n != nullptr ? n->as_table() : nullptr, key_path(key)};
    }

private:
    [[nodiscard]] const toml::node* node(std::string_view key) const {
        return t_ == nullptr ? nullptr : t_->get(key);
    }
    [[noreturn]] void wrong_type(std::string_view key, const toml::node* n,
                                 const std::string& expected) const {
        throw InputError(ctx_.where(key_path(key), n), "wrong type", expected, describe(*n));
    }

    const Ctx& ctx_;
    const toml::table* t_;
    std::string path_;
};

// The value named f among options (pairs of a name and its value); an unknown name fails with
// the names and the closest one.
template <class E, class Options>
E choose_from(const Field<std::string>& f, const Options& options) {
    std::vector<std::string> names;
    for (const auto& [name, e] : options) {
        if (f.value == name) return e;
        names.emplace_back(name);
    }
    std::string problem = "unknown value";
    if (auto c = closest(f.value, names)) problem += " (did you mean \"" + *c + "\"?)";
    std::vector<std::string> q;
    for (const auto& n : names) q.push_back(dquote(n));
    fail(f, problem, "one of " + list(q));
}

// The names of the choices the case codes as numbers or flags, read (choose_from) and echoed
// (name_in, write_modern_case) from the same table.
constexpr NameTable<int, 2> kPrecisionNames{{{"single", 1}, {"double", 2}}};
constexpr NameTable<int, 3> kTensileNames{{{"auto", -1}, {"on", 1}, {"off", 0}}};
constexpr NameTable<int, 1> kObstacleShapes{{{"rectangle", 1}}};
constexpr NameTable<int, 2> kObstacleKinds{{{"solid", 1}, {"walls", 2}}};
constexpr NameTable<int, 2> kGateFacings{{{"left", -1}, {"right", 1}}};
constexpr NameTable<bool, 2> kDiscLattices{{{"case", false}, {"rings", true}}};
// the nozzle's jet direction (ex, ez)
constexpr NameTable<std::pair<double, double>, 4> kNozzleAxes{
    {{"down", {0.0, -1.0}}, {"up", {0.0, 1.0}}, {"left", {-1.0, 0.0}}, {"right", {1.0, 0.0}}}};

// An enum of the parameters, by the names of its table (EnumNames, params.hpp).
template <NamedEnum E>
E choose(const Field<std::string>& f) {
    return choose_from<E>(f, EnumNames<E>::list);
}

// ---------------------------------------------------------------------------------------
// Unknown keys: walk the whole tree against the schema.
// ---------------------------------------------------------------------------------------

// "[numerics]", "[[fluid.block]]" or "the top level", for messages.
std::string section_name(const std::string& pattern) {
    if (pattern.empty()) return "the top level";
    if (pattern.size() > 2 && pattern.substr(pattern.size() - 2) == "[]")
        return "[[" + pattern.substr(0, pattern.size() - 2) + "]]";
    return "[" + pattern + "]";
}

[[noreturn]] void unknown_key(const Ctx& ctx, const std::string& pattern_prefix,
                              const std::string& actual_path, std::string_view key,
                              const toml::node* n) {
    const auto options = children(pattern_prefix);
    std::string problem = "unknown key";
    if (auto c = closest(key, options)) {
        problem += " (did you mean '" + join(pattern_prefix, *c) + "'?)";
    } else {
        // The right name in the wrong section?
        for (const auto& k : kKeys) {
            const std::string p(k.path);
            const auto dot = p.rfind('.');
            const std::string leaf = dot == std::string::npos ? p : p.substr(dot + 1);
            if (leaf == key) {
                problem += " here (it is a key of " +
                           section_name(dot == std::string::npos ? "" : p.substr(0, dot)) + ")";
                break;
            }
        }
    }
    throw InputError(ctx.where(actual_path, n), problem,
                     "one of the keys of " + section_name(pattern_prefix) + ": " + list(options),
                     dquote(key));
}

void check_keys(const Ctx& ctx, const toml::table& t, const std::string& pattern_prefix,
                const std::string& actual_prefix) {
    for (auto&& [k, node] : t) {
        const std::string key(k.str());
        const std::string pat = join(pattern_prefix, key);
        const std::string act = join(actual_prefix, key);
        if (find_key(pat) != nullptr) continue;  // a leaf: its type is checked when read
        if (is_section(pat)) {
            if (!node.is_table())
                throw InputError(ctx.where(act, &node), "wrong type",
                                 "a table [" + pat + "]", describe(node));
            check_keys(ctx, *node.as_table(), pat, act);
            continue;
        }
        if (is_section(pat + "[]")) {
            const toml::array* arr = node.as_array();
            const bool tables = arr != nullptr &&
                std::all_of(arr->begin(), arr->end(), [](const toml::node& e) { return e.is_table(); });
            if (!tables)
                throw InputError(ctx.where(act, &node), "wrong type",
                                 "an array of tables, written [[" + pat + "]]", describe(node));
            for (std::size_t i = 0; i < arr->size(); ++i)
                check_keys(ctx, *arr->get(i)->as_table(), pat + "[]",
                           act + "[" + std::to_string(i) + "]");
            continue;
        }
        unknown_key(ctx, pattern_prefix, act, key, &node);
    }
}

// ---------------------------------------------------------------------------------------
// Three toml++ 3.3 defects, kept away from it.
// ---------------------------------------------------------------------------------------

// toml++ 3.3 (the Debian 12 package) has defects that malformed text reaches, all found
// by tests/fuzz (-fsanitize=undefined on toml++ compiled header-only):
//  - a table header whose key starts with a character that cannot start a key ("[^x]",
//    "[[[1]]]", "[" at the end of a line) fails an assertion in parse_key() (abort without
//    NDEBUG, an assumption that does not hold with it); fixed upstream in
//    marzer/tomlplusplus pull 301;
//  - a non-ASCII character where toml++ tests for whitespace (after a key, in the text it
//    scans ahead of a bare value, after a backslash in a multi-line string) reaches
//    TOML_UNREACHABLE in its Unicode tables: undefined behaviour in every build;
//    marzer/tomlplusplus reports 190 and 295, fixed by pull 305.

// The first line that starts (after blanks) with '[' or '[[' not followed by a key, ']' or
// another '[' toml++ reports itself: its byte offset. Line by line, without regard to
// strings, so a multi-line string or array holding such a line is reported too (the format
// has neither).
std::optional<std::size_t> bad_table_header(std::string_view text) {
    const auto blank = [](char c) { return c == ' ' || c == '\t'; };
    const auto key_start = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '"' || c == '\'';
    };
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text = text.substr(3);  // UTF-8 byte-order mark
    for (std::size_t b = 0; b < text.size();) {
        std::size_t e = text.find('\n', b);
        if (e == std::string_view::npos) e = text.size();
        std::size_t i = b;
        while (i < e && blank(text[i])) ++i;
        if (i < e && text[i] == '[') {
            ++i;
            bool had_blank = false;
            while (i < e && blank(text[i])) ++i, had_blank = true;
            if (i < e && text[i] == '[' && !had_blank) {  // "[ [" is an error toml++ reports
                ++i;
                while (i < e && blank(text[i])) ++i;
            }
            if (i < text.size() && text[i] != ']' && !(had_blank && text[i] == '[') && !key_start(text[i]))
                return i;
        }
        b = e + 1;
    }
    return std::nullopt;
}

// Length of the well-formed UTF-8 sequence of a non-ASCII character at s[i] (0: none).
std::size_t utf8_length(std::string_view s, std::size_t i) {
    const auto u = [&](std::size_t k) { return k < s.size() ? static_cast<unsigned char>(s[k]) : 0u; };
    const auto cont = [&](std::size_t k, unsigned lo = 0x80, unsigned hi = 0xBF) { return u(k) >= lo && u(k) <= hi; };
    const unsigned c = u(i);
    if (c >= 0xC2 && c <= 0xDF) return cont(i + 1) ? 2 : 0;
    if (c == 0xE0) return cont(i + 1, 0xA0) && cont(i + 2) ? 3 : 0;
    if ((c >= 0xE1 && c <= 0xEC) || c == 0xEE || c == 0xEF) return cont(i + 1) && cont(i + 2) ? 3 : 0;
    if (c == 0xED) return cont(i + 1, 0x80, 0x9F) && cont(i + 2) ? 3 : 0;
    if (c == 0xF0) return cont(i + 1, 0x90) && cont(i + 2) && cont(i + 3) ? 4 : 0;
    if (c >= 0xF1 && c <= 0xF3) return cont(i + 1) && cont(i + 2) && cont(i + 3) ? 4 : 0;
    if (c == 0xF4) return cont(i + 1, 0x80, 0x8F) && cont(i + 2) && cont(i + 3) ? 4 : 0;
    return 0;
}

// The text toml++ is given: every non-ASCII character replaced by '?'. TOML allows those
// characters only in comments and strings; every key and string value of this format is
// ASCII, so a case file means the same after the replacement (a wrong value or key is
// quoted with '?' in its message) and columns, counted in characters, stay the same.
// Malformed UTF-8 is left for toml++ to report.
std::string ascii_for_toml(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t n = utf8_length(text, i);
        if (n == 0) {
            out += text[i++];
        } else {
            out += '?';
            i += n;
        }
    }
    return out;
}

// Two more defects fail the assertion !is_value_terminator in parse_value() (abort without
// NDEBUG, an unmet assumption with it):
//  - in an array, a '}' where a value is expected ("a = [}", "[1, }", also after blank lines
//    and comments);
//  - a bare value of ten characters with '-' at the 5th and 8th (a date's shape), then a
//    space, one digit and a value terminator ("a = 1979-05-27 7 "): toml++ takes the space
//    for the date-time separator and scans on past the digit. Never valid TOML (a time after
//    the space needs hh:mm:ss).
// The offset of the first, from a small lexer (comments and the four kinds of string): toml++
// reaches either only through text that parses, which the lexer follows exactly.
bool toml_terminator(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ',' || c == ']' || c == '}' || c == '#';
}

bool date_space_digit(std::string_view text, std::size_t i) {
    if (i + 13 > text.size()) return false;
    for (std::size_t k = i; k < i + 10; ++k)
        if (toml_terminator(text[k])) return false;
    const auto digit = [](char c) { return c >= '0' && c <= '9'; };
    return digit(text[i]) && text[i + 4] == '-' && text[i + 7] == '-' && text[i + 10] == ' ' &&
           digit(text[i + 11]) && toml_terminator(text[i + 12]);
}

std::optional<std::size_t> toml_assertion_hazard(std::string_view text) {
    enum class S { Normal, Comment, Basic, Literal, MlBasic, MlLiteral } s = S::Normal;
    std::vector<char> open;     // '[' (array) or '{' (inline table), innermost last
    bool expect_value = false;  // just after '[' or ',' of an array
    bool line_begin = true;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') {
            if (s == S::Comment || s == S::Basic || s == S::Literal) s = S::Normal;
            line_begin = true;
            continue;
        }
        switch (s) {
            case S::Normal: {
                const bool header = line_begin && open.empty();
                if (c == ' ' || c == '\t' || c == '\r') break;
                line_begin = false;
                if (c == '#') {
                    s = S::Comment;
                    break;
                }
                if (expect_value && c == '}') return i;
                if ((i == 0 || std::string_view(" \t=[,{").find(text[i - 1]) != std::string_view::npos) &&
                    date_space_digit(text, i))
                    return i;
                expect_value = false;
                if (c == '"' || c == '\'') {
                    const bool multi = text.substr(i, 3) == std::string(3, c);
                    s = c == '"' ? (multi ? S::MlBasic : S::Basic) : (multi ? S::MlLiteral : S::Literal);
                    if (multi) i += 2;
                } else if (c == '[' && !header) {
                    open.push_back('['), expect_value = true;
                } else if (c == '[' && header) {  // a table header: to the end of its line
                    while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
                } else if (c == '{') {
                    open.push_back('{');
                } else if ((c == ']' || c == '}') && !open.empty()) {
                    open.pop_back();
                } else if (c == ',' && !open.empty() && open.back() == '[') {
                    expect_value = true;
                }
                break;
            }
            case S::Comment:
                break;
            case S::Basic:
                if (c == '\\' && i + 1 < text.size() && text[i + 1] != '\n') ++i;
                else if (c == '"') s = S::Normal;
                break;
            case S::Literal:
                if (c == '\'') s = S::Normal;
                break;
            case S::MlBasic:
            case S::MlLiteral: {
                const char q = s == S::MlBasic ? '"' : '\'';
                if (s == S::MlBasic && c == '\\' && i + 1 < text.size() && text[i + 1] != '\n') {
                    ++i;
                } else if (c == q && text.substr(i, 3) == std::string(3, q)) {
                    std::size_t j = i;
                    while (j < text.size() && text[j] == q && j - i < 5) ++j;
                    i = j - 1;
                    s = S::Normal;
                }
                break;
            }
        }
    }
    return std::nullopt;
}

bool has_non_ascii(std::string_view s) {
    return std::any_of(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) >= 0x80; });
}

// ---------------------------------------------------------------------------------------
// Overrides: key.path=value, applied to the tree before validation.
// ---------------------------------------------------------------------------------------

std::string trim(std::string_view s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string_view::npos) return {};
    const auto e = s.find_last_not_of(" \t");
    return std::string(s.substr(b, e - b + 1));
}

void apply_override(Ctx& ctx, toml::table& root, const std::string& text) {
    const std::string where = "override '" + text + "'";
    const auto eq = text.find('=');
    if (eq == std::string::npos)
        throw InputError(where, "not of the form key.path=value", "key.path=value",
                         dquote(text));
    const std::string path = trim(std::string_view(text).substr(0, eq));
    const std::string value = trim(std::string_view(text).substr(eq + 1));

    std::vector<std::string> segs;
    for (std::size_t b = 0;;) {
        const auto d = path.find('.', b);
        segs.push_back(path.substr(b, d == std::string::npos ? std::string::npos : d - b));
        if (d == std::string::npos) break;
        b = d + 1;
    }

    // The key must exist in the schema.
    std::string pattern, pattern_prefix;
    for (std::size_t i = 0; i < segs.size(); ++i) {
        auto [name, idx] = split_index(segs[i]);
        if (name.empty())
            throw InputError(where, "empty key segment", "key.path=value", dquote(path));
        pattern_prefix = pattern;
        pattern = join(pattern, name) + (idx ? "[]" : "");
    }
    if (find_key(pattern) == nullptr) {
        std::string problem = "unknown key";
        const std::string last = split_index(segs.back()).first;
        if (is_section(pattern) || is_section(pattern + "[]")) {
            problem = "names a section, not a key";
        } else if (auto c = closest(last, children(pattern_prefix)); c && find_key(join(pattern_prefix, *c))) {
            problem += " (did you mean '" + join(pattern_prefix, *c) + "'?)";
        } else {
            // "fluid.block.u0" for "fluid.block[0].u0"?
            for (const auto& k : kKeys) {
                std::string p(k.path);
                p.erase(std::remove(p.begin(), p.end(), '['), p.end());
                p.erase(std::remove(p.begin(), p.end(), ']'), p.end());
                if (p == pattern) {
                    problem += " (elements of an array of tables are named with an index, e.g. '" +
                               std::string(k.path).replace(std::string(k.path).find("[]"), 2, "[0]") +
                               "')";
                    break;
                }
            }
        }
        throw InputError(where, problem, "a key listed in cases/CASE_FORMAT.md", dquote(path));
    }

    // Parse the value as TOML; what does not parse (a bare word) is a string.
    toml::table parsed;
    bool ok = false;
    try {
        const std::string line = "v = " + value;
        if (!has_non_ascii(line) && !bad_table_header(line) && !toml_assertion_hazard(line)) {
            parsed = toml::parse(line);
            ok = parsed.size() == 1 && parsed.get("v") != nullptr;
        }
    } catch (const toml::parse_error&) {
        ok = false;
    }
    if (!ok) {
        parsed = toml::table{};
        parsed.insert_or_assign("v", value);
    }

    // Walk down the tree, creating missing tables.
    toml::table* t = &root;
    std::string actual, array_name;
    for (std::size_t i = 0; i + 1 < segs.size(); ++i) {
        auto [name, idx] = split_index(segs[i]);
        array_name = join(actual, name);
        actual = join(actual, segs[i]);
        toml::node* n = t->get(name);
        if (!idx) {
            if (n == nullptr) n = &t->insert_or_assign(name, toml::table{}).first->second;
            if (!n->is_table())
                throw InputError(where, "cannot set a key inside " + actual, "a table",
                                 describe(*n));
            t = n->as_table();
        } else {
            toml::array* arr = n != nullptr ? n->as_array() : nullptr;
            const std::size_t size = arr != nullptr ? arr->size() : 0;
            if (arr == nullptr || *idx >= size || !arr->get(*idx)->is_table())
                throw InputError(where, "no such element in the case file",
                                 "an index below the number of [[" + array_name +
                                     "]] entries (" + std::to_string(size) + ")",
                                 dquote(segs[i]));
            t = arr->get(*idx)->as_table();
        }
    }
    t->insert_or_assign(split_index(segs.back()).first, std::move(*parsed.get("v")));
    ctx.overridden[path] = text;
}

// ---------------------------------------------------------------------------------------
// From the tree to a CaseSpec.
// ---------------------------------------------------------------------------------------

void positive(const Field<double>& f) {
    if (!(f.value > 0)) fail(f, "must be positive", "a number > 0");
}
void non_negative(const Field<double>& f) {
    if (!(f.value >= 0)) fail(f, "must not be negative", "a number >= 0");
}
void at_least(const Field<std::int64_t>& f, std::int64_t lo) {
    if (f.value < lo) fail(f, "out of range", "an integer >= " + std::to_string(lo));
}
int to_int(const Field<std::int64_t>& f) {
    if (f.value > 1000000000) fail(f, "out of range", "an integer <= 1000000000");
    return static_cast<int>(f.value);
}

struct Box {
    double lx, lz;
};

// A coordinate of a region must lie in [0, L] (with a tolerance for round-off).
void inside(const Field<double>& f, double L, const char* axis, const char* what) {
    const double tol = 1e-9 * std::max(L, 1.0);
    if (f.value < -tol || f.value > L + tol)
        fail(f, std::string(what) + " outside the box",
             std::string(axis) + " in [0, " + num(L) + "] (domain." + (axis[0] == 'x' ? "lx" : "lz") + ")");
}

Rect read_rect(const Section& s, const Box& box, const char* what) {
    const auto xmin = s.required_num("xmin", "the left edge [m]");
    const auto xmax = s.required_num("xmax", "the right edge [m]");
    const auto zmin = s.required_num("zmin", "the bottom edge [m]");
    const auto zmax = s.required_num("zmax", "the top edge [m]");
    if (!(xmax.value > xmin.value)) fail(xmax, "empty region", "xmax > xmin = " + num(xmin.value));
    if (!(zmax.value > zmin.value)) fail(zmax, "empty region", "zmax > zmin = " + num(zmin.value));
    inside(xmin, box.lx, "x", what);
    inside(xmax, box.lx, "x", what);
    inside(zmin, box.lz, "z", what);
    inside(zmax, box.lz, "z", what);
    return {xmin.value, xmax.value, zmin.value, zmax.value};
}

// Centre +- half extent must lie inside the box.
void centred_inside(const Field<double>& xc, const Field<double>& zc, const Field<double>& size,
                    double half, const Box& box, const char* what) {
    const double tol = 1e-9 * std::max({box.lx, box.lz, 1.0});
    if (xc.value - half < -tol || xc.value + half > box.lx + tol)
        fail(xc, std::string(what) + " outside the box",
             "xc - " + num(half) + " >= 0 and xc + " + num(half) + " <= domain.lx = " + num(box.lx));
    if (zc.value - half < -tol || zc.value + half > box.lz + tol)
        fail(zc, std::string(what) + " outside the box",
             "zc - " + num(half) + " >= 0 and zc + " + num(half) + " <= domain.lz = " + num(box.lz));
    (void)size;
}

CaseSpec build(const Ctx& ctx, const toml::table& root) {
    CaseSpec spec;
    spec.source = ctx.file;
    SimParams& p = spec.params;
    const Section top(ctx, &root, "");

    if (auto v = top.integer("format_version"); v && v->value != 1)
        fail(*v, "unsupported format version", "1");

    // [legacy]: read first, single_precision changes how B and h are derived.
    const Section leg = top.sub("legacy");
    bool single = false;
    leg.get("fill", spec.legacy_fill);
    leg.get("single_precision", single);
    LegacyRunInfo& info = spec.legacy;
    leg.get("detail_out", info.detail_out);
    leg.get("detail_start", info.detail_start);
    leg.get("detail_end", info.detail_end);
    if (auto f = leg.boolean("vorticity")) info.vorticity = f->value ? 1 : 0;
    if (auto f = leg.integer("compiler")) {
        if (f->value < 1 || f->value > 4) fail(*f, "out of range", "1 (gfortran), 2 (ifort), 3 (win_ifort) or 4 (FTN95)");
        info.compiler = to_int(*f);
    }
    if (auto f = leg.string("xz_precision"))
        info.xz_precision = choose_from<int>(*f, kPrecisionNames);
    const auto legacy_h_coef = leg.num("h_coefficient");
    if (legacy_h_coef) positive(*legacy_h_coef), info.h_coefficient = legacy_h_coef->value;

    // [numerics] (everything but the viscosity value, which needs h and c0)
    const Section num_s = top.sub("numerics");
    if (auto f = num_s.string("kernel"))
        p.kernel = choose<KernelType>(*f);
    if (auto f = num_s.string("integrator"))
        p.integrator = choose<Integrator>(*f);
    if (auto f = num_s.string("density_filter"))
        p.density_filter = choose<DensityFilter>(*f);
    if (auto f = num_s.integer("filter_period")) at_least(*f, 1), p.filter_period = to_int(*f);
    if (auto f = num_s.string("viscosity"))
        p.viscosity = choose<ViscosityModel>(*f);
    if (auto f = num_s.num("xsph_eps")) {
        if (!(f->value >= 0 && f->value <= 1)) fail(*f, "out of range", "a number in [0, 1]");
        p.xsph_eps = f->value;
    }
    if (auto f = num_s.string("tensile_correction"))
        p.tensile_correction = choose_from<int>(*f, kTensileNames);
    if (auto f = num_s.string("boundary"))
        p.boundary = choose<BoundaryType>(*f);
    if (auto f = num_s.integer("dbc_period")) at_least(*f, 1), p.dbc_period = to_int(*f);
    if (auto f = num_s.num("wall_viscosity")) non_negative(*f), p.wall_viscosity = f->value;
    if (auto f = num_s.string("lattice"))
        p.lattice = choose<Lattice>(*f);

    // [gravity]
    const Section grav = top.sub("gravity");
    grav.get("gx", p.gx);
    grav.get("gz", p.gz);

    // [surface_tension]
    if (auto f = top.sub("surface_tension").num("sigma")) non_negative(*f), p.sigma = f->value;
    if (auto f = top.sub("surface_tension").string("delta"))
        p.st_delta = choose<SurfaceTensionDelta>(*f);

    // [fluid]: equation of state
    const Section fluid = top.sub("fluid");
    if (auto f = fluid.num("rho0")) positive(*f), p.rho0 = f->value;
    if (auto f = fluid.num("gamma")) positive(*f), p.gamma = f->value;
    const auto c0 = fluid.num("c0");
    const auto coef = fluid.num("coef");
    const auto h_swl = fluid.num("h_swl");
    if (c0) {
        if (coef || h_swl)
            fail(*c0, "give the sound speed either as c0 or through coef and h_swl, not both",
                 "fluid.c0 alone, or fluid.coef with fluid.h_swl");
        positive(*c0);
        p.h_swl = 0;  // marks "c0 given directly"; coef is then unused
        p.B = tait_B_from_c0(p.rho0, c0->value, p.gamma);
    } else if (coef || h_swl) {
        if (!coef)
            throw InputError(ctx.where(fluid.key_path("coef")), "missing required key",
                             "fluid.coef together with fluid.h_swl (c0 = coef sqrt(g h_swl))", "nothing");
        if (!h_swl)
            throw InputError(ctx.where(fluid.key_path("h_swl")), "missing required key",
                             "fluid.h_swl together with fluid.coef (c0 = coef sqrt(g h_swl))", "nothing");
        positive(*coef);
        positive(*h_swl);
        const double g = std::abs(p.gz);
        if (!(g > 0))
            fail(*coef, "coef and h_swl need gravity (c0 = coef sqrt(|gz| h_swl)) but gravity.gz = 0",
                 "fluid.c0 given directly when gz = 0");
        p.coef = coef->value;
        p.h_swl = h_swl->value;
        p.B = single ? tait_B_from_coef_single(p.coef, p.rho0, g, p.h_swl, p.gamma)
                     : tait_B_from_coef(p.coef, p.rho0, g, p.h_swl, p.gamma);
    } else {
        throw InputError(ctx.where(fluid.key_path("c0")), "missing required key",
                         "fluid.c0 [m/s], or fluid.coef with fluid.h_swl [m]", "nothing");
    }

    // B overflows (c0 = 1e200) or underflows (rho0 = 1e-300) for extreme inputs.
    if (!(std::isfinite(p.B) && p.B > 0))
        fail(c0 ? *c0 : *coef, "gives a Tait constant B that is not a finite number > 0 (B = " + num(p.B) + " Pa)",
             c0 ? "B = rho0 c0^2 / gamma finite and > 0" : "B = coef^2 rho0 |gz| h_swl / gamma finite and > 0");

    // [resolution]
    const Section res = top.sub("resolution");
    const auto dx = res.required_num("dx", "the particle spacing in x [m]");
    positive(dx);
    p.dx = dx.value;
    p.dz = dx.value;
    if (auto f = res.num("dz")) positive(*f), p.dz = f->value;
    const auto h = res.num("h");
    const auto h_coef = res.num("h_coefficient");
    const auto h_over = res.num("h_over_dx");
    const int n_h = int(h.has_value()) + int(h_coef.has_value()) + int(h_over.has_value());
    if (n_h == 0)
        throw InputError(ctx.where(res.key_path("h")), "missing required key",
                         "one of resolution.h [m], resolution.h_coefficient, resolution.h_over_dx",
                         "nothing");
    if (n_h > 1) {
        const auto& f = h ? *h : *h_coef;
        fail(f, "give the smoothing length one way only",
             "exactly one of resolution.h, resolution.h_coefficient, resolution.h_over_dx");
    }
    if (h) positive(*h), p.h = h->value;
    if (h_coef) {
        positive(*h_coef);
        if (legacy_h_coef)
            fail(*legacy_h_coef, "the h coefficient is given twice",
                 "resolution.h_coefficient alone (legacy.h_coefficient only records it beside resolution.h)");
        p.h = h_from_coefficient(h_coef->value, p.dx, p.dz, single);
        info.h_coefficient = h_coef->value;
    }
    if (h_over) positive(*h_over), p.h = h_over->value * p.dx;
    if (!(std::isfinite(p.h) && p.h > 0))  // h_over_dx = 1e300 with dx = 1, dx = 1e-200 (dx^2 = 0)
        fail(h ? *h : h_coef ? *h_coef : *h_over, "gives a smoothing length that is not a finite number > 0 (h = " +
                 num(p.h) + " m)", "h finite and > 0");

    // Viscosity: numerics.alpha, fluid.nu or fluid.mu (at most one).
    const auto alpha = num_s.num("alpha");
    const auto nu = fluid.num("nu");
    const auto mu = fluid.num("mu");
    if (int(alpha.has_value()) + int(nu.has_value()) + int(mu.has_value()) > 1) {
        const auto& f = alpha ? *alpha : *nu;
        fail(f, "give the viscosity one way only",
             "one of numerics.alpha, fluid.nu [m^2/s], fluid.mu [Pa s]");
    }
    std::optional<double> nu_phys;
    if (nu) non_negative(*nu), nu_phys = nu->value;
    if (mu) non_negative(*mu), nu_phys = mu->value / p.rho0;
    if (p.viscosity == ViscosityModel::Artificial) {
        if (alpha) non_negative(*alpha), p.visc_value = alpha->value;
        if (nu_phys) p.visc_value = alpha_from_nu(*nu_phys, p.h, p.c0());
        if (nu_phys && !std::isfinite(p.visc_value))
            fail(nu ? *nu : *mu, "gives an artificial viscosity alpha = 8 nu / (h c0) that is not finite (alpha = " +
                     num(p.visc_value) + ")", "nu (or mu / rho0) with 8 nu / (h c0) finite");
    } else {
        if (alpha)
            fail(*alpha, "alpha is the artificial-viscosity coefficient but numerics.viscosity is \"laminar\"",
                 "fluid.mu [Pa s] or fluid.nu [m^2/s]");
        if (!nu_phys)
            throw InputError(ctx.where(fluid.key_path("mu")), "missing required key",
                             "fluid.mu [Pa s] or fluid.nu [m^2/s] for laminar viscosity", "nothing");
        p.visc_value = *nu_phys;
        if (!std::isfinite(p.visc_value))  // mu / rho0 with rho0 = 1e-300
            fail(nu ? *nu : *mu, "gives a kinematic viscosity that is not finite (nu = " + num(p.visc_value) + ")",
                 "mu / rho0 finite");
    }

    // [domain]
    const Section dom = top.sub("domain");
    const auto lx = dom.required_num("lx", "the box width [m]");
    const auto lz = dom.required_num("lz", "the box height [m]");
    positive(lx);
    positive(lz);
    p.lx = lx.value;
    p.lz = lz.value;
    dom.get("wall_left", spec.wall_left);
    dom.get("wall_right", spec.wall_right);
    dom.get("wall_bottom", spec.wall_bottom);
    dom.get("wall_top", spec.wall_top);
    if (auto f = dom.num("floor_inclination_deg")) {
        if (f->value != 0) fail(*f, "an inclined floor is not supported", "0");
        spec.floor_beta_deg = f->value;
    }
    const Box box{p.lx, p.lz};
    if (auto f = dom.string("geometry"))
        p.geometry = choose<Geometry>(*f);
    const bool axi = p.geometry == Geometry::Axisymmetric;
    dom.get("periodic_z", p.periodic_z);
    if (axi && spec.wall_left)
        throw InputError(ctx.where(dom.key_path("wall_left")),
                         "domain.geometry = \"axisymmetric\" has its symmetry axis at x = 0, not a wall",
                         "domain.wall_left = false", "true (the default)");
    if (axi && p.lattice == Lattice::BodyCentred)
        throw InputError(ctx.where(top.sub("numerics").key_path("lattice")),
                         "domain.geometry = \"axisymmetric\" fills shapes on the lattice ((i + 1/2) dx, k dz)",
                         "numerics.lattice = \"sc\"", "\"bcc\" (the default)");
    if (p.periodic_z && (spec.wall_bottom || spec.wall_top))
        throw InputError(ctx.where(dom.key_path("periodic_z")),
                         "a domain periodic in z has no bottom or top wall",
                         "domain.wall_bottom = false and domain.wall_top = false with periodic_z = true",
                         spec.wall_bottom ? "wall_bottom = true (the default)" : "wall_top = true");
    if (p.periodic_z) p.domain_box = true;  // the box [0, lx] x [0, lz]; z in [0, lz) is the period
    if (auto f = dom.string("axis_pair")) {
        if (!axi)
            throw InputError(ctx.where(dom.key_path("axis_pair")),
                             "domain.axis_pair chooses the pressure pair of the axisymmetric geometry",
                             "no domain.axis_pair, or domain.geometry = \"axisymmetric\"",
                             "domain.geometry = \"planar\" (the default)");
        p.axis_pair = choose<AxisPair>(*f);
        // the rings pair's lattice error at the axis is too large at h = 1.3 dx (the R/dx 10
        // sphere 0.91 of its Laplace pressure, ka 1.2 grows; cases/axisymmetric/README.md)
        if (p.axis_pair == AxisPair::Rings && p.h < 2.0 * p.dx * (1.0 - 1e-9))
            throw InputError(ctx.where(dom.key_path("axis_pair")),
                             "the rings pair needs a smoothing length of at least 2 dx",
                             "resolution.h_over_dx >= 2 with domain.axis_pair = \"rings\"",
                             "h = " + num(p.h / p.dx) + " dx");
    }
    // after [domain]: the key belongs to the rings pair's pressure-consistent CSF
    const Section st = top.sub("surface_tension");
    if (auto f = st.string("rings_curvature")) {
        if (p.axis_pair != AxisPair::Rings || p.st_delta != SurfaceTensionDelta::PressureConsistent)
            throw InputError(ctx.where(st.key_path("rings_curvature")),
                             "surface_tension.rings_curvature chooses the curvature of the rings pair's "
                             "surface rows",
                             "domain.axis_pair = \"rings\" with surface_tension.delta = \"pressure_consistent\"",
                             p.axis_pair != AxisPair::Rings
                                 ? "domain.axis_pair = \"" + to_string(p.axis_pair) + "\""
                                 : "surface_tension.delta = \"" + to_string(p.st_delta) + "\"");
        p.rings_curvature = choose<RingsCurvature>(*f);
    }

    // [time]
    const Section tim = top.sub("time");
    if (auto f = tim.num("tmax")) positive(*f), p.tmax = f->value;
    if (auto f = tim.num("dt")) positive(*f), p.dt = f->value;
    tim.get("variable_dt", p.variable_dt);
    if (auto f = tim.num("cfl")) {
        if (!(f->value > 0 && f->value <= 1)) fail(*f, "out of range", "a number in (0, 1]");
        p.cfl = f->value;
    }
    if (auto f = tim.num("out")) positive(*f), p.out = f->value;
    if (auto f = tim.num("trec_ini")) non_negative(*f), p.trec_ini = f->value;

    // [[obstacle]]
    for (const Section& s : top.array_of_tables("obstacle")) {
        ObstacleSpec o;
        if (auto f = s.string("shape"))
            o.shape = choose_from<int>(*f, kObstacleShapes);
        if (auto f = s.string("kind"))
            o.kind = choose_from<int>(*f, kObstacleKinds);
        if (auto f = s.integer("density")) at_least(*f, 1), o.density = to_int(*f);
        o.r = read_rect(s, box, "obstacle");
        if (auto f = s.num("beta_deg")) {
            if (!(f->value > 0 && f->value < 180)) fail(*f, "out of range", "an angle in (0, 180) degrees");
            o.beta_deg = f->value;
            if (o.beta_deg != 90) {  // the inclined sides shift the top by height / tan(beta)
                const double shift =
                    (o.r.zmax - std::max(o.r.zmin, 0.0)) / std::tan(o.beta_deg * 3.14159265358979323846 / 180);
                if (!(o.r.xmin + std::min(shift, 0.0) >= 0 && o.r.xmax + std::max(shift, 0.0) <= box.lx))
                    fail(*f, "inclined sides reach outside the box (the top shifted by " + num(shift) + " m)",
                         "an angle whose sides stay in 0 <= x <= domain.lx = " + num(box.lx));
            }
        }
        spec.obstacles.push_back(o);
    }

    // [[wall]]
    for (const Section& s : top.array_of_tables("wall")) {
        WallSpec w;
        const auto x = s.required_num("x", "the wall position [m]");
        const auto height = s.required_num("height", "the wall height [m]");
        inside(x, box.lx, "x", "wall");
        if (!(height.value > 0 && height.value <= box.lz))
            fail(height, "out of range", "0 < height <= domain.lz = " + num(box.lz));
        if (p.boundary != BoundaryType::Dynamic)
            fail(x, "a [[wall]] needs dynamic boundaries (as legacy \"Add wall\")",
                 "numerics.boundary = \"dynamic\"");
        w.x = x.value, w.height = height.value;
        spec.walls.push_back(w);
    }

    // [gate]
    if (top.has("gate")) {
        const Section s = top.sub("gate");
        GateSpec g;
        const auto x = s.required_num("x", "the gate position [m]");
        const auto zmin = s.required_num("zmin", "the bottom of the gate [m]");
        const auto zmax = s.required_num("zmax", "the top of the gate [m]");
        inside(x, box.lx, "x", "gate");
        inside(zmin, box.lz, "z", "gate");
        inside(zmax, box.lz, "z", "gate");
        if (!(zmax.value >= zmin.value)) fail(zmax, "empty gate", "zmax >= zmin = " + num(zmin.value));
        g.x = x.value, g.zmin = zmin.value, g.zmax = zmax.value;
        s.get("vx", g.vx);
        s.get("vz", g.vz);
        if (auto f = s.num("t_start")) non_negative(*f), g.t_start = f->value;
        if (auto f = s.string("facing")) g.facing = choose_from<int>(*f, kGateFacings);
        spec.gates.push_back(g);
    }

    // [nozzle] and [breakup]: a jet
    if (top.has("nozzle")) {
        const Section s = top.sub("nozzle");
        NozzleSpec nz;
        const auto x0 = s.required_num("x0", "the orifice centre x [m]");
        const auto z0 = s.required_num("z0", "the orifice centre z [m]");
        const auto d0 = s.required_num("d0", "the orifice width D0 [m]");
        const auto u0 = s.required_num("u0", "the jet speed u0 [m/s]");
        positive(d0);
        if (!(u0.value > 0)) fail(u0, "the jet speed must be positive (the plug moves out of the nozzle)", "u0 > 0");
        nz.x0 = x0.value, nz.z0 = z0.value, nz.d0 = d0.value, nz.u0 = u0.value;
        double len_over_d0 = 15.0;
        if (auto f = s.num("length_over_d0")) positive(*f), len_over_d0 = f->value;
        nz.length_over_d0 = len_over_d0;
        if (auto f = s.string("axis")) {
            const auto dir = choose_from<std::pair<double, double>>(*f, kNozzleAxes);
            nz.ex = dir.first, nz.ez = dir.second;
        }
        s.get("walls", nz.walls);
        if (auto f = s.num("disturbance")) {
            if (!(f->value >= 0 && f->value < 1))
                fail(*f, "the disturbance is a relative amplitude of the plug speed", "0 <= disturbance < 1");
            nz.disturbance = f->value;
        }
        if (auto f = s.num("disturbance_ka")) positive(*f), nz.disturbance_ka = f->value;
        const bool axisymmetric = p.geometry == Geometry::Axisymmetric;
        if (axisymmetric) {
            // A round jet: the nozzle is a pipe around the symmetry axis x = 0.
            if (nz.ex != 0.0)
                throw InputError(s.string("axis")->where, "a round jet runs along the symmetry axis",
                                 "axis = \"down\" or \"up\" with domain.geometry = \"axisymmetric\"",
                                 nz.ex > 0 ? "\"right\"" : "\"left\"");
            if (x0.value != 0.0)
                fail(x0, "a round jet's orifice is centred on the symmetry axis", "x0 = 0 with domain.geometry = \"axisymmetric\"");
        }
        // The nozzle, its walls (half a spacing outside the fluid) and the orifice in the box.
        const double across = 0.5 * nz.d0 + (nz.walls ? std::max(p.dx, p.dz) : 0.0);
        const double back_x = nz.x0 - nz.ex * nz.length(), back_z = nz.z0 - nz.ez * nz.length();
        const double xlo = axisymmetric ? 0.0 : std::min(nz.x0, back_x) - std::abs(nz.ez) * across;
        const double xhi = std::max(nz.x0, back_x) + std::abs(nz.ez) * across;
        const double zlo = std::min(nz.z0, back_z) - std::abs(nz.ex) * across;
        const double zhi = std::max(nz.z0, back_z) + std::abs(nz.ex) * across;
        const double tol = 1e-9 * std::max({box.lx, box.lz, 1.0});
        if (xlo < -tol || xhi > box.lx + tol)
            fail(x0, "nozzle outside the box",
                 "the nozzle (from the orifice " + num(nz.length()) + " m back against the axis, " + num(2 * across) +
                     " m wide with its walls) within x in [0, domain.lx = " + num(box.lx) + "]: x from " + num(xlo) +
                     " to " + num(xhi));
        if (zlo < -tol || zhi > box.lz + tol)
            fail(z0, "nozzle outside the box",
                 "the nozzle (from the orifice " + num(nz.length()) + " m back against the axis, " + num(2 * across) +
                     " m wide with its walls) within z in [0, domain.lz = " + num(box.lz) + "]: z from " + num(zlo) +
                     " to " + num(zhi));
        // The breakup axis runs from the orifice along e to the box edge; it must stay in the
        // box for a jet to be followed (at least 2 d0 of it).
        const double room = nz.ex > 0 ? box.lx - nz.x0 : nz.ex < 0 ? nz.x0 : nz.ez > 0 ? box.lz - nz.z0 : nz.z0;
        if (!(room >= 2 * nz.d0))
            throw InputError(s.string("axis") ? s.string("axis")->where : x0.where,
                 "the breakup axis leaves the domain at once",
                 "at least 2 d0 = " + num(2 * nz.d0) + " m of axis from the orifice to the box edge along the jet",
                 num(room) + " m");
        spec.nozzle = nz;
        p.drive_u = nz.u0;
        p.drive_x0 = nz.x0, p.drive_z0 = nz.z0, p.drive_ex = nz.ex, p.drive_ez = nz.ez;
        // Half a spacing beyond the outer fluid rows, so that every plug particle is driven
        // and the walls (a spacing out) are not.
        p.drive_half_width = 0.5 * nz.d0 + 0.25 * std::max(p.dx, p.dz);
        p.drive_eps = nz.disturbance;
        p.drive_omega = nz.disturbance > 0 ? nz.disturbance_omega() : 0.0;
        p.domain_box = true;

        BreakupSpec bk;
        const Section b = top.sub("breakup");
        if (auto f = b.num("link_over_h")) positive(*f), bk.link_over_h = f->value;
        if (auto f = b.num("band_over_d0")) positive(*f), bk.band_over_d0 = f->value;
        if (auto f = b.num("check_every")) non_negative(*f), bk.check_every = f->value;
        if (auto f = b.num("stop_after")) non_negative(*f), bk.stop_after = f->value;
        if (auto f = b.num("remove_drops_below_h")) non_negative(*f), bk.remove_drops_below_h = f->value;
        spec.breakup = bk;
    } else if (top.has("breakup")) {
        throw InputError(ctx.where("breakup"), "[breakup] needs a jet",
                         "a [nozzle] table (the breakup axis starts at its orifice)", "no [nozzle]");
    }

    // Fluid regions
    for (const Section& s : fluid.array_of_tables("block")) {
        FluidBlock b;
        b.r = read_rect(s, box, "fluid region");
        s.get("u0", b.u0);
        s.get("w0", b.w0);
        spec.fluid_blocks.push_back(b);
    }
    for (const Section& s : fluid.array_of_tables("disc")) {
        FluidDisc d;
        const auto xc = s.required_num("xc", "the centre x [m]");
        const auto zc = s.required_num("zc", "the centre z [m]");
        const auto r = s.required_num("radius", "the radius [m]");
        positive(r);
        // axisymmetric: a disc centred on the axis is a sphere (the generator fills x >= 0);
        // one that crosses the axis elsewhere would be a self-intersecting ring: refused
        const bool sphere = axi && xc.value == 0.0;
        if (axi && !sphere && xc.value - r.value < 0.0)
            fail(xc, "an axisymmetric disc reaches x < 0 (the other side of the axis)",
                 "xc = 0 (a sphere) or xc >= radius = " + num(r.value) + " (a torus)");
        // a sphere takes x in [0, R] only: checked as a disc in a box twice as wide
        const Box dbox = sphere ? Box{2 * box.lx, box.lz} : box;
        centred_inside(sphere ? Field<double>{box.lx, xc.where} : xc, zc, r, r.value, dbox, "fluid disc");
        d.xc = xc.value, d.zc = zc.value, d.radius = r.value;
        s.get("u0", d.u0);
        s.get("w0", d.w0);
        if (auto f = s.string("lattice"))
            d.rings = choose_from<bool>(*f, kDiscLattices);
        if (auto f = s.num("elongation")) {
            if (!(f->value > -0.5 && f->value < 0.5)) fail(*f, "out of range", "a number in (-0.5, 0.5)");
            d.elongation = f->value;
            const double a = r.value * (1 + std::abs(f->value));
            centred_inside(sphere ? Field<double>{box.lx, xc.where} : xc, zc, r, a, dbox, "fluid disc (stretched)");
        }
        spec.fluid_discs.push_back(d);
    }
    for (const Section& s : fluid.array_of_tables("cylinder")) {
        // axisymmetric only: r(z) = radius (1 + eps cos(2 pi (z - zmin) / wavelength))
        FluidCylinder c;
        const auto r = s.required_num("radius", "the radius a [m]");
        positive(r);
        if (!axi)
            fail(r, "[[fluid.cylinder]] is a liquid cylinder about the axis x = 0",
                 "domain.geometry = \"axisymmetric\"");
        c.radius = r.value;
        c.zmin = 0.0, c.zmax = box.lz;
        if (auto f = s.num("zmin")) inside(*f, box.lz, "z", "fluid cylinder"), c.zmin = f->value;
        if (auto f = s.num("zmax")) inside(*f, box.lz, "z", "fluid cylinder"), c.zmax = f->value;
        if (!(c.zmax > c.zmin)) fail(r, "empty cylinder", "zmax > zmin = " + num(c.zmin));
        if (auto f = s.num("eps")) {
            if (!(f->value > -0.5 && f->value < 0.5)) fail(*f, "out of range", "a number in (-0.5, 0.5)");
            c.eps = f->value;
        }
        if (auto f = s.num("wavelength")) positive(*f), c.wavelength = f->value;
        else if (c.eps != 0.0)
            throw InputError(ctx.where(s.key_path("wavelength")), "missing required key",
                             "fluid.cylinder.wavelength [m] with eps != 0", "nothing");
        if (!(c.radius * (1 + std::abs(c.eps)) <= box.lx))
            fail(r, "fluid cylinder outside the box", "radius (1 + |eps|) <= domain.lx = " + num(box.lx));
        spec.fluid_cylinders.push_back(c);
    }
    for (const Section& s : fluid.array_of_tables("square")) {
        FluidSquare q;
        const auto xc = s.required_num("xc", "the centre x [m]");
        const auto zc = s.required_num("zc", "the centre z [m]");
        const auto side = s.required_num("side", "the side length [m]");
        positive(side);
        centred_inside(xc, zc, side, side.value / 2, box, "fluid square");
        q.xc = xc.value, q.zc = zc.value, q.side = side.value;
        s.get("u0", q.u0);
        s.get("w0", q.w0);
        spec.fluid_squares.push_back(q);
    }
    if (spec.legacy_fill && p.h_swl <= 0)
        throw InputError(ctx.where(fluid.key_path("h_swl")), "missing required key",
                         "fluid.coef and fluid.h_swl with legacy.fill = true (the legacy fill stops at h_swl)",
                         "nothing");
    if (spec.fluid_blocks.empty() && spec.fluid_discs.empty() && spec.fluid_squares.empty() &&
        spec.fluid_cylinders.empty() && !spec.nozzle)
        throw InputError(ctx.file + ": fluid", "no fluid in the case",
                         "at least one [[fluid.block]], [[fluid.disc]], [[fluid.square]] or [[fluid.cylinder]], or a [nozzle]",
                         "none");

    // [output]
    const Section out = top.sub("output");
    OutputSpec& o = spec.output;
    if (auto f = out.string("format"))
        o.format = choose<OutputFormat>(*f);
    if (auto f = out.integer("checkpoint_every_steps"))
        at_least(*f, 0), o.checkpoint_every_steps = static_cast<long>(f->value);
    if (auto f = out.num("checkpoint_every_minutes")) non_negative(*f), o.checkpoint_every_minutes = f->value;
    out.get("remove_out_of_domain", o.remove_out_of_domain);
    if (auto f = out.num("rho_min_factor")) {
        if (!(f->value >= 0 && f->value < 1)) fail(*f, "out of range", "a number in [0, 1)");
        o.rho_min_factor = f->value;
    }
    if (auto f = out.num("rho_max_factor")) {
        if (!(f->value > 1)) fail(*f, "out of range", "a number > 1");
        o.rho_max_factor = f->value;
    }
    if (auto f = out.num("dt_min")) non_negative(*f), o.dt_min = f->value;
    if (auto f = out.integer("revolution_sectors")) {
        if (f->value < 0 || f->value > kMaxRevolutionSectors)
            fail(*f, "out of range",
                 "an integer in [0, " + std::to_string(kMaxRevolutionSectors) + "] (0 = off)");
        if (!axi)
            fail(*f, "only an axisymmetric case has rings to revolve about the axis",
                 "no output.revolution_sectors with domain.geometry = \"planar\" (the default), "
                 "or domain.geometry = \"axisymmetric\"");
        o.revolution_sectors = static_cast<int>(f->value);
    }

    return spec;
}

}  // namespace

std::vector<std::string> modern_case_keys() {
    std::vector<std::string> out;
    for (const auto& k : kKeys) out.emplace_back(k.path);
    return out;
}

CaseSpec parse_modern_case(std::string_view text, const std::string& source_name,
                           const std::vector<std::string>& overrides) {
    Ctx ctx{source_name, {}};
    toml::table root;
    if (const auto bad = bad_table_header(text)) {
        const std::size_t pos = *bad + (text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0);
        std::size_t line = 1, start = 0;
        for (std::size_t k = 0; k < pos; ++k)
            if (text[k] == '\n') ++line, start = k + 1;
        const unsigned char c = static_cast<unsigned char>(text[pos]);
        std::string found = "'" + std::string(1, static_cast<char>(c)) + "'";
        if (c == '\n' || c == '\r') found = "the end of the line";
        else if (c < 0x20 || c >= 0x7f) found = "byte " + std::to_string(c);
        throw InputError(source_name + ":" + std::to_string(line) + ":" + std::to_string(pos - start + 1),
                         "TOML syntax error: a table header without a key",
                         "a bare key (letters, digits, _ or -) or a quoted key after '[' or '[['", found);
    }
    const std::string toml_text = ascii_for_toml(text);
    if (const auto bad = toml_assertion_hazard(toml_text)) {
        std::size_t line = 1, start = 0;
        for (std::size_t k = 0; k < *bad; ++k)
            if (toml_text[k] == '\n') ++line, start = k + 1;
        throw InputError(source_name + ":" + std::to_string(line) + ":" + std::to_string(*bad - start + 1),
                         "TOML syntax error", toml_text[*bad] == '}' ? "a value or ']'" : "a valid value",
                         toml_text[*bad] == '}' ? "'}' in an array" : "a date followed by a space and one digit");
    }
    try {
        root = toml::parse(toml_text, source_name);
    } catch (const toml::parse_error& e) {
        const auto& b = e.source().begin;
        throw InputError(source_name + ":" + std::to_string(b.line) + ":" + std::to_string(b.column),
                         "TOML syntax error: " + std::string(e.description()));
    }
    for (const auto& o : overrides) apply_override(ctx, root, o);
    check_keys(ctx, root, "", "");
    return build(ctx, root);
}

CaseSpec read_modern_case(const std::filesystem::path& path,
                          const std::vector<std::string>& overrides) {
    if (std::filesystem::is_directory(path))
        throw InputError(path.string(), "cannot open the case file", "a TOML file", "a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(path.string(), "cannot open the case file", "a readable TOML file",
                         std::filesystem::exists(path) ? "a file that cannot be read" : "no such file");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_modern_case(text.str(), path.string(), overrides);
}

// ---------------------------------------------------------------------------------------
// Writer
// ---------------------------------------------------------------------------------------

namespace {

// The c0 whose B = rho0 c0^2 / gamma is exactly spec's B, when such a double exists
// near sqrt(gamma B / rho0) (so that a round trip reproduces B to the bit).
double c0_for_B(const SimParams& p) {
    const double guess = std::sqrt(p.gamma * p.B / p.rho0);
    if (!std::isfinite(guess) || guess <= 0) return guess;
    double lo = guess, hi = guess;
    for (int i = 0; i < 8; ++i) {
        if (tait_B_from_c0(p.rho0, lo, p.gamma) == p.B) return lo;
        if (tait_B_from_c0(p.rho0, hi, p.gamma) == p.B) return hi;
        lo = std::nextafter(lo, 0.0);
        hi = std::nextafter(hi, INFINITY);
    }
    return guess;
}

std::string line(const std::string& key, const std::string& value, const std::string& comment) {
    std::string s = key + " = " + value;
    if (!comment.empty()) {
        if (s.size() < 32) s.resize(32, ' ');
        else s += ' ';
        s += "# " + comment;
    }
    return s + "\n";
}

std::string str(std::string_view s) { return dquote(s); }
std::string boolean(bool b) { return b ? "true" : "false"; }


std::string sanitize_comment(std::string s) {
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    return s;
}

}  // namespace

std::string write_modern_case(const CaseSpec& spec) {
    const SimParams& p = spec.params;
    const double c0 = p.c0();
    const LegacyRunInfo& info = spec.legacy;
    const LegacyRunInfo info_default;
    // Derived numbers made in single precision (a legacy case): say so, so that they read
    // back to the bit.
    const double g = std::abs(p.gz);
    const bool b_single = p.h_swl > 0 &&
                          tait_B_from_coef(p.coef, p.rho0, g, p.h_swl, p.gamma) != p.B &&
                          tait_B_from_coef_single(p.coef, p.rho0, g, p.h_swl, p.gamma) == p.B;
    const bool h_single = info.h_coefficient > 0 &&
                          h_from_coefficient(info.h_coefficient, p.dx, p.dz, false) != p.h &&
                          h_from_coefficient(info.h_coefficient, p.dx, p.dz, true) == p.h;
    const bool single = b_single || h_single;
    const bool h_by_coefficient =
        info.h_coefficient > 0 && h_from_coefficient(info.h_coefficient, p.dx, p.dz, single) == p.h;
    const bool legacy_section =
        spec.legacy_fill || single || (info.h_coefficient > 0 && !h_by_coefficient) ||
        info.detail_out != info_default.detail_out || info.detail_start != info_default.detail_start ||
        info.detail_end != info_default.detail_end || info.vorticity != info_default.vorticity ||
        info.compiler != info_default.compiler || info.xz_precision != info_default.xz_precision;
    std::string s;
    s += "# sphjet case file (modern format, reference: cases/CASE_FORMAT.md).\n";
    if (!spec.source.empty()) s += "# Written from: " + sanitize_comment(spec.source) + "\n";
    s += "# Units: SI (m, s, kg). Coordinates: x horizontal, z vertical, box [0, lx] x [0, lz].\n\n";
    s += line("format_version", "1", "");

    s += "\n[numerics]\n";
    s += line("kernel", str(to_string(p.kernel)), choices<KernelType>());
    s += line("integrator", str(to_string(p.integrator)), choices<Integrator>());
    s += line("density_filter", str(to_string(p.density_filter)), choices<DensityFilter>());
    s += line("filter_period", std::to_string(p.filter_period), "steps between density filters");
    s += line("viscosity", str(to_string(p.viscosity)), choices<ViscosityModel>());
    if (p.viscosity == ViscosityModel::Artificial) {
        const double nu_eq = p.visc_value * p.h * c0 / 8.0;
        s += line("alpha", num(p.visc_value),
                  "artificial viscosity; same as nu = alpha h c0 / 8 = " + num(nu_eq) + " m^2/s");
    }
    s += line("xsph_eps", num(p.xsph_eps), "XSPH velocity correction, 0 = off");
    s += line("tensile_correction", str(name_in(kTensileNames, p.tensile_correction)),
              "auto (legacy: on for gaussian, cubic_spline) | on | off");
    s += line("boundary", str(to_string(p.boundary)), choices<BoundaryType>() + " (repulsive: Monaghan-Kos/Rogers)");
    s += line("dbc_period", std::to_string(p.dbc_period), "steps between dynamic-boundary density updates");
    s += line("wall_viscosity", num(p.wall_viscosity), "m^2/s, repulsive walls only");
    s += line("lattice", str(to_string(p.lattice)), choices<Lattice>());

    s += "\n[fluid]\n";
    s += line("rho0", num(p.rho0), "reference density [kg/m^3]");
    s += line("gamma", num(p.gamma), "Tait exponent");
    if (p.h_swl > 0) {
        s += line("coef", num(p.coef), "c0 = coef sqrt(|gz| h_swl) = " + num(c0) + " m/s");
        s += line("h_swl", num(p.h_swl), "still-water depth [m]; B = " + num(p.B) + " Pa");
    } else {
        s += line("c0", num(c0_for_B(p)), "sound speed at rest [m/s]; B = rho0 c0^2 / gamma = " + num(p.B) + " Pa");
    }
    if (p.viscosity == ViscosityModel::Laminar)
        s += line("nu", num(p.visc_value), "kinematic viscosity [m^2/s] (mu = " + num(p.visc_value * p.rho0) + " Pa s)");
    for (const auto& b : spec.fluid_blocks) {
        s += "\n[[fluid.block]]                  # rectangle filled on the lattice\n";
        s += line("xmin", num(b.r.xmin), "m");
        s += line("xmax", num(b.r.xmax), "m");
        s += line("zmin", num(b.r.zmin), "m");
        s += line("zmax", num(b.r.zmax), "m");
        s += line("u0", num(b.u0), "initial velocity [m/s]");
        s += line("w0", num(b.w0), "m/s");
    }
    for (const auto& d : spec.fluid_discs) {
        s += "\n[[fluid.disc]]\n";
        s += line("xc", num(d.xc), "centre [m]");
        s += line("zc", num(d.zc), "m");
        s += line("radius", num(d.radius), "m");
        s += line("lattice", str(name_in(kDiscLattices, d.rings)),
                  "case (numerics.lattice points inside) | rings (concentric rings, smooth edge)");
        s += line("elongation", num(d.elongation),
                  "e: stretched to semi-axes R(1+e) (x), R/(1+e) (z), area kept; 0 = round");
        s += line("u0", num(d.u0), "initial velocity [m/s]");
        s += line("w0", num(d.w0), "m/s");
    }
    for (const auto& c : spec.fluid_cylinders) {
        s += "\n[[fluid.cylinder]]               # axisymmetric: r(z) = a (1 + eps cos(2 pi (z - zmin) / wavelength))\n";
        s += line("radius", num(c.radius), "a [m]");
        s += line("eps", num(c.eps), "relative amplitude of the perturbation");
        if (c.wavelength > 0) s += line("wavelength", num(c.wavelength), "m");
        s += line("zmin", num(c.zmin), "m");
        s += line("zmax", num(c.zmax), "m");
    }
    for (const auto& q : spec.fluid_squares) {
        s += "\n[[fluid.square]]\n";
        s += line("xc", num(q.xc), "centre [m]");
        s += line("zc", num(q.zc), "m");
        s += line("side", num(q.side), "m");
        s += line("u0", num(q.u0), "initial velocity [m/s]");
        s += line("w0", num(q.w0), "m/s");
    }

    s += "\n[surface_tension]\n";
    s += line("sigma", num(p.sigma), "N/m, CSF (Morris 2000); 0 = off");
    s += line("delta", str(to_string(p.st_delta)),
              choices<SurfaceTensionDelta>() +
                  " (pressure_consistent: free surface, right Laplace jump; colour_gradient: paper "
                  "eq 24 as printed, about 0.13 of sigma at a free surface)");
    if (p.axis_pair == AxisPair::Rings && p.st_delta == SurfaceTensionDelta::PressureConsistent)
        s += line("rings_curvature", str(to_string(p.rings_curvature)),
                  choices<RingsCurvature>() +
                      " (neighbour_mean: holds a drop's pole; own: longer round jets, pole lost)");

    s += "\n[gravity]\n";
    s += line("gx", num(p.gx), "m/s^2");
    s += line("gz", num(p.gz), "m/s^2");

    s += "\n[domain]\n";
    s += line("lx", num(p.lx), "box width [m]");
    s += line("lz", num(p.lz), "box height [m]");
    s += line("wall_left", boolean(spec.wall_left), "");
    s += line("wall_right", boolean(spec.wall_right), "");
    s += line("wall_bottom", boolean(spec.wall_bottom), "");
    s += line("wall_top", boolean(spec.wall_top), "");
    s += line("floor_inclination_deg", num(spec.floor_beta_deg), "only 0 is supported");
    s += line("geometry", str(to_string(p.geometry)), choices<Geometry>() + " (axisymmetric: x = r >= 0, axis x = 0)");
    s += line("periodic_z", boolean(p.periodic_z), "periodic in z with period lz");
    if (p.geometry == Geometry::Axisymmetric)
        s += line("axis_pair", str(to_string(p.axis_pair)), choices<AxisPair>() + " (cases/axisymmetric/README.md)");

    s += "\n[resolution]\n";
    s += line("dx", num(p.dx), "particle spacing [m]");
    s += line("dz", num(p.dz), "m");
    const double diag = std::sqrt(p.dx * p.dx + p.dz * p.dz);
    if (h_by_coefficient)
        s += line("h_coefficient", num(info.h_coefficient),
                  "h = coefficient sqrt(dx^2 + dz^2) = " + num(p.h) + " m = " + num(p.h / p.dx) + " dx");
    else
        s += line("h", num(p.h), "smoothing length [m] = " + num(p.h / p.dx) + " dx = " +
                                     num(p.h / diag) + " sqrt(dx^2 + dz^2)");

    s += "\n[time]\n";
    s += line("tmax", num(p.tmax), "end time [s]");
    s += line("dt", num(p.dt), "initial (or fixed) step [s]");
    s += line("variable_dt", boolean(p.variable_dt), "");
    s += line("cfl", num(p.cfl), "Courant number");
    s += line("out", num(p.out), "output interval [s]");
    s += line("trec_ini", num(p.trec_ini), "time of the first output [s]");

    for (const auto& o : spec.obstacles) {
        s += "\n[[obstacle]]\n";
        s += line("shape", str(name_in(kObstacleShapes, o.shape)), "");
        s += line("kind", str(name_in(kObstacleKinds, o.kind)), choices_in(kObstacleKinds) + " (walls: outline only)");
        s += line("density", std::to_string(o.density), "boundary points every dx / density");
        s += line("xmin", num(o.r.xmin), "m");
        s += line("xmax", num(o.r.xmax), "m");
        s += line("zmin", num(o.r.zmin), "m");
        s += line("zmax", num(o.r.zmax), "m");
        s += line("beta_deg", num(o.beta_deg), "inclination of the side walls");
    }

    for (const auto& g : spec.gates) {
        s += "\n[gate]                          # legacy \"Add gate\": a column of moving boundary particles\n";
        s += line("x", num(g.x), "position [m]");
        s += line("zmin", num(g.zmin), "bottom [m]");
        s += line("zmax", num(g.zmax), "top [m]");
        s += line("vx", num(g.vx), "velocity from t_start [m/s]");
        s += line("vz", num(g.vz), "m/s; each particle stops at the top of the initial particles + 0.1 h");
        s += line("t_start", num(g.t_start), "s");
        s += line("facing", str(name_in(kGateFacings, g.facing)),
                  "side of the fluid (repulsive walls): " + choices_in(kGateFacings));
    }

    if (spec.nozzle) {
        const NozzleSpec& nz = *spec.nozzle;
        s += "\n[nozzle]                        # a driven nozzle: the fluid in it moves out at u0 as a plug\n";
        s += line("x0", num(nz.x0), "orifice centre [m]");
        s += line("z0", num(nz.z0), "m");
        s += line("axis", str(name_in(kNozzleAxes, std::pair{nz.ex, nz.ez})),
                  "jet direction: " + choices_in(kNozzleAxes));
        s += line("d0", num(nz.d0), "orifice width D0 [m]");
        s += line("length_over_d0", num(nz.length_over_d0), "nozzle length upstream of the orifice / D0");
        s += line("u0", num(nz.u0), "jet speed [m/s]");
        s += line("walls", boolean(nz.walls), "boundary lines along the nozzle sides");
        if (nz.disturbance > 0) {
            s += line("disturbance", num(nz.disturbance), "plug speed u0 (1 + disturbance sin(omega t))");
            s += line("disturbance_ka", num(nz.disturbance_ka), "omega = u0 ka / (d0 / 2)");
        }
    }
    if (spec.breakup) {
        const BreakupSpec& b = *spec.breakup;
        s += "\n[breakup]                       # breakup detection while the run goes\n";
        s += line("link_over_h", num(b.link_over_h), "broken where two particles along the axis are more than this x h apart");
        s += line("band_over_d0", num(b.band_over_d0), "particles within this x D0 of the axis count");
        s += line("check_every", num(b.check_every), "s between checks; 0 = every output");
        if (b.stop_after >= 0) s += line("stop_after", num(b.stop_after), "s after the first breakup the run stops");
        if (b.remove_drops_below_h > 0)
            s += line("remove_drops_below_h", num(b.remove_drops_below_h),
                      "drops with d_eq below this x h are removed at the checks");
    }

    for (const auto& w : spec.walls) {
        s += "\n[[wall]]                        # legacy \"Add wall\": two layers of boundary particles\n";
        s += line("x", num(w.x), "position [m]");
        s += line("height", num(w.height), "from the floor [m]");
    }

    if (legacy_section) {
        s += "\n[legacy]                        # carried over from a legacy SPHysics case file\n";
        s += line("fill", boolean(spec.legacy_fill), "fill blocks as SPHYSICSgen_2D (from the floor, up to h_swl)");
        s += line("single_precision", boolean(single), "derive B and h in single precision as SPHYSICSgen_2D");
        if (info.h_coefficient > 0 && !h_by_coefficient)
            s += line("h_coefficient", num(info.h_coefficient), "recorded only; resolution.h rules");
        s += line("detail_out", num(info.detail_out), "detailed-recording interval [s] (INDAT only)");
        s += line("detail_start", num(info.detail_start), "s");
        s += line("detail_end", num(info.detail_end), "s");
        s += line("vorticity", boolean(info.vorticity != 0), "vorticity printing (INDAT only)");
        s += line("compiler", std::to_string(info.compiler), "1 gfortran, 2 ifort, 3 win_ifort, 4 FTN95 (INDAT only)");
        s += line("xz_precision", str(name_in(kPrecisionNames, info.xz_precision)), "legacy solver's x/z precision");
    }

    s += "\n[output]\n";
    s += line("format", str(to_string(spec.output.format)), choices<OutputFormat>());
    s += line("checkpoint_every_steps", std::to_string(spec.output.checkpoint_every_steps), "0 = off");
    s += line("checkpoint_every_minutes", num(spec.output.checkpoint_every_minutes), "wall-clock minutes, 0 = off");
    s += line("remove_out_of_domain", boolean(spec.output.remove_out_of_domain),
              "false = stop when a particle leaves");
    s += line("rho_min_factor", num(spec.output.rho_min_factor), "stop if rho < factor rho0");
    s += line("rho_max_factor", num(spec.output.rho_max_factor), "stop if rho > factor rho0");
    s += line("dt_min", num(spec.output.dt_min), "stop if dt falls below [s]");
    if (spec.output.revolution_sectors > 0)
        s += line("revolution_sectors", std::to_string(spec.output.revolution_sectors),
                  "HDF5 snapshots also hold the rings revolved into this many copies");
    return s;
}

}  // namespace sphjet
