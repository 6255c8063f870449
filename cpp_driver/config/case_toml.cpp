// The text functions of the case reader and the walk of the tree against the schema, with
// spelling suggestions for unknown keys (config/case_toml.hpp).
#include "config/case_toml.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

#include "model/case_params.hpp"

namespace sphjet::casefile {

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


namespace {

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

}  // namespace

void check_keys(const Ctx& ctx, const toml::table& t, const std::string& pattern_prefix,
                const std::string& actual_prefix) {
    for (auto&& [k, node] : t) {
        const std::string key(k.str());
        const std::string pat = join(pattern_prefix, key);
        const std::string act = join(actual_prefix, key);
        if (find_param(pat) != nullptr) continue;  // a leaf: its type is checked when read
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


}  // namespace sphjet::casefile
