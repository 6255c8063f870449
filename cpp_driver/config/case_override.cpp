// Overrides: key.path=value, applied to the case's tree before it is checked
// (config/case_toml.hpp; the keys are those of model/case_params.hpp).
#include <algorithm>

#include "config/case_toml.hpp"
#include "model/case_params.hpp"

namespace sphjet::casefile {

namespace {

std::string trim(std::string_view s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string_view::npos) return {};
    const auto e = s.find_last_not_of(" \t");
    return std::string(s.substr(b, e - b + 1));
}

}  // namespace

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
    if (find_param(pattern) == nullptr) {
        std::string problem = "unknown key";
        const std::string last = split_index(segs.back()).first;
        if (is_section(pattern) || is_section(pattern + "[]")) {
            problem = "names a section, not a key";
        } else if (auto c = closest(last, children(pattern_prefix)); c && find_param(join(pattern_prefix, *c))) {
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
        if (safe_for_toml(line)) {
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


}  // namespace sphjet::casefile
