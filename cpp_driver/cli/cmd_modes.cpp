// sphjet modes: the linear modes of a case's state (core/linear_modes.hpp): the case is run
// for --relax seconds without output, then its dynamics are linearised about that state and the
// fastest-growing modes printed. A growing mode of a state that physics says is stable is an
// instability of the discretisation, measured without waiting for it to grow.
#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "config/load_case.hpp"
#include "core/linear_modes.hpp"
#include "core/solver.hpp"
#include "model/errors.hpp"

namespace sphjet::cli {

namespace {

struct ModesArgs {
    std::string case_path;
    double relax = 0;
    std::size_t top = 10;
    double radius = 0;
    std::vector<std::string> sets;
};

}  // namespace

void register_modes(CLI::App& app) {
    auto args = std::make_shared<ModesArgs>();
    auto* cmd = app.add_subcommand(
        "modes", "Linear modes of a case's state: growth rates of its dynamics linearised by "
                 "central differences (small cases: the Jacobian is dense, 5 x fluid particles square).");
    cmd->add_option("case", args->case_path, "case file (legacy case, INDAT or .toml)")->required();
    cmd->add_option("--relax", args->relax, "run the case this long first [s] (0: its initial state)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--top", args->top, "modes printed, fastest-growing first")->check(CLI::PositiveNumber);
    cmd->add_option("--radius", args->radius, "a column's radius [m]: prints ka of each mode (periodic z)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--set", args->sets, "override a key of a modern case (repeatable)");
    cmd->callback([args]() {
        const LoadedCase lc = load_case(args->case_path, args->sets);
        const SimParams& prm = lc.spec.params;
        // a dense Jacobian of (5 n)^2 doubles and its eigenvectors, O((5 n)^3) work: the a/dx = 10
        // column (900 fluid particles) took 6.6 min of one core and 330 MB, the jets' (225) 4 s
        constexpr std::size_t kMaxFluid = 1000;
        if (lc.particles.n_fluid() > kMaxFluid)
            throw InputError(args->case_path, "too many fluid particles for the dense linearisation",
                             fmt::format("at most {}", kMaxFluid), std::to_string(lc.particles.n_fluid()));
        Solver::set_threads(1);
        Solver s(prm, lc.spec.output, lc.particles);
        long steps = 0;
        while (s.state().time < args->relax) {
            s.step(false);
            s.density_filter_if_due();
            ++steps;
        }
        LinearModeOptions opt;
        opt.dx = prm.dx;
        opt.top = args->top;
        opt.period = prm.periodic_z ? prm.lz : 0.0;
        const LinearModes lm = linear_modes(s, opt);
        std::cout << fmt::format("case {}: {} fluid particles, state at t = {:.6g} s ({} steps), {} "
                                 "variables, {} growing eigenvalues\n",
                                 args->case_path, lm.n_fluid, s.state().time, steps, lm.dimension,
                                 lm.growing);
        // each mode's ka (periodic z and --radius), and the fastest of those with ka > 1 (a
        // column's capillary-stable waves: physics has none of them grow)
        double stable_max = 0;
        int stable_n = -1;
        std::cout << "mode  growth[1/s]  omega[1/s]  n_z   ka     outer  radial\n";
        for (std::size_t k = 0; k < lm.modes.size(); ++k) {
            const LinearMode& m = lm.modes[k];
            const double ka = (m.n_axial >= 0 && args->radius > 0 && opt.period > 0)
                                  ? 2.0 * std::numbers::pi * m.n_axial * args->radius / opt.period
                                  : std::nan("");
            if (ka > 1.0 && m.lambda.real() > stable_max) {
                stable_max = m.lambda.real();
                stable_n = m.n_axial;
            }
            std::cout << fmt::format("{:4d}  {:11.4g}  {:10.4g}  {:3d}  {:5.2f}  {:5.3f}  {:5.3f}\n", k + 1,
                                     m.lambda.real(), std::abs(m.lambda.imag()), m.n_axial, ka,
                                     m.outer_share, m.radial_share);
        }
        const LinearMode top = lm.modes.empty() ? LinearMode{} : lm.modes.front();
        std::cout << fmt::format("SUMMARY growing={} top_growth={:.6g} top_omega={:.6g} top_n={} "
                                 "stable_max_growth={:.6g} stable_max_n={}\n",
                                 lm.growing, top.lambda.real(), std::abs(top.lambda.imag()), top.n_axial,
                                 stable_max, stable_n);
    });
}

}  // namespace sphjet::cli
