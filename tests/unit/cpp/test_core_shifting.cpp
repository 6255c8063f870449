// Particle shifting (numerics.shifting, fortran_core/loops/surface_tension_loops.f90,
// shifting_velocity): with XSPH off, the XSPH velocity the rates return is the shifting velocity
// alone, u_s = -A h (c0/10) grad C, grad C = sum_b V_b grad_a W_ab (the kernel's truncation
// vector), with only its part along the surface where the surface cuts the kernel (colour below
// 0.97); axisymmetric rings closer to the axis than h/2 shift along the axis only.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "core_fixture.hpp"

using sphjet_test::call_rates;
using sphjet_test::CoreParticles;
using sphjet_test::RatesCall;

namespace {

constexpr int kWendland = 5;

// Water at rest and rho0, periodic in z over nz rows of spacing dx, no gravity, XSPH off,
// surface tension on (its passes find the surface), shifting A.
sph_params_t column_params(double dx, double h, int nz, double a) {
    auto p = sphjet_test::water_params(kWendland, h);
    p.geometry.periodic_z = 1;
    p.domain.zmin = 0;
    p.domain.zmax = nz * dx;
    p.gravity.gz = 0;
    p.numerics.xsph_eps = 0;
    p.surface_tension.sigma = 0.07;
    p.numerics.shifting = a;
    return p;
}

// A planar slab of nx columns at x = i dx (free sides at 0 and (nx - 1) dx) and nz rows.
CoreParticles slab(int nx, int nz, double dx) {
    CoreParticles ps;
    for (int i = 0; i < nx; ++i)
        for (int k = 0; k < nz; ++k) ps.add(i * dx, (k + 0.5) * dx, 0, 0, 1000, 1000 * dx * dx, 2);
    return ps;
}

}  // namespace

// A particle moved 0.2 dx off its lattice site inside the slab shifts back, with exactly
// -A h (c0/10) sum_b V_b F(r_ab) (r_a - r_b) (F = W'/r from the core's kernel; round-off
// tolerance); the outermost columns, whose kernel the surface cuts, get no shift across the
// surface (the even lattice has no part along it).
TEST(CoreShifting, InteriorShiftsBackSurfaceNotPushedOut) {
    const double dx = 0.001, h = 1.3 * dx, a = 1.0;
    const int nx = 12, nz = 20, moved = 6 * nz + 7;
    const auto prm = column_params(dx, h, nz, a);
    auto ps = slab(nx, nz, dx);
    ps.x[moved] += 0.2 * dx;
    sphjet_test::compute_rates(ps, prm);

    std::vector<double> r, ex, ez;
    for (std::size_t b = 0; b < ps.x.size(); ++b) {
        if (static_cast<int>(b) == moved) continue;
        const double dxab = ps.x[moved] - ps.x[b], dzab = ps.z[moved] - ps.z[b];
        r.push_back(std::hypot(dxab, dzab)), ex.push_back(dxab), ez.push_back(dzab);
    }
    std::vector<double> w(r.size()), f(r.size());
    ASSERT_EQ(sph_kernel_eval(kWendland, h, static_cast<std::int64_t>(r.size()), r.data(), w.data(), f.data()),
              SPH_OK);
    double gx = 0, gz = 0;
    for (std::size_t j = 0; j < r.size(); ++j) gx += dx * dx * f[j] * ex[j], gz += dx * dx * f[j] * ez[j];
    const double d = a * h * prm.eos.c0 / 10;
    ASSERT_GT(gx, 0.0);  // the moved particle is nearer its right neighbours: C grows to the right
    EXPECT_NEAR(ps.xu[moved], -d * gx, 1e-9 * d * gx);
    EXPECT_NEAR(ps.xw[moved], -d * gz, 1e-9 * d * gx);

    for (int k = 0; k < nz; ++k) {
        EXPECT_EQ(ps.xu[k], 0.0) << "left surface, row " << k;
        EXPECT_EQ(ps.xu[(nx - 1) * nz + k], 0.0) << "right surface, row " << k;
    }
}

// Off (A = 0) the rates are bitwise those of a build without shifting: the XSPH velocity stays
// exactly zero with XSPH off, on the same disordered slab.
TEST(CoreShifting, OffLeavesNoShift) {
    const double dx = 0.001, h = 1.3 * dx;
    const int nx = 12, nz = 20;
    auto ps = slab(nx, nz, dx);
    ps.x[6 * nz + 7] += 0.2 * dx;
    sphjet_test::compute_rates(ps, column_params(dx, h, nz, 0.0));
    for (std::size_t i = 0; i < ps.x.size(); ++i) {
        ASSERT_EQ(ps.xu[i], 0.0) << i;
        ASSERT_EQ(ps.xw[i], 0.0) << i;
    }
}

// Axisymmetric rings pair: a ring lattice of a column (rings at (i + 1/2) dx, mass 2 pi r rho0
// dx^2), the axis's ring of one row moved 0.2 dx along z: it shifts back along z, and not
// radially (it lies closer to the axis than h/2), as every ring of the innermost column.
TEST(CoreShifting, AxisRingsShiftAlongTheAxisOnly) {
    const double dx = 0.001, h = 2.0 * dx, a = 1.0;
    const int nr = 6, nz = 24, moved = 10;
    auto prm = column_params(dx, h, nz, a);
    prm.geometry.kind = 1;
    prm.geometry.axis_pair = 1;
    CoreParticles ps;
    for (int i = 0; i < nr; ++i)
        for (int k = 0; k < nz; ++k) {
            const double r = (i + 0.5) * dx;
            ps.add(r, (k + 0.5) * dx, 0, 0, 1000, 2 * std::numbers::pi * r * 1000 * dx * dx, 2);
        }
    ps.z[moved] += 0.2 * dx;
    sphjet_test::compute_rates(ps, prm);
    EXPECT_LT(ps.xw[moved], 0.0);
    for (int k = 0; k < nz; ++k) EXPECT_EQ(ps.xu[k], 0.0) << "axis ring, row " << k;
}

// The core refuses shifting without surface tension, whose passes set its velocity.
TEST(CoreShifting, RefusedWithoutSurfaceTension) {
    const double dx = 0.001;
    auto prm = column_params(dx, 1.3 * dx, 20, 1.0);
    prm.surface_tension.sigma = 0;
    auto ps = slab(12, 20, dx);
    const RatesCall c = call_rates(ps, prm);
    EXPECT_NE(c.prepare, SPH_OK);
    EXPECT_NE(c.rates, SPH_OK);
}
