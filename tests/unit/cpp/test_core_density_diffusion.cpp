// Density diffusion (numerics.density_diffusion, fortran_core/physics/density_diffusion.f90):
// the density rate gains delta h c0 times the SPH (Brookshaw) Laplacian of rho,
// 2 sum_b V_b (rho_a - rho_b) F_ab, over the fluid pairs.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "core_fixture.hpp"

using sphjet_test::CoreParticles;

namespace {

// A lattice of nx x nz fluid particles at spacing dx, density rho(z), at rest.
template <class Rho>
CoreParticles block(int nx, int nz, double dx, Rho rho, double jitter = 0, unsigned seed = 1) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> off(-jitter * dx, jitter * dx);
    CoreParticles ps;
    for (int i = 0; i < nx; ++i)
        for (int k = 0; k < nz; ++k) {
            const double z = (k + 0.5) * dx;
            ps.add(i * dx + off(rng), z + off(rng), 0, 0, rho(z), 1000 * dx * dx, 2);
        }
    return ps;
}

// The density rates of ps with the given delta.
std::vector<double> density_rates(CoreParticles ps, sph_params_t prm, double delta) {
    prm.numerics.density_diffusion = delta;
    (void)sphjet_test::compute_rates(ps, prm);
    return ps.ar;
}

}  // namespace

// A uniform density on a disordered set gives exactly zero (the rates bitwise as without the
// diffusion); a random density is moved around with sum_a V_a drho_a/dt unchanged (each pair
// adds t V_a V_b to one particle and takes it from the other: round-off of ~400 sums, 1e-12 of
// the sum of the magnitudes).
TEST(CoreDensityDiffusion, ZeroForUniformDensityAndConservative) {
    const double dx = 0.01;
    auto prm = sphjet_test::water_params(5, 1.3 * dx);
    const auto uniform = block(20, 20, dx, [](double) { return 1000.0; }, 0.2);
    const auto off = density_rates(uniform, prm, 0.0), on = density_rates(uniform, prm, 0.1);
    for (std::size_t i = 0; i < on.size(); ++i) ASSERT_EQ(on[i], off[i]) << i;

    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> drho(-5, 5);
    auto noisy = uniform;
    for (double& r : noisy.rho) r = 1000 + drho(rng);
    const auto a = density_rates(noisy, prm, 0.0), b = density_rates(noisy, prm, 0.1);
    double sum = 0, scale = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double v = noisy.m[i] / noisy.rho[i];
        sum += v * (b[i] - a[i]);
        scale += v * std::abs(b[i] - a[i]);
    }
    ASSERT_GT(scale, 0.0);
    EXPECT_LT(std::abs(sum), 1e-12 * scale);
}

// rho = rho0 (1 + eps sin kz) on a lattice periodic in z (40 spacings, kh = 0.20 at
// h = 1.3 dx): away from the block's free sides (columns 5-14 of 20; 2h = 2.6 dx inside) the
// diffusion rate is delta h c0 times the lattice's SPH Laplacian of rho, which for a sine is
// -k^2 rho0 eps sin kz times the lattice factor -2 sum_s (1 - cos k s_z) F(s) dx^2 / k^2 over
// the lattice offsets s (computed here from the core's kernel): that to 1e-6 (the sums' round-off
// is 1e-13; the fit over the columns averages nothing away). The factor itself, 0.9711 for the
// Wendland kernel at h = 1.3 dx (the continuum's is 0.9971), must be within 3.5% of 1: the
// Brookshaw Laplacian's lattice error at this h, which the diffusion carries.
TEST(CoreDensityDiffusion, LaplacianOfASineWave) {
    const double dx = 0.01, L = 40 * dx, eps = 1e-3, k = 2 * std::numbers::pi / L, delta = 0.1;
    auto prm = sphjet_test::water_params(5, 1.3 * dx);
    prm.geometry.periodic_z = 1;
    prm.domain.zmin = 0;
    prm.domain.zmax = L;
    const auto ps = block(20, 40, dx, [&](double z) { return 1000 * (1 + eps * std::sin(k * z)); });
    const auto rate = density_rates(ps, prm, delta);

    const auto lat = sphjet_test::lattice_offsets(5, prm.numerics.h, dx);
    ASSERT_FALSE(lat.f.empty());
    double factor = 0;
    for (std::size_t i = 0; i < lat.f.size(); ++i)
        factor -= 2 * (1 - std::cos(k * lat.sz[i])) * lat.f[i] * dx * dx / (k * k);

    const double scale = delta * prm.numerics.h * prm.eos.c0 * k * k * 1000 * eps;
    double num = 0, den = 0;
    for (std::size_t i = 0; i < ps.x.size(); ++i) {
        if (ps.x[i] < 5 * dx - 1e-9 || ps.x[i] > 14 * dx + 1e-9) continue;
        const double expected = -scale * std::sin(k * ps.z[i]);
        num += rate[i] * expected;
        den += expected * expected;
    }
    const double ratio = num / den;
    std::printf("SPH Laplacian of sin(kz), kh = %.3f: %.6f of the exact, lattice factor %.6f\n",
                k * prm.numerics.h, ratio, factor);
    EXPECT_NEAR(ratio, factor, 1e-6);
    EXPECT_NEAR(factor, 1.0, 0.035);
}
