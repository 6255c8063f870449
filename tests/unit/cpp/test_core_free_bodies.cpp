// surface_tension.balance_free_bodies (fortran_core/loops/surface_tension_loops.f90,
// balance_free_bodies): the surface tension's net force on each free body is taken off as a
// uniform acceleration of that body, along z in the axisymmetric geometry, along x and z in the
// planar one; a body that touches a boundary particle or holds driven nozzle fluid keeps its
// force.
// The set: four irregular blobs of 21-25 particles (the points of a disc of radius 2.6 dx on
// the lattice, each moved by up to 0.15 dx in a fixed pattern), h = 2 dx, more than 2h apart,
// sigma = 0.072 N/m with the round jets' CSF (pressure-consistent delta, surface fit; in the
// axisymmetric geometry the rings pair, its surface rows with their neighbours' mean
// curvature), at rho0 and at rest: A and B free, C beside a boundary particle, D upstream of a
// driven nozzle's orifice line. Checked, in either geometry:
// - without the key the net force of A and of B is not zero (its size over sum m |a| is
//   printed; the premise of the key);
// - with it, the net force of A and of B along the balanced axes is zero to round-off
//   (1e-12 of sum m |a|), and each of their particles' accelerations moved by one and the same
//   amount (1e-12 of its size: the sums in another order);
// - C and D, the radial accelerations (axisymmetric) and every density rate are bitwise those
//   without the key.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "core_fixture.hpp"

using sphjet_test::CoreParticles;

namespace {

constexpr double kDx = 5e-5, kH = 2 * kDx, kRho0 = 1000;
constexpr int kWendland = 5;

struct Blobs {
    CoreParticles ps;
    std::vector<std::vector<std::size_t>> members;   // A, B, C, D
};

// The blobs centred at r = 20 dx (axisymmetric: ring masses 2 pi r rho0 dx^2; planar rho0 dx^2)
// and z = 10, 30, 50, 70 dx; a boundary particle 1.5 dx beyond C's edge.
Blobs blobs(bool axi) {
    Blobs b;
    b.ps.add(20 * kDx + 4.1 * kDx, 50 * kDx, 0, 0, kRho0, kRho0 * kDx * kDx, 0);
    b.ps.nb = 1;
    b.members.resize(4);
    for (int blob = 0; blob < 4; ++blob) {
        const double xc = 20 * kDx, zc = (10 + 20 * blob) * kDx;
        for (int i = -3; i <= 3; ++i)
            for (int j = -3; j <= 3; ++j) {
                if (std::hypot(i, j) > 2.6) continue;
                const double x = xc + (i + 0.15 * std::sin(1.7 * i + 2.3 * j + blob)) * kDx;
                const double z = zc + (j + 0.15 * std::cos(2.9 * i - 1.1 * j + 2 * blob)) * kDx;
                const double m = axi ? 2 * std::numbers::pi * x * kRho0 * kDx * kDx : kRho0 * kDx * kDx;
                b.members[static_cast<std::size_t>(blob)].push_back(b.ps.x.size());
                b.ps.add(x, z, 0, 0, kRho0, m, 2);
            }
    }
    return b;
}

sph_params_t params(bool axi, bool balance) {
    sph_params_t p = sphjet_test::water_params(kWendland, kH);
    p.viscosity.model = 2;
    p.viscosity.value = 1e-6;
    p.eos.c0 = 12;
    p.eos.b = kRho0 * p.eos.c0 * p.eos.c0 / p.eos.gamma;
    p.gravity.gz = 0;
    p.surface_tension.sigma = 0.072;
    p.surface_tension.curvature = 1;
    p.surface_tension.free_bodies = balance ? 1 : 0;
    if (axi) {
        p.geometry.kind = 1;
        p.geometry.axis_pair = 1;
        p.geometry.axis_m1 = 2 * std::numbers::pi * kRho0 * kDx * kDx * kDx;
    }
    // a nozzle pointing down (-z) whose orifice line lies between C and D: D is in its plug
    p.nozzle.u = 1;
    p.nozzle.x0 = 20 * kDx;
    p.nozzle.z0 = 65 * kDx;
    p.nozzle.ex = 0;
    p.nozzle.ez = -1;
    p.nozzle.half_width = 10 * kDx;
    return p;
}

struct Net {
    double f = 0, scale = 0, mass = 0;
};
Net net(const CoreParticles& ps, const std::vector<std::size_t>& idx, const std::vector<double>& a) {
    Net n;
    for (const std::size_t k : idx) {
        n.f += ps.m[k] * a[k];
        n.scale += ps.m[k] * std::abs(a[k]);
        n.mass += ps.m[k];
    }
    return n;
}

void check(bool axi) {
    Blobs off = blobs(axi), on = blobs(axi);
    sphjet_test::compute_rates(off.ps, params(axi, false));
    sphjet_test::compute_rates(on.ps, params(axi, true));
    const CoreParticles &a = off.ps, &b = on.ps;
    std::vector<const std::vector<double>*> axes_off{&a.az}, axes_on{&b.az};
    if (!axi) axes_off.push_back(&a.ax), axes_on.push_back(&b.ax);
    for (std::size_t blob = 0; blob < 2; ++blob) {
        const auto& idx = off.members[blob];
        for (std::size_t d = 0; d < axes_off.size(); ++d) {
            const Net before = net(a, idx, *axes_off[d]), after = net(b, idx, *axes_on[d]);
            std::printf("%s blob %zu axis %zu: net force / sum m|a| %.3e without, %.3e with\n",
                        axi ? "axisymmetric" : "planar", blob, d, before.f / before.scale, after.f / after.scale);
            EXPECT_GT(std::abs(before.f), 1e-6 * before.scale) << "blob " << blob << " axis " << d;
            EXPECT_LE(std::abs(after.f), 1e-12 * after.scale) << "blob " << blob << " axis " << d;
            const double shift = (*axes_on[d])[idx[0]] - (*axes_off[d])[idx[0]];
            EXPECT_NEAR(shift, -before.f / before.mass, 1e-12 * before.scale / before.mass);
            for (const std::size_t k : idx)
                EXPECT_NEAR((*axes_on[d])[k] - (*axes_off[d])[k], shift, 1e-12 * std::abs(shift)) << k;
        }
    }
    for (std::size_t blob = 2; blob < 4; ++blob)
        for (const std::size_t k : off.members[blob]) {
            ASSERT_EQ(b.ax[k], a.ax[k]) << "blob " << blob << " particle " << k;
            ASSERT_EQ(b.az[k], a.az[k]) << "blob " << blob << " particle " << k;
        }
    for (std::size_t k = 0; k < a.x.size(); ++k) {
        ASSERT_EQ(b.ar[k], a.ar[k]) << k;
        if (axi) ASSERT_EQ(b.ax[k], a.ax[k]) << k;
    }
}

}  // namespace

TEST(CoreFreeBodies, AxisymmetricNetAxialForceRemoved) { check(true); }

TEST(CoreFreeBodies, PlanarNetForceRemoved) { check(false); }
