// Kernels of the Fortran core: normalisation and gradient symmetry (SPlisHSPlasH KernelTests,
// SWIFT style), and agreement of F = (dW/dr)/r with a finite difference of W.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "sphjet_core.h"

namespace {

constexpr int kKernels[] = {1, 2, 3, 5};
const char* name(int k) {
    switch (k) {
        case 1: return "gaussian";
        case 2: return "quadratic";
        case 3: return "cubic";
        default: return "wendland";
    }
}

std::vector<double> eval_w(int kernel, double h, const std::vector<double>& r,
                           std::vector<double>* f = nullptr) {
    std::vector<double> w(r.size()), ff(r.size());
    EXPECT_EQ(sph_kernel_eval(kernel, h, static_cast<int64_t>(r.size()), r.data(), w.data(),
                              ff.data()),
              SPH_OK);
    if (f) *f = ff;
    return w;
}

// Radial integral 2 pi int_0^2h W(r) r dr by composite Simpson (W is smooth enough inside the
// support; 20000 panels give ~1e-12 for the polynomial kernels).
double radial_integral(int kernel, double h) {
    const int n = 20000;
    const double b = 2.0 * h, dr = b / n;
    std::vector<double> r(n + 1);
    for (int i = 0; i <= n; ++i) r[i] = i * dr;
    r[n] = b * (1 - 1e-15);
    const auto w = eval_w(kernel, h, r);
    double s = 0;
    for (int i = 0; i <= n; ++i) {
        const double wt = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        s += wt * w[i] * r[i];
    }
    return 2 * std::numbers::pi * s * dr / 3;
}

}  // namespace

// Every kernel integrates to 1 over its support; the Gaussian, cut at 2h as in SPHysics,
// to 1 - exp(-4). Tolerance 1e-8: quadrature error only.
TEST(CoreKernels, IntegrateToOne) {
    for (int k : kKernels) {
        for (double h : {0.01, 1.3}) {
            const double expected = k == 1 ? 1 - std::exp(-4.0) : 1.0;
            EXPECT_NEAR(radial_integral(k, h), expected, 1e-8) << name(k) << " h=" << h;
        }
    }
}

// On a lattice (BCC, the legacy fluid lattice) the discrete sum of m/rho W is close to 1 and
// the sum of grad W over all neighbours vanishes by symmetry (to round-off).
TEST(CoreKernels, LatticeSumsAndGradientSumZero) {
    const double dx = 1.0, h = 1.3 * dx;
    for (int k : kKernels) {
        double sw = 0, gx = 0, gz = 0;
        std::vector<double> r, ddx, ddz;
        for (int i = -6; i <= 6; ++i)
            for (int j = -6; j <= 6; ++j)
                for (int s = 0; s < 2; ++s) {
                    const double x = i * dx + 0.5 * s * dx, z = j * dx + 0.5 * s * dx;
                    const double rr = std::hypot(x, z);
                    if (rr >= 2 * h) continue;
                    r.push_back(rr);
                    ddx.push_back(-x);
                    ddz.push_back(-z);
                }
        std::vector<double> f;
        const auto w = eval_w(k, h, r, &f);
        for (std::size_t i = 0; i < r.size(); ++i) {
            sw += w[i] * 0.5 * dx * dx;  // volume per particle on BCC
            gx += f[i] * ddx[i];
            gz += f[i] * ddz[i];
        }
        // Lattice sum of a smooth kernel approximates its integral: within 2% at h = 1.3 dx
        // (4% for the cut Gaussian, which integrates to 0.982 itself).
        EXPECT_NEAR(sw, 1.0, k == 1 ? 0.04 : 0.02) << name(k);
        EXPECT_NEAR(gx, 0.0, 1e-12) << name(k);
        EXPECT_NEAR(gz, 0.0, 1e-12) << name(k);
    }
}

// F = (dW/dr)/r agrees with a central difference of W (relative 1e-6: difference error).
TEST(CoreKernels, GradientMatchesFiniteDifference) {
    const double h = 0.7;
    for (int k : kKernels) {
        for (double q : {0.3, 0.9, 1.1, 1.7}) {
            const double r = q * h, e = 1e-6 * h;
            std::vector<double> f;
            const auto w = eval_w(k, h, {r - e, r + e, r}, &f);
            const double dwdr = (w[1] - w[0]) / (2 * e);
            EXPECT_NEAR(f[2] * r, dwdr, 1e-6 * std::abs(dwdr) + 1e-12) << name(k) << " q=" << q;
        }
    }
}

// The 2D normalisation constants the paper's digest gives: Wendland W(0) = 7/(4 pi h^2),
// cubic W(0) = 10/(7 pi h^2).
TEST(CoreKernels, Constants) {
    const double h = 0.5;
    EXPECT_NEAR(eval_w(5, h, {0.0})[0], 7.0 / (4 * std::numbers::pi * h * h), 1e-14);
    EXPECT_NEAR(eval_w(3, h, {0.0})[0], 10.0 / (7 * std::numbers::pi * h * h), 1e-14);
}

// The cubic spline with Thomas & Couchman's gradient (kernel 4): W is the spline's; dW/dr is
// the spline's from q = 2/3 out, its value there, -norm/h^3, from q = 0.25 to 2/3, and linear
// in q below 0.25 (fortran_core/kernels/kernel_cubic.f90). Relative 1e-13: round-off only.
TEST(CoreKernels, ThomasCouchmanGradient) {
    const double h = 0.7, norm = 10.0 / (7 * std::numbers::pi);
    std::vector<double> r;
    for (double q : {0.0, 0.1, 0.25, 0.4, 0.6, 2.0 / 3.0, 0.8, 1.2, 1.9}) r.push_back(q * h);
    std::vector<double> f3, f4;
    const auto w3 = eval_w(3, h, r, &f3);
    const auto w4 = eval_w(4, h, r, &f4);
    for (std::size_t i = 0; i < r.size(); ++i) {
        const double q = r[i] / h;
        EXPECT_NEAR(w4[i], w3[i], 1e-13 * w3[i]) << "q=" << q;
        if (q == 0.0) continue;   // F = (dW/dr)/r at r > 0 only
        const double dwdr = f4[i] * r[i];
        const double expected = q >= 2.0 / 3.0 ? f3[i] * r[i]
                                : q >= 0.25    ? -norm / (h * h * h)
                                               : -norm / (h * h * h) * q / 0.25;
        EXPECT_NEAR(dwdr, expected, 1e-13 * std::abs(expected)) << "q=" << q;
    }
}

TEST(CoreKernels, BadArgumentsAreAnError) {
    double r = 0.1, w, f;
    EXPECT_EQ(sph_kernel_eval(6, 1.0, 1, &r, &w, &f), SPH_ERR_ARGUMENT);
    EXPECT_EQ(sph_kernel_eval(0, 1.0, 1, &r, &w, &f), SPH_ERR_ARGUMENT);
    EXPECT_EQ(sph_kernel_eval(5, 0.0, 1, &r, &w, &f), SPH_ERR_ARGUMENT);
}
