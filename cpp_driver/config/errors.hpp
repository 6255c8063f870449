// Errors a user can cause: they name the file, the line or key, what was expected and found.
#pragma once

#include <stdexcept>
#include <string>

namespace sphjet {

class InputError : public std::runtime_error {
public:
    // where: "file:line" or "file: key"; what_expected / what_found may be empty.
    InputError(const std::string& where, const std::string& problem,
               const std::string& expected = {}, const std::string& found = {})
        : std::runtime_error(format(where, problem, expected, found)) {}

private:
    static std::string format(const std::string& where, const std::string& problem,
                              const std::string& expected, const std::string& found) {
        std::string s = where + ": " + problem;
        if (!expected.empty()) s += "; expected " + expected;
        if (!found.empty()) s += ", found " + found;
        return s;
    }
};

// A failure of the simulation itself (blow-up, particle out of the domain, core status).
class SimulationError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace sphjet
