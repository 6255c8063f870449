// From a checked tree to a CaseSpec (config/case_toml.hpp): the plain keys through their
// rows (model/case_params.hpp), the derived and cross-checked ones by hand, one function a
// section.
#include <algorithm>
#include <cmath>

#include "config/case_derived.hpp"
#include "config/case_toml.hpp"
#include "config/modern_case.hpp"
#include "geometry/nozzle.hpp"
#include "model/case_params.hpp"

namespace sphjet::casefile {

namespace {

void positive(const Field<double>& f) {
    if (!(f.value > 0)) fail(f, "must be positive", "a number > 0");
}
void non_negative(const Field<double>& f) {
    if (!(f.value >= 0)) fail(f, "must not be negative", "a number >= 0");
}

// "a number in [0, 1]", "an integer >= 1": what a range allows.
std::string range_expected(const Range& g, bool integer) {
    const std::string text = range_text(g);
    const std::string a = integer ? "an integer " : "a number ";
    return g.kind == Range::Kind::Between && g.hi < kNoLimit ? a + "in " + text : a + text;
}

template <class T>
void check_range(const Field<T>& f, const Range& g) {
    const double v = static_cast<double>(f.value);
    const bool integer = std::is_integral_v<T>;
    switch (g.kind) {
        case Range::Kind::Any: return;
        case Range::Kind::Positive:
            if (!(v > 0)) fail(f, "must be positive", range_expected(g, integer));
            return;
        case Range::Kind::NonNegative:
            if (!(v >= 0)) fail(f, "must not be negative", range_expected(g, integer));
            return;
        case Range::Kind::Between: {
            const bool above = g.lo_open ? v > g.lo : v >= g.lo;
            const bool below = g.hi >= kNoLimit || (g.hi_open ? v < g.hi : v <= g.hi);
            if (!(above && below)) fail(f, "out of range", range_expected(g, integer));
            return;
        }
    }
}

// Reads the keys of section s whose member lives in owner (a struct of type tag), as their
// rows say: type, range or choices, required; rows read by hand are left to the caller.
void read_members(const Section& s, void* owner, const void* tag) {
    for (const Param& r : case_params()) {
        if (r.key.empty() || section_of(r.key) != s.pattern() || r.member.owner != tag || (r.hand & kHandRead))
            continue;
        const std::string_view key = leaf_of(r.key);
        const Member& m = r.member;
        if (r.required && !s.has(key)) {
            std::string expected(r.doc);
            if (!r.unit.empty()) expected += " [" + std::string(r.unit) + "]";
            throw InputError(s.where(key), "missing required key", expected, "nothing");
        }
        switch (r.type) {
            case KeyType::Float:
                if (auto f = s.num(key)) check_range(*f, r.range), m.set_f(owner, f->value);
                break;
            case KeyType::Int:
                if (auto f = s.integer(key)) {
                    check_range(*f, r.range);
                    if (f->value > m.max_i)
                        fail(*f, "out of range", "an integer <= " + std::to_string(m.max_i));
                    m.set_i(owner, f->value);
                }
                break;
            case KeyType::Bool:
                if (auto f = s.boolean(key)) m.set_i(owner, f->value ? 1 : 0);
                break;
            case KeyType::String:
                if (auto f = s.string(key)) m.set_i(owner, choose_from<std::int64_t>(*f, r.choices));
                break;
        }
    }
}

template <class S>
void read_members(const Section& s, S& owner) {
    read_members(s, &owner, &owner_tag<S>);
}

struct Box {
    double lx, lz;
};

// A coordinate of a region must lie in [0, L] (with a tolerance for round-off).
void inside(const Field<double>& f, double L, const char* axis, const char* what) {
    const double tol = 1e-9 * std::max(L, 1.0);
    if (f.value < -tol || f.value > L + tol)
        fail(f, std::string(what) + " outside the box",
             std::string(axis) + " in [0, " + num(L) + "] (domain." + (axis[0] == 'x' ? "lx" : "lz") + ")");
}

Rect read_rect(const Section& s, const Box& box, const char* what) {
    const auto xmin = s.required_num("xmin", "the left edge [m]");
    const auto xmax = s.required_num("xmax", "the right edge [m]");
    const auto zmin = s.required_num("zmin", "the bottom edge [m]");
    const auto zmax = s.required_num("zmax", "the top edge [m]");
    if (!(xmax.value > xmin.value)) fail(xmax, "empty region", "xmax > xmin = " + num(xmin.value));
    if (!(zmax.value > zmin.value)) fail(zmax, "empty region", "zmax > zmin = " + num(zmin.value));
    inside(xmin, box.lx, "x", what);
    inside(xmax, box.lx, "x", what);
    inside(zmin, box.lz, "z", what);
    inside(zmax, box.lz, "z", what);
    return {xmin.value, xmax.value, zmin.value, zmax.value};
}

// Centre +- half extent must lie inside the box.
void centred_inside(const Field<double>& xc, const Field<double>& zc, const Field<double>& size,
                    double half, const Box& box, const char* what) {
    const double tol = 1e-9 * std::max({box.lx, box.lz, 1.0});
    if (xc.value - half < -tol || xc.value + half > box.lx + tol)
        fail(xc, std::string(what) + " outside the box",
             "xc - " + num(half) + " >= 0 and xc + " + num(half) + " <= domain.lx = " + num(box.lx));
    if (zc.value - half < -tol || zc.value + half > box.lz + tol)
        fail(zc, std::string(what) + " outside the box",
             "zc - " + num(half) + " >= 0 and zc + " + num(half) + " <= domain.lz = " + num(box.lz));
    (void)size;
}

// [legacy]: read first, single_precision changes how B and h are derived.
struct LegacyRead {
    bool single = false;
    std::optional<Field<double>> h_coef;
};

LegacyRead read_legacy(const Section& top, CaseSpec& spec) {
    const Section leg = top.sub("legacy");
    read_members(leg, spec);
    read_members(leg, spec.legacy);
    LegacyRead out;
    leg.get("single_precision", out.single);
    out.h_coef = leg.num("h_coefficient");
    if (out.h_coef) positive(*out.h_coef), spec.legacy.h_coefficient = out.h_coef->value;
    return out;
}

// [fluid]: the equation of state, B from c0 or from coef and h_swl.
void read_sound_speed(const Ctx& ctx, const Section& fluid, SimParams& p, bool single) {
    const auto c0 = fluid.num("c0");
    const auto coef = fluid.num("coef");
    const auto h_swl = fluid.num("h_swl");
    if (c0) {
        if (coef || h_swl)
            fail(*c0, "give the sound speed either as c0 or through coef and h_swl, not both",
                 "fluid.c0 alone, or fluid.coef with fluid.h_swl");
        positive(*c0);
        p.h_swl = 0;  // marks "c0 given directly"; coef is then unused
        p.B = tait_B_from_c0(p.rho0, c0->value, p.gamma);
    } else if (coef || h_swl) {
        if (!coef)
            throw InputError(ctx.where(fluid.key_path("coef")), "missing required key",
                             "fluid.coef together with fluid.h_swl (c0 = coef sqrt(g h_swl))", "nothing");
        if (!h_swl)
            throw InputError(ctx.where(fluid.key_path("h_swl")), "missing required key",
                             "fluid.h_swl together with fluid.coef (c0 = coef sqrt(g h_swl))", "nothing");
        positive(*coef);
        positive(*h_swl);
        const double g = std::abs(p.gz);
        if (!(g > 0))
            fail(*coef, "coef and h_swl need gravity (c0 = coef sqrt(|gz| h_swl)) but gravity.gz = 0",
                 "fluid.c0 given directly when gz = 0");
        p.coef = coef->value;
        p.h_swl = h_swl->value;
        p.B = single ? tait_B_from_coef_single(p.coef, p.rho0, g, p.h_swl, p.gamma)
                     : tait_B_from_coef(p.coef, p.rho0, g, p.h_swl, p.gamma);
    } else {
        throw InputError(ctx.where(fluid.key_path("c0")), "missing required key",
                         "fluid.c0 [m/s], or fluid.coef with fluid.h_swl [m]", "nothing");
    }

    // B overflows (c0 = 1e200) or underflows (rho0 = 1e-300) for extreme inputs.
    if (!(std::isfinite(p.B) && p.B > 0))
        fail(c0 ? *c0 : *coef, "gives a Tait constant B that is not a finite number > 0 (B = " + num(p.B) + " Pa)",
             c0 ? "B = rho0 c0^2 / gamma finite and > 0" : "B = coef^2 rho0 |gz| h_swl / gamma finite and > 0");
}

// [resolution]: dx, dz and h given one of three ways.
void read_resolution(const Ctx& ctx, const Section& top, SimParams& p, LegacyRunInfo& info, const LegacyRead& leg) {
    const Section res = top.sub("resolution");
    const auto dx = res.required_num("dx", "the particle spacing in x [m]");
    positive(dx);
    p.dx = dx.value;
    p.dz = dx.value;
    if (auto f = res.num("dz")) positive(*f), p.dz = f->value;
    const auto h = res.num("h");
    const auto h_coef = res.num("h_coefficient");
    const auto h_over = res.num("h_over_dx");
    const int n_h = int(h.has_value()) + int(h_coef.has_value()) + int(h_over.has_value());
    if (n_h == 0)
        throw InputError(ctx.where(res.key_path("h")), "missing required key",
                         "one of resolution.h [m], resolution.h_coefficient, resolution.h_over_dx",
                         "nothing");
    if (n_h > 1) {
        const auto& f = h ? *h : *h_coef;
        fail(f, "give the smoothing length one way only",
             "exactly one of resolution.h, resolution.h_coefficient, resolution.h_over_dx");
    }
    if (h) positive(*h), p.h = h->value;
    if (h_coef) {
        positive(*h_coef);
        if (leg.h_coef)
            fail(*leg.h_coef, "the h coefficient is given twice",
                 "resolution.h_coefficient alone (legacy.h_coefficient only records it beside resolution.h)");
        p.h = h_from_coefficient(h_coef->value, p.dx, p.dz, leg.single);
        info.h_coefficient = h_coef->value;
    }
    if (h_over) positive(*h_over), p.h = h_over->value * p.dx;
    if (!(std::isfinite(p.h) && p.h > 0))  // h_over_dx = 1e300 with dx = 1, dx = 1e-200 (dx^2 = 0)
        fail(h ? *h : h_coef ? *h_coef : *h_over, "gives a smoothing length that is not a finite number > 0 (h = " +
                 num(p.h) + " m)", "h finite and > 0");
}

// Viscosity: numerics.alpha, fluid.nu or fluid.mu (at most one); needs h and c0.
void read_viscosity(const Ctx& ctx, const Section& num_s, const Section& fluid, SimParams& p) {
    const auto alpha = num_s.num("alpha");
    const auto nu = fluid.num("nu");
    const auto mu = fluid.num("mu");
    if (int(alpha.has_value()) + int(nu.has_value()) + int(mu.has_value()) > 1) {
        const auto& f = alpha ? *alpha : *nu;
        fail(f, "give the viscosity one way only",
             "one of numerics.alpha, fluid.nu [m^2/s], fluid.mu [Pa s]");
    }
    std::optional<double> nu_phys;
    if (nu) non_negative(*nu), nu_phys = nu->value;
    if (mu) non_negative(*mu), nu_phys = mu->value / p.rho0;
    if (p.viscosity == ViscosityModel::Artificial) {
        if (alpha) non_negative(*alpha), p.visc_value = alpha->value;
        if (nu_phys) p.visc_value = alpha_from_nu(*nu_phys, p.h, p.c0());
        if (nu_phys && !std::isfinite(p.visc_value))
            fail(nu ? *nu : *mu, "gives an artificial viscosity alpha = 8 nu / (h c0) that is not finite (alpha = " +
                     num(p.visc_value) + ")", "nu (or mu / rho0) with 8 nu / (h c0) finite");
        if (const auto extra = num_s.num("artificial_alpha"); extra && extra->value != 0)
            fail(*extra, "adds an artificial viscosity to the laminar one but numerics.viscosity is \"artificial\"",
                 "numerics.alpha for the artificial viscosity, or numerics.viscosity = \"laminar\"");
    } else {
        if (alpha)
            fail(*alpha, "alpha is the artificial-viscosity coefficient but numerics.viscosity is \"laminar\"",
                 "fluid.mu [Pa s] or fluid.nu [m^2/s]");
        if (!nu_phys)
            throw InputError(ctx.where(fluid.key_path("mu")), "missing required key",
                             "fluid.mu [Pa s] or fluid.nu [m^2/s] for laminar viscosity", "nothing");
        p.visc_value = *nu_phys;
        if (!std::isfinite(p.visc_value))  // mu / rho0 with rho0 = 1e-300
            fail(nu ? *nu : *mu, "gives a kinematic viscosity that is not finite (nu = " + num(p.visc_value) + ")",
                 "mu / rho0 finite");
    }
    if (const auto rec = num_s.boolean("artificial_reconstruction");
        rec && rec->value && p.viscosity == ViscosityModel::Laminar && p.artificial_alpha == 0)
        throw InputError(ctx.where(num_s.key_path("artificial_reconstruction")),
                         "reconstructs the artificial viscosity's velocity jump but no artificial viscosity is on",
                         "numerics.viscosity = \"artificial\", or numerics.artificial_alpha > 0 beside the laminar one",
                         "numerics.viscosity = \"laminar\" with numerics.artificial_alpha = 0");
}

// [domain], and the surface-tension key that depends on its pair.
void read_domain(const Ctx& ctx, const Section& top, CaseSpec& spec) {
    SimParams& p = spec.params;
    const Section dom = top.sub("domain");
    read_members(dom, p);
    read_members(dom, spec);
    if (auto f = dom.num("floor_inclination_deg")) {
        if (f->value != 0) fail(*f, "an inclined floor is not supported", "0");
        spec.floor_beta_deg = f->value;
    }
    const bool axi = p.geometry == Geometry::Axisymmetric;
    if (axi && spec.wall_left)
        throw InputError(ctx.where(dom.key_path("wall_left")),
                         "domain.geometry = \"axisymmetric\" has its symmetry axis at x = 0, not a wall",
                         "domain.wall_left = false", "true (the default)");
    // the meridian-plane diffusion is not the axisymmetric one: on the jets' column at rest it
    // moved the rows' densities by 1e-3 rho0 and the liquid at 0.027 m/s within 10 ms
    // (cases/round_jet/README.md)
    if (axi && p.density_diffusion > 0)
        throw InputError(ctx.where(top.sub("numerics").key_path("density_diffusion")),
                         "numerics.density_diffusion is the planar form (the axisymmetric one is not built)",
                         "numerics.density_diffusion = 0 with domain.geometry = \"axisymmetric\"",
                         num(p.density_diffusion));
    if (axi && p.lattice == Lattice::BodyCentred)
        throw InputError(ctx.where(top.sub("numerics").key_path("lattice")),
                         "domain.geometry = \"axisymmetric\" fills shapes on the lattice ((i + 1/2) dx, k dz)",
                         "numerics.lattice = \"sc\"", "\"bcc\" (the default)");
    if (p.periodic_z && (spec.wall_bottom || spec.wall_top))
        throw InputError(ctx.where(dom.key_path("periodic_z")),
                         "a domain periodic in z has no bottom or top wall",
                         "domain.wall_bottom = false and domain.wall_top = false with periodic_z = true",
                         spec.wall_bottom ? "wall_bottom = true (the default)" : "wall_top = true");
    if (p.periodic_z) p.domain_box = true;  // the box [0, lx] x [0, lz]; z in [0, lz) is the period
    const Param& pair_row = *find_param("domain.axis_pair");
    if (auto f = dom.string("axis_pair")) {
        if (!axi)
            throw InputError(ctx.where(dom.key_path("axis_pair")),
                             "domain.axis_pair chooses the pressure pair of the axisymmetric geometry",
                             "no domain.axis_pair, or domain.geometry = \"axisymmetric\"",
                             "domain.geometry = \"planar\" (the default)");
        p.axis_pair = static_cast<AxisPair>(choose_from<std::int64_t>(*f, pair_row.choices));
        // the rings pair's lattice error at the axis is too large at h = 1.3 dx (the R/dx 10
        // sphere 0.91 of its Laplace pressure, ka 1.2 grows; cases/axisymmetric/README.md)
        if (p.axis_pair == AxisPair::Rings && p.h < 2.0 * p.dx * (1.0 - 1e-9))
            throw InputError(ctx.where(dom.key_path("axis_pair")),
                             "the rings pair needs a smoothing length of at least 2 dx",
                             "resolution.h_over_dx >= 2 with domain.axis_pair = \"rings\"",
                             "h = " + num(p.h / p.dx) + " dx");
    }
    // the rings pair's own switches: true is refused with any other pair
    auto rings_switch = [&](const char* key, const std::string& what, bool& member) {
        if (auto f = dom.boolean(key)) {
            if (f->value && p.axis_pair != AxisPair::Rings)
                throw InputError(ctx.where(dom.key_path(key)), "domain." + std::string(key) + " " + what,
                                 "domain.axis_pair = \"rings\" with domain." + std::string(key) + " = true",
                                 "domain.axis_pair = \"" + to_string(p.axis_pair) + "\"");
            member = f->value;
        }
    };
    rings_switch("split_axis_rings", "splits the rings of the rings pair", p.split_axis_rings);
    rings_switch("renormalise_ring_continuity", "renormalises the rings pair's continuity",
                 p.renormalise_ring_continuity);
    rings_switch("bound_ring_xsph", "bounds the XSPH correction of the rings pair's rings", p.bound_ring_xsph);
    // after [domain]: the key belongs to the rings pair's pressure-consistent CSF
    const Section st = top.sub("surface_tension");
    if (auto f = st.string("rings_curvature")) {
        if (p.axis_pair != AxisPair::Rings || p.st_delta != SurfaceTensionDelta::PressureConsistent)
            throw InputError(ctx.where(st.key_path("rings_curvature")),
                             "surface_tension.rings_curvature chooses the curvature of the rings pair's "
                             "surface rows",
                             "domain.axis_pair = \"rings\" with surface_tension.delta = \"pressure_consistent\"",
                             p.axis_pair != AxisPair::Rings
                                 ? "domain.axis_pair = \"" + to_string(p.axis_pair) + "\""
                                 : "surface_tension.delta = \"" + to_string(p.st_delta) + "\"");
        p.rings_curvature = static_cast<RingsCurvature>(
            choose_from<std::int64_t>(*f, find_param("surface_tension.rings_curvature")->choices));
    }
    if (auto f = st.string("curvature_normals")) {
        if (p.st_delta != SurfaceTensionDelta::PressureConsistent)
            throw InputError(ctx.where(st.key_path("curvature_normals")),
                             "surface_tension.curvature_normals chooses the normals of the free-surface curvature",
                             "surface_tension.delta = \"pressure_consistent\"",
                             "surface_tension.delta = \"" + to_string(p.st_delta) + "\"");
        p.curvature_normals = static_cast<CurvatureNormals>(
            choose_from<std::int64_t>(*f, find_param("surface_tension.curvature_normals")->choices));
    }
    if (auto f = st.string("curvature")) {
        if (p.st_delta != SurfaceTensionDelta::PressureConsistent)
            throw InputError(ctx.where(st.key_path("curvature")),
                             "surface_tension.curvature chooses the free-surface curvature",
                             "surface_tension.delta = \"pressure_consistent\"",
                             "surface_tension.delta = \"" + to_string(p.st_delta) + "\"");
        p.curvature = static_cast<CurvatureModel>(
            choose_from<std::int64_t>(*f, find_param("surface_tension.curvature")->choices));
    }
    if (const auto f = st.boolean("balance_free_bodies"); f && f->value && !(p.sigma > 0))
        throw InputError(ctx.where(st.key_path("balance_free_bodies")),
                         "surface_tension.balance_free_bodies balances the surface tension's force on free bodies "
                         "but the surface tension is off",
                         "surface_tension.sigma > 0 with surface_tension.balance_free_bodies = true",
                         "surface_tension.sigma = " + num(p.sigma));
    if (const auto f = st.boolean("thin_rings_normals"); f && f->value) {
        if (p.geometry != Geometry::Axisymmetric || p.curvature != CurvatureModel::SurfaceFit)
            throw InputError(ctx.where(st.key_path("thin_rings_normals")),
                             "surface_tension.thin_rings_normals takes free rings off the surface fit",
                             "domain.geometry = \"axisymmetric\" and surface_tension.curvature = "
                             "\"surface_fit\" with surface_tension.thin_rings_normals = true",
                             std::string("domain.geometry = \"") + to_string(p.geometry) +
                                 "\", surface_tension.curvature = \"" + to_string(p.curvature) + "\"");
    }
    if (const auto f = st.integer("fit_points_min"); f && f->value > 3 && p.curvature != CurvatureModel::SurfaceFit)
        throw InputError(ctx.where(st.key_path("fit_points_min")),
                         "surface_tension.fit_points_min refuses surface fits through fewer points",
                         "surface_tension.curvature = \"surface_fit\" with surface_tension.fit_points_min > 3",
                         "surface_tension.curvature = \"" + to_string(p.curvature) + "\"");
}

// [[obstacle]], [[wall]] and [gate]: boundary particles in the box.
void read_structures(const Section& top, CaseSpec& spec, const Box& box) {
    for (const Section& s : top.array_of_tables("obstacle")) {
        ObstacleSpec o;
        read_members(s, o);
        o.r = read_rect(s, box, "obstacle");
        if (auto f = s.num("beta_deg"); f && o.beta_deg != 90) {
            // the inclined sides shift the top by height / tan(beta)
            const double shift =
                (o.r.zmax - std::max(o.r.zmin, 0.0)) / std::tan(o.beta_deg * 3.14159265358979323846 / 180);
            if (!(o.r.xmin + std::min(shift, 0.0) >= 0 && o.r.xmax + std::max(shift, 0.0) <= box.lx))
                fail(*f, "inclined sides reach outside the box (the top shifted by " + num(shift) + " m)",
                     "an angle whose sides stay in 0 <= x <= domain.lx = " + num(box.lx));
        }
        spec.obstacles.push_back(o);
    }

    for (const Section& s : top.array_of_tables("wall")) {
        WallSpec w;
        const auto x = s.required_num("x", "the wall position [m]");
        const auto height = s.required_num("height", "the wall height [m]");
        inside(x, box.lx, "x", "wall");
        if (!(height.value > 0 && height.value <= box.lz))
            fail(height, "out of range", "0 < height <= domain.lz = " + num(box.lz));
        if (spec.params.boundary != BoundaryType::Dynamic)
            fail(x, "a [[wall]] needs dynamic boundaries (as legacy \"Add wall\")",
                 "numerics.boundary = \"dynamic\"");
        w.x = x.value, w.height = height.value;
        spec.walls.push_back(w);
    }

    if (top.has("gate")) {
        const Section s = top.sub("gate");
        GateSpec g;
        const auto x = s.required_num("x", "the gate position [m]");
        const auto zmin = s.required_num("zmin", "the bottom of the gate [m]");
        const auto zmax = s.required_num("zmax", "the top of the gate [m]");
        inside(x, box.lx, "x", "gate");
        inside(zmin, box.lz, "z", "gate");
        inside(zmax, box.lz, "z", "gate");
        if (!(zmax.value >= zmin.value)) fail(zmax, "empty gate", "zmax >= zmin = " + num(zmin.value));
        g.x = x.value, g.zmin = zmin.value, g.zmax = zmax.value;
        read_members(s, g);
        spec.gates.push_back(g);
    }
}

// [nozzle] and [breakup]: a jet.
void read_jet(const Ctx& ctx, const Section& top, CaseSpec& spec, const Box& box) {
    SimParams& p = spec.params;
    if (!top.has("nozzle")) {
        if (top.has("breakup"))
            throw InputError(ctx.where("breakup"), "[breakup] needs a jet",
                             "a [nozzle] table (the breakup axis starts at its orifice)", "no [nozzle]");
        return;
    }
    const Section s = top.sub("nozzle");
    NozzleSpec nz;
    const auto x0 = s.required_num("x0", "the orifice centre x [m]");
    const auto z0 = s.required_num("z0", "the orifice centre z [m]");
    const auto d0 = s.required_num("d0", "the orifice width D0 [m]");
    const auto u0 = s.required_num("u0", "the jet speed u0 [m/s]");
    positive(d0);
    if (!(u0.value > 0)) fail(u0, "the jet speed must be positive (the plug moves out of the nozzle)", "u0 > 0");
    nz.x0 = x0.value, nz.z0 = z0.value, nz.d0 = d0.value, nz.u0 = u0.value;
    read_members(s, nz);
    if (auto f = s.string("axis")) {
        const auto dir = kNozzleDirections[choose_from<std::int64_t>(*f, find_param("nozzle.axis")->choices)];
        nz.ex = dir.first, nz.ez = dir.second;
    }
    const bool axisymmetric = p.geometry == Geometry::Axisymmetric;
    if (axisymmetric) {
        // A round jet: the nozzle is a pipe around the symmetry axis x = 0.
        if (nz.ex != 0.0)
            throw InputError(s.string("axis")->where, "a round jet runs along the symmetry axis",
                             "axis = \"down\" or \"up\" with domain.geometry = \"axisymmetric\"",
                             nz.ex > 0 ? "\"right\"" : "\"left\"");
        if (x0.value != 0.0)
            fail(x0, "a round jet's orifice is centred on the symmetry axis", "x0 = 0 with domain.geometry = \"axisymmetric\"");
    }
    // The nozzle, its walls (half a spacing outside the fluid) and the orifice in the box.
    const double across = 0.5 * nz.d0 + (nz.walls ? std::max(p.dx, p.dz) : 0.0);
    const double back_x = nz.x0 - nz.ex * nz.length(), back_z = nz.z0 - nz.ez * nz.length();
    const double xlo = axisymmetric ? 0.0 : std::min(nz.x0, back_x) - std::abs(nz.ez) * across;
    const double xhi = std::max(nz.x0, back_x) + std::abs(nz.ez) * across;
    const double zlo = std::min(nz.z0, back_z) - std::abs(nz.ex) * across;
    const double zhi = std::max(nz.z0, back_z) + std::abs(nz.ex) * across;
    const double tol = 1e-9 * std::max({box.lx, box.lz, 1.0});
    if (xlo < -tol || xhi > box.lx + tol)
        fail(x0, "nozzle outside the box",
             "the nozzle (from the orifice " + num(nz.length()) + " m back against the axis, " + num(2 * across) +
                 " m wide with its walls) within x in [0, domain.lx = " + num(box.lx) + "]: x from " + num(xlo) +
                 " to " + num(xhi));
    if (zlo < -tol || zhi > box.lz + tol)
        fail(z0, "nozzle outside the box",
             "the nozzle (from the orifice " + num(nz.length()) + " m back against the axis, " + num(2 * across) +
                 " m wide with its walls) within z in [0, domain.lz = " + num(box.lz) + "]: z from " + num(zlo) +
                 " to " + num(zhi));
    // The breakup axis runs from the orifice along e to the box edge; it must stay in the
    // box for a jet to be followed (at least 2 d0 of it).
    const double room = nz.ex > 0 ? box.lx - nz.x0 : nz.ex < 0 ? nz.x0 : nz.ez > 0 ? box.lz - nz.z0 : nz.z0;
    if (!(room >= 2 * nz.d0))
        throw InputError(s.string("axis") ? s.string("axis")->where : x0.where,
             "the breakup axis leaves the domain at once",
             "at least 2 d0 = " + num(2 * nz.d0) + " m of axis from the orifice to the box edge along the jet",
             num(room) + " m");
    if (nz.column() > room + tol)
        fail(*s.num("column_over_d0"), "the starting column leaves the box",
             "at most " + num(room / nz.d0) + " (the box's edge is " + num(room) +
                 " m from the orifice along the jet)");
    spec.nozzle = nz;
    p.drive_u = nz.u0;
    p.drive_x0 = nz.x0, p.drive_z0 = nz.z0, p.drive_ex = nz.ex, p.drive_ez = nz.ez;
    // Half a spacing beyond the outer fluid rows, so that every plug particle is driven
    // and the walls (a spacing out) are not.
    p.drive_half_width = 0.5 * nz.d0 + 0.25 * std::max(p.dx, p.dz);
    if (nz.profile == NozzleProfile::Parabolic) {
        p.drive_profile_a = 0.5 * nz.d0;
        const bool axi = p.geometry == Geometry::Axisymmetric;
        p.drive_profile_k = nozzle_profile_k(nz, p.dx, p.dz, axi);
        p.drive_profile_lmax = 0.5 * nz.d0 - 0.5 * nozzle_layout(nz, p.dx, p.dz, false, 0.0, axi).spacing_across;
        p.drive_profile_rho = plug_state(p, nz).rho;
    }
    if (nz.release == NozzleRelease::Landed && nz.profile == NozzleProfile::Parabolic)
        throw InputError(s.string("release")->where,
                         "nozzle.release = \"landed\" lands the plug's rows on the orifice line, but a parabolic "
                         "profile's lines cross it at different times",
                         "nozzle.release = \"landed\" with nozzle.profile = \"plug\" (\"crossing\" with "
                         "\"parabolic\")",
                         "nozzle.profile = \"parabolic\"");
    p.drive_release_crossing = nz.release != NozzleRelease::Step;
    p.drive_release_landed = nz.release == NozzleRelease::Landed;
    p.drive_eps = nz.disturbance;
    p.drive_omega = nz.disturbance > 0 ? nz.disturbance_omega() : 0.0;
    p.domain_box = true;

    BreakupSpec bk;
    read_members(top.sub("breakup"), bk);
    spec.breakup = bk;
}

// [[fluid.block]], [[fluid.disc]], [[fluid.cylinder]], [[fluid.square]]
void read_fluid_shapes(const Ctx& ctx, const Section& fluid, CaseSpec& spec, const Box& box) {
    const bool axi = spec.params.geometry == Geometry::Axisymmetric;
    for (const Section& s : fluid.array_of_tables("block")) {
        FluidBlock b;
        b.r = read_rect(s, box, "fluid region");
        read_members(s, b);
        spec.fluid_blocks.push_back(b);
    }
    for (const Section& s : fluid.array_of_tables("disc")) {
        FluidDisc d;
        const auto xc = s.required_num("xc", "the centre x [m]");
        const auto zc = s.required_num("zc", "the centre z [m]");
        const auto r = s.required_num("radius", "the radius [m]");
        positive(r);
        // axisymmetric: a disc centred on the axis is a sphere (the generator fills x >= 0);
        // one that crosses the axis elsewhere would be a self-intersecting ring: refused
        const bool sphere = axi && xc.value == 0.0;
        if (axi && !sphere && xc.value - r.value < 0.0)
            fail(xc, "an axisymmetric disc reaches x < 0 (the other side of the axis)",
                 "xc = 0 (a sphere) or xc >= radius = " + num(r.value) + " (a torus)");
        // a sphere takes x in [0, R] only: checked as a disc in a box twice as wide
        const Box dbox = sphere ? Box{2 * box.lx, box.lz} : box;
        centred_inside(sphere ? Field<double>{box.lx, xc.where} : xc, zc, r, r.value, dbox, "fluid disc");
        d.xc = xc.value, d.zc = zc.value, d.radius = r.value;
        read_members(s, d);
        if (d.elongation != 0.0) {
            const double a = r.value * (1 + std::abs(d.elongation));
            centred_inside(sphere ? Field<double>{box.lx, xc.where} : xc, zc, r, a, dbox, "fluid disc (stretched)");
        }
        spec.fluid_discs.push_back(d);
    }
    for (const Section& s : fluid.array_of_tables("cylinder")) {
        // axisymmetric only: r(z) = radius (1 + eps cos(2 pi (z - zmin) / wavelength))
        FluidCylinder c;
        const auto r = s.required_num("radius", "the radius a [m]");
        positive(r);
        if (!axi)
            fail(r, "[[fluid.cylinder]] is a liquid cylinder about the axis x = 0",
                 "domain.geometry = \"axisymmetric\"");
        c.radius = r.value;
        c.zmin = 0.0, c.zmax = box.lz;
        if (auto f = s.num("zmin")) inside(*f, box.lz, "z", "fluid cylinder"), c.zmin = f->value;
        if (auto f = s.num("zmax")) inside(*f, box.lz, "z", "fluid cylinder"), c.zmax = f->value;
        if (!(c.zmax > c.zmin)) fail(r, "empty cylinder", "zmax > zmin = " + num(c.zmin));
        read_members(s, c);
        if (!s.has("wavelength") && c.eps != 0.0)
            throw InputError(ctx.where(s.key_path("wavelength")), "missing required key",
                             "fluid.cylinder.wavelength [m] with eps != 0", "nothing");
        if (!(c.radius * (1 + std::abs(c.eps)) <= box.lx))
            fail(r, "fluid cylinder outside the box", "radius (1 + |eps|) <= domain.lx = " + num(box.lx));
        spec.fluid_cylinders.push_back(c);
    }
    for (const Section& s : fluid.array_of_tables("square")) {
        FluidSquare q;
        const auto xc = s.required_num("xc", "the centre x [m]");
        const auto zc = s.required_num("zc", "the centre z [m]");
        const auto side = s.required_num("side", "the side length [m]");
        positive(side);
        centred_inside(xc, zc, side, side.value / 2, box, "fluid square");
        q.xc = xc.value, q.zc = zc.value, q.side = side.value;
        read_members(s, q);
        spec.fluid_squares.push_back(q);
    }
}

}  // namespace

CaseSpec build_case(const Ctx& ctx, const toml::table& root) {
    CaseSpec spec;
    spec.source = ctx.file;
    SimParams& p = spec.params;
    const Section top(ctx, &root, "", "");

    if (auto v = top.integer("format_version"); v && v->value != 1)
        fail(*v, "unsupported format version", "1");

    const LegacyRead leg = read_legacy(top, spec);
    const Section num_s = top.sub("numerics");
    read_members(num_s, p);  // everything but the viscosity value, which needs h and c0
    read_members(top.sub("gravity"), p);
    read_members(top.sub("surface_tension"), p);
    const Section fluid = top.sub("fluid");
    read_members(fluid, p);
    read_sound_speed(ctx, fluid, p, leg.single);
    read_resolution(ctx, top, p, spec.legacy, leg);
    read_members(top.sub("resolution"), p);  // the keys beyond dx, dz and h (jitter)
    read_viscosity(ctx, num_s, fluid, p);
    read_domain(ctx, top, spec);
    const Section time_s = top.sub("time");
    read_members(time_s, p);
    if (auto f = time_s.num("dt_max"); f && p.dt_max > 0 && !p.variable_dt)
        fail(*f, "time.dt_max caps the variable step, but time.variable_dt = false fixes the step at time.dt",
             "time.variable_dt = true with time.dt_max > 0 (or time.dt alone for a fixed step)");
    const Box box{p.lx, p.lz};
    read_structures(top, spec, box);
    read_jet(ctx, top, spec, box);
    if (p.renormalise_margin_d0 > 0) {
        const Section dom = top.sub("domain");
        if (!p.renormalise_ring_continuity)
            throw InputError(ctx.where(dom.key_path("renormalise_margin_d0")),
                             "domain.renormalise_margin_d0 stops the renormalised continuity short of a jet's end",
                             "domain.renormalise_ring_continuity = true with domain.renormalise_margin_d0 > 0",
                             "domain.renormalise_ring_continuity = false");
        if (!spec.nozzle)
            throw InputError(ctx.where(dom.key_path("renormalise_margin_d0")),
                             "domain.renormalise_margin_d0 is counted from a jet's end in its nozzle's diameters",
                             "a [nozzle] with domain.renormalise_margin_d0 > 0", "no [nozzle]");
    }
    read_fluid_shapes(ctx, fluid, spec, box);
    if (spec.legacy_fill && p.h_swl <= 0)
        throw InputError(ctx.where(fluid.key_path("h_swl")), "missing required key",
                         "fluid.coef and fluid.h_swl with legacy.fill = true (the legacy fill stops at h_swl)",
                         "nothing");
    if (spec.fluid_blocks.empty() && spec.fluid_discs.empty() && spec.fluid_squares.empty() &&
        spec.fluid_cylinders.empty() && !spec.nozzle)
        throw InputError(ctx.file + ": fluid", "no fluid in the case",
                         "at least one [[fluid.block]], [[fluid.disc]], [[fluid.square]] or [[fluid.cylinder]], or a [nozzle]",
                         "none");

    const Section out = top.sub("output");
    read_members(out, spec.output);
    if (auto f = out.integer("revolution_sectors"); f && p.geometry != Geometry::Axisymmetric)
        fail(*f, "only an axisymmetric case has rings to revolve about the axis",
             "no output.revolution_sectors with domain.geometry = \"planar\" (the default), "
             "or domain.geometry = \"axisymmetric\"");
    return spec;
}


}  // namespace sphjet::casefile
