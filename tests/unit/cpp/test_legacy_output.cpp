// Legacy output files: PART (Fortran 7e16.8), DT, steps.txt, INDAT and run directories.
// The format checks are exact (byte for byte); the legacy-run checks read the reference runs in
// ../shared/legacy and skip when that folder is absent.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "io/legacy_output.hpp"
#include "model/errors.hpp"

namespace fs = std::filesystem;
using namespace sphjet;

namespace {

fs::path temp_dir(const std::string& name) {
    fs::path d = fs::temp_directory_path() / ("sphjet_test_legacy_output_" + name);
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_text(const fs::path& p, const std::string& s) { std::ofstream(p) << s; }

fs::path legacy_dir(const std::string& run) { return fs::path(SPHJET_SHARED_DIR) / "legacy" / run; }

#define REQUIRE_LEGACY(run)                                                                     \
    if (!fs::is_directory(legacy_dir(run)))                                                     \
    GTEST_SKIP() << "legacy reference run " << legacy_dir(run) << " not found (needs ../shared)"

std::string error_of(auto&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

// gfortran's E16.8, checked against gfortran 12 output for the same doubles.
TEST(FortranE16_8, MatchesGfortran) {
    EXPECT_EQ(fortran_e16_8(1.0), "  0.10000000E+01");
    EXPECT_EQ(fortran_e16_8(-1.0), " -0.10000000E+01");
    EXPECT_EQ(fortran_e16_8(0.0), "  0.00000000E+00");
    EXPECT_EQ(fortran_e16_8(-0.0), " -0.00000000E+00");
    EXPECT_EQ(fortran_e16_8(0.03), "  0.30000000E-01");
    EXPECT_EQ(fortran_e16_8(1e-5), "  0.10000000E-04");
    EXPECT_EQ(fortran_e16_8(123456785.0), "  0.12345678E+09");  // round half to even
    EXPECT_EQ(fortran_e16_8(9.999999995), "  0.10000000E+02");  // rounds into the next decade
    EXPECT_EQ(fortran_e16_8(1e100), "  0.10000000+101");        // 3-digit exponent drops the E
    EXPECT_EQ(fortran_e16_8(-2.5e-120), " -0.25000000-119");
    EXPECT_EQ(fortran_e16_8(0.125), "  0.12500000E+00");
    EXPECT_EQ(fortran_e16_8(1000.0), "  0.10000000E+04");
}

TEST(PartFile, RoundTripInLegacyOrder) {
    const auto dir = temp_dir("roundtrip");
    ParticleSet ps;
    ps.push(0.0, 0.0, 0.0, 0.0, 1000.0, 0.0, 0.45, ParticleKind::FixedBoundary);
    ps.push(0.5, 0.25, -1.5, 2.0e-3, 1001.25, 17.5, 0.225, ParticleKind::Fluid);
    ps.push(0.75, 0.125, 3.0, -4.0, 999.5, -2.0, 0.225, ParticleKind::Fluid);
    ps.nb = ps.nbf = 1;
    // Stored in another order (as a cell-sorted core keeps them): file order follows id.
    std::swap(ps.x[1], ps.x[2]);
    std::swap(ps.z[1], ps.z[2]);
    std::swap(ps.u[1], ps.u[2]);
    std::swap(ps.w[1], ps.w[2]);
    std::swap(ps.rho[1], ps.rho[2]);
    std::swap(ps.p[1], ps.p[2]);
    ps.id = {0, 2, 1};
    write_part(dir / "PART_0001", ps);
    const std::string text = slurp(dir / "PART_0001");
    const std::string line2 =
        "  0.50000000E+00  0.25000000E+00 -0.15000000E+01  0.20000000E-02  0.10012500E+04  0.17500000E+02  0.22500000E+00\n";
    EXPECT_EQ(text.substr(113, 113), line2);
    EXPECT_EQ(text.size(), 3u * 113u);  // 7 x 16 characters and a newline per particle

    const ParticleSet back = read_part(dir / "PART_0001", 1);
    ASSERT_EQ(back.size(), 3u);
    EXPECT_EQ(back.kind[0], static_cast<int>(ParticleKind::FixedBoundary));
    EXPECT_EQ(back.kind[1], static_cast<int>(ParticleKind::Fluid));
    EXPECT_DOUBLE_EQ(back.x[1], 0.5);
    EXPECT_DOUBLE_EQ(back.u[2], 3.0);
    EXPECT_DOUBLE_EQ(back.p[2], -2.0);
    EXPECT_EQ(back.id[2], 2);
    EXPECT_EQ(back.active[2], 1);
}

TEST(PartFile, MalformedLineNamesFileAndLine) {
    const auto dir = temp_dir("malformed");
    write_text(dir / "PART_0001",
               "  0.1E+01  0.1E+01  0.0  0.0  0.1E+04  0.0  0.1\n"
               "  0.1E+01  0.1E+01  0.0  0.0  0.1E+04  0.0  0.1\n"
               "  0.1E+01  0.1E+01  0.0  garbage  0.1E+04  0.0  0.1\n");
    const std::string msg = error_of([&] { (void)read_part(dir / "PART_0001", 0); });
    EXPECT_NE(msg.find("PART_0001:3"), std::string::npos) << msg;
    EXPECT_NE(msg.find("garbage"), std::string::npos) << msg;

    write_text(dir / "PART_0002", "  0.1E+01  0.1E+01  0.0  0.0  0.1E+04  0.0\n");  // 6 columns
    EXPECT_NE(error_of([&] { (void)read_part(dir / "PART_0002", 0); }).find("PART_0002:1"), std::string::npos);

    write_text(dir / "PART_0003", "  0.1E+01  0.1E+01  0.0  0.0  0.1E+04  0.0  0.1\n");
    EXPECT_NE(error_of([&] { (void)read_part(dir / "PART_0003", 5); }).find("nb = 5"), std::string::npos);
    EXPECT_NE(error_of([&] { (void)read_part(dir / "missing", 0); }).find("no such file"), std::string::npos);
}

TEST(PartFile, ReadsThreeDigitExponentsAndDExponents) {
    const auto dir = temp_dir("exponents");
    write_text(dir / "P", "  0.10000000+101 -0.25000000-119  0.1D+01  0.0  0.1E+04  0.0  0.1\n");
    const ParticleSet ps = read_part(dir / "P", 0);
    EXPECT_DOUBLE_EQ(ps.x[0], 1e100);
    EXPECT_DOUBLE_EQ(ps.z[0], -2.5e-120);
    EXPECT_DOUBLE_EQ(ps.u[0], 1.0);
}

TEST(DtFile, WritesHeaderAndRowsReadBack) {
    const auto dir = temp_dir("dt");
    {
        DtFile dt(dir / "DT");
        dt.append({2.03292146e-2, 2.04347335e-2, 8.49752745e-4, 1.69950552e-4});
        dt.append({0.1, 1e-3, 2e-4, 3e-5});
    }
    const std::string text = slurp(dir / "DT");
    EXPECT_EQ(text.substr(0, 21), " time dt1 dt2 dt_new\n");
    const auto rows = read_dt(dir / "DT");
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_NEAR(rows[0].time, 2.03292146e-2, 1e-16);
    EXPECT_NEAR(rows[1].dt_new, 3e-5, 1e-20);

    write_text(dir / "DT2", " time dt1 dt2 dt_new\n 0.1 0.2 0.3 0.4\n 0.1 0.2 x 0.4\n");
    EXPECT_NE(error_of([&] { (void)read_dt(dir / "DT2"); }).find("DT2:3"), std::string::npos);
}

TEST(StepsFile, WritesAndReadsBack) {
    const auto dir = temp_dir("steps");
    {
        StepsFile s(dir / "steps.txt");
        s.append({0, 0, 0.0});
        s.append({1, 12, 2.03107111e-3});
        s.append({kFinalOutput, 295, 5.01343124e-2});
    }
    const auto rows = read_steps(dir / "steps.txt");
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_EQ(rows[1].step, 12);
    EXPECT_EQ(rows[2].output, -1);
    EXPECT_NEAR(rows[2].time, 5.01343124e-2, 1e-12);
    write_text(dir / "bad.txt", "# output step time\n1 12.5 0.1\n");
    EXPECT_NE(error_of([&] { (void)read_steps(dir / "bad.txt"); }).find("bad.txt:2"), std::string::npos);
}

TEST(LegacyRun, OurRunDirectoryWithStepsFile) {
    const auto dir = temp_dir("ours");
    ParticleSet ps;
    ps.push(0.0, 0.0, 0, 0, 1000, 0, 1, ParticleKind::FixedBoundary);
    ps.push(1.0, 0.0, 0, 0, 1000, 0, 1, ParticleKind::FixedBoundary);
    ps.push(0.5, 0.5, 0, 0, 1000, 0, 1, ParticleKind::Fluid);
    ps.push(2.0, 0.0, 0, 0, 1000, 0, 1, ParticleKind::Fluid);  // parked beyond the walls
    ps.nb = ps.nbf = 2;
    write_part(dir / "PART_0010", ps);
    write_part(dir / "PART_0002", ps);
    {
        StepsFile s(dir / "steps.txt");
        s.append({2, 20, 0.2});
        s.append({10, 100, 1.0});
    }
    const LegacyRun run = read_legacy_run(dir);
    ASSERT_EQ(run.outputs.size(), 2u);
    EXPECT_EQ(run.outputs[0].number, 2);  // sorted by number, not by name
    EXPECT_EQ(run.outputs[1].number, 10);
    EXPECT_EQ(*run.outputs[1].step, 100);
    EXPECT_DOUBLE_EQ(*run.outputs[1].time, 1.0);
    EXPECT_TRUE(run.has_steps());
    EXPECT_NE(error_of([&] { (void)load_output(run, run.outputs[0]); }).find("INDAT"), std::string::npos);
    const ParticleSet back = load_output(run, run.outputs[0], 2);
    EXPECT_EQ(back.active[2], 1);
    EXPECT_EQ(back.active[3], 0);  // x = 2 > the boundary's max x = 1: removed
    EXPECT_NE(error_of([&] { (void)read_legacy_run(dir / "nowhere"); }).find("not a run directory"),
              std::string::npos);
    EXPECT_NE(error_of([&] { (void)read_legacy_run(temp_dir("empty")); }).find("no particle files"),
              std::string::npos);
}

// Our writer reproduces the legacy files byte for byte (the values are the legacy ones, read
// back from the file: 8 significant digits survive the round trip through double exactly).
TEST(LegacyReference, PartFilesRewriteByteIdentical) {
    REQUIRE_LEGACY("case1_early");
    const auto dir = temp_dir("rewrite");
    for (const char* name : {"IPART", "PART_0029", "EPART"}) {
        const ParticleSet ps = read_part(legacy_dir("case1_early") / name, 801);
        write_part(dir / name, ps);
        EXPECT_EQ(slurp(dir / name), slurp(legacy_dir("case1_early") / name)) << name;
    }
}

TEST(LegacyReference, Case1EarlyStepsTimesAndCounts) {
    REQUIRE_LEGACY("case1_early");
    const LegacyRun run = read_legacy_run(legacy_dir("case1_early"));
    ASSERT_TRUE(run.indat);
    EXPECT_DOUBLE_EQ(run.indat->dx, 0.03);
    EXPECT_EQ(run.indat->np, 5123u);
    EXPECT_EQ(run.indat->nb, 801u);
    EXPECT_EQ(run.indat->nbf, 801u);
    ASSERT_EQ(run.outputs.size(), 31u);  // IPART, PART_0001..0029, EPART
    EXPECT_EQ(run.outputs.front().number, 0);
    EXPECT_EQ(*run.outputs.front().step, 0);
    for (int k = 1; k <= 29; ++k) {
        EXPECT_EQ(run.outputs[k].number, k);
        EXPECT_EQ(*run.outputs[k].step, 2 + 10 * k) << "PART_" << k;  // steps 12, 22, ... 292
    }
    EXPECT_EQ(run.outputs.back().number, kFinalOutput);
    EXPECT_EQ(*run.outputs.back().step, 295);
    EXPECT_NEAR(*run.outputs[1].time, 2.03107111e-3, 1e-12);
    EXPECT_NEAR(*run.outputs.back().time, 5.01343124e-2, 1e-12);
    EXPECT_TRUE(run.has_steps());
    EXPECT_TRUE(run.has_times());
}

TEST(LegacyReference, Case1SparsePartFilesKeepTheirNumbers) {
    REQUIRE_LEGACY("case1");
    const LegacyRun run = read_legacy_run(legacy_dir("case1"));
    ASSERT_EQ(run.outputs.size(), 31u);  // IPART, PART_0005..0145 every 5th, EPART
    EXPECT_EQ(run.outputs[1].number, 5);
    EXPECT_EQ(*run.outputs[1].step, 591);
    EXPECT_NEAR(*run.outputs[1].time, 0.100174859, 1e-9);
    EXPECT_EQ(*run.outputs.back().step, 18327);
    EXPECT_NEAR(*run.outputs.back().time, 3.00004411, 1e-8);
    // Particle 5063 (1-based) is reported out of limits at 0.75 s and stays parked at the wall.
    const auto& p40 = run.outputs[8];
    ASSERT_EQ(p40.number, 40);
    ASSERT_EQ(p40.removed.size(), 1u);
    EXPECT_EQ(p40.removed[0], 5062);
    const ParticleSet ps = load_output(run, p40);
    EXPECT_EQ(ps.active[5062], 0);
    EXPECT_EQ(ps.active[5061], 1);
}

TEST(LegacyReference, ObstacleRemovedParticlesPerOutput) {
    REQUIRE_LEGACY("obstacle_wendland");
    const LegacyRun run = read_legacy_run(legacy_dir("obstacle_wendland"));
    ASSERT_EQ(run.outputs.size(), 13u);
    EXPECT_EQ(run.outputs[6].removed.size(), 0u);   // PART_0006
    EXPECT_EQ(run.outputs[7].removed.size(), 20u);  // PART_0007 (stdout: 20 by 0.350 s)
    EXPECT_EQ(run.outputs[8].removed.size(), 25u);
    EXPECT_EQ(run.outputs.back().removed.size(), 25u);
}
