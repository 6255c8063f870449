#include "core/solver.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "model/errors.hpp"

namespace sphjet {

namespace {
// Fluid beyond these bounds leaves the run: the box for open jets (SimParams::domain_box),
// else the legacy rule (legacy_domain).
DomainBounds run_domain(const SimParams& p, const ParticleSet& ps) {
    if (p.domain_box) return {0.0, p.lx, 0.0, p.lz};
    DomainBounds d = legacy_domain(ps);
    // periodic in z: the period is [0, lz] (the core folds particles back into it)
    if (p.periodic_z) d.zmin = 0.0, d.zmax = p.lz;
    return d;
}
}  // namespace

sph_params_t core_params(const SimParams& p, const OutputSpec& out, const DomainBounds& dom) {
    sph_params_t c{};
    c.numerics.kernel = static_cast<int>(p.kernel);
    c.numerics.density_filter = static_cast<int>(p.density_filter);
    c.numerics.tensile = p.tensile_on() ? 1 : 0;
    c.numerics.integrator = static_cast<int>(p.integrator);
    c.numerics.h = p.h;
    c.numerics.xsph_eps = p.xsph_eps;
    c.numerics.density_diffusion = p.density_diffusion;
    c.numerics.bulk_viscosity = p.bulk_viscosity;
    c.numerics.shifting = p.shifting;

    c.time_step.variable_dt = p.variable_dt ? 1 : 0;
    c.time_step.cfl = p.cfl;
    c.time_step.dt_min = out.dt_min;
    c.time_step.dt_max = p.dt_max;

    c.eos.rho0 = p.rho0;
    c.eos.b = p.B;
    c.eos.gamma = p.gamma;
    c.eos.c0 = p.c0();

    c.domain.remove_out = out.remove_out_of_domain ? 1 : 0;
    c.domain.xmin = dom.xmin;
    c.domain.xmax = dom.xmax;
    c.domain.zmin = dom.zmin;
    c.domain.zmax = dom.zmax;
    c.domain.rho_min = out.rho_min_factor * p.rho0;
    c.domain.rho_max = out.rho_max_factor * p.rho0;

    c.viscosity.model = static_cast<int>(p.viscosity);
    c.viscosity.value = p.visc_value;
    c.viscosity.artificial_alpha = p.artificial_alpha;
    c.viscosity.reconstruct = p.artificial_reconstruction ? 1 : 0;

    c.boundary.model = static_cast<int>(p.boundary);
    c.boundary.dbc_period = std::max(p.dbc_period, 1);
    c.boundary.coef = p.coef;
    c.boundary.h_swl = p.h_swl > 0 ? p.h_swl : 1.0;
    c.boundary.viscosity = p.wall_viscosity;
    c.boundary.gate_vx = p.gate_vx;
    c.boundary.gate_vz = p.gate_vz;
    c.boundary.gate_t_start = p.gate_t_start;
    c.boundary.gate_z_cap = p.gate_z_cap;

    c.surface_tension.delta = static_cast<int>(p.st_delta);
    c.surface_tension.rings_curvature = static_cast<int>(p.rings_curvature);
    c.surface_tension.curvature_normals = static_cast<int>(p.curvature_normals);
    c.surface_tension.curvature = static_cast<int>(p.curvature);
    c.surface_tension.free_bodies = p.balance_free_bodies ? 1 : 0;
    c.surface_tension.thin_rings = p.thin_rings_normals ? 1 : 0;
    c.surface_tension.fit_points_min = p.fit_points_min;
    c.surface_tension.sigma = p.sigma;

    c.nozzle.u = p.drive_u;
    c.nozzle.x0 = p.drive_x0;
    c.nozzle.z0 = p.drive_z0;
    c.nozzle.ex = p.drive_ex;
    c.nozzle.ez = p.drive_ez;
    c.nozzle.half_width = p.drive_half_width;
    c.nozzle.profile_a = p.drive_profile_a;
    c.nozzle.profile_k = p.drive_profile_k;
    c.nozzle.profile_lmax = p.drive_profile_lmax;
    c.nozzle.profile_rho = p.drive_profile_rho;
    c.nozzle.release = p.drive_release_landed ? 2 : p.drive_release_crossing ? 1 : 0;

    c.geometry.kind = static_cast<int>(p.geometry);
    c.geometry.periodic_z = p.periodic_z ? 1 : 0;
    c.geometry.axis_pair = static_cast<int>(p.axis_pair);
    // the rings pair's axis correction tells the first column (r = dx/2) by its ring mass,
    // pi rho0 dx^2 dz against 3 pi rho0 dx^2 dz for the second (axisymmetric_loops.f90)
    c.geometry.axis_m1 =
        p.axis_pair == AxisPair::Rings ? 2.0 * std::numbers::pi * p.rho0 * p.dx * p.dx * p.dz : 0.0;
    c.geometry.ring_mass_per_radius = p.split_axis_rings ? 2.0 * std::numbers::pi * p.rho0 * p.dx * p.dz : 0.0;
    c.geometry.renormalise_continuity = p.renormalise_ring_continuity ? 1 : 0;
    c.geometry.bound_xsph = p.bound_ring_xsph ? 1 : 0;

    c.gravity.gx = p.gx;
    c.gravity.gz = p.gz;
    return c;
}

std::string status_text(int status) {
    switch (status) {
        case SPH_OK: return "ok";
        case SPH_ERR_ARGUMENT: return "invalid argument or option passed to the core";
        case SPH_ERR_NONFINITE: return "non-finite value (NaN or Inf)";
        case SPH_ERR_DENSITY: return "density outside the allowed band";
        case SPH_ERR_OUT_OF_DOMAIN: return "particle left the domain";
        case SPH_ERR_DT_COLLAPSE: return "time step collapsed below dt_min";
        case SPH_ERR_CAPACITY: return "output buffer too small";
        default: return fmt::format("unknown status {}", status);
    }
}

Solver::Solver(const SimParams& params, const OutputSpec& output, ParticleSet particles)
    : params_(params), output_(output), ps_(std::move(particles)) {
    const std::size_t n = ps_.size();
    if (ps_.active.size() != n) ps_.active.assign(n, 1);
    for (auto* v : {&c_, &xo_, &zo_, &uo_, &wo_, &rhoo_, &ax_, &az_, &ar_, &xu_, &xw_})
        v->assign(n, 0.0);
    for (auto* v : {&list_x_, &list_z_}) v->assign(n, std::numeric_limits<double>::quiet_NaN());
    if (params_.boundary == BoundaryType::Repulsive) {
        if (ps_.wall.size() != ps_.nb)
            throw InputError("particles", "repulsive walls need the wall links of every boundary "
                                          "particle (NORMALS.init)",
                             fmt::format("{} links", ps_.nb), fmt::format("{}", ps_.wall.size()));
        wall_prev_.resize(n, 0);
        wall_next_.resize(n, 0);
        for (std::size_t i = 0; i < ps_.nb; ++i) {
            wall_prev_[i] = ps_.wall[i].prev;
            wall_next_[i] = ps_.wall[i].next;
        }
        for (auto* v : {&wall_nx_, &wall_nz_, &wall_db_, &wall_df_}) v->assign(n, 0.0);
    }
    if (params_.sigma > 0)
        for (auto* v : {&colour_, &st_nx_, &st_nz_, &kappa_}) v->assign(n, 0.0);
    prm_ = core_params(params_, output_, run_domain(params_, ps_));
    was_active_.assign(ps_.active.begin(), ps_.active.end());
    state_.dt = params_.dt;
    bind_arrays();
    ws_ = sph_workspace_create();
    const int status = sph_prepare(&prm_, &arr_);
    if (status != SPH_OK) {
        sph_workspace_destroy(ws_);
        throw SimulationError("core refused the case parameters or the wall links: " +
                              status_text(status));
    }
    if (params_.sigma > 0) {
        // Surface-tension fields of the initial state, so that the t = 0 output has them
        // (the steps compute them inside the rates). No acceleration is requested (ax, az
        // null), so nothing the integrator keeps is touched.
        sph_arrays_t a = arr_;
        a.ax = nullptr;
        a.az = nullptr;
        const int st = sph_surface_tension_fields(ws_, &prm_, &a);
        if (st != SPH_OK) {
            sph_workspace_destroy(ws_);
            throw SimulationError("core refused the surface-tension fields of the initial state: " +
                                  status_text(st));
        }
    }
}

Solver::~Solver() { sph_workspace_destroy(ws_); }

void Solver::bind_arrays() {
    arr_ = sph_arrays_t{};
    arr_.n = static_cast<int64_t>(ps_.size());
    arr_.nb = static_cast<int64_t>(ps_.nb);
    arr_.x = ps_.x.data();
    arr_.z = ps_.z.data();
    arr_.u = ps_.u.data();
    arr_.w = ps_.w.data();
    arr_.rho = ps_.rho.data();
    arr_.p = ps_.p.data();
    arr_.c = c_.data();
    arr_.m = ps_.m.data();
    arr_.kind = ps_.kind.data();
    arr_.active = ps_.active.data();
    arr_.xo = xo_.data();
    arr_.zo = zo_.data();
    arr_.uo = uo_.data();
    arr_.wo = wo_.data();
    arr_.rhoo = rhoo_.data();
    arr_.ax = ax_.data();
    arr_.az = az_.data();
    arr_.ar = ar_.data();
    arr_.xsph_u = xu_.data();
    arr_.xsph_w = xw_.data();
    if (!wall_prev_.empty()) {
        arr_.wall_prev = wall_prev_.data();
        arr_.wall_next = wall_next_.data();
        arr_.wall_nx = wall_nx_.data();
        arr_.wall_nz = wall_nz_.data();
        arr_.wall_dback = wall_db_.data();
        arr_.wall_dfwd = wall_df_.data();
    }
    arr_.list_x = list_x_.data();
    arr_.list_z = list_z_.data();
    if (!colour_.empty()) {
        arr_.colour = colour_.data();
        arr_.st_nx = st_nx_.data();
        arr_.st_nz = st_nz_.data();
        arr_.kappa = kappa_.data();
    }
}

void Solver::fail(int status, std::int64_t particle, const std::string& where) const {
    std::string msg = fmt::format("{} at step {} (t = {:.6g} s): {}", where, state_.step + 1,
                                  state_.time, status_text(status));
    if (particle >= 0 && static_cast<std::size_t>(particle) < ps_.size()) {
        const auto i = static_cast<std::size_t>(particle);
        msg += fmt::format("; particle id {} (index {}, {}) at x = {:.6g} m, z = {:.6g} m, "
                           "u = {:.6g} m/s, w = {:.6g} m/s, rho = {:.6g} kg/m^3",
                           ps_.id[i], i, ps_.kind[i] == 2 ? "fluid" : "boundary", ps_.x[i],
                           ps_.z[i], ps_.u[i], ps_.w[i], ps_.rho[i]);
    }
    throw SimulationError(msg);
}

StepReport Solver::step(bool fields) {
    if (!colour_.empty()) {
        arr_.colour = fields ? colour_.data() : nullptr;
        arr_.st_nx = fields ? st_nx_.data() : nullptr;
        arr_.st_nz = fields ? st_nz_.data() : nullptr;
        arr_.kappa = fields ? kappa_.data() : nullptr;
    }
    sph_step_info_t info{};
    info.dt = state_.dt;
    info.time = state_.time;
    info.dbc_counter = state_.dbc_counter;
    info.rates_kept = rates_kept_ ? 1 : 0;
    // A disturbed nozzle: the plug speed over this step (SimParams::drive_eps).
    if (params_.drive_eps != 0.0)
        prm_.nozzle.u = params_.drive_u * (1.0 + params_.drive_eps * std::sin(params_.drive_omega * state_.time));
    prm_.geometry.renormalise_reach = state_.renormalise_reach;
    const int status = sph_step(ws_, &prm_, &arr_, &info);
    if (status == SPH_ERR_DT_COLLAPSE) {
        fail(status, -1,
             fmt::format("time step {:.3g} s (force term {:.3g} s, CFL term {:.3g} s)",
                         info.dt_next, info.dt_f, info.dt_cv));
    }
    if (status != SPH_OK) fail(status, info.bad_particle, "step");
    if (!params_.variable_dt && info.dt_new > 0.0) {
        fixed_record_.steps += 1;
        if (info.dt > info.dt_new) fixed_record_.above += 1;
        fixed_record_.smallest = std::min(fixed_record_.smallest, info.dt_new);
    }
    StepReport r;
    r.dt_taken = info.dt;
    r.removed = info.n_removed;
    if (info.n_removed > 0) {
        for (std::size_t i = 0; i < ps_.size(); ++i)
            if (!ps_.active[i] && was_active_[i]) r.removed_ids.push_back(ps_.id[i]);
    }
    if (info.n_removed > 0 || was_active_.empty())
        was_active_.assign(ps_.active.begin(), ps_.active.end());
    state_.step += 1;
    state_.time += info.dt;
    // SPHysics advances its clock by the new step; a landed step (nozzle.release = "landed") took
    // less than the step asked, state_.dt
    state_.legacy_time += info.dt_next + (info.dt - state_.dt);
    state_.dt = info.dt_next;
    state_.dt_f = info.dt_f;
    state_.dt_cv = info.dt_cv;
    state_.dt_new = info.dt_new;
    state_.dbc_counter = info.dbc_counter;
    rates_kept_ = info.rates_kept != 0;
    state_.n_removed += info.n_removed;
    return r;
}

void Solver::density_filter() {
    if (params_.density_filter == DensityFilter::None) return;
    int64_t singular = 0;
    const int status = sph_density_filter(ws_, &prm_, &arr_, &singular);
    if (status != SPH_OK) fail(status, -1, "density filter");
    rates_kept_ = false;
}

void Solver::density_filter_if_due() {
    if (params_.density_filter != DensityFilter::None && params_.filter_period > 0 &&
        state_.step % params_.filter_period == 0)
        density_filter();
}

void Solver::check_state() const {
    int64_t bad = -1;
    const int status = sph_check_state(&prm_, &arr_, &bad);
    if (status != SPH_OK) fail(status, bad, "state check");
}

std::size_t Solver::deactivate(const std::vector<std::size_t>& indices) {
    std::size_t n = 0;
    for (const std::size_t i : indices) {
        if (i >= ps_.size() || ps_.active[i] == 0 || ps_.kind[i] != static_cast<int>(ParticleKind::Fluid)) continue;
        ps_.active[i] = 0;
        ps_.u[i] = 0.0;
        ps_.w[i] = 0.0;
        was_active_[i] = 0;  // not among the next step's domain leavers
        ++n;
    }
    if (n > 0) {
        rates_kept_ = false;
        std::fill(list_x_.begin(), list_x_.end(), std::numeric_limits<double>::quiet_NaN());
        std::fill(list_z_.begin(), list_z_.end(), std::numeric_limits<double>::quiet_NaN());
    }
    return n;
}

std::size_t Solver::append_fluid(const ParticleSet& more, bool plug_rows) {
    const std::size_t n0 = ps_.size(), k = more.size();
    if (k == 0) return 0;
    if (!plug_rows) rates_kept_ = false;
    for (std::size_t i = 0; i < k; ++i)
        (void)ps_.push(more.x[i], more.z[i], more.u[i], more.w[i], more.rho[i], more.p[i], more.m[i],
                       ParticleKind::Fluid);
    const std::size_t n = ps_.size();
    for (auto* v : {&c_, &xo_, &zo_, &uo_, &wo_, &rhoo_, &ax_, &az_, &ar_, &xu_, &xw_}) v->resize(n, 0.0);
    if (!wall_prev_.empty()) {
        wall_prev_.resize(n, 0);
        wall_next_.resize(n, 0);
        for (auto* v : {&wall_nx_, &wall_nz_, &wall_db_, &wall_df_}) v->resize(n, 0.0);
    }
    if (!colour_.empty())
        for (auto* v : {&colour_, &st_nx_, &st_nz_, &kappa_}) v->resize(n, 0.0);
    list_x_.assign(n, std::numeric_limits<double>::quiet_NaN());
    list_z_.assign(n, std::numeric_limits<double>::quiet_NaN());
    was_active_.resize(n, 1);
    bind_arrays();
    const int status = sph_eos(&prm_, static_cast<int64_t>(k), ps_.rho.data() + n0, ps_.p.data() + n0, c_.data() + n0);
    if (status != SPH_OK) fail(status, -1, "equation of state");
    return k;
}

std::size_t Solver::split_heavy_rings() {
    if (!params_.split_axis_rings) return 0;
    std::vector<std::int64_t> idx(16);
    std::int64_t found = 0;
    for (;;) {
        const int status = sph_axis_rings_to_split(&prm_, &arr_, static_cast<std::int64_t>(idx.size()), idx.data(),
                                                   &found);
        if (status != SPH_OK) fail(status, -1, "rings to split");
        if (found <= static_cast<std::int64_t>(idx.size())) break;
        idx.resize(static_cast<std::size_t>(found));
    }
    if (found == 0) return 0;
    ParticleSet halves;
    const double dz = params_.dz;
    for (std::int64_t k = 0; k < found; ++k) {
        const auto i = static_cast<std::size_t>(idx[static_cast<std::size_t>(k)]);
        ps_.m[i] *= 0.5;
        (void)halves.push(ps_.x[i], ps_.z[i] - 0.5 * dz, ps_.u[i], ps_.w[i], ps_.rho[i], ps_.p[i], ps_.m[i],
                          ParticleKind::Fluid);
        ps_.z[i] += 0.5 * dz;
    }
    rings_split_unasked_ += halves.size();
    return append_fluid(halves);
}

double Solver::compute_rates() {
    double vmax = 0;
    rates_kept_ = false;   // the leapfrog's rates of the last step's end are overwritten
    prm_.geometry.renormalise_reach = state_.renormalise_reach;
    const int status = sph_compute_rates(ws_, &prm_, &arr_, &vmax);
    if (status != SPH_OK) fail(status, -1, "rates");
    return vmax;
}

double Solver::rates_of_edited_state() {
    rates_kept_ = false;
    std::fill(ar_.begin(), ar_.end(), 0.0);
    const int status = sph_eos(&prm_, static_cast<int64_t>(ps_.size()), ps_.rho.data(), ps_.p.data(), c_.data());
    if (status != SPH_OK) fail(status, -1, "equation of state");
    return compute_rates();
}

std::vector<ExtraField> Solver::kept_state() const {
    std::vector<ExtraField> f{{"list_x", list_x_, "m"}, {"list_z", list_z_, "m"}};
    if (params_.bulk_viscosity > 0 || rates_kept_) f.push_back({"drho_dt", ar_, "kg/m^3/s"});
    if (rates_kept_) {
        f.push_back({"rate_ax", ax_, "m/s^2"});
        f.push_back({"rate_az", az_, "m/s^2"});
        f.push_back({"xsph_u", xu_, "m/s"});
        f.push_back({"xsph_w", xw_, "m/s"});
    }
    if (!wall_nx_.empty()) {
        f.push_back({"wall_nx", wall_nx_, "1"});
        f.push_back({"wall_nz", wall_nz_, "1"});
        f.push_back({"wall_dback", wall_db_, "m"});
        f.push_back({"wall_dfwd", wall_df_, "m"});
    }
    return f;
}

void Solver::restore_kept_state(const std::function<const std::vector<double>*(std::string_view)>& find) {
    using Part = std::vector<std::pair<const char*, std::vector<double>*>>;
    // a part is restored whole, or not at all
    auto restore = [&find](const Part& part) {
        for (const auto& [name, dst] : part) {
            const std::vector<double>* src = find(name);
            if (src == nullptr || src->size() != dst->size()) return false;
        }
        for (const auto& [name, dst] : part) {
            const std::vector<double>* src = find(name);
            std::copy(src->begin(), src->end(), dst->begin());
        }
        return true;
    };
    restore({{"list_x", &list_x_}, {"list_z", &list_z_}});
    restore({{"drho_dt", &ar_}});
    rates_kept_ = restore({{"rate_ax", &ax_}, {"rate_az", &az_}, {"drho_dt", &ar_}, {"xsph_u", &xu_}, {"xsph_w", &xw_}});
    if (!wall_nx_.empty())
        restore({{"wall_nx", &wall_nx_}, {"wall_nz", &wall_nz_}, {"wall_dback", &wall_db_}, {"wall_dfwd", &wall_df_}});
}

void Solver::set_threads(int n) { sph_set_threads(n); }
int Solver::threads() { return sph_get_threads(); }
int Solver::threads_for(std::size_t n) {
    return sph_threads_for(static_cast<int>(std::min<std::size_t>(n, std::numeric_limits<int>::max())));
}

std::string Solver::openmp_waits() {
    const char* policy = std::getenv("OMP_WAIT_POLICY");
    const char* spins = std::getenv("GOMP_SPINCOUNT");
    std::string p = policy != nullptr ? policy : "";
    for (auto& ch : p) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (spins != nullptr) return fmt::format("spin {}, then sleep", spins);
    if (p == "passive") return "sleep (OMP_WAIT_POLICY=PASSIVE)";
    if (p == "active") return "spin (OMP_WAIT_POLICY=ACTIVE)";
    return "libgomp's default (spin about 3 ms, then sleep)";
}

}  // namespace sphjet
