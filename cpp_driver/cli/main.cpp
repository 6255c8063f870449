// sphjet: the command-line program. Sub-commands register themselves (cli/commands.hpp).
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"

int main(int argc, char** argv) {
    CLI::App app{"sphjet: 2D weakly compressible SPH (a modern fork of SPHysics 2D) with CSF "
                 "surface tension"};
    app.set_version_flag("--version", std::string(SPHJET_VERSION) + " (" SPHJET_GIT_HASH ")");
    app.require_subcommand(1);
    sphjet::cli::set_command_line(argc, argv);
    sphjet::cli::register_run(app);
    sphjet::cli::register_gen(app);
    sphjet::cli::register_bench(app);
    sphjet::cli::register_compare(app);
    sphjet::cli::register_analyse(app);
    sphjet::cli::register_convert(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const std::exception& e) {
        std::cerr << "sphjet: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
