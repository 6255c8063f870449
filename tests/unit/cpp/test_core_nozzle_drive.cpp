// The driven nozzle in the core (fortran_core/integrate/nozzle_drive.f90, half_step): through
// the C header, one predictor-corrector step of a block of fluid whose upper rows lie in the
// nozzle strip (s < 0 along the axis, |l| <= half-width) and whose lower rows are past the
// orifice line. Exact answers: a driven particle moves by u0 dt along the axis and leaves
// the step with velocity u0 (to round-off of one multiply-add), also when it entered the
// strip with another velocity (the corrector's extrapolation 2 u^{n+1/2} - u^n must not give
// 2 u0 - u^n); particles outside the strip follow their forces (gravity here); drive_u = 0
// drives nothing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core_fixture.hpp"

using namespace sphjet_test;

namespace {

struct Block {
    CoreParticles ps;
    std::vector<bool> in_strip;
};

// 6 x 10 particles, dx = 1 mm, centred on x = 0; the orifice line at z = 0, axis down:
// rows at z = +0.5 .. +4.5 mm are in the nozzle, rows at -0.5 .. -4.5 mm past it. A seventh
// column at x = 5 mm lies beside the strip (half-width 3.25 mm).
// z_shift moves every row (a plug row just upstream of the orifice line with z_shift < 0).
Block block(double u0, double w_entering, double z_shift = 0.0) {
    Block b;
    const double dx = 0.001;
    for (int k = 0; k < 10; ++k) {
        const double z = (k - 4.5) * dx + z_shift;
        for (int j = 0; j < 7; ++j) {
            const double x = j < 6 ? (j - 2.5) * dx : 0.005;
            const bool strip = z > 0 && j < 6;
            // One particle in the strip enters it at rest; the rest of the strip moves at u0.
            const double w = strip ? (k == 9 && j == 0 ? w_entering : -u0) : 0.0;
            b.ps.add(x, z, 0.0, w, 1000.0, 1000.0 * dx * dx, 2);
            b.in_strip.push_back(strip);
        }
    }
    return b;
}

sph_params_t drive_params(double u0) {
    sph_params_t p = water_params(5, 0.0013);
    p.time_step.variable_dt = 0;
    p.nozzle.u = u0;
    p.nozzle.x0 = 0.0;
    p.nozzle.z0 = 0.0;
    p.nozzle.ex = 0.0;
    p.nozzle.ez = -1.0;
    p.nozzle.half_width = 0.00325;
    return p;
}

// One step of b with prm and a fixed dt through the C header (prepare, step), on a workspace of
// its own.
void step_block(Block& b, const sph_params_t& prm, double dt) {
    auto arr = b.ps.bind();
    ASSERT_EQ(sph_prepare(&prm, &arr), SPH_OK);
    void* ws = sph_workspace_create();
    sph_step_info_t info{};
    info.dt = dt;
    const int status = sph_step(ws, &prm, &arr, &info);
    sph_workspace_destroy(ws);
    ASSERT_EQ(status, SPH_OK);
}

TEST(CoreNozzleDrive, PlugMovesRigidlyAtU0) {
    const double u0 = 0.25, dt = 1e-5;
    Block b = block(u0, 0.0);
    const std::vector<double> x0 = b.ps.x, z0 = b.ps.z;
    ASSERT_NO_FATAL_FAILURE(step_block(b, drive_params(u0), dt));
    for (std::size_t i = 0; i < b.ps.x.size(); ++i) {
        if (b.in_strip[i]) {
            EXPECT_EQ(b.ps.x[i], x0[i]) << i;
            EXPECT_NEAR(b.ps.z[i], z0[i] - u0 * dt, 1e-18) << i;
            EXPECT_EQ(b.ps.u[i], 0.0) << i;
            EXPECT_NEAR(b.ps.w[i], -u0, 1e-15) << i;  // also the one that entered at rest
        } else {
            // Free fluid: gravity (and pair forces) act; nothing holds it at -u0.
            EXPECT_NE(b.ps.w[i], -u0) << i;
            EXPECT_LT(b.ps.w[i], 0.0) << i;
        }
    }
}

TEST(CoreNozzleDrive, NoDriveWhenUIsZero) {
    Block b = block(0.25, 0.0);
    auto prm = drive_params(0.25);
    prm.nozzle.u = 0.0;
    ASSERT_NO_FATAL_FAILURE(step_block(b, prm, 1e-5));
    // Nothing is driven: the particle that entered at rest is not dragged to -u0, and the
    // strip's particles moving at -u0 are not held at drive_u = 0; only the forces of one
    // step act (the pair forces between the resting particle and its neighbours moving at
    // -u0 dominate gravity's 1e-4 m/s). Measured: the resting particle w = -1.02e-3 m/s, a
    // moving one w + u0 = -3.1e-4 m/s. Bounds ten times those (1e-2 and 3e-3 m/s), 25 and 80
    // times below u0, the error a driven or held particle would show.
    const std::size_t resting = 9 * 7 + 0, moving = 9 * 7 + 1;
    std::printf("after one step: resting particle w = %.3e m/s, moving particle w + u0 = %.3e m/s\n",
                b.ps.w[resting], b.ps.w[moving] + 0.25);
    EXPECT_NEAR(b.ps.w[resting], 0.0, 1e-2);
    EXPECT_NEAR(b.ps.w[moving], -0.25, 3e-3);
}

// nozzle.release = "crossing" (release = 1): the plug's last row starts the step 1 um upstream of
// the orifice line and the plug carries it 2.5 um, so it spends t_out = 1.5 um / u0 = 6 us of the
// 10 us step past the line and leaves the step with -u0 plus t_out times its acceleration (its
// rates after the step, which are the ones the step's last stage used, and gravity), to
// round-off; the rows that stay upstream keep -u0 exactly. With release = 0 the crossing row
// leaves with -u0. Both integrators.
TEST(CoreNozzleDrive, ReleaseAtTheCrossingAddsTheTimePastTheLine) {
    const double u0 = 0.25, dt = 1e-5, t_out = 1.5e-6 / u0;
    for (const int integrator : {1, 2}) {
        for (const int release : {0, 1}) {
            Block b = block(u0, -u0, -0.0005 + 1e-6);
            auto prm = drive_params(u0);
            prm.numerics.integrator = integrator;
            prm.nozzle.release = release;
            ASSERT_NO_FATAL_FAILURE(step_block(b, prm, dt));
            int crossed = 0;
            for (std::size_t i = 0; i < b.ps.x.size(); ++i) {
                if (!b.in_strip[i]) continue;
                const bool crossing = std::abs(b.ps.z[i] + 1.5e-6) < 1e-12;  // the last row, now past the line
                if (crossing && release == 1) {
                    ++crossed;
                    EXPECT_NEAR(b.ps.w[i], -u0 + t_out * (b.ps.az[i] + prm.gravity.gz), 1e-14) << i;
                    EXPECT_NEAR(b.ps.u[i], t_out * (b.ps.ax[i] + prm.gravity.gx), 1e-14) << i;
                    EXPECT_GT(std::abs(b.ps.w[i] + u0), 1e-5) << i;  // the release is seen: gravity's part 6e-5
                } else {
                    crossed += crossing ? 1 : 0;
                    EXPECT_NEAR(b.ps.w[i], -u0, 1e-15) << i << " integrator " << integrator;
                    EXPECT_EQ(b.ps.u[i], 0.0) << i;
                }
            }
            EXPECT_EQ(crossed, 6) << "integrator " << integrator << ", release " << release;
        }
    }
}

// nozzle.release = "landed" (release = 2): the plug's last row starts 33 um upstream of the orifice
// line, r = 132 us of travel at u0 = 0.25 m/s from it; asked for steps of 10 us, the core cuts r
// (plus the LAND_PAST of 1e-7 step, 1 ps) into ceiling(r / dt) = 14 equal steps and returns each
// in info.dt: the row crosses the line at the 14th step's end, within 1e-12 m (u0 times LAND_PAST
// of a step, 2.5e-13 m, plus round-off), with -u0 plus 1 ps of its acceleration, as the crossing's
// release gives (1e-9 m/s here, where the block's free rows feel 1e3 m/s^2). A
// fixed step keeps its size (info.dt_next = the step asked); a variable one is never lengthened
// (but for the landing's slack of a millionth).
// Both integrators; the next row, 1 mm upstream, is then 4 ms = 400 steps away: the step asked
// again (to round-off: 400 steps, not 401, whichever side of 400 steps round-off puts it).
TEST(CoreNozzleDrive, LandedStepsCarryEachRowToTheLine) {
    const double u0 = 0.25, dt = 1e-5, t_past = 1e-7 * dt;
    for (const int integrator : {1, 2}) {
        for (const int variable : {0, 1}) {
            Block b = block(u0, -u0, -0.0005 + 33e-6);
            auto prm = drive_params(u0);
            prm.numerics.integrator = integrator;
            prm.time_step.variable_dt = variable;
            prm.nozzle.release = 2;
            auto arr = b.ps.bind();
            ASSERT_EQ(sph_prepare(&prm, &arr), SPH_OK);
            void* ws = sph_workspace_create();
            const std::size_t row = 5 * 7;  // the leading row's first particle (z = 33 um)
            std::vector<double> taken;
            double asked = dt;
            for (int k = 0; k < 20 && b.ps.z[row] > 0.0; ++k) {
                sph_step_info_t info{};
                info.dt = asked;
                ASSERT_EQ(sph_step(ws, &prm, &arr, &info), SPH_OK);
                EXPECT_LE(info.dt, asked * (1 + 1e-6)) << "step " << k;  // LAND_SLACK
                if (variable == 0) EXPECT_EQ(info.dt_next, asked) << "step " << k;
                taken.push_back(info.dt);
                asked = variable == 0 ? dt : std::min(dt, info.dt_next);
            }
            const std::string what = "integrator " + std::to_string(integrator) + ", variable " + std::to_string(variable);
            EXPECT_LT(b.ps.z[row], 0.0) << what;
            EXPECT_GT(b.ps.z[row], -1e-12) << what;
            EXPECT_NEAR(b.ps.w[row], -u0 + t_past * (b.ps.az[row] + prm.gravity.gz), 1e-14) << what;
            if (variable == 0) {
                ASSERT_EQ(taken.size(), 14U) << what;
                for (const double t : taken) EXPECT_NEAR(t, (132e-6 + t_past) / 14, 1e-18) << what;
                sph_step_info_t next{};
                next.dt = dt;
                ASSERT_EQ(sph_step(ws, &prm, &arr, &next), SPH_OK);
                EXPECT_NEAR(next.dt, dt, 1e-16) << what;
            }
            sph_workspace_destroy(ws);
        }
    }
}

// A disturbed plug (its speed set anew before each step, as the driver does with
// nozzle.disturbance): each landing reads the speed of its own step, so the step that reaches the
// line lands the row there as exactly as with a steady plug, whatever the speeds before it.
TEST(CoreNozzleDrive, LandedStepsFollowADisturbedPlug) {
    const double u0 = 0.25, dt = 1e-5;
    Block b = block(u0, -u0, -0.0005 + 33e-6);
    auto prm = drive_params(u0);
    prm.numerics.integrator = 2;
    prm.nozzle.release = 2;
    auto arr = b.ps.bind();
    ASSERT_EQ(sph_prepare(&prm, &arr), SPH_OK);
    void* ws = sph_workspace_create();
    const std::size_t row = 5 * 7;
    int steps = 0;
    for (; steps < 30 && b.ps.z[row] > 0.0; ++steps) {
        prm.nozzle.u = u0 * (1.0 + 0.05 * std::sin(1.3 * steps));
        sph_step_info_t info{};
        info.dt = dt;
        ASSERT_EQ(sph_step(ws, &prm, &arr, &info), SPH_OK);
    }
    sph_workspace_destroy(ws);
    EXPECT_GT(steps, 10);
    EXPECT_LT(steps, 30);
    EXPECT_LT(b.ps.z[row], 0.0);
    EXPECT_GT(b.ps.z[row], -1e-12);
}

// A parabolic profile (profile_a > 0): a driven particle at distance l from the axis moves at
// u0 k (1 - l^2 / a^2), l capped at profile_lmax (so the column beside the strip's edge line, at
// l = 2.5 mm, and the one at the edge line itself move alike), and holds the density profile_rho
// whatever continuity says. Here a = 3 mm, k = 2, lmax = 2.5 mm: speeds 2 u0 (1 - (l/3)^2) for
// l = 0.5, 1.5, 2.5 mm; exact to one multiply-add as the plug's. Planar is enough: the profile
// reads only l (the axisymmetric rings are the same code).
TEST(CoreNozzleDrive, ParabolicProfileDrivesEachLineAtItsSpeed) {
    const double u0 = 0.25, dt = 1e-5, a = 0.003, k = 2.0, rho_plug = 1003.0;
    Block b = block(u0, 0.0);
    const std::vector<double> x0 = b.ps.x, z0 = b.ps.z;
    auto prm = drive_params(u0);
    prm.nozzle.profile_a = a;
    prm.nozzle.profile_k = k;
    prm.nozzle.profile_lmax = 0.0025;
    prm.nozzle.profile_rho = rho_plug;
    ASSERT_NO_FATAL_FAILURE(step_block(b, prm, dt));
    int driven = 0;
    for (std::size_t i = 0; i < b.ps.x.size(); ++i) {
        if (!b.in_strip[i]) continue;
        const double l = std::min(std::abs(x0[i]), 0.0025) / a;
        const double speed = u0 * k * (1.0 - l * l);
        EXPECT_EQ(b.ps.x[i], x0[i]) << i;
        EXPECT_NEAR(b.ps.w[i], -speed, 1e-15) << i;
        EXPECT_NEAR(b.ps.z[i], z0[i] - speed * dt, 1e-18) << i;
        EXPECT_EQ(b.ps.rho[i], rho_plug) << i;
        ++driven;
    }
    EXPECT_EQ(driven, 30);
}

// The core refuses a profile it cannot drive: no centre speed, an outer line beyond the tube, or
// no density to hold.
TEST(CoreNozzleDrive, ParabolicProfileNeedsItsParameters) {
    Block b = block(0.25, 0.0);
    auto arr = b.ps.bind();
    auto good = drive_params(0.25);
    good.nozzle.profile_a = 0.003, good.nozzle.profile_k = 2.0, good.nozzle.profile_lmax = 0.0025;
    good.nozzle.profile_rho = 1000.0;
    EXPECT_EQ(sph_prepare(&good, &arr), SPH_OK);
    auto no_k = good, wide = good, no_rho = good;
    no_k.nozzle.profile_k = 0.0;
    wide.nozzle.profile_lmax = 0.003;
    no_rho.nozzle.profile_rho = 0.0;
    for (const auto* bad : {&no_k, &wide, &no_rho}) EXPECT_NE(sph_prepare(bad, &arr), SPH_OK);
}

}  // namespace
