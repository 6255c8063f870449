// A case as data: parameters plus the geometry the generator turns into particles.
// Both readers (legacy SPHysics case file, modern TOML) produce a CaseSpec.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/params.hpp"

namespace sphjet {

struct Rect {
    double xmin = 0, xmax = 0, zmin = 0, zmax = 0;
};

// Legacy "Add obstacle": rectangular obstacle standing in the box.
struct ObstacleSpec {
    int shape = 1;        // 1 rectangle (2 trapezoid is refused by the legacy reader)
    int kind = 1;         // 1 solid (filled with boundary particles), 2 outline walls only
    int density = 1;      // ndens: spacing of boundary points = dx / ndens
    Rect r;
    double beta_deg = 90; // inclination of the side walls
};

// A region filled with fluid particles on the case lattice (legacy "cube containing particles").
struct FluidBlock {
    Rect r;
    double u0 = 0, w0 = 0;  // initial velocity [m/s]
};

// Legacy "Add wall": a vertical two-layer wall of boundary particles standing on the floor
// at x, from z = 0 to height (dynamic boundaries only).
struct WallSpec {
    double x = 0, height = 0;
};

// Legacy "Add gate": a vertical column of moving boundary particles at x, z = k dz for
// k = nint(zmin/dz) .. nint(zmax/dz), at rest until t_start, then moving with (vx, vz); each
// particle stops rising at the top of the initial particles plus 0.1 h (SPHysics' zmax_ini).
// With repulsive walls (modern format only) it is one wall line whose normal faces `facing`
// (-1: the fluid stands on its left, -x; +1: on its right), moving as one piece and stopping
// when its lowest particle reaches that height.
struct GateSpec {
    double x = 0, zmin = 0, zmax = 0;
    double vx = 0, vz = 0;
    double t_start = 0;
    int facing = -1;
};

// What a legacy case file carries that the simulation does not use but INDAT records
// (so that gen -> INDAT -> read_indat keeps them).
struct LegacyRunInfo {
    int restart = 0;                 // starting option (only 0, a new run, is supported)
    double detail_out = 5e-4;        // detailed-recording interval, start, end [s]
    double detail_start = 1.0;
    double detail_end = -1.0;
    int vorticity = 0;               // vorticity printing flag
    int compiler = 1;                // compiler choice (1 gfortran ... 4 FTN95); not used
    int xz_precision = 2;            // legacy solver's x/z precision: 1 single, 2 double
    double h_coefficient = 0;        // h = h_coefficient * sqrt(dx^2 + dz^2)
};

// Modern-format shapes (not expressible in a legacy case file).
// lattice = "case" (default): the case lattice points inside the disc. lattice = "rings":
// concentric rings (geometry/generator.hpp), a smooth edge for the surface-tension tests.
// elongation e: the disc is stretched to an ellipse of semi-axes R (1 + e) along x and
// R / (1 + e) along z (area kept; r(theta) = R (1 + e cos 2 theta) + O(e^2)), the mode-2
// perturbation of the oscillating-drop test.
struct FluidDisc {
    double xc = 0, zc = 0, radius = 0;
    double u0 = 0, w0 = 0;
    bool rings = false;
    double elongation = 0;
};

// A liquid cylinder about the axis x = 0 (axisymmetric geometry only), radius
// r(z) = radius (1 + eps cos(2 pi (z - zmin) / wavelength)) for zmin <= z < zmax: the
// Rayleigh-Plateau test. The lattice of the unperturbed cylinder, ((i + 1/2) dx, k dz) with
// x < radius, is stretched radially by 1 + eps cos(...) (geometry/generator.hpp).
struct FluidCylinder {
    double radius = 0, eps = 0, wavelength = 0;
    double zmin = 0, zmax = 0;  // [m]; the reader's default is the whole box height
};

// A square of fluid, sides parallel to the axes (the classic surface-tension test: a square
// drop relaxes to a circle). Filled on the case lattice like a FluidBlock.
struct FluidSquare {
    double xc = 0, zc = 0, side = 0;
    double u0 = 0, w0 = 0;
};

// A driven nozzle (modern format [nozzle], the paper's jets; cases/jet/README.md): a
// channel of width d0 and length `length` upstream of the orifice, filled with fluid that
// moves as a rigid plug at u0 along the axis and becomes free fluid when it crosses the
// orifice line ("a tank filled with particles serves as the nozzle"). With `walls`, a
// boundary line runs along each side of the channel, one spacing outside the outer rows,
// from the nozzle's back end to 2h upstream of the orifice (geometry/nozzle.hpp). The axis is one of the four lattice directions.
struct NozzleSpec {
    double x0 = 0, z0 = 0;      // orifice centre [m]
    double ex = 0, ez = -1;     // jet axis (unit, flow direction): down, up, left or right
    double d0 = 0;              // orifice width [m]
    double length_over_d0 = 15; // nozzle length upstream of the orifice / d0 (the paper's aspect ratio)
    double u0 = 0;              // jet speed [m/s]
    bool walls = true;
    // The speed across the orifice: a rigid plug at u0, or parabolic with the same flux (the
    // core's plug_step; SimParams::drive_profile_a).
    NozzleProfile profile = NozzleProfile::Plug;
    // When a plug particle turns free (NozzleRelease; SimParams::drive_release_crossing).
    NozzleRelease release = NozzleRelease::Step;
    // An imposed disturbance: the plug speed is u0 (1 + disturbance sin(omega t)), omega =
    // u0 k with k = disturbance_ka / (d0 / 2): a wave of that k leaves the orifice. 0: none.
    double disturbance = 0;
    double disturbance_ka = 0.697;  // Rayleigh's fastest-growing mode of a round jet
    // The nozzle stays length() long: a row of plug enters at its back each time the plug has
    // moved one spacing (geometry/nozzle.hpp, nozzle_refill_rows). false: it runs dry.
    bool refill = false;
    // A jet already out at the start: a column of the plug's lattice this long / d0 past the
    // orifice, moving at u0 at the plug's density (free fluid, not driven). 0: none, the jet
    // starts at the orifice.
    double column_over_d0 = 0;
    [[nodiscard]] double length() const { return length_over_d0 * d0; }
    [[nodiscard]] double column() const { return column_over_d0 * d0; }
    [[nodiscard]] double disturbance_omega() const { return u0 * disturbance_ka / (0.5 * d0); }
};

// Breakup detection while the run goes (modern format [breakup]; analysis/jet_monitor.hpp).
struct BreakupSpec {
    double link_over_h = 1.5;       // the paper: broken where two particles along the axis are > 1.5 h apart
    double band_over_d0 = 0.5;      // particles within band_over_d0 * d0 of the axis are "along the axis"
    double check_every = 0;         // [s] between checks; 0 = every output
    double stop_after = -1;         // [s] after the first breakup the run stops; < 0 = never
    // Drops with d_eq < this x h are removed at the checks; 0 = never. A drop of radius below
    // h has no interior and collapses (cases/CASE_FORMAT.md [breakup]).
    double remove_drops_below_h = 0;
    // Once the jet is broken, drops wholly farther than this x d0 past its end (the breakup
    // length) are removed at the checks: a sink that follows the jet, so that the run's cost
    // follows the jet's length and not the box's; 0 = never (cases/CASE_FORMAT.md [breakup]).
    double remove_drops_beyond_d0 = 0;
};

enum class OutputFormat { Legacy, Hdf5, Both };
template <>
struct EnumNames<OutputFormat> {
    static constexpr NameTable<OutputFormat, 3> list{
        {{"legacy", OutputFormat::Legacy}, {"hdf5", OutputFormat::Hdf5}, {"both", OutputFormat::Both}}};
};

struct OutputSpec {
    OutputFormat format = OutputFormat::Both;
    long checkpoint_every_steps = 0;       // 0 = off
    double checkpoint_every_minutes = 5;   // wall-clock minutes; 0 = off (CASE_FORMAT.md: why 5)
    bool remove_out_of_domain = true;      // legacy removes and counts leavers; false = stop
    double rho_min_factor = 0.5;           // density band [f_min, f_max] x rho0, else stop
    double rho_max_factor = 1.5;
    double dt_min = 1e-9;                  // a step below this is a collapse [s]
    // Axisymmetric only: each HDF5 snapshot also carries the rings revolved about the axis,
    // copies at phi = 2 pi k / N, k = 0..N-1 (io/hdf5_output.hpp); 0 = off.
    int revolution_sectors = 0;
};

// The most sectors [output] revolution_sectors takes: one a degree (a snapshot of n rings
// then holds 360 n revolved points, about 17 kB per ring: see cases/CASE_FORMAT.md).
inline constexpr int kMaxRevolutionSectors = 360;

struct CaseSpec {
    SimParams params;
    std::string source;           // file it was read from, for messages
    double floor_beta_deg = 0.0;  // legacy floor inclination (only 0 is supported)
    bool wall_left = true, wall_right = true, wall_bottom = true, wall_top = false;
    std::vector<ObstacleSpec> obstacles;
    std::vector<FluidBlock> fluid_blocks;
    std::vector<FluidDisc> fluid_discs;
    std::vector<FluidSquare> fluid_squares;
    std::vector<FluidCylinder> fluid_cylinders;
    OutputSpec output;
    std::vector<WallSpec> walls;  // legacy "Add wall" (dynamic boundaries)
    std::vector<GateSpec> gates;  // legacy "Add gate": at most one (legacy moves only the first)
    std::optional<NozzleSpec> nozzle;    // a driven nozzle (a jet), modern format only
    std::optional<BreakupSpec> breakup;  // breakup detection (with a nozzle)
    LegacyRunInfo legacy;
    // True for a legacy case file: fluid blocks are filled exactly as SPHYSICSgen2D fills them
    // (from the floor up, whatever ZMin says, and never above h_SWL). False: blocks, squares
    // and discs take the lattice points inside them (geometry/generator.hpp).
    bool legacy_fill = false;
    std::vector<std::string> warnings;  // things the reader accepted but a user should know
};

}  // namespace sphjet
