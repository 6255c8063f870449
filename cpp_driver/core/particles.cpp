#include "core/particles.hpp"

namespace sphjet {

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

}  // namespace sphjet
