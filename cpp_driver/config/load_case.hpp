// Any supported case file read into the case and its particles.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "model/case_spec.hpp"
#include "model/particles.hpp"

namespace sphjet {

// The case as the run sees it: a CaseSpec and its particles.
struct LoadedCase {
    CaseSpec spec;
    ParticleSet particles;
};

// Reads any supported case: a modern .toml, an INDAT (with IPART beside it), or a legacy
// case file (the stdin of SPHYSICSgen2D), generating the particles.
[[nodiscard]] LoadedCase load_case(const std::filesystem::path& path,
                                   const std::vector<std::string>& overrides);

}  // namespace sphjet
