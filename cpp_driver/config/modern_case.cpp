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

#include "config/case_params.hpp"
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

// The schema: every key the format knows (config/case_params.hpp). Sections are the
// prefixes; "name[]" is an array of tables ([[name]] in the file).

const Param* find_key(std::string_view pattern) { return find_param(pattern); }

const std::set<std::string>& sections() {
    static const std::set<std::string> s = [] {
        std::set<std::string> out;
        for (const auto& k : case_params()) {
            std::string_view p = k.key;
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
    for (const auto& k : case_params()) {
        std::string_view p = k.key;
        if (p.empty()) continue;
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
    Section(const Ctx& ctx, const toml::table* t, std::string path, std::string pattern)
        : ctx_(ctx), t_(t), path_(std::move(path)), pattern_(std::move(pattern)) {}

    [[nodiscard]] const std::string& path() const { return path_; }
    // The section's name in the schema: "fluid.block[]" for "fluid.block[2]".
    [[nodiscard]] const std::string& pattern() const { return pattern_; }
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

    [[nodiscard]] std::string where(std::string_view key) const { return ctx_.where(key_path(key)); }

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
            out.emplace_back(ctx_, arr->get(i)->as_table(), key_path(key) + "[" + std::to_string(i) + "]",
                             join(pattern_, key) + "[]");
        return out;
    }
    [[nodiscard]] Section sub(std::string_view key) const {
        const toml::node* n = node(key);
        return {ctx_, n != nullptr ? n->as_table() : nullptr, key_path(key), join(pattern_, key)};
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
    std::string pattern_;
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

// The jet direction (ex, ez) of each of nozzle.axis's choices, by their numbers.
constexpr std::pair<double, double> kNozzleDirections[] = {{0.0, -1.0}, {0.0, 1.0}, {-1.0, 0.0}, {1.0, 0.0}};

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
        for (const auto& k : case_params()) {
            const std::string p(k.key);
            if (p.empty()) continue;
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
//    marzer/tomlplusplus issues 190 and 295, fixed by pull 305.

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
            for (const auto& k : case_params()) {
                if (k.key.empty()) continue;
                std::string p(k.key);
                p.erase(std::remove(p.begin(), p.end(), '['), p.end());
                p.erase(std::remove(p.begin(), p.end(), ']'), p.end());
                if (p == pattern) {
                    problem += " (elements of an array of tables are named with an index, e.g. '" +
                               std::string(k.key).replace(std::string(k.key).find("[]"), 2, "[0]") +
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
// "a number in [0, 1]", "an integer >= 1": what a range allows.
std::string range_expected(const Range& g, bool integer) {
    const std::string text = range_text(g);
    const std::string a = integer ? "an integer " : "a number ";
    return g.kind == Range::Kind::Between && g.hi < kNoLimit ? a + "in " + text : a + text;
}

template <class T>
void check_range(const Field<T>& f, const Range& g) {
    const double v = static_cast<double>(f.value);
    const bool integer = std::is_integral_v<T>;
    switch (g.kind) {
        case Range::Kind::Any: return;
        case Range::Kind::Positive:
            if (!(v > 0)) fail(f, "must be positive", range_expected(g, integer));
            return;
        case Range::Kind::NonNegative:
            if (!(v >= 0)) fail(f, "must not be negative", range_expected(g, integer));
            return;
        case Range::Kind::Between: {
            const bool above = g.lo_open ? v > g.lo : v >= g.lo;
            const bool below = g.hi >= kNoLimit || (g.hi_open ? v < g.hi : v <= g.hi);
            if (!(above && below)) fail(f, "out of range", range_expected(g, integer));
            return;
        }
    }
}

// Reads the keys of section s whose member lives in owner (a struct of type tag), as their
// rows say: type, range or choices, required; rows read by hand are left to the caller.
void read_members(const Section& s, void* owner, const void* tag) {
    for (const Param& r : case_params()) {
        if (r.key.empty() || section_of(r.key) != s.pattern() || r.member.owner != tag || (r.hand & kHandRead))
            continue;
        const std::string_view key = leaf_of(r.key);
        const Member& m = r.member;
        if (r.required && !s.has(key)) {
            std::string expected(r.doc);
            if (!r.unit.empty()) expected += " [" + std::string(r.unit) + "]";
            throw InputError(s.where(key), "missing required key", expected, "nothing");
        }
        switch (r.type) {
            case KeyType::Float:
                if (auto f = s.num(key)) check_range(*f, r.range), m.set_f(owner, f->value);
                break;
            case KeyType::Int:
                if (auto f = s.integer(key)) {
                    check_range(*f, r.range);
                    if (f->value > m.max_i)
                        fail(*f, "out of range", "an integer <= " + std::to_string(m.max_i));
                    m.set_i(owner, f->value);
                }
                break;
            case KeyType::Bool:
                if (auto f = s.boolean(key)) m.set_i(owner, f->value ? 1 : 0);
                break;
            case KeyType::String:
                if (auto f = s.string(key)) m.set_i(owner, choose_from<std::int64_t>(*f, r.choices));
                break;
        }
    }
}

template <class S>
void read_members(const Section& s, S& owner) {
    read_members(s, &owner, &owner_tag<S>);
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

// [legacy]: read first, single_precision changes how B and h are derived.
struct LegacyRead {
    bool single = false;
    std::optional<Field<double>> h_coef;
};

LegacyRead read_legacy(const Section& top, CaseSpec& spec) {
    const Section leg = top.sub("legacy");
    read_members(leg, spec);
    read_members(leg, spec.legacy);
    LegacyRead out;
    leg.get("single_precision", out.single);
    out.h_coef = leg.num("h_coefficient");
    if (out.h_coef) positive(*out.h_coef), spec.legacy.h_coefficient = out.h_coef->value;
    return out;
}

// [fluid]: the equation of state, B from c0 or from coef and h_swl.
void read_sound_speed(const Ctx& ctx, const Section& fluid, SimParams& p, bool single) {
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
}

// [resolution]: dx, dz and h given one of three ways.
void read_resolution(const Ctx& ctx, const Section& top, SimParams& p, LegacyRunInfo& info, const LegacyRead& leg) {
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
        if (leg.h_coef)
            fail(*leg.h_coef, "the h coefficient is given twice",
                 "resolution.h_coefficient alone (legacy.h_coefficient only records it beside resolution.h)");
        p.h = h_from_coefficient(h_coef->value, p.dx, p.dz, leg.single);
        info.h_coefficient = h_coef->value;
    }
    if (h_over) positive(*h_over), p.h = h_over->value * p.dx;
    if (!(std::isfinite(p.h) && p.h > 0))  // h_over_dx = 1e300 with dx = 1, dx = 1e-200 (dx^2 = 0)
        fail(h ? *h : h_coef ? *h_coef : *h_over, "gives a smoothing length that is not a finite number > 0 (h = " +
                 num(p.h) + " m)", "h finite and > 0");
}

// Viscosity: numerics.alpha, fluid.nu or fluid.mu (at most one); needs h and c0.
void read_viscosity(const Ctx& ctx, const Section& num_s, const Section& fluid, SimParams& p) {
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
}

// [domain], and the surface-tension key that depends on its pair.
void read_domain(const Ctx& ctx, const Section& top, CaseSpec& spec) {
    SimParams& p = spec.params;
    const Section dom = top.sub("domain");
    read_members(dom, p);
    read_members(dom, spec);
    if (auto f = dom.num("floor_inclination_deg")) {
        if (f->value != 0) fail(*f, "an inclined floor is not supported", "0");
        spec.floor_beta_deg = f->value;
    }
    const bool axi = p.geometry == Geometry::Axisymmetric;
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
    const Param& pair_row = *find_param("domain.axis_pair");
    if (auto f = dom.string("axis_pair")) {
        if (!axi)
            throw InputError(ctx.where(dom.key_path("axis_pair")),
                             "domain.axis_pair chooses the pressure pair of the axisymmetric geometry",
                             "no domain.axis_pair, or domain.geometry = \"axisymmetric\"",
                             "domain.geometry = \"planar\" (the default)");
        p.axis_pair = static_cast<AxisPair>(choose_from<std::int64_t>(*f, pair_row.choices));
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
        p.rings_curvature = static_cast<RingsCurvature>(
            choose_from<std::int64_t>(*f, find_param("surface_tension.rings_curvature")->choices));
    }
}

// [[obstacle]], [[wall]] and [gate]: boundary particles in the box.
void read_structures(const Section& top, CaseSpec& spec, const Box& box) {
    for (const Section& s : top.array_of_tables("obstacle")) {
        ObstacleSpec o;
        read_members(s, o);
        o.r = read_rect(s, box, "obstacle");
        if (auto f = s.num("beta_deg"); f && o.beta_deg != 90) {
            // the inclined sides shift the top by height / tan(beta)
            const double shift =
                (o.r.zmax - std::max(o.r.zmin, 0.0)) / std::tan(o.beta_deg * 3.14159265358979323846 / 180);
            if (!(o.r.xmin + std::min(shift, 0.0) >= 0 && o.r.xmax + std::max(shift, 0.0) <= box.lx))
                fail(*f, "inclined sides reach outside the box (the top shifted by " + num(shift) + " m)",
                     "an angle whose sides stay in 0 <= x <= domain.lx = " + num(box.lx));
        }
        spec.obstacles.push_back(o);
    }

    for (const Section& s : top.array_of_tables("wall")) {
        WallSpec w;
        const auto x = s.required_num("x", "the wall position [m]");
        const auto height = s.required_num("height", "the wall height [m]");
        inside(x, box.lx, "x", "wall");
        if (!(height.value > 0 && height.value <= box.lz))
            fail(height, "out of range", "0 < height <= domain.lz = " + num(box.lz));
        if (spec.params.boundary != BoundaryType::Dynamic)
            fail(x, "a [[wall]] needs dynamic boundaries (as legacy \"Add wall\")",
                 "numerics.boundary = \"dynamic\"");
        w.x = x.value, w.height = height.value;
        spec.walls.push_back(w);
    }

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
        read_members(s, g);
        spec.gates.push_back(g);
    }
}

// [nozzle] and [breakup]: a jet.
void read_jet(const Ctx& ctx, const Section& top, CaseSpec& spec, const Box& box) {
    SimParams& p = spec.params;
    if (!top.has("nozzle")) {
        if (top.has("breakup"))
            throw InputError(ctx.where("breakup"), "[breakup] needs a jet",
                             "a [nozzle] table (the breakup axis starts at its orifice)", "no [nozzle]");
        return;
    }
    const Section s = top.sub("nozzle");
    NozzleSpec nz;
    const auto x0 = s.required_num("x0", "the orifice centre x [m]");
    const auto z0 = s.required_num("z0", "the orifice centre z [m]");
    const auto d0 = s.required_num("d0", "the orifice width D0 [m]");
    const auto u0 = s.required_num("u0", "the jet speed u0 [m/s]");
    positive(d0);
    if (!(u0.value > 0)) fail(u0, "the jet speed must be positive (the plug moves out of the nozzle)", "u0 > 0");
    nz.x0 = x0.value, nz.z0 = z0.value, nz.d0 = d0.value, nz.u0 = u0.value;
    read_members(s, nz);
    if (auto f = s.string("axis")) {
        const auto dir = kNozzleDirections[choose_from<std::int64_t>(*f, find_param("nozzle.axis")->choices)];
        nz.ex = dir.first, nz.ez = dir.second;
    }
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
    read_members(top.sub("breakup"), bk);
    spec.breakup = bk;
}

// [[fluid.block]], [[fluid.disc]], [[fluid.cylinder]], [[fluid.square]]
void read_fluid_shapes(const Ctx& ctx, const Section& fluid, CaseSpec& spec, const Box& box) {
    const bool axi = spec.params.geometry == Geometry::Axisymmetric;
    for (const Section& s : fluid.array_of_tables("block")) {
        FluidBlock b;
        b.r = read_rect(s, box, "fluid region");
        read_members(s, b);
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
        read_members(s, d);
        if (d.elongation != 0.0) {
            const double a = r.value * (1 + std::abs(d.elongation));
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
        read_members(s, c);
        if (!s.has("wavelength") && c.eps != 0.0)
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
        read_members(s, q);
        spec.fluid_squares.push_back(q);
    }
}

CaseSpec build(const Ctx& ctx, const toml::table& root) {
    CaseSpec spec;
    spec.source = ctx.file;
    SimParams& p = spec.params;
    const Section top(ctx, &root, "", "");

    if (auto v = top.integer("format_version"); v && v->value != 1)
        fail(*v, "unsupported format version", "1");

    const LegacyRead leg = read_legacy(top, spec);
    const Section num_s = top.sub("numerics");
    read_members(num_s, p);  // everything but the viscosity value, which needs h and c0
    read_members(top.sub("gravity"), p);
    read_members(top.sub("surface_tension"), p);
    const Section fluid = top.sub("fluid");
    read_members(fluid, p);
    read_sound_speed(ctx, fluid, p, leg.single);
    read_resolution(ctx, top, p, spec.legacy, leg);
    read_viscosity(ctx, num_s, fluid, p);
    read_domain(ctx, top, spec);
    read_members(top.sub("time"), p);
    const Box box{p.lx, p.lz};
    read_structures(top, spec, box);
    read_jet(ctx, top, spec, box);
    read_fluid_shapes(ctx, fluid, spec, box);
    if (spec.legacy_fill && p.h_swl <= 0)
        throw InputError(ctx.where(fluid.key_path("h_swl")), "missing required key",
                         "fluid.coef and fluid.h_swl with legacy.fill = true (the legacy fill stops at h_swl)",
                         "nothing");
    if (spec.fluid_blocks.empty() && spec.fluid_discs.empty() && spec.fluid_squares.empty() &&
        spec.fluid_cylinders.empty() && !spec.nozzle)
        throw InputError(ctx.file + ": fluid", "no fluid in the case",
                         "at least one [[fluid.block]], [[fluid.disc]], [[fluid.square]] or [[fluid.cylinder]], or a [nozzle]",
                         "none");

    const Section out = top.sub("output");
    read_members(out, spec.output);
    if (auto f = out.integer("revolution_sectors"); f && p.geometry != Geometry::Axisymmetric)
        fail(*f, "only an axisymmetric case has rings to revolve about the axis",
             "no output.revolution_sectors with domain.geometry = \"planar\" (the default), "
             "or domain.geometry = \"axisymmetric\"");
    return spec;
}

}  // namespace

std::vector<std::string> modern_case_keys() {
    std::vector<std::string> out;
    for (const auto& k : case_params())
        if (!k.key.empty()) out.emplace_back(k.key);
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

// A row's comment in the echo: its echo text, else its choices or its doc; "{choices}" is
// replaced by the names.
std::string comment_of(const Param& r) {
    std::string c(r.echo.empty() ? (r.choices.empty() ? r.doc : "{choices}") : r.echo);
    if (c == "-") return "";
    if (const auto at = c.find("{choices}"); at != std::string::npos) c.replace(at, 9, choice_list(r.choices));
    return c;
}

// A member's value as the case file writes it.
std::string value_of(const Param& r, const void* owner) {
    const Member& m = r.member;
    if (m.store == Member::Store::Float) return num(m.get_f(owner));
    const std::int64_t v = m.get_i(owner);
    if (r.type == KeyType::String) return str(choice_name(r.choices, v));
    if (r.type == KeyType::Bool) return boolean(v != 0);
    return std::to_string(v);
}

// The structs a section's rows live in.
struct Owner {
    const void* tag;
    const void* object;
};

// The lines of one section: the rows whose member lives in one of owners, in the table's
// order; a row echoed by hand gets the line custom(row) makes ("" for none).
template <class Custom>
std::string echo_section(std::string_view section, std::initializer_list<Owner> owners, Custom&& custom) {
    std::string s;
    for (const Param& r : case_params()) {
        if (r.key.empty() || section_of(r.key) != section) continue;
        if (r.hand & kHandEcho) {
            s += custom(r);
            continue;
        }
        for (const Owner& o : owners)
            if (o.tag == r.member.owner) s += line(std::string(leaf_of(r.key)), value_of(r, o.object), comment_of(r));
    }
    return s;
}

template <class S>
Owner owner(const S& s) {
    return {&owner_tag<S>, &s};
}

// A section whose every row is echoed from one struct.
template <class S>
std::string echo_section(std::string_view section, const S& s) {
    return echo_section(section, {owner(s)}, [](const Param&) { return std::string(); });
}

// The flags of the derived numbers of a legacy case, made in single precision: written
// so that they read back to the bit.
struct EchoFlags {
    bool single = false;
    bool h_by_coefficient = false;
    bool legacy_section = false;
};

EchoFlags echo_flags(const CaseSpec& spec) {
    const SimParams& p = spec.params;
    const LegacyRunInfo& info = spec.legacy;
    const LegacyRunInfo info_default;
    const double g = std::abs(p.gz);
    const bool b_single = p.h_swl > 0 &&
                          tait_B_from_coef(p.coef, p.rho0, g, p.h_swl, p.gamma) != p.B &&
                          tait_B_from_coef_single(p.coef, p.rho0, g, p.h_swl, p.gamma) == p.B;
    const bool h_single = info.h_coefficient > 0 &&
                          h_from_coefficient(info.h_coefficient, p.dx, p.dz, false) != p.h &&
                          h_from_coefficient(info.h_coefficient, p.dx, p.dz, true) == p.h;
    EchoFlags e;
    e.single = b_single || h_single;
    e.h_by_coefficient =
        info.h_coefficient > 0 && h_from_coefficient(info.h_coefficient, p.dx, p.dz, e.single) == p.h;
    e.legacy_section =
        spec.legacy_fill || e.single || (info.h_coefficient > 0 && !e.h_by_coefficient) ||
        info.detail_out != info_default.detail_out || info.detail_start != info_default.detail_start ||
        info.detail_end != info_default.detail_end || info.vorticity != info_default.vorticity ||
        info.compiler != info_default.compiler || info.xz_precision != info_default.xz_precision;
    return e;
}

// The lines of the keys the writer makes by hand (kHandEcho): derived numbers and keys shown
// only in some cases.
std::string custom_line(const Param& r, const CaseSpec& spec, const EchoFlags& e) {
    const SimParams& p = spec.params;
    const std::string key(leaf_of(r.key));
    const std::string_view k = r.key;
    const double c0 = p.c0();
    if (k == "numerics.alpha" && p.viscosity == ViscosityModel::Artificial)
        return line(key, num(p.visc_value),
                    "artificial viscosity; same as nu = alpha h c0 / 8 = " + num(p.visc_value * p.h * c0 / 8.0) +
                        " m^2/s");
    if (k == "fluid.c0" && p.h_swl <= 0)
        return line(key, num(c0_for_B(p)), "sound speed at rest [m/s]; B = rho0 c0^2 / gamma = " + num(p.B) + " Pa");
    if (k == "fluid.coef" && p.h_swl > 0)
        return line(key, num(p.coef), "c0 = coef sqrt(|gz| h_swl) = " + num(c0) + " m/s");
    if (k == "fluid.h_swl" && p.h_swl > 0)
        return line(key, num(p.h_swl), "still-water depth [m]; B = " + num(p.B) + " Pa");
    if (k == "fluid.nu" && p.viscosity == ViscosityModel::Laminar)
        return line(key, num(p.visc_value), "kinematic viscosity [m^2/s] (mu = " + num(p.visc_value * p.rho0) + " Pa s)");
    if (k == "surface_tension.rings_curvature" && p.axis_pair == AxisPair::Rings &&
        p.st_delta == SurfaceTensionDelta::PressureConsistent)
        return line(key, value_of(r, &p), comment_of(r));
    if (k == "domain.axis_pair" && p.geometry == Geometry::Axisymmetric) return line(key, value_of(r, &p), comment_of(r));
    if (k == "resolution.h") {
        const double diag = std::sqrt(p.dx * p.dx + p.dz * p.dz);
        if (e.h_by_coefficient)
            return line("h_coefficient", num(spec.legacy.h_coefficient),
                        "h = coefficient sqrt(dx^2 + dz^2) = " + num(p.h) + " m = " + num(p.h / p.dx) + " dx");
        return line(key, num(p.h), "smoothing length [m] = " + num(p.h / p.dx) + " dx = " + num(p.h / diag) +
                                       " sqrt(dx^2 + dz^2)");
    }
    if (k == "legacy.single_precision") return line(key, boolean(e.single), std::string(r.doc));
    if (k == "legacy.h_coefficient" && spec.legacy.h_coefficient > 0 && !e.h_by_coefficient)
        return line(key, num(spec.legacy.h_coefficient), std::string(r.doc));
    if (k == "output.revolution_sectors" && spec.output.revolution_sectors > 0)
        return line(key, value_of(r, &spec.output), comment_of(r));
    if (spec.nozzle && k == "nozzle.axis") {
        const NozzleSpec& nz = *spec.nozzle;
        std::int64_t axis = 0;
        for (std::size_t i = 0; i < std::size(kNozzleDirections); ++i)
            if (kNozzleDirections[i] == std::pair{nz.ex, nz.ez}) axis = static_cast<std::int64_t>(i);
        return line(key, str(choice_name(r.choices, axis)), comment_of(r));
    }
    if (spec.nozzle && spec.nozzle->disturbance > 0 &&
        (k == "nozzle.disturbance" || k == "nozzle.disturbance_ka"))
        return line(key, value_of(r, &*spec.nozzle), comment_of(r));
    if (spec.breakup && ((k == "breakup.stop_after" && spec.breakup->stop_after >= 0) ||
                         (k == "breakup.remove_drops_below_h" && spec.breakup->remove_drops_below_h > 0)))
        return line(key, value_of(r, &*spec.breakup), comment_of(r));
    return "";
}

}  // namespace

std::string write_modern_case(const CaseSpec& spec) {
    const SimParams& p = spec.params;
    const EchoFlags e = echo_flags(spec);
    const auto custom = [&](const Param& r) { return custom_line(r, spec, e); };
    std::string s;
    s += "# sphjet case file (modern format, reference: cases/CASE_FORMAT.md).\n";
    if (!spec.source.empty()) s += "# Written from: " + sanitize_comment(spec.source) + "\n";
    s += "# Units: SI (m, s, kg). Coordinates: x horizontal, z vertical, box [0, lx] x [0, lz].\n\n";
    s += line("format_version", "1", "");

    s += "\n[numerics]\n" + echo_section("numerics", {owner(p)}, custom);
    s += "\n[fluid]\n" + echo_section("fluid", {owner(p)}, custom);
    for (const auto& b : spec.fluid_blocks)
        s += "\n[[fluid.block]]                  # rectangle filled on the lattice\n" +
             echo_section("fluid.block[]", b);
    for (const auto& d : spec.fluid_discs) s += "\n[[fluid.disc]]\n" + echo_section("fluid.disc[]", d);
    for (const auto& c : spec.fluid_cylinders) {
        s += "\n[[fluid.cylinder]]               # axisymmetric: r(z) = a (1 + eps cos(2 pi (z - zmin) / wavelength))\n";
        s += echo_section("fluid.cylinder[]", {owner(c)}, [&c](const Param& r) {
            return c.wavelength > 0 ? line(std::string(leaf_of(r.key)), num(c.wavelength), comment_of(r)) : "";
        });
    }
    for (const auto& q : spec.fluid_squares) s += "\n[[fluid.square]]\n" + echo_section("fluid.square[]", q);
    s += "\n[surface_tension]\n" + echo_section("surface_tension", {owner(p)}, custom);
    s += "\n[gravity]\n" + echo_section("gravity", p);
    s += "\n[domain]\n" + echo_section("domain", {owner(p), owner(spec)}, custom);
    s += "\n[resolution]\n" + echo_section("resolution", {owner(p)}, custom);
    s += "\n[time]\n" + echo_section("time", p);
    for (const auto& o : spec.obstacles) s += "\n[[obstacle]]\n" + echo_section("obstacle[]", o);
    for (const auto& g : spec.gates)
        s += "\n[gate]                          # legacy \"Add gate\": a column of moving boundary particles\n" +
             echo_section("gate", g);
    if (spec.nozzle)
        s += "\n[nozzle]                        # a driven nozzle: the fluid in it moves out at u0 as a plug\n" +
             echo_section("nozzle", {owner(*spec.nozzle)}, custom);
    if (spec.breakup)
        s += "\n[breakup]                       # breakup detection while the run goes\n" +
             echo_section("breakup", {owner(*spec.breakup)}, custom);
    for (const auto& w : spec.walls)
        s += "\n[[wall]]                        # legacy \"Add wall\": two layers of boundary particles\n" +
             echo_section("wall[]", w);
    if (e.legacy_section)
        s += "\n[legacy]                        # carried over from a legacy SPHysics case file\n" +
             echo_section("legacy", {owner(spec), owner(spec.legacy)}, custom);
    s += "\n[output]\n" + echo_section("output", {owner(spec.output)}, custom);
    return s;
}

}  // namespace sphjet
