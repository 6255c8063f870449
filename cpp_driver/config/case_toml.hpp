// Reading a case file's TOML tree (the modern case format, config/modern_case.hpp): the text
// functions, where a key is in the file (Ctx, Field, Section), the walk of the tree against the
// keys of model/case_params.hpp with spelling suggestions, the overrides, the toml++ guard
// and the build of the CaseSpec. The pieces live in case_toml.cpp, case_override.cpp,
// toml_guard.cpp and case_build.cpp; only those and the writer include this header.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "model/case_spec.hpp"
#include "model/errors.hpp"

namespace sphjet::casefile {

// Shortest text that reads back as the same double, always a TOML float.
[[nodiscard]] std::string num(double v);
// s in double quotes, '"' and '\\' escaped, control characters dropped.
[[nodiscard]] std::string dquote(std::string_view s);
// "a, b, c"
[[nodiscard]] std::string list(const std::vector<std::string>& items);
// "prefix.key", or "key" at the top.
[[nodiscard]] std::string join(const std::string& prefix, std::string_view key);
// "the integer 3", "a table": a node as the messages name it.
[[nodiscard]] std::string describe(const toml::node& n);
// Array index segment "name[3]" -> ("name", 3); plain "name" -> ("name", nullopt).
[[nodiscard]] std::pair<std::string, std::optional<std::size_t>> split_index(const std::string& seg);
// The option closest to word, when one is close enough to suggest.
[[nodiscard]] std::optional<std::string> closest(std::string_view word, const std::vector<std::string>& options);

// The sections of the schema ("numerics", "fluid.block[]"), and the keys and sections
// directly inside one ("" = the top level), as written in a file.
[[nodiscard]] const std::set<std::string>& sections();
[[nodiscard]] bool is_section(const std::string& pattern);
[[nodiscard]] std::vector<std::string> children(const std::string& prefix);

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

inline std::string found_text(double v) { return num(v); }
inline std::string found_text(std::int64_t v) { return std::to_string(v); }
inline std::string found_text(const std::string& v) { return dquote(v); }

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


// Every key of the tree (and of its tables) against the schema: an unknown key fails with the
// closest valid one, or the section it belongs to.
void check_keys(const Ctx& ctx, const toml::table& t, const std::string& pattern_prefix,
                const std::string& actual_prefix);

// One override "key.path=value" applied to the tree (case_override.cpp).
void apply_override(Ctx& ctx, toml::table& root, const std::string& text);

// The tree of a case file's text; toml++'s defects kept away (toml_guard.cpp). Syntax errors
// are InputErrors naming file, line and column.
[[nodiscard]] toml::table parse_toml(std::string_view text, const std::string& source_name);
// Whether a line can go to toml++ as it is (an override's value).
[[nodiscard]] bool safe_for_toml(std::string_view line);

// The CaseSpec of a checked tree (case_build.cpp).
[[nodiscard]] CaseSpec build_case(const Ctx& ctx, const toml::table& root);

}  // namespace sphjet::casefile
