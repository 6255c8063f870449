// domain.renormalise_ring_continuity (fortran_core/loops/axisymmetric_loops.f90,
// renormalised_rate): the rings pair's density rate scaled along r and z so that both respond
// as their volume-weighted mean. On a five-ring column (h = 2 dx, the round jets' lattice, and
// the same stretched to a radial spacing of 0.9 dx and an axial one of dx / 0.81, a falling jet's
// lattice about 25% faster than at its orifice), periodic in z over 60 rows:
// - a divergence-free stretch w = B sin(kz)/k, u = -(r/2) B cos(kz) (one wavelength over the
//   period) leaves every row's density alone: the cos(kz) part of its rate within 0.01 rho B
//   (measured: at most 0.0053, at the surface row; the sine's own discretisation, k dz = 2 pi /
//   60, is 0.6% of each part). Without the key the two outer rows' rates are 0.11-0.16 rho B
//   (the surface cuts their kernel less axially than radially), which the test checks too
//   (above 0.1 at the surface row), so that it would notice a key that did nothing.
// - a change of volume, u = A r cos(kz), w = A sin(kz)/k (div = 3 A cos kz), changes each row's
//   density as without the key, within 1e-3 of rho 3A (measured: within 2e-4, the sine's
//   error weighted differently).
// - with the key the rings pair is otherwise unchanged: the accelerations are bitwise those
//   without it.
// - along a jet (geometry.renormalise_reach = L > 0, a nozzle whose orifice is at the column's
//   top, pointing down) the key acts only nearer the orifice than L: rings farther than L have
//   bitwise the rate without the key, rings nearer than L - 2h bitwise the rate with the key
//   everywhere (reach 0), those between a rate between the two.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "core_fixture.hpp"

using sphjet_test::CoreParticles;

namespace {

constexpr int kWendland = 5;
constexpr int kRows = 5, kNz = 60;
constexpr double kDx = 1e-4, kRho0 = 1000;

struct Column {
    CoreParticles ps;
    sph_params_t prm;
    double dz, k;
};

// The column with radial spacing s dx and axial dx / s^2 (each ring's meridian area dx^2 / s, as
// a ring of the nozzle's lattice keeps its volume while the jet stretches), its velocity
// field(r, z, k) = (u, w), row i's density rho0 (1 + drho i); its rates set.
template <class Field>
Column column(double s, bool renormalise, Field field, double drho = 0, double reach = 0) {
    Column c;
    const double dr = s * kDx;
    c.dz = kDx / (s * s);
    c.k = 2 * std::numbers::pi / (kNz * c.dz);
    auto& p = c.prm;
    p = sphjet_test::water_params(kWendland, 2 * kDx);
    p.viscosity.model = 2;
    p.viscosity.value = 1e-6;
    p.numerics.xsph_eps = 0;
    p.eos.c0 = 12;
    p.eos.b = kRho0 * p.eos.c0 * p.eos.c0 / p.eos.gamma;
    p.gravity.gz = 0;
    p.geometry.kind = 1;
    p.geometry.axis_pair = 1;
    p.geometry.periodic_z = 1;
    p.geometry.axis_m1 = 2 * std::numbers::pi * kRho0 * dr * dr * c.dz;
    p.geometry.renormalise_continuity = renormalise ? 1 : 0;
    p.geometry.renormalise_reach = reach;
    p.domain.zmin = 0;
    p.domain.zmax = kNz * c.dz;
    for (int i = 0; i < kRows; ++i)
        for (int j = 0; j < kNz; ++j) {
            const double r = (i + 0.5) * dr, z = (j + 0.5) * c.dz;
            const auto [u, w] = field(r, z, c.k);
            c.ps.add(r, z, u, w, kRho0 * (1 + drho * i), 2 * std::numbers::pi * r * kRho0 * dr * c.dz, 2);
        }
    sphjet_test::compute_rates(c.ps, c.prm);
    return c;
}

// Each row's cos(kz) part of the density rate, over rho0 times `scale`.
std::vector<double> cos_parts(const Column& c, double scale) {
    std::vector<double> out;
    for (int i = 0; i < kRows; ++i) {
        double num = 0, den = 0;
        for (int j = 0; j < kNz; ++j) {
            const double cs = std::cos(c.k * (j + 0.5) * c.dz);
            num += c.ps.ar[i * kNz + j] * cs;
            den += cs * cs;
        }
        out.push_back(num / den / (kRho0 * scale));
    }
    return out;
}

}  // namespace

TEST(CoreRingContinuity, StretchWithoutChangeOfVolumeKeepsTheDensity) {
    const double b = 1.0;
    auto stretch = [b](double r, double z, double k) {
        return std::pair{-0.5 * r * b * std::cos(k * z), b * std::sin(k * z) / k};
    };
    for (double s : {1.0, 0.9}) {
        const auto with = cos_parts(column(s, true, stretch), b);
        const auto without = cos_parts(column(s, false, stretch), b);
        for (int i = 0; i < kRows; ++i) EXPECT_LT(std::abs(with[i]), 0.01) << "s " << s << ", row " << i;
        EXPECT_GT(std::abs(without[kRows - 1]), 0.1) << "s " << s << ": the surface row without the key";
    }
}

TEST(CoreRingContinuity, ChangeOfVolumeAsBefore) {
    const double a = 1.0;
    auto dilate = [a](double r, double z, double k) {
        return std::pair{a * r * std::cos(k * z), a * std::sin(k * z) / k};
    };
    for (double s : {1.0, 0.9}) {
        const auto with = cos_parts(column(s, true, dilate), 3 * a);
        const auto without = cos_parts(column(s, false, dilate), 3 * a);
        for (int i = 0; i < kRows; ++i) EXPECT_NEAR(with[i], without[i], 1e-3) << "s " << s << ", row " << i;
    }
}

TEST(CoreRingContinuity, AccelerationsUnchanged) {
    auto stretch = [](double r, double z, double k) {
        return std::pair{-0.5 * r * std::cos(k * z), std::sin(k * z) / k};
    };
    // a pressure for the pair to act on: each row's density 1e-4 rho0 above the last's
    auto with = column(0.9, true, stretch, 1e-4);
    auto without = column(0.9, false, stretch, 1e-4);
    for (std::size_t q = 0; q < with.ps.ax.size(); ++q) {
        ASSERT_EQ(with.ps.ax[q], without.ps.ax[q]) << q;
        ASSERT_EQ(with.ps.az[q], without.ps.az[q]) << q;
    }
}

TEST(CoreRingContinuity, AlongTheIntactJetOnly) {
    auto stretch = [](double r, double z, double k) {
        return std::pair{-0.5 * r * std::cos(k * z), std::sin(k * z) / k};
    };
    const double s = 0.9;
    const Column everywhere = column(s, true, stretch);
    const Column plain = column(s, false, stretch);
    // the orifice on the axis at the column's top, the jet running down: a ring's distance
    // from it is z_top - z; the intact jet reaches to the middle
    auto along = [&](double reach) {
        Column c = column(s, true, stretch, 0, reach);   // rates with the nozzle unset: redone below
        c.prm.nozzle.x0 = 0;
        c.prm.nozzle.z0 = c.prm.domain.zmax;
        c.prm.nozzle.ex = 0;
        c.prm.nozzle.ez = -1;
        sphjet_test::compute_rates(c.ps, c.prm);
        return c;
    };
    const double top = everywhere.prm.domain.zmax, reach = 0.5 * top, h = everywhere.prm.numerics.h;
    const Column jet = along(reach);
    int near = 0, far = 0, between = 0;
    for (std::size_t q = 0; q < jet.ps.ar.size(); ++q) {
        const double dist = top - jet.ps.z[q];
        if (dist < reach - 2 * h) {
            ASSERT_EQ(jet.ps.ar[q], everywhere.ps.ar[q]) << q;
            ++near;
        } else if (dist > reach) {
            ASSERT_EQ(jet.ps.ar[q], plain.ps.ar[q]) << q;
            ++far;
        } else {
            const double lo = std::min(everywhere.ps.ar[q], plain.ps.ar[q]);
            const double hi = std::max(everywhere.ps.ar[q], plain.ps.ar[q]);
            EXPECT_GE(jet.ps.ar[q], lo - 1e-12 * std::abs(lo)) << q;
            EXPECT_LE(jet.ps.ar[q], hi + 1e-12 * std::abs(hi)) << q;
            ++between;
        }
    }
    EXPECT_GT(near, 0);
    EXPECT_GT(far, 0);
    EXPECT_GT(between, 0);
    // and the key does act on this column (else the test would see nothing)
    double most = 0;
    for (std::size_t q = 0; q < plain.ps.ar.size(); ++q)
        most = std::max(most, std::abs(everywhere.ps.ar[q] - plain.ps.ar[q]));
    EXPECT_GT(most, 0.05 * kRho0);
}
