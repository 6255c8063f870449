#include "config/load_case.hpp"

#include "config/indat.hpp"
#include "config/legacy_case.hpp"
#include "config/modern_case.hpp"
#include "geometry/generator.hpp"
#include "model/errors.hpp"

namespace fs = std::filesystem;

namespace sphjet {

LoadedCase load_case(const fs::path& path, const std::vector<std::string>& overrides) {
    if (!fs::exists(path))
        throw InputError(path.string(), "case file not found", "an existing file", "nothing");
    if (fs::is_directory(path))
        throw InputError(path.string(), "case path is a directory",
                         "a case file (.toml, INDAT or a legacy case file)", "a directory");
    LoadedCase lc;
    if (looks_like_modern_case(path)) {
        lc.spec = read_modern_case(path, overrides);
        InitialState init = generate(lc.spec);
        lc.spec.params = init.params;
        lc.particles = std::move(init.particles);
        if (lc.spec.params.integrator == Integrator::Leapfrog) {
            const std::string where = path.string() + ": numerics.integrator";
            if (lc.particles.nb > 0)
                throw InputError(where, "the leapfrog advances fluid particles alone; this case has boundary particles",
                                 "numerics.integrator = \"predictor_corrector\", or a case without walls, "
                                 "obstacles, nozzle walls or a gate",
                                 std::to_string(lc.particles.nb) + " boundary particles");
            // its prediction amplifies an undamped sound wave twice as fast as the
            // predictor-corrector (fortran_core/integrate/leapfrog.f90)
            // legacy output writes INDAT, whose integrator line is SPHysics' (2 is its Verlet)
            if (lc.spec.output.format != OutputFormat::Hdf5)
                throw InputError(where, "legacy output (INDAT, PART) has no line for the leapfrog",
                                 "output.format = \"hdf5\", or numerics.integrator = \"predictor_corrector\"",
                                 "a legacy output format");
            if (!(lc.spec.params.bulk_viscosity > 0))
                throw InputError(where, "the leapfrog needs the bulk viscosity, which damps the sound waves "
                                        "its prediction amplifies",
                                 "numerics.bulk_viscosity > 0 (e.g. 0.5), or numerics.integrator = "
                                 "\"predictor_corrector\"",
                                 "numerics.bulk_viscosity = 0");
        }
        if (lc.spec.params.kernel == KernelType::CubicSplineTC && lc.spec.output.format != OutputFormat::Hdf5)
            throw InputError(path.string() + ": numerics.kernel",
                             "legacy output (INDAT, PART) has no kernel number for the Thomas-Couchman gradient",
                             "output.format = \"hdf5\", or numerics.kernel = \"cubic_spline\"",
                             "a legacy output format");
        if (lc.spec.params.shifting > 0 && !(lc.spec.params.sigma > 0))
            throw InputError(path.string() + ": numerics.shifting",
                             "shifting finds the free surface with the surface tension's passes, "
                             "and a case without surface tension has none",
                             "surface_tension.sigma > 0, or numerics.shifting = 0",
                             "surface_tension.sigma = 0");
        return lc;
    }
    if (!overrides.empty())
        throw InputError(path.string(), "--set works on modern (.toml) cases only",
                         "a .toml case (sphjet convert writes one from a legacy case)",
                         "a legacy case file");
    if (path.filename() == "INDAT") {
        InitialState init = read_indat(path);
        lc.spec.params = init.params;
        lc.spec.source = path.string();
        lc.spec.legacy = init.legacy;
        lc.particles = std::move(init.particles);
        return lc;
    }
    lc.spec = read_legacy_case(path);
    InitialState init = generate(lc.spec);
    lc.spec.params = init.params;
    lc.particles = std::move(init.particles);
    return lc;
}

}  // namespace sphjet
