#include "analysis/breakup.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

#include "analysis/cell_grid.hpp"

namespace sphjet::analysis {

std::optional<double> breakup_length(const ParticleSet& ps, const Axis& axis, double band, double link,
                                     const Bounds& bounds) {
    const double len = std::hypot(axis.dir_x, axis.dir_z);
    if (!(len > 0.0)) throw std::invalid_argument("breakup_length: the axis direction is zero");
    if (!(band > 0.0) || !(link > 0.0))
        throw std::invalid_argument("breakup_length: band and link must be positive");
    const double ex = axis.dir_x / len, ez = axis.dir_z / len;
    std::vector<double> s;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        if (!selected(ps, i, bounds)) continue;
        const double rx = ps.x[i] - axis.x0, rz = ps.z[i] - axis.z0;
        const double along = rx * ex + rz * ez;
        const double across = std::fabs(rx * ez - rz * ex);
        if (along >= 0.0 && across <= band) s.push_back(along);
    }
    std::sort(s.begin(), s.end());
    for (std::size_t k = 0; k + 1 < s.size(); ++k)
        if (s[k + 1] - s[k] > link) return s[k];
    return std::nullopt;
}

namespace {
std::size_t find_root(std::vector<std::size_t>& parent, std::size_t a) {
    while (parent[a] != a) {
        parent[a] = parent[parent[a]];
        a = parent[a];
    }
    return a;
}
}  // namespace

std::vector<Cluster> label_clusters(const ParticleSet& ps, double link, const Bounds& bounds,
                                    std::vector<int>* labels) {
    if (!(link > 0.0)) throw std::invalid_argument("label_clusters: link must be positive");
    std::vector<std::size_t> idx;  // selected particles
    for (std::size_t i = 0; i < ps.size(); ++i)
        if (selected(ps, i, bounds)) idx.push_back(i);

    std::unordered_map<detail::CellIndex, std::vector<std::size_t>, detail::CellHash> grid;
    for (std::size_t a = 0; a < idx.size(); ++a) grid[detail::cell_of(ps.x[idx[a]], ps.z[idx[a]], link)].push_back(a);

    std::vector<std::size_t> parent(idx.size());
    std::iota(parent.begin(), parent.end(), std::size_t{0});
    const double link2 = link * link;
    for (const auto& [c, members] : grid) {
        for (std::int64_t di = -1; di <= 1; ++di) {
            for (std::int64_t dk = -1; dk <= 1; ++dk) {
                const auto it = grid.find({c.i + di, c.k + dk});
                if (it == grid.end()) continue;
                for (std::size_t a : members) {
                    for (std::size_t b : it->second) {
                        if (b <= a) continue;
                        const double dx = ps.x[idx[a]] - ps.x[idx[b]], dz = ps.z[idx[a]] - ps.z[idx[b]];
                        if (dx * dx + dz * dz <= link2) parent[find_root(parent, a)] = find_root(parent, b);
                    }
                }
            }
        }
    }

    std::unordered_map<std::size_t, std::size_t> root_to_cluster;
    std::vector<Cluster> clusters;
    std::vector<std::size_t> of(idx.size());
    for (std::size_t a = 0; a < idx.size(); ++a) {
        const std::size_t r = find_root(parent, a);
        auto [it, fresh] = root_to_cluster.try_emplace(r, clusters.size());
        if (fresh) clusters.push_back({});
        Cluster& cl = clusters[it->second];
        ++cl.size;
        cl.xc += ps.x[idx[a]];
        cl.zc += ps.z[idx[a]];
        of[a] = it->second;
    }
    for (auto& cl : clusters) {
        cl.xc /= static_cast<double>(cl.size);
        cl.zc /= static_cast<double>(cl.size);
    }
    std::vector<std::size_t> order(clusters.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) {
        const Cluster &a = clusters[p], &b = clusters[q];
        if (a.size != b.size) return a.size > b.size;
        if (a.xc != b.xc) return a.xc < b.xc;
        return a.zc < b.zc;
    });
    std::vector<std::size_t> rank(clusters.size());
    std::vector<Cluster> sorted(clusters.size());
    for (std::size_t r = 0; r < order.size(); ++r) {
        rank[order[r]] = r;
        sorted[r] = clusters[order[r]];
    }
    if (labels) {
        labels->assign(ps.size(), -1);
        for (std::size_t a = 0; a < idx.size(); ++a) (*labels)[idx[a]] = static_cast<int>(rank[of[a]]);
    }
    return sorted;
}

}  // namespace sphjet::analysis
