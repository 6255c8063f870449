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
#include <sstream>
#include <string>
#include <vector>

#include "config/errors.hpp"
#include "io/h5_util.hpp"
#include "io/hdf5_output.hpp"

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
