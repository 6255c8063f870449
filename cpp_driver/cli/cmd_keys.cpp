// sphjet keys [--update PAGE]: the key tables of the case format, made from the description
// of every case parameter (model/case_params.hpp). Without --update they go to stdout, one
// per section; with it, the tables of PAGE (cases/CASE_FORMAT.md) between their markers are
// written anew and the rest of the page is left as it is.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>
#include <string>

#include "cli/commands.hpp"
#include "io/file_write.hpp"
#include "model/case_params.hpp"
#include "model/errors.hpp"

namespace sphjet::cli {

namespace {

struct KeysOptions {
    std::string update;
};

void run_keys(const KeysOptions& o) {
    if (o.update.empty()) {
        std::set<std::string_view> done;
        for (const Param& r : case_params()) {
            if (r.key.empty() || !done.insert(section_of(r.key)).second) continue;
            const std::string name = section_of(r.key).empty() ? "top" : std::string(section_of(r.key));
            std::cout << "<!-- keys " << name << " -->\n" << case_format_table(section_of(r.key))
                      << "<!-- end keys -->\n\n";
        }
        std::cout << "<!-- keys hdf5 -->\n" << case_format_table("hdf5") << "<!-- end keys -->\n";
        return;
    }
    std::ifstream in(o.update, std::ios::binary);
    if (!in) throw InputError(o.update, "cannot open the page", "a readable markdown file", "no such file");
    std::ostringstream text;
    text << in.rdbuf();
    const std::string page = text.str();
    const std::string updated = with_case_format_tables(page);
    if (updated == page) {
        std::cerr << "sphjet keys: " << o.update << " is up to date\n";
        return;
    }
    write_file_atomically(o.update, updated, "the page");
    std::cerr << "sphjet keys: " << o.update << ": tables written anew\n";
}

}  // namespace

void register_keys(CLI::App& app) {
    auto opts = std::make_shared<KeysOptions>();
    CLI::App* cmd = app.add_subcommand(
        "keys", "Print the key tables of the case format (cases/CASE_FORMAT.md), or write them into a page");
    cmd->add_option("--update", opts->update,
                    "rewrite the tables between '<!-- keys SECTION -->' and '<!-- end keys -->' in this page");
    cmd->callback([opts] { run_keys(*opts); });
}

}  // namespace sphjet::cli
