#include "model/particles.hpp"

#include <algorithm>
#include <limits>

namespace sphjet {

DomainBounds legacy_domain(const ParticleSet& ps) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const std::size_t n = ps.nbf > 0 ? ps.nbf : ps.nb;
    if (n == 0) return {-inf, inf, -inf, inf};
    DomainBounds d{inf, -inf, inf, inf};
    for (std::size_t i = 0; i < n; ++i) {
        d.xmin = std::min(d.xmin, ps.x[i]);
        d.xmax = std::max(d.xmax, ps.x[i]);
        d.zmin = std::min(d.zmin, ps.z[i]);
    }
    return d;
}

double gate_z_cap(const ParticleSet& ps, double h) {
    return *std::max_element(ps.z.begin(), ps.z.end()) + 0.1 * h;
}

void ParticleSet::resize(std::size_t n) {
    x.resize(n);
    z.resize(n);
    u.resize(n);
    w.resize(n);
    rho.resize(n);
    p.resize(n);
    m.resize(n);
    kind.resize(n);
    id.resize(n);
    active.resize(n, 1);
}

std::size_t ParticleSet::push(double x_, double z_, double u_, double w_, double rho_, double p_,
                              double m_, ParticleKind k) {
    const std::size_t i = size();
    x.push_back(x_);
    z.push_back(z_);
    u.push_back(u_);
    w.push_back(w_);
    rho.push_back(rho_);
    p.push_back(p_);
    m.push_back(m_);
    kind.push_back(static_cast<int>(k));
    id.push_back(static_cast<std::int64_t>(i));
    active.push_back(1);
    return i;
}

std::size_t ParticleSet::n_active() const {
    return static_cast<std::size_t>(std::count(active.begin(), active.end(), 1));
}

}  // namespace sphjet
