#include "io/jet_output.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include "config/errors.hpp"
#include "io/h5_util.hpp"

namespace fs = std::filesystem;

namespace sphjet {

void write_text_atomically(const fs::path& path, const std::string& content) {
    fs::path tmp = path;
    tmp += ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (out) {
            out << content;
            out.flush();
        }
        if (!out) {
            const std::string why = std::strerror(errno);
            std::error_code ec;
            fs::remove(tmp, ec);
            throw InputError(path.string(), "cannot write the file", "room and permission to write it", why);
        }
    }
    h5::commit_file(tmp, path);
}

namespace {

const char* column_units(const std::string& name) {
    if (name == "time") return "s";
    if (name == "volume_out" || name == "L") return name == "L" ? "m" : "m^2";
    if (name == "flux") return "m^2/s";
    if (name == "u_flux" || name == "u_orifice") return "m/s";
    return "1";
}

}  // namespace

void write_jet_table(const fs::path& dir, std::optional<double> first_time, std::optional<double> first_length,
                     double eq37_l_over_d0) {
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
    fs::path tmp = run;
    tmp += ".tmp";
    std::error_code ec;
    fs::copy_file(run, tmp, fs::copy_options::overwrite_existing, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw InputError(run.string(), "cannot copy the run file to add the jet table", "room to write it",
                         ec.message());
    }
    try {
        h5::QuietErrors quiet;
        h5::File f(H5Fopen(tmp.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
        if (f.get() < 0) throw InputError(tmp.string(), "cannot open for writing", "", h5::last_error());
        if (h5::has_link(f, "jet")) H5Ldelete(f, "jet", H5P_DEFAULT);
        h5::Group g = h5::create_group(f, "jet");
        for (std::size_t k = 0; k < names.size(); ++k) h5::write_array(g, names[k], cols[k], column_units(names[k]));
        const double nan = std::numeric_limits<double>::quiet_NaN();
        h5::write_attr(g, "first_breakup_time", first_time.value_or(nan));
        h5::write_attr(g, "first_breakup_L", first_length.value_or(nan));
        h5::write_attr(g, "eq37_L_over_d0", eq37_l_over_d0);
        h5::write_attr(g, "source", std::string("jet.csv; columns in cases/jet/README.md"));
        g.reset();
        h5::close_file(f, tmp);
    } catch (...) {
        fs::remove(tmp, ec);
        throw;
    }
    h5::commit_file(tmp, run);
}

}  // namespace sphjet
