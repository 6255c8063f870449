// HDF5 snapshots and the XDMF index: what is written comes back bit for bit, the index lists
// every snapshot with the right file, dataset paths and times, and a run directory survives
// a restart. No tolerances: storage must be exact, so every comparison is bitwise.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <span>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "io/h5_util.hpp"
#include "io/hdf5_output.hpp"
#include "io/xdmf.hpp"
#include "model/case_spec.hpp"
#include "model/errors.hpp"

namespace fs = std::filesystem;
using namespace sphjet;

namespace {

fs::path fresh_dir(const std::string& name) {
    const fs::path d =
        fs::temp_directory_path() / ("sphjet_test_h5_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    return d;
}

// Doubles that a lossy path would change: signed zero, subnormals, extremes, infinities,
// a NaN with a payload, and random bit patterns across all exponents.
std::vector<double> awkward_doubles(std::size_t n, std::uint64_t seed) {
    std::vector<double> v = {-0.0,
                             std::numeric_limits<double>::denorm_min(),
                             std::numeric_limits<double>::max(),
                             -std::numeric_limits<double>::infinity(),
                             std::bit_cast<double>(std::uint64_t{0x7ff8000000012345}),
                             0.1 + 0.2,
                             1.0 / 3.0};
    std::mt19937_64 rng(seed);
    while (v.size() < n) {
        const double d = std::bit_cast<double>(rng());
        v.push_back(d);
    }
    v.resize(n);
    return v;
}

ParticleSet synthetic(std::size_t n, std::size_t nb, std::size_t nbf) {
    ParticleSet ps;
    ps.x = awkward_doubles(n, 1);
    ps.z = awkward_doubles(n, 2);
    ps.u = awkward_doubles(n, 3);
    ps.w = awkward_doubles(n, 4);
    ps.rho = awkward_doubles(n, 5);
    ps.p = awkward_doubles(n, 6);
    ps.m = awkward_doubles(n, 7);
    for (std::size_t i = 0; i < n; ++i) {
        ps.id.push_back(static_cast<std::int64_t>(n - 1 - i) + (std::int64_t{1} << 40));
        ps.kind.push_back(i < nbf ? 0 : i < nb ? 1 : 2);
        ps.active.push_back(i % 7 == 3 ? 0 : 1);
    }
    ps.nb = nb;
    ps.nbf = nbf;
    return ps;
}

template <class T>
void expect_bitwise(const std::vector<T>& a, const std::vector<T>& b, const char* what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if constexpr (std::is_same_v<T, double>) {
            ASSERT_EQ(std::bit_cast<std::uint64_t>(a[i]), std::bit_cast<std::uint64_t>(b[i]))
                << what << "[" << i << "]";
        } else {
            ASSERT_EQ(a[i], b[i]) << what << "[" << i << "]";
        }
    }
}

void expect_same_particles(const ParticleSet& a, const ParticleSet& b) {
    expect_bitwise(a.x, b.x, "x");
    expect_bitwise(a.z, b.z, "z");
    expect_bitwise(a.u, b.u, "u");
    expect_bitwise(a.w, b.w, "w");
    expect_bitwise(a.rho, b.rho, "rho");
    expect_bitwise(a.p, b.p, "p");
    expect_bitwise(a.m, b.m, "m");
    expect_bitwise(a.id, b.id, "id");
    expect_bitwise(a.kind, b.kind, "kind");
    expect_bitwise(a.active, b.active, "active");
    EXPECT_EQ(a.nb, b.nb);
    EXPECT_EQ(a.nbf, b.nbf);
}

RunState state_at(double time, std::int64_t step) {
    RunState s;
    s.time = time;
    s.legacy_time = time + 1e-5;
    s.step = step;
    s.dt = 1.25e-5;
    return s;
}

// ---- a minimal XML reader: enough to check well-formedness and walk the index ----------

struct Element {
    std::string tag;
    std::map<std::string, std::string> attrs;
    std::string text;
    std::vector<Element> children;
};

std::string unescape(const std::string& s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] != '&') {
            out += s[i];
            continue;
        }
        const std::size_t end = s.find(';', i);
        const std::string ent = s.substr(i + 1, end - i - 1);
        out += ent == "amp"    ? '&'
               : ent == "lt"   ? '<'
               : ent == "gt"   ? '>'
               : ent == "quot" ? '"'
                               : '\'';
        i = end;
    }
    return out;
}

// Throws std::runtime_error on anything that is not well-formed.
class MiniXml {
public:
    explicit MiniXml(std::string s) : s_(std::move(s)) {}

    Element parse() {
        skip_ws();
        if (s_.compare(pos_, 5, "<?xml") == 0) pos_ = need(s_.find("?>", pos_)) + 2;
        skip_ws();
        Element root = element();
        skip_ws();
        if (pos_ != s_.size()) throw std::runtime_error("content after the root element");
        return root;
    }

private:
    std::size_t need(std::size_t p) {
        if (p == std::string::npos) throw std::runtime_error("unexpected end of document");
        return p;
    }
    void skip_ws() {
        while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    }
    std::string name() {
        const std::size_t b = pos_;
        while (pos_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[pos_])) ||
                                    s_[pos_] == '_' || s_[pos_] == ':' || s_[pos_] == '-'))
            ++pos_;
        if (b == pos_) throw std::runtime_error("expected a name at " + std::to_string(b));
        return s_.substr(b, pos_ - b);
    }
    Element element() {
        if (s_[pos_] != '<') throw std::runtime_error("expected '<' at " + std::to_string(pos_));
        ++pos_;
        Element e;
        e.tag = name();
        for (;;) {
            skip_ws();
            need(pos_ < s_.size() ? pos_ : std::string::npos);
            if (s_.compare(pos_, 2, "/>") == 0) {
                pos_ += 2;
                return e;
            }
            if (s_[pos_] == '>') {
                ++pos_;
                break;
            }
            const std::string a = name();
            skip_ws();
            if (s_[pos_] != '=') throw std::runtime_error("expected '=' after " + a);
            ++pos_;
            skip_ws();
            const char q = s_[pos_];
            if (q != '"' && q != '\'') throw std::runtime_error("unquoted attribute " + a);
            const std::size_t end = need(s_.find(q, pos_ + 1));
            const std::string v = s_.substr(pos_ + 1, end - pos_ - 1);
            if (v.find('<') != std::string::npos) throw std::runtime_error("'<' in attribute");
            if (!e.attrs.emplace(a, unescape(v)).second) throw std::runtime_error("duplicate " + a);
            pos_ = end + 1;
        }
        for (;;) {
            const std::size_t lt = need(s_.find('<', pos_));
            e.text += unescape(s_.substr(pos_, lt - pos_));
            pos_ = lt;
            if (s_.compare(pos_, 2, "</") == 0) {
                pos_ += 2;
                const std::string closing = name();
                if (closing != e.tag)
                    throw std::runtime_error("</" + closing + "> closes <" + e.tag + ">");
                skip_ws();
                if (s_[pos_] != '>') throw std::runtime_error("bad closing tag");
                ++pos_;
                return e;
            }
            e.children.push_back(element());
        }
    }

    std::string s_;
    std::size_t pos_ = 0;
};

std::string slurp(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

std::vector<const Element*> children(const Element& e, const std::string& tag) {
    std::vector<const Element*> out;
    for (const Element& c : e.children) {
        if (c.tag == tag) out.push_back(&c);
    }
    return out;
}

void collect_data_items(const Element& e, std::vector<const Element*>& out) {
    if (e.tag == "DataItem" && e.attrs.count("Format")) out.push_back(&e);
    for (const Element& c : e.children) collect_data_items(c, out);
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\n");
    const auto e = s.find_last_not_of(" \t\n");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

}  // namespace

TEST(Hdf5Snapshot, RoundTripIsBitwise) {
    const fs::path dir = fresh_dir("roundtrip");
    const ParticleSet ps = synthetic(53, 12, 5);
    const auto colour = awkward_doubles(53, 11);
    const auto nx = awkward_doubles(53, 12);
    const auto nz = awkward_doubles(53, 13);
    const auto kappa = awkward_doubles(53, 14);
    const std::vector<ExtraField> extra = {{"colour", colour, ""},
                                           {"normal_x", nx, ""},
                                           {"normal_z", nz, ""},
                                           {"curvature", kappa, ""}};

    Hdf5Writer writer(dir, SimParams{}, "sphjet run test.toml");
    const RunState st = state_at(0.1 + 0.2, 1234567);
    const fs::path file = writer.write(ps, st, extra);
    EXPECT_EQ(file, dir / "snap_000000.h5");
    EXPECT_FALSE(fs::exists(dir / "snap_000000.h5.tmp"));

    const Snapshot s = read_snapshot(file);
    expect_same_particles(ps, s.particles);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(s.time), std::bit_cast<std::uint64_t>(st.time));
    EXPECT_EQ(s.legacy_time, st.legacy_time);
    EXPECT_EQ(s.dt, st.dt);
    EXPECT_EQ(s.step, st.step);
    EXPECT_EQ(s.index, 0);
    ASSERT_EQ(s.extra.size(), 4u);
    ASSERT_NE(s.field("colour"), nullptr);
    expect_bitwise(*s.field("colour"), colour, "colour");
    expect_bitwise(*s.field("normal_x"), nx, "normal_x");
    expect_bitwise(*s.field("normal_z"), nz, "normal_z");
    expect_bitwise(*s.field("curvature"), kappa, "curvature");

    // Units on every dataset.
    h5::File f = h5::open_file(file);
    h5::Group g = h5::open_group(f, "particles");
    const std::map<std::string, std::string> units = {
        {"x", "m"},        {"z", "m"},          {"u", "m/s"},    {"w", "m/s"},
        {"rho", "kg/m^3"}, {"p", "Pa"},         {"m", "kg"},     {"id", "1"},
        {"kind", "1"},     {"active", "1"},     {"colour", "1"}, {"normal_x", "1"},
        {"normal_z", "1"}, {"curvature", "1/m"}};
    for (const auto& [name, unit] : units) {
        h5::Dataset d(H5Dopen2(g, name.c_str(), H5P_DEFAULT));
        ASSERT_GE(d.get(), 0) << name;
        EXPECT_EQ(h5::read_attr_string(d, "units"), unit) << name;
    }
    fs::remove_all(dir);
}

TEST(Hdf5Snapshot, RunFileHoldsParametersVersionAndCommandLine) {
    const fs::path dir = fresh_dir("runfile");
    SimParams p;
    p.kernel = KernelType::CubicSpline;
    p.viscosity = ViscosityModel::Laminar;
    p.visc_value = 1e-6;
    p.h = 0.1 / 3.0;
    p.variable_dt = false;
    p.sigma = 0.0728;
    p.tensile_correction = 0;
    Hdf5Writer writer(dir, p, "sphjet run --case \"a b.toml\"");
    const SimParams q = read_run_params(dir / "run.h5");
    EXPECT_EQ(q.kernel, p.kernel);
    EXPECT_EQ(q.viscosity, p.viscosity);
    EXPECT_EQ(q.visc_value, p.visc_value);
    EXPECT_EQ(q.h, p.h);
    EXPECT_EQ(q.variable_dt, p.variable_dt);
    EXPECT_EQ(q.sigma, p.sigma);
    EXPECT_EQ(q.tensile_correction, p.tensile_correction);
    EXPECT_EQ(q.gz, p.gz);

    h5::File f = h5::open_file(dir / "run.h5");
    EXPECT_EQ(h5::read_attr_string(f, "command_line"), "sphjet run --case \"a b.toml\"");
    EXPECT_NE(h5::read_attr_string(f, "code_version").find(sphjet::h5::git_hash()), std::string::npos);
    h5::Group g = h5::open_group(f, "parameters");
    EXPECT_EQ(h5::read_attr_string(g, "kernel_name"), "cubic_spline");
    EXPECT_EQ(h5::read_attr_string(g, "visc_value_units"), "m^2/s");
    EXPECT_EQ(h5::read_attr_string(g, "h_units"), "m");
    EXPECT_EQ(h5::read_attr_string(g, "sigma_units"), "N/m");

    // Every snapshot carries the parameters too.
    writer.write(synthetic(4, 0, 0), state_at(0, 0));
    EXPECT_EQ(read_run_params(dir / "snap_000000.h5").h, p.h);
    fs::remove_all(dir);
}

TEST(Xdmf, IndexListsEverySnapshotWithPathsAndTimes) {
    const fs::path dir = fresh_dir("xdmf");
    Hdf5Writer writer(dir, SimParams{}, "test");
    const std::vector<double> times = {0.0, 0.1 + 0.2, 1.0 / 3.0};
    const std::vector<std::size_t> sizes = {20, 19, 17};  // particles removed on the way
    for (std::size_t k = 0; k < times.size(); ++k) {
        const ParticleSet ps = synthetic(sizes[k], 4, 2);
        const auto nx = awkward_doubles(sizes[k], 3);
        const std::vector<ExtraField> extra = {{"normal_x", nx, ""}, {"normal_z", nx, ""}};
        writer.write(ps, state_at(times[k], static_cast<std::int64_t>(10 * k)),
                     k == 2 ? std::span<const ExtraField>(extra) : std::span<const ExtraField>());

        // After each snapshot the index is complete: a run killed now can be opened.
        const Element root = MiniXml(slurp(writer.xdmf_path())).parse();
        ASSERT_EQ(root.tag, "Xdmf");
        EXPECT_EQ(root.attrs.at("Version"), "3.0");
        const auto domains = children(root, "Domain");
        ASSERT_EQ(domains.size(), 1u);
        const auto collections = children(*domains[0], "Grid");
        ASSERT_EQ(collections.size(), 1u);
        EXPECT_EQ(collections[0]->attrs.at("GridType"), "Collection");
        EXPECT_EQ(collections[0]->attrs.at("CollectionType"), "Temporal");
        const auto grids = children(*collections[0], "Grid");
        ASSERT_EQ(grids.size(), k + 1);
        EXPECT_FALSE(fs::exists(dir / "sphjet.xmf.tmp"));

        for (std::size_t j = 0; j <= k; ++j) {
            const Element& g = *grids[j];
            const std::string file = snapshot_file_name(static_cast<std::int64_t>(j));
            ASSERT_EQ(children(g, "Time").size(), 1u);
            EXPECT_EQ(std::stod(children(g, "Time")[0]->attrs.at("Value")), times[j]);  // exact
            const auto topo = children(g, "Topology");
            ASSERT_EQ(topo.size(), 1u);
            EXPECT_EQ(topo[0]->attrs.at("TopologyType"), "Polyvertex");
            EXPECT_EQ(topo[0]->attrs.at("NumberOfElements"), std::to_string(sizes[j]));
            EXPECT_EQ(children(g, "Geometry").size(), 1u);

            std::map<std::string, std::string> attr_type;
            for (const Element* a : children(g, "Attribute")) {
                attr_type[a->attrs.at("Name")] = a->attrs.at("AttributeType");
            }
            for (const char* s : {"x", "z", "u", "w", "rho", "p", "m", "id", "kind", "active"}) {
                EXPECT_EQ(attr_type[s], "Scalar") << s;
            }
            EXPECT_EQ(attr_type["velocity"], "Vector");
            EXPECT_EQ(attr_type.count("normal"), j == 2 ? 1u : 0u);

            // Every HDF reference names this snapshot's file and a dataset of the shape the
            // index states: [n] for scalars and the connectivity, [n x 3] for points and vectors.
            std::vector<const Element*> items;
            collect_data_items(g, items);
            // connectivity, points, velocity, 10 standard fields; snapshot 2 adds normal_x,
            // normal_z and the normal vector
            ASSERT_EQ(items.size(), 13u + (j == 2 ? 3u : 0u));
            h5::File f = h5::open_file(dir / file);
            for (const Element* item : items) {
                const std::string ref = trim(item->text);
                const auto colon = ref.find(':');
                ASSERT_NE(colon, std::string::npos) << ref;
                EXPECT_EQ(ref.substr(0, colon), file);
                const std::string path = ref.substr(colon + 1);
                h5::Dataset d(H5Dopen2(f, path.c_str(), H5P_DEFAULT));
                ASSERT_GE(d.get(), 0) << ref;
                h5::Dataspace sp(H5Dget_space(d));
                hsize_t dims[2] = {0, 0};
                const int rank = H5Sget_simple_extent_dims(sp, dims, nullptr);
                const std::string expected =
                    rank == 1 ? std::to_string(dims[0]) : fmt::format("{} {}", dims[0], dims[1]);
                EXPECT_EQ(item->attrs.at("Dimensions"), expected) << ref;
                EXPECT_EQ(dims[0], sizes[j]) << ref;
            }
        }
    }
    // The points the index shows are (x, 0, z), bit for bit.
    const ParticleSet ps = synthetic(sizes[1], 4, 2);
    h5::File f = h5::open_file(dir / "snap_000001.h5");
    h5::Dataset d(H5Dopen2(f, "/xdmf/points", H5P_DEFAULT));
    ASSERT_GE(d.get(), 0);
    std::vector<double> xyz(3 * sizes[1]);
    ASSERT_GE(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, xyz.data()), 0);
    for (std::size_t i = 0; i < sizes[1]; ++i) {
        EXPECT_EQ(std::bit_cast<std::uint64_t>(xyz[3 * i]), std::bit_cast<std::uint64_t>(ps.x[i]));
        EXPECT_EQ(std::bit_cast<std::uint64_t>(xyz[3 * i + 1]), 0u);
        EXPECT_EQ(std::bit_cast<std::uint64_t>(xyz[3 * i + 2]),
                  std::bit_cast<std::uint64_t>(ps.z[i]));
    }
    h5::Group g = h5::open_group(f, "xdmf");
    const auto vertices = h5::read_int64(g, "vertices", sizes[1]);
    for (std::size_t i = 0; i < sizes[1]; ++i) EXPECT_EQ(vertices[i], static_cast<std::int64_t>(i));
    fs::remove_all(dir);
}

TEST(Hdf5Writer, FreshRefusesOldSnapshotsResumeKeepsThem) {
    const fs::path dir = fresh_dir("modes");
    {
        Hdf5Writer w(dir, SimParams{}, "first");
        for (int k = 0; k < 4; ++k) w.write(synthetic(5, 0, 0), state_at(0.1 * k, 100 * k));
    }
    EXPECT_THROW(Hdf5Writer(dir, SimParams{}, "again"), InputError);

    // Restart from a checkpoint at step 150: snapshots 0 (step 0) and 1 (step 100) stay.
    Hdf5Writer w(dir, SimParams{}, "resume", Hdf5Writer::Mode::Resume, 150);
    ASSERT_EQ(w.snapshots().size(), 2u);
    EXPECT_EQ(w.write(synthetic(5, 0, 0), state_at(0.2, 200)), dir / "snap_000002.h5");
    EXPECT_EQ(read_snapshot(dir / "snap_000002.h5").step, 200);
    const std::string xmf = slurp(w.xdmf_path());
    EXPECT_NE(xmf.find("snap_000002.h5"), std::string::npos);
    EXPECT_EQ(xmf.find("snap_000003.h5"), std::string::npos);  // superseded, not indexed
    h5::File f = h5::open_file(dir / "run.h5");
    const std::string history = h5::read_attr_string(f, "history");
    EXPECT_NE(history.find("first"), std::string::npos);
    EXPECT_NE(history.find("resume (resumed at step 150)"), std::string::npos);

    Hdf5Writer o(dir, SimParams{}, "over", Hdf5Writer::Mode::Overwrite);
    EXPECT_FALSE(fs::exists(dir / "snap_000000.h5"));
    EXPECT_FALSE(fs::exists(dir / "sphjet.xmf"));
    fs::remove_all(dir);
}

TEST(Hdf5Writer, RejectsMismatchedArrays) {
    const fs::path dir = fresh_dir("bad");
    Hdf5Writer w(dir, SimParams{}, "x");
    ParticleSet ps = synthetic(5, 0, 0);
    ps.rho.pop_back();
    EXPECT_THROW(w.write(ps, RunState{}), std::invalid_argument);
    const ParticleSet good = synthetic(5, 0, 0);
    const std::vector<double> short_field(4, 1.0);
    const std::vector<ExtraField> bad_len = {{"colour", short_field, ""}};
    EXPECT_THROW(w.write(good, RunState{}, bad_len), std::invalid_argument);
    const std::vector<double> field(5, 1.0);
    const std::vector<ExtraField> bad_name = {{"rho", field, ""}};
    EXPECT_THROW(w.write(good, RunState{}, bad_name), std::invalid_argument);
    EXPECT_TRUE(w.snapshots().empty());
    EXPECT_FALSE(fs::exists(dir / "snap_000000.h5"));
    fs::remove_all(dir);
}

TEST(Hdf5Snapshot, MissingDatasetIsAnInputErrorNamingIt) {
    const fs::path dir = fresh_dir("missing");
    Hdf5Writer w(dir, SimParams{}, "x");
    const fs::path file = w.write(synthetic(6, 0, 0), RunState{});
    {
        h5::File f(H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
        ASSERT_GE(f.get(), 0);
        ASSERT_GE(H5Ldelete(f, "/particles/rho", H5P_DEFAULT), 0);
    }
    try {
        (void)read_snapshot(file);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("snap_000000.h5"), std::string::npos) << msg;
        EXPECT_NE(msg.find("/particles/rho"), std::string::npos) << msg;
        EXPECT_NE(msg.find("missing dataset"), std::string::npos) << msg;
    }
    EXPECT_THROW((void)read_snapshot(dir / "snap_000099.h5"), InputError);
    fs::remove_all(dir);
}

// Smoke check with the HDF5 tools: the file is valid HDF5 that h5dump understands.
TEST(Hdf5Snapshot, H5dumpReadsTheHeader) {
    if (std::system("command -v h5dump > /dev/null 2>&1") != 0) GTEST_SKIP() << "no h5dump";
    const fs::path dir = fresh_dir("h5dump");
    Hdf5Writer w(dir, SimParams{}, "x");
    const fs::path file = w.write(synthetic(8, 2, 1), state_at(0.5, 7));
    const fs::path out = dir / "header.txt";
    const std::string cmd = "h5dump -H '" + file.string() + "' > '" + out.string() + "' 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(out);
    const std::string header = slurp(out);
    for (const char* s :
         {"GROUP \"particles\"", "DATASET \"rho\"", "H5T_IEEE_F64LE", "H5T_STD_I64LE",
          "ATTRIBUTE \"units\"", "ATTRIBUTE \"time\"", "GROUP \"parameters\""}) {
        EXPECT_NE(header.find(s), std::string::npos) << s << "\n" << header;
    }
    fs::remove_all(dir);
}

TEST(Hdf5Snapshot, EmptySetRoundTrips) {
    const fs::path dir = fresh_dir("empty");
    Hdf5Writer w(dir, SimParams{}, "x");
    w.write(ParticleSet{}, state_at(1.0, 10));
    const Snapshot s = read_snapshot(dir / "snap_000000.h5");
    EXPECT_EQ(s.particles.size(), 0u);
    EXPECT_EQ(s.step, 10);
    EXPECT_NO_THROW((void)MiniXml(slurp(w.xdmf_path())).parse());
    fs::remove_all(dir);
}

// ---- the revolved copies of an axisymmetric snapshot ([output] revolution_sectors) -------

namespace {

// Rings at radii 0 (on the axis) to 0.05 m, with every field distinct.
ParticleSet rings(std::size_t n) {
    ParticleSet ps;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = static_cast<double>(i);
        ps.x.push_back(0.05 * t / static_cast<double>(n - 1));
        ps.z.push_back(0.1 - 0.003 * t);
        ps.u.push_back(0.25 - 0.1 * t);
        ps.w.push_back(-1.0 + 0.01 * t);
        ps.rho.push_back(1000.0 + t);
        ps.p.push_back(100.0 - 3.0 * t);
        ps.m.push_back(1e-4 * (1.0 + t) / 3.0);
        ps.id.push_back(static_cast<std::int64_t>(n - i) + (std::int64_t{1} << 40));
        ps.kind.push_back(i < 2 ? 1 : 2);
        ps.active.push_back(i % 5 == 3 ? 0 : 1);
    }
    ps.nb = 2;
    ps.nbf = 0;
    return ps;
}

SimParams axisymmetric() {
    SimParams p;
    p.geometry = Geometry::Axisymmetric;
    return p;
}

std::vector<double> read_vec3(hid_t f, const std::string& path, std::size_t rows) {
    h5::Dataset d(H5Dopen2(f, path.c_str(), H5P_DEFAULT));
    EXPECT_GE(d.get(), 0) << path;
    h5::Dataspace sp(H5Dget_space(d));
    hsize_t dims[2] = {0, 0};
    EXPECT_EQ(H5Sget_simple_extent_dims(sp, dims, nullptr), 2) << path;
    EXPECT_EQ(dims[0], rows) << path;
    EXPECT_EQ(dims[1], 3u) << path;
    std::vector<double> v(3 * rows);
    EXPECT_GE(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), 0) << path;
    return v;
}

// Every grid of every collection of the index at path: each HDF reference names the grid's
// file and a dataset of the dimensions the index states, [n] or [n x 3] with n the grid's
// point count. Returns the grid count per collection name.
std::map<std::string, std::size_t> check_index(const fs::path& dir, const fs::path& path) {
    std::map<std::string, std::size_t> count;
    const Element root = MiniXml(slurp(path)).parse();
    const auto domains = children(root, "Domain");
    EXPECT_EQ(domains.size(), 1u);
    for (const Element* c : children(*domains.at(0), "Grid")) {
        EXPECT_EQ(c->attrs.at("CollectionType"), "Temporal");
        for (const Element* g : children(*c, "Grid")) {
            ++count[c->attrs.at("Name")];
            const std::string n =
                children(*g, "Topology").at(0)->attrs.at("NumberOfElements");
            std::vector<const Element*> items;
            collect_data_items(*g, items);
            for (const Element* item : items) {
                const std::string ref = trim(item->text);
                const auto colon = ref.find(':');
                h5::File f = h5::open_file(dir / ref.substr(0, colon));
                const std::string ds_path = ref.substr(colon + 1);
                h5::Dataset d(H5Dopen2(f, ds_path.c_str(), H5P_DEFAULT));
                EXPECT_GE(d.get(), 0) << ref;
                if (d.get() < 0) continue;
                h5::Dataspace sp(H5Dget_space(d));
                hsize_t dims[2] = {0, 0};
                const int rank = H5Sget_simple_extent_dims(sp, dims, nullptr);
                const std::string got =
                    rank == 1 ? std::to_string(dims[0]) : fmt::format("{} {}", dims[0], dims[1]);
                EXPECT_EQ(item->attrs.at("Dimensions"), got) << ref;
                EXPECT_EQ(std::to_string(dims[0]), n) << ref;
            }
        }
    }
    return count;
}

}  // namespace

// Each ring becomes N points at phi_k = 2 pi k / N on the circle of its radius at its z (to
// 1e-15 relative: one rounding each in cos, sin and the products), its radial velocity turns
// with it, the scalar fields are repeated bit for bit, and the copies' masses m / N sum to the
// rings' mass (to 1e-13: a sum of 63 terms, each rounded once by the division and once by the
// sum, is within 64 x 1.1e-16 of the exact one).
TEST(Hdf5Revolution, CopiesLieOnTheRingsAndCarryMassOverN) {
    const fs::path dir = fresh_dir("revolve");
    const std::size_t n = 9;
    const int sectors = 7;
    const ParticleSet ps = rings(n);
    std::vector<double> nx(n), nz(n), colour(n, 0.5);
    for (std::size_t i = 0; i < n; ++i) {
        nx[i] = std::cos(0.3 * static_cast<double>(i));
        nz[i] = std::sin(0.3 * static_cast<double>(i));
    }
    const std::vector<ExtraField> extra = {
        {"colour", colour, ""}, {"normal_x", nx, ""}, {"normal_z", nz, ""}};
    Hdf5Writer w(dir, axisymmetric(), "revolve");
    w.set_revolution_sectors(sectors);
    const fs::path file = w.write(ps, state_at(0.125, 10), extra);

    const std::size_t rows = n * sectors;
    h5::File f = h5::open_file(file);
    h5::Group g = h5::open_group(f, "revolved");
    EXPECT_EQ(h5::read_attr_int64(g, "sectors"), sectors);
    EXPECT_EQ(h5::read_attr_int64(g, "n_points"), static_cast<std::int64_t>(rows));
    const auto pts = read_vec3(f, "/revolved/points", rows);
    const auto vel = read_vec3(f, "/revolved/velocity", rows);
    const auto nor = read_vec3(f, "/revolved/normal", rows);
    const double two_pi = 2.0 * std::acos(-1.0);
    for (int k = 0; k < sectors; ++k) {
        const double phi = two_pi * k / sectors;
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t r = k * n + i;
            const double* p = &pts[3 * r];
            EXPECT_NEAR(std::hypot(p[0], p[1]), ps.x[i], 1e-15 * ps.x[i]) << k << " " << i;
            EXPECT_EQ(p[2], ps.z[i]);
            if (ps.x[i] > 0) EXPECT_NEAR(std::remainder(std::atan2(p[1], p[0]) - phi, two_pi), 0.0, 1e-14);
            const double* v = &vel[3 * r];
            EXPECT_NEAR(v[0], ps.u[i] * std::cos(phi), 1e-15 * std::abs(ps.u[i]));
            EXPECT_NEAR(v[1], ps.u[i] * std::sin(phi), 1e-15 * std::abs(ps.u[i]));
            EXPECT_EQ(v[2], ps.w[i]);
            const double* q = &nor[3 * r];
            EXPECT_NEAR(q[0], nx[i] * std::cos(phi), 1e-15);
            EXPECT_NEAR(q[1], nx[i] * std::sin(phi), 1e-15);
            EXPECT_EQ(q[2], nz[i]);
        }
    }
    const auto repeated = [&](const auto& v) {
        std::remove_cvref_t<decltype(v)> out;
        for (int k = 0; k < sectors; ++k) out.insert(out.end(), v.begin(), v.end());
        return out;
    };
    expect_bitwise(h5::read_doubles(g, "x", rows), repeated(ps.x), "x");
    expect_bitwise(h5::read_doubles(g, "z", rows), repeated(ps.z), "z");
    expect_bitwise(h5::read_doubles(g, "u", rows), repeated(ps.u), "u");
    expect_bitwise(h5::read_doubles(g, "w", rows), repeated(ps.w), "w");
    expect_bitwise(h5::read_doubles(g, "rho", rows), repeated(ps.rho), "rho");
    expect_bitwise(h5::read_doubles(g, "p", rows), repeated(ps.p), "p");
    expect_bitwise(h5::read_int64(g, "id", rows), repeated(ps.id), "id");
    expect_bitwise(h5::read_int32(g, "kind", rows), repeated(ps.kind), "kind");
    expect_bitwise(h5::read_int32(g, "active", rows), repeated(ps.active), "active");
    expect_bitwise(h5::read_doubles(g, "colour", rows), repeated(colour), "colour");
    const auto m = h5::read_doubles(g, "m", rows);
    double ring_mass = 0.0, copy_mass = 0.0;
    for (double v : ps.m) ring_mass += v;
    for (std::size_t r = 0; r < rows; ++r) {
        EXPECT_EQ(m[r], ps.m[r % n] / sectors) << r;
        copy_mass += m[r];
    }
    EXPECT_NEAR(copy_mass, ring_mass, 1e-13 * ring_mass);
    const auto vertices = h5::read_int64(g, "vertices", rows);
    for (std::size_t r = 0; r < rows; ++r) EXPECT_EQ(vertices[r], static_cast<std::int64_t>(r));

    // The (r, z) snapshot is as without the copies.
    const Snapshot s = read_snapshot(file);
    expect_same_particles(ps, s.particles);
    EXPECT_EQ(s.extra.size(), 3u);

    // The index: "particles" as ever, then "revolved" with a grid of N n points per snapshot.
    const auto count = check_index(dir, w.xdmf_path());
    EXPECT_EQ(count.size(), 2u);
    EXPECT_EQ(count.at("particles"), 1u);
    EXPECT_EQ(count.at("revolved"), 1u);
    const std::string xmf = slurp(w.xdmf_path());
    EXPECT_NE(xmf.find("<Grid Name=\"snap_000000_revolved\""), std::string::npos) << xmf;
    EXPECT_LT(xmf.find("<Grid Name=\"particles\""), xmf.find("<Grid Name=\"revolved\""));
    fs::remove_all(dir);
}

// Without revolution the snapshot has no /revolved and the index one collection, written as
// xdmf::document(grids) writes it (the format before revolution existed).
TEST(Hdf5Revolution, OffLeavesSnapshotAndIndexAsBefore) {
    const fs::path dir = fresh_dir("revolve_off");
    Hdf5Writer w(dir, axisymmetric(), "off");
    const fs::path file = w.write(rings(6), state_at(0.5, 5));
    h5::File f = h5::open_file(file);
    EXPECT_FALSE(h5::has_link(f, "revolved"));
    EXPECT_EQ(check_index(dir, w.xdmf_path()).size(), 1u);
    std::vector<xdmf::Grid> grids;  // what the index holds, rebuilt by hand
    xdmf::Grid g;
    g.name = "snap_000000";
    g.h5_file = "snap_000000.h5";
    g.time = 0.5;
    g.n = 6;
    g.connectivity = "/xdmf/vertices";
    g.points = "/xdmf/points";
    g.fields.push_back({"velocity", "/xdmf/velocity", xdmf::NumberType::Float64, true});
    for (const char* s : {"x", "z", "u", "w", "rho", "p", "m"})
        g.fields.push_back({s, std::string("/particles/") + s, xdmf::NumberType::Float64, false});
    g.fields.push_back({"id", "/particles/id", xdmf::NumberType::Int64, false});
    g.fields.push_back({"kind", "/particles/kind", xdmf::NumberType::Int32, false});
    g.fields.push_back({"active", "/particles/active", xdmf::NumberType::Int32, false});
    grids.push_back(g);
    EXPECT_EQ(slurp(w.xdmf_path()), xdmf::document(std::span<const xdmf::Grid>(grids)));
    fs::remove_all(dir);
}

TEST(Hdf5Revolution, RefusesBadSectorCountsAndThePlanarGeometry) {
    const fs::path dir = fresh_dir("revolve_bad");
    Hdf5Writer axi(dir / "a", axisymmetric(), "x");
    EXPECT_THROW(axi.set_revolution_sectors(-1), std::invalid_argument);
    EXPECT_THROW(axi.set_revolution_sectors(kMaxRevolutionSectors + 1), std::invalid_argument);
    EXPECT_NO_THROW(axi.set_revolution_sectors(kMaxRevolutionSectors));
    EXPECT_EQ(axi.revolution_sectors(), kMaxRevolutionSectors);
    Hdf5Writer planar(dir / "p", SimParams{}, "x");
    EXPECT_THROW(planar.set_revolution_sectors(4), std::invalid_argument);
    EXPECT_NO_THROW(planar.set_revolution_sectors(0));
    fs::remove_all(dir);
}

// A resumed run re-indexes the kept snapshots with their copies: once it has written the
// snapshots after the checkpoint again, its index equals the uninterrupted run's, byte for
// byte. A snapshot written without copies (the setting changed) is listed in "particles" only.
TEST(Hdf5Revolution, ResumeReindexesTheCopies) {
    const fs::path dir = fresh_dir("revolve_resume");
    std::string uninterrupted;
    {
        Hdf5Writer w(dir, axisymmetric(), "first");
        w.set_revolution_sectors(3);
        for (int k = 0; k < 4; ++k) w.write(rings(5), state_at(0.1 * k, 100 * k));
        uninterrupted = slurp(w.xdmf_path());
    }
    {
        Hdf5Writer w(dir, axisymmetric(), "resume", Hdf5Writer::Mode::Resume, 150);
        ASSERT_EQ(w.snapshots().size(), 2u);
        EXPECT_EQ(w.snapshots()[1].revolution_sectors, 3);
        EXPECT_EQ(check_index(dir, w.xdmf_path()).at("revolved"), 2u);
        w.set_revolution_sectors(3);
        for (int k = 2; k < 4; ++k) w.write(rings(5), state_at(0.1 * k, 100 * k));
        EXPECT_EQ(slurp(w.xdmf_path()), uninterrupted);
    }
    Hdf5Writer w(dir, axisymmetric(), "again", Hdf5Writer::Mode::Resume, 250);
    w.write(rings(5), state_at(0.3, 300));  // revolution off from here
    const auto count = check_index(dir, w.xdmf_path());
    EXPECT_EQ(count.at("particles"), 4u);
    EXPECT_EQ(count.at("revolved"), 3u);
    EXPECT_EQ(slurp(w.xdmf_path()).find("snap_000003_revolved"), std::string::npos);
    fs::remove_all(dir);
}
