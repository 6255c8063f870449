// Each sub-command lives in its own cli/cmd_<name>.cpp and registers itself here.
#pragma once

#include <CLI/CLI.hpp>

namespace sphjet::cli {

void register_run(CLI::App& app);
void register_gen(CLI::App& app);

}  // namespace sphjet::cli
