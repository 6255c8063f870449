// A sparse square-cell grid over particle positions (internal to analysis/).
#pragma once

#include <cmath>
#include <cstdint>

namespace sphjet::analysis::detail {

struct CellIndex {
    std::int64_t i = 0, k = 0;
    bool operator==(const CellIndex&) const = default;
};

inline CellIndex cell_of(double x, double z, double cell) {
    return {static_cast<std::int64_t>(std::floor(x / cell)), static_cast<std::int64_t>(std::floor(z / cell))};
}

struct CellHash {
    std::size_t operator()(const CellIndex& c) const {
        const auto a = static_cast<std::uint64_t>(c.i) * 0x9E3779B97F4A7C15ull;
        const auto b = static_cast<std::uint64_t>(c.k) * 0xC2B2AE3D27D4EB4Full;
        return static_cast<std::size_t>(a ^ (b >> 1) ^ (b << 31));
    }
};

}  // namespace sphjet::analysis::detail
