// Tait EoS as SPHysics sets it: p(rho0) = 0, c(rho0) = c0, the round trip rho -> p -> rho,
// and c^2 = dp/drho for gamma = 7 (the reason for SPHysics' c = c0 (rho/rho0)^3).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core_fixture.hpp"

TEST(CoreEos, TaitRoundTripAndSoundSpeed) {
    auto prm = sphjet_test::water_params(5, 0.01);
    std::vector<double> rho{990, 1000, 1003.7, 1020, 1050}, p(rho.size()), c(rho.size());
    ASSERT_EQ(sph_eos(&prm, static_cast<int64_t>(rho.size()), rho.data(), p.data(), c.data()),
              SPH_OK);
    EXPECT_EQ(p[1], 0.0);
    EXPECT_DOUBLE_EQ(c[1], prm.eos.c0);
    for (std::size_t i = 0; i < rho.size(); ++i) {
        // inverse: rho = rho0 (1 + p/B)^(1/gamma); relative 1e-13 (round-off of pow)
        const double back = prm.eos.rho0 * std::pow(1 + p[i] / prm.eos.b, 1 / prm.eos.gamma);
        EXPECT_NEAR(back, rho[i], 1e-13 * rho[i]);
        // dp/drho by central difference equals c^2 (relative 1e-7: difference error)
        double r2[2] = {rho[i] * (1 - 1e-6), rho[i] * (1 + 1e-6)}, p2[2], c2[2];
        ASSERT_EQ(sph_eos(&prm, 2, r2, p2, c2), SPH_OK);
        const double dpdrho = (p2[1] - p2[0]) / (r2[1] - r2[0]);
        EXPECT_NEAR(dpdrho, c[i] * c[i], 1e-7 * c[i] * c[i]);
    }
}
