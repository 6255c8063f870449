// The case writer: a complete, commented case file for a CaseSpec (config/modern_case.hpp),
// the plain keys from their rows (model/case_params.hpp), derived numbers by hand.
#include <cmath>
#include <initializer_list>

#include "config/case_derived.hpp"
#include "config/case_toml.hpp"
#include "config/modern_case.hpp"
#include "model/case_params.hpp"

namespace sphjet {

using casefile::dquote;
using casefile::num;

namespace {

// The c0 whose B = rho0 c0^2 / gamma is exactly spec's B, when such a double exists
// near sqrt(gamma B / rho0) (so that a round trip reproduces B to the bit).
double c0_for_B(const SimParams& p) {
    const double guess = std::sqrt(p.gamma * p.B / p.rho0);
    if (!std::isfinite(guess) || guess <= 0) return guess;
    double lo = guess, hi = guess;
    for (int i = 0; i < 8; ++i) {
        if (tait_B_from_c0(p.rho0, lo, p.gamma) == p.B) return lo;
        if (tait_B_from_c0(p.rho0, hi, p.gamma) == p.B) return hi;
        lo = std::nextafter(lo, 0.0);
        hi = std::nextafter(hi, INFINITY);
    }
    return guess;
}

std::string line(const std::string& key, const std::string& value, const std::string& comment) {
    std::string s = key + " = " + value;
    if (!comment.empty()) {
        if (s.size() < 32) s.resize(32, ' ');
        else s += ' ';
        s += "# " + comment;
    }
    return s + "\n";
}

std::string str(std::string_view s) { return dquote(s); }
std::string boolean(bool b) { return b ? "true" : "false"; }


std::string sanitize_comment(std::string s) {
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    return s;
}

// A row's comment in the echo: its echo text, else its choices or its doc; "{choices}" is
// replaced by the names.
std::string comment_of(const Param& r) {
    std::string c(r.echo.empty() ? (r.choices.empty() ? r.doc : "{choices}") : r.echo);
    if (c == "-") return "";
    if (const auto at = c.find("{choices}"); at != std::string::npos) c.replace(at, 9, choice_list(r.choices));
    return c;
}

// A member's value as the case file writes it.
std::string value_of(const Param& r, const void* owner) {
    const Member& m = r.member;
    if (m.store == Member::Store::Float) return num(m.get_f(owner));
    const std::int64_t v = m.get_i(owner);
    if (r.type == KeyType::String) return str(choice_name(r.choices, v));
    if (r.type == KeyType::Bool) return boolean(v != 0);
    return std::to_string(v);
}

// The structs a section's rows live in.
struct Owner {
    const void* tag;
    const void* object;
};

// The lines of one section: the rows whose member lives in one of owners, in the table's
// order; a row echoed by hand gets the line custom(row) makes ("" for none).
template <class Custom>
std::string echo_section(std::string_view section, std::initializer_list<Owner> owners, Custom&& custom) {
    std::string s;
    for (const Param& r : case_params()) {
        if (r.key.empty() || section_of(r.key) != section) continue;
        if (r.hand & kHandEcho) {
            s += custom(r);
            continue;
        }
        for (const Owner& o : owners)
            if (o.tag == r.member.owner) s += line(std::string(leaf_of(r.key)), value_of(r, o.object), comment_of(r));
    }
    return s;
}

template <class S>
Owner owner(const S& s) {
    return {&owner_tag<S>, &s};
}

// A section whose every row is echoed from one struct.
template <class S>
std::string echo_section(std::string_view section, const S& s) {
    return echo_section(section, {owner(s)}, [](const Param&) { return std::string(); });
}

// The flags of the derived numbers of a legacy case, made in single precision: written
// so that they read back to the bit.
struct EchoFlags {
    bool single = false;
    bool h_by_coefficient = false;
    bool legacy_section = false;
};

EchoFlags echo_flags(const CaseSpec& spec) {
    const SimParams& p = spec.params;
    const LegacyRunInfo& info = spec.legacy;
    const LegacyRunInfo info_default;
    const double g = std::abs(p.gz);
    const bool b_single = p.h_swl > 0 &&
                          tait_B_from_coef(p.coef, p.rho0, g, p.h_swl, p.gamma) != p.B &&
                          tait_B_from_coef_single(p.coef, p.rho0, g, p.h_swl, p.gamma) == p.B;
    const bool h_single = info.h_coefficient > 0 &&
                          h_from_coefficient(info.h_coefficient, p.dx, p.dz, false) != p.h &&
                          h_from_coefficient(info.h_coefficient, p.dx, p.dz, true) == p.h;
    EchoFlags e;
    e.single = b_single || h_single;
    e.h_by_coefficient =
        info.h_coefficient > 0 && h_from_coefficient(info.h_coefficient, p.dx, p.dz, e.single) == p.h;
    e.legacy_section =
        spec.legacy_fill || e.single || (info.h_coefficient > 0 && !e.h_by_coefficient) ||
        info.detail_out != info_default.detail_out || info.detail_start != info_default.detail_start ||
        info.detail_end != info_default.detail_end || info.vorticity != info_default.vorticity ||
        info.compiler != info_default.compiler || info.xz_precision != info_default.xz_precision;
    return e;
}

// The lines of the keys the writer makes by hand (kHandEcho): derived numbers and keys shown
// only in some cases.
std::string custom_line(const Param& r, const CaseSpec& spec, const EchoFlags& e) {
    const SimParams& p = spec.params;
    const std::string key(leaf_of(r.key));
    const std::string_view k = r.key;
    const double c0 = p.c0();
    if (k == "numerics.alpha" && p.viscosity == ViscosityModel::Artificial)
        return line(key, num(p.visc_value),
                    "artificial viscosity; same as nu = alpha h c0 / 8 = " + num(p.visc_value * p.h * c0 / 8.0) +
                        " m^2/s");
    if (k == "fluid.c0" && p.h_swl <= 0)
        return line(key, num(c0_for_B(p)), "sound speed at rest [m/s]; B = rho0 c0^2 / gamma = " + num(p.B) + " Pa");
    if (k == "fluid.coef" && p.h_swl > 0)
        return line(key, num(p.coef), "c0 = coef sqrt(|gz| h_swl) = " + num(c0) + " m/s");
    if (k == "fluid.h_swl" && p.h_swl > 0)
        return line(key, num(p.h_swl), "still-water depth [m]; B = " + num(p.B) + " Pa");
    if (k == "fluid.nu" && p.viscosity == ViscosityModel::Laminar)
        return line(key, num(p.visc_value), "kinematic viscosity [m^2/s] (mu = " + num(p.visc_value * p.rho0) + " Pa s)");
    if (k == "surface_tension.rings_curvature" && p.axis_pair == AxisPair::Rings &&
        p.st_delta == SurfaceTensionDelta::PressureConsistent)
        return line(key, value_of(r, &p), comment_of(r));
    if (k == "surface_tension.curvature_normals" && p.curvature_normals != CurvatureNormals::All)
        return line(key, value_of(r, &p), comment_of(r));
    if (k == "surface_tension.curvature" && p.curvature != CurvatureModel::Normals)
        return line(key, value_of(r, &p), comment_of(r));
    if (k == "domain.axis_pair" && p.geometry == Geometry::Axisymmetric) return line(key, value_of(r, &p), comment_of(r));
    if (k == "resolution.h") {
        const double diag = std::sqrt(p.dx * p.dx + p.dz * p.dz);
        if (e.h_by_coefficient)
            return line("h_coefficient", num(spec.legacy.h_coefficient),
                        "h = coefficient sqrt(dx^2 + dz^2) = " + num(p.h) + " m = " + num(p.h / p.dx) + " dx");
        return line(key, num(p.h), "smoothing length [m] = " + num(p.h / p.dx) + " dx = " + num(p.h / diag) +
                                       " sqrt(dx^2 + dz^2)");
    }
    if (k == "legacy.single_precision") return line(key, boolean(e.single), std::string(r.doc));
    if (k == "legacy.h_coefficient" && spec.legacy.h_coefficient > 0 && !e.h_by_coefficient)
        return line(key, num(spec.legacy.h_coefficient), std::string(r.doc));
    if (k == "output.revolution_sectors" && spec.output.revolution_sectors > 0)
        return line(key, value_of(r, &spec.output), comment_of(r));
    if (spec.nozzle && k == "nozzle.axis") {
        const NozzleSpec& nz = *spec.nozzle;
        std::int64_t axis = 0;
        for (std::size_t i = 0; i < std::size(kNozzleDirections); ++i)
            if (kNozzleDirections[i] == std::pair{nz.ex, nz.ez}) axis = static_cast<std::int64_t>(i);
        return line(key, str(choice_name(r.choices, axis)), comment_of(r));
    }
    if (spec.nozzle && spec.nozzle->disturbance > 0 &&
        (k == "nozzle.disturbance" || k == "nozzle.disturbance_ka"))
        return line(key, value_of(r, &*spec.nozzle), comment_of(r));
    if (spec.breakup && ((k == "breakup.stop_after" && spec.breakup->stop_after >= 0) ||
                         (k == "breakup.remove_drops_below_h" && spec.breakup->remove_drops_below_h > 0) ||
                         (k == "breakup.remove_drops_beyond_d0" && spec.breakup->remove_drops_beyond_d0 > 0)))
        return line(key, value_of(r, &*spec.breakup), comment_of(r));
    return "";
}

}  // namespace

std::string write_modern_case(const CaseSpec& spec) {
    const SimParams& p = spec.params;
    const EchoFlags e = echo_flags(spec);
    const auto custom = [&](const Param& r) { return custom_line(r, spec, e); };
    std::string s;
    s += "# sphjet case file (modern format, reference: cases/CASE_FORMAT.md).\n";
    if (!spec.source.empty()) s += "# Written from: " + sanitize_comment(spec.source) + "\n";
    s += "# Units: SI (m, s, kg). Coordinates: x horizontal, z vertical, box [0, lx] x [0, lz].\n\n";
    s += line("format_version", "1", "");

    s += "\n[numerics]\n" + echo_section("numerics", {owner(p)}, custom);
    s += "\n[fluid]\n" + echo_section("fluid", {owner(p)}, custom);
    for (const auto& b : spec.fluid_blocks)
        s += "\n[[fluid.block]]                  # rectangle filled on the lattice\n" +
             echo_section("fluid.block[]", b);
    for (const auto& d : spec.fluid_discs) s += "\n[[fluid.disc]]\n" + echo_section("fluid.disc[]", d);
    for (const auto& c : spec.fluid_cylinders) {
        s += "\n[[fluid.cylinder]]               # axisymmetric: r(z) = a (1 + eps cos(2 pi (z - zmin) / wavelength))\n";
        s += echo_section("fluid.cylinder[]", {owner(c)}, [&c](const Param& r) {
            return c.wavelength > 0 ? line(std::string(leaf_of(r.key)), num(c.wavelength), comment_of(r)) : "";
        });
    }
    for (const auto& q : spec.fluid_squares) s += "\n[[fluid.square]]\n" + echo_section("fluid.square[]", q);
    s += "\n[surface_tension]\n" + echo_section("surface_tension", {owner(p)}, custom);
    s += "\n[gravity]\n" + echo_section("gravity", p);
    s += "\n[domain]\n" + echo_section("domain", {owner(p), owner(spec)}, custom);
    s += "\n[resolution]\n" + echo_section("resolution", {owner(p)}, custom);
    s += "\n[time]\n" + echo_section("time", p);
    for (const auto& o : spec.obstacles) s += "\n[[obstacle]]\n" + echo_section("obstacle[]", o);
    for (const auto& g : spec.gates)
        s += "\n[gate]                          # legacy \"Add gate\": a column of moving boundary particles\n" +
             echo_section("gate", g);
    if (spec.nozzle)
        s += "\n[nozzle]                        # a driven nozzle: the fluid in it moves out at u0 as a plug\n" +
             echo_section("nozzle", {owner(*spec.nozzle)}, custom);
    if (spec.breakup)
        s += "\n[breakup]                       # breakup detection while the run goes\n" +
             echo_section("breakup", {owner(*spec.breakup)}, custom);
    for (const auto& w : spec.walls)
        s += "\n[[wall]]                        # legacy \"Add wall\": two layers of boundary particles\n" +
             echo_section("wall[]", w);
    if (e.legacy_section)
        s += "\n[legacy]                        # carried over from a legacy SPHysics case file\n" +
             echo_section("legacy", {owner(spec), owner(spec.legacy)}, custom);
    s += "\n[output]\n" + echo_section("output", {owner(spec.output)}, custom);
    return s;
}

}  // namespace sphjet

