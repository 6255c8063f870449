// The only caller of the Fortran core (capi/sphjet_core.h): it lends the particle arrays,
// turns status codes into exceptions with a diagnostic, and keeps the integrator work space.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/hdf5_output.hpp"
#include "model/case_spec.hpp"
#include "model/params.hpp"
#include "model/particles.hpp"
#include "model/run_state.hpp"
#include "sphjet_core.h"

namespace sphjet {

// sph_params_t from the case parameters.
[[nodiscard]] sph_params_t core_params(const SimParams& p, const OutputSpec& out,
                                       const DomainBounds& dom);

struct StepReport {
    double dt_taken = 0;
    std::int64_t removed = 0;
    std::vector<std::int64_t> removed_ids;  // ids of the particles removed in this step
};

class Solver {
public:
    Solver(const SimParams& params, const OutputSpec& output, ParticleSet particles);
    ~Solver();
    Solver(const Solver&) = delete;
    Solver& operator=(const Solver&) = delete;

    // One step of numerics.integrator with state().dt; updates RunState (time, legacy clock,
    // step, dt, counters). Throws SimulationError with step, time, particle and cause.
    // fields: whether colour(), st_nx(), st_nz() and curvature() are to hold this step's
    // surface-tension fields afterwards (an output follows); otherwise they keep what they
    // held and the core does not copy them out (the step itself is the same either way).
    StepReport step(bool fields = true);
    // Density filter (Shepard or MLS, as the parameters say); no-op when none.
    void density_filter();
    // The density filter when its period has come: after every filter_period-th step
    // (numerics.filter_period), as legacy SPHysics; no-op otherwise or when there is none.
    void density_filter_if_due();
    // NaN/Inf and density band check of the whole state; throws SimulationError.
    void check_state() const;
    // Makes these fluid particles inactive as the core does with those that leave the domain
    // (state_checks.f90 check_domain: velocity zeroed, no longer in any sum), and has the
    // next step list the pairs again from the positions then, as the core does after such a
    // removal (list_x = NaN, which a checkpoint keeps: a resumed run does the same). They
    // are not counted in RunState::n_removed (the domain's leavers). Returns how many were
    // active.
    std::size_t deactivate(const std::vector<std::size_t>& indices);
    // Appends fluid particles (ids: their indices), at rest in the integrator's sense (no
    // rates yet), their pressure and sound speed from their densities; the pairs are listed
    // again at the next step. The leapfrog's rates kept from the last step are then
    // evaluated again, unless plug_rows: rows entering a driven nozzle's plug, whose rates
    // are zero (every neighbour moves with the same velocity, none across the axis) and add
    // nothing to their neighbours'. Returns how many.
    std::size_t append_fluid(const ParticleSet& more, bool plug_rows = false);
    // domain.split_axis_rings: each ring too heavy for its radius (sph_axis_rings_to_split)
    // becomes two of half its mass, at z + dz/2 (itself) and z - dz/2 (appended), with its
    // velocity, density and pressure: mass, momentum and centre of mass kept. Returns how many
    // were split (0 when the key is off).
    std::size_t split_heavy_rings();
    // The rings split since the last call (for the log; not kept by a checkpoint).
    std::size_t rings_split_since_asked() { return std::exchange(rings_split_unasked_, 0); }
    // Pair rates at the current state (tests and diagnostics); returns max visc term.
    double compute_rates();
    // Diagnostics (core/linear_modes.cpp): the particles to edit in place, then
    // rates_of_edited_state() for the rates of the edited state, with pressure and sound speed
    // from its densities (Tait); returns max visc term. An edited state has no last evaluation,
    // so numerics.bulk_viscosity's term (which uses its density rates) is left out of them.
    [[nodiscard]] ParticleSet& particles_to_edit() {
        rates_kept_ = false;   // an edited state has no rates of its own yet
        return ps_;
    }
    double rates_of_edited_state();

    [[nodiscard]] const ParticleSet& particles() const { return ps_; }
    [[nodiscard]] const std::vector<double>& sound_speed() const { return c_; }
    [[nodiscard]] const std::vector<double>& ax() const { return ax_; }
    [[nodiscard]] const std::vector<double>& az() const { return az_; }
    [[nodiscard]] const std::vector<double>& ar() const { return ar_; }
    // The XSPH velocity correction of the last rates (dx/dt = u + xsph_u).
    [[nodiscard]] const std::vector<double>& xsph_u() const { return xu_; }
    [[nodiscard]] const std::vector<double>& xsph_w() const { return xw_; }
    // Surface-tension fields (empty when sigma = 0).
    [[nodiscard]] const std::vector<double>& colour() const { return colour_; }
    [[nodiscard]] const std::vector<double>& st_nx() const { return st_nx_; }
    [[nodiscard]] const std::vector<double>& st_nz() const { return st_nz_; }
    [[nodiscard]] const std::vector<double>& curvature() const { return kappa_; }
    // The core's state beyond the particles that a checkpoint keeps, so that a resumed run
    // steps as the first one would have gone on (bitwise resume), as named fields:
    // - list_x, list_z: the positions at the core's last neighbour-list build (NaN: none yet),
    //   so that the resumed run lists the pairs in the same order;
    // - drho_dt: the density rates of the last evaluation, where the bulk viscosity uses them
    //   in the next one or the leapfrog keeps its rates;
    // - rate_ax, rate_az, xsph_u, xsph_w (with drho_dt): numerics.integrator = "leapfrog", the
    //   rates of the state as it is (the last step's end), where they are kept;
    // - wall_nx, wall_nz, wall_dback, wall_dfwd: the repulsive-wall geometry (unit normal,
    //   spacing to the wall neighbours), which sph_prepare computes from the positions at
    //   construction: a moving gate would give it again from moved positions, which round
    //   differently.
    [[nodiscard]] std::vector<ExtraField> kept_state() const;
    // Restores what kept_state() gave, from a checkpoint's arrays (find: the array of that
    // name, or nullptr). A part with an array missing or of another length is left to the
    // core: the pairs listed at the current positions, the leapfrog's rates evaluated at the
    // next step's start, the wall geometry as sph_prepare gave it.
    void restore_kept_state(const std::function<const std::vector<double>*(std::string_view)>& find);
    [[nodiscard]] RunState& state() { return state_; }
    [[nodiscard]] const RunState& state() const { return state_; }
    [[nodiscard]] const SimParams& params() const { return params_; }
    [[nodiscard]] const sph_params_t& core() const { return prm_; }
    // A fixed step (time.variable_dt = false) against the step the CFL and force conditions
    // would have taken (RunState::dt_new), over the steps this Solver took: how many took more,
    // and the smallest such step [s] (infinity before the first step). The leapfrog's: the
    // predictor-corrector evaluates no such step when the step is fixed (dt_new stays 0).
    struct FixedStepRecord {
        std::int64_t steps = 0, above = 0;
        double smallest = std::numeric_limits<double>::infinity();
    };
    [[nodiscard]] const FixedStepRecord& fixed_step_record() const { return fixed_record_; }

    static void set_threads(int n);
    static int threads();
    // The threads a step of n particles runs on: threads(), fewer for a small case (the
    // core's sph_threads_for).
    static int threads_for(std::size_t n);
    // How OpenMP threads wait at barriers, from the environment libgomp read at start-up
    // (cli/main.cpp sets it unless the user did): e.g. "spin 5000, then sleep".
    static std::string openmp_waits();

private:
    void bind_arrays();
    [[noreturn]] void fail(int status, std::int64_t particle, const std::string& where) const;

    SimParams params_;
    OutputSpec output_;
    ParticleSet ps_;
    RunState state_;
    sph_params_t prm_{};
    sph_arrays_t arr_{};
    std::vector<double> c_, xo_, zo_, uo_, wo_, rhoo_, ax_, az_, ar_, xu_, xw_;
    std::vector<int> wall_prev_, wall_next_;
    std::vector<double> wall_nx_, wall_nz_, wall_db_, wall_df_;
    std::vector<double> colour_, st_nx_, st_nz_, kappa_;
    std::vector<double> list_x_, list_z_;
    std::size_t rings_split_unasked_ = 0;
    FixedStepRecord fixed_record_;
    bool rates_kept_ = false;  // leapfrog: the rates arrays are the current state's
    std::vector<char> was_active_;  // active flags before the last step with a removal
    void* ws_ = nullptr;
};

// Text of an SPH_* status.
[[nodiscard]] std::string status_text(int status);

}  // namespace sphjet
