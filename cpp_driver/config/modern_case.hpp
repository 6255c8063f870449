// The modern case format: one TOML file that says everything a legacy SPHysics case file
// says, plus what it cannot (surface tension, gravity vector, discs and squares of fluid,
// physical viscosity, output and safety settings). Every key is documented, with its
// legacy counterpart, in cases/CASE_FORMAT.md.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "model/case_spec.hpp"

namespace sphjet {

// Reads and validates a modern case file. Each override is "key.path=value"
// (e.g. "surface_tension.sigma=0.05", "fluid.block[0].u0=0.25"); it is applied to the
// TOML tree before validation, the value parsed as a TOML value (number, boolean, string;
// a bare word is a string). Every user error is an InputError naming file, key, what was
// expected and what was found; unknown keys (in the file or an override) get a suggestion.
[[nodiscard]] CaseSpec read_modern_case(const std::filesystem::path& path,
                                        const std::vector<std::string>& overrides = {});

// The same from text in memory; source_name is used in messages and as CaseSpec::source.
[[nodiscard]] CaseSpec parse_modern_case(std::string_view text, const std::string& source_name,
                                         const std::vector<std::string>& overrides = {});

// A complete, commented modern case file for spec. Round trip: parse(write(spec)) equals
// spec in every field except `source` (for any spec that passes validation).
[[nodiscard]] std::string write_modern_case(const CaseSpec& spec);

// True when the file name ends in ".toml" (any case); the content is not looked at.
[[nodiscard]] bool looks_like_modern_case(const std::filesystem::path& path);

// Every valid key path, elements of arrays of tables written "fluid.block[].xmin".
[[nodiscard]] std::vector<std::string> modern_case_keys();

// The mappings the format documents (cases/CASE_FORMAT.md, "Derived quantities").
// Tait stiffness from the sound speed: B = rho0 c0^2 / gamma.
[[nodiscard]] double tait_B_from_c0(double rho0, double c0, double gamma);
// Legacy SPHysics: c0 = coef sqrt(g h_swl), so B = coef^2 rho0 g h_swl / gamma.
[[nodiscard]] double tait_B_from_coef(double coef, double rho0, double g, double h_swl,
                                      double gamma);
// 2D artificial viscosity with the same shear viscosity as nu: alpha = 8 nu / (h c0).
[[nodiscard]] double alpha_from_nu(double nu, double h, double c0);

}  // namespace sphjet
