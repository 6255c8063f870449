// The legacy case-file reader: a valid case gives the parameters SPHYSICSgen2D derives from
// it, and every malformed or unsupported case gives an InputError that names the file and
// line, the option, and what was found (tests/data/bad_cases holds one file per fault, each
// a copy of the small valid case below with one line changed).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "config/legacy_case.hpp"
#include "core/solver.hpp"
#include "geometry/generator.hpp"
#include "model/errors.hpp"
#include "sphjet_core.h"

namespace fs = std::filesystem;
using namespace sphjet;

namespace {

const fs::path kBadCases = fs::path(SPHJET_SOURCE_DIR) / "tests" / "data" / "bad_cases";
const fs::path kShared = fs::path(SPHJET_SHARED_DIR) / "legacy";

// The small valid case the bad cases derive from: dynamic boundaries, BCC, 1 m box.
const char* kValidCase = R"(0                 Choose Starting options:  0=new, 1=restart
5                 Kernel: 1=gaussian, 2=quadratic; 3=cubic; 5=Wendland
1                 Time-stepping algorithm: 1=predictor-corrector
2                 Density Filter: 0=none, 1=Shepard filter, 2=MLS
30                ndt_FilterPerform ?
0                 Kernel correction
1                 Viscosity treatment: 1=artificial; 2=laminar; 3=laminar + SPS
0.3               Viscosity value
0                 vorticity printing ? (1=yes)
1                 Equation of State: 1=Tait's equation
0.5               Maximum Depth (h_SWL) to calculate B
10                Coefficient of speed of sound
2                 Boundary Conditions: 1=Repulsive Force; 2=Dalrymple
15                ndt_DBCPerform ? (1 means no correction)
1                 Geometry of the zone:  1=BOX
2                 Initial Fluid Particle Structure: 1= SC, 2= BCC
1.0,1.0           Box dimension LX,LZ?
0.05,0.05         Spacing dx,dz?
0                 Inclination of floor in X ( beta ) ??
0,0,0             Periodic Lateral boundaries
0                 Add wall
0                 Add obstacle (1=y)
0                 Add wavemaker (1=y)
0                 Add gate (1=y)
0                 Add Floating Body (1=yes)
2                 Initial conditions: 2) particles on a staggered grid
0                 Correct pressure at boundaries ?? (1=y)
0.05,0.4          Cube containing particles :  XMin, Xmax ??
0.05,0.5          Cube containing particles :  ZMin, Zmax ??
0                 Fill a new region
1.0,0.01          Input the tmax and out
0.                initial time of outputting general data
0.0005,1.0,-1.0   For detailed recording during RUN: out_detail, start, end
0.0001,1          Input dt?? , i_var_dt ??
0.2               CFL number (0.1-0.5)
0.92              h=coefficient*sqrt(dx*dx+dz*dz):  coefficient ???
0                 Use of Riemann Solver
1                 Which compiler is desired
2                 Precision of XYZ Variables: 1=Single, 2=Double
)";

std::string error_of(const fs::path& file) {
    try {
        (void)read_legacy_case(file);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST(LegacyCase, ValidCaseGivesTheGeneratorsParameters) {
    const CaseSpec s = parse_legacy_case(kValidCase, "valid.txt");
    const SimParams& p = s.params;
    EXPECT_EQ(p.kernel, KernelType::Wendland);
    EXPECT_EQ(p.density_filter, DensityFilter::MLS);
    EXPECT_EQ(p.filter_period, 30);
    EXPECT_EQ(p.boundary, BoundaryType::Dynamic);
    EXPECT_EQ(p.dbc_period, 15);
    EXPECT_EQ(p.lattice, Lattice::BodyCentred);
    EXPECT_DOUBLE_EQ(p.visc_value, 0.3);
    EXPECT_DOUBLE_EQ(p.lx, 1.0);
    EXPECT_DOUBLE_EQ(p.dx, 0.05);
    EXPECT_DOUBLE_EQ(p.tmax, 1.0);
    EXPECT_DOUBLE_EQ(p.out, 0.01);
    EXPECT_DOUBLE_EQ(p.dt, 1e-4);
    EXPECT_TRUE(p.variable_dt);
    EXPECT_DOUBLE_EQ(p.cfl, 0.2);
    // B = coef^2 rho0 g h_SWL / 7 in single precision, as SPHYSICSgen2D: 100*1000*9.81*0.5/7.
    EXPECT_EQ(p.B, static_cast<double>(static_cast<float>(100.0f * 1000.0f * 9.81f * 0.5f / 7.0f)));
    EXPECT_NEAR(p.B, 100.0 * 1000.0 * 9.81 * 0.5 / 7.0, 0.02);
    // h = 0.92 sqrt(dx^2 + dz^2), kept in single precision (relative 6e-8).
    EXPECT_NEAR(p.h, 0.92 * std::sqrt(2.0) * 0.05, 1e-7 * p.h);
    EXPECT_NEAR(p.c0(), 10.0 * std::sqrt(9.81 * 0.5), 1e-5);
    ASSERT_EQ(s.fluid_blocks.size(), 1u);
    EXPECT_DOUBLE_EQ(s.fluid_blocks[0].r.xmax, 0.4);
    EXPECT_TRUE(s.legacy_fill);
    EXPECT_EQ(s.legacy.xz_precision, 2);
    EXPECT_DOUBLE_EQ(s.legacy.detail_end, -1.0);
}

// The legacy Case1 dam break (tests/regression/case1_early/Case1E.txt: coef 10, h_SWL 2 m)
// read by the case reader and handed to the core's Tait EoS: B = coef^2 rho0 g h_SWL / 7 in
// single precision, as SPHYSICSgen2D (its INDAT prints 280285.719), c0 = coef sqrt(g h_SWL)
// = 44.294 m/s (relative 1e-7: B's single-precision rounding), and the core's sound speed at
// rho0 is that c0 (sph_eos's c = c0 (rho/rho0)^3, exact at rho0 to round-off).
TEST(LegacyCase, Case1SoundSpeedReachesTheEos) {
    const CaseSpec s = read_legacy_case(fs::path(SPHJET_SOURCE_DIR) / "tests" / "regression" /
                                        "case1_early" / "Case1E.txt");
    const SimParams& p = s.params;
    EXPECT_EQ(p.B, static_cast<double>(100.0f * 1000.0f * 9.81f * 2.0f / 7.0f));
    EXPECT_NEAR(p.B, 280285.719, 1e-3);
    const double c0 = 10 * std::sqrt(9.81 * 2.0);
    EXPECT_NEAR(p.c0(), c0, 1e-7 * c0);
    const sph_params_t prm = core_params(p, s.output, DomainBounds{0, 4, 0, 4});
    EXPECT_EQ(prm.eos.b, p.B);
    double rho[2] = {p.rho0, 1.01 * p.rho0}, pr[2], c[2];
    ASSERT_EQ(sph_eos(&prm, 2, rho, pr, c), SPH_OK);
    EXPECT_EQ(pr[0], 0.0);
    EXPECT_NEAR(c[0], c0, 1e-7 * c0);
    // p = B ((rho/rho0)^7 - 1) at 1% compression (relative 1e-12: round-off of pow)
    const double p1 = p.B * (std::pow(1.01, 7) - 1);
    EXPECT_NEAR(pr[1], p1, 1e-12 * p1);
}

TEST(LegacyCase, SeveralFillRegionsObstaclesAndWalls) {
    std::string text = kValidCase;
    const auto replace = [&](const std::string& from, const std::string& to) {
        const auto at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    };
    replace("0                 Add wall\n", "1  Add wall\n0.8  XWall\n0.3  ZWall\n0  Add another wall\n");
    replace("0                 Add obstacle (1=y)\n",
            "1  Add obstacle\n1 rectangular\n1 solid\n2 ndens\n0.5,0.6  X\n0.0,0.1  Z\n90. beta\n0  another\n");
    replace("0                 Fill a new region\n", "1  Fill a new region\n0.6,0.75  X\n0.05,0.2  Z\n0  Fill\n");
    const CaseSpec s = parse_legacy_case(text, "multi.txt");
    ASSERT_EQ(s.walls.size(), 1u);
    EXPECT_DOUBLE_EQ(s.walls[0].x, 0.8);
    ASSERT_EQ(s.obstacles.size(), 1u);
    EXPECT_EQ(s.obstacles[0].density, 2);
    EXPECT_EQ(s.obstacles[0].kind, 1);
    EXPECT_EQ(s.fluid_blocks.size(), 2u);
}

// Legacy "Add gate": the lines after it are read as SPHYSICSgen2D asks them, the generator
// places one column of moving boundary particles after the fixed ones (nbf < nb) at z = k dz,
// and the motion goes into the parameters with SPHysics' cap (top particle + 0.1 h).
TEST(LegacyCase, GateIsReadAndPlacedAsMovingBoundary) {
    std::string text = kValidCase;
    const std::string from = "0                 Add gate (1=y)\n";
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, from.size(), "1  Add gate\n0.42  X\n0.0,0.5  ZZmin,ZZmax\n0.0,1.25  Vx,Vz\n0.01  tgate\n0  another\n");
    const CaseSpec s = parse_legacy_case(text, "gate.txt");
    ASSERT_EQ(s.gates.size(), 1u);
    EXPECT_DOUBLE_EQ(s.gates[0].x, 0.42);
    EXPECT_DOUBLE_EQ(s.gates[0].zmax, 0.5);
    EXPECT_DOUBLE_EQ(s.gates[0].vz, 1.25);
    EXPECT_DOUBLE_EQ(s.gates[0].t_start, 0.01);

    const InitialState st = generate(s);
    const ParticleSet& ps = st.particles;
    ASSERT_EQ(ps.nb - ps.nbf, 11u);  // z = 0, 0.05, ..., 0.5
    double ztop = 0;
    for (std::size_t i = 0; i < ps.size(); ++i) ztop = std::max(ztop, ps.z[i]);
    for (std::size_t k = 0; k < 11; ++k) {
        const std::size_t i = ps.nbf + k;
        EXPECT_EQ(ps.kind[i], static_cast<int>(ParticleKind::MovingBoundary));
        EXPECT_DOUBLE_EQ(ps.x[i], 0.42);
        EXPECT_NEAR(ps.z[i], 0.05 * static_cast<double>(k), 1e-12);
        EXPECT_DOUBLE_EQ(ps.rho[i], st.params.rho0);
    }
    for (std::size_t i = 0; i < ps.nbf; ++i) EXPECT_EQ(ps.kind[i], static_cast<int>(ParticleKind::FixedBoundary));
    EXPECT_EQ(ps.kind[ps.nb], static_cast<int>(ParticleKind::Fluid));
    EXPECT_DOUBLE_EQ(st.params.gate_vz, 1.25);
    EXPECT_DOUBLE_EQ(st.params.gate_t_start, 0.01);
    EXPECT_DOUBLE_EQ(st.params.gate_z_cap, ztop + 0.1 * st.params.h);
}

TEST(LegacyCase, FortranStyleNumbersAreAccepted) {
    std::string text = kValidCase;
    const auto at = text.find("0.3               Viscosity value");
    text.replace(at, 3, "3.0D-1");
    EXPECT_DOUBLE_EQ(parse_legacy_case(text, "d.txt").params.visc_value, 0.3);
}

TEST(LegacyCase, MissingFileIsNamed) {
    const std::string msg = error_of(kBadCases / "no_such_case.txt");
    EXPECT_NE(msg.find("no_such_case.txt"), std::string::npos) << msg;
    EXPECT_NE(msg.find("no such file"), std::string::npos) << msg;
}

// One bad case file per fault: the line the error must name, and words the message must hold
// (the option and what was found).
struct BadCase {
    const char* file;
    int line;
    std::vector<std::string> words;
};

class BadCases : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadCases, ErrorNamesLineOptionAndFinding) {
    const BadCase& c = GetParam();
    const fs::path file = kBadCases / c.file;
    ASSERT_TRUE(fs::exists(file)) << file;
    const std::string msg = error_of(file);
    const std::string where = file.string() + ":" + std::to_string(c.line) + ":";
    EXPECT_EQ(msg.rfind(where, 0), 0u) << "expected the message to start with " << where << "\n  got: " << msg;
    for (const std::string& w : c.words) EXPECT_NE(msg.find(w), std::string::npos) << "'" << w << "' not in: " << msg;
}

INSTANTIATE_TEST_SUITE_P(
    Table, BadCases,
    ::testing::Values(
        BadCase{"restart.txt", 1, {"unsupported starting option", "1 (restart)", "0 (new run)"}},
        BadCase{"kernel_4.txt", 2, {"invalid kernel", "found 4"}},
        BadCase{"verlet.txt", 3, {"time-stepping algorithm", "Verlet", "predictor-corrector"}},
        // Without its period line, the next answer (kernel correction 0) is read as the period.
        BadCase{"filter_period_missing.txt", 5, {"ndt_FilterPerform", "found 0"}},
        BadCase{"kernel_correction.txt", 6, {"unsupported kernel correction", "found 1"}},
        BadCase{"sps_viscosity.txt", 7, {"viscosity treatment", "SPS"}},
        BadCase{"ideal_gas.txt", 10, {"equation of state", "ideal gas", "Tait"}},
        BadCase{"hswl_zero.txt", 11, {"h_SWL", "> 0", "found 0"}},
        BadCase{"coef_not_number.txt", 12, {"speed of sound", "not a number", "'ten'"}},
        BadCase{"beach.txt", 15, {"geometry", "BEACH", "1 (BOX)"}},
        BadCase{"box_negative.txt", 17, {"box dimension", "found -1"}},
        BadCase{"spacing_zero.txt", 18, {"spacing", "> 0", "found 0"}},
        BadCase{"spacing_one_value.txt", 18, {"spacing dx,dz", "dz", "not a number", "'Spacing'"}},
        BadCase{"floor_inclined.txt", 19, {"inclination of floor", "found 10"}},
        BadCase{"periodic_x.txt", 20, {"periodic", "0,0,0"}},
        BadCase{"wavemaker.txt", 23, {"wavemaker"}},
        BadCase{"gate_second.txt", 29, {"another gate", "moves only the first", "0 (one gate)"}},
        BadCase{"gate_repulsive.txt", 24, {"gate", "repulsive", "no neighbour links"}},
        BadCase{"gate_inverted_z.txt", 26, {"gate ZZmin,ZZmax", "0.6, 0.2", "ZZmin <= ZZmax"}},
        BadCase{"floating_body.txt", 25, {"floating bod"}},
        BadCase{"drop.txt", 26, {"initial conditions", "round drop"}},
        BadCase{"correct_pressure.txt", 27, {"correct pressure at boundaries"}},
        BadCase{"fill_outside_box.txt", 28, {"fill region", "outside the box", "1.5"}},
        BadCase{"fill_inverted_z.txt", 29, {"fill region", "inverted", "ZMin < ZMax"}},
        BadCase{"ivar_dt_not_integer.txt", 34, {"i_var_dt", "not an integer", "'yes'"}},
        BadCase{"cfl_negative.txt", 35, {"CFL", "found -0.2"}},
        BadCase{"h_coefficient_zero.txt", 36, {"h coefficient", "found 0"}},
        BadCase{"riemann.txt", 37, {"Riemann solver", "Vila"}},
        BadCase{"truncated.txt", 31, {"ends before the tmax and out line", "end of file"}},
        BadCase{"trapezoid.txt", 23, {"obstacle shape", "trapezoid"}},
        BadCase{"repulsive_solid_obstacle.txt", 24, {"solid obstacle", "repulsive"}},
        BadCase{"repulsive_add_wall.txt", 21, {"add wall", "repulsive"}},
        BadCase{"obstacle_outside_box.txt", 26, {"obstacle", "outside the box", "1.2"}},
        BadCase{"add_wall_flag_2.txt", 21, {"add wall", "0 (no) or 1 (yes)", "found 2"}},
        BadCase{"empty.txt", 1, {"ends before the starting option", "end of file"}}),
    [](const ::testing::TestParamInfo<BadCase>& info) {
        std::string n = info.param.file;
        n = n.substr(0, n.find('.'));
        return n;
    });

TEST(LegacyCase, SharedLegacyCasesParse) {
    if (!fs::exists(kShared)) GTEST_SKIP() << "legacy reference data not found at " << kShared;
    const CaseSpec c1 = read_legacy_case(kShared / "case1" / "Case1.txt");
    EXPECT_EQ(c1.params.boundary, BoundaryType::Dynamic);
    EXPECT_EQ(c1.params.dbc_period, 15);
    EXPECT_EQ(c1.legacy.xz_precision, 1);
    const CaseSpec ob = read_legacy_case(kShared / "obstacle_wendland" / "ObstW.txt");
    EXPECT_EQ(ob.params.boundary, BoundaryType::Repulsive);
    EXPECT_DOUBLE_EQ(ob.params.wall_viscosity, 1e-5);
    ASSERT_EQ(ob.obstacles.size(), 1u);
    EXPECT_EQ(ob.obstacles[0].kind, 2);
    EXPECT_DOUBLE_EQ(ob.obstacles[0].r.xmax, 0.316);
    EXPECT_TRUE(ob.warnings.empty());
}
