// numerics.artificial_reconstruction (loops/velocity_gradient_loops.f90, physics/viscosity.f90):
// Monaghan's Pi of the velocity jump left at each pair's midpoint after both velocities are
// extrapolated there with their corrected gradients. On a square lattice at rest density (no
// pressure), the accelerations it adds are compared with those of the plain Pi, each less the
// accelerations with alpha = 0, on the particles 5 dx or more inside the block (h = 2 dx: their
// neighbours are not on the block's edge, so every gradient they use is the corrected one):
// - a linear velocity field (a strain with compression and a rotation) on the lattice with each
//   particle moved at random by up to 0.2 dx: the plain Pi accelerates the particles (on the
//   regular lattice its pair terms would cancel by symmetry), the reconstructed one, whose
//   corrected gradients are exact, adds nothing;
// - a field that alternates sign from particle to particle has zero gradient on the regular
//   lattice, so the reconstructed Pi is the plain one.
#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include <gtest/gtest.h>

#include "core_fixture.hpp"

using sphjet_test::CoreParticles;
using sphjet_test::compute_rates;

namespace {

constexpr int kN = 20;
constexpr double kDx = 0.01;

using Field = std::function<std::pair<double, double>(double, double, int, int)>;

// The kN x kN lattice of spacing kDx, each particle moved by up to jitter dx in x and z (the
// same moves every call), with velocity (u, w) = field(x, z, i, j).
CoreParticles lattice(const Field& field, double jitter) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> move(-jitter * kDx, jitter * kDx);
    CoreParticles ps;
    for (int i = 0; i < kN; ++i)
        for (int j = 0; j < kN; ++j) {
            const double x = i * kDx + move(rng), z = j * kDx + move(rng);
            const auto [u, w] = field(x, z, i, j);
            ps.add(x, z, u, w, 1000, 1000 * kDx * kDx, 2);
        }
    return ps;
}

bool inside(std::size_t k) {
    const int i = static_cast<int>(k) / kN, j = static_cast<int>(k) % kN;
    return std::min({i, j, kN - 1 - i, kN - 1 - j}) >= 5;
}

// The accelerations of the artificial viscosity alpha (reconstructed or not) less those of
// alpha = 0, on the lattice with the given field.
struct PiTerms {
    std::vector<double> plain_x, plain_z, rec_x, rec_z;
};
PiTerms pi_terms(const Field& field, double jitter) {
    const auto rates = [&](double alpha, int reconstruct) {
        auto ps = lattice(field, jitter);
        auto prm = sphjet_test::water_params(5, 2.0 * kDx);
        prm.viscosity.model = 1;
        prm.viscosity.value = alpha;
        prm.viscosity.reconstruct = reconstruct;
        prm.numerics.xsph_eps = 0;
        (void)compute_rates(ps, prm);
        return ps;
    };
    const auto zero = rates(0.0, 0), plain = rates(0.5, 0), rec = rates(0.5, 1);
    PiTerms t;
    for (std::size_t k = 0; k < zero.x.size(); ++k) {
        t.plain_x.push_back(plain.ax[k] - zero.ax[k]);
        t.plain_z.push_back(plain.az[k] - zero.az[k]);
        t.rec_x.push_back(rec.ax[k] - zero.ax[k]);
        t.rec_z.push_back(rec.az[k] - zero.az[k]);
    }
    return t;
}

// The largest plain Pi acceleration inside.
double largest_inside(const PiTerms& t) {
    double big = 0;
    for (std::size_t k = 0; k < t.plain_x.size(); ++k)
        if (inside(k)) big = std::max(big, std::hypot(t.plain_x[k], t.plain_z[k]));
    return big;
}

}  // namespace

TEST(CoreArtificialReconstruction, LinearFlowIsNotDamped) {
    // u = A (x - x_c): compression along x, shear and rotation; every pair inside approaches or
    // recedes, and the plain Pi acts on the approaching ones
    const auto t = pi_terms([](double x, double z, int, int) {
        return std::pair{-0.8 * x + 0.3 * z, -0.2 * x + 0.1 * z};
    }, 0.2);
    const double big = largest_inside(t);
    ASSERT_GT(big, 0.0);
    // round-off of the gradient's sums (a few dozen terms) and of the 2x2 inverse: 1e-10 of the
    // plain term (measured: 1e-15)
    for (std::size_t k = 0; k < t.rec_x.size(); ++k) {
        if (!inside(k)) continue;
        EXPECT_NEAR(t.rec_x[k], 0.0, 1e-10 * big) << k;
        EXPECT_NEAR(t.rec_z[k], 0.0, 1e-10 * big) << k;
    }
}

TEST(CoreArtificialReconstruction, ParticleScaleNoiseIsDampedAsBefore) {
    const auto t = pi_terms([](double, double, int i, int j) {
        return std::pair{0.1 * ((i + j) % 2 == 0 ? 1.0 : -1.0), 0.05 * (i % 2 == 0 ? 1.0 : -1.0)};
    }, 0.0);
    const double big = largest_inside(t);
    ASSERT_GT(big, 0.0);
    // the gradient inside is 0 to round-off, which leaves the plain Pi to 1e-10 of it (measured:
    // equal)
    for (std::size_t k = 0; k < t.rec_x.size(); ++k) {
        if (!inside(k)) continue;
        EXPECT_NEAR(t.rec_x[k], t.plain_x[k], 1e-10 * big) << k;
        EXPECT_NEAR(t.rec_z[k], t.plain_z[k], 1e-10 * big) << k;
    }
}
