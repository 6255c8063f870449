// The description of every case parameter (model/case_params.hpp says what reads it).
#include "model/case_params.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

// GCC 12 warns of the members a designated initializer leaves out; they take their defaults.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace sphjet {

namespace {

using K = KeyType;

// The choices the case codes as numbers or flags (the enums' are kChoicesOf<E>).
constexpr Choice kTensile[] = {{"auto", -1}, {"on", 1}, {"off", 0}};
constexpr Choice kPrecision[] = {{"single", 1}, {"double", 2}};
constexpr Choice kObstacleShapes[] = {{"rectangle", 1}};
constexpr Choice kObstacleKinds[] = {{"solid", 1}, {"walls", 2}};
constexpr Choice kGateFacings[] = {{"left", -1}, {"right", 1}};
constexpr Choice kDiscLattices[] = {{"case", 0}, {"rings", 1}};
constexpr Choice kNozzleAxes[] = {{"down", 0}, {"up", 1}, {"left", 2}, {"right", 3}};
// The lattice's "lattice_name" attribute in HDF5 files: the long names its files have carried.
constexpr Choice kLatticeH5Names[] = {{"simple_cubic", static_cast<std::int64_t>(Lattice::SimpleCubic)},
                                      {"body_centred", static_cast<std::int64_t>(Lattice::BodyCentred)}};

template <NamedEnum E>
constexpr std::span<const Choice> names() {
    return kChoicesOf<E>;
}

constexpr unsigned kRead = kHandRead;
constexpr unsigned kEcho = kHandEcho;

// Sections in the order of the echo; within one, keys in the order of the echo. The rows
// without a key (derived SimParams members) come last. SimParams' rows reach HDF5 in the
// order of its members (io/h5_util.cpp).
const Param kParams[] = {
    {.key = "format_version", .type = K::Int, .def = "1", .allowed = "1", .doc = "version of this format",
     .legacy = "(none)", .hand = kRead | kEcho},

    // [numerics]
    {.key = "numerics.kernel", .attr = "kernel", .type = K::String, .member = member<&SimParams::kernel>(),
     .choices = names<KernelType>(),
     .allowed = "cubic_spline_tc: the cubic spline with Thomas & Couchman's (1992) gradient, df/dq held at "
                "its q = 2/3 value inside it (linear to 0 below q = 0.25), which keeps rows from pairing; "
                "no legacy number, HDF5 output only",
     .doc = "smoothing kernel",
     .legacy = "`Kernel: 1=gaussian, 2=quadratic; 3=cubic; 5=Wendland`"},
    {.key = "numerics.integrator", .attr = "integrator", .type = K::String,
     .member = member<&SimParams::integrator>(), .choices = names<Integrator>(),
     .allowed = "leapfrog: without boundary particles, with numerics.bulk_viscosity > 0, HDF5 output only",
     .doc = "time integration: predictor_corrector (SPHysics', two evaluations of the rates per step) or "
            "leapfrog (kick-drift-kick, one evaluation per step; fortran_core/integrate/leapfrog.f90)",
     .legacy = "`Time-stepping algorithm` (1)"},
    {.key = "numerics.density_filter", .attr = "density_filter", .type = K::String,
     .member = member<&SimParams::density_filter>(), .choices = names<DensityFilter>(),
     .doc = "density filter", .legacy = "`Density Filter: 0=none, 1=Shepard filter, 2=MLS`"},
    {.key = "numerics.filter_period", .attr = "filter_period", .type = K::Int, .unit = "steps",
     .member = member<&SimParams::filter_period>(), .range = between(1, kNoLimit),
     .doc = "steps between density filters", .legacy = "`ndt_FilterPerform` (only present when a filter is on)"},
    {.key = "numerics.viscosity", .attr = "viscosity", .type = K::String, .member = member<&SimParams::viscosity>(),
     .choices = names<ViscosityModel>(), .doc = "viscosity model",
     .legacy = "`Viscosity treatment: 1=artificial; 2=laminar`"},
    {.key = "numerics.alpha", .type = K::Float, .unit = "1", .range = kNonNegative, .def = "0.3",
     .allowed = "artificial viscosity only", .doc = "artificial viscosity coefficient (SimParams::visc_value)",
     .legacy = "`Viscosity value` when treatment = 1", .hand = kRead | kEcho},
    {.key = "numerics.artificial_alpha", .attr = "artificial_alpha", .type = K::Float, .unit = "1",
     .member = member<&SimParams::artificial_alpha>(), .range = between(0, 1),
     .allowed = "0 = off; needs numerics.viscosity = \"laminar\"",
     .doc = "alpha of Monaghan's artificial viscosity added to the laminar one (approaching pairs): damps "
            "particle-scale noise, adds about alpha c0 h / 8 of shear viscosity",
     .legacy = "(none)", .h5_optional = true},
    {.key = "numerics.artificial_reconstruction", .attr = "artificial_reconstruction", .type = K::Bool,
     .member = member<&SimParams::artificial_reconstruction>(), .def = "false",
     .allowed = "needs an artificial viscosity (numerics.viscosity = \"artificial\" or numerics.artificial_alpha > 0)",
     .doc = "the artificial viscosity acts on the velocity jump left at each pair's midpoint after both velocities "
            "are extrapolated there with their corrected gradients (van Leer limited): a linear velocity field "
            "is not damped, particle-scale motion is",
     .legacy = "(none)", .h5_optional = true},
    {.key = "numerics.xsph_eps", .attr = "xsph_eps", .type = K::Float, .unit = "1",
     .member = member<&SimParams::xsph_eps>(), .range = between(0, 1), .allowed = "0 = off",
     .doc = "XSPH velocity correction, 0 = off", .legacy = "fixed at 0.5 by SPHYSICSgen_2D"},
    {.key = "numerics.density_diffusion", .attr = "density_diffusion", .type = K::Float, .unit = "1",
     .member = member<&SimParams::density_diffusion>(), .range = between(0, 1), .allowed = "0 = off; 0.1 is usual",
     .doc = "delta of the density diffusion drho_a/dt += 2 delta h c0 sum_b (rho_a - rho_b) F_ab V_b (fluid pairs)",
     .legacy = "(none)", .echo = "delta-SPH (Molteni-Colagrossi); no hydrostatic correction", .h5_optional = true},
    {.key = "numerics.bulk_viscosity", .attr = "bulk_viscosity", .type = K::Float, .unit = "1",
     .member = member<&SimParams::bulk_viscosity>(), .range = between(0, 1), .allowed = "0 = off",
     .doc = "beta of a bulk viscosity zeta = beta rho0 c0 h: the momentum equation's pressure is p - zeta div v "
            "(div v = -drho/dt / rho of the last evaluation); damps sound waves, not divergence-free flow",
     .legacy = "(none)", .h5_optional = true},
    {.key = "numerics.shifting", .attr = "shifting", .type = K::Float, .unit = "1",
     .member = member<&SimParams::shifting>(), .range = between(0, 100),
     .allowed = "0 = off; needs surface tension (surface_tension.sigma > 0), whose passes find the free surface",
     .doc = "particle shifting (Lind et al. 2012): each fluid particle drifts with the velocity "
            "-A h (c0/10) grad C (C = sum_b V_b W_ab, the kernel's sum) added to its XSPH velocity; where the "
            "surface cuts its kernel (colour below 0.97) only its part along the surface; axisymmetric: "
            "rings closer to the axis than h/2 only along the axis",
     .legacy = "(none)", .h5_optional = true},
    {.key = "numerics.tensile_correction", .attr = "tensile_correction", .type = K::String,
     .member = member<&SimParams::tensile_correction>(), .choices = kTensile,
     .allowed = "auto: on for gaussian, cubic_spline and cubic_spline_tc, as legacy",
     .doc = "tensile-instability correction (Monaghan 2000)", .legacy = "implied by the kernel",
     .echo = "auto (legacy: on for gaussian, cubic_spline) | on | off"},
    {.key = "numerics.boundary", .attr = "boundary", .type = K::String, .member = member<&SimParams::boundary>(),
     .choices = names<BoundaryType>(), .allowed = "repulsive: Monaghan-Kos / Rogers et al. 2008",
     .doc = "boundary particles' model", .legacy = "`Boundary Conditions: 1=Repulsive Force; 2=Dalrymple`",
     .echo = "{choices} (repulsive: Monaghan-Kos/Rogers)"},
    {.key = "numerics.dbc_period", .attr = "dbc_period", .type = K::Int, .unit = "steps",
     .member = member<&SimParams::dbc_period>(), .range = between(1, kNoLimit),
     .doc = "steps between dynamic-boundary density updates", .legacy = "`ndt_DBCPerform` (dynamic boundaries)"},
    {.key = "numerics.wall_viscosity", .attr = "wall_viscosity", .type = K::Float, .unit = "m^2/s",
     .member = member<&SimParams::wall_viscosity>(), .range = kNonNegative,
     .doc = "nu of the repulsive-wall viscous term", .legacy = "`Wall viscosity value for Repulsive Force BC`",
     .echo = "m^2/s, repulsive walls only"},
    {.key = "numerics.lattice", .attr = "lattice", .type = K::String, .member = member<&SimParams::lattice>(),
     .choices = names<Lattice>(), .doc = "lattice the fluid shapes are filled on",
     .legacy = "`Initial Fluid Particle Structure: 1= SC, 2= BCC`", .h5_choices = kLatticeH5Names},

    // [fluid]
    {.key = "fluid.rho0", .attr = "rho0", .type = K::Float, .unit = "kg/m^3", .member = member<&SimParams::rho0>(),
     .range = kPositive, .doc = "reference density [kg/m^3]", .legacy = "fixed at 1000 by SPHYSICSgen_2D"},
    {.key = "fluid.gamma", .attr = "gamma", .type = K::Float, .unit = "1", .member = member<&SimParams::gamma>(),
     .range = kPositive, .doc = "Tait exponent", .legacy = "fixed at 7"},
    {.key = "fluid.c0", .type = K::Float, .unit = "m/s", .range = kPositive, .def = " ",
     .doc = "sound speed at rest; B = rho0 c0^2 / gamma", .legacy = "(none: legacy gives coef and h_SWL)",
     .hand = kRead | kEcho},
    {.key = "fluid.coef", .attr = "coef", .type = K::Float, .unit = "1", .member = member<&SimParams::coef>(),
     .range = kPositive, .def = " ", .allowed = "with `h_swl`", .doc = "c0 = coef sqrt(|gz| h_swl)",
     .legacy = "`Coefficient of speed of sound`", .hand = kRead | kEcho},
    {.key = "fluid.h_swl", .attr = "h_swl", .type = K::Float, .unit = "m", .member = member<&SimParams::h_swl>(),
     .range = kPositive, .def = " ", .allowed = "with `coef`", .doc = "still-water depth that sets c0 and B",
     .legacy = "`Maximum Depth (h_SWL) to calculate B`", .hand = kRead | kEcho},
    {.key = "fluid.mu", .type = K::Float, .unit = "Pa s", .range = kNonNegative, .def = " ",
     .doc = "dynamic viscosity, nu = mu / rho0", .legacy = "(none)", .hand = kRead | kEcho},
    {.key = "fluid.nu", .type = K::Float, .unit = "m^2/s", .range = kNonNegative, .def = " ",
     .doc = "kinematic viscosity", .legacy = "`Viscosity value` when treatment = 2", .hand = kRead | kEcho},

    // [[fluid.block]]
    {.key = "fluid.block[].xmin", .type = K::Float, .unit = "m", .member = member<&FluidBlock::r, &Rect::xmin>(),
     .allowed = "in [0, lx], < xmax", .doc = "the left edge", .legacy = "`Cube containing particles : XMin, Xmax` (after \"Initial conditions\")",
     .echo = "m", .required = true, .hand = kRead},
    {.key = "fluid.block[].xmax", .type = K::Float, .unit = "m", .member = member<&FluidBlock::r, &Rect::xmax>(),
     .allowed = "in [0, lx]", .doc = "the right edge", .legacy = "same line", .echo = "m", .required = true,
     .hand = kRead},
    {.key = "fluid.block[].zmin", .type = K::Float, .unit = "m", .member = member<&FluidBlock::r, &Rect::zmin>(),
     .allowed = "in [0, lz], < zmax", .doc = "the bottom edge", .legacy = "`Cube containing particles : ZMin, Zmax`",
     .echo = "m", .required = true, .hand = kRead},
    {.key = "fluid.block[].zmax", .type = K::Float, .unit = "m", .member = member<&FluidBlock::r, &Rect::zmax>(),
     .allowed = "in [0, lz]", .doc = "the top edge", .legacy = "same line", .echo = "m", .required = true,
     .hand = kRead},
    {.key = "fluid.block[].u0", .type = K::Float, .unit = "m/s", .member = member<&FluidBlock::u0>(),
     .doc = "initial velocity [m/s]", .legacy = "(none: legacy starts at rest)"},
    {.key = "fluid.block[].w0", .type = K::Float, .unit = "m/s", .member = member<&FluidBlock::w0>(),
     .doc = "initial vertical velocity", .legacy = "(none)", .echo = "m/s"},

    // [[fluid.disc]]
    {.key = "fluid.disc[].xc", .type = K::Float, .unit = "m", .member = member<&FluidDisc::xc>(),
     .allowed = "xc - radius >= 0, xc + radius <= lx", .doc = "the centre x", .legacy = "(none)",
     .echo = "centre [m]", .required = true, .hand = kRead},
    {.key = "fluid.disc[].zc", .type = K::Float, .unit = "m", .member = member<&FluidDisc::zc>(),
     .allowed = "zc - radius >= 0, zc + radius <= lz", .doc = "the centre z", .legacy = "(none)", .echo = "m",
     .required = true, .hand = kRead},
    {.key = "fluid.disc[].radius", .type = K::Float, .unit = "m", .member = member<&FluidDisc::radius>(),
     .range = kPositive, .doc = "the radius", .legacy = "(none)", .echo = "m", .required = true, .hand = kRead},
    {.key = "fluid.disc[].lattice", .type = K::String, .member = member<&FluidDisc::rings>(),
     .choices = kDiscLattices, .doc = "the numerics.lattice points inside, or concentric rings", .legacy = "(none)",
     .echo = "case (numerics.lattice points inside) | rings (concentric rings, smooth edge)"},
    {.key = "fluid.disc[].elongation", .type = K::Float, .unit = "1", .member = member<&FluidDisc::elongation>(),
     .range = between(-0.5, 0.5, true, true), .allowed = "the stretched disc inside the box",
     .doc = "stretch to an ellipse of the same area", .legacy = "(none)",
     .echo = "e: stretched to semi-axes R(1+e) (x), R/(1+e) (z), area kept; 0 = round"},
    {.key = "fluid.disc[].u0", .type = K::Float, .unit = "m/s", .member = member<&FluidDisc::u0>(),
     .doc = "initial velocity [m/s]", .legacy = "(none)"},
    {.key = "fluid.disc[].w0", .type = K::Float, .unit = "m/s", .member = member<&FluidDisc::w0>(),
     .doc = "initial vertical velocity", .legacy = "(none)", .echo = "m/s"},

    // [[fluid.cylinder]]
    {.key = "fluid.cylinder[].radius", .type = K::Float, .unit = "m", .member = member<&FluidCylinder::radius>(),
     .range = kPositive, .allowed = "radius (1 + abs(eps)) <= lx", .doc = "the radius a", .legacy = "(none)",
     .echo = "a [m]", .required = true, .hand = kRead},
    {.key = "fluid.cylinder[].eps", .type = K::Float, .unit = "1", .member = member<&FluidCylinder::eps>(),
     .range = between(-0.5, 0.5, true, true), .doc = "relative amplitude of the perturbation", .legacy = "(none)"},
    {.key = "fluid.cylinder[].wavelength", .type = K::Float, .unit = "m", .member = member<&FluidCylinder::wavelength>(),
     .range = kPositive, .def = "**required** when eps != 0", .doc = "wavelength of the perturbation",
     .legacy = "(none)", .echo = "m", .hand = kEcho},
    {.key = "fluid.cylinder[].zmin", .type = K::Float, .unit = "m", .member = member<&FluidCylinder::zmin>(),
     .def = "0", .allowed = "in [0, lz]", .doc = "bottom of the cylinder", .legacy = "(none)", .echo = "m",
     .hand = kRead},
    {.key = "fluid.cylinder[].zmax", .type = K::Float, .unit = "m", .member = member<&FluidCylinder::zmax>(),
     .def = "lz", .allowed = "in [0, lz], > zmin", .doc = "top of the cylinder", .legacy = "(none)", .echo = "m",
     .hand = kRead},

    // [[fluid.square]]
    {.key = "fluid.square[].xc", .type = K::Float, .unit = "m", .member = member<&FluidSquare::xc>(),
     .allowed = "the square inside the box", .doc = "the centre x", .legacy = "(none)", .echo = "centre [m]",
     .required = true, .hand = kRead},
    {.key = "fluid.square[].zc", .type = K::Float, .unit = "m", .member = member<&FluidSquare::zc>(),
     .allowed = "the square inside the box", .doc = "the centre z", .legacy = "(none)", .echo = "m",
     .required = true, .hand = kRead},
    {.key = "fluid.square[].side", .type = K::Float, .unit = "m", .member = member<&FluidSquare::side>(),
     .range = kPositive, .doc = "the side length", .legacy = "(none)", .echo = "m", .required = true,
     .hand = kRead},
    {.key = "fluid.square[].u0", .type = K::Float, .unit = "m/s", .member = member<&FluidSquare::u0>(),
     .doc = "initial velocity [m/s]", .legacy = "(none)"},
    {.key = "fluid.square[].w0", .type = K::Float, .unit = "m/s", .member = member<&FluidSquare::w0>(),
     .doc = "initial vertical velocity", .legacy = "(none)", .echo = "m/s"},

    // [surface_tension]
    {.key = "surface_tension.sigma", .attr = "sigma", .type = K::Float, .unit = "N/m",
     .member = member<&SimParams::sigma>(), .range = kNonNegative, .def = "0 (off)",
     .doc = "surface tension coefficient, CSF (Morris 2000)", .legacy = "(none: legacy has no surface tension)",
     .echo = "N/m, CSF (Morris 2000); 0 = off"},
    {.key = "surface_tension.delta", .attr = "st_delta", .type = K::String, .member = member<&SimParams::st_delta>(),
     .choices = names<SurfaceTensionDelta>(), .doc = "the delta of the CSF force", .legacy = "(none)",
     .echo = "{choices} (pressure_consistent: free surface, right Laplace jump; colour_gradient: paper eq 24 as "
             "printed, about 0.13 of sigma at a free surface)",
     .h5_optional = true},
    {.key = "surface_tension.rings_curvature", .attr = "rings_curvature", .type = K::String,
     .member = member<&SimParams::rings_curvature>(), .choices = names<RingsCurvature>(),
     .allowed = "needs `domain.axis_pair = \"rings\"` and `delta = \"pressure_consistent\"`",
     .doc = "curvature of the rings pair's rows below the surface", .legacy = "(none)",
     .echo = "{choices} (neighbour_mean: holds a drop's pole; own: longer round jets, pole lost)",
     .hand = kRead | kEcho, .h5_optional = true},
    {.key = "surface_tension.curvature_normals", .attr = "curvature_normals", .type = K::String,
     .member = member<&SimParams::curvature_normals>(), .choices = names<CurvatureNormals>(),
     .allowed = "needs `delta = \"pressure_consistent\"`",
     .doc = "whose unit normals enter the free-surface curvature: every filtered particle's, or those within h "
            "of the surface",
     .legacy = "(none)",
     .echo = "{choices} (surface_band: only the normals within h of the surface; for h = 2 dx)",
     .hand = kRead | kEcho, .h5_optional = true},
    {.key = "surface_tension.curvature", .attr = "curvature", .type = K::String,
     .member = member<&SimParams::curvature>(), .choices = names<CurvatureModel>(),
     .allowed = "needs `delta = \"pressure_consistent\"`",
     .doc = "the free-surface curvature: the divergence of the unit normals, or a parabola fitted to the "
            "outer row of particles",
     .legacy = "(none)",
     .echo = "{choices} (surface_fit: a curve through the surface particles; no particle-scale waves grow)",
     .hand = kRead | kEcho, .h5_optional = true},
    {.key = "surface_tension.balance_free_bodies", .attr = "balance_free_bodies", .type = K::Bool,
     .member = member<&SimParams::balance_free_bodies>(), .def = "false", .allowed = "needs `sigma > 0`",
     .doc = "the surface tension's net force on each free body (fluid joined by pairs closer than 2h that "
            "touches no boundary particle and no driven nozzle fluid) taken off as a uniform acceleration of "
            "that body: along z in the axisymmetric geometry, along x and z in the planar one. Under a uniform "
            "sigma a closed surface's net force is zero; the CSF force of a fragment of a few particles is not",
     .legacy = "(none)", .h5_optional = true},
    {.key = "surface_tension.thin_rings_normals", .attr = "thin_rings_normals", .type = K::Bool,
     .member = member<&SimParams::thin_rings_normals>(), .def = "false",
     .allowed = "needs the axisymmetric geometry and `curvature = \"surface_fit\"`",
     .doc = "a free ring (a free body with no particle within h of the axis) whose meridian cross-section is "
            "narrower than a tube of radius 1.5 h takes the normals' curvature instead of the surface fit, "
            "which draws a tube narrower than the kernel's reach too sharply bent",
     .legacy = "(none)", .h5_optional = true},

    {.key = "surface_tension.fit_points_min", .attr = "fit_points_min", .type = K::Int, .unit = "points",
     .member = member<&SimParams::fit_points_min>(), .range = between(3, kNoLimit), .def = "3",
     .allowed = "needs `curvature = \"surface_fit\"` when above 3",
     .doc = "the fewest outer-row points a surface fit may pass through: a fit through fewer is refused and its "
            "particle keeps the normals' curvature; with the rings pair's `neighbour_mean` it enters no mean and "
            "takes its neighbours'. 3 determine the parabola and no more",
     .legacy = "(none)", .h5_optional = true},

    // [gravity]
    {.key = "gravity.gx", .attr = "gx", .type = K::Float, .unit = "m/s^2", .member = member<&SimParams::gx>(),
     .doc = "gravity along x", .legacy = "(none: legacy fixes g = (0, -9.81))", .echo = "m/s^2"},
    {.key = "gravity.gz", .attr = "gz", .type = K::Float, .unit = "m/s^2", .member = member<&SimParams::gz>(),
     .doc = "gravity along z", .legacy = "(none)", .echo = "m/s^2"},

    // [domain]
    {.key = "domain.lx", .attr = "lx", .type = K::Float, .unit = "m", .member = member<&SimParams::lx>(),
     .range = kPositive, .doc = "the box width", .legacy = "`Box dimension LX,LZ`", .echo = "box width [m]",
     .required = true},
    {.key = "domain.lz", .attr = "lz", .type = K::Float, .unit = "m", .member = member<&SimParams::lz>(),
     .range = kPositive, .doc = "the box height", .legacy = "same line", .echo = "box height [m]", .required = true},
    {.key = "domain.wall_left", .type = K::Bool, .member = member<&CaseSpec::wall_left>(),
     .doc = "boundary particles along x = 0", .legacy = "(BOX geometry: always)", .echo = "-"},
    {.key = "domain.wall_right", .type = K::Bool, .member = member<&CaseSpec::wall_right>(),
     .doc = "boundary particles along x = lx", .legacy = "(BOX geometry: always)", .echo = "-"},
    {.key = "domain.wall_bottom", .type = K::Bool, .member = member<&CaseSpec::wall_bottom>(),
     .doc = "boundary particles along z = 0", .legacy = "(BOX geometry: always)", .echo = "-"},
    {.key = "domain.wall_top", .type = K::Bool, .member = member<&CaseSpec::wall_top>(),
     .doc = "boundary particles along z = lz", .legacy = "(BOX geometry: never)", .echo = "-"},
    {.key = "domain.floor_inclination_deg", .type = K::Float, .unit = "degrees",
     .member = member<&CaseSpec::floor_beta_deg>(), .allowed = "0 only", .doc = "inclination of the floor",
     .legacy = "`Inclination of floor in X ( beta )`", .echo = "only 0 is supported", .hand = kRead},
    {.key = "domain.geometry", .attr = "geometry", .type = K::String, .member = member<&SimParams::geometry>(),
     .choices = names<Geometry>(), .doc = "planar (x, z) or axisymmetric (r, z)", .legacy = "(none)",
     .echo = "{choices} (axisymmetric: x = r >= 0, axis x = 0)", .h5_optional = true},
    {.key = "domain.periodic_z", .attr = "periodic_z", .type = K::Bool, .member = member<&SimParams::periodic_z>(),
     .allowed = "true needs wall_bottom = wall_top = false", .doc = "periodic in z with period lz",
     .legacy = "(none; legacy `Periodic Lateral boundaries` must be 0)", .h5_optional = true},
    {.key = "domain.split_axis_rings", .attr = "split_axis_rings", .type = K::Bool,
     .member = member<&SimParams::split_axis_rings>(), .def = "false", .allowed = "needs `axis_pair = \"rings\"`",
     .doc = "after each step a ring heavier than max(2 x the lattice ring at its radius, 2 x the first column's) "
            "becomes two of half its mass, dz/2 either side of it along the axis",
     .legacy = "(none)", .hand = kRead, .h5_optional = true},
    {.key = "domain.renormalise_ring_continuity", .attr = "renormalise_ring_continuity", .type = K::Bool,
     .member = member<&SimParams::renormalise_ring_continuity>(), .def = "false",
     .allowed = "needs `axis_pair = \"rings\"`",
     .doc = "each ring's density rate from the radial and from the axial stretch scaled to the mean of its own "
            "kernel's responses to the two, so that a stretch without a change of volume leaves the density alone "
            "where the surface cuts the kernel; with a `[nozzle]`, along the intact jet only",
     .legacy = "(none)", .hand = kRead, .h5_optional = true},
    {.key = "domain.renormalise_margin_d0", .attr = "renormalise_margin_d0", .type = K::Float, .unit = "1",
     .member = member<&SimParams::renormalise_margin_d0>(), .range = kNonNegative, .def = "0",
     .allowed = "> 0 needs `renormalise_ring_continuity = true` and a `[nozzle]`",
     .doc = "along a jet the renormalised continuity stops this many nozzle diameters short of the jet's intact "
            "end instead of at it, so that the end, where the next drop forms and the rings move as in a drop, "
            "keeps the rings pair's own continuity",
     .legacy = "(none)", .h5_optional = true},
    {.key = "domain.bound_ring_xsph", .attr = "bound_ring_xsph", .type = K::Bool,
     .member = member<&SimParams::bound_ring_xsph>(), .def = "false", .allowed = "needs `axis_pair = \"rings\"`",
     .doc = "each ring's XSPH correction divided by its planar kernel sum (sum_b m_b W_ab / rho_b over the meridian "
            "plane, axis images included) where that sum exceeds 1, so that it stays about xsph_eps times the "
            "ring's departure from its neighbours' mean velocity, as on a lattice; false: SPHysics' XSPH. Near the axis rings heavier than "
            "the first column's (split products) count the planar mass of a larger area and the sum reaches 2-3.5: "
            "with xsph_eps = 0.5 the correction cancelled or reversed a ring's own velocity",
     .legacy = "(none)", .hand = kRead, .h5_optional = true},
    {.key = "domain.axis_pair", .attr = "axis_pair", .type = K::String, .member = member<&SimParams::axis_pair>(),
     .choices = names<AxisPair>(),
     .allowed = "needs `geometry = \"axisymmetric\"`; `\"rings\"` needs h >= 2 dx",
     .doc = "the axisymmetric pressure and continuity pair", .legacy = "(none)",
     .echo = "{choices} (cases/axisymmetric/README.md)", .hand = kRead | kEcho, .h5_optional = true},

    // [resolution]
    {.key = "resolution.dx", .attr = "dx", .type = K::Float, .unit = "m", .member = member<&SimParams::dx>(),
     .range = kPositive, .doc = "the particle spacing in x", .legacy = "`Spacing dx,dz`",
     .echo = "particle spacing [m]", .required = true, .hand = kRead},
    {.key = "resolution.dz", .attr = "dz", .type = K::Float, .unit = "m", .member = member<&SimParams::dz>(),
     .range = kPositive, .def = "`dx`", .doc = "the particle spacing in z", .legacy = "same line", .echo = "m",
     .hand = kRead},
    {.key = "resolution.h", .attr = "h", .type = K::Float, .unit = "m", .member = member<&SimParams::h>(),
     .range = kPositive, .def = " ", .allowed = "one of h, h_coefficient, h_over_dx",
     .doc = "smoothing length", .legacy = "(none)", .hand = kRead | kEcho},
    {.key = "resolution.h_coefficient", .type = K::Float, .unit = "1", .range = kPositive, .def = " ",
     .doc = "h = coefficient sqrt(dx^2 + dz^2)", .legacy = "`h=coefficient*sqrt(dx*dx+dz*dz): coefficient`",
     .hand = kRead | kEcho},
    {.key = "resolution.h_over_dx", .type = K::Float, .unit = "1", .range = kPositive, .def = " ",
     .doc = "h = h_over_dx dx", .legacy = "(none)", .hand = kRead | kEcho},
    {.key = "resolution.jitter", .attr = "jitter", .type = K::Float, .unit = "1", .member = member<&SimParams::jitter>(),
     .range = between(0, 0.25), .allowed = "0 = off",
     .doc = "each fluid particle of the shapes moved by a random offset, uniform in [-j dx, j dx] x [-j dz, j dz]",
     .legacy = "(none)", .echo = "fraction of the spacing; a disordered start (cases/round_jet/README.md)",
     .h5_optional = true},
    {.key = "resolution.jitter_seed", .attr = "jitter_seed", .type = K::Int, .member = member<&SimParams::jitter_seed>(),
     .range = between(0, 2147483647), .doc = "seed of the jitter (one seed, one set of positions)",
     .legacy = "(none)", .echo = "-", .h5_optional = true},

    // [time]
    {.key = "time.tmax", .attr = "tmax", .type = K::Float, .unit = "s", .member = member<&SimParams::tmax>(),
     .range = kPositive, .doc = "end time [s]", .legacy = "`Input the tmax and out`"},
    {.key = "time.dt", .attr = "dt", .type = K::Float, .unit = "s", .member = member<&SimParams::dt>(),
     .range = kPositive, .doc = "initial (or fixed) step [s]", .legacy = "`Input dt?? , i_var_dt ??`"},
    {.key = "time.variable_dt", .attr = "variable_dt", .type = K::Bool, .member = member<&SimParams::variable_dt>(),
     .doc = "step from the CFL and force conditions", .legacy = "same line (i_var_dt)", .echo = "-"},
    {.key = "time.dt_max", .attr = "dt_max", .type = K::Float, .unit = "s", .member = member<&SimParams::dt_max>(),
     .range = kNonNegative, .def = "0 (none)", .allowed = "needs variable_dt = true",
     .doc = "the variable step's cap [s]: every step takes it where the CFL and force conditions allow it, less "
            "where they ask for less (the paragraph below)",
     .legacy = "(none)", .h5_optional = true},
    {.key = "time.cfl", .attr = "cfl", .type = K::Float, .unit = "1", .member = member<&SimParams::cfl>(),
     .range = between(0, 1, true), .doc = "Courant number", .legacy = "`CFL number`"},
    {.key = "time.out", .attr = "out", .type = K::Float, .unit = "s", .member = member<&SimParams::out>(),
     .range = kPositive, .doc = "output interval [s]", .legacy = "`Input the tmax and out` (the same line)"},
    {.key = "time.trec_ini", .attr = "trec_ini", .type = K::Float, .unit = "s", .member = member<&SimParams::trec_ini>(),
     .range = kNonNegative, .doc = "time of the first output [s]", .legacy = "`initial time of outputting general data`"},

    // [[obstacle]]
    {.key = "obstacle[].shape", .type = K::String, .member = member<&ObstacleSpec::shape>(),
     .choices = kObstacleShapes, .doc = "the obstacle's shape", .legacy = "`Choose rectangular (1) or trapezoid (2)`",
     .echo = "-"},
    {.key = "obstacle[].kind", .type = K::String, .member = member<&ObstacleSpec::kind>(), .choices = kObstacleKinds,
     .allowed = "walls: outline only", .doc = "filled with boundary particles, or its outline only",
     .legacy = "`Which kind of obstacle: (1) Solid, (2) With Solid Walls`", .echo = "{choices} (walls: outline only)"},
    {.key = "obstacle[].density", .type = K::Int, .member = member<&ObstacleSpec::density>(),
     .range = between(1, kNoLimit), .doc = "boundary points every dx / density", .legacy = "`Density of points(ndens)`"},
    {.key = "obstacle[].xmin", .type = K::Float, .unit = "m", .member = member<&ObstacleSpec::r, &Rect::xmin>(),
     .allowed = "in [0, lx], < xmax", .doc = "the left edge",
     .legacy = "`Cube containing particles : XMin, Xmax` (after \"Add obstacle\")", .echo = "m", .required = true,
     .hand = kRead},
    {.key = "obstacle[].xmax", .type = K::Float, .unit = "m", .member = member<&ObstacleSpec::r, &Rect::xmax>(),
     .allowed = "in [0, lx]", .doc = "the right edge", .legacy = "same line", .echo = "m", .required = true,
     .hand = kRead},
    {.key = "obstacle[].zmin", .type = K::Float, .unit = "m", .member = member<&ObstacleSpec::r, &Rect::zmin>(),
     .allowed = "in [0, lz], < zmax", .doc = "the bottom edge", .legacy = "`Cube containing particles : ZMin, Zmax`",
     .echo = "m", .required = true, .hand = kRead},
    {.key = "obstacle[].zmax", .type = K::Float, .unit = "m", .member = member<&ObstacleSpec::r, &Rect::zmax>(),
     .allowed = "in [0, lz]", .doc = "the top edge", .legacy = "same line", .echo = "m", .required = true,
     .hand = kRead},
    {.key = "obstacle[].beta_deg", .type = K::Float, .unit = "degrees", .member = member<&ObstacleSpec::beta_deg>(),
     .range = between(0, 180, true, true), .allowed = "the inclined sides inside the box",
     .doc = "inclination of the side walls", .legacy = "`Inclination ( beta )`"},

    // [gate]
    {.key = "gate.x", .type = K::Float, .unit = "m", .member = member<&GateSpec::x>(), .allowed = "in [0, lx]",
     .doc = "the gate position", .legacy = "`Add gate` then its position X", .echo = "position [m]", .required = true,
     .hand = kRead},
    {.key = "gate.zmin", .type = K::Float, .unit = "m", .member = member<&GateSpec::zmin>(), .allowed = "in [0, lz]",
     .doc = "the bottom of the gate", .legacy = "`ZZmin, ZZmax`", .echo = "bottom [m]", .required = true,
     .hand = kRead},
    {.key = "gate.zmax", .type = K::Float, .unit = "m", .member = member<&GateSpec::zmax>(),
     .allowed = "in [0, lz], >= zmin", .doc = "the top of the gate", .legacy = "same line", .echo = "top [m]",
     .required = true, .hand = kRead},
    {.key = "gate.vx", .type = K::Float, .unit = "m/s", .member = member<&GateSpec::vx>(),
     .doc = "velocity from t_start [m/s]", .legacy = "`Vx, Vz` (the gate velocity)"},
    {.key = "gate.vz", .type = K::Float, .unit = "m/s", .member = member<&GateSpec::vz>(),
     .doc = "vertical velocity from t_start", .legacy = "same line",
     .echo = "m/s; each particle stops at the top of the initial particles + 0.1 h"},
    {.key = "gate.t_start", .type = K::Float, .unit = "s", .member = member<&GateSpec::t_start>(),
     .range = kNonNegative, .doc = "time the gate starts moving", .legacy = "`tgate` (time the gate starts moving)",
     .echo = "s"},
    {.key = "gate.facing", .type = K::String, .member = member<&GateSpec::facing>(), .choices = kGateFacings,
     .doc = "side of the fluid (repulsive walls)", .legacy = "(none: legacy gates need dynamic boundaries)",
     .echo = "side of the fluid (repulsive walls): {choices}"},

    // [nozzle]
    {.key = "nozzle.x0", .type = K::Float, .unit = "m", .member = member<&NozzleSpec::x0>(),
     .allowed = "the nozzle and its walls inside the box", .doc = "the orifice centre x",
     .legacy = "(none: legacy has no inflow)", .echo = "orifice centre [m]", .required = true, .hand = kRead},
    {.key = "nozzle.z0", .type = K::Float, .unit = "m", .member = member<&NozzleSpec::z0>(), .allowed = "same",
     .doc = "the orifice centre z", .legacy = "(none)", .echo = "m", .required = true, .hand = kRead},
    {.key = "nozzle.axis", .type = K::String, .choices = kNozzleAxes, .def = "`\"down\"`",
     .allowed = "at least 2 d0 of it in the box", .doc = "jet direction", .legacy = "(none)",
     .echo = "jet direction: {choices}", .hand = kRead | kEcho},
    {.key = "nozzle.d0", .type = K::Float, .unit = "m", .member = member<&NozzleSpec::d0>(), .range = kPositive,
     .allowed = "at least 2 particles across", .doc = "the orifice width D0", .legacy = "(none)",
     .echo = "orifice width D0 [m]", .required = true, .hand = kRead},
    {.key = "nozzle.length_over_d0", .type = K::Float, .unit = "1", .member = member<&NozzleSpec::length_over_d0>(),
     .range = kPositive, .doc = "nozzle length upstream of the orifice / D0", .legacy = "(none)"},
    {.key = "nozzle.u0", .type = K::Float, .unit = "m/s", .member = member<&NozzleSpec::u0>(), .range = kPositive,
     .doc = "the jet speed u0", .legacy = "(none)", .echo = "jet speed [m/s]", .required = true, .hand = kRead},
    {.key = "nozzle.walls", .type = K::Bool, .member = member<&NozzleSpec::walls>(),
     .doc = "boundary lines along the nozzle sides", .legacy = "(none)"},
    {.key = "nozzle.refill", .type = K::Bool, .member = member<&NozzleSpec::refill>(), .def = "false",
     .allowed = "true: the run never runs dry; with the box's far end as the sink its cost stays flat",
     .doc = "a row of plug enters at the nozzle's back each time the plug has moved one spacing, so that the nozzle "
            "keeps its length",
     .legacy = "(none)"},
    {.key = "nozzle.profile", .type = K::String, .member = member<&NozzleSpec::profile>(),
     .choices = names<NozzleProfile>(), .def = "`\"plug\"`",
     .doc = "the plug's speed across the orifice: uniform, or a tube's fully developed laminar flow, u0 k (1 - "
            "l^2 / (d0/2)^2) at distance l from the axis with the plug's flux (k about 2 round, 1.5 planar), each line "
            "refilling on its own and the plug holding its built density; measured louder than the plug at d0/dx 10 "
            "(cases/round_jet/README.md)",
     .legacy = "(none)", .echo = "exit profile: {choices}"},
    {.key = "nozzle.release", .type = K::String, .member = member<&NozzleSpec::release>(),
     .choices = names<NozzleRelease>(), .def = "`\"step\"`",
     .doc = "when a plug particle turns free: at the first step that starts past the orifice (step), at its "
            "crossing of the orifice line (crossing), or at its crossing with each step shortened where needed so "
            "that the rows cross the line at a step's end (landed; the paragraph below); measured quieter at the exit "
            "with crossing, and landed quieter still (cases/round_jet/README.md)",
     .legacy = "(none)", .echo = "release: {choices}"},
    {.key = "nozzle.column_over_d0", .type = K::Float, .unit = "1", .member = member<&NozzleSpec::column_over_d0>(),
     .range = kNonNegative, .def = "0 (none)", .allowed = "the column inside the box",
     .doc = "a jet already out at the start: a column of the plug's rows this long / D0 past the orifice, moving "
            "at u0 at the plug's density (free fluid)",
     .legacy = "(none)"},
    {.key = "nozzle.disturbance", .type = K::Float, .unit = "1", .member = member<&NozzleSpec::disturbance>(),
     .range = between(0, 1, false, true), .def = "0 (none)", .doc = "plug speed u0 (1 + disturbance sin(omega t))",
     .legacy = "(none)", .hand = kEcho},
    {.key = "nozzle.disturbance_ka", .type = K::Float, .unit = "1", .member = member<&NozzleSpec::disturbance_ka>(),
     .range = kPositive, .doc = "omega = u0 ka / (d0 / 2)", .legacy = "(none)", .hand = kEcho},

    // [breakup]
    {.key = "breakup.link_over_h", .type = K::Float, .unit = "1", .member = member<&BreakupSpec::link_over_h>(),
     .range = kPositive, .doc = "broken where two particles along the axis are more than this x h apart",
     .legacy = "(none)"},
    {.key = "breakup.band_over_d0", .type = K::Float, .unit = "1", .member = member<&BreakupSpec::band_over_d0>(),
     .range = kPositive, .doc = "particles within this x D0 of the axis count", .legacy = "(none)"},
    {.key = "breakup.check_every", .type = K::Float, .unit = "s", .member = member<&BreakupSpec::check_every>(),
     .range = kNonNegative, .def = "0 (every output)", .doc = "s between checks; 0 = every output",
     .legacy = "(none)"},
    {.key = "breakup.stop_after", .type = K::Float, .unit = "s", .member = member<&BreakupSpec::stop_after>(),
     .range = kNonNegative, .def = "never", .doc = "s after the first breakup the run stops", .legacy = "(none)",
     .hand = kEcho},
    {.key = "breakup.remove_drops_below_h", .type = K::Float, .unit = "1",
     .member = member<&BreakupSpec::remove_drops_below_h>(), .range = kNonNegative, .def = "0 (off)",
     .doc = "drops with d_eq below this x h are removed at the checks", .legacy = "(none)", .hand = kEcho},
    {.key = "breakup.remove_drops_beyond_d0", .type = K::Float, .unit = "1",
     .member = member<&BreakupSpec::remove_drops_beyond_d0>(), .range = kNonNegative, .def = "0 (off)",
     .doc = "once the jet is broken, drops wholly farther than this x D0 past its end are removed at the checks",
     .legacy = "(none)", .hand = kEcho},

    // [[wall]]
    {.key = "wall[].x", .type = K::Float, .unit = "m", .member = member<&WallSpec::x>(), .allowed = "in [0, lx]",
     .doc = "the wall position", .legacy = "`Add wall` then its position XWall", .echo = "position [m]",
     .required = true, .hand = kRead},
    {.key = "wall[].height", .type = K::Float, .unit = "m", .member = member<&WallSpec::height>(),
     .allowed = "(0, lz]", .doc = "the wall height", .legacy = "its height ZWall", .echo = "from the floor [m]",
     .required = true, .hand = kRead},

    // [legacy]
    {.key = "legacy.fill", .type = K::Bool, .member = member<&CaseSpec::legacy_fill>(),
     .allowed = "true needs `fluid.coef`/`fluid.h_swl`",
     .doc = "fill blocks as SPHYSICSgen_2D (from the floor, up to h_swl)",
     .legacy = "(the legacy generator's fill rules)"},
    {.key = "legacy.single_precision", .type = K::Bool, .def = "false",
     .doc = "derive B and h in single precision as SPHYSICSgen_2D",
     .legacy = "(SPHYSICSgen_2D computes in single precision)", .hand = kRead | kEcho},
    {.key = "legacy.h_coefficient", .type = K::Float, .unit = "1", .member = member<&LegacyRunInfo::h_coefficient>(),
     .range = kPositive, .def = " ", .allowed = "not with `resolution.h_coefficient`",
     .doc = "recorded only; resolution.h rules", .legacy = "`h=coefficient*...` (recorded only)",
     .hand = kRead | kEcho},
    {.key = "legacy.detail_out", .type = K::Float, .unit = "s", .member = member<&LegacyRunInfo::detail_out>(),
     .doc = "detailed-recording interval [s] (INDAT only)",
     .legacy = "`For detailed recording during RUN: out_detail, start, end`"},
    {.key = "legacy.detail_start", .type = K::Float, .unit = "s", .member = member<&LegacyRunInfo::detail_start>(),
     .doc = "start of the detailed recording (INDAT only)", .legacy = "same line", .echo = "s"},
    {.key = "legacy.detail_end", .type = K::Float, .unit = "s", .member = member<&LegacyRunInfo::detail_end>(),
     .doc = "end of the detailed recording (INDAT only)", .legacy = "same line", .echo = "s"},
    {.key = "legacy.vorticity", .type = K::Bool, .member = member<&LegacyRunInfo::vorticity>(),
     .doc = "vorticity printing (INDAT only)", .legacy = "`vorticity printing ? (1=yes)`"},
    {.key = "legacy.compiler", .type = K::Int, .member = member<&LegacyRunInfo::compiler>(), .range = between(1, 4),
     .allowed = "1 gfortran, 2 ifort, 3 win_ifort, 4 FTN95", .doc = "compiler choice (INDAT only)",
     .legacy = "`Which compiler is desired`", .echo = "1 gfortran, 2 ifort, 3 win_ifort, 4 FTN95 (INDAT only)"},
    {.key = "legacy.xz_precision", .type = K::String, .member = member<&LegacyRunInfo::xz_precision>(),
     .choices = kPrecision, .doc = "legacy solver's x/z precision",
     .legacy = "`Precision of XYZ Variables: 1=Single, 2=Double`", .echo = "legacy solver's x/z precision"},

    // [output]
    {.key = "output.format", .type = K::String, .member = member<&OutputSpec::format>(),
     .choices = names<OutputFormat>(), .allowed = "legacy: PART/DT files; hdf5: HDF5 + XDMF",
     .doc = "which files the run writes", .legacy = "(none)"},
    {.key = "output.checkpoint_every_steps", .type = K::Int, .unit = "steps",
     .member = member<&OutputSpec::checkpoint_every_steps>(), .range = between(0, kNoLimit), .def = "0 (off)",
     .doc = "steps between checkpoints, 0 = off", .legacy = "(none)", .echo = "0 = off"},
    {.key = "output.checkpoint_every_minutes", .type = K::Float, .unit = "minutes (wall clock)",
     .member = member<&OutputSpec::checkpoint_every_minutes>(), .range = kNonNegative, .allowed = "0 = off",
     .doc = "wall-clock minutes, 0 = off", .legacy = "(none)"},
    {.key = "output.remove_out_of_domain", .type = K::Bool, .member = member<&OutputSpec::remove_out_of_domain>(),
     .allowed = "true: remove and count leavers (legacy); false: stop", .doc = "false = stop when a particle leaves",
     .legacy = "(none)"},
    {.key = "output.rho_min_factor", .type = K::Float, .unit = "1", .member = member<&OutputSpec::rho_min_factor>(),
     .range = between(0, 1, false, true), .doc = "stop if rho < factor rho0", .legacy = "(none)"},
    {.key = "output.rho_max_factor", .type = K::Float, .unit = "1", .member = member<&OutputSpec::rho_max_factor>(),
     .range = between(1, kNoLimit, true), .doc = "stop if rho > factor rho0", .legacy = "(none)"},
    {.key = "output.dt_min", .type = K::Float, .unit = "s", .member = member<&OutputSpec::dt_min>(),
     .range = kNonNegative, .doc = "stop if dt falls below [s]", .legacy = "(none)"},
    {.key = "output.revolution_sectors", .type = K::Int, .member = member<&OutputSpec::revolution_sectors>(),
     .range = between(0, kMaxRevolutionSectors), .def = "0 (off)",
     .allowed = "`domain.geometry = \"axisymmetric\"` only",
     .doc = "HDF5 snapshots also hold the rings revolved into this many copies", .legacy = "(none)",
     .hand = kEcho},

    // SimParams members no key sets directly (HDF5 attributes only)
    {.attr = "visc_value", .unit = "1", .member = member<&SimParams::visc_value>(),
     .doc = "alpha (numerics.alpha, or 8 nu / (h c0)) or, laminar, nu [m^2/s] (fluid.nu or fluid.mu / rho0)"},
    {.attr = "B", .unit = "Pa", .member = member<&SimParams::B>(),
     .doc = "Tait constant: rho0 c0^2 / gamma, or coef^2 rho0 |gz| h_swl / gamma"},
    {.attr = "gate_vx", .unit = "m/s", .member = member<&SimParams::gate_vx>(), .doc = "gate.vx",
     .h5_optional = true},
    {.attr = "gate_vz", .unit = "m/s", .member = member<&SimParams::gate_vz>(), .doc = "gate.vz",
     .h5_optional = true},
    {.attr = "gate_t_start", .unit = "s", .member = member<&SimParams::gate_t_start>(), .doc = "gate.t_start",
     .h5_optional = true},
    {.attr = "gate_z_cap", .unit = "m", .member = member<&SimParams::gate_z_cap>(),
     .doc = "where the gate's particles stop: the top particle + 0.1 h", .h5_optional = true},
    {.attr = "drive_u", .unit = "m/s", .member = member<&SimParams::drive_u>(), .doc = "nozzle.u0; 0: no nozzle",
     .h5_optional = true},
    {.attr = "drive_x0", .unit = "m", .member = member<&SimParams::drive_x0>(), .doc = "nozzle.x0",
     .h5_optional = true},
    {.attr = "drive_z0", .unit = "m", .member = member<&SimParams::drive_z0>(), .doc = "nozzle.z0",
     .h5_optional = true},
    {.attr = "drive_ex", .unit = "1", .member = member<&SimParams::drive_ex>(), .doc = "nozzle.axis, x",
     .h5_optional = true},
    {.attr = "drive_ez", .unit = "1", .member = member<&SimParams::drive_ez>(), .doc = "nozzle.axis, z",
     .h5_optional = true},
    {.attr = "drive_half_width", .unit = "m", .member = member<&SimParams::drive_half_width>(),
     .doc = "driven half width: d0 / 2 + max(dx, dz) / 4", .h5_optional = true},
    {.attr = "drive_profile_a", .unit = "m", .member = member<&SimParams::drive_profile_a>(),
     .doc = "nozzle.profile = \"parabolic\": d0 / 2; 0: a plug", .h5_optional = true},
    {.attr = "drive_profile_k", .unit = "1", .member = member<&SimParams::drive_profile_k>(),
     .doc = "the parabolic profile's centre speed / u0 on the nozzle's lattice (about 2 round, 1.5 planar)",
     .h5_optional = true},
    {.attr = "drive_profile_lmax", .unit = "m", .member = member<&SimParams::drive_profile_lmax>(),
     .doc = "the plug's outer line's distance from the axis; fluid farther out moves with it", .h5_optional = true},
    {.attr = "drive_profile_rho", .unit = "kg/m^3", .member = member<&SimParams::drive_profile_rho>(),
     .doc = "the density a profiled plug holds (the plug's as built)", .h5_optional = true},
    {.attr = "drive_release_crossing", .member = member<&SimParams::drive_release_crossing>(),
     .doc = "nozzle.release = \"crossing\" or \"landed\"", .h5_optional = true},
    {.attr = "drive_release_landed", .member = member<&SimParams::drive_release_landed>(),
     .doc = "nozzle.release = \"landed\"", .h5_optional = true},
    {.attr = "drive_eps", .unit = "1", .member = member<&SimParams::drive_eps>(), .doc = "nozzle.disturbance",
     .h5_optional = true},
    {.attr = "drive_omega", .unit = "rad/s", .member = member<&SimParams::drive_omega>(),
     .doc = "u0 disturbance_ka / (d0 / 2) with a disturbance, else 0", .h5_optional = true},
    {.attr = "domain_box", .member = member<&SimParams::domain_box>(),
     .doc = "fluid leaves the box [0, lx] x [0, lz] (a nozzle, periodic_z), not the walls' extent",
     .h5_optional = true},
};

// Shortest text of v, as the tables write numbers.
std::string short_num(double v) {
    std::array<char, 64> buf{};
    auto res = std::to_chars(buf.data(), buf.data() + buf.size(), v);
    return {buf.data(), res.ptr};
}

std::string type_name(KeyType t) {
    switch (t) {
        case KeyType::Float: return "number";
        case KeyType::Int: return "integer";
        case KeyType::Bool: return "boolean";
        case KeyType::String: return "string";
    }
    return "";
}

// The owner with its defaults, for the tables: one instance of each struct a row names.
const void* defaults_of(const void* owner) {
    static const SimParams sim{};
    static const CaseSpec spec{};
    static const OutputSpec out{};
    static const LegacyRunInfo leg{};
    static const BreakupSpec bk{};
    static const NozzleSpec nz{};
    static const GateSpec gate{};
    static const WallSpec wall{};
    static const ObstacleSpec ob{};
    static const FluidBlock block{};
    static const FluidDisc disc{};
    static const FluidCylinder cyl{};
    static const FluidSquare sq{};
    const std::pair<const void*, const void*> all[] = {
        {&owner_tag<SimParams>, &sim},      {&owner_tag<CaseSpec>, &spec},     {&owner_tag<OutputSpec>, &out},
        {&owner_tag<LegacyRunInfo>, &leg},  {&owner_tag<BreakupSpec>, &bk},    {&owner_tag<NozzleSpec>, &nz},
        {&owner_tag<GateSpec>, &gate},      {&owner_tag<WallSpec>, &wall},     {&owner_tag<ObstacleSpec>, &ob},
        {&owner_tag<FluidBlock>, &block},   {&owner_tag<FluidDisc>, &disc},    {&owner_tag<FluidCylinder>, &cyl},
        {&owner_tag<FluidSquare>, &sq}};
    for (const auto& [tag, obj] : all)
        if (tag == owner) return obj;
    return nullptr;
}

std::string default_text(const Param& r) {
    if (r.required) return "**required**";
    if (!r.def.empty()) return r.def == " " ? "" : std::string(r.def);
    const void* o = defaults_of(r.member.owner);
    if (o == nullptr) return "";
    const Member& m = r.member;
    if (m.store == Member::Store::Float) return short_num(m.get_f(o));
    const std::int64_t v = m.get_i(o);
    if (!r.choices.empty()) return "`\"" + choice_name(r.choices, v) + "\"`";
    if (r.type == KeyType::Bool) return v != 0 ? "true" : "false";
    return std::to_string(v);
}

}  // namespace

std::string range_text(const Range& g) {
    switch (g.kind) {
        case Range::Kind::Any: return "";
        case Range::Kind::Positive: return "> 0";
        case Range::Kind::NonNegative: return ">= 0";
        case Range::Kind::Between:
            if (g.hi >= kNoLimit) return (g.lo_open ? "> " : ">= ") + short_num(g.lo);
            return (g.lo_open ? "(" : "[") + short_num(g.lo) + ", " + short_num(g.hi) + (g.hi_open ? ")" : "]");
    }
    return "";
}

namespace {

// A table cell: '|' would end it.
std::string cell(std::string_view text) {
    std::string s;
    for (char c : text) s += c == '|' ? std::string("\\|") : std::string(1, c);
    return s;
}

std::string allowed_text(const Param& r) {
    std::string s = range_text(r.range);
    if (!r.choices.empty()) {
        for (const auto& c : r.choices) s += (s.empty() ? "`\"" : ", `\"") + std::string(c.name) + "\"`";
    }
    if (!r.allowed.empty()) s += (s.empty() ? "" : "; ") + std::string(r.allowed);
    return s;
}

}  // namespace

std::span<const Param> case_params() { return kParams; }

const Param* find_param(std::string_view key) {
    if (key.empty()) return nullptr;
    for (const auto& r : kParams)
        if (r.key == key) return &r;
    return nullptr;
}

std::string_view section_of(std::string_view key) {
    const auto dot = key.rfind('.');
    return dot == std::string_view::npos ? std::string_view{} : key.substr(0, dot);
}

std::string_view leaf_of(std::string_view key) {
    const auto dot = key.rfind('.');
    return dot == std::string_view::npos ? key : key.substr(dot + 1);
}

std::string choice_name(std::span<const Choice> choices, std::int64_t v) {
    for (const auto& c : choices)
        if (c.value == v) return std::string(c.name);
    return "unknown";
}

std::string choice_list(std::span<const Choice> choices) {
    std::string s;
    for (const auto& c : choices) s += (s.empty() ? "" : " | ") + std::string(c.name);
    return s;
}

std::string_view attr_unit(const Param& row, const SimParams& p) {
    if (row.attr == "visc_value" && p.viscosity == ViscosityModel::Laminar) return "m^2/s";
    return row.unit;
}

std::string case_format_table(std::string_view section) {
    std::string s;
    if (section == "hdf5") {
        s = "| attribute | units | what it holds |\n|---|---|---|\n";
        for (const auto& r : kParams)
            if (!r.attr.empty())
                s += "| `" + std::string(r.attr) + "` | " + cell(r.unit) + " | " +
                     (r.key.empty() ? cell(r.doc) : "`" + std::string(r.key) + "`") + " |\n";
        return s;
    }
    s = "| key | type | units | default | allowed | meaning | legacy line |\n|---|---|---|---|---|---|---|\n";
    for (const auto& r : kParams) {
        if (r.key.empty() || section_of(r.key) != section) continue;
        s += "| `" + std::string(leaf_of(r.key)) + "` | " + type_name(r.type) + " | " + cell(r.unit) + " | " +
             cell(default_text(r)) + " | " + cell(allowed_text(r)) + " | " + cell(r.doc) + " | " + cell(r.legacy) +
             " |\n";
    }
    return s;
}

std::string with_case_format_tables(const std::string& page) {
    static constexpr std::string_view open = "<!-- keys ", close = "<!-- end keys -->";
    std::string out;
    std::size_t at = 0;
    for (;;) {
        const auto b = page.find(open, at);
        if (b == std::string::npos) break;
        const auto name_end = page.find(" -->\n", b);
        const auto e = name_end == std::string::npos ? name_end : page.find(close, name_end);
        if (e == std::string::npos) break;
        const std::string section = page.substr(b + open.size(), name_end - b - open.size());
        out += page.substr(at, name_end + 5 - at);
        out += case_format_table(section == "top" ? "" : section);
        at = e;
    }
    return out + page.substr(at);
}

}  // namespace sphjet
