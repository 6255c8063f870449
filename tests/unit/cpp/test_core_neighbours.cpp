// The cell-list search finds exactly the pairs of a brute-force search (SWIFT test27cells
// style): random particles, some inactive, several smoothing lengths.
#include <algorithm>
#include <random>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "core_fixture.hpp"

using sphjet_test::CoreParticles;

TEST(CoreNeighbours, CellSearchEqualsBruteForce) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> ux(-0.3, 1.7), uz(0.0, 0.9);
    for (double h : {0.013, 0.05, 0.2}) {
        CoreParticles ps;
        for (int i = 0; i < 1500; ++i) ps.add(ux(rng), uz(rng), 0, 0, 1000, 1, 2);
        for (int i = 0; i < 1500; i += 17) ps.active[i] = 0;
        auto arr = ps.bind();
        auto prm = sphjet_test::water_params(5, h);
        std::set<std::pair<int64_t, int64_t>> brute;
        for (int i = 0; i < 1500; ++i)
            for (int j = i + 1; j < 1500; ++j) {
                if (!ps.active[i] || !ps.active[j]) continue;
                const double dx = ps.x[i] - ps.x[j], dz = ps.z[i] - ps.z[j];
                if (dx * dx + dz * dz < 4 * h * h) brute.insert({i, j});
            }
        std::vector<int64_t> pi(brute.size() + 10), pj(brute.size() + 10);
        int64_t n = 0;
        ASSERT_EQ(sph_neighbour_pairs(&prm, &arr, static_cast<int64_t>(pi.size()), pi.data(),
                                      pj.data(), &n),
                  SPH_OK);
        std::set<std::pair<int64_t, int64_t>> cells;
        for (int64_t k = 0; k < n; ++k) cells.insert({pi[k], pj[k]});
        EXPECT_EQ(static_cast<std::size_t>(n), cells.size()) << "a pair was found twice";
        EXPECT_EQ(cells, brute) << "h = " << h;
    }
}

TEST(CoreNeighbours, CapacityOverflowIsReported) {
    CoreParticles ps;
    for (int i = 0; i < 10; ++i) ps.add(0.001 * i, 0, 0, 0, 1000, 1, 2);
    auto arr = ps.bind();
    auto prm = sphjet_test::water_params(5, 1.0);
    std::vector<int64_t> pi(3), pj(3);
    int64_t n = 0;
    EXPECT_EQ(sph_neighbour_pairs(&prm, &arr, 3, pi.data(), pj.data(), &n), SPH_ERR_CAPACITY);
    EXPECT_EQ(n, 45);
}
