// Each sub-command lives in its own cli/cmd_<name>.cpp and registers itself here.
#pragma once

#include <CLI/CLI.hpp>

namespace sphjet::cli {

// The command line of this invocation, recorded in the outputs.
void set_command_line(int argc, char** argv);

void register_run(CLI::App& app);
void register_gen(CLI::App& app);
void register_bench(CLI::App& app);
void register_compare(CLI::App& app);
void register_analyse(CLI::App& app);
void register_convert(CLI::App& app);
void register_drop(CLI::App& app);
void register_keys(CLI::App& app);
void register_modes(CLI::App& app);

}  // namespace sphjet::cli
