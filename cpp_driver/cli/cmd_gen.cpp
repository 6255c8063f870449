// sphjet gen CASE --out DIR: the legacy particle generator. Reads a legacy SPHysics case
// file, places the particles as SPHYSICSgen2D does and writes IPART, INDAT (and NORMALS.init
// for repulsive walls) into DIR.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "config/indat.hpp"
#include "config/legacy_case.hpp"
#include "geometry/generator.hpp"
#include "model/errors.hpp"

namespace sphjet::cli {

namespace {

namespace fs = std::filesystem;

struct GenOptions {
    std::string case_file;
    std::string out_dir;
    bool force = false;
};

void run_gen(const GenOptions& o) {
    const CaseSpec spec = read_legacy_case(o.case_file);
    const InitialState st = generate(spec);
    const ParticleSet& ps = st.particles;
    const bool repulsive = st.params.boundary == BoundaryType::Repulsive;

    const fs::path dir = o.out_dir;
    if (fs::exists(dir) && !fs::is_directory(dir))
        throw InputError(dir.string(), "the output path is not a directory", "a directory (or nothing)",
                         "a file");
    if (!o.force) {
        for (const char* name : {"IPART", "INDAT", "NORMALS.init", "gate"})
            if (fs::exists(dir / name))
                throw InputError((dir / name).string(), "the output directory already holds generated files",
                                 "a new or empty directory, or --force to overwrite", "an existing " +
                                 std::string(name));
    }
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw InputError(dir.string(), "cannot create the output directory", "a writable place", ec.message());

    // Everything is built before anything is written; each file is replaced whole.
    write_legacy_inputs(dir, st.params, ps, st.legacy);
    const bool gate = ps.nbf < ps.nb;

    std::cout << fmt::format("sphjet gen: {} -> {}\n", o.case_file, dir.string());
    std::cout << fmt::format("  particles: np = {}  (boundary nb = {}, fixed nbf = {}, fluid = {})\n", ps.size(),
                             ps.nb, ps.nbf, ps.n_fluid());
    std::cout << fmt::format("  h = {:.7g} m   c0 = {:.6g} m/s   B = {:.7g} Pa   dx = {:g}, dz = {:g} m\n",
                             st.params.h, st.params.c0(), st.params.B, st.params.dx, st.params.dz);
    std::cout << fmt::format("  boundary: {}   kernel: {}   lattice: {}\n", to_string(st.params.boundary),
                             to_string(st.params.kernel),
                             st.params.lattice == Lattice::BodyCentred ? "BCC" : "SC");
    std::cout << "  wrote IPART, INDAT" << (repulsive ? ", NORMALS.init" : "") << (gate ? ", gate" : "") << "\n";
    for (const std::string& w : spec.warnings) std::cerr << "sphjet gen: warning: " << w << "\n";
}

}  // namespace

void register_gen(CLI::App& app) {
    auto opts = std::make_shared<GenOptions>();
    CLI::App* cmd = app.add_subcommand(
        "gen", "Generate the initial particles of a legacy SPHysics case file (as SPHYSICSgen2D): "
               "writes IPART, INDAT and, for repulsive walls, NORMALS.init");
    cmd->add_option("CASE", opts->case_file, "legacy SPHysics case file (the generator's stdin)")->required();
    cmd->add_option("--out,-o", opts->out_dir, "output directory (created if missing)")->required();
    cmd->add_flag("--force", opts->force, "overwrite IPART/INDAT/NORMALS.init already in the output directory");
    cmd->callback([opts] { run_gen(*opts); });
}

}  // namespace sphjet::cli
