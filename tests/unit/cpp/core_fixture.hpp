// Small helpers for tests of the Fortran core through its C header.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "sphjet_core.h"

namespace sphjet_test {

// A particle set with its own storage, bound to an sph_arrays_t.
struct CoreParticles {
    std::vector<double> x, z, u, w, rho, p, c, m, xo, zo, uo, wo, rhoo, ax, az, ar, xu, xw;
    std::vector<int> kind, active;
    std::int64_t nb = 0;

    void add(double x_, double z_, double u_, double w_, double rho_, double m_, int kind_) {
        x.push_back(x_); z.push_back(z_); u.push_back(u_); w.push_back(w_);
        rho.push_back(rho_); p.push_back(0); c.push_back(0); m.push_back(m_);
        kind.push_back(kind_); active.push_back(1);
    }
    sph_arrays_t bind() {
        const std::size_t n = x.size();
        for (auto* v : {&xo, &zo, &uo, &wo, &rhoo, &ax, &az, &ar, &xu, &xw}) v->assign(n, 0.0);
        sph_arrays_t a{};
        a.n = static_cast<std::int64_t>(n);
        a.nb = nb;
        a.x = x.data(); a.z = z.data(); a.u = u.data(); a.w = w.data();
        a.rho = rho.data(); a.p = p.data(); a.c = c.data(); a.m = m.data();
        a.kind = kind.data(); a.active = active.data();
        a.xo = xo.data(); a.zo = zo.data(); a.uo = uo.data(); a.wo = wo.data();
        a.rhoo = rhoo.data(); a.ax = ax.data(); a.az = az.data(); a.ar = ar.data();
        a.xsph_u = xu.data(); a.xsph_w = xw.data();
        return a;
    }
};

// The statuses of sph_prepare and sph_compute_rates on ps with prm, on a workspace of its own
// (the rates of ps set where they succeed), and the sweep's largest approach rate.
struct RatesCall {
    int prepare = SPH_OK, rates = SPH_OK;
    double vmax = 0;
};
inline RatesCall call_rates(CoreParticles& ps, sph_params_t prm) {
    RatesCall c;
    auto arr = ps.bind();
    c.prepare = sph_prepare(&prm, &arr);
    void* ws = sph_workspace_create();
    c.rates = sph_compute_rates(ws, &prm, &arr, &c.vmax);
    sph_workspace_destroy(ws);
    return c;
}

// Sets the rates of ps (ax, az, ar, xu, xw) with prm on a workspace of its own (a failed call
// is a test failure); returns the sweep's largest approach rate.
inline double compute_rates(CoreParticles& ps, sph_params_t prm) {
    const RatesCall c = call_rates(ps, prm);
    EXPECT_EQ(c.prepare, SPH_OK);
    EXPECT_EQ(c.rates, SPH_OK);
    return c.vmax;
}

// The offsets of a square lattice of spacing dx within 3 spacings in x and z, the origin left
// out: their z components sz and the kernel's F = W'/r at their lengths (the lattice sums of the
// tests' factors).
struct LatticeOffsets {
    std::vector<double> sz, f;
};
inline LatticeOffsets lattice_offsets(int kernel, double h, double dx) {
    LatticeOffsets o;
    std::vector<double> r;
    for (int i = -3; i <= 3; ++i)
        for (int j = -3; j <= 3; ++j)
            if (i != 0 || j != 0) r.push_back(std::hypot(i, j) * dx), o.sz.push_back(j * dx);
    std::vector<double> w(r.size());
    o.f.resize(r.size());
    if (sph_kernel_eval(kernel, h, static_cast<std::int64_t>(r.size()), r.data(), w.data(), o.f.data()) != SPH_OK)
        o.f.clear();
    return o;
}

inline sph_params_t water_params(int kernel, double h) {
    sph_params_t p{};
    p.numerics.kernel = kernel;
    p.numerics.integrator = 1;   // the predictor-corrector
    p.viscosity.model = 1;
    p.boundary.model = 2;
    p.numerics.density_filter = 0;
    p.numerics.tensile = 0;
    p.boundary.dbc_period = 1;
    p.time_step.variable_dt = 1;
    p.domain.remove_out = 1;
    p.numerics.h = h;
    p.eos.rho0 = 1000;
    p.eos.gamma = 7;
    p.eos.c0 = 20;
    p.eos.b = p.eos.rho0 * p.eos.c0 * p.eos.c0 / p.eos.gamma;
    p.boundary.coef = 10;
    p.boundary.h_swl = 1;
    p.viscosity.value = 0.1;
    p.numerics.xsph_eps = 0.5;
    p.time_step.cfl = 0.2;
    p.gravity.gz = -9.81;
    p.domain.xmin = -1e30; p.domain.xmax = 1e30; p.domain.zmin = -1e30; p.domain.zmax = 1e30;
    return p;
}

}  // namespace sphjet_test
