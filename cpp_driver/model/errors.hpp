// Errors a user can cause: they name the file, the line or key, what was expected and found.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

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

// An output file that could not be written (a full disk, a quota, a read-only or vanished
// file system). The message names the file and the cause from errno ("No space left on
// device"); the writer has removed its temporary file and left the previous version of the
// file as it was. io/file_write.hpp throws these.
class WriteError : public InputError {
public:
    WriteError(std::string path, int error_number, const std::string& problem,
               const std::string& expected = {}, const std::string& found = {})
        : InputError(path, problem, expected, found),
          path_(std::move(path)),
          errno_(error_number) {}
    // The file that was being written (its final name, not the temporary one).
    [[nodiscard]] const std::string& path() const { return path_; }
    // errno of the failed call; 0 when unknown.
    [[nodiscard]] int error_number() const { return errno_; }

private:
    std::string path_;
    int errno_ = 0;
};

// A failure of the simulation itself (blow-up, particle out of the domain, core status).
class SimulationError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace sphjet
