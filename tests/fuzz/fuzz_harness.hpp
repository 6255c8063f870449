// One input through one parser, shared by the libFuzzer targets (fuzz_*.cpp) and the
// deterministic mutation test (test_parser_mutations.cpp).
//
// The contract every input is held to: the parser either returns, or throws
// sphjet::InputError. Anything else escapes from run_*() and is a finding: another exception
// type (std::out_of_range, std::bad_alloc, std::invalid_argument, ...), a crash, a hang, a
// sanitizer report, or a HarnessViolation, thrown here when an input is accepted but what
// comes out breaks what the later stages assume (a non-finite parameter, a period < 1, a
// wall link outside the boundary particles, a non-finite generated particle).
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "model/case_spec.hpp"

namespace sphjet::fuzz {

// An accepted input whose result breaks an invariant (see above).
class HarnessViolation : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

enum class Outcome {
    Rejected,   // InputError from the parser (or from the generator)
    Accepted,   // parsed; generator not run (too many particles for the cap)
    Generated,  // parsed and generated
};

// Upper bound of the particles generate(spec) creates, and of the lattice points it visits;
// +inf when a size is not finite. Double arithmetic only, so it is safe for any spec.
[[nodiscard]] double estimate_particles(const CaseSpec& spec);

// Legacy case file: parse_legacy_case, then generate when estimate <= generate_cap.
Outcome run_legacy(std::string_view data, double generate_cap);

// INDAT, IPART, NORMALS.init and gate in one input, split at lines holding exactly the markers:
//   <INDAT> "\n%%IPART%%\n" <IPART> "\n%%NORMALS.init%%\n" <NORMALS.init> "\n%%gate%%\n" <gate>
// (each marker optional, in this order). A file whose marker is missing is not written
// (read_indat then meets a missing file).
// The files are written to dir (created if needed), then read_indat(dir / "INDAT").
inline constexpr std::string_view kIpartMarker = "%%IPART%%";
inline constexpr std::string_view kNormalsMarker = "%%NORMALS.init%%";
inline constexpr std::string_view kGateMarker = "%%gate%%";
Outcome run_indat(std::string_view data, const std::filesystem::path& dir);

// Modern TOML case; after a line "#%%OVERRIDES%%" (a TOML comment, so the part above is
// the case file as it would be on disk) each line is one override "key.path=value", in
// which the two characters \n stand for a newline (so that an override can hold one).
// parse_modern_case, then generate when estimate <= generate_cap.
inline constexpr std::string_view kOverridesMarker = "#%%OVERRIDES%%";
Outcome run_modern(std::string_view data, double generate_cap);

// Splits the modern input into the TOML text and the override lines.
void split_modern(std::string_view data, std::string& toml, std::vector<std::string>& overrides);

// The libFuzzer side: runs f, returns normally for any outcome, and for anything that is a
// finding prints "sphjet-fuzz FINDING (<parser>): <exception type>: <what>" to stderr and
// aborts, so that libFuzzer records the input as a crash.
template <class F>
void guard(const char* parser, F&& f);

[[noreturn]] void report_finding(const char* parser, const char* type, const char* what);

}  // namespace sphjet::fuzz

#include <exception>
#include <typeinfo>

#include "model/errors.hpp"

namespace sphjet::fuzz {

template <class F>
void guard(const char* parser, F&& f) {
    try {
        f();
    } catch (const sphjet::InputError&) {
        // the contract: a user error with a message
    } catch (const HarnessViolation& e) {
        report_finding(parser, "HarnessViolation", e.what());
    } catch (const std::exception& e) {
        report_finding(parser, typeid(e).name(), e.what());
    } catch (...) {
        report_finding(parser, "(not a std::exception)", "");
    }
}

}  // namespace sphjet::fuzz
