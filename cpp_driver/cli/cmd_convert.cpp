// sphjet convert LEGACY_CASE [-o OUT.toml]: a legacy SPHysics case file as a modern (TOML)
// case file (cases/CASE_FORMAT.md). The result reads back to the same CaseSpec, every
// number to the bit; it goes to stdout without -o.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "cli/commands.hpp"
#include "config/legacy_case.hpp"
#include "config/modern_case.hpp"
#include "io/file_write.hpp"
#include "model/errors.hpp"

namespace sphjet::cli {

namespace {

namespace fs = std::filesystem;

struct ConvertOptions {
    std::string legacy_case;
    std::string out;
    bool force = false;
};

// Writes next to the target and renames (io/file_write.hpp), so a failure never leaves half a
// file or a temporary one; WriteError names the file and the cause.
void write_whole(const fs::path& target, const std::string& text) {
    write_file_atomically(target, text, "the case file");
}

void run_convert(const ConvertOptions& o) {
    const CaseSpec spec = read_legacy_case(o.legacy_case);
    const std::string text = write_modern_case(spec);

    // The converted case must read back as itself; a failure here is a bug, not a user error.
    const CaseSpec back = parse_modern_case(text, o.out.empty() ? "<converted>" : o.out);
    CaseSpec same = back;
    same.source = spec.source;
    if (write_modern_case(same) != text)
        throw std::logic_error("sphjet convert: the converted case does not read back to the same "
                               "case (please report this with the legacy case file)");

    for (const std::string& w : spec.warnings) std::cerr << "sphjet convert: warning: " << w << "\n";
    if (o.out.empty()) {
        std::cout << text;
        return;
    }
    const fs::path out = o.out;
    if (fs::exists(out) && !o.force)
        throw InputError(out.string(), "the output file exists", "a new file, or --force to overwrite it",
                         "an existing file");
    if (fs::exists(out) && fs::is_directory(out))
        throw InputError(out.string(), "the output path is a directory", "a file name", "a directory");
    write_whole(out, text);
    std::cerr << "sphjet convert: " << o.legacy_case << " -> " << out.string() << "\n";
}

}  // namespace

void register_convert(CLI::App& app) {
    auto opts = std::make_shared<ConvertOptions>();
    CLI::App* cmd = app.add_subcommand(
        "convert", "Convert a legacy SPHysics case file into a modern TOML case file "
                   "(cases/CASE_FORMAT.md); stdout unless -o is given");
    cmd->add_option("LEGACY_CASE", opts->legacy_case, "legacy SPHysics case file (the generator's stdin)")
        ->required();
    cmd->add_option("-o,--output", opts->out, "modern case file to write (.toml)");
    cmd->add_flag("--force", opts->force, "overwrite the output file if it exists");
    cmd->callback([opts] { run_convert(*opts); });
}

}  // namespace sphjet::cli
