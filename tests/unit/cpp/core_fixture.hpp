// Small helpers for tests of the Fortran core through its C header.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

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

inline sph_params_t water_params(int kernel, double h) {
    sph_params_t p{};
    p.kernel = kernel;
    p.viscosity = 1;
    p.boundary = 2;
    p.density_filter = 0;
    p.tensile = 0;
    p.dbc_period = 1;
    p.variable_dt = 1;
    p.remove_out_of_domain = 1;
    p.h = h;
    p.rho0 = 1000;
    p.gamma = 7;
    p.c0 = 20;
    p.b = p.rho0 * p.c0 * p.c0 / p.gamma;
    p.coef = 10;
    p.h_swl = 1;
    p.visc_value = 0.1;
    p.xsph_eps = 0.5;
    p.cfl = 0.2;
    p.gz = -9.81;
    p.dom_xmin = -1e30; p.dom_xmax = 1e30; p.dom_zmin = -1e30; p.dom_zmax = 1e30;
    return p;
}

}  // namespace sphjet_test
