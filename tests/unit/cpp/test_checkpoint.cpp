// Checkpoints: a restart must continue bit for bit, so every array, the run state and the
// parameters must come back bitwise identical (no tolerance). A missing, truncated or
// corrupt checkpoint must give an InputError naming the file, never a crash or wrong numbers.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "io/checkpoint.hpp"
#include "io/h5_util.hpp"
#include "model/errors.hpp"

namespace fs = std::filesystem;
using namespace sphjet;

namespace {

fs::path fresh_dir(const std::string& name) {
    const fs::path d =
        fs::temp_directory_path() / ("sphjet_test_ckpt_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    return d;
}

std::vector<double> awkward_doubles(std::size_t n, std::uint64_t seed) {
    std::vector<double> v = {-0.0, std::numeric_limits<double>::denorm_min(),
                             std::bit_cast<double>(std::uint64_t{0x7ff8000000012345}),
                             std::numeric_limits<double>::infinity(), 0.1 + 0.2};
    std::mt19937_64 rng(seed);
    while (v.size() < n) v.push_back(std::bit_cast<double>(rng()));
    v.resize(n);
    return v;
}

std::uint64_t bits(double d) { return std::bit_cast<std::uint64_t>(d); }

ParticleSet synthetic(std::size_t n, std::size_t nb, std::size_t nbf) {
    ParticleSet ps;
    ps.x = awkward_doubles(n, 21);
    ps.z = awkward_doubles(n, 22);
    ps.u = awkward_doubles(n, 23);
    ps.w = awkward_doubles(n, 24);
    ps.rho = awkward_doubles(n, 25);
    ps.p = awkward_doubles(n, 26);
    ps.m = awkward_doubles(n, 27);
    for (std::size_t i = 0; i < n; ++i) {
        ps.id.push_back(static_cast<std::int64_t>(3 * i + 1));
        ps.kind.push_back(i < nbf ? 0 : i < nb ? 1 : 2);
        ps.active.push_back(i % 5 == 0 ? 0 : 1);
    }
    for (std::size_t i = 0; i < nb; ++i) {
        ps.wall.push_back(
            {static_cast<int>(i == 0 ? 0 : i - 1), static_cast<int>(i + 1 == nb ? i : i + 1)});
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
            ASSERT_EQ(bits(a[i]), bits(b[i])) << what << "[" << i << "]";
        } else {
            ASSERT_EQ(a[i], b[i]) << what << "[" << i << "]";
        }
    }
}

SimParams unusual_params() {
    SimParams p;
    p.kernel = KernelType::Gaussian;
    p.density_filter = DensityFilter::MLS;
    p.filter_period = 17;
    p.viscosity = ViscosityModel::Laminar;
    p.visc_value = 1.0e-6 / 3.0;
    p.wall_viscosity = 2e-6;
    p.boundary = BoundaryType::Repulsive;
    p.dbc_period = 3;
    p.lattice = Lattice::SimpleCubic;
    p.xsph_eps = 0.25;
    p.tensile_correction = 1;
    p.rho0 = 999.7;
    p.gamma = 7.0;
    p.h_swl = 0.3;
    p.coef = 12.5;
    p.B = p.coef * p.coef * p.rho0 * 9.81 * p.h_swl / p.gamma;
    p.lx = 1.61;
    p.lz = 0.8;
    p.dx = 0.01 / 3.0;
    p.dz = 0.01 / 7.0;
    p.h = 1.3 * std::sqrt(p.dx * p.dx + p.dz * p.dz);
    p.variable_dt = false;
    p.dt = 1e-5 / 3.0;
    p.cfl = 0.3;
    p.tmax = 2.5;
    p.out = 0.01;
    p.trec_ini = 0.001;
    p.gx = 0.1;
    p.gz = -9.80665;
    p.sigma = 0.0728;
    p.st_delta = SurfaceTensionDelta::ColourGradient;  // not the default
    p.gate_vx = 0.01 / 3.0;
    p.gate_vz = 1.5;
    p.gate_t_start = 0.02;
    p.gate_z_cap = 0.6 + 1e-3 / 7.0;
    p.drive_u = 0.07 / 3.0;
    p.drive_x0 = 0.04 + 1e-3 / 3.0;
    p.drive_z0 = 0.41;
    p.drive_ex = 1.0;
    p.drive_ez = 0.0;
    p.drive_half_width = 0.005 + 1e-3 / 7.0;
    p.drive_eps = 0.01 / 3.0;
    p.drive_omega = 2000.0 / 7.0;
    p.drive_release_crossing = true;  // not the default
    p.drive_release_landed = true;    // not the default
    p.domain_box = true;
    p.geometry = Geometry::Axisymmetric;  // not the default
    p.periodic_z = true;
    p.axis_pair = AxisPair::Rings;  // not the default
    p.rings_curvature = RingsCurvature::Own;  // not the default
    p.renormalise_ring_continuity = true;      // not the default
    p.curvature_normals = CurvatureNormals::SurfaceBand;  // not the default
    p.curvature = CurvatureModel::SurfaceFit;  // not the default
    return p;
}

void expect_same_params(const SimParams& a, const SimParams& b) {
    EXPECT_EQ(a.kernel, b.kernel);
    EXPECT_EQ(a.integrator, b.integrator);
    EXPECT_EQ(a.density_filter, b.density_filter);
    EXPECT_EQ(a.filter_period, b.filter_period);
    EXPECT_EQ(a.viscosity, b.viscosity);
    EXPECT_EQ(bits(a.visc_value), bits(b.visc_value));
    EXPECT_EQ(bits(a.wall_viscosity), bits(b.wall_viscosity));
    EXPECT_EQ(a.boundary, b.boundary);
    EXPECT_EQ(a.dbc_period, b.dbc_period);
    EXPECT_EQ(a.lattice, b.lattice);
    EXPECT_EQ(bits(a.xsph_eps), bits(b.xsph_eps));
    EXPECT_EQ(a.tensile_correction, b.tensile_correction);
    for (const auto& [x, y] : {std::pair{a.rho0, b.rho0},
                               {a.gamma, b.gamma},
                               {a.h_swl, b.h_swl},
                               {a.coef, b.coef},
                               {a.B, b.B},
                               {a.lx, b.lx},
                               {a.lz, b.lz},
                               {a.dx, b.dx},
                               {a.dz, b.dz},
                               {a.h, b.h},
                               {a.dt, b.dt},
                               {a.cfl, b.cfl},
                               {a.tmax, b.tmax},
                               {a.out, b.out},
                               {a.trec_ini, b.trec_ini},
                               {a.gx, b.gx},
                               {a.gz, b.gz},
                               {a.sigma, b.sigma},
                               {a.gate_vx, b.gate_vx},
                               {a.gate_vz, b.gate_vz},
                               {a.gate_t_start, b.gate_t_start},
                               {a.gate_z_cap, b.gate_z_cap},
                               {a.drive_u, b.drive_u},
                               {a.drive_x0, b.drive_x0},
                               {a.drive_z0, b.drive_z0},
                               {a.drive_ex, b.drive_ex},
                               {a.drive_ez, b.drive_ez},
                               {a.drive_half_width, b.drive_half_width},
                               {a.drive_eps, b.drive_eps},
                               {a.drive_omega, b.drive_omega}}) {
        EXPECT_EQ(bits(x), bits(y));
    }
    EXPECT_EQ(a.variable_dt, b.variable_dt);
    EXPECT_EQ(a.st_delta, b.st_delta);
    EXPECT_EQ(a.drive_release_crossing, b.drive_release_crossing);
    EXPECT_EQ(a.drive_release_landed, b.drive_release_landed);
    EXPECT_EQ(a.domain_box, b.domain_box);
    EXPECT_EQ(a.geometry, b.geometry);
    EXPECT_EQ(a.periodic_z, b.periodic_z);
    EXPECT_EQ(a.axis_pair, b.axis_pair);
    EXPECT_EQ(a.rings_curvature, b.rings_curvature);
    EXPECT_EQ(a.renormalise_ring_continuity, b.renormalise_ring_continuity);
    EXPECT_EQ(a.curvature_normals, b.curvature_normals);
    EXPECT_EQ(a.curvature, b.curvature);
}

RunState unusual_state() {
    RunState s;
    s.time = 0.1 + 0.2;
    s.legacy_time = 0.30000000000001;
    s.step = (std::int64_t{1} << 33) + 5;
    s.dt = 1.0 / 3.0 * 1e-4;
    s.dt_f = 2e-4 / 7.0;
    s.dt_cv = std::numeric_limits<double>::denorm_min();
    s.dt_new = -0.0;
    s.dbc_counter = 2;
    s.n_outputs = 31;
    s.n_removed = 4;
    s.renormalise_reach = 0.0123456789012345;
    return s;
}

void write_sample(const fs::path& dir) {
    const auto prev_rho = awkward_doubles(40, 31);
    write_checkpoint(dir, synthetic(40, 14, 6), unusual_state(), unusual_params(),
                     std::vector<ExtraField>{{"rho_old", prev_rho, "kg/m^3"}});
}

// A sample checkpoint in dir without the named attributes of one group (an older or damaged file).
void write_sample_without(const fs::path& dir, const char* group, std::initializer_list<const char*> names) {
    write_sample(dir);
    h5::File f(H5Fopen((dir / "checkpoint.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
    h5::Group g(H5Gopen2(f, group, H5P_DEFAULT));
    for (const char* name : names) ASSERT_GE(H5Adelete(g, name), 0) << name;
}

// Reading must fail with an InputError that names the checkpoint file.
void expect_input_error(const fs::path& dir, const std::string& also = {}) {
    try {
        (void)read_checkpoint(dir);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("checkpoint.h5"), std::string::npos) << msg;
        if (!also.empty()) {
            EXPECT_NE(msg.find(also), std::string::npos) << msg;
        }
    }
}

}  // namespace

// The checkpoint stores every field of RunState by name. When it grows, add the new field to
// the checkpoint (visit_state in io/checkpoint.cpp) and to this test, then update the size
// here. SimParams' members go through their rows in model/case_params.cpp, and
// CaseParams.AttributesCoverSimParams (test_case_params.cpp) fails for a member without one.
TEST(Checkpoint, KnowsEveryFieldOfTheStructs) {
    EXPECT_EQ(sizeof(RunState), 88u) << "RunState changed: update the checkpoint";
}

TEST(Checkpoint, RoundTripIsBitwise) {
    const fs::path dir = fresh_dir("roundtrip");
    const ParticleSet ps = synthetic(40, 14, 6);
    const RunState st = unusual_state();
    const SimParams prm = unusual_params();
    const auto prev_rho = awkward_doubles(40, 31);
    const std::vector<double> scalar_state = {42.0, -1.5};
    const std::vector<ExtraField> extra = {{"rho_old", prev_rho, "kg/m^3"},
                                           {"analysis_state", scalar_state, ""}};
    write_checkpoint(dir, ps, st, prm, extra);
    EXPECT_TRUE(fs::exists(dir / "checkpoint.h5"));
    EXPECT_FALSE(fs::exists(dir / "checkpoint.h5.tmp"));

    const Checkpoint c = read_checkpoint(dir);
    const ParticleSet& q = c.particles;
    expect_bitwise(ps.x, q.x, "x");
    expect_bitwise(ps.z, q.z, "z");
    expect_bitwise(ps.u, q.u, "u");
    expect_bitwise(ps.w, q.w, "w");
    expect_bitwise(ps.rho, q.rho, "rho");
    expect_bitwise(ps.p, q.p, "p");
    expect_bitwise(ps.m, q.m, "m");
    expect_bitwise(ps.id, q.id, "id");
    expect_bitwise(ps.kind, q.kind, "kind");
    expect_bitwise(ps.active, q.active, "active");
    ASSERT_EQ(ps.wall.size(), q.wall.size());
    for (std::size_t i = 0; i < ps.wall.size(); ++i) {
        EXPECT_EQ(ps.wall[i].prev, q.wall[i].prev);
        EXPECT_EQ(ps.wall[i].next, q.wall[i].next);
    }
    EXPECT_EQ(q.nb, ps.nb);
    EXPECT_EQ(q.nbf, ps.nbf);

    EXPECT_EQ(bits(c.state.time), bits(st.time));
    EXPECT_EQ(bits(c.state.legacy_time), bits(st.legacy_time));
    EXPECT_EQ(c.state.step, st.step);
    EXPECT_EQ(bits(c.state.dt), bits(st.dt));
    EXPECT_EQ(bits(c.state.dt_f), bits(st.dt_f));
    EXPECT_EQ(bits(c.state.dt_cv), bits(st.dt_cv));
    EXPECT_EQ(bits(c.state.dt_new), bits(st.dt_new));
    EXPECT_EQ(c.state.dbc_counter, st.dbc_counter);
    EXPECT_EQ(c.state.n_outputs, st.n_outputs);
    EXPECT_EQ(c.state.n_removed, st.n_removed);
    EXPECT_EQ(bits(c.state.renormalise_reach), bits(st.renormalise_reach));

    expect_same_params(prm, c.params);
    ASSERT_NE(c.array("rho_old"), nullptr);
    expect_bitwise(*c.array("rho_old"), prev_rho, "rho_old");
    ASSERT_NE(c.array("analysis_state"), nullptr);
    expect_bitwise(*c.array("analysis_state"), scalar_state, "analysis_state");
    EXPECT_NE(c.code_version.find(sphjet::h5::git_hash()), std::string::npos);

    // The file itself can be named too.
    EXPECT_EQ(read_checkpoint(dir / "checkpoint.h5").state.step, st.step);
    fs::remove_all(dir);
}

TEST(Checkpoint, EmptySetAndNoWallsRoundTrip) {
    const fs::path dir = fresh_dir("empty");
    write_checkpoint(dir, ParticleSet{}, RunState{}, SimParams{});
    const Checkpoint c = read_checkpoint(dir);
    EXPECT_EQ(c.particles.size(), 0u);
    EXPECT_TRUE(c.particles.wall.empty());
    EXPECT_TRUE(c.extra.empty());
    fs::remove_all(dir);
}

TEST(Checkpoint, RewriteReplacesTheOldOne) {
    const fs::path dir = fresh_dir("rewrite");
    write_sample(dir);
    RunState later = unusual_state();
    later.step += 1000;
    write_checkpoint(dir, synthetic(10, 4, 2), later, SimParams{});
    const Checkpoint c = read_checkpoint(dir);
    EXPECT_EQ(c.state.step, later.step);
    EXPECT_EQ(c.particles.size(), 10u);
    EXPECT_EQ(c.array("rho_old"), nullptr);
    fs::remove_all(dir);
}

TEST(Checkpoint, MissingFileIsAnInputError) {
    const fs::path dir = fresh_dir("missingfile");
    fs::create_directories(dir);
    expect_input_error(dir, "no such file");
    fs::remove_all(dir);
}

TEST(Checkpoint, TruncatedFileIsAnInputError) {
    const fs::path dir = fresh_dir("truncated");
    write_sample(dir);
    const fs::path file = dir / "checkpoint.h5";
    const auto size = fs::file_size(file);
    const fs::path copy = dir / "full.h5";
    fs::copy_file(file, copy);
    for (const std::uintmax_t keep :
         {std::uintmax_t{0}, std::uintmax_t{7}, std::uintmax_t{600}, size / 2, size - 1}) {
        fs::copy_file(copy, file, fs::copy_options::overwrite_existing);
        fs::resize_file(file, keep);
        SCOPED_TRACE("kept " + std::to_string(keep) + " of " + std::to_string(size) + " bytes");
        expect_input_error(dir);
    }
    fs::remove_all(dir);
}

TEST(Checkpoint, GarbageFileIsAnInputError) {
    const fs::path dir = fresh_dir("garbage");
    fs::create_directories(dir);
    std::ofstream(dir / "checkpoint.h5") << "this is not HDF5\n";
    expect_input_error(dir, "not an HDF5 file");
    fs::remove_all(dir);
}

// One flipped bit in the raw data of rho: the Fletcher-32 checksum must catch it.
TEST(Checkpoint, CorruptedDataIsAnInputError) {
    const fs::path dir = fresh_dir("bitflip");
    write_sample(dir);
    const fs::path file = dir / "checkpoint.h5";
    haddr_t addr = 0;
    {
        h5::File f = h5::open_file(file);
        h5::Dataset d(H5Dopen2(f, "/particles/rho", H5P_DEFAULT));
        ASSERT_GE(d.get(), 0);
        hsize_t offset = 0, size = 0;
        unsigned mask = 0;
        h5::Dataspace sp(H5Dget_space(d));
        ASSERT_GE(H5Dget_chunk_info(d, sp, 0, &offset, &mask, &addr, &size), 0);
        ASSERT_GT(size, 100u);
    }
    {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekg(static_cast<std::streamoff>(addr + 100));
        char c = 0;
        f.read(&c, 1);
        c ^= 0x10;
        f.seekp(static_cast<std::streamoff>(addr + 100));
        f.write(&c, 1);
    }
    expect_input_error(dir, "/particles/rho");
    fs::remove_all(dir);
}

TEST(Checkpoint, MissingDatasetOrAttributeIsNamed) {
    const fs::path dir = fresh_dir("missingobj");
    const fs::path file = dir / "checkpoint.h5";
    write_sample(dir);
    {
        h5::File f(H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
        ASSERT_GE(H5Ldelete(f, "/particles/wall_next", H5P_DEFAULT), 0);
    }
    expect_input_error(dir, "/particles/wall_next");

    write_sample_without(dir, "/run_state", {"dbc_counter"});
    expect_input_error(dir, "dbc_counter");

    write_sample_without(dir, "/parameters", {"sigma"});
    expect_input_error(dir, "sigma");

    // st_delta came later: a file without it reads as the pressure-consistent delta, the only
    // surface-tension model of the builds that wrote such files.
    write_sample_without(dir, "/parameters", {"st_delta", "st_delta_name"});
    EXPECT_EQ(read_checkpoint(dir).params.st_delta, SurfaceTensionDelta::PressureConsistent);

    // So did the gate's motion: a file without it has no gate (all zero).
    write_sample_without(dir, "/parameters", {"gate_vx", "gate_vz", "gate_t_start", "gate_z_cap"});
    const SimParams old = read_checkpoint(dir).params;
    EXPECT_EQ(old.gate_vx, 0.0);
    EXPECT_EQ(old.gate_vz, 0.0);
    EXPECT_EQ(old.gate_t_start, 0.0);
    EXPECT_EQ(old.gate_z_cap, 0.0);

    // And the driven nozzle and the box domain of the jets: without them, no nozzle.
    write_sample_without(dir, "/parameters", {"drive_u", "drive_x0", "drive_z0", "drive_ex", "drive_ez",
                                              "drive_half_width", "drive_eps", "drive_omega", "domain_box"});
    const SimParams pre_jet = read_checkpoint(dir).params;
    EXPECT_EQ(pre_jet.drive_u, 0.0);
    // and a file from before nozzle.release: the step's release
    write_sample_without(dir, "/parameters", {"drive_release_crossing", "drive_release_landed"});
    EXPECT_FALSE(read_checkpoint(dir).params.drive_release_crossing);
    EXPECT_FALSE(read_checkpoint(dir).params.drive_release_landed);
    EXPECT_FALSE(pre_jet.domain_box);

    // A run state from before the renormalised continuity's reach: everywhere (0), as then.
    write_sample_without(dir, "/run_state", {"renormalise_reach"});
    EXPECT_EQ(read_checkpoint(dir).state.renormalise_reach, 0.0);

    // And the axisymmetric pair: without it, the smoothed-radius pair (the only one before).
    write_sample_without(dir, "/parameters", {"axis_pair", "rings_curvature"});
    EXPECT_EQ(read_checkpoint(dir).params.axis_pair, AxisPair::SmoothedRadius);
    EXPECT_EQ(read_checkpoint(dir).params.rings_curvature, RingsCurvature::NeighbourMean);
    fs::remove_all(dir);
}

// The run's output clock (`sphjet run --legacy-clock`), which a resumed run takes from its
// checkpoint: written and read back for both clocks; unset in a file written before it was kept
// (the resumed run then takes the command line's); an unknown value is an InputError naming it.
TEST(Checkpoint, KeepsTheOutputClock) {
    const fs::path dir = fresh_dir("clock");
    for (const bool legacy : {false, true}) {
        write_checkpoint(dir, synthetic(10, 4, 2), unusual_state(), SimParams{}, {}, legacy);
        const Checkpoint c = read_checkpoint(dir);
        ASSERT_TRUE(c.legacy_clock.has_value());
        EXPECT_EQ(*c.legacy_clock, legacy);
    }
    const fs::path file = dir / "checkpoint.h5";
    {
        h5::File f(H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
        ASSERT_GE(H5Adelete(f, "output_clock"), 0);
    }
    EXPECT_FALSE(read_checkpoint(dir).legacy_clock.has_value());
    {
        h5::File f(H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT));
        h5::write_attr(f, "output_clock", std::string("sundial"));
    }
    expect_input_error(dir, "output_clock");
    fs::remove_all(dir);
}

TEST(Checkpoint, RejectsMismatchedArraysAndKeepsTheOldFile) {
    const fs::path dir = fresh_dir("mismatch");
    write_sample(dir);
    ParticleSet bad = synthetic(10, 0, 0);
    bad.p.pop_back();
    EXPECT_THROW(write_checkpoint(dir, bad, RunState{}, SimParams{}), std::invalid_argument);
    EXPECT_EQ(read_checkpoint(dir).state.step, unusual_state().step);
    fs::remove_all(dir);
}
