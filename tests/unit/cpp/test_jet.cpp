// The jets: the nozzle's layout, the generator's nozzle, and the jet monitor on synthetic
// particle sets whose answers are known by construction: a plug moved rigidly gives the
// orifice flux u0 d0 exactly (the gradual crossing count is linear in time for rows ds
// apart); a column with one gap of known size gives its breakup length; a row of square
// drops gives their count and equivalent diameters (d = 2 sqrt(A / pi) to round-off); eq 37
// gives the paper's Table 1 values to the 2 decimals it prints.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/jet_monitor.hpp"
#include "config/modern_case.hpp"
#include "geometry/generator.hpp"
#include "geometry/nozzle.hpp"
#include "model/case_spec.hpp"

using namespace sphjet;
using namespace sphjet::analysis;

namespace {

NozzleSpec down_nozzle(double d0 = 0.01, double u0 = 0.25) {
    NozzleSpec nz;
    nz.x0 = 0.04, nz.z0 = 0.4, nz.ex = 0, nz.ez = -1, nz.d0 = d0, nz.length_over_d0 = 15, nz.u0 = u0;
    return nz;
}

TEST(NozzleLayout, PlugFillsTheChannelSymmetrically) {
    const NozzleSpec nz = down_nozzle();
    const NozzleLayout lay = nozzle_layout(nz, 0.001, 0.001, false, 0.0026);
    ASSERT_EQ(lay.fluid.size(), 10u * 150u);  // 10 across, 150 along
    double xmin = 1, xmax = 0, zmax = 0, zmin = 1;
    for (const auto& q : lay.fluid) {
        xmin = std::min(xmin, q.x), xmax = std::max(xmax, q.x);
        zmin = std::min(zmin, q.z), zmax = std::max(zmax, q.z);
    }
    EXPECT_NEAR(xmin, 0.04 - 0.0045, 1e-12);  // half a spacing inside the orifice edges
    EXPECT_NEAR(xmax, 0.04 + 0.0045, 1e-12);
    EXPECT_NEAR(zmax, 0.4 + 0.15 - 0.0005, 1e-12);
    EXPECT_NEAR(zmin, 0.4 + 0.0005, 1e-12);  // upstream of the orifice line
    // Repulsive walls: one line per side, one spacing outside the outer rows, ending
    // ceil(2h / ds) = 3 spacings upstream of the orifice; the +l side (l = CCW(e) = +x for a
    // jet going down) is linked reversed so that its normal faces the plug.
    ASSERT_EQ(lay.walls.size(), 2u);
    for (const auto& w : lay.walls) {
        ASSERT_EQ(w.points.size(), 150u - 3u + 1u);
        EXPECT_NEAR(std::abs(w.points.front().x - 0.04), 0.0055, 1e-12);
        EXPECT_NEAR(w.points.back().z, 0.403, 1e-12);
        EXPECT_EQ(w.reversed, w.points.front().x > 0.04);
    }
    // Dynamic boundaries: a staggered second layer per side.
    EXPECT_EQ(nozzle_layout(nz, 0.001, 0.001, true, 0.0026).walls.size(), 4u);
    NozzleSpec bare = nz;
    bare.walls = false;
    EXPECT_TRUE(nozzle_layout(bare, 0.001, 0.001, false, 0.0026).walls.empty());
}

TEST(NozzleGenerator, PlugMovesAtU0AndWeighsItsVolume) {
    const CaseSpec spec = parse_modern_case(R"([numerics]
boundary = "repulsive"
lattice = "sc"
[fluid]
c0 = 20.0
[gravity]
gz = 0.0
[nozzle]
x0 = 0.04
z0 = 0.41
d0 = 0.01
u0 = 0.17
[domain]
lx = 0.08
lz = 0.57
wall_left = false
wall_right = false
wall_bottom = false
[resolution]
dx = 0.001
h_over_dx = 1.3
)",
                                            "jet.toml");
    const InitialState init = generate(spec);
    const ParticleSet& ps = init.particles;
    ASSERT_EQ(ps.n_fluid(), 1500u);
    double mass = 0;
    for (std::size_t i = ps.nb; i < ps.size(); ++i) {
        EXPECT_EQ(ps.u[i], 0.0);
        EXPECT_EQ(ps.w[i], -0.17);
        mass += ps.m[i];
    }
    EXPECT_NEAR(mass, 1000.0 * 0.01 * 0.15, 1e-12);
    EXPECT_EQ(ps.wall.size(), ps.nb);  // links for every wall particle
}

// A rigid plug of rows ds apart moved through the orifice line: the volume out grows by
// u0 d0 per second whatever the phase of the rows.
TEST(JetMonitor, FluxOfARigidPlugIsU0D0) {
    const NozzleSpec nz = down_nozzle();
    const double ds = 0.001, dl = 0.001, u0 = nz.u0;
    ParticleSet ps;
    for (int k = 0; k < 40; ++k)
        for (int j = 0; j < 10; ++j)
            ps.push(0.04 - 0.0045 + j * dl, 0.4 + (k + 0.5) * ds, 0, -u0, 1000, 0, 1000 * dl * ds, ParticleKind::Fluid);
    JetMonitor mon(nz, BreakupSpec{}, 0.0013, 1000.0, ds);
    mon.start(ps, 0.0);
    for (int s = 1; s <= 30; ++s) {
        const double dt = 0.0013;  // not a multiple of ds / u0 = 0.004 s
        for (std::size_t i = 0; i < ps.size(); ++i) ps.z[i] -= u0 * dt;
        const JetSample r = mon.sample(ps, s * dt, s);
        EXPECT_NEAR(r.u_flux, u0, 1e-9) << "sample " << s;
        EXPECT_NEAR(r.volume_out, u0 * nz.d0 * s * dt, 1e-12);
    }
}

// A jet column from the orifice down to s = 0.05 m, a gap of 3 h, then a square drop and,
// further, a second one: L = 0.05 m, two drops, the head drop the farthest one.
TEST(JetMonitor, BreakupLengthAndDrops) {
    const NozzleSpec nz = down_nozzle();
    const double dx = 0.001, h = 0.0013, rho = 1000, m = rho * dx * dx;
    ParticleSet ps;
    ps.push(0.0, 0.0, 0, 0, rho, 0, m, ParticleKind::FixedBoundary);  // a wall particle: ignored
    ps.nb = ps.nbf = 1;
    const auto column = [&](double s0, double s1, int across) {
        for (double s = s0; s <= s1 + 1e-12; s += dx)
            for (int j = 0; j < across; ++j)
                ps.push(0.04 + (j - 0.5 * (across - 1)) * dx, 0.4 - s, 0, -0.3, rho, 0, m, ParticleKind::Fluid);
    };
    column(0.0005, 0.0495, 6);          // the jet: s up to 0.0495
    column(0.0495 + 3 * h, 0.0495 + 3 * h + 0.004, 5);  // a drop of 5 x 5 particles
    column(0.09, 0.092, 3);             // a drop of 3 x 3, farthest
    JetMonitor mon(nz, BreakupSpec{}, h, rho, dx);
    mon.start(ps, 0.0);
    const JetSample r = mon.sample(ps, 0.1, 10);
    ASSERT_TRUE(r.length);
    EXPECT_NEAR(*r.length, 0.0495, 1e-12);
    EXPECT_NEAR(r.jet_tip, 0.0495, 1e-12);
    ASSERT_EQ(r.drops.size(), 2u);
    EXPECT_EQ(r.drops[0].particles, 9u);   // the head drop
    EXPECT_EQ(r.drops[1].particles, 25u);
    EXPECT_NEAR(r.drops[0].d_eq, 2 * std::sqrt(9 * dx * dx / std::numbers::pi), 1e-12);
    EXPECT_NEAR(r.drops[1].d_eq, 2 * std::sqrt(25 * dx * dx / std::numbers::pi), 1e-12);
    EXPECT_NEAR(r.drops[0].s_max, 0.092, 1e-12);

    // Closing the gap to 1.4 h (< 1.5 h) joins the first drop to the jet.
    ParticleSet joined;
    joined.push(0.0, 0.0, 0, 0, rho, 0, m, ParticleKind::FixedBoundary);
    joined.nb = joined.nbf = 1;
    std::swap(ps, joined);
    column(0.0005, 0.0495, 6);
    column(0.0495 + 1.4 * h, 0.0495 + 1.4 * h + 0.004, 5);
    JetMonitor mon2(nz, BreakupSpec{}, h, rho, dx);
    mon2.start(ps, 0.0);
    const JetSample r2 = mon2.sample(ps, 0.1, 10);
    EXPECT_FALSE(r2.length);
    EXPECT_TRUE(r2.drops.empty());
    EXPECT_NEAR(r2.jet_tip, 0.0495 + 1.4 * h + 0.004, 1e-12);
}

// A drop beside the axis (beyond the band) breaks nothing on the axis but is a drop.
TEST(JetMonitor, DropsOffTheAxisAreDropsNotBreakup) {
    const NozzleSpec nz = down_nozzle();
    const double dx = 0.001, h = 0.0013, rho = 1000, m = rho * dx * dx;
    ParticleSet ps;
    for (double s = 0.0005; s <= 0.03; s += dx)
        for (int j = 0; j < 4; ++j) ps.push(0.04 + (j - 1.5) * dx, 0.4 - s, 0, 0, rho, 0, m, ParticleKind::Fluid);
    ps.push(0.04 + 0.02, 0.4 - 0.01, 0, 0, rho, 0, m, ParticleKind::Fluid);  // 2 d0 to the side
    JetMonitor mon(nz, BreakupSpec{}, h, rho, dx);
    mon.start(ps, 0.0);
    const JetSample r = mon.sample(ps, 0.1, 1);
    EXPECT_FALSE(r.length);
    EXPECT_EQ(r.drops.size(), 1u);
}

// A round nozzle (axisymmetric): rings on the side r = x >= 0 only at r = (j + 1/2) dl, so that
// rings of 2 pi r dl ds make a volume pi d0^2 / 4 x length; one wall line, at r = d0/2 + dl/2.
TEST(NozzleLayout, RoundPipeHasRingsOnOneSide) {
    NozzleSpec nz = down_nozzle();
    nz.x0 = 0.0;
    const NozzleLayout lay = nozzle_layout(nz, 0.001, 0.001, false, 0.0026, true);
    ASSERT_EQ(lay.fluid.size(), 5u * 150u);  // 5 rings across the radius, 150 rows
    double vol = 0, xmin = 1, xmax = -1;
    for (const auto& q : lay.fluid) {
        vol += 2 * std::numbers::pi * q.x * lay.spacing_across * lay.spacing_along;
        xmin = std::min(xmin, q.x), xmax = std::max(xmax, q.x);
    }
    EXPECT_NEAR(xmin, 0.0005, 1e-12);
    EXPECT_NEAR(xmax, 0.0045, 1e-12);
    EXPECT_NEAR(vol, std::numbers::pi * 0.25 * 0.01 * 0.01 * 0.15, 1e-12 * vol);  // exact: sum of (2j+1) = N^2
    ASSERT_EQ(lay.walls.size(), 1u);
    EXPECT_NEAR(lay.walls[0].points.front().x, 0.0055, 1e-12);
    EXPECT_TRUE(lay.walls[0].reversed);  // its normal faces the plug (-x)
    EXPECT_EQ(nozzle_layout(nz, 0.001, 0.001, true, 0.0026, true).walls.size(), 2u);  // dynamic: two layers
    // Going up, the rings still stand at x >= 0.
    nz.ez = 1.0;
    for (const auto& q : nozzle_layout(nz, 0.001, 0.001, false, 0.0026, true).fluid) EXPECT_GT(q.x, 0.0);
    nz.x0 = 0.01;  // off the axis: refused
    EXPECT_THROW((void)nozzle_layout(nz, 0.001, 0.001, false, 0.0026, true), std::invalid_argument);
}

// nozzle.column_over_d0: the plug's lattice continued past the orifice, the column's rows at
// s = (k + 1/2) ds after the plug's; the generator gives them the plug's velocity and density.
TEST(NozzleLayout, StartingColumnContinuesThePlugsLattice) {
    NozzleSpec nz = down_nozzle();
    nz.x0 = 0.0;
    nz.column_over_d0 = 2.5;  // 25 rows of 5 rings at ds = 1 mm
    const NozzleLayout lay = nozzle_layout(nz, 0.001, 0.001, false, 0.0026, true);
    ASSERT_EQ(lay.fluid.size(), 5u * (150u + 25u));
    for (std::size_t i = 0; i < lay.fluid.size(); ++i) {
        const std::size_t row = i / 5, ring = i % 5;
        const double s = row < 150 ? -(static_cast<double>(row) + 0.5) * 0.001
                                   : (static_cast<double>(row - 150) + 0.5) * 0.001;
        EXPECT_NEAR(lay.fluid[i].z, nz.z0 - s, 1e-12);  // down: s = z0 - z
        EXPECT_NEAR(lay.fluid[i].x, (static_cast<double>(ring) + 0.5) * 0.001, 1e-12);
    }
}

TEST(NozzleGenerator, StartingColumnMovesWithThePlug) {
    const CaseSpec spec = parse_modern_case(R"([numerics]
lattice = "sc"
[domain]
geometry = "axisymmetric"
lx = 0.004
lz = 0.03
wall_left = false
wall_right = false
wall_bottom = false
wall_top = false
[fluid]
c0 = 12.0
[surface_tension]
sigma = 0.072
[gravity]
gz = 0.0
[nozzle]
x0 = 0.0
z0 = 0.025
d0 = 0.002
length_over_d0 = 1
column_over_d0 = 3
u0 = 0.8
walls = false
[resolution]
dx = 0.0002
h_over_dx = 2.0
)",
                                            "column.toml");
    const InitialState init = generate(spec);
    const ParticleSet& ps = init.particles;
    ASSERT_EQ(ps.n_fluid(), 5u * (10u + 30u));
    std::size_t out = 0;
    for (std::size_t i = ps.nb; i < ps.size(); ++i) {
        EXPECT_EQ(ps.u[i], 0.0);
        EXPECT_EQ(ps.w[i], -0.8);
        EXPECT_EQ(ps.rho[i], ps.rho[ps.nb]);  // the plug's density (the Laplace pressure's)
        if (ps.z[i] < 0.025) ++out;
    }
    EXPECT_EQ(out, 5u * 30u);
    EXPECT_GT(ps.p[ps.nb], 0.0);
}

// The refill tests' round nozzle: d0 = 2 mm, 2 d0 long (20 rows of 5 rings at ds = dl = 0.2 mm),
// water at c0 = 16 m/s with surface tension.
struct RoundRefillCase {
    NozzleSpec nz;
    SimParams prm;
};
RoundRefillCase round_refill_case() {
    RoundRefillCase c{down_nozzle(0.002), {}};
    c.nz.x0 = 0.0;
    c.nz.length_over_d0 = 2;
    c.prm.geometry = Geometry::Axisymmetric;
    c.prm.rho0 = 1000, c.prm.gamma = 7, c.prm.B = 1000 * 16.0 * 16.0 / 7, c.prm.sigma = 0.072;
    return c;
}

// nozzle.refill: once the plug has moved one spacing, one row enters at its back: the back
// row's positions one spacing upstream, its velocities and masses, at the plug's built density
// and pressure (plug_state: the round jet's Laplace pressure 2 sigma / d0), not the back row's,
// which fluid passing beside the plug can have changed.
TEST(NozzleRefill, NewRowsCopyTheBackRowAtTheBuiltDensity) {
    const auto [nz, prm] = round_refill_case();
    const PlugState built = plug_state(prm, nz);
    const double p_lap = 2 * 0.072 / 0.002;
    EXPECT_NEAR(built.p, p_lap, 1e-9 * p_lap);
    EXPECT_NEAR(prm.B * (std::pow(built.rho / prm.rho0, prm.gamma) - 1), p_lap, 1e-9 * p_lap);
    SimParams sheet = prm;
    sheet.geometry = Geometry::Planar;
    EXPECT_EQ(plug_state(sheet, nz).rho, 1000.0);
    EXPECT_EQ(plug_state(sheet, nz).p, 0.0);

    const double ds = 0.0002, u0 = nz.u0;
    const NozzleLayout lay = nozzle_layout(nz, ds, ds, false, 0.0, true);
    ParticleSet ps;
    for (const NozzlePoint& q : lay.fluid)
        ps.push(q.x, q.z, 0, -u0, built.rho, built.p, 1e-6 * q.x, ParticleKind::Fluid);
    EXPECT_EQ(nozzle_refill_rows(nz, ds, ds, 0.0011, built, ps).size(), 0u);  // nothing due yet
    for (std::size_t i = 0; i < ps.size(); ++i) {
        ps.z[i] -= ds;                                     // the plug has moved one spacing
        if (ps.z[i] > nz.z0 + 18 * ds) ps.rho[i] = 990, ps.p[i] = -2000;  // the back row, disturbed
    }
    const ParticleSet rows = nozzle_refill_rows(nz, ds, ds, 0.0011, built, ps);
    ASSERT_EQ(rows.size(), 5u);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        EXPECT_NEAR(rows.z[i], nz.z0 + 19.5 * ds, 1e-12);  // where the back row was built
        EXPECT_NEAR(rows.x[i], (static_cast<double>(i) + 0.5) * ds, 1e-12);
        EXPECT_EQ(rows.w[i], -u0);
        EXPECT_NEAR(rows.m[i], 1e-6 * rows.x[i], 1e-18);
        EXPECT_EQ(rows.rho[i], built.rho);
        EXPECT_EQ(rows.p[i], built.p);
    }
}

// nozzle.profile = "parabolic": k makes the lattice's flux the plug's. On 5 rings at r/a = 0.1,
// 0.3, .., 0.9, sum r = 2.5 and sum r (1 - r^2) = 1.275 (k = 1.9608); on a sheet's 10 rows at
// l/a = +-0.1, .., +-0.9, sum 1 = 10 and sum (1 - l^2) = 6.7 (k = 1.4925). Continuous: 2 and 1.5.
TEST(NozzleProfile, ParabolicKeepsTheLatticesFlux) {
    NozzleSpec nz = down_nozzle(0.002);
    nz.x0 = 0.0;
    EXPECT_NEAR(nozzle_profile_k(nz, 0.0002, 0.0002, true), 2.5 / 1.275, 1e-12);
    nz.x0 = 0.01;
    EXPECT_NEAR(nozzle_profile_k(nz, 0.0002, 0.0002, false), 10.0 / 6.7, 1e-12);
}

// With a parabolic profile each line of the plug moves at its own speed, so each line refills
// on its own: the lines that moved a spacing get one particle at the built position, the
// others none; a ring of fluid that came back into the strip near the orifice is not a line.
TEST(NozzleRefill, EachLineRefillsOnItsOwn) {
    const auto [nz, prm] = round_refill_case();
    const PlugState built = plug_state(prm, nz);
    const double ds = 0.0002;
    const NozzleLayout lay = nozzle_layout(nz, ds, ds, false, 0.0, true);
    ParticleSet ps;
    for (const NozzlePoint& q : lay.fluid) ps.push(q.x, q.z, 0, -1, built.rho, built.p, 1, ParticleKind::Fluid);
    // the two inner lines have moved 1.3 and 1.0 spacings, the three outer 0.6
    for (std::size_t i = 0; i < ps.size(); ++i) ps.z[i] -= (ps.x[i] < ds ? 1.3 : ps.x[i] < 2 * ds ? 1.0 : 0.6) * ds;
    ps.push(1.0 * ds, nz.z0 + 0.2 * ds, 0, 0.3, 990, 0, 1, ParticleKind::Fluid);  // back into the strip, between lines
    const ParticleSet rows = nozzle_refill_rows(nz, ds, ds, 0.0011, built, ps);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_NEAR(rows.x[0], 0.5 * ds, 1e-12);
    EXPECT_NEAR(rows.z[0], nz.z0 + 19.2 * ds, 1e-12);  // 19.5 - 1.3 + 1
    EXPECT_NEAR(rows.x[1], 1.5 * ds, 1e-12);
    EXPECT_NEAR(rows.z[1], nz.z0 + 19.5 * ds, 1e-12);
}

// A round jet: a rigid plug of rings gives u_flux = u0 (flux over pi d0^2 / 4); a sphere-sized
// cluster of rings gives the diameter of the sphere of its volume; the neck is the thinnest
// slice of the jet, not its rounded tip.
TEST(JetMonitor, RoundJetFluxDropsAndNeck) {
    NozzleSpec nz = down_nozzle();
    nz.x0 = 0.0;
    const double ds = 0.001, dl = 0.001, rho = 1000, h = 0.002, u0 = nz.u0;
    const auto ring = [&](ParticleSet& ps, double r, double z, double w) {
        ps.push(r, z, 0, w, rho, 0, rho * 2 * std::numbers::pi * r * dl * ds, ParticleKind::Fluid);
    };
    ParticleSet plug;
    for (int k = 0; k < 40; ++k)
        for (int j = 0; j < 5; ++j) ring(plug, (j + 0.5) * dl, 0.4 + (k + 0.5) * ds, -u0);
    JetMonitor mon(nz, BreakupSpec{}, h, rho, ds, true);
    EXPECT_TRUE(mon.round());
    mon.start(plug, 0.0);
    for (int s = 1; s <= 20; ++s) {
        for (std::size_t i = 0; i < plug.size(); ++i) plug.z[i] -= u0 * 0.0013;
        const JetSample r = mon.sample(plug, s * 0.0013, s);
        EXPECT_NEAR(r.u_flux, u0, 1e-9) << "sample " << s;
    }

    // A jet 0.04 m long, 5 rings thick but 2 rings thick between s = 0.02 and 0.025 (the
    // neck, radius 1.5 dl + dl/2), 1 ring in its last 0.005 (the tip: not the neck); a gap of
    // 4 h; a drop of 12 x 6 rings (a short cylinder); far on, a small drop of 1 ring.
    ParticleSet ps;
    for (double s = 0.0005; s < 0.04; s += ds) {
        const int rings = s > 0.035 ? 1 : (s > 0.02 && s < 0.025) ? 2 : 5;
        for (int j = 0; j < rings; ++j) ring(ps, (j + 0.5) * dl, 0.4 - s, -u0);
    }
    double vol = 0;
    for (int k = 0; k < 12; ++k)
        for (int j = 0; j < 6; ++j) {
            ring(ps, (j + 0.5) * dl, 0.4 - (0.0395 + 4 * h + k * ds), -u0);
            vol += 2 * std::numbers::pi * (j + 0.5) * dl * dl * ds;
        }
    ring(ps, 0.5 * dl, 0.4 - 0.09, -u0);
    JetMonitor mon2(nz, BreakupSpec{}, h, rho, ds, true);
    mon2.start(ps, 0.0);
    const JetSample r = mon2.sample(ps, 0.1, 1);
    ASSERT_TRUE(r.length);
    EXPECT_NEAR(*r.length, 0.0395, 1e-12);
    ASSERT_EQ(r.drops.size(), 2u);
    EXPECT_NEAR(r.drops[1].size, vol, 1e-15);
    EXPECT_NEAR(r.drops[1].d_eq, std::cbrt(6 * vol / std::numbers::pi), 1e-12);
    EXPECT_NEAR(r.drops[1].xc, 0.0, 0.0);  // on the axis
    EXPECT_FALSE(r.drops[1].satellite);     // 13.7 mm > d0
    EXPECT_TRUE(r.drops[0].satellite);      // one ring: 2.7 mm < d0
    ASSERT_TRUE(r.neck_r && r.neck_s);
    EXPECT_NEAR(*r.neck_r, 2 * dl, 1e-12);
    EXPECT_GT(*r.neck_s, 0.02);
    EXPECT_LT(*r.neck_s, 0.025);
    const std::string row = jet_csv_row(r, nz.d0);
    EXPECT_NE(row.find(",1,0.2,"), std::string::npos) << row;  // 1 satellite, neck r / d0 = 0.2
}

// The disturbance record of a round jet: a column of 5 rings whose surface ring sits at
// r_s(s) = a + A sin(k s) (the other rings on the lattice) gives that radius, plus half a
// spacing, in the surface profile (the line through the outer rings; to round-off), and the exit noise is the
// mean and spread of the pressures put within 2 d0 of the orifice (alternating p0 +- dp:
// mean p0, standard deviation dp) and the rms of the radial velocities there.
TEST(JetMonitor, RoundJetSurfaceProfileAndExitNoise) {
    NozzleSpec nz = down_nozzle();
    nz.x0 = 0.0;
    const double ds = 0.001, dl = 0.001, rho = 1000, h = 0.002, u0 = nz.u0;
    const double amp = 0.1 * dl, k = 2 * std::numbers::pi / 0.009, p0 = 120, dp = 30, ur = 0.01;
    ParticleSet ps;
    int n = 0;
    for (double s = 0.0005; s < 0.05; s += ds, ++n) {
        for (int j = 0; j < (n == 25 ? 4 : 5); ++j) {
            const double r = (j + 0.5) * dl + (j == 4 ? amp * std::sin(k * s) : 0.0);
            const double p = s < 2 * nz.d0 ? p0 + (n % 2 ? dp : -dp) : 0.0;
            const double u = s < 2 * nz.d0 ? (j % 2 ? ur : -ur) : 0.0;
            ps.push(r, 0.4 - s, u, -u0, rho, p, rho * 2 * std::numbers::pi * r * dl * ds, ParticleKind::Fluid);
        }
    }
    JetMonitor mon(nz, BreakupSpec{}, h, rho, ds, true);
    mon.start(ps, 0.0);
    const JetSample r = mon.sample(ps, 0.1, 7);
    ASSERT_FALSE(r.length);
    // the profile runs to one d0 short of the tip (0.0495 - 0.01)
    ASSERT_EQ(r.surface.size(), 40u);
    // slice i reads the outer ring of row i (row n has s = (n + 1/2) ds, the slice's centre);
    // row 25, built without its outer ring (a stretched row: that slice holds no outer ring),
    // reads the line through its neighbours' outer rings; the neck is the thinnest single
    // slice: row 25, one ring short
    const auto outer = [&](int n) { return 4.5 * dl + amp * std::sin(k * (n + 0.5) * ds); };
    for (int i = 0; i < static_cast<int>(r.surface.size()); ++i) {
        const double want = i == 25 ? 0.5 * (outer(24) + outer(26)) : outer(i);
        EXPECT_NEAR(r.surface[static_cast<std::size_t>(i)], want + 0.5 * ds, 1e-12) << "slice " << i;
    }
    ASSERT_TRUE(r.neck_r);
    EXPECT_NEAR(*r.neck_r, 4.0 * dl, 1e-12);
    // 20 rows of 5 rings within 2 d0 = 0.02 m, alternating +- dp by row
    EXPECT_EQ(r.exit_n, 100u);
    EXPECT_NEAR(r.exit_p_mean, p0, 1e-9);
    EXPECT_NEAR(r.exit_p_std, dp, 1e-9);
    EXPECT_NEAR(r.exit_ul_rms, ur, 1e-12);
    const std::string rows = surface_csv_rows(r, nz.d0, ds);
    EXPECT_EQ(std::count(rows.begin(), rows.end(), '\n'), 40);
    EXPECT_EQ(rows.rfind("0.1,7,0.05,", 0), 0u) << rows.substr(0, 40);
    const std::string row = jet_csv_row(r, nz.d0);
    EXPECT_NE(row.find(",100,120,30,0.01"), std::string::npos) << row;
}

// A tapering jet (a falling one thins as it speeds up): rows 1.37 slice widths apart, each of
// 5 rings whose outer ring sits at r = a (1 - s / (40 d0)). The surface profile is that straight
// line at every slice centre, plus half a spacing, to round-off. The largest ring over a slice
// and its neighbours (this profile's former rule) reads the taper of up to 1.5 slice widths
// above the line (here 3.7e-3 of the radius), changing as the rows move through the slices,
// and a disturbance envelope read that as noise.
TEST(JetMonitor, TaperingJetSurfaceProfileIsTheLine) {
    NozzleSpec nz = down_nozzle();
    nz.x0 = 0.0;
    const double ds = 0.001, dl = 0.001, dz = 1.37 * ds, rho = 1000, h = 0.002;
    const auto outer = [&](double s) { return 4.5 * dl * (1.0 - s / (40.0 * nz.d0)); };
    ParticleSet ps;
    for (double s = 0.3 * dz; s < 0.06; s += dz)
        for (int j = 0; j < 5; ++j) {
            const double r = j == 4 ? outer(s) : (j + 0.5) * dl * outer(s) / (4.5 * dl);
            ps.push(r, 0.4 - s, 0.0, -nz.u0, rho, 0.0, rho * 2 * std::numbers::pi * r * dl * dz, ParticleKind::Fluid);
        }
    JetMonitor mon(nz, BreakupSpec{}, h, rho, ds, true);
    mon.start(ps, 0.0);
    const JetSample r = mon.sample(ps, 0.1, 7);
    ASSERT_GT(r.surface.size(), 40u);
    // the rows the profile takes: up to one d0 short of the tip
    double first = 0.3 * dz, last = first, tip = first;
    for (double s = first; s < 0.06; s += dz) tip = s;
    for (double s = first; s <= tip - nz.d0; s += dz) last = s;
    double stepped = 0;
    for (std::size_t i = 0; i < r.surface.size(); ++i) {
        const double c = (static_cast<double>(i) + 0.5) * ds;
        if (c < first || c > last) continue;  // beyond the end rows the profile holds their rings
        EXPECT_NEAR(r.surface[i], outer(c) + 0.5 * ds, 1e-12) << "slice " << i;
        // the former rule: the largest outer ring over slices i - 1 ... i + 1
        double widest = 0;
        for (double s = 0.3 * dz; s < 0.06; s += dz)
            if (s >= (static_cast<double>(i) - 1) * ds && s < (static_cast<double>(i) + 2) * ds) widest = std::max(widest, outer(s));
        stepped = std::max(stepped, std::abs(widest - outer(c)));
    }
    EXPECT_GT(stepped, 1.4 * 4.5 * dl * ds / (40.0 * nz.d0));  // the former rule: 1.5 slices' taper (1.499 here)
}

TEST(JetGroups, Eq37ReproducesTable1) {
    // Table 1 (paper): We 0.34 / 2.01 / 2.78 / 4.34, eq 37 7.62 / 18.51 / 21.78 / 27.22.
    const double u0s[] = {0.07, 0.17, 0.20, 0.25};
    const double we[] = {0.34, 2.01, 2.78, 4.34};
    const double eq37[] = {7.62, 18.51, 21.78, 27.22};
    for (int k = 0; k < 4; ++k) {
        const JetGroups g = jet_groups(1000, u0s[k], 0.01, 0.072, 1e-3, 9.81);
        EXPECT_NEAR(g.we, we[k], 0.005 + 1e-9) << u0s[k];  // the paper prints 2 decimals
        EXPECT_NEAR(g.eq37, eq37[k], 0.005 + 1e-9) << u0s[k];
        EXPECT_NEAR(g.re, 1000 * u0s[k] * 0.005 / 1e-3, 1e-9);
    }
    EXPECT_EQ(jet_groups(1000, 0.25, 0.01, 0.072, 0.0, 9.81).oh, 0.0);  // inviscid: Oh = 0
    // The diameter groups: We_d = 2 We, Oh_d = Oh / sqrt 2 (Mansour & Chigier's slowest jet:
    // U = 0.3441 m/s, d0 = 1.194 mm, water: We_d = 1000 0.3441^2 0.001194 / 0.072 = 1.96).
    const JetGroups g = jet_groups(1000, 0.3441, 0.001194, 0.072, 1e-3, 9.81);
    EXPECT_NEAR(g.we_d, 1000 * 0.3441 * 0.3441 * 0.001194 / 0.072, 1e-12);
    EXPECT_NEAR(g.oh_d, 1e-3 / std::sqrt(1000 * 0.072 * 0.001194), 1e-12);
    EXPECT_NEAR(g.eq37_d, 13 * std::sqrt(g.we_d) * (1 + 3 * g.oh_d), 1e-12);
}

}  // namespace
