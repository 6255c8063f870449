// The modern (TOML) case format: parsing, validation messages, overrides, round trip and the
// documented mappings (c0 <-> coef/h_swl, mu -> alpha). Numbers are compared exactly where the
// format promises exactness (a round trip, a value copied through) and to 1e-12 relative where
// a formula is evaluated (one or two roundings of double arithmetic).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "config/legacy_case.hpp"
#include "config/modern_case.hpp"
#include "core/jet_run.hpp"
#include "model/errors.hpp"

namespace sphjet {
namespace {

// The paper's dam break with an obstacle (the legacy obstacle_wendland case), every key set,
// plus a disc and a square of fluid and surface tension so that every section is exercised.
const char* const kFull = R"(format_version = 1

[numerics]
kernel = "wendland"
integrator = "predictor_corrector"
density_filter = "mls"
filter_period = 40
viscosity = "artificial"
alpha = 0.3
xsph_eps = 0.5
tensile_correction = "off"
boundary = "repulsive"
dbc_period = 15
wall_viscosity = 1.0e-5
lattice = "bcc"

[fluid]
rho0 = 1000.0
gamma = 7.0
coef = 10.0
h_swl = 0.292

[[fluid.block]]
xmin = 0.0
xmax = 0.146
zmin = 0.002
zmax = 0.292

[[fluid.disc]]
xc = 0.45
zc = 0.45
radius = 0.02
u0 = -0.5
w0 = 0.25

[[fluid.square]]
xc = 0.5
zc = 0.3
side = 0.04

[surface_tension]
sigma = 0.072

[gravity]
gx = 0.0
gz = -9.81

[domain]
lx = 0.584
lz = 0.584
wall_left = true
wall_right = true
wall_bottom = true
wall_top = false
floor_inclination_deg = 0.0

[resolution]
dx = 0.002
dz = 0.002
h_coefficient = 0.92

[time]
tmax = 0.6
dt = 1.0e-4
variable_dt = true
cfl = 0.2
out = 0.05
trec_ini = 0.0

[[obstacle]]
shape = "rectangle"
kind = "walls"
density = 1
xmin = 0.292
xmax = 0.316
zmin = 0.0
zmax = 0.048
beta_deg = 90.0

[output]
format = "hdf5"
checkpoint_every_steps = 5000
checkpoint_every_minutes = 0.0
remove_out_of_domain = false
rho_min_factor = 0.8
rho_max_factor = 1.2
dt_min = 1.0e-8
)";

// A small valid case; tests change one line of it.
const char* const kMinimal = R"([fluid]
c0 = 17.0
[[fluid.block]]
xmin = 0.0
xmax = 0.1
zmin = 0.0
zmax = 0.2
[domain]
lx = 0.5
lz = 0.5
[resolution]
dx = 0.002
h_over_dx = 1.3
[time]
tmax = 0.6
out = 0.05
cfl = 0.2
[surface_tension]
sigma = 0.072
)";

std::string replace_line(std::string text, const std::string& from, const std::string& to) {
    const auto pos = text.find(from);
    if (pos == std::string::npos) ADD_FAILURE() << "test setup: '" << from << "' not in the text";
    else text.replace(pos, from.size(), to);
    return text;
}

// The message of the InputError that parsing throws (empty and a test failure if none).
std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
    try {
        (void)parse_modern_case(text, "case.toml", overrides);
    } catch (const InputError& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not an InputError: " << e.what();
        return e.what();
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return {};
}

// Every field of two specs, except `source`.
void expect_same(const CaseSpec& a, const CaseSpec& b) {
    const SimParams &p = a.params, &q = b.params;
    EXPECT_EQ(p.kernel, q.kernel);
    EXPECT_EQ(p.geometry, q.geometry);
    EXPECT_EQ(p.periodic_z, q.periodic_z);
    EXPECT_EQ(p.axis_pair, q.axis_pair);
    EXPECT_EQ(p.rings_curvature, q.rings_curvature);
    EXPECT_EQ(p.curvature_normals, q.curvature_normals);
    EXPECT_EQ(p.curvature, q.curvature);
    EXPECT_EQ(p.integrator, q.integrator);
    EXPECT_EQ(p.density_filter, q.density_filter);
    EXPECT_EQ(p.filter_period, q.filter_period);
    EXPECT_EQ(p.viscosity, q.viscosity);
    EXPECT_EQ(p.visc_value, q.visc_value);
    EXPECT_EQ(p.wall_viscosity, q.wall_viscosity);
    EXPECT_EQ(p.boundary, q.boundary);
    EXPECT_EQ(p.dbc_period, q.dbc_period);
    EXPECT_EQ(p.lattice, q.lattice);
    EXPECT_EQ(p.xsph_eps, q.xsph_eps);
    EXPECT_EQ(p.tensile_correction, q.tensile_correction);
    EXPECT_EQ(p.rho0, q.rho0);
    EXPECT_EQ(p.gamma, q.gamma);
    EXPECT_EQ(p.h_swl, q.h_swl);
    EXPECT_EQ(p.coef, q.coef);
    EXPECT_EQ(p.B, q.B);
    EXPECT_EQ(p.lx, q.lx);
    EXPECT_EQ(p.lz, q.lz);
    EXPECT_EQ(p.dx, q.dx);
    EXPECT_EQ(p.dz, q.dz);
    EXPECT_EQ(p.h, q.h);
    EXPECT_EQ(p.variable_dt, q.variable_dt);
    EXPECT_EQ(p.dt, q.dt);
    EXPECT_EQ(p.cfl, q.cfl);
    EXPECT_EQ(p.tmax, q.tmax);
    EXPECT_EQ(p.out, q.out);
    EXPECT_EQ(p.trec_ini, q.trec_ini);
    EXPECT_EQ(p.gx, q.gx);
    EXPECT_EQ(p.gz, q.gz);
    EXPECT_EQ(p.sigma, q.sigma);
    EXPECT_EQ(a.floor_beta_deg, b.floor_beta_deg);
    EXPECT_EQ(a.wall_left, b.wall_left);
    EXPECT_EQ(a.wall_right, b.wall_right);
    EXPECT_EQ(a.wall_bottom, b.wall_bottom);
    EXPECT_EQ(a.wall_top, b.wall_top);
    ASSERT_EQ(a.obstacles.size(), b.obstacles.size());
    for (std::size_t i = 0; i < a.obstacles.size(); ++i) {
        const auto &o = a.obstacles[i], &r = b.obstacles[i];
        EXPECT_EQ(o.shape, r.shape);
        EXPECT_EQ(o.kind, r.kind);
        EXPECT_EQ(o.density, r.density);
        EXPECT_EQ(o.r.xmin, r.r.xmin);
        EXPECT_EQ(o.r.xmax, r.r.xmax);
        EXPECT_EQ(o.r.zmin, r.r.zmin);
        EXPECT_EQ(o.r.zmax, r.r.zmax);
        EXPECT_EQ(o.beta_deg, r.beta_deg);
    }
    ASSERT_EQ(a.fluid_blocks.size(), b.fluid_blocks.size());
    for (std::size_t i = 0; i < a.fluid_blocks.size(); ++i) {
        const auto &o = a.fluid_blocks[i], &r = b.fluid_blocks[i];
        EXPECT_EQ(o.r.xmin, r.r.xmin);
        EXPECT_EQ(o.r.xmax, r.r.xmax);
        EXPECT_EQ(o.r.zmin, r.r.zmin);
        EXPECT_EQ(o.r.zmax, r.r.zmax);
        EXPECT_EQ(o.u0, r.u0);
        EXPECT_EQ(o.w0, r.w0);
    }
    ASSERT_EQ(a.fluid_discs.size(), b.fluid_discs.size());
    for (std::size_t i = 0; i < a.fluid_discs.size(); ++i) {
        const auto &o = a.fluid_discs[i], &r = b.fluid_discs[i];
        EXPECT_EQ(o.xc, r.xc);
        EXPECT_EQ(o.zc, r.zc);
        EXPECT_EQ(o.radius, r.radius);
        EXPECT_EQ(o.u0, r.u0);
        EXPECT_EQ(o.w0, r.w0);
    }
    ASSERT_EQ(a.fluid_squares.size(), b.fluid_squares.size());
    for (std::size_t i = 0; i < a.fluid_squares.size(); ++i) {
        const auto &o = a.fluid_squares[i], &r = b.fluid_squares[i];
        EXPECT_EQ(o.xc, r.xc);
        EXPECT_EQ(o.zc, r.zc);
        EXPECT_EQ(o.side, r.side);
        EXPECT_EQ(o.u0, r.u0);
        EXPECT_EQ(o.w0, r.w0);
    }
    ASSERT_EQ(a.walls.size(), b.walls.size());
    for (std::size_t i = 0; i < a.walls.size(); ++i) {
        EXPECT_EQ(a.walls[i].x, b.walls[i].x);
        EXPECT_EQ(a.walls[i].height, b.walls[i].height);
    }
    EXPECT_EQ(a.legacy_fill, b.legacy_fill);
    EXPECT_EQ(a.legacy.restart, b.legacy.restart);
    EXPECT_EQ(a.legacy.detail_out, b.legacy.detail_out);
    EXPECT_EQ(a.legacy.detail_start, b.legacy.detail_start);
    EXPECT_EQ(a.legacy.detail_end, b.legacy.detail_end);
    EXPECT_EQ(a.legacy.vorticity, b.legacy.vorticity);
    EXPECT_EQ(a.legacy.compiler, b.legacy.compiler);
    EXPECT_EQ(a.legacy.xz_precision, b.legacy.xz_precision);
    EXPECT_EQ(a.legacy.h_coefficient, b.legacy.h_coefficient);
    EXPECT_EQ(a.output.format, b.output.format);
    EXPECT_EQ(a.output.checkpoint_every_steps, b.output.checkpoint_every_steps);
    EXPECT_EQ(a.output.checkpoint_every_minutes, b.output.checkpoint_every_minutes);
    EXPECT_EQ(a.output.remove_out_of_domain, b.output.remove_out_of_domain);
    EXPECT_EQ(a.output.rho_min_factor, b.output.rho_min_factor);
    EXPECT_EQ(a.output.rho_max_factor, b.output.rho_max_factor);
    EXPECT_EQ(a.output.dt_min, b.output.dt_min);
    EXPECT_EQ(a.output.revolution_sectors, b.output.revolution_sectors);
}

std::string read_text(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// ------------------------------------------------------------------------------------------

TEST(ModernCase, ParsesFullExample) {
    const CaseSpec s = parse_modern_case(kFull, "full.toml");
    const SimParams& p = s.params;
    EXPECT_EQ(s.source, "full.toml");
    EXPECT_EQ(p.kernel, KernelType::Wendland);
    EXPECT_EQ(p.integrator, Integrator::PredictorCorrector);
    EXPECT_EQ(p.density_filter, DensityFilter::MLS);
    EXPECT_EQ(p.filter_period, 40);
    EXPECT_EQ(p.viscosity, ViscosityModel::Artificial);
    EXPECT_EQ(p.visc_value, 0.3);
    EXPECT_EQ(p.xsph_eps, 0.5);
    EXPECT_EQ(p.tensile_correction, 0);
    EXPECT_EQ(p.boundary, BoundaryType::Repulsive);
    EXPECT_EQ(p.dbc_period, 15);
    EXPECT_EQ(p.wall_viscosity, 1e-5);
    EXPECT_EQ(p.lattice, Lattice::BodyCentred);
    EXPECT_EQ(p.rho0, 1000.0);
    EXPECT_EQ(p.gamma, 7.0);
    EXPECT_EQ(p.coef, 10.0);
    EXPECT_EQ(p.h_swl, 0.292);
    EXPECT_EQ(p.sigma, 0.072);
    EXPECT_EQ(p.gx, 0.0);
    EXPECT_EQ(p.gz, -9.81);
    EXPECT_EQ(p.lx, 0.584);
    EXPECT_EQ(p.lz, 0.584);
    EXPECT_TRUE(s.wall_left && s.wall_right && s.wall_bottom && !s.wall_top);
    EXPECT_EQ(p.dx, 0.002);
    EXPECT_EQ(p.dz, 0.002);
    // Legacy h = coef sqrt(dx^2 + dz^2) = 0.92 * 0.002 * sqrt(2) = 1.3011 dx (README of the
    // legacy runs); one rounding of sqrt and two products: 1e-12 relative.
    EXPECT_NEAR(p.h, 0.92 * std::sqrt(2.0) * 0.002, 1e-12 * p.h);
    EXPECT_NEAR(p.h / p.dx, 1.3011, 1e-4);
    EXPECT_EQ(p.tmax, 0.6);
    EXPECT_EQ(p.dt, 1e-4);
    EXPECT_TRUE(p.variable_dt);
    EXPECT_EQ(p.cfl, 0.2);
    EXPECT_EQ(p.out, 0.05);
    EXPECT_EQ(p.trec_ini, 0.0);
    ASSERT_EQ(s.fluid_blocks.size(), 1u);
    EXPECT_EQ(s.fluid_blocks[0].r.xmax, 0.146);
    EXPECT_EQ(s.fluid_blocks[0].r.zmin, 0.002);
    EXPECT_EQ(s.fluid_blocks[0].u0, 0.0);
    ASSERT_EQ(s.fluid_discs.size(), 1u);
    EXPECT_EQ(s.fluid_discs[0].radius, 0.02);
    EXPECT_EQ(s.fluid_discs[0].u0, -0.5);
    EXPECT_EQ(s.fluid_discs[0].w0, 0.25);
    ASSERT_EQ(s.fluid_squares.size(), 1u);
    EXPECT_EQ(s.fluid_squares[0].side, 0.04);
    ASSERT_EQ(s.obstacles.size(), 1u);
    EXPECT_EQ(s.obstacles[0].kind, 2);
    EXPECT_EQ(s.obstacles[0].shape, 1);
    EXPECT_EQ(s.obstacles[0].r.xmin, 0.292);
    EXPECT_EQ(s.obstacles[0].r.zmax, 0.048);
    EXPECT_EQ(s.obstacles[0].beta_deg, 90.0);
    EXPECT_EQ(s.output.format, OutputFormat::Hdf5);
    EXPECT_EQ(s.output.checkpoint_every_steps, 5000);
    EXPECT_EQ(s.output.checkpoint_every_minutes, 0.0);
    EXPECT_FALSE(s.output.remove_out_of_domain);
    EXPECT_EQ(s.output.rho_min_factor, 0.8);
    EXPECT_EQ(s.output.rho_max_factor, 1.2);
    EXPECT_EQ(s.output.dt_min, 1e-8);
}

TEST(ModernCase, DefaultsOfTheMinimalCase) {
    const CaseSpec s = parse_modern_case(kMinimal, "min.toml");
    const SimParams d;  // the defaults documented in CASE_FORMAT.md are SimParams' defaults
    EXPECT_EQ(s.params.kernel, d.kernel);
    EXPECT_EQ(s.params.visc_value, d.visc_value);
    EXPECT_EQ(s.params.boundary, d.boundary);
    EXPECT_EQ(s.params.gz, -9.81);
    EXPECT_EQ(s.params.dz, s.params.dx);  // dz defaults to dx
    EXPECT_NEAR(s.params.h, 1.3 * 0.002, 1e-15);
    EXPECT_EQ(s.output.format, OutputFormat::Both);
}

// Every name of an enum's table (EnumNames, params.hpp) is read by its key and written back by
// to_string, and no two values share a name. extra: the overrides a value needs besides.
template <class E, class Get>
void expect_every_name_read(const std::string& key, Get get, std::vector<std::string> extra = {}) {
    std::set<std::string_view> seen;
    for (const auto& [name, value] : EnumNames<E>::list) {
        EXPECT_TRUE(seen.insert(name).second) << key << ": \"" << name << "\" twice";
        EXPECT_EQ(to_string(value), name);
        std::vector<std::string> overrides = extra;
        overrides.push_back(key + "=" + std::string(name));
        const CaseSpec s = parse_modern_case(kMinimal, "n.toml", overrides);
        EXPECT_EQ(get(s), value) << key << " = " << name;
    }
}

TEST(ModernCase, EveryEnumNameIsReadAndWritten) {
    expect_every_name_read<KernelType>("numerics.kernel", [](const CaseSpec& s) { return s.params.kernel; });
    expect_every_name_read<Integrator>("numerics.integrator",
                                       [](const CaseSpec& s) { return s.params.integrator; });
    expect_every_name_read<DensityFilter>("numerics.density_filter",
                                          [](const CaseSpec& s) { return s.params.density_filter; });
    expect_every_name_read<ViscosityModel>("numerics.viscosity",
                                           [](const CaseSpec& s) { return s.params.viscosity; },
                                           {"fluid.nu=1e-6"});
    expect_every_name_read<BoundaryType>("numerics.boundary",
                                         [](const CaseSpec& s) { return s.params.boundary; });
    expect_every_name_read<Lattice>("numerics.lattice", [](const CaseSpec& s) { return s.params.lattice; });
    expect_every_name_read<SurfaceTensionDelta>("surface_tension.delta",
                                                [](const CaseSpec& s) { return s.params.st_delta; });
    expect_every_name_read<OutputFormat>("output.format", [](const CaseSpec& s) { return s.output.format; });
    expect_every_name_read<Geometry>("domain.geometry", [](const CaseSpec& s) { return s.params.geometry; },
                                     {"domain.wall_left=false", "numerics.lattice=sc"});
    const std::vector<std::string> axi{"domain.geometry=axisymmetric", "domain.wall_left=false",
                                       "numerics.lattice=sc", "resolution.h_over_dx=2"};
    expect_every_name_read<AxisPair>("domain.axis_pair", [](const CaseSpec& s) { return s.params.axis_pair; },
                                     axi);
    std::vector<std::string> rings = axi;
    rings.push_back("domain.axis_pair=rings");
    expect_every_name_read<RingsCurvature>("surface_tension.rings_curvature",
                                           [](const CaseSpec& s) { return s.params.rings_curvature; }, rings);
    expect_every_name_read<CurvatureNormals>("surface_tension.curvature_normals",
                                             [](const CaseSpec& s) { return s.params.curvature_normals; });
    expect_every_name_read<CurvatureModel>("surface_tension.curvature",
                                           [](const CaseSpec& s) { return s.params.curvature; });
}

TEST(ModernCase, ReadsFromFileAndRejectsMissingFile) {
    const auto dir = std::filesystem::temp_directory_path() / "sphjet_test_modern_case";
    std::filesystem::create_directories(dir);
    const auto file = dir / "case.toml";
    std::ofstream(file) << kFull;
    const CaseSpec s = read_modern_case(file);
    EXPECT_EQ(s.source, file.string());
    EXPECT_EQ(s.params.sigma, 0.072);
    try {
        (void)read_modern_case(dir / "absent.toml");
        FAIL() << "no error for a missing file";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("absent.toml"), std::string::npos) << e.what();
    }
    std::filesystem::remove_all(dir);
}

TEST(ModernCase, LooksLikeModernCase) {
    EXPECT_TRUE(looks_like_modern_case("cases/jet/case.toml"));
    EXPECT_TRUE(looks_like_modern_case("CASE.TOML"));
    EXPECT_FALSE(looks_like_modern_case("Case1.txt"));
    EXPECT_FALSE(looks_like_modern_case("toml"));
}

// --- The documented mappings ------------------------------------------------------------

TEST(ModernCase, SoundSpeedFromCoefAndStillWaterDepth) {
    // Legacy obstacle case: coef 10, h_swl 0.292, g 9.81 -> c0 = 10 sqrt(9.81 * 0.292) =
    // 16.925 m/s (the paper's 17 m/s), B = rho0 c0^2 / 7.
    const std::string text = replace_line(kMinimal, "c0 = 17.0", "coef = 10.0\nh_swl = 0.292");
    const SimParams p = parse_modern_case(text, "c.toml").params;
    const double c0 = 10.0 * std::sqrt(9.81 * 0.292);
    EXPECT_NEAR(p.c0(), 16.925, 1e-3);
    EXPECT_NEAR(p.c0(), c0, 1e-12 * c0);
    EXPECT_NEAR(p.B, 1000.0 * c0 * c0 / 7.0, 1e-12 * p.B);
    EXPECT_NEAR(p.B, 40921.7, 0.1);
    EXPECT_EQ(p.coef, 10.0);
    EXPECT_EQ(p.h_swl, 0.292);
    // g is |gz|: gravity pointing up gives the same B.
    const SimParams up =
        parse_modern_case(text, "c.toml", {"gravity.gz=9.81"}).params;
    EXPECT_EQ(up.B, p.B);
}

TEST(ModernCase, SoundSpeedGivenDirectly) {
    const SimParams p = parse_modern_case(kMinimal, "c.toml").params;
    EXPECT_EQ(p.B, 1000.0 * 17.0 * 17.0 / 7.0);  // same expression: exact
    EXPECT_NEAR(p.c0(), 17.0, 1e-12 * 17.0);
    EXPECT_EQ(p.h_swl, 0.0);  // marks "c0 given directly"
    // Another gamma changes B, not c0.
    const SimParams q = parse_modern_case(kMinimal, "c.toml", {"fluid.gamma=1"}).params;
    EXPECT_NEAR(q.c0(), 17.0, 1e-12 * 17.0);
    EXPECT_EQ(q.B, 1000.0 * 17.0 * 17.0);
}

// The run log's note on a first step above the CFL step cfl h / c0 of the fluid at rest
// (model/params.cpp): the ratio it states, and no note at or below that step.
TEST(ModernCase, InitialStepNote) {
    SimParams p;
    p.rho0 = 1000.0;
    p.gamma = 7.0;
    p.B = 1000.0 * 10.0 * 10.0 / 7.0;  // c0 = 10 m/s
    p.h = 0.001;
    p.cfl = 0.2;                         // CFL step 2e-5 s
    p.dt = 1e-4;
    const std::string note = initial_step_note(p);
    EXPECT_NE(note.find("5 times the CFL step"), std::string::npos) << note;
    EXPECT_NE(note.find("first step"), std::string::npos) << note;
    p.variable_dt = false;
    EXPECT_NE(initial_step_note(p).find("fixed for the whole run"), std::string::npos);
    p.variable_dt = true;
    p.dt = 2e-5 * 0.999;
    EXPECT_EQ(initial_step_note(p), "");
}

TEST(ModernCase, ZeroGravityWorksWithC0) {
    const SimParams p =
        parse_modern_case(kMinimal, "c.toml", {"gravity.gz=0", "gravity.gx=0"}).params;
    EXPECT_EQ(p.gz, 0.0);
    EXPECT_NEAR(p.c0(), 17.0, 1e-12 * 17.0);
}

TEST(ModernCase, DynamicViscosityToArtificialAlpha) {
    // Water, mu = 1e-3 Pa s, rho0 = 1000: nu = 1e-6 m^2/s. h = 1.3 * 0.002 = 0.0026 m,
    // c0 = 17 m/s: alpha = 8 nu / (h c0) = 8e-6 / 0.0442 = 1.80995e-4.
    const std::string text = replace_line(kMinimal, "c0 = 17.0", "c0 = 17.0\nmu = 1.0e-3");
    const SimParams p = parse_modern_case(text, "v.toml").params;
    EXPECT_EQ(p.viscosity, ViscosityModel::Artificial);
    EXPECT_NEAR(p.visc_value, 8e-6 / (0.0026 * 17.0), 1e-12 * p.visc_value);
    EXPECT_NEAR(p.visc_value, 1.80995e-4, 1e-9);
    // Back to nu with the documented link nu = alpha h c0 / 8.
    EXPECT_NEAR(p.visc_value * p.h * p.c0() / 8.0, 1e-6, 1e-17);
    // nu directly gives the same alpha.
    const std::string t2 = replace_line(kMinimal, "c0 = 17.0", "c0 = 17.0\nnu = 1.0e-6");
    EXPECT_NEAR(parse_modern_case(t2, "v.toml").params.visc_value, p.visc_value,
                1e-12 * p.visc_value);
    EXPECT_NEAR(alpha_from_nu(1e-6, 0.0026, 17.0), 1.80995e-4, 1e-9);
}

TEST(ModernCase, DynamicViscosityToLaminarNu) {
    const std::string text = replace_line(kMinimal, "c0 = 17.0", "c0 = 17.0\nmu = 1.0e-3");
    const SimParams p =
        parse_modern_case(text, "v.toml", {"numerics.viscosity=laminar"}).params;
    EXPECT_EQ(p.viscosity, ViscosityModel::Laminar);
    EXPECT_NEAR(p.visc_value, 1e-6, 1e-18);  // nu = mu / rho0
}

TEST(ModernCase, SmoothingLengthThreeWays) {
    const auto h_of = [](const std::string& line) {
        return parse_modern_case(replace_line(kMinimal, "h_over_dx = 1.3", line), "h.toml").params.h;
    };
    EXPECT_EQ(h_of("h = 0.0026"), 0.0026);
    EXPECT_NEAR(h_of("h_over_dx = 1.3"), 0.0026, 1e-15);
    EXPECT_NEAR(h_of("h_coefficient = 0.92"), 0.92 * std::sqrt(2.0) * 0.002, 1e-15);
    EXPECT_NEAR(h_of("h_coefficient = 0.92\ndz = 0.001"),
                0.92 * std::sqrt(0.002 * 0.002 + 0.001 * 0.001), 1e-15);
}

TEST(ModernCase, IntegerWhereAFloatIsExpected) {
    const CaseSpec s = parse_modern_case(replace_line(kMinimal, "lx = 0.5", "lx = 1"), "i.toml");
    EXPECT_EQ(s.params.lx, 1.0);
}

// --- Validation: one row per rule; the message must name file and key ------------------

struct BadCase {
    const char* name;
    const char* from;   // a line of kMinimal ("" to append, "^" to prepend)
    const char* to;     // its replacement
    std::vector<std::string> must_contain;
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

class Validation : public ::testing::TestWithParam<BadCase> {};

TEST_P(Validation, NamesFileKeyExpectedAndFound) {
    const BadCase& c = GetParam();
    const std::string from = c.from;
    const std::string text = from.empty()    ? std::string(kMinimal) + c.to
                             : from == "^" ? c.to + std::string(kMinimal)
                                           : replace_line(kMinimal, c.from, c.to);
    const std::string msg = error_of(text);
    EXPECT_NE(msg.find("case.toml"), std::string::npos) << msg;
    for (const auto& s : c.must_contain) EXPECT_NE(msg.find(s), std::string::npos) << "'" << s << "' not in: " << msg;
}

const BadCase kBad[] = {
    {"UnknownKeySuggestion", "", "[numerics]\nkernal = \"wendland\"\n",
     {"numerics.kernal", "unknown key", "did you mean 'numerics.kernel'", "line 21"}},
    {"UnknownSection", "", "[outputs]\nformat = \"hdf5\"\n",
     {"outputs", "unknown key", "did you mean 'output'"}},
    {"KeyInWrongSection", "sigma = 0.072", "tmax = 0.072",
     {"surface_tension.tmax", "unknown key", "it is a key of [time]"}},
    {"UnknownKeyInBlock", "zmax = 0.2", "zmax = 0.2\nvelocity = 1.0",
     {"fluid.block[0].velocity", "unknown key", "expected one of the keys of [[fluid.block]]"}},
    {"WrongTypeString", "dx = 0.002", "dx = \"0.002\"",
     {"resolution.dx", "wrong type", "expected a number", "found the string \"0.002\""}},
    {"WrongTypeBool", "cfl = 0.2", "cfl = 0.2\nvariable_dt = 1",
     {"time.variable_dt", "wrong type", "a boolean", "the integer 1"}},
    {"WrongTypeInt", "", "[numerics]\nfilter_period = 2.5\n",
     {"numerics.filter_period", "wrong type", "an integer", "the float 2.5"}},
    {"SectionNotTable", "^", "numerics = 3\n", {"numerics", "wrong type", "a table [numerics]"}},
    {"BlockNotArray", "[[fluid.block]]", "[fluid.block]",
     {"fluid.block", "wrong type", "[[fluid.block]]"}},
    {"UnknownEnum", "", "[numerics]\nkernel = \"wendlnd\"\n",
     {"numerics.kernel", "unknown value", "did you mean \"wendland\"", "\"cubic_spline\"",
      "found \"wendlnd\""}},
    {"HZero", "h_over_dx = 1.3", "h = 0.0", {"resolution.h", "must be positive", "found 0.0"}},
    {"HNegativeCoefficient", "h_over_dx = 1.3", "h_coefficient = -0.9",
     {"resolution.h_coefficient", "must be positive"}},
    {"HTwoWays", "h_over_dx = 1.3", "h_over_dx = 1.3\nh = 0.0026",
     {"resolution.h", "one way only", "exactly one of"}},
    {"HMissing", "h_over_dx = 1.3", "", {"resolution.h", "missing required key", "found nothing"}},
    {"DxZero", "dx = 0.002", "dx = 0.0", {"resolution.dx", "must be positive", "found 0.0"}},
    {"DxNegative", "dx = 0.002", "dx = -0.002", {"resolution.dx", "found -0.002"}},
    {"DxMissing", "dx = 0.002", "", {"resolution.dx", "missing required key"}},
    {"DzZero", "dx = 0.002", "dx = 0.002\ndz = 0", {"resolution.dz", "must be positive"}},
    {"SigmaNegative", "sigma = 0.072", "sigma = -0.072",
     {"surface_tension.sigma", "must not be negative", "found -0.072", "line 19"}},
    {"Rho0Zero", "c0 = 17.0", "c0 = 17.0\nrho0 = 0", {"fluid.rho0", "must be positive"}},
    {"GammaNegative", "c0 = 17.0", "c0 = 17.0\ngamma = -7", {"fluid.gamma", "must be positive"}},
    {"C0Zero", "c0 = 17.0", "c0 = 0.0", {"fluid.c0", "must be positive"}},
    {"C0AndCoef", "c0 = 17.0", "c0 = 17.0\ncoef = 10.0\nh_swl = 0.3",
     {"fluid.c0", "not both"}},
    {"CoefWithoutHswl", "c0 = 17.0", "coef = 10.0", {"fluid.h_swl", "missing required key"}},
    {"HswlWithoutCoef", "c0 = 17.0", "h_swl = 0.3", {"fluid.coef", "missing required key"}},
    {"NoSoundSpeed", "c0 = 17.0", "", {"fluid.c0", "missing required key", "fluid.coef"}},
    {"CoefWithoutGravity", "c0 = 17.0", "coef = 10.0\nh_swl = 0.3\n[gravity]\ngz = 0.0",
     {"fluid.coef", "gravity.gz = 0", "fluid.c0 given directly"}},
    {"AlphaAndMu", "c0 = 17.0", "c0 = 17.0\nmu = 1e-3\n[numerics]\nalpha = 0.1",
     {"numerics.alpha", "one way only"}},
    {"NuAndMu", "c0 = 17.0", "c0 = 17.0\nmu = 1e-3\nnu = 1e-6", {"fluid.nu", "one way only"}},
    {"NegativeMu", "c0 = 17.0", "c0 = 17.0\nmu = -1e-3", {"fluid.mu", "must not be negative"}},
    {"NegativeAlpha", "", "[numerics]\nalpha = -0.1\n", {"numerics.alpha", "must not be negative"}},
    {"LaminarWithAlpha", "", "[numerics]\nviscosity = \"laminar\"\nalpha = 0.1\n",
     {"numerics.alpha", "laminar"}},
    {"LaminarWithoutViscosity", "", "[numerics]\nviscosity = \"laminar\"\n",
     {"fluid.mu", "missing required key"}},
    {"CflZero", "cfl = 0.2", "cfl = 0.0", {"time.cfl", "out of range", "(0, 1]", "found 0.0"}},
    {"CflAboveOne", "cfl = 0.2", "cfl = 1.5", {"time.cfl", "(0, 1]", "found 1.5"}},
    {"TmaxZero", "tmax = 0.6", "tmax = 0.0", {"time.tmax", "must be positive"}},
    {"TmaxNegative", "tmax = 0.6", "tmax = -1.0", {"time.tmax", "found -1.0"}},
    {"OutZero", "out = 0.05", "out = 0.0", {"time.out", "must be positive"}},
    {"DtZero", "out = 0.05", "out = 0.05\ndt = 0", {"time.dt", "must be positive"}},
    {"TrecNegative", "out = 0.05", "out = 0.05\ntrec_ini = -1", {"time.trec_ini", "must not be negative"}},
    {"NotFinite", "tmax = 0.6", "tmax = inf", {"time.tmax", "finite"}},
    {"BlockOutsideBox", "xmax = 0.1", "xmax = 0.6",
     {"fluid.block[0].xmax", "fluid region outside the box", "domain.lx", "found 0.6"}},
    {"BlockBelowFloor", "zmin = 0.0", "zmin = -0.01", {"fluid.block[0].zmin", "outside the box"}},
    {"BlockEmpty", "xmax = 0.1", "xmax = 0.0", {"fluid.block[0].xmax", "empty region"}},
    {"BlockMissingEdge", "zmax = 0.2", "", {"fluid.block[0].zmax", "missing required key"}},
    {"DiscRadiusZero", "", "[[fluid.disc]]\nxc = 0.25\nzc = 0.25\nradius = 0.0\n",
     {"fluid.disc[0].radius", "must be positive"}},
    {"DiscOutsideBox", "", "[[fluid.disc]]\nxc = 0.45\nzc = 0.25\nradius = 0.1\n",
     {"fluid.disc[0].xc", "fluid disc outside the box"}},
    {"SquareOutsideBox", "", "[[fluid.square]]\nxc = 0.25\nzc = 0.49\nside = 0.1\n",
     {"fluid.square[0].zc", "fluid square outside the box"}},
    {"NoFluid", "[[fluid.block]]\nxmin = 0.0\nxmax = 0.1\nzmin = 0.0\nzmax = 0.2\n", "",
     {"fluid", "no fluid"}},
    {"BoxZero", "lx = 0.5", "lx = 0.0", {"domain.lx", "must be positive"}},
    {"InclinedFloor", "lx = 0.5", "lx = 0.5\nfloor_inclination_deg = 5",
     {"domain.floor_inclination_deg", "not supported"}},
    {"ObstacleOutside", "", "[[obstacle]]\nxmin = 0.3\nxmax = 0.7\nzmin = 0\nzmax = 0.1\n",
     {"obstacle[0].xmax", "obstacle outside the box"}},
    {"ObstacleTrapezoid", "", "[[obstacle]]\nshape = \"trapezoid\"\nxmin = 0.3\nxmax = 0.4\nzmin = 0\nzmax = 0.1\n",
     {"obstacle[0].shape", "\"rectangle\""}},
    {"ObstacleDensity", "", "[[obstacle]]\ndensity = 0\nxmin = 0.3\nxmax = 0.4\nzmin = 0\nzmax = 0.1\n",
     {"obstacle[0].density", ">= 1"}},
    {"FilterPeriodZero", "", "[numerics]\nfilter_period = 0\n", {"numerics.filter_period", ">= 1"}},
    {"XsphOutOfRange", "", "[numerics]\nxsph_eps = 1.5\n", {"numerics.xsph_eps", "[0, 1]"}},
    {"OutputFormat", "", "[output]\nformat = \"vtk\"\n", {"output.format", "\"hdf5\""}},
    {"RhoBand", "", "[output]\nrho_max_factor = 0.9\n", {"output.rho_max_factor", "> 1"}},
    {"NegativeCheckpoint", "", "[output]\ncheckpoint_every_steps = -1\n",
     {"output.checkpoint_every_steps", ">= 0"}},
    // revolution_sectors: the range first, then the geometry (kMinimal is planar)
    {"RevolutionNegative", "", "[output]\nrevolution_sectors = -4\n",
     {"output.revolution_sectors", "out of range", "an integer in [0, 360]", "found -4", "line 21"}},
    {"RevolutionAbsurd", "", "[output]\nrevolution_sectors = 100000\n",
     {"output.revolution_sectors", "out of range", "[0, 360]", "found 100000"}},
    {"RevolutionNotInteger", "", "[output]\nrevolution_sectors = 12.0\n",
     {"output.revolution_sectors", "wrong type", "an integer", "the float 12.0"}},
    {"RevolutionPlanar", "", "[output]\nrevolution_sectors = 16\n",
     {"output.revolution_sectors", "axisymmetric", "domain.geometry = \"planar\"", "found 16"}},
    {"RevolutionPlanarZero", "", "[output]\nrevolution_sectors = 0\n",
     {"output.revolution_sectors", "axisymmetric", "found 0"}},
    {"WallNeedsDynamic", "", "[[wall]]\nx = 0.2\nheight = 0.1\n[numerics]\nboundary = \"repulsive\"\n",
     {"wall[0].x", "dynamic"}},
    {"WallTooHigh", "", "[[wall]]\nx = 0.2\nheight = 0.6\n", {"wall[0].height", "domain.lz"}},
    {"WallOutside", "", "[[wall]]\nx = 0.7\nheight = 0.1\n", {"wall[0].x", "wall outside the box"}},
    {"LegacyFillNeedsHswl", "", "[legacy]\nfill = true\n", {"fluid.h_swl", "legacy.fill"}},
    {"LegacyCompiler", "", "[legacy]\ncompiler = 7\n", {"legacy.compiler", "out of range"}},
    {"LegacyHCoefficientTwice", "h_over_dx = 1.3", "h_coefficient = 0.92\n[legacy]\nh_coefficient = 0.92",
     {"legacy.h_coefficient", "given twice"}},
    // Jets: the nozzle (x0 = 0.25, 0.3 m; d0 = 0.02 m; 15 d0 = 0.3 m long; axis down) in the 0.5 m box.
    {"NozzleU0Zero", "", "[nozzle]\nx0 = 0.25\nz0 = 0.1\nd0 = 0.02\nlength_over_d0 = 5\nu0 = 0.0\n",
     {"nozzle.u0", "must be positive", "u0 > 0", "found 0.0"}},
    {"NozzleU0Negative", "", "[nozzle]\nx0 = 0.25\nz0 = 0.1\nd0 = 0.02\nlength_over_d0 = 5\nu0 = -0.25\n",
     {"nozzle.u0", "must be positive", "found -0.25"}},
    {"NozzleD0Zero", "", "[nozzle]\nx0 = 0.25\nz0 = 0.1\nd0 = 0\nu0 = 0.25\n", {"nozzle.d0", "must be positive"}},
    {"NozzleOutsideBoxTop", "", "[nozzle]\nx0 = 0.25\nz0 = 0.3\nd0 = 0.02\nu0 = 0.25\n",
     {"nozzle.z0", "nozzle outside the box", "domain.lz = 0.5", "z from 0.3 to 0.6"}},
    {"NozzleOutsideBoxSide", "", "[nozzle]\nx0 = 0.49\nz0 = 0.1\nd0 = 0.02\nlength_over_d0 = 5\nu0 = 0.25\n",
     {"nozzle.x0", "nozzle outside the box", "domain.lx = 0.5"}},
    {"NozzleAxisLeavesDomain", "", "[nozzle]\nx0 = 0.25\nz0 = 0.03\nd0 = 0.02\nlength_over_d0 = 5\nu0 = 0.25\n",
     {"nozzle", "the breakup axis leaves the domain", "at least 2 d0 = 0.04", "found 0.03 m"}},
    {"NozzleAxisLeavesDomainRight", "", "[nozzle]\nx0 = 0.49\nz0 = 0.25\naxis = \"right\"\nd0 = 0.02\nlength_over_d0 = 5\nu0 = 0.25\n",
     {"nozzle.axis", "the breakup axis leaves the domain", "found 0.01"}},
    // z0 = 0.1, down: 0.1 m = 5 d0 of box below the orifice for the starting column
    {"NozzleColumnLeavesBox", "", "[nozzle]\nx0 = 0.25\nz0 = 0.1\nd0 = 0.02\nlength_over_d0 = 5\nu0 = 0.25\ncolumn_over_d0 = 6\n",
     {"nozzle.column_over_d0", "the starting column leaves the box", "at most 5", "found 6"}},
    {"NozzleColumnNegative", "", "[nozzle]\nx0 = 0.25\nz0 = 0.1\nd0 = 0.02\nlength_over_d0 = 5\nu0 = 0.25\ncolumn_over_d0 = -1\n",
     {"nozzle.column_over_d0", "must not be negative", "found -1"}},
    {"NozzleUnknownAxis", "", "[nozzle]\nx0 = 0.25\nz0 = 0.1\naxis = \"sideways\"\nd0 = 0.02\nu0 = 0.25\n",
     {"nozzle.axis", "unknown value", "\"down\""}},
    {"NozzleUnknownRelease", "", "[nozzle]\nx0 = 0.25\nz0 = 0.1\nd0 = 0.02\nlength_over_d0 = 5\nu0 = 0.25\nrelease = \"early\"\n",
     {"nozzle.release", "unknown value", "\"crossing\"", "early"}},
    {"NozzleLandedParabolic", "", "[nozzle]\nx0 = 0.25\nz0 = 0.1\nd0 = 0.02\nlength_over_d0 = 5\nu0 = 0.25\nprofile = \"parabolic\"\nrelease = \"landed\"\n",
     {"nozzle.release", "cross it at different times", "with nozzle.profile = \"plug\"", "nozzle.profile = \"parabolic\""}},
    {"BreakupWithoutNozzle", "", "[breakup]\nstop_after = 0.1\n", {"breakup", "needs a jet", "[nozzle]"}},
    {"BreakupLinkZero", "", "[nozzle]\nx0 = 0.25\nz0 = 0.1\nd0 = 0.02\nlength_over_d0 = 5\nu0 = 0.25\n[breakup]\nlink_over_h = 0\n",
     {"breakup.link_over_h", "must be positive"}},
    {"BreakupRemoveNegative", "", "[nozzle]\nx0 = 0.25\nz0 = 0.1\nd0 = 0.02\nlength_over_d0 = 5\nu0 = 0.25\n[breakup]\nremove_drops_below_h = -2\n",
     {"breakup.remove_drops_below_h", "must not be negative", "a number >= 0", "found -2"}},
    {"BreakupRemoveString", "", "[nozzle]\nx0 = 0.25\nz0 = 0.1\nd0 = 0.02\nlength_over_d0 = 5\nu0 = 0.25\n[breakup]\nremove_drops_below_h = \"2\"\n",
     {"breakup.remove_drops_below_h", "wrong type", "a number", "the string \"2\""}},
    {"FormatVersion", "^", "format_version = 2\n", {"format_version", "unsupported"}},
    {"SyntaxError", "lx = 0.5", "lx = = 0.5", {"case.toml:9:", "TOML syntax error"}},
    // Text that reaches an assertion in toml++ 3.3 (tests/fuzz/README.md) is a syntax error too.
    {"SyntaxBraceInArray", "lx = 0.5", "lx = [1, }", {"case.toml:9:10", "'}' in an array"}},
    {"SyntaxDateSpaceDigit", "lx = 0.5", "lx = 1979-05-27 7 ", {"case.toml:9:6", "a date followed by a space"}},
    {"SyntaxDateUnderscoreSpaceDigit", "lx = 0.5", "lx = 1_979-05-27 7 ", {"case.toml:9:6", "a date followed by a space"}},
    {"SyntaxDateUnderscoreSpaceDigits", "lx = 0.5", "lx = 1979-05-27__ 77", {"case.toml:9:6", "a date followed by a space"}},
    {"SyntaxDateSpaceDigitVerticalTab", "lx = 0.5", "lx = 1979-05-27 7\v", {"case.toml:9:6", "a date followed by a space"}},
    // A date-time with a space before the time is valid TOML: the key's type is wrong, no more.
    {"DateTimeWithSpace", "lx = 0.5", "lx = 1979-05-27 07:32:00", {"lx", "wrong type"}},
};

INSTANTIATE_TEST_SUITE_P(ModernCase, Validation, ::testing::ValuesIn(kBad),
                         [](const auto& info) { return std::string(info.param.name); });

// --- Overrides -----------------------------------------------------------------------------

TEST(ModernCaseOverride, SetsValues) {
    const CaseSpec s = parse_modern_case(
        kMinimal, "o.toml",
        {"surface_tension.sigma=0.05", "time.tmax=0.2", "numerics.kernel=cubic_spline",
         "numerics.tensile_correction = \"on\"", "fluid.block[0].u0=0.25",
         "output.remove_out_of_domain=false", "gravity.gx=1"});
    EXPECT_EQ(s.params.sigma, 0.05);
    EXPECT_EQ(s.params.tmax, 0.2);
    EXPECT_EQ(s.params.kernel, KernelType::CubicSpline);
    EXPECT_EQ(s.params.tensile_correction, 1);
    EXPECT_EQ(s.fluid_blocks[0].u0, 0.25);
    EXPECT_FALSE(s.output.remove_out_of_domain);
    EXPECT_EQ(s.params.gx, 1.0);  // [gravity] was not in the file: created
}

TEST(ModernCaseOverride, LastOneWins) {
    const CaseSpec s = parse_modern_case(kMinimal, "o.toml", {"time.tmax=0.2", "time.tmax=0.3"});
    EXPECT_EQ(s.params.tmax, 0.3);
}

TEST(ModernCaseOverride, ValidatedLikeTheFile) {
    const std::string msg = error_of(kMinimal, {"surface_tension.sigma=-1"});
    EXPECT_NE(msg.find("surface_tension.sigma"), std::string::npos) << msg;
    EXPECT_NE(msg.find("set by override 'surface_tension.sigma=-1'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("must not be negative"), std::string::npos) << msg;
}

TEST(ModernCaseOverride, UnknownKeyIsAnError) {
    const std::string msg = error_of(kMinimal, {"surface_tension.sigmaa=0.05"});
    EXPECT_NE(msg.find("unknown key"), std::string::npos) << msg;
    EXPECT_NE(msg.find("did you mean 'surface_tension.sigma'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("surface_tension.sigmaa"), std::string::npos) << msg;
    const std::string m2 = error_of(kMinimal, {"solver.tmax=1"});
    EXPECT_NE(m2.find("unknown key"), std::string::npos) << m2;
    const std::string m3 = error_of(kMinimal, {"fluid.block.u0=1"});
    EXPECT_NE(m3.find("fluid.block[0].u0"), std::string::npos) << m3;
    const std::string m4 = error_of(kMinimal, {"numerics=1"});
    EXPECT_NE(m4.find("names a section"), std::string::npos) << m4;
}

TEST(ModernCaseOverride, TypeErrorNamesKeyAndOverride) {
    const std::string msg = error_of(kMinimal, {"time.tmax=abc"});
    EXPECT_NE(msg.find("time.tmax"), std::string::npos) << msg;
    EXPECT_NE(msg.find("wrong type"), std::string::npos) << msg;
    EXPECT_NE(msg.find("found the string \"abc\""), std::string::npos) << msg;
    const std::string m2 = error_of(kMinimal, {"time.variable_dt=1"});
    EXPECT_NE(m2.find("a boolean"), std::string::npos) << m2;
}

TEST(ModernCaseOverride, MalformedAndMissingElement) {
    const std::string msg = error_of(kMinimal, {"time.tmax"});
    EXPECT_NE(msg.find("key.path=value"), std::string::npos) << msg;
    const std::string m2 = error_of(kMinimal, {"fluid.disc[0].radius=0.1"});
    EXPECT_NE(m2.find("no such element"), std::string::npos) << m2;
    EXPECT_NE(m2.find("[[fluid.disc]] entries (0)"), std::string::npos) << m2;
}

// --- Round trip ----------------------------------------------------------------------------

void expect_round_trip(const CaseSpec& spec) {
    const std::string text = write_modern_case(spec);
    CaseSpec back;
    try {
        back = parse_modern_case(text, "written.toml");
    } catch (const InputError& e) {
        FAIL() << e.what() << "\n" << text;
    }
    expect_same(spec, back);
    back.source = spec.source;
    EXPECT_EQ(write_modern_case(back), text);  // the writer is a fixed point too
}

TEST(ModernCaseRoundTrip, FullExample) { expect_round_trip(parse_modern_case(kFull, "full.toml")); }

TEST(ModernCaseRoundTrip, C0GivenDirectly) {
    // B = rho0 c0^2 / gamma written back as c0 must give the same B to the bit.
    for (const char* c0 : {"17.0", "16.925", "1.0e3", "0.3", "44.29"})
        expect_round_trip(parse_modern_case(replace_line(kMinimal, "c0 = 17.0", std::string("c0 = ") + c0 + "\ngamma = 7.15\nrho0 = 998.2"), "c.toml"));
}

TEST(ModernCaseRoundTrip, LaminarAndVariants) {
    const std::string text = replace_line(kFull, "alpha = 0.3", "") ;
    expect_round_trip(parse_modern_case(
        replace_line(text, "h_swl = 0.292", "h_swl = 0.292\nmu = 1.0e-3"), "l.toml",
        {"numerics.viscosity=laminar", "numerics.kernel=gaussian", "numerics.lattice=sc",
         "numerics.boundary=dynamic", "numerics.density_filter=none",
         "numerics.tensile_correction=auto", "obstacle[0].kind=solid", "output.format=legacy",
         "domain.wall_top=true", "time.variable_dt=false"}));
    // mu mapped to alpha: the written alpha reproduces visc_value exactly.
    expect_round_trip(parse_modern_case(
        replace_line(text, "h_swl = 0.292", "h_swl = 0.292\nmu = 1.0e-3"), "a.toml"));
}

TEST(ModernCaseRoundTrip, Jet) {
    const std::string jet = "[nozzle]\nx0 = 0.25\nz0 = 0.2\naxis = \"down\"\nd0 = 0.02\nlength_over_d0 = 7.5\nu0 = 0.17\n"
                            "walls = false\n[breakup]\nlink_over_h = 1.5\nband_over_d0 = 0.4\ncheck_every = 0.002\n"
                            "stop_after = 0.05\nremove_drops_below_h = 2\n";
    const CaseSpec s = parse_modern_case(std::string(kMinimal) + jet, "jet.toml");
    ASSERT_TRUE(s.nozzle && s.breakup);
    EXPECT_EQ(s.nozzle->length_over_d0, 7.5);
    EXPECT_EQ(s.nozzle->ez, -1.0);
    EXPECT_FALSE(s.nozzle->walls);
    EXPECT_EQ(s.params.drive_u, 0.17);
    EXPECT_TRUE(s.params.domain_box);
    EXPECT_EQ(s.breakup->band_over_d0, 0.4);
    EXPECT_EQ(s.breakup->remove_drops_below_h, 2.0);
    EXPECT_FALSE(s.params.drive_release_crossing);  // nozzle.release = "step" by default
    expect_round_trip(s);
    // nozzle.release = "crossing" reaches the core's parameters and is written back.
    const CaseSpec c = parse_modern_case(std::string(kMinimal) + jet, "jet.toml", {"nozzle.release=\"crossing\""});
    EXPECT_EQ(c.nozzle->release, NozzleRelease::Crossing);
    EXPECT_TRUE(c.params.drive_release_crossing);
    expect_round_trip(c);
    // nozzle.release = "landed": the crossing's release with the steps landed on the crossings.
    const CaseSpec l = parse_modern_case(std::string(kMinimal) + jet, "jet.toml", {"nozzle.release=\"landed\""});
    EXPECT_EQ(l.nozzle->release, NozzleRelease::Landed);
    EXPECT_TRUE(l.params.drive_release_crossing);
    EXPECT_TRUE(l.params.drive_release_landed);
    expect_round_trip(l);
    // Axis "right" and the defaults of [breakup] (none given).
    const CaseSpec r = parse_modern_case(
        std::string(kMinimal) + "[nozzle]\nx0 = 0.2\nz0 = 0.3\naxis = \"right\"\nd0 = 0.02\nlength_over_d0 = 5\nu0 = 0.1\n",
        "right.toml");
    EXPECT_EQ(r.params.drive_ex, 1.0);
    EXPECT_EQ(r.params.drive_ez, 0.0);
    ASSERT_TRUE(r.breakup);
    EXPECT_EQ(r.breakup->link_over_h, 1.5);
    EXPECT_LT(r.breakup->stop_after, 0.0);
    EXPECT_EQ(r.breakup->remove_drops_below_h, 0.0);  // legacy and older cases: removal off
    expect_round_trip(r);
}

TEST(ModernCaseRoundTrip, ProgrammaticSpec) {
    CaseSpec s;
    s.params.lx = 1.0 / 3.0;
    s.params.lz = 0.7;
    s.params.dx = s.params.dz = 1e-3;
    s.params.h = 1.3e-3;
    s.params.B = 1e5 / 3.0;
    s.params.sigma = 0.0728;
    s.params.gx = 1e-300;
    s.fluid_discs.push_back({0.1, 0.2, 0.05, 0.1, -0.2});
    s.fluid_squares.push_back({0.2, 0.5, 0.1, 0, 0});
    expect_round_trip(s);
}

TEST(ModernCaseRoundTrip, ThroughAFile) {
    const CaseSpec spec = parse_modern_case(kFull, "full.toml");
    const auto dir = std::filesystem::temp_directory_path() / "sphjet_test_modern_case_rt";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "rt.toml") << write_modern_case(spec);
    expect_same(spec, read_modern_case(dir / "rt.toml"));
    std::filesystem::remove_all(dir);
}

// --- Legacy case files (the other reader) through the modern format ---------------------

// What `sphjet convert` does: legacy -> modern text -> CaseSpec must give the legacy spec back,
// every field exact (B and h are derived in single precision by both readers).
class LegacyConversion : public ::testing::TestWithParam<const char*> {};

TEST_P(LegacyConversion, ConvertedCaseReadsBackToTheSameSpec) {
    const auto path = std::filesystem::path(SPHJET_SHARED_DIR) / "legacy" / GetParam();
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not present";
    const CaseSpec legacy = read_legacy_case(path);
    expect_round_trip(legacy);
    const CaseSpec modern = parse_modern_case(write_modern_case(legacy), "converted.toml");
    EXPECT_TRUE(modern.legacy_fill);
}

INSTANTIATE_TEST_SUITE_P(ModernCase, LegacyConversion,
                         ::testing::Values("case1/Case1.txt", "case1_early/Case1E.txt",
                                           "obstacle_wendland/ObstW.txt"));

TEST(ModernCaseLegacy, SinglePrecisionDerivationMatchesLegacyNumbers) {
    // Case1: coef 10, h_SWL 2 -> c0 = 44.29 m/s; h coefficient 0.92, dx = dz = 0.03.
    const std::string text = replace_line(
        replace_line(kMinimal, "c0 = 17.0", "coef = 10.0\nh_swl = 2.0"), "h_over_dx = 1.3",
        "h_coefficient = 0.92\n[legacy]\nsingle_precision = true");
    const SimParams p = parse_modern_case(text, "s.toml").params;
    float b = 10.0f * 10.0f;
    b = b * 1000.0f * 9.81f * 2.0f / 7.0f;
    EXPECT_EQ(p.B, static_cast<double>(b));
    EXPECT_EQ(p.h, static_cast<double>(static_cast<float>(
                       static_cast<double>(0.92f) * std::sqrt(2 * 0.002 * 0.002))));
    EXPECT_NEAR(p.c0(), 44.29, 0.01);
}

// --- The reference page ----------------------------------------------------------------

const std::filesystem::path kDoc = std::filesystem::path(SPHJET_SOURCE_DIR) / "cases" / "CASE_FORMAT.md";

TEST(ModernCaseDoc, DocumentsEveryKey) {
    const std::string doc = read_text(kDoc);
    ASSERT_FALSE(doc.empty()) << kDoc;
    for (const auto& key : modern_case_keys()) {
        // A table row starts "| `key`" with the key's last component inside its section.
        const std::string leaf = key.substr(key.rfind('.') + 1);
        EXPECT_NE(doc.find("| `" + leaf + "`"), std::string::npos) << key << " is not documented";
    }
}

// The TOML block after an HTML marker comment in the reference page.
std::string doc_example(const std::string& marker) {
    const std::string doc = read_text(kDoc);
    const std::string open = "<!-- " + marker + " -->\n```toml\n";
    const auto b = doc.find(open);
    if (b == std::string::npos) return {};
    const auto e = doc.find("```", b + open.size());
    return e == std::string::npos ? std::string{} : doc.substr(b + open.size(), e - b - open.size());
}

TEST(ModernCaseDoc, DropExampleParses) {
    const std::string example = doc_example("drop-example");
    ASSERT_FALSE(example.empty()) << "no drop example in " << kDoc;
    const CaseSpec s = parse_modern_case(example, "CASE_FORMAT.md drop");
    EXPECT_EQ(s.fluid_discs.size(), 1u);
    EXPECT_EQ(s.params.sigma, 0.072);
    EXPECT_EQ(s.params.gz, 0.0);
    expect_round_trip(s);
}

TEST(ModernCaseDoc, FullExampleParses) {
    const std::string doc = read_text(kDoc);
    const std::string open = "<!-- full-example -->\n```toml\n";
    const auto b = doc.find(open);
    ASSERT_NE(b, std::string::npos) << "no full example in " << kDoc;
    const auto e = doc.find("```", b + open.size());
    ASSERT_NE(e, std::string::npos);
    const std::string example = doc.substr(b + open.size(), e - b - open.size());
    CaseSpec s;
    try {
        s = parse_modern_case(example, "CASE_FORMAT.md example");
    } catch (const InputError& err) {
        FAIL() << err.what();
    }
    // The example is the paper's dam break with an obstacle (legacy obstacle_wendland).
    EXPECT_EQ(s.params.dx, 0.002);
    EXPECT_EQ(s.obstacles.size(), 1u);
    expect_round_trip(s);
}

// domain.geometry and domain.periodic_z (cases/CASE_FORMAT.md): read, and the combinations the
// axisymmetric mode cannot run refused with the key and what was expected.
TEST(ModernCase, AxisymmetricAndPeriodicZ) {
    const std::vector<std::string> axi = {"domain.geometry=\"axisymmetric\"", "domain.wall_left=false",
                                          "numerics.lattice=\"sc\""};
    const CaseSpec s = parse_modern_case(kMinimal, "case.toml", axi);
    EXPECT_EQ(s.params.geometry, Geometry::Axisymmetric);
    EXPECT_FALSE(s.params.periodic_z);
    EXPECT_EQ(parse_modern_case(kMinimal, "case.toml").params.geometry, Geometry::Planar);

    std::string e = error_of(kMinimal, {"domain.geometry=\"axisymmetric\""});
    EXPECT_NE(e.find("domain.wall_left"), std::string::npos) << e;
    e = error_of(kMinimal, {"domain.geometry=\"cylindrical\""});
    EXPECT_NE(e.find("axisymmetric"), std::string::npos) << e;
    e = error_of(kMinimal, {"domain.geometry=\"axisymmetric\"", "domain.wall_left=false"});
    EXPECT_NE(e.find("numerics.lattice"), std::string::npos) << e;

    // a disc centred on the axis is a sphere; one crossing the axis elsewhere is refused
    const std::string disc = std::string(kMinimal) + "[[fluid.disc]]\nxc = 0.0\nzc = 0.3\nradius = 0.05\n";
    EXPECT_EQ(parse_modern_case(disc, "case.toml", axi).fluid_discs.size(), 1u);
    std::vector<std::string> off = axi;
    off.push_back("fluid.disc[0].xc=0.02");
    e = error_of(disc, off);
    EXPECT_NE(e.find("x < 0"), std::string::npos) << e;

    // the cylinder needs the axisymmetric geometry; its wavelength is required with eps
    const std::string cyl = std::string(kMinimal) + "[[fluid.cylinder]]\nradius = 0.01\neps = 0.02\nwavelength = 0.1\n";
    e = error_of(cyl);
    EXPECT_NE(e.find("axisymmetric"), std::string::npos) << e;
    const CaseSpec c = parse_modern_case(cyl, "case.toml", axi);
    ASSERT_EQ(c.fluid_cylinders.size(), 1u);
    EXPECT_DOUBLE_EQ(c.fluid_cylinders[0].zmax, 0.5);
    e = error_of(std::string(kMinimal) + "[[fluid.cylinder]]\nradius = 0.01\neps = 0.02\n", axi);
    EXPECT_NE(e.find("wavelength"), std::string::npos) << e;

    // periodic z: read in either geometry, refused with a bottom wall (the default)
    e = error_of(kMinimal, {"domain.periodic_z=true"});
    EXPECT_NE(e.find("periodic_z"), std::string::npos) << e;
    const CaseSpec p = parse_modern_case(kMinimal, "case.toml", {"domain.periodic_z=true", "domain.wall_bottom=false"});
    EXPECT_TRUE(p.params.periodic_z);
    EXPECT_TRUE(p.params.domain_box);
}

// domain.axis_pair (cases/CASE_FORMAT.md): the smoothed-radius pair by default; "rings" read,
// written back and read again; refused in planar geometry, below h = 2 dx and for an unknown
// value, naming the key, what was expected and what was found.
TEST(ModernCase, AxisPair) {
    const std::vector<std::string> axi = {"domain.geometry=\"axisymmetric\"", "domain.wall_left=false",
                                          "numerics.lattice=\"sc\""};
    EXPECT_EQ(parse_modern_case(kMinimal, "case.toml", axi).params.axis_pair, AxisPair::SmoothedRadius);
    std::vector<std::string> rings = axi;
    rings.push_back("domain.axis_pair=\"rings\"");
    std::string e = error_of(kMinimal, rings);   // kMinimal's h is below 2 dx
    EXPECT_NE(e.find("domain.axis_pair"), std::string::npos) << e;
    EXPECT_NE(e.find("h_over_dx >= 2"), std::string::npos) << e;
    EXPECT_NE(e.find("found h = "), std::string::npos) << e;
    rings.push_back("resolution.h_over_dx=2.0");
    const CaseSpec s = parse_modern_case(kMinimal, "case.toml", rings);
    EXPECT_EQ(s.params.axis_pair, AxisPair::Rings);
    expect_round_trip(s);
    e = error_of(kMinimal, {"domain.axis_pair=\"rings\""});
    EXPECT_NE(e.find("domain.geometry = \"axisymmetric\""), std::string::npos) << e;
    std::vector<std::string> bad = axi;
    bad.push_back("domain.axis_pair=\"ring\"");
    e = error_of(kMinimal, bad);
    EXPECT_NE(e.find("\"smoothed_radius\", \"rings\""), std::string::npos) << e;
}

// domain.renormalise_ring_continuity (cases/CASE_FORMAT.md): off by default; read with the rings
// pair, written back and read again; refused with the smoothed-radius pair, naming the key and
// the pair it needs.
TEST(ModernCase, RenormaliseRingContinuity) {
    std::vector<std::string> rings = {"domain.geometry=\"axisymmetric\"", "domain.wall_left=false",
                                      "numerics.lattice=\"sc\"", "resolution.h_over_dx=2.0",
                                      "domain.axis_pair=\"rings\""};
    EXPECT_FALSE(parse_modern_case(kMinimal, "case.toml", rings).params.renormalise_ring_continuity);
    rings.push_back("domain.renormalise_ring_continuity=true");
    const CaseSpec s = parse_modern_case(kMinimal, "case.toml", rings);
    EXPECT_TRUE(s.params.renormalise_ring_continuity);
    expect_round_trip(s);
    const std::string e = error_of(kMinimal, {"domain.geometry=\"axisymmetric\"", "domain.wall_left=false",
                                              "numerics.lattice=\"sc\"", "domain.renormalise_ring_continuity=true"});
    EXPECT_NE(e.find("domain.renormalise_ring_continuity"), std::string::npos) << e;
    EXPECT_NE(e.find("domain.axis_pair = \"rings\""), std::string::npos) << e;
    EXPECT_NE(e.find("smoothed_radius"), std::string::npos) << e;
}

// The round-jet case of cases/ (it has a [nozzle]; the tests add the rings pair).
static std::string round_jet_case() {
    return read_text(std::filesystem::path(SPHJET_SOURCE_DIR) / "cases" / "round_jet" / "round_jet.toml");
}

// domain.renormalise_margin_d0 (cases/CASE_FORMAT.md): 0 by default; read with the renormalised
// continuity and a [nozzle], written back and read again; refused without the renormalised
// continuity or without a nozzle (naming the key and what it needs), and when negative.
TEST(ModernCase, RenormaliseMarginD0) {
    // the round-jet case of cases/, with the rings pair
    const std::string jet = round_jet_case();
    ASSERT_NE(jet.find("[nozzle]"), std::string::npos);
    const std::string rings = "domain.axis_pair=\"rings\"";
    EXPECT_EQ(parse_modern_case(jet, "jet.toml", {rings}).params.renormalise_margin_d0, 0.0);
    const CaseSpec s = parse_modern_case(
        jet, "jet.toml", {rings, "domain.renormalise_ring_continuity=true", "domain.renormalise_margin_d0=2"});
    EXPECT_EQ(s.params.renormalise_margin_d0, 2.0);
    expect_round_trip(s);
    std::string e = error_of(jet, {rings, "domain.renormalise_margin_d0=2"});
    EXPECT_NE(e.find("domain.renormalise_margin_d0"), std::string::npos) << e;
    EXPECT_NE(e.find("domain.renormalise_ring_continuity = true"), std::string::npos) << e;
    e = error_of(jet, {rings, "domain.renormalise_ring_continuity=true", "domain.renormalise_margin_d0=-1"});
    EXPECT_NE(e.find("domain.renormalise_margin_d0"), std::string::npos) << e;
    e = error_of(kMinimal, {"domain.geometry=\"axisymmetric\"", "domain.wall_left=false", "numerics.lattice=\"sc\"",
                            "resolution.h_over_dx=2.0", "domain.axis_pair=\"rings\"",
                            "domain.renormalise_ring_continuity=true", "domain.renormalise_margin_d0=2"});
    EXPECT_NE(e.find("domain.renormalise_margin_d0"), std::string::npos) << e;
    EXPECT_NE(e.find("[nozzle]"), std::string::npos) << e;
}

// domain.bound_ring_xsph (cases/CASE_FORMAT.md): off by default; read and written back with the
// rings pair; refused with any other pair, naming the key and what it needs.
TEST(ModernCase, BoundRingXsph) {
    const std::string jet = round_jet_case();
    const std::string rings = "domain.axis_pair=\"rings\"";
    EXPECT_FALSE(parse_modern_case(jet, "jet.toml", {rings}).params.bound_ring_xsph);
    const CaseSpec s = parse_modern_case(jet, "jet.toml", {rings, "domain.bound_ring_xsph=true"});
    EXPECT_TRUE(s.params.bound_ring_xsph);
    expect_round_trip(s);
    const std::string e = error_of(jet, {"domain.bound_ring_xsph=true"});
    EXPECT_NE(e.find("domain.bound_ring_xsph"), std::string::npos) << e;
    EXPECT_NE(e.find("domain.axis_pair = \"rings\""), std::string::npos) << e;
}

// surface_tension.balance_free_bodies (cases/CASE_FORMAT.md): off by default; read and written
// back; refused without surface tension, naming the key and what it needs.
TEST(ModernCase, BalanceFreeBodies) {
    const std::string jet = round_jet_case();
    EXPECT_FALSE(parse_modern_case(jet, "jet.toml").params.balance_free_bodies);
    const CaseSpec s = parse_modern_case(jet, "jet.toml", {"surface_tension.balance_free_bodies=true"});
    EXPECT_TRUE(s.params.balance_free_bodies);
    expect_round_trip(s);
    const std::string e = error_of(jet, {"surface_tension.balance_free_bodies=true", "surface_tension.sigma=0"});
    EXPECT_NE(e.find("surface_tension.balance_free_bodies"), std::string::npos) << e;
    EXPECT_NE(e.find("surface_tension.sigma > 0"), std::string::npos) << e;
}

// surface_tension.thin_rings_normals (cases/CASE_FORMAT.md): off by default; read and written
// back; refused without the surface fit, naming the key and what it needs.
TEST(ModernCase, ThinRingsNormals) {
    const std::string jet = round_jet_case();
    EXPECT_FALSE(parse_modern_case(jet, "jet.toml").params.thin_rings_normals);
    const CaseSpec s = parse_modern_case(
        jet, "jet.toml", {"surface_tension.curvature=surface_fit", "surface_tension.thin_rings_normals=true"});
    EXPECT_TRUE(s.params.thin_rings_normals);
    expect_round_trip(s);
    const std::string e = error_of(jet, {"surface_tension.curvature=normals", "surface_tension.thin_rings_normals=true"});
    EXPECT_NE(e.find("surface_tension.thin_rings_normals"), std::string::npos) << e;
    EXPECT_NE(e.find("surface_tension.curvature = \"surface_fit\""), std::string::npos) << e;
}

// surface_tension.fit_points_min (cases/CASE_FORMAT.md): 3 by default; read and written back;
// below 3 refused as out of range, above 3 refused without the surface fit, naming the key and
// what it needs.
TEST(ModernCase, FitPointsMin) {
    const std::string jet = round_jet_case();
    EXPECT_EQ(parse_modern_case(jet, "jet.toml").params.fit_points_min, 3);
    const CaseSpec s = parse_modern_case(
        jet, "jet.toml", {"surface_tension.curvature=surface_fit", "surface_tension.fit_points_min=4"});
    EXPECT_EQ(s.params.fit_points_min, 4);
    expect_round_trip(s);
    std::string e = error_of(jet, {"surface_tension.curvature=normals", "surface_tension.fit_points_min=4"});
    EXPECT_NE(e.find("surface_tension.fit_points_min"), std::string::npos) << e;
    EXPECT_NE(e.find("surface_tension.curvature = \"surface_fit\""), std::string::npos) << e;
    e = error_of(jet, {"surface_tension.curvature=surface_fit", "surface_tension.fit_points_min=2"});
    EXPECT_NE(e.find("surface_tension.fit_points_min"), std::string::npos) << e;
    EXPECT_NE(e.find("out of range"), std::string::npos) << e;
}

// The renormalised continuity's reach along a jet (core/jet_run.hpp): the intact length less
// the margin in nozzle diameters, never below 0, none while the jet is unbroken; margin 0
// leaves the length itself (bit for bit: the runs made before the key are unchanged).
TEST(JetRun, RenormaliseReach) {
    EXPECT_FALSE(renormalise_reach(std::nullopt, 2.0, 0.001));
    EXPECT_EQ(*renormalise_reach(0.0457, 0.0, 0.001194), 0.0457);
    EXPECT_NEAR(*renormalise_reach(0.0457, 2.0, 0.001194), 0.0457 - 0.002388, 1e-15);
    EXPECT_EQ(*renormalise_reach(0.002, 2.0, 0.001194), 0.0);
}

// numerics.bulk_viscosity (cases/CASE_FORMAT.md): off by default; read, written back and read
// again, in either geometry; out of [0, 1] refused, naming the key and the range.
TEST(ModernCase, BulkViscosity) {
    EXPECT_EQ(parse_modern_case(kMinimal, "case.toml", {}).params.bulk_viscosity, 0.0);
    const CaseSpec s = parse_modern_case(kMinimal, "case.toml", {"numerics.bulk_viscosity=0.5"});
    EXPECT_EQ(s.params.bulk_viscosity, 0.5);
    expect_round_trip(s);
    const CaseSpec a = parse_modern_case(kMinimal, "case.toml",
                                         {"domain.geometry=\"axisymmetric\"", "domain.wall_left=false",
                                          "numerics.lattice=\"sc\"", "numerics.bulk_viscosity=0.25"});
    EXPECT_EQ(a.params.bulk_viscosity, 0.25);
    for (const char* bad : {"numerics.bulk_viscosity=-0.1", "numerics.bulk_viscosity=1.5"}) {
        const std::string e = error_of(kMinimal, {bad});
        EXPECT_NE(e.find("numerics.bulk_viscosity"), std::string::npos) << e;
        EXPECT_NE(e.find("[0, 1]"), std::string::npos) << e;
    }
}

// numerics.shifting (cases/CASE_FORMAT.md): off by default; read, written back and read again;
// below 0 or above 100 refused, naming the key and the range.
TEST(ModernCase, Shifting) {
    EXPECT_EQ(parse_modern_case(kMinimal, "case.toml", {}).params.shifting, 0.0);
    const CaseSpec s = parse_modern_case(kMinimal, "case.toml", {"numerics.shifting=0.03"});
    EXPECT_EQ(s.params.shifting, 0.03);
    expect_round_trip(s);
    for (const char* bad : {"numerics.shifting=-0.1", "numerics.shifting=101"}) {
        const std::string e = error_of(kMinimal, {bad});
        EXPECT_NE(e.find("numerics.shifting"), std::string::npos) << e;
        EXPECT_NE(e.find("[0, 100]"), std::string::npos) << e;
    }
}

// numerics.artificial_alpha (cases/CASE_FORMAT.md): off by default; with laminar viscosity read,
// written back and read again; with the artificial viscosity (the default model) refused, naming
// the key and numerics.alpha; out of [0, 1] refused, naming the key and the range.
TEST(ModernCase, ArtificialAlphaOnTopOfLaminar) {
    EXPECT_EQ(parse_modern_case(kMinimal, "case.toml", {}).params.artificial_alpha, 0.0);
    const CaseSpec s = parse_modern_case(
        kMinimal, "case.toml", {"numerics.viscosity=\"laminar\"", "fluid.mu=1e-3", "numerics.artificial_alpha=0.02"});
    EXPECT_EQ(s.params.artificial_alpha, 0.02);
    EXPECT_EQ(s.params.visc_value, 1e-6);
    expect_round_trip(s);
    std::string e = error_of(kMinimal, {"numerics.artificial_alpha=0.02"});
    EXPECT_NE(e.find("numerics.artificial_alpha"), std::string::npos) << e;
    EXPECT_NE(e.find("numerics.alpha"), std::string::npos) << e;
    EXPECT_NE(e.find("\"artificial\""), std::string::npos) << e;
    e = error_of(kMinimal, {"numerics.viscosity=\"laminar\"", "fluid.mu=1e-3", "numerics.artificial_alpha=1.5"});
    EXPECT_NE(e.find("numerics.artificial_alpha"), std::string::npos) << e;
    EXPECT_NE(e.find("[0, 1]"), std::string::npos) << e;
}

// numerics.artificial_reconstruction (cases/CASE_FORMAT.md): off by default; read with the
// artificial viscosity and with artificial_alpha beside the laminar one, written back and read
// again; with the laminar viscosity alone refused, naming the key, what it needs and what was
// found.
TEST(ModernCase, ArtificialReconstructionNeedsAnArtificialViscosity) {
    EXPECT_FALSE(parse_modern_case(kMinimal, "case.toml", {}).params.artificial_reconstruction);
    EXPECT_TRUE(parse_modern_case(kMinimal, "case.toml", {"numerics.artificial_reconstruction=true"})
                    .params.artificial_reconstruction);
    const CaseSpec s = parse_modern_case(kMinimal, "case.toml",
                                         {"numerics.viscosity=\"laminar\"", "fluid.mu=1e-3",
                                          "numerics.artificial_alpha=0.02", "numerics.artificial_reconstruction=true"});
    EXPECT_TRUE(s.params.artificial_reconstruction);
    expect_round_trip(s);
    const std::string e = error_of(
        kMinimal, {"numerics.viscosity=\"laminar\"", "fluid.mu=1e-3", "numerics.artificial_reconstruction=true"});
    EXPECT_NE(e.find("numerics.artificial_reconstruction"), std::string::npos) << e;
    EXPECT_NE(e.find("numerics.artificial_alpha > 0"), std::string::npos) << e;
    EXPECT_NE(e.find("numerics.artificial_alpha = 0"), std::string::npos) << e;
}

// numerics.density_diffusion and resolution.jitter (cases/CASE_FORMAT.md): off by default; read,
// written back and read again; out of range refused; the diffusion refused in the axisymmetric
// geometry, naming the key, what was expected and what was found.
TEST(ModernCase, DensityDiffusionAndJitter) {
    EXPECT_EQ(parse_modern_case(kMinimal, "case.toml", {}).params.density_diffusion, 0.0);
    EXPECT_EQ(parse_modern_case(kMinimal, "case.toml", {}).params.jitter, 0.0);
    const CaseSpec s = parse_modern_case(kMinimal, "case.toml",
                                         {"numerics.density_diffusion=0.1", "resolution.jitter=0.01",
                                          "resolution.jitter_seed=9"});
    EXPECT_EQ(s.params.density_diffusion, 0.1);
    EXPECT_EQ(s.params.jitter, 0.01);
    EXPECT_EQ(s.params.jitter_seed, 9);
    expect_round_trip(s);
    std::string e = error_of(kMinimal, {"numerics.density_diffusion=-0.1"});
    EXPECT_NE(e.find("numerics.density_diffusion"), std::string::npos) << e;
    e = error_of(kMinimal, {"resolution.jitter=0.5"});
    EXPECT_NE(e.find("[0, 0.25]"), std::string::npos) << e;
    e = error_of(kMinimal, {"domain.geometry=\"axisymmetric\"", "domain.wall_left=false",
                            "numerics.lattice=\"sc\"", "numerics.density_diffusion=0.1"});
    EXPECT_NE(e.find("numerics.density_diffusion"), std::string::npos) << e;
    EXPECT_NE(e.find("domain.geometry = \"axisymmetric\""), std::string::npos) << e;
    EXPECT_NE(e.find("found 0.1"), std::string::npos) << e;
}

// surface_tension.curvature_normals (cases/CASE_FORMAT.md): every filtered normal by default;
// "surface_band" read, written back and read again; refused with the colour-gradient delta,
// naming key, expected and found.
TEST(ModernCase, CurvatureNormals) {
    EXPECT_EQ(parse_modern_case(kMinimal, "case.toml", {}).params.curvature_normals, CurvatureNormals::All);
    const CaseSpec s = parse_modern_case(kMinimal, "case.toml", {"surface_tension.curvature_normals=\"surface_band\""});
    EXPECT_EQ(s.params.curvature_normals, CurvatureNormals::SurfaceBand);
    expect_round_trip(s);
    const std::string e = error_of(kMinimal, {"surface_tension.delta=\"colour_gradient\"",
                                              "surface_tension.curvature_normals=\"surface_band\""});
    EXPECT_NE(e.find("surface_tension.curvature_normals"), std::string::npos) << e;
    EXPECT_NE(e.find("surface_tension.delta = \"pressure_consistent\""), std::string::npos) << e;
    EXPECT_NE(e.find("found surface_tension.delta = \"colour_gradient\""), std::string::npos) << e;
}

// surface_tension.curvature (cases/CASE_FORMAT.md): the normals' divergence by default;
// "surface_fit" read, written back and read again; refused with the colour-gradient delta,
// naming key, expected and found.
TEST(ModernCase, CurvatureModel) {
    EXPECT_EQ(parse_modern_case(kMinimal, "case.toml", {}).params.curvature, CurvatureModel::Normals);
    const CaseSpec s = parse_modern_case(kMinimal, "case.toml", {"surface_tension.curvature=\"surface_fit\""});
    EXPECT_EQ(s.params.curvature, CurvatureModel::SurfaceFit);
    expect_round_trip(s);
    const std::string e = error_of(kMinimal, {"surface_tension.delta=\"colour_gradient\"",
                                              "surface_tension.curvature=\"surface_fit\""});
    EXPECT_NE(e.find("surface_tension.curvature"), std::string::npos) << e;
    EXPECT_NE(e.find("surface_tension.delta = \"pressure_consistent\""), std::string::npos) << e;
    EXPECT_NE(e.find("found surface_tension.delta = \"colour_gradient\""), std::string::npos) << e;
}

// surface_tension.rings_curvature (cases/CASE_FORMAT.md): the neighbours' mean by default in the
// rings pair; "own" read, written back and read again; refused with the smoothed-radius pair,
// with the colour-gradient delta and for an unknown value, naming key, expected and found.
TEST(ModernCase, RingsCurvature) {
    const std::vector<std::string> rings = {"domain.geometry=\"axisymmetric\"", "domain.wall_left=false",
                                            "numerics.lattice=\"sc\"", "resolution.h_over_dx=2.0",
                                            "domain.axis_pair=\"rings\""};
    EXPECT_EQ(parse_modern_case(kMinimal, "case.toml", rings).params.rings_curvature,
              RingsCurvature::NeighbourMean);
    std::vector<std::string> own = rings;
    own.push_back("surface_tension.rings_curvature=\"own\"");
    const CaseSpec s = parse_modern_case(kMinimal, "case.toml", own);
    EXPECT_EQ(s.params.rings_curvature, RingsCurvature::Own);
    expect_round_trip(s);
    std::vector<std::string> smoothed(rings.begin(), rings.end() - 1);
    smoothed.push_back("surface_tension.rings_curvature=\"own\"");
    std::string e = error_of(kMinimal, smoothed);
    EXPECT_NE(e.find("surface_tension.rings_curvature"), std::string::npos) << e;
    EXPECT_NE(e.find("domain.axis_pair = \"rings\""), std::string::npos) << e;
    EXPECT_NE(e.find("found domain.axis_pair = \"smoothed_radius\""), std::string::npos) << e;
    std::vector<std::string> colour = own;
    colour.push_back("surface_tension.delta=\"colour_gradient\"");
    e = error_of(kMinimal, colour);
    EXPECT_NE(e.find("found surface_tension.delta = \"colour_gradient\""), std::string::npos) << e;
    std::vector<std::string> bad = rings;
    bad.push_back("surface_tension.rings_curvature=\"mean\"");
    e = error_of(kMinimal, bad);
    EXPECT_NE(e.find("\"neighbour_mean\", \"own\""), std::string::npos) << e;
}

// output.revolution_sectors (cases/CASE_FORMAT.md [output]): read in axisymmetric cases, off by
// default, written back only when on (so that the case.toml of a run without it is unchanged);
// out-of-range values are refused in either geometry, naming file, key, expected and found.
TEST(ModernCase, RevolutionSectors) {
    const std::vector<std::string> axi = {"domain.geometry=\"axisymmetric\"", "domain.wall_left=false",
                                          "numerics.lattice=\"sc\""};
    EXPECT_EQ(parse_modern_case(kMinimal, "case.toml", axi).output.revolution_sectors, 0);
    EXPECT_EQ(write_modern_case(parse_modern_case(kMinimal, "case.toml", axi)).find("revolution_sectors"),
              std::string::npos);
    for (const int n : {1, 24, 360}) {
        std::vector<std::string> on = axi;
        on.push_back("output.revolution_sectors=" + std::to_string(n));
        const CaseSpec s = parse_modern_case(kMinimal, "case.toml", on);
        EXPECT_EQ(s.output.revolution_sectors, n);
        expect_round_trip(s);
    }
    std::vector<std::string> bad = axi;
    bad.push_back("output.revolution_sectors=361");
    std::string e = error_of(kMinimal, bad);
    for (const char* part : {"case.toml: output.revolution_sectors", "set by override", "out of range",
                             "expected an integer in [0, 360]", "found 361"})
        EXPECT_NE(e.find(part), std::string::npos) << part << " not in: " << e;
    bad.back() = "output.revolution_sectors=-1";
    e = error_of(kMinimal, bad);
    EXPECT_NE(e.find("found -1"), std::string::npos) << e;
}

}  // namespace
}  // namespace sphjet
