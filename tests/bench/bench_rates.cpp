// ns per pair of the rates pair loop (sph_compute_rates: the momentum, continuity and XSPH
// sums of one force evaluation) on a perturbed square lattice of fluid, h = 1.3 dx, for each
// kernel and viscosity. The pair count (pairs closer than 2h) comes from sph_neighbour_pairs;
// the counter time_per_pair is the wall time of one evaluation divided by it.
#include <cstdint>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "core_fixture.hpp"

namespace {

sphjet_test::CoreParticles lattice(int side) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1), vel(-0.5, 0.5), drho(-2, 2);
    sphjet_test::CoreParticles ps;
    const double dx = 0.01;
    for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j)
            ps.add((i + jitter(rng)) * dx, (j + jitter(rng)) * dx, vel(rng), vel(rng),
                   1000 + drho(rng), 1000 * dx * dx, 2);
    return ps;
}

void BM_Rates(benchmark::State& state) {
    const int kernel = static_cast<int>(state.range(0));
    const int visc = static_cast<int>(state.range(1));
    const int side = static_cast<int>(state.range(2));
    auto ps = lattice(side);
    auto arr = ps.bind();
    auto prm = sphjet_test::water_params(kernel, 1.3 * 0.01);
    prm.viscosity.model = visc;
    prm.viscosity.value = visc == 1 ? 0.1 : 1e-6;
    if (sph_prepare(&prm, &arr) != SPH_OK) {
        state.SkipWithError("sph_prepare failed");
        return;
    }
    const auto n = static_cast<std::int64_t>(ps.x.size());
    std::vector<std::int64_t> pi(64 * n), pj(64 * n);
    std::int64_t npairs = 0;
    if (sph_neighbour_pairs(&prm, &arr, 64 * n, pi.data(), pj.data(), &npairs) != SPH_OK) {
        state.SkipWithError("sph_neighbour_pairs failed");
        return;
    }
    void* ws = sph_workspace_create();
    for (auto _ : state) {
        double vmax = 0;
        sph_compute_rates(ws, &prm, &arr, &vmax);
        benchmark::DoNotOptimize(vmax);
        benchmark::ClobberMemory();
    }
    sph_workspace_destroy(ws);
    state.SetItemsProcessed(state.iterations() * npairs);
    state.counters["pairs"] = static_cast<double>(npairs);
    // seconds per pair, printed with an SI prefix (n = ns)
    state.counters["time_per_pair"] = benchmark::Counter(
        static_cast<double>(npairs),
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

// kernel (3 cubic, 5 Wendland), viscosity (1 artificial, 2 laminar), lattice side
BENCHMARK(BM_Rates)
    ->ArgNames({"kernel", "visc", "side"})
    ->Args({5, 1, 100})
    ->Args({3, 1, 100})
    ->Args({5, 2, 100})
    ->Args({5, 1, 300})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

BENCHMARK_MAIN();
