// Bulk viscosity (numerics.bulk_viscosity, fortran_core/loops/rates.f90): the momentum
// equation's pressure is p + zeta/rho drho/dt = p - zeta div v, zeta = beta rho0 c0 h, with the
// density rate of the last evaluation (the state's ar on entry).
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "core_fixture.hpp"

using sphjet_test::CoreParticles;

namespace {

// A lattice of nx x nz fluid particles at spacing dx and rho0, at rest.
CoreParticles block(int nx, int nz, double dx, double jitter = 0, unsigned seed = 1) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> off(-jitter * dx, jitter * dx);
    CoreParticles ps;
    for (int i = 0; i < nx; ++i)
        for (int k = 0; k < nz; ++k) ps.add(i * dx + off(rng), (k + 0.5) * dx + off(rng), 0, 0, 1000, 1000 * dx * dx, 2);
    return ps;
}

// The accelerations (ax, az) of ps with the given beta, the last density rates being ar.
std::pair<std::vector<double>, std::vector<double>> accelerations(CoreParticles ps, sph_params_t prm, double beta,
                                                                  const std::vector<double>& ar) {
    prm.numerics.bulk_viscosity = beta;
    auto arr = ps.bind();
    ps.ar = ar;
    arr.ar = ps.ar.data();
    EXPECT_EQ(sph_prepare(&prm, &arr), SPH_OK);
    void* ws = sph_workspace_create();
    double vmax = 0;
    EXPECT_EQ(sph_compute_rates(ws, &prm, &arr, &vmax), SPH_OK);
    sph_workspace_destroy(ws);
    return {ps.ax, ps.az};
}

}  // namespace

// With no density change in the last evaluation (a divergence-free flow), the rates are
// bitwise those without the bulk viscosity, on a disordered set.
TEST(CoreBulkViscosity, NothingWithoutCompression) {
    const double dx = 0.01;
    const auto prm = sphjet_test::water_params(5, 1.3 * dx);
    const auto ps = block(20, 20, dx, 0.2);
    const std::vector<double> zero(ps.x.size(), 0.0);
    const auto off = accelerations(ps, prm, 0.0, zero), on = accelerations(ps, prm, 0.5, zero);
    for (std::size_t i = 0; i < ps.x.size(); ++i) {
        ASSERT_EQ(on.first[i], off.first[i]) << i;
        ASSERT_EQ(on.second[i], off.second[i]) << i;
    }
}

// A compression drho/dt = A sin(kz) on a lattice at rest and rho0 (zero pressure), periodic in z
// (40 spacings, kh = 0.20 at h = 1.3 dx): away from the block's free sides (columns 5-14 of 20)
// the acceleration is the gradient of zeta A sin(kz) / rho0, -zeta A k cos(kz) / rho0^2, times the
// lattice factor of the SPH pressure gradient for a sine, -dx^2 sum_s sin(k s_z) s_z F(s) / k
// over the lattice offsets s (F = W'/r from the core's kernel): that to 1e-9 (round-off), with no
// x acceleration beyond round-off. The factor, 0.968 for the Wendland kernel at h = 1.3 dx, must
// be within 3.5% of 1: the lattice's error in the kernel's second moment, -dx^2 sum_s s_z^2 F(s)
// (the continuum's is 1), which every SPH pressure gradient at this h carries.
TEST(CoreBulkViscosity, GradientOfACompressionWave) {
    const double dx = 0.01, L = 40 * dx, k = 2 * std::numbers::pi / L, A = 50.0, beta = 0.5;
    auto prm = sphjet_test::water_params(5, 1.3 * dx);
    prm.geometry.periodic_z = 1;
    prm.domain.zmin = 0;
    prm.domain.zmax = L;
    prm.gravity.gz = 0;
    const auto ps = block(20, 40, dx);
    std::vector<double> ar(ps.x.size());
    for (std::size_t i = 0; i < ar.size(); ++i) ar[i] = A * std::sin(k * ps.z[i]);
    const auto [ax, az] = accelerations(ps, prm, beta, ar);

    const auto lat = sphjet_test::lattice_offsets(5, prm.numerics.h, dx);
    ASSERT_FALSE(lat.f.empty());
    double factor = 0;
    for (std::size_t i = 0; i < lat.f.size(); ++i) factor -= dx * dx * std::sin(k * lat.sz[i]) * lat.sz[i] * lat.f[i] / k;

    const double zeta = beta * prm.eos.rho0 * prm.eos.c0 * prm.numerics.h;
    const double scale = zeta * A * k / (prm.eos.rho0 * prm.eos.rho0);
    double num = 0, den = 0, axmax = 0;
    for (std::size_t i = 0; i < ps.x.size(); ++i) {
        if (ps.x[i] < 5 * dx - 1e-9 || ps.x[i] > 14 * dx + 1e-9) continue;
        const double expected = -scale * std::cos(k * ps.z[i]);
        num += az[i] * expected;
        den += expected * expected;
        axmax = std::max(axmax, std::abs(ax[i]));
    }
    const double ratio = num / den;
    std::printf("bulk-viscous acceleration of a compression sin(kz), kh = %.3f: %.9f of the exact, "
                "lattice factor %.9f, |ax| max %.2e of %.2e\n",
                k * prm.numerics.h, ratio, factor, axmax, scale);
    EXPECT_NEAR(ratio, factor, 1e-9);
    EXPECT_NEAR(factor, 1.0, 0.035);
    EXPECT_LT(axmax, 1e-9 * scale);
}
