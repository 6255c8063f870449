// Simulation parameters: what SPHysics keeps in INDAT, plus what this fork adds.
// One struct travels from the case readers (legacy and modern) to the core.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <utility>

namespace sphjet {

// Numbering follows the legacy case file so that legacy values map one to one; CubicSplineTC, which
// legacy SPHysics does not have, takes the 4 it leaves unused (its case files are refused a 4).
enum class KernelType : int { Gaussian = 1, Quadratic = 2, CubicSpline = 3, CubicSplineTC = 4, Wendland = 5 };
enum class Integrator : int { PredictorCorrector = 1, Leapfrog = 2 };
enum class DensityFilter : int { None = 0, Shepard = 1, MLS = 2 };
enum class ViscosityModel : int { Artificial = 1, Laminar = 2 };
enum class BoundaryType : int { Repulsive = 1, Dynamic = 2 };
enum class Lattice : int { SimpleCubic = 1, BodyCentred = 2 };
// The delta of the CSF force (paper eq 24, a_s = -(sigma/rho) kappa delta): the numbering is the
// core's (sph_params_t::surface_tension.delta). ColourGradient is eq 24 as printed (delta = the
// colour gradient n of eq 18); PressureConsistent replaces it by 2 sum_b V_b grad_a W_ab so that
// the force balances the discrete pressure force at the Laplace pressure at a free surface
// (fortran_core/loops/surface_tension_loops.f90, cases/CASE_FORMAT.md).
enum class SurfaceTensionDelta : int { PressureConsistent = 0, ColourGradient = 1 };
// Planar (x, z) or axisymmetric (r, z): then x is the radius r >= 0, the symmetry axis is the line
// x = 0 and a particle is a ring whose mass is its true 3D mass (core: sph_params_t::geometry.kind,
// fortran_core/physics/axisymmetric.f90, cases/axisymmetric/README.md).
enum class Geometry : int { Planar = 0, Axisymmetric = 1 };
// The axisymmetric pressure and continuity pair (core: sph_params_t::geometry.axis_pair,
// cases/axisymmetric/README.md): the smoothed-radius pair (the default) or the rings pair,
// the 3D SPH density of the rings with the midpoint rule's end correction at the axis.
enum class AxisPair : int { SmoothedRadius = 0, Rings = 1 };
// The curvature in the rings pair's CSF force of the rows below the surface (core:
// sph_params_t::surface_tension.rings_curvature): their neighbours' weighted mean (the default;
// holds a drop's pole) or each row's own (longer round jets; cases/round_jet/README.md).
enum class RingsCurvature : int { NeighbourMean = 0, Own = 1 };
// The driven nozzle's exit profile (NozzleSpec::profile): a rigid plug at u0, or a tube's fully
// developed laminar flow, parabolic across it with the plug's flux (SimParams::drive_profile_a).
enum class NozzleProfile : int { Plug = 0, Parabolic = 1 };
// When a plug particle turns free (NozzleSpec::release): at the first step that starts past the
// orifice, at its crossing (SimParams::drive_release_crossing), or at its crossing with the steps
// landed on the crossings (SimParams::drive_release_landed).
enum class NozzleRelease : int { Step = 0, Crossing = 1, Landed = 2 };
// Whose unit normals enter the free-surface curvature's sums (core:
// sph_params_t::surface_tension.curvature_normals; surface_tension.delta = "pressure_consistent"):
// every particle that passes the normal filter (the default), or only those within h of the surface
// (depth from the colour), whose normals follow the surface's shape (physics/surface_tension.f90).
enum class CurvatureNormals : int { All = 0, SurfaceBand = 1 };
// The free-surface curvature (core: sph_params_t::surface_tension.curvature; surface_tension.delta =
// "pressure_consistent"): the divergence of the unit normals (the default), or the curvature of a
// parabola fitted to the positions of the particles within h of the surface, which does not change
// when they slide along it (physics/surface_tension.f90, cases/round_jet/README.md).
enum class CurvatureModel : int { Normals = 0, SurfaceFit = 1 };

// The case file's name of each value of an enum, written once: the modern reader accepts these
// (through kChoicesOf in model/case_params.hpp), and to_string, the case echo, the HDF5
// attributes and the messages write them. One specialisation per enum that a case names.
template <class E>
struct EnumNames;

template <class E, std::size_t N>
using NameTable = std::array<std::pair<std::string_view, E>, N>;

template <>
struct EnumNames<KernelType> {
    static constexpr NameTable<KernelType, 5> list{{{"gaussian", KernelType::Gaussian},
                                                    {"quadratic", KernelType::Quadratic},
                                                    {"cubic_spline", KernelType::CubicSpline},
                                                    {"cubic_spline_tc", KernelType::CubicSplineTC},
                                                    {"wendland", KernelType::Wendland}}};
};
template <>
struct EnumNames<Integrator> {
    static constexpr NameTable<Integrator, 2> list{
        {{"predictor_corrector", Integrator::PredictorCorrector}, {"leapfrog", Integrator::Leapfrog}}};
};
template <>
struct EnumNames<DensityFilter> {
    static constexpr NameTable<DensityFilter, 3> list{
        {{"none", DensityFilter::None}, {"shepard", DensityFilter::Shepard}, {"mls", DensityFilter::MLS}}};
};
template <>
struct EnumNames<ViscosityModel> {
    static constexpr NameTable<ViscosityModel, 2> list{
        {{"artificial", ViscosityModel::Artificial}, {"laminar", ViscosityModel::Laminar}}};
};
template <>
struct EnumNames<BoundaryType> {
    static constexpr NameTable<BoundaryType, 2> list{
        {{"repulsive", BoundaryType::Repulsive}, {"dynamic", BoundaryType::Dynamic}}};
};
template <>
struct EnumNames<Lattice> {
    static constexpr NameTable<Lattice, 2> list{{{"sc", Lattice::SimpleCubic}, {"bcc", Lattice::BodyCentred}}};
};
template <>
struct EnumNames<SurfaceTensionDelta> {
    static constexpr NameTable<SurfaceTensionDelta, 2> list{
        {{"pressure_consistent", SurfaceTensionDelta::PressureConsistent},
         {"colour_gradient", SurfaceTensionDelta::ColourGradient}}};
};
template <>
struct EnumNames<Geometry> {
    static constexpr NameTable<Geometry, 2> list{
        {{"planar", Geometry::Planar}, {"axisymmetric", Geometry::Axisymmetric}}};
};
template <>
struct EnumNames<AxisPair> {
    static constexpr NameTable<AxisPair, 2> list{
        {{"smoothed_radius", AxisPair::SmoothedRadius}, {"rings", AxisPair::Rings}}};
};
template <>
struct EnumNames<RingsCurvature> {
    static constexpr NameTable<RingsCurvature, 2> list{
        {{"neighbour_mean", RingsCurvature::NeighbourMean}, {"own", RingsCurvature::Own}}};
};
template <>
struct EnumNames<NozzleProfile> {
    static constexpr NameTable<NozzleProfile, 2> list{
        {{"plug", NozzleProfile::Plug}, {"parabolic", NozzleProfile::Parabolic}}};
};
template <>
struct EnumNames<NozzleRelease> {
    static constexpr NameTable<NozzleRelease, 3> list{
        {{"step", NozzleRelease::Step}, {"crossing", NozzleRelease::Crossing}, {"landed", NozzleRelease::Landed}}};
};
template <>
struct EnumNames<CurvatureNormals> {
    static constexpr NameTable<CurvatureNormals, 2> list{
        {{"all", CurvatureNormals::All}, {"surface_band", CurvatureNormals::SurfaceBand}}};
};
template <>
struct EnumNames<CurvatureModel> {
    static constexpr NameTable<CurvatureModel, 2> list{
        {{"normals", CurvatureModel::Normals}, {"surface_fit", CurvatureModel::SurfaceFit}}};
};

template <class E>
concept NamedEnum = requires { EnumNames<E>::list; };

// The name of v in a table ("unknown" for a value outside it).
template <class E, std::size_t N>
[[nodiscard]] std::string name_in(const NameTable<E, N>& table, E v) {
    for (const auto& [name, value] : table)
        if (value == v) return std::string(name);
    return "unknown";
}

// The case file's name of e ("unknown" for a value outside the table).
template <NamedEnum E>
[[nodiscard]] std::string to_string(E e) {
    return name_in(EnumNames<E>::list, e);
}

struct SimParams {
    // Numerics
    KernelType kernel = KernelType::Wendland;
    Integrator integrator = Integrator::PredictorCorrector;
    DensityFilter density_filter = DensityFilter::None;
    int filter_period = 30;            // steps between density filters
    ViscosityModel viscosity = ViscosityModel::Artificial;
    double visc_value = 0.3;           // alpha (artificial) or kinematic nu [m^2/s] (laminar)
    // With laminar viscosity, an artificial viscosity's alpha on top of it (case key
    // numerics.artificial_alpha; rates.f90): numerical damping of particle-scale noise; 0 = off.
    double artificial_alpha = 0.0;
    // Monaghan's Pi of the velocity jump left at the pair's midpoint after each particle's
    // velocity is extrapolated there with its corrected gradient (case key
    // numerics.artificial_reconstruction; physics/viscosity.f90): damps particle-scale
    // motion, the resolved flow only at second order in h.
    bool artificial_reconstruction = false;
    double wall_viscosity = 0.0;       // nu of the repulsive-wall viscous term [m^2/s]
    BoundaryType boundary = BoundaryType::Dynamic;
    int dbc_period = 1;                // steps between dynamic-boundary density updates
    Lattice lattice = Lattice::BodyCentred;
    double xsph_eps = 0.5;
    // Density diffusion in the continuity equation (delta-SPH, Molteni & Colagrossi 2009):
    // its delta; 0 = off (fortran_core/physics/density_diffusion.f90).
    double density_diffusion = 0.0;
    // Bulk viscosity zeta = beta rho0 c0 h in the momentum equation (rates.f90): its beta; 0 = off.
    double bulk_viscosity = 0.0;
    // Particle shifting (Lind et al. 2012; surface_tension_loops.f90): the A of the shifting
    // velocity -A h (c0/10) grad C, tangential at the free surface; 0 = off.
    double shifting = 0.0;
    // Tensile-instability correction (Monaghan 2000): legacy SPHysics turns it on for the
    // Gaussian and cubic-spline kernels and off for the others. -1 = as legacy, 0 off, 1 on.
    int tensile_correction = -1;

    // Equation of state (Tait): p = B [(rho/rho0)^gamma - 1], c = c0 (rho/rho0)^3
    double rho0 = 1000.0;              // [kg/m^3]
    double gamma = 7.0;
    double h_swl = 0.0;                // still-water depth used to set B [m]
    double coef = 10.0;                // c0 = coef * sqrt(g h_swl)
    double B = 0.0;                    // [Pa]; B = coef^2 rho0 g h_swl / gamma

    // Geometry and resolution
    double lx = 0.0, lz = 0.0;         // box size [m]
    double dx = 0.0, dz = 0.0;         // particle spacing [m]
    double h = 0.0;                    // smoothing length [m]
    // A disordered start: each fluid particle of the case's shapes (not a nozzle's plug) moved
    // by a random offset uniform in [-jitter dx, jitter dx] x [-jitter dz, jitter dz], from a
    // generator seeded with jitter_seed (geometry/generator.cpp). 0 = the exact lattice.
    double jitter = 0.0;
    int jitter_seed = 1;

    // Time
    bool variable_dt = true;
    double dt = 1e-4;                  // initial (or fixed) time step [s]
    double dt_max = 0;                 // the variable step's cap [s]; 0: none (time.dt_max)
    double cfl = 0.2;
    double tmax = 1.0;                 // end time [s]
    double out = 0.01;                 // output interval [s]
    double trec_ini = 0.0;             // time of the first output [s]

    // Body force and surface tension (this fork's additions)
    double gx = 0.0, gz = -9.81;       // gravity [m/s^2]
    double sigma = 0.0;                // surface tension coefficient [N/m]; 0 = off
    SurfaceTensionDelta st_delta = SurfaceTensionDelta::PressureConsistent;
    // Moving boundary particles (a legacy gate, CaseSpec::gates): from t >= gate_t_start they
    // move with (gate_vx, gate_vz), each stopping at z = gate_z_cap; at rest before.
    double gate_vx = 0.0, gate_vz = 0.0;  // [m/s]
    double gate_t_start = 0.0;            // [s]
    double gate_z_cap = 0.0;              // [m]; the generator sets it (top particle + 0.1 h)
    // A driven nozzle (CaseSpec::nozzle, the jets): the fluid particles whose start-of-step
    // position lies upstream of the orifice line through (drive_x0, drive_z0) across the unit
    // axis (drive_ex, drive_ez), within drive_half_width of the axis, move as a rigid plug at
    // drive_u along the axis (fortran_core/integrate/nozzle_drive.f90). drive_u = 0: none.
    double drive_u = 0.0;                     // [m/s]
    double drive_x0 = 0.0, drive_z0 = 0.0;    // orifice centre [m]
    double drive_ex = 0.0, drive_ez = -1.0;   // jet axis (unit)
    double drive_half_width = 0.0;            // [m]
    // A parabolic exit profile (NozzleSpec::profile): a plug particle at distance l from the axis
    // moves at drive_u drive_profile_k (1 - l^2 / drive_profile_a^2), drive_profile_a = d0 / 2;
    // drive_profile_k makes the lattice's flux drive_u's (nozzle_profile_k); fluid
    // farther than drive_profile_lmax (the outer line) moves with that line, and the plug holds
    // the density drive_profile_rho (plug_state's). 0: a plug.
    double drive_profile_a = 0.0;             // [m]
    double drive_profile_k = 0.0;             // [1]
    double drive_profile_lmax = 0.0;          // [m]
    double drive_profile_rho = 0.0;           // [kg/m^3]
    // A plug particle whose step carries it past the orifice leaves the step with the plug's
    // velocity plus its acceleration (rates and gravity) over the part of the step it spent past
    // the orifice (NozzleSpec::release = crossing). false: with the plug's velocity.
    bool drive_release_crossing = false;
    // Each step is shortened where needed so that the plug's leading row crosses the orifice line at
    // its end (NozzleSpec::release = landed; fortran_core/integrate/nozzle_drive.f90, landed_step):
    // every row turns free at the line, none a part of a step late. Implies drive_release_crossing.
    bool drive_release_landed = false;
    // The plug speed may carry an imposed disturbance (NozzleSpec::disturbance): over the step
    // that starts at time t it is drive_u (1 + drive_eps sin(drive_omega t)).
    double drive_eps = 0.0;                   // relative amplitude
    double drive_omega = 0.0;                 // [rad/s]
    // Where fluid leaves the domain: false (legacy) beyond the fixed boundary particles'
    // extent (x and floor; no top); true the box [0, lx] x [0, lz] (open jets, no box walls).
    bool domain_box = false;
    // Planar or axisymmetric (r, z) geometry, and a domain periodic in z with period lz
    // (case keys domain.geometry, domain.periodic_z; either geometry).
    Geometry geometry = Geometry::Planar;
    bool periodic_z = false;
    // The axisymmetric pair (case key domain.axis_pair; axisymmetric only).
    AxisPair axis_pair = AxisPair::SmoothedRadius;
    // Rings too heavy for their radius split in two after each step (case key
    // domain.split_axis_rings; rings pair only; Solver::split_heavy_rings).
    bool split_axis_rings = false;
    // The rings pair's continuity renormalised along r and z (case key
    // domain.renormalise_ring_continuity; fortran_core/loops/axisymmetric_loops.f90).
    bool renormalise_ring_continuity = false;
    // Along a jet it stops this many nozzle diameters short of the jet's end, not at the end
    // (case key domain.renormalise_margin_d0; JetRun::Check::reach).
    double renormalise_margin_d0 = 0.0;
    // Each ring's XSPH correction over its planar kernel sum where that exceeds 1 (case key
    // domain.bound_ring_xsph; fortran_core/loops/axisymmetric_loops.f90).
    bool bound_ring_xsph = false;
    // Its surface rows' curvature (case key surface_tension.rings_curvature; rings pair only).
    RingsCurvature rings_curvature = RingsCurvature::NeighbourMean;
    // The normals of the free-surface curvature (case key surface_tension.curvature_normals).
    CurvatureNormals curvature_normals = CurvatureNormals::All;
    // The free-surface curvature (case key surface_tension.curvature).
    CurvatureModel curvature = CurvatureModel::Normals;
    // Each free body's net surface-tension force removed (case key
    // surface_tension.balance_free_bodies; fortran_core/loops/surface_tension_loops.f90).
    bool balance_free_bodies = false;
    // Free rings thinner than the kernel's reach take the normals' curvature (case key
    // surface_tension.thin_rings_normals; fortran_core/loops/free_body_loops.f90).
    bool thin_rings_normals = false;
    // The fewest points a surface fit may pass through (case key surface_tension.fit_points_min;
    // fortran_core/physics/surface_tension.f90).
    int fit_points_min = 3;

    // Sound speed at rest, from B: c0 = sqrt(gamma B / rho0)
    [[nodiscard]] double c0() const;
    // Whether the tensile correction is on, resolving "as legacy".
    [[nodiscard]] bool tensile_on() const;
};

// A note for the run log when the case's time.dt exceeds the CFL step of the fluid at rest,
// cfl h / c0 (the bound of the step control before anything moves), else "". With variable dt
// the first step takes time.dt all the same, as in legacy SPHysics: the particles get a kick,
// and a case refined from a coarser one without scaling its time.dt gets a large one.
[[nodiscard]] std::string initial_step_note(const SimParams& p);

}  // namespace sphjet
