#include "core/linear_modes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/Dense>

namespace sphjet {

namespace {

// The fluid particles' state y = (x, z, u, w, rho), five blocks of n.
struct FluidState {
    std::vector<std::size_t> idx;  // particle indices
    double xmax = 0;               // their largest x: the outer layer is x >= xmax - dx/2
    [[nodiscard]] std::size_t n() const { return idx.size(); }
};

void put_state(ParticleSet& ps, const FluidState& f, const Eigen::VectorXd& y) {
    const std::size_t n = f.n();
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = f.idx[k];
        ps.x[i] = y[static_cast<Eigen::Index>(k)];
        ps.z[i] = y[static_cast<Eigen::Index>(n + k)];
        ps.u[i] = y[static_cast<Eigen::Index>(2 * n + k)];
        ps.w[i] = y[static_cast<Eigen::Index>(3 * n + k)];
        ps.rho[i] = y[static_cast<Eigen::Index>(4 * n + k)];
    }
}

// dy/dt: dx/dt = u + XSPH, du/dt = the pair acceleration (gravity, a constant, left out),
// drho/dt the continuity.
Eigen::VectorXd rates(Solver& s, const FluidState& f, const Eigen::VectorXd& y) {
    put_state(s.particles_to_edit(), f, y);
    s.rates_of_edited_state();
    const std::size_t n = f.n();
    const ParticleSet& ps = s.particles();
    Eigen::VectorXd r(static_cast<Eigen::Index>(5 * n));
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = f.idx[k];
        r[static_cast<Eigen::Index>(k)] = ps.u[i] + s.xsph_u()[i];
        r[static_cast<Eigen::Index>(n + k)] = ps.w[i] + s.xsph_w()[i];
        r[static_cast<Eigen::Index>(2 * n + k)] = s.ax()[i];
        r[static_cast<Eigen::Index>(3 * n + k)] = s.az()[i];
        r[static_cast<Eigen::Index>(4 * n + k)] = s.ar()[i];
    }
    return r;
}

// Shape of one eigenvector: outer-layer and radial shares, dominant axial Fourier mode.
void describe(LinearMode& m, const Eigen::VectorXcd& v, const FluidState& f, const ParticleSet& ps,
              double dx, double period) {
    const std::size_t n = f.n();
    const double xmax = f.xmax;
    double all = 0, outer = 0, radial = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const double ax = std::norm(v[static_cast<Eigen::Index>(k)]);
        const double az = std::norm(v[static_cast<Eigen::Index>(n + k)]);
        all += ax + az;
        radial += ax;
        if (ps.x[f.idx[k]] >= xmax - 0.5 * dx) outer += ax + az;
    }
    m.outer_share = all > 0 ? outer / all : 0;
    m.radial_share = all > 0 ? radial / all : 0;
    if (period <= 0) return;
    // the outer layer's radial displacement along z, projected on exp(i 2 pi j z / period)
    const int jmax = static_cast<int>(period / dx / 2.0);
    double best = -1;
    for (int j = 0; j <= jmax; ++j) {
        std::complex<double> c = 0;
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t i = f.idx[k];
            if (ps.x[i] < xmax - 0.5 * dx) continue;
            const double ph = 2.0 * std::numbers::pi * j * ps.z[i] / period;
            c += v[static_cast<Eigen::Index>(k)] * std::complex<double>(std::cos(ph), -std::sin(ph));
        }
        if (std::abs(c) > best) {
            best = std::abs(c);
            m.n_axial = j;
        }
    }
}

}  // namespace

LinearModes linear_modes(Solver& s, const LinearModeOptions& opt) {
    if (!(opt.dx > 0)) throw std::invalid_argument("linear_modes: dx must be positive");
    const ParticleSet saved = s.particles();
    FluidState f;
    for (std::size_t i = saved.nb; i < saved.size(); ++i)
        if (saved.active[i] != 0 && saved.kind[i] == static_cast<int>(ParticleKind::Fluid)) f.idx.push_back(i);
    const std::size_t n = f.n();
    if (n == 0) throw std::invalid_argument("linear_modes: no active fluid particle");
    f.xmax = saved.x[f.idx[0]];
    for (const std::size_t i : f.idx) f.xmax = std::max(f.xmax, saved.x[i]);
    const auto dim = static_cast<Eigen::Index>(5 * n);
    Eigen::VectorXd y0(dim);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = f.idx[k];
        y0[static_cast<Eigen::Index>(k)] = saved.x[i];
        y0[static_cast<Eigen::Index>(n + k)] = saved.z[i];
        y0[static_cast<Eigen::Index>(2 * n + k)] = opt.at_rest ? 0.0 : saved.u[i];
        y0[static_cast<Eigen::Index>(3 * n + k)] = opt.at_rest ? 0.0 : saved.w[i];
        y0[static_cast<Eigen::Index>(4 * n + k)] = saved.rho[i];
    }
    // steps: positions 1e-6 dx; velocities 1e-6 m/s and densities 1e-7 rho (the rates are linear
    // in the velocities; a density step of 1e-7 rho moves the pressure by 1e-7 rho c^2)
    Eigen::MatrixXd jac(dim, dim);
    for (Eigen::Index j = 0; j < dim; ++j) {
        const auto block = static_cast<std::size_t>(j) / n;
        const double step = block < 2 ? 1e-6 * opt.dx : block < 4 ? 1e-6 : 1e-7 * y0[j];
        Eigen::VectorXd y = y0;
        y[j] = y0[j] + step;
        const Eigen::VectorXd rp = rates(s, f, y);
        y[j] = y0[j] - step;
        const Eigen::VectorXd rm = rates(s, f, y);
        jac.col(j) = (rp - rm) / (2.0 * step);
    }
    s.particles_to_edit() = saved;
    s.rates_of_edited_state();

    Eigen::EigenSolver<Eigen::MatrixXd> es(jac, true);
    if (es.info() != Eigen::Success) throw std::runtime_error("linear_modes: the eigenvalue solver failed");
    const Eigen::VectorXcd ev = es.eigenvalues();
    std::vector<Eigen::Index> order(static_cast<std::size_t>(dim));
    for (Eigen::Index j = 0; j < dim; ++j) order[static_cast<std::size_t>(j)] = j;
    std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
        return ev[a].real() > ev[b].real() || (ev[a].real() == ev[b].real() && a < b);
    });
    LinearModes out;
    out.n_fluid = n;
    out.dimension = static_cast<std::size_t>(dim);
    for (Eigen::Index j = 0; j < dim; ++j)
        if (ev[j].real() > 0) ++out.growing;
    const Eigen::MatrixXcd vecs = es.eigenvectors();
    for (std::size_t t = 0; t < std::min<std::size_t>(opt.top, order.size()); ++t) {
        LinearMode m;
        m.lambda = ev[order[t]];
        describe(m, vecs.col(order[t]), f, saved, opt.dx, opt.period);
        out.modes.push_back(m);
    }
    return out;
}

}  // namespace sphjet
