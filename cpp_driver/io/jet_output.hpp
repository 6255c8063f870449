// Files of a jet run (core/jet_run.hpp): the CSV tables and their copy in run.h5.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace sphjet {

// Copies DIR/jet.csv into DIR/run.h5 as the group /jet: one float64 dataset per column (with
// units), and attributes first_breakup_time [s] and first_breakup_L [m] (NaN when the jet
// did not break) and eq37_L_over_d0; round: an axisymmetric jet (volumes in m^3). run.h5 is rebuilt in memory with its attributes
// and groups and written whole (io/h5_util.hpp), so a failure leaves the old file. Nothing is done when run.h5 is absent.
void write_jet_table(const std::filesystem::path& dir, std::optional<double> first_time,
                     std::optional<double> first_length, double eq37_l_over_d0, bool round = false);

}  // namespace sphjet
