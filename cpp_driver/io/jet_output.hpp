// Files of a jet run (core/jet_run.hpp): the CSV tables and their copy in run.h5.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace sphjet {

// Writes `content` to path.tmp, fsyncs and renames it over path. Throws InputError naming
// the file and the system's reason (e.g. "No space left on device"); the temporary file is
// removed on failure and the old file stays as it was.
void write_text_atomically(const std::filesystem::path& path, const std::string& content);

// Copies DIR/jet.csv into DIR/run.h5 as the group /jet: one float64 dataset per column (with
// units), and attributes first_breakup_time [s] and first_breakup_L_over_d0 (NaN when the
// jet did not break) and eq37_L_over_d0. run.h5 is rewritten through a temporary copy, so a
// failure leaves the old file. Nothing is done when run.h5 is absent.
void write_jet_table(const std::filesystem::path& dir, std::optional<double> first_time,
                     std::optional<double> first_length, double eq37_l_over_d0);

}  // namespace sphjet
