#include "config/modern_case.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "config/case_toml.hpp"
#include "model/case_params.hpp"
#include "model/errors.hpp"

namespace sphjet {

bool looks_like_modern_case(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".toml";
}

std::vector<std::string> modern_case_keys() {
    std::vector<std::string> out;
    for (const auto& k : case_params())
        if (!k.key.empty()) out.emplace_back(k.key);
    return out;
}

CaseSpec parse_modern_case(std::string_view text, const std::string& source_name,
                           const std::vector<std::string>& overrides) {
    casefile::Ctx ctx{source_name, {}};
    toml::table root = casefile::parse_toml(text, source_name);
    for (const auto& o : overrides) casefile::apply_override(ctx, root, o);
    casefile::check_keys(ctx, root, "", "");
    return casefile::build_case(ctx, root);
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

}  // namespace sphjet
