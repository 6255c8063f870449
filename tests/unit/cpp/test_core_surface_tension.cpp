// CSF surface tension (Morris 2000; paper eqs 14-24) through the C interface
// (sph_surface_tension_fields, sph_compute_rates, sph_step):
//  - a static ring disc of radius R has curvature -1/R at its surface particles (the
//    outermost ring), mean within 5% for both kernels; a disc cut from a square lattice has
//    the right sign and magnitude on average;
//  - every number these static sets give is also checked against its measured value
//    (kRegressionTol below): a change of the model shows even where the target still holds;
//  - the normal and the force point into the liquid (the paper's sign convention);
//  - sigma = 0 leaves the rates bitwise unchanged; the CSF acceleration the rates loop adds is
//    the one the entry point reports;
//  - momentum: CSF is not pairwise antisymmetric, so sum_a m_a a_s,a = 0 only by symmetry; a
//    symmetric drop gives round-off, a jittered drop a small, stated remainder;
//  - boundary particles neither contribute nor receive (fluid-only colour);
//  - results are bitwise independent of the thread count; bad input is a status;
//  - the time step respects the capillary limit 0.25 sqrt(rho0 h^3 / (2 pi sigma));
//  - the two deltas of eq 24 (st_delta 0 pressure-consistent, the default; 1 the paper's colour
//    gradient): the Laplace balance of a static disc, and the surface weight that keeps the
//    pressure-consistent force off the interior.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core_fixture.hpp"

using sphjet_test::CoreParticles;

namespace {

// Regression tolerance of the numbers measured on the fixed particle sets below: one
// evaluation of the fields, no time stepping, so builds and thread counts change them by
// round-off only (results are bitwise across thread counts, IndependentOfThreadCount; a reordered
// sum moves a value of order 1 by ~1e-13). 1e-5 is ten times the precision the values are
// printed and recorded with (1e-6), and catches a change of 0.001%.
constexpr double kRegressionTol = 1e-5;

// Measured values, [kernel: 0 cubic spline, 1 Wendland][R/dx: 10, 20, 40].
using Measured = double[2][3];
double measured(const Measured& m, int kernel, int nr) {
    return m[kernel == 5 ? 1 : 0][nr == 10 ? 0 : nr == 20 ? 1 : 2];
}
constexpr Measured kStaticDiscMeasured = {{-0.999839, -0.998482, -0.998757},
                                          {-0.991583, -0.994421, -0.996827}};
constexpr Measured kLatticeDiscMeasured = {{-0.959937, -0.969469, -0.999975},
                                           {-0.936731, -0.903159, -0.931474}};
constexpr Measured kLaplaceMeasured = {{1.055338, 1.025097, 1.009854},
                                       {1.046488, 1.021866, 1.010458}};
constexpr Measured kLaplacePaperMeasured = {{0.138451, 0.133358, 0.130915},
                                            {0.119822, 0.116005, 0.114004}};

constexpr int kCubic = 3;
constexpr int kWendland = 5;

struct Fields {
    std::vector<double> colour, nx, nz, kappa;
    void bind(sph_arrays_t& a, std::size_t n) {
        for (auto* v : {&colour, &nx, &nz, &kappa}) v->assign(n, -99.0);
        a.colour = colour.data();
        a.st_nx = nx.data();
        a.st_nz = nz.data();
        a.kappa = kappa.data();
    }
};

// Fluid disc of radius r (nr = r/dx lattice spacings) centred at (xc, zc), square lattice,
// at rest at rho0: mass rho0 dx^2. Optional jitter of the positions (fraction of dx).
CoreParticles disc(int nr, double dx, double xc, double zc, double jitter = 0, unsigned seed = 1) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    CoreParticles ps;
    const double r = nr * dx;
    for (int i = -nr; i <= nr; ++i)
        for (int k = -nr; k <= nr; ++k) {
            const double x = i * dx, z = k * dx;
            if (x * x + z * z > r * r * (1 + 1e-9)) continue;
            ps.add(xc + x + jitter * dx * u(rng), zc + z + jitter * dx * u(rng), 0, 0, 1000,
                   1000 * dx * dx, 2);
        }
    return ps;
}

// Fluid disc of concentric rings (a smooth surface, unlike the staircase of a square lattice):
// one particle at the centre, ring j = 1..nr at radius j dx holding round(2 pi j) particles
// (ring j offset by half a spacing in angle against ring j - 1), each with the mass of its
// share of the annulus (j -+ 1/2) dx at rho0. The drop's area is pi ((nr + 1/2) dx)^2.
CoreParticles ring_disc(int nr, double dx, double xc, double zc) {
    CoreParticles ps;
    const double pi = std::numbers::pi;
    ps.add(xc, zc, 0, 0, 1000, 1000 * pi * 0.25 * dx * dx, 2);
    for (int j = 1; j <= nr; ++j) {
        const int nj = static_cast<int>(std::lround(2 * pi * j));
        const double m = 1000 * 2 * pi * j * dx * dx / nj;
        for (int k = 0; k < nj; ++k) {
            const double th = 2 * pi * (k + 0.5 * (j % 2)) / nj;
            ps.add(xc + j * dx * std::cos(th), zc + j * dx * std::sin(th), 0, 0, 1000, m, 2);
        }
    }
    return ps;
}

sph_params_t drop_params(int kernel, double dx, double sigma) {
    auto p = sphjet_test::water_params(kernel, 1.3 * dx);
    p.gravity.gz = 0;
    p.surface_tension.sigma = sigma;
    p.eos.c0 = 5;
    p.eos.b = p.eos.rho0 * p.eos.c0 * p.eos.c0 / p.eos.gamma;
    return p;
}

struct Stats {
    double mean = 0, sd = 0, min = 0, max = 0;
    std::size_t n = 0;
};

Stats stats(const std::vector<double>& v) {
    Stats s;
    s.n = v.size();
    if (v.empty()) return s;
    s.min = *std::min_element(v.begin(), v.end());
    s.max = *std::max_element(v.begin(), v.end());
    for (double x : v) s.mean += x;
    s.mean /= static_cast<double>(v.size());
    for (double x : v) s.sd += (x - s.mean) * (x - s.mean);
    s.sd = std::sqrt(s.sd / static_cast<double>(v.size()));
    return s;
}

// Fields and CSF acceleration (into ax, az) of a particle set.
void csf(CoreParticles& ps, Fields& f, const sph_params_t& prm) {
    auto arr = ps.bind();
    f.bind(arr, ps.x.size());
    ASSERT_EQ(sph_prepare(&prm, &arr), SPH_OK);
    void* ws = sph_workspace_create();
    ASSERT_EQ(sph_surface_tension_fields(ws, &prm, &arr), SPH_OK);
    sph_workspace_destroy(ws);
}

}  // namespace

class StaticDisc : public ::testing::TestWithParam<std::tuple<int, int>> {};

// kappa = div(nhat) with nhat = -e_r is -1/r. Surface particles: the outermost ring, at
// r_s = nr dx (the drop's edge, by area, is half a spacing further out). The mean within 5%:
// the project's target for the surface curvature (README, validation cases). Measured
// kappa r_s (regression, kRegressionTol): cubic spline -0.9998 / -0.9985 / -0.9988, Wendland
// -0.9916 / -0.9944 / -0.9968 at R/dx = 10 / 20 / 40 (6 digits in kStaticDiscMeasured).
TEST_P(StaticDisc, SurfaceCurvatureIsMinusOneOverR) {
    const auto [kernel, nr] = GetParam();
    const double dx = 0.001, rs = nr * dx, xc = 0.1, zc = 0.1;
    auto ps = ring_disc(nr, dx, xc, zc);
    Fields f;
    const auto prm = drop_params(kernel, dx, 1.0);
    csf(ps, f, prm);
    std::vector<double> kr, cs, band;
    for (std::size_t i = 0; i < ps.x.size(); ++i) {
        const double r = std::hypot(ps.x[i] - xc, ps.z[i] - zc);
        if (r > rs - 0.5 * dx) {
            kr.push_back(f.kappa[i] * rs);
            cs.push_back(f.colour[i]);
        } else if (r > rs - 2.5 * dx) {
            band.push_back(f.kappa[i] * r);
        }
    }
    const Stats s = stats(kr), c = stats(cs), b = stats(band);
    std::printf("kernel %d R/dx %d: %zu surface particles, kappa r_s mean %.6f sd %.2e "
                "[%.4f, %.4f] (kappa (r_s + dx/2) mean %.4f), colour %.3f; rows 2-3: kappa r "
                "mean %.4f sd %.2e\n",
                kernel, nr, s.n, s.mean, s.sd, s.min, s.max, s.mean * (rs + 0.5 * dx) / rs,
                c.mean, b.mean, b.sd);
    EXPECT_NEAR(s.mean, -1.0, 0.05);
    EXPECT_NEAR(s.mean, measured(kStaticDiscMeasured, kernel, nr), kRegressionTol)
        << "regression: kernel " << kernel << " R/dx " << nr;
}

INSTANTIATE_TEST_SUITE_P(Kernels, StaticDisc,
                         ::testing::Combine(::testing::Values(kCubic, kWendland),
                                            ::testing::Values(10, 20, 40)));

// surface_tension.curvature = "surface_fit" (physics/surface_tension.f90): the curvature of a
// parabola fitted to the positions of the particles within h of the surface, moved to the
// surface by the depth. On the static ring disc its mean over the outermost ring within 5% of
// -1/r_s, as the normals' divergence above; measured kappa r_s (regression, kRegressionTol):
// cubic spline -0.958 / -0.976 / -0.987, Wendland -0.953 / -0.974 / -0.986 at R/dx = 10 / 20 /
// 40, an error of about dx / (2R) that halves with the spacing.
constexpr Measured kStaticDiscFitMeasured = {{-0.957609, -0.975938, -0.987206},
                                             {-0.953498, -0.974158, -0.986378}};

class StaticDiscFit : public ::testing::TestWithParam<std::tuple<int, int>> {};

TEST_P(StaticDiscFit, SurfaceFitCurvatureIsMinusOneOverR) {
    const auto [kernel, nr] = GetParam();
    const double dx = 0.001, rs = nr * dx, xc = 0.1, zc = 0.1;
    auto ps = ring_disc(nr, dx, xc, zc);
    Fields f;
    auto prm = drop_params(kernel, dx, 1.0);
    prm.surface_tension.curvature = 1;
    csf(ps, f, prm);
    std::vector<double> kr;
    for (std::size_t i = 0; i < ps.x.size(); ++i)
        if (std::hypot(ps.x[i] - xc, ps.z[i] - zc) > rs - 0.5 * dx) kr.push_back(f.kappa[i] * rs);
    const Stats s = stats(kr);
    std::printf("surface fit: kernel %d R/dx %d: %zu surface particles, kappa r_s mean %.6f sd %.2e\n",
                kernel, nr, s.n, s.mean, s.sd);
    EXPECT_NEAR(s.mean, -1.0, 0.05);
    EXPECT_NEAR(s.mean, measured(kStaticDiscFitMeasured, kernel, nr), kRegressionTol)
        << "regression: kernel " << kernel << " R/dx " << nr;
}

INSTANTIATE_TEST_SUITE_P(Kernels, StaticDiscFit,
                         ::testing::Combine(::testing::Values(kCubic, kWendland),
                                            ::testing::Values(10, 20, 40)));

// What the surface fit is for: particles that slide along the surface leave the surface as it
// was, and its curvature with it. The outermost ring of the R/dx = 20 ring disc (Wendland) has
// each particle moved along the circle by a seeded random angle of up to 0.3 spacings; the
// geometric curvature stays -1/r_s at every particle. At h = 1.3 dx and 2 dx, over that ring:
// the surface fit's kappa r_s within 5% of -1 on average (as the static disc) and with a spread
// (sd) of at most 0.02: the ideal is 0, measured 0.0056 and 0.0031; a fit that follows the
// particles' places along the surface, as one through the outer two rows did (0.52 at
// h = 2 dx), fails it. The normals' divergence (the default) spreads 3.06 and 0.49 (printed).
TEST(CoreSurfaceTension, SurfaceFitIgnoresSlidingAlongTheSurface) {
    const int nr = 20;
    const double dx = 0.001, rs = nr * dx, xc = 0.1, zc = 0.1;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-0.3, 0.3);
    auto ps = ring_disc(nr, dx, xc, zc);
    for (std::size_t i = 0; i < ps.x.size(); ++i) {
        const double r = std::hypot(ps.x[i] - xc, ps.z[i] - zc);
        if (r < rs - 0.5 * dx) continue;
        const double th = std::atan2(ps.z[i] - zc, ps.x[i] - xc) + u(rng) * dx / rs;
        ps.x[i] = xc + r * std::cos(th);
        ps.z[i] = zc + r * std::sin(th);
    }
    for (double h_dx : {1.3, 2.0})
        for (int model : {0, 1}) {
            auto p = ps;
            Fields f;
            auto prm = drop_params(kWendland, dx, 1.0);
            prm.numerics.h = h_dx * dx;
            prm.surface_tension.curvature = model;
            csf(p, f, prm);
            std::vector<double> kr;
            for (std::size_t i = 0; i < p.x.size(); ++i)
                if (std::hypot(p.x[i] - xc, p.z[i] - zc) > rs - 0.5 * dx) kr.push_back(f.kappa[i] * rs);
            const Stats st = stats(kr);
            std::printf("slid outer ring, h = %.1f dx, curvature %s: kappa r_s mean %.6f sd %.4f [%.4f, %.4f]\n",
                        h_dx, model == 0 ? "normals" : "surface_fit", st.mean, st.sd, st.min, st.max);
            if (model == 1) {
                EXPECT_NEAR(st.mean, -1.0, 0.05) << "h = " << h_dx << " dx";
                EXPECT_LE(st.sd, 0.02) << "h = " << h_dx << " dx";
            }
        }
}

// The surface fit's parabola alone (sph_surface_fit): points in the frame of a particle at the
// origin whose unit normal (into the liquid) is (0, 1), so that s = -x (s runs along
// (-nz, nx)) and eta = z; the point sets are symmetric in x, so the sign does not show; spacing
// dx = h / 2, as in the round jets.
//  - Points of a circle of radius R = 10 h whose surface passes 0.5 h below the particle, at
//    x = -2h ... 2h (spacing h/2): taken, c0 = -0.5 h within 0.1% and kin = -1/R within 2%:
//    the circle's quartic term s^4 / (8 R^3), which the parabola takes up in part, moves the
//    least-squares c2 by about (s/R)^2 / 4 at the points' spread (measured kin R = -1.0105)
//    and c0 by about 1e-3 of it (measured -0.50049 d).
//  - The same circle seen with the particle's normal tilted by 20 degrees: the fit's slope is
//    c1 = -0.35, and kin = -2 c2 / (1 + c1^2)^(3/2) is still -1/R within 3% (measured -1.0236;
//    -2 c2 alone would be 19% off), the fitted curve's normal radial part nrx within 0.02 of the
//    circle's, 0 (measured 0.013), and c0 the distance along the tilted normal, -d / cos 20,
//    within 1% (measured -0.5315 h against -0.5321 h).
//  - A flat row 2.1 h below the particle (one deep in a sheet sees the surface there): taken,
//    kin = 0 and c0 = -2.1 h. How far the curve passes does not refuse a fit.
//  - Points on parabolas whose curvature at the particle is 0.9 / dx and 1.1 / dx: the first
//    taken with exactly that curvature, the second refused (a radius below one spacing).
//  - Two bunches of points either side of the particle, a surface that runs along its normal as
//    where a froth of rings meets the axis: kin = 293 / h, refused (the loops then keep the
//    normals' curvature there).
//  - surface_tension.fit_points_min: three points of the circle at s = -h, 0, h give a parabola
//    (taken at 3, kin = -1/R within 1%: the circle's quartic term is not fitted); at 4 the same
//    fit is refused for too few points (fitted 2, kin 0), and the nine points are taken at 4
//    and at 9 and refused at 10. Points of weight 0 are not counted.
//  - A normal that is not a unit vector, a spacing that is not positive, a negative count or a
//    negative points_min is an argument error.
TEST(CoreSurfaceTension, SurfaceFitRefusesCurvesTighterThanTheParticles) {
    const double h = 0.002, dx = 0.5 * h, R = 10 * h, d = 0.5 * h;
    double nrx = 0;
    auto fit = [dx, &nrx](const std::vector<double>& px, const std::vector<double>& pz, double nx,
                          double nz, double& kin, double& c0, int& fitted, double spacing = -1,
                          int points_min = 3) {
        const std::vector<double> om(px.size(), 1.0);
        return sph_surface_fit(static_cast<std::int64_t>(px.size()), px.data(), pz.data(), om.data(), nx,
                               nz, spacing < 0 ? dx : spacing, points_min, &kin, &nrx, &c0, &fitted);
    };
    std::vector<double> px, pz;
    for (int i = -4; i <= 4; ++i) {
        const double sx = 0.5 * h * i;
        px.push_back(sx);
        pz.push_back(-d + R - std::sqrt(R * R - sx * sx));
    }
    double kin = 0, c0 = 0;
    int fitted = -1;
    ASSERT_EQ(fit(px, pz, 0, 1, kin, c0, fitted), SPH_OK);
    EXPECT_EQ(fitted, 1);
    EXPECT_NEAR(c0, -d, 1e-3 * d);
    EXPECT_NEAR(kin * R, -1.0, 2e-2);
    const double tilt = 20.0 * std::acos(-1.0) / 180.0;
    ASSERT_EQ(fit(px, pz, std::sin(tilt), std::cos(tilt), kin, c0, fitted), SPH_OK);
    EXPECT_EQ(fitted, 1);
    EXPECT_NEAR(kin * R, -1.0, 3e-2);
    EXPECT_NEAR(nrx, 0.0, 2e-2);
    EXPECT_NEAR(c0, -d / std::cos(tilt), 1e-2 * d);
    const std::vector<double> flat(px.size(), -2.1 * h);
    ASSERT_EQ(fit(px, flat, 0, 1, kin, c0, fitted), SPH_OK);
    EXPECT_EQ(fitted, 1);
    EXPECT_NEAR(c0, -2.1 * h, 1e-12);
    EXPECT_NEAR(kin * h, 0.0, 1e-9);
    for (double kdx : {0.9, 1.1}) {   // eta = -0.3 h + (kdx / dx) s^2 / 2: kin = -kdx / dx at s = 0
        std::vector<double> bent;
        for (double sx : px) bent.push_back(-0.3 * h + 0.5 * (kdx / dx) * sx * sx);
        ASSERT_EQ(fit(px, bent, 0, 1, kin, c0, fitted), SPH_OK);
        EXPECT_EQ(fitted, kdx < 1 ? 1 : 0) << "curvature " << kdx << " / dx";
        EXPECT_NEAR(kin * dx, kdx < 1 ? -kdx : 0.0, 1e-9);
    }
    ASSERT_EQ(fit({-0.30 * h, -0.28 * h, 0.28 * h, 0.30 * h}, {-0.7 * h, 1.0 * h, 1.0 * h, -0.7 * h}, 0, 1, kin,
                  c0, fitted),
              SPH_OK);
    EXPECT_EQ(fitted, 0);
    EXPECT_EQ(kin, 0.0);
    EXPECT_EQ(fit(px, pz, 0, 2, kin, c0, fitted), SPH_ERR_ARGUMENT);
    EXPECT_EQ(fit(px, pz, 0, 1, kin, c0, fitted, 0.0), SPH_ERR_ARGUMENT);
    EXPECT_EQ(fit(px, pz, 0, 1, kin, c0, fitted, -1, -1), SPH_ERR_ARGUMENT);
    EXPECT_EQ(sph_surface_fit(-1, px.data(), pz.data(), px.data(), 0, 1, dx, 3, &kin, &nrx, &c0, &fitted),
              SPH_ERR_ARGUMENT);

    // fit_points_min: three of the circle's points, s = -h, 0, h (px[2], px[4], px[6])
    const std::vector<double> px3{px[2], px[4], px[6]}, pz3{pz[2], pz[4], pz[6]};
    ASSERT_EQ(fit(px3, pz3, 0, 1, kin, c0, fitted), SPH_OK);
    EXPECT_EQ(fitted, 1);
    EXPECT_NEAR(kin * R, -1.0, 1e-2);
    ASSERT_EQ(fit(px3, pz3, 0, 1, kin, c0, fitted, -1, 4), SPH_OK);
    EXPECT_EQ(fitted, 2);
    EXPECT_EQ(kin, 0.0);
    for (int points_min : {4, 9, 10}) {
        ASSERT_EQ(fit(px, pz, 0, 1, kin, c0, fitted, -1, points_min), SPH_OK);
        EXPECT_EQ(fitted, points_min <= 9 ? 1 : 2) << points_min;
    }
    std::vector<double> om4(px.size(), 0.0);   // nine points, four of them weighted
    for (int i : {1, 3, 5, 7}) om4[i] = 1.0;
    ASSERT_EQ(sph_surface_fit(9, px.data(), pz.data(), om4.data(), 0, 1, dx, 5, &kin, &nrx, &c0, &fitted),
              SPH_OK);
    EXPECT_EQ(fitted, 2);
    ASSERT_EQ(sph_surface_fit(9, px.data(), pz.data(), om4.data(), 0, 1, dx, 4, &kin, &nrx, &c0, &fitted),
              SPH_OK);
    EXPECT_EQ(fitted, 1);
}

// The same on a square lattice: the staircase edge has its own curvature of order 1/dx at
// corners, so single particles scatter widely (sd 0.35-1.8 in kappa R) and the mean over the
// edge particles does not converge to -1/R (measured kappa R: cubic spline -0.960 / -0.970 /
// -1.000, Wendland -0.937 / -0.903 / -0.932 at R/dx = 10 / 20 / 40): the physics asks only
// the sign and the magnitude (within 50%: a staircase edge is not a circle); the measured
// means are checked as regression values (kRegressionTol).
TEST(CoreSurfaceTension, LatticeDiscMeanCurvature) {
    for (int kernel : {kCubic, kWendland})
        for (int nr : {10, 20, 40}) {
            const double dx = 0.001, R = nr * dx, xc = 0.1, zc = 0.1;
            auto ps = disc(nr, dx, xc, zc);
            Fields f;
            csf(ps, f, drop_params(kernel, dx, 1.0));
            std::vector<double> kr;
            for (std::size_t i = 0; i < ps.x.size(); ++i)
                if (std::hypot(ps.x[i] - xc, ps.z[i] - zc) > R - dx) kr.push_back(f.kappa[i] * R);
            const Stats s = stats(kr);
            std::printf("lattice kernel %d R/dx %d: %zu edge particles, kappa R mean %.6f sd "
                        "%.3f\n", kernel, nr, s.n, s.mean, s.sd);
            EXPECT_NEAR(s.mean, -1.0, 0.5);
            EXPECT_NEAR(s.mean, measured(kLatticeDiscMeasured, kernel, nr), kRegressionTol)
                << "regression: kernel " << kernel << " R/dx " << nr;
        }
}

// Sign convention: n and a_s point into the liquid (towards the centre) at the surface
// (outermost ring of a ring disc), kappa < 0, and a_s is proportional to sigma.
TEST(CoreSurfaceTension, NormalAndForcePointInward) {
    for (int kernel : {kCubic, kWendland}) {
        const double dx = 0.001, xc = 0.05, zc = 0.05;
        auto ps = ring_disc(15, dx, xc, zc);
        Fields f;
        const auto prm = drop_params(kernel, dx, 0.5);
        csf(ps, f, prm);
        auto ps2 = ps;
        Fields f2;
        auto prm2 = prm;
        prm2.surface_tension.sigma = 2 * prm.surface_tension.sigma;
        csf(ps2, f2, prm2);
        int checked = 0;
        for (std::size_t i = 0; i < ps.x.size(); ++i) {
            if (std::hypot(ps.x[i] - xc, ps.z[i] - zc) < 14.5 * dx) continue;
            const double ex = ps.x[i] - xc, ez = ps.z[i] - zc;
            EXPECT_LT(f.nx[i] * ex + f.nz[i] * ez, 0.0) << "normal of particle " << i;
            EXPECT_LT(ps.ax[i] * ex + ps.az[i] * ez, 0.0) << "force on particle " << i;
            EXPECT_LT(f.kappa[i], 0.0);
            EXPECT_DOUBLE_EQ(ps2.ax[i], 2 * ps.ax[i]);
            EXPECT_DOUBLE_EQ(ps2.az[i], 2 * ps.az[i]);
            ++checked;
        }
        EXPECT_EQ(checked, 94);  // round(2 pi 15)
    }
}

// sigma = 0: the rates loop does not call CSF; the rates are bitwise those of a run without
// the field arrays, and the entry point reports a zero acceleration. sigma > 0: the rates
// differ from the sigma = 0 rates by exactly the CSF acceleration (to round-off of the sum).
TEST(CoreSurfaceTension, SigmaZeroHasNoEffectAndRatesAddCsf) {
    const double dx = 0.001;
    auto a = disc(12, dx, 0.05, 0.05, 0.2, 3), b = a, c = a, d = a;
    auto p0 = drop_params(kWendland, dx, 0.0);
    auto p1 = drop_params(kWendland, dx, 0.8);
    void* ws = sph_workspace_create();
    double v = 0;
    // a: sigma 0 without fields; b: sigma 0 with fields; c: sigma > 0 with fields
    auto arr_a = a.bind();
    Fields fb, fc, fd;
    auto arr_b = b.bind();
    fb.bind(arr_b, b.x.size());
    auto arr_c = c.bind();
    fc.bind(arr_c, c.x.size());
    ASSERT_EQ(sph_prepare(&p0, &arr_a), SPH_OK);
    ASSERT_EQ(sph_prepare(&p0, &arr_b), SPH_OK);
    ASSERT_EQ(sph_prepare(&p1, &arr_c), SPH_OK);
    ASSERT_EQ(sph_compute_rates(ws, &p0, &arr_a, &v), SPH_OK);
    ASSERT_EQ(sph_compute_rates(ws, &p0, &arr_b, &v), SPH_OK);
    ASSERT_EQ(sph_compute_rates(ws, &p1, &arr_c, &v), SPH_OK);
    for (std::size_t i = 0; i < a.x.size(); ++i) {
        EXPECT_EQ(a.ax[i], b.ax[i]);
        EXPECT_EQ(a.az[i], b.az[i]);
        EXPECT_EQ(fb.colour[i], -99.0) << "sigma = 0 must not touch the fields";
    }
    // CSF alone
    auto arr_d = d.bind();
    fd.bind(arr_d, d.x.size());
    ASSERT_EQ(sph_prepare(&p1, &arr_d), SPH_OK);
    ASSERT_EQ(sph_surface_tension_fields(ws, &p1, &arr_d), SPH_OK);
    double scale = 0;
    for (std::size_t i = 0; i < a.x.size(); ++i) scale = std::max(scale, std::hypot(a.ax[i], a.az[i]));
    for (std::size_t i = 0; i < a.x.size(); ++i) {
        EXPECT_NEAR(c.ax[i] - a.ax[i], d.ax[i], 1e-12 * scale);
        EXPECT_NEAR(c.az[i] - a.az[i], d.az[i], 1e-12 * scale);
        EXPECT_EQ(fc.kappa[i], fd.kappa[i]);
        EXPECT_EQ(fc.colour[i], fd.colour[i]);
    }
    // entry point with sigma = 0: fields computed, acceleration exactly zero
    ASSERT_EQ(sph_surface_tension_fields(ws, &p0, &arr_d), SPH_OK);
    for (std::size_t i = 0; i < d.x.size(); ++i) {
        EXPECT_EQ(d.ax[i], 0.0);
        EXPECT_EQ(d.az[i], 0.0);
        EXPECT_EQ(fd.kappa[i], fc.kappa[i]);
    }
    sph_workspace_destroy(ws);
}

// Momentum of the CSF force over a closed drop. Eq 24 is a per-particle force, not a sum of
// antisymmetric pair terms, so sum m a_s vanishes only as far as the drop is symmetric:
// a lattice disc (symmetric under x -> -x, z -> -z) gives round-off (1e-12 of sum m |a_s|);
// a jittered disc (positions moved by up to +-0.1 dx) leaves a remainder, measured at 2.0%
// (cubic spline) and 0.97% (Wendland) of sum m |a_s|, bounded here by 5%.
TEST(CoreSurfaceTension, MomentumOfClosedDrop) {
    for (int kernel : {kCubic, kWendland}) {
        for (double jitter : {0.0, 0.2}) {
            const double dx = 0.001;
            auto ps = disc(15, dx, 0.05, 0.05, jitter, 11);
            Fields f;
            csf(ps, f, drop_params(kernel, dx, 1.0));
            double px = 0, pz = 0, scale = 0;
            for (std::size_t i = 0; i < ps.x.size(); ++i) {
                px += ps.m[i] * ps.ax[i];
                pz += ps.m[i] * ps.az[i];
                scale += ps.m[i] * std::hypot(ps.ax[i], ps.az[i]);
            }
            const double rel = std::hypot(px, pz) / scale;
            std::printf("kernel %d jitter %.1f dx: |sum m a_s| / sum m |a_s| = %.3e\n", kernel,
                        jitter, rel);
            EXPECT_LT(rel, jitter == 0.0 ? 1e-12 : 5e-2);
        }
    }
}

// Fluid-only colour: boundary particles get zero fields and no force, and the fields of
// fluid particles do not depend on boundary particles near them.
TEST(CoreSurfaceTension, BoundaryParticlesDoNotEnter) {
    const double dx = 0.001;
    auto fluid_only = disc(10, dx, 0.05, 0.05);
    CoreParticles with_wall;
    // a wall line just below the drop, boundary particles first (legacy order)
    for (int i = -12; i <= 12; ++i) with_wall.add(0.05 + i * dx, 0.05 - 11 * dx, 0, 0, 1000, 1000 * dx * dx, 0);
    with_wall.nb = static_cast<std::int64_t>(with_wall.x.size());
    const auto nb = with_wall.x.size();
    for (std::size_t i = 0; i < fluid_only.x.size(); ++i)
        with_wall.add(fluid_only.x[i], fluid_only.z[i], 0, 0, 1000, fluid_only.m[i], 2);
    Fields f1, f2;
    const auto prm = drop_params(kWendland, dx, 1.0);
    csf(fluid_only, f1, prm);
    csf(with_wall, f2, prm);
    for (std::size_t i = 0; i < nb; ++i) {
        EXPECT_EQ(f2.colour[i], 0.0);
        EXPECT_EQ(f2.kappa[i], 0.0);
        EXPECT_EQ(with_wall.ax[i], 0.0);
        EXPECT_EQ(with_wall.az[i], 0.0);
    }
    for (std::size_t i = 0; i < fluid_only.x.size(); ++i) {
        // same sums, possibly visited in another order: equal to round-off
        EXPECT_NEAR(f2.colour[nb + i], f1.colour[i], 1e-12);
        EXPECT_NEAR(f2.kappa[nb + i], f1.kappa[i], 1e-9 * std::max(1.0, std::abs(f1.kappa[i])));
    }
}

// The traversal gives every particle its contributions in a fixed order: bitwise equal
// fields and accelerations with 1 and 2 threads.
TEST(CoreSurfaceTension, IndependentOfThreadCount) {
    const double dx = 0.001;
    auto a = disc(20, dx, 0.05, 0.05, 0.2, 5), b = a;
    Fields fa, fb;
    const auto prm = drop_params(kCubic, dx, 1.0);
    const int old = sph_get_threads();
    sph_set_threads(1);
    csf(a, fa, prm);
    sph_set_threads(2);
    csf(b, fb, prm);
    sph_set_threads(old);
    for (std::size_t i = 0; i < a.x.size(); ++i) {
        EXPECT_EQ(fa.colour[i], fb.colour[i]);
        EXPECT_EQ(fa.kappa[i], fb.kappa[i]);
        EXPECT_EQ(a.ax[i], b.ax[i]);
        EXPECT_EQ(a.az[i], b.az[i]);
    }
}

TEST(CoreSurfaceTension, MissingFieldArraysIsAnError) {
    auto ps = disc(5, 0.001, 0.05, 0.05);
    auto arr = ps.bind();
    const auto prm = drop_params(kWendland, 0.001, 1.0);
    void* ws = sph_workspace_create();
    EXPECT_EQ(sph_surface_tension_fields(ws, &prm, &arr), SPH_ERR_ARGUMENT);
    Fields f;
    f.bind(arr, ps.x.size());
    EXPECT_EQ(sph_surface_tension_fields(nullptr, &prm, &arr), SPH_ERR_ARGUMENT);
    auto bad = prm;
    bad.surface_tension.sigma = -1;
    EXPECT_EQ(sph_surface_tension_fields(ws, &bad, &arr), SPH_ERR_ARGUMENT);
    for (int delta : {-1, 2}) {  // only 0 (pressure-consistent) and 1 (colour gradient)
        bad = prm;
        bad.surface_tension.delta = delta;
        EXPECT_EQ(sph_surface_tension_fields(ws, &bad, &arr), SPH_ERR_ARGUMENT) << delta;
    }
    EXPECT_EQ(sph_surface_tension_fields(ws, &prm, &arr), SPH_OK);
    sph_workspace_destroy(ws);
}

// Capillary limit (a departure from eqs 30-32, time_step.f90): with a large sigma the next
// step is at most 0.25 sqrt(rho0 h^3 / (2 pi sigma)), and equal to it when that is the
// smallest term.
TEST(CoreSurfaceTension, TimeStepRespectsCapillaryLimit) {
    const double dx = 0.001;
    auto ps = disc(8, dx, 0.05, 0.05);
    auto prm = drop_params(kWendland, dx, 50.0);
    auto arr = ps.bind();
    Fields f;
    f.bind(arr, ps.x.size());
    ASSERT_EQ(sph_prepare(&prm, &arr), SPH_OK);
    void* ws = sph_workspace_create();
    sph_step_info_t info{};
    info.dt = 1e-6;
    ASSERT_EQ(sph_step(ws, &prm, &arr, &info), SPH_OK);
    sph_workspace_destroy(ws);
    const double dt_st = 0.25 * std::sqrt(prm.eos.rho0 * std::pow(prm.numerics.h, 3) /
                                          (2 * std::numbers::pi * prm.surface_tension.sigma));
    const double dt_cfl = prm.time_step.cfl * std::min(info.dt_f, info.dt_cv);
    ASSERT_LT(dt_st, dt_cfl) << "the case must make the capillary term the smallest";
    EXPECT_DOUBLE_EQ(info.dt_new, dt_st);
    EXPECT_LE(info.dt_next, dt_st);
}

// Discrete Laplace balance of a static ring disc: the uniform pressure p* that best balances
// the CSF force (least squares over all particles of |a_p(p) + a_s|, a_p the pair pressure
// acceleration of rates.f90 with p uniform) against sigma/R, R = (nr + 1/2) dx (the area
// radius). The measured values and the tolerances: LaplaceBalanceOfStaticDisc below.
double laplace_balance(int kernel, int nr, int st_delta) {
    const double dx = 0.001, xc = 0.1, zc = 0.1, R = (nr + 0.5) * dx;
    auto ps = ring_disc(nr, dx, xc, zc);
    Fields f;
    auto prm = drop_params(kernel, dx, 1.0);
    prm.surface_tension.delta = st_delta;
    csf(ps, f, prm);  // a_s in ps.ax
    auto q = ps;
    const double p = prm.surface_tension.sigma / R;
    for (auto& r : q.rho) r = prm.eos.rho0 * std::pow(1 + p / prm.eos.b, 1 / prm.eos.gamma);
    auto arr = q.bind();
    auto p0 = prm;
    p0.surface_tension.sigma = 0;
    p0.numerics.tensile = 0;
    EXPECT_EQ(sph_prepare(&p0, &arr), SPH_OK);
    void* ws = sph_workspace_create();
    double v;
    EXPECT_EQ(sph_compute_rates(ws, &p0, &arr, &v), SPH_OK);
    sph_workspace_destroy(ws);
    double sp = 0, pp = 0;
    for (std::size_t i = 0; i < q.x.size(); ++i) {
        sp += ps.ax[i] * q.ax[i] + ps.az[i] * q.az[i];
        pp += q.ax[i] * q.ax[i] + q.az[i] * q.az[i];
    }
    return -sp / pp;
}

// The default model (free-surface curvature, pressure-consistent delta) converges to the
// Laplace jump at first order in dx/R (the excess is the curvature -1/r of the outer rows,
// r < R): measured 1.0553 / 1.0251 / 1.0099 (cubic spline) and 1.0465 / 1.0219 / 1.0105
// (Wendland) at R/dx = 10 / 20 / 40. Checked: the project's 3% target from R/dx = 20 on, 6%
// at R/dx = 10 (first order: twice the error at half the resolution), and the error falling
// with resolution. The paper's eq 24 (st_delta = 1, colour gradient) holds only 0.1385 /
// 0.1334 / 0.1309 (cubic spline) and 0.1198 / 0.1160 / 0.1140 (Wendland) of it at a free
// surface: there is no physics target for a model that misses the jump; the band 0.08-0.20
// says "about 1/8", and the measured values are checked as regression values. Both with
// kRegressionTol (6 digits in kLaplaceMeasured, kLaplacePaperMeasured).
TEST(CoreSurfaceTension, LaplaceBalanceOfStaticDisc) {
    for (int kernel : {kCubic, kWendland}) {
        double previous_error = 1.0;
        for (int nr : {10, 20, 40}) {
            const double r0 = laplace_balance(kernel, nr, 0), r1 = laplace_balance(kernel, nr, 1);
            std::printf("kernel %d R/dx %d: p*/(sigma/R) = %.6f pressure_consistent, %.6f "
                        "colour_gradient (paper eq 24)\n", kernel, nr, r0, r1);
            EXPECT_NEAR(r0, measured(kLaplaceMeasured, kernel, nr), kRegressionTol)
                << "regression: kernel " << kernel << " R/dx " << nr;
            EXPECT_NEAR(r1, measured(kLaplacePaperMeasured, kernel, nr), kRegressionTol)
                << "regression (eq 24): kernel " << kernel << " R/dx " << nr;
            EXPECT_NEAR(r0, 1.0, nr >= 20 ? 0.03 : 0.06) << "kernel " << kernel << " R/dx " << nr;
            EXPECT_LT(std::abs(r0 - 1.0), previous_error) << "kernel " << kernel << " R/dx " << nr;
            previous_error = std::abs(r0 - 1.0);
            EXPECT_GT(r1, 0.08);
            EXPECT_LT(r1, 0.20);
        }
    }
}

// The surface weight of the pressure-consistent force (csf_surface_weight: 0 where
// |n| h < 0.025): in a ring disc the rings next to the centre are irregular enough for their
// colour gradient to pass the 0.01/h filter of eq 20 (|n| h = 0.017-0.024) and get a
// curvature of order 1/h; they must get no force (a run blew up from the centre without the
// weight). The outer two rows (|n| h = 0.13) get the full force. The paper's force
// (st_delta = 1) has no weight: it is eq 24 as printed.
TEST(CoreSurfaceTension, PressureConsistentForceOnlyOnTheOuterRows) {
    const double dx = 0.001, xc = 0.05, zc = 0.05;
    const int nr = 20;
    for (int st_delta : {0, 1}) {
        auto ps = ring_disc(nr, dx, xc, zc);
        Fields f;
        auto prm = drop_params(kWendland, dx, 1.0);
        prm.surface_tension.delta = st_delta;
        csf(ps, f, prm);
        int interior_flagged = 0, interior_forced = 0, outer = 0;
        for (std::size_t i = 0; i < ps.x.size(); ++i) {
            const double r = std::hypot(ps.x[i] - xc, ps.z[i] - zc);
            const double a = std::hypot(ps.ax[i], ps.az[i]);
            if (r < (nr - 4) * dx) {
                if (f.kappa[i] != 0.0) ++interior_flagged;
                if (a != 0.0) ++interior_forced;
            } else if (r > (nr - 1.5) * dx) {
                EXPECT_GT(a, 0.0) << "outer-row particle " << i;
                ++outer;
            }
        }
        std::printf("st_delta %d: %d interior particles with a curvature, %d with a force\n",
                    st_delta, interior_flagged, interior_forced);
        EXPECT_GT(interior_flagged, 0) << "the case must have flagged interior particles";
        if (st_delta == 0) EXPECT_EQ(interior_forced, 0);
        if (st_delta == 1) EXPECT_GT(interior_forced, 0);
        EXPECT_GT(outer, 200);
    }
}
