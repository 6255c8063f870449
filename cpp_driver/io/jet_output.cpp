#include "io/jet_output.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include "io/h5_util.hpp"
#include "model/errors.hpp"

namespace fs = std::filesystem;

namespace sphjet {

namespace {

const char* column_units(const std::string& name, bool round) {
    if (name == "time") return "s";
    if (name == "L") return "m";
    if (name == "volume_out") return round ? "m^3" : "m^2";
    if (name == "flux") return round ? "m^3/s" : "m^2/s";
    if (name == "u_flux" || name == "u_orifice" || name == "ur_exit_rms") return "m/s";
    if (name == "p_exit_mean" || name == "p_exit_std") return "Pa";
    return "1";
}

}  // namespace

namespace {

// Copies the scalar attributes of src (strings, integers, floats) onto dst.
herr_t copy_attr(hid_t src, const char* name, const H5A_info_t*, void* op) {
    const hid_t dst = *static_cast<hid_t*>(op);
    h5::Attribute a(H5Aopen(src, name, H5P_DEFAULT));
    h5::Datatype t(H5Aget_type(a));
    switch (H5Tget_class(t)) {
        case H5T_STRING: h5::write_attr(dst, name, h5::read_attr_string(src, name)); break;
        case H5T_INTEGER: h5::write_attr(dst, name, h5::read_attr_int64(src, name)); break;
        case H5T_FLOAT: h5::write_attr(dst, name, h5::read_attr_double(src, name)); break;
        default: break;
    }
    return 0;
}

}  // namespace

void write_jet_table(const fs::path& dir, std::optional<double> first_time, std::optional<double> first_length,
                     double eq37_l_over_d0, bool round) {
    const fs::path run = dir / "run.h5", csv = dir / "jet.csv";
    if (!fs::exists(run) || !fs::exists(csv)) return;
    std::ifstream in(csv);
    std::string header, line;
    std::getline(in, header);
    std::vector<std::string> names;
    {
        std::stringstream ss(header);
        for (std::string x; std::getline(ss, x, ',');) names.push_back(x);
    }
    std::vector<std::vector<double>> cols(names.size());
    while (std::getline(in, line)) {
        std::vector<double> row;
        std::stringstream ss(line);
        for (std::string x; std::getline(ss, x, ',');) row.push_back(std::strtod(x.c_str(), nullptr));
        if (row.size() != names.size()) break;
        for (std::size_t k = 0; k < row.size(); ++k) cols[k].push_back(row[k]);
    }
    // run.h5 anew in memory: its attributes and groups as they are, and /jet (h5_util.hpp:
    // written in one piece, the old file untouched on failure).
    h5::QuietErrors quiet;
    h5::File src = h5::open_file(run);
    h5::File dst = h5::create_file(run, 8 * names.size() * (cols.empty() ? 0 : cols[0].size()));
    hid_t dst_id = dst.get();
    hsize_t idx = 0;
    H5Aiterate2(src, H5_INDEX_NAME, H5_ITER_NATIVE, &idx, copy_attr, &dst_id);
    for (const std::string& name : h5::link_names(src))
        if (name != "jet" && H5Ocopy(src, name.c_str(), dst, name.c_str(), H5P_DEFAULT, H5P_DEFAULT) < 0)
            throw InputError(h5::where(src, name), "cannot copy into the new run file", "", h5::last_error());
    src.reset();
    h5::Group g = h5::create_group(dst, "jet");
    for (std::size_t k = 0; k < names.size(); ++k) h5::write_array(g, names[k], cols[k], column_units(names[k], round));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    h5::write_attr(g, "first_breakup_time", first_time.value_or(nan));
    h5::write_attr(g, "first_breakup_L", first_length.value_or(nan));
    h5::write_attr(g, "eq37_L_over_d0", eq37_l_over_d0);
    h5::write_attr(g, "source", std::string("jet.csv; columns in cases/CASE_FORMAT.md [breakup]"));
    g.reset();
    h5::write_file(dst, run, "the run file");
}

}  // namespace sphjet
