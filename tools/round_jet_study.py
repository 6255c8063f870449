#!/usr/bin/python3
"""Round (axisymmetric) jets against measurements: the laminar water jets of Mansour & Chigier
(1994) and the paper's four jets as round jets. Run them, then tabulate and plot them.

Usage (Debian's python3 has numpy, matplotlib and h5py):
  /usr/bin/python3 tools/round_jet_study.py run [--root runs/round_jet] [--eps 0.01]
      [--d0-over-dx 10] [--size-c C] [--remove-drops-below-h D] [--axis-pair rings|rings_own|rings_fit]
      [--quiet-exit] [--artificial-alpha A [--reconstruct]] [--c0 C] [--sink M] [--window 1] [--own-window]
      [--cfl K] [--leapfrog] [--xsph E] [--quiet-jets] [--gravity] [--fixed-step F | --step-cap F] [--landed] [--renormalise-margin M] [--bound-xsph] [--free-bodies] [--thin-rings] [--fit-points N] [--h-over-dx H] [--relaxed-exit] [--kernel K] [--set-name mc paper]
      [--only RUN ...] [--threads 2] [--parallel 1]
      [--sphjet build/cpp_driver/sphjet] [--dry-run]
  /usr/bin/python3 tools/round_jet_study.py report [--root runs/round_jet] [--eps 0.01]
      [--d0-over-dx 10] [--size-c C] [--remove-drops-below-h D] [--axis-pair rings|rings_own|rings_fit]
      [--quiet-exit] [--artificial-alpha A [--reconstruct]] [--c0 C] [--sink M] [--window 1] [--own-window]
      [--cfl K] [--leapfrog] [--xsph E] [--quiet-jets] [--gravity] [--fixed-step F | --step-cap F] [--landed] [--renormalise-margin M] [--bound-xsph] [--free-bodies] [--thin-rings] [--fit-points N] [--h-over-dx H] [--relaxed-exit] [--kernel K] [--out cases/round_jet]
      [--set-name mc paper] [--only RUN ...] [--brief] [--keep-rows]

The plan: `--set` overrides on cases/round_jet/round_jet.toml, in ROOT/epsEPS_nN/NAME:
  mc     mc_u{U} for every speed of cases/round_jet/mansour_chigier_1994.csv (d0 = 1.194 mm)
  paper  paper_u{0.07,0.17,0.2,0.25}: the paper's jets (d0 = 10 mm) as round jets, c0 = 4 m/s
The disturbance amplitude EPS (nozzle.disturbance, the plug speed u0 (1 + EPS sin(omega t)) at
k a = 0.697) is the one free parameter: the same for every run of a study directory. With
--remove-drops-below-h D every run removes the detached drops thinner than D h at its breakup
checks (breakup.remove_drops_below_h, cases/CASE_FORMAT.md), in a study directory of its own;
with --axis-pair rings every run uses the rings pair (domain.axis_pair, cases/axisymmetric/
README.md) instead of the default smoothed-radius pair, likewise in a directory of its own;
--axis-pair rings_own the rings pair with each surface row's own curvature
(surface_tension.rings_curvature = "own", cases/round_jet/README.md), in another;
--axis-pair rings_fit the rings pair with the surface fit (surface_tension.curvature =
"surface_fit") and the tensile correction (numerics.tensile_correction = "on"), in another.
With --quiet-exit (with a rings --axis-pair) every run has the bulk viscosity
numerics.bulk_viscosity = 0.5 (which damps the jet's sound waves, cases/round_jet/README.md), a
3 d0 nozzle that refills (nozzle.refill) and the rings too heavy for their radius split
(domain.split_axis_rings), in a directory of its own (suffix _quiet). --artificial-alpha A adds
numerics.artificial_alpha = A (Monaghan's artificial viscosity on top of the laminar one, which
damps the particles' noise; cases/round_jet/README.md) to every run (suffix _alphaA), and
--reconstruct numerics.artificial_reconstruction, which keeps that damping to the particle-scale
motion (suffix _alphaA_rec); --c0 C sets the measured jets' sound speed fluid.c0 = C (16 m/s in
the case; the step is 0.2 h / (c0 + the pinch-offs' velocity differences), so 12 m/s takes 0.84
of the particle-steps of 16, but its unforced jets are 5-12% longer: the sound speed moves the
noise floor; suffix _c0C). --sink M removes, at every check once the jet is
broken, the drops wholly farther than M d0 past its end (breakup.remove_drops_beyond_d0, a sink
that follows the jet), so that a run costs its jet's length and not its box's (suffix _sinkM).
--cfl K sets time.cfl = K (the Courant number of the variable step, 0.2 in the case) in every
run (suffix _cflK); with --quiet-exit a step above 0.25 h / c0 is held there by the bulk
viscosity's bound. K = 0.3 takes about 1.4 times fewer steps but is not converged at the
pinch-offs (the drops and the shed particles change; cases/round_jet/README.md, "The quick start
jet"); K = 0.25 with --c0 12 takes 0.79 of the steps, its forced jets within 3% and its unforced
0.86 m/s jet within 2.4% of 0.2's ("The sound speed and the step together"). The study uses c0
16 m/s and 0.2, as its table was made. --leapfrog (needs --quiet-exit's bulk viscosity) sets
numerics.integrator = "leapfrog" (suffix _lf): one evaluation of the rates per step instead of
two, about half the cost; the forced jets within 1.3% and the unforced ones within 2.5% of the
predictor-corrector's ("One evaluation per step: the leapfrog"). --quiet-jets stands for the
quiet round jets' numerics, the quick start's and the validation's: --axis-pair rings_fit
--quiet-exit --artificial-alpha 0.02 --reconstruct --c0 12 --cfl 0.25 --leapfrog --sink 15 (the
same study directory as those flags; one of them given with another value is refused).
--gravity makes the jets fall along their axis (gravity.gz = -9.81 m/s^2; the case's nozzle
points down) with the falling jets' numerics: the continuity renormalised along r and z
(domain.renormalise_ring_continuity) and the plug's particles freed where they cross the orifice
(nozzle.release = "crossing"), as "A plug that lets go at the orifice" measured them (suffix _g;
needs a rings --axis-pair). Its report gives, beside C = L/(d0 x), the C = ln(a/delta0) that
Weber's growth along a falling jet reaches at the measured and at the run's length
(tools/jet_gravity_theory.py): 17.0-19.6 for the measured jets up to 1.28 m/s. Beside it, the same
followed at one frequency (jet_gravity_theory's --one-frequency: each wave carried down at its
own frequency; lower wherever the jet speeds up), 2-4 s more a run.
--fixed-step F gives every run a fixed step of F times the CFL step of its fluid at rest,
time.dt = F cfl h / c0 with time.variable_dt = false (suffix _fixF; 0 < F < 1): the variable
step changes every step with the pinch-offs far down the jet, and that jitter seeds the jet
("A step that does not jitter"); F = 0.6 costs about 1.3 times the variable step's steps, but
cannot follow a pinch-off that asks for less (each run.log says how often it was above that).
--step-cap F keeps the variable step but caps it there (time.dt_max = F cfl h / c0; suffix _capF):
the step changes only where the CFL and force conditions ask for less than the cap.
--landed frees each of the plug's rows exactly at the orifice line (nozzle.release = "landed";
suffix _land): the steps are shortened where needed so that the rows cross it at a step's end.
The release's jitter, not the step's, was what seeded the jets ("Rows that turn free on the line").
--renormalise-margin M (with --gravity; suffix _marginM) stops the renormalised continuity M d0
short of the jet's intact end (domain.renormalise_margin_d0): at the end, where the next drop
forms, it made the carried density of rings crowding the axis fall further behind their 3D
density ("Rings that gather at a drop's axis").
--bound-xsph (with a rings --axis-pair; suffix _bx) divides each ring's XSPH correction by its
planar kernel sum where that exceeds 1 (domain.bound_ring_xsph): near the axis, where that sum
reached 2-3.5, the correction cancelled or reversed a ring's own velocity, which the pressure
then drove without the ring moving ("A ring held at the axis").
--free-bodies (suffix _fb) takes the surface tension's net axial force off each free body, a
drop or fragment that touches neither the jet nor the nozzle (surface_tension.balance_free_bodies):
the CSF force of a fragment of a few rings does not sum to zero, and one shed by a slow falling
jet at d0/dx 20 flew back up against gravity and broke the jet ("Fragments that fly").
--thin-rings (with the surface fit: --axis-pair rings_fit or --quiet-jets; suffix _tr) gives a free
ring narrower than a tube of radius 1.5 h the normals' curvature instead of the fit
(surface_tension.thin_rings_normals): the fit pulled such a ring, flung out from a slow falling
jet at d0/dx 20, back onto the jet and stopped the run ("Thin rings let go").
--fit-points N (with the surface fit; suffix _fpN) refuses surface fits through fewer than N
points (surface_tension.fit_points_min): a row at the edge of the kernel's reach of the surface
sees three, and where a falling jet has sped up their parabola bent that row the wrong way
("The jets' own capillary growth").
--h-over-dx H (suffix _hH) sets the smoothing length to H spacings (resolution.h_over_dx; the
case's is 2); --step-cap's and --fixed-step's step stay those of the case's h, so that only the
kernel's reach changes (and the breakup rule's gap, 1.5 h, with it). A falling jet's rings move
apart along the axis as it speeds up, and on such a stretched lattice a kernel of 2 spacings
grows capillary waves too fast; 2.32 spacings lengthen every jet, the fast ones past 20% ("A
stretched lattice").
--kernel K (suffix _K) sets numerics.kernel = K in every run (the case's is "wendland"): on such
a stretched lattice the cubic spline grows a column's wave at Weber's rate to a stretch of
about 2 at d0/dx 10, where the Wendland kernel goes wrong from about 1.5; its falling jets grow
at Weber's rate from 0.49 m/s up (17 of the 20 speeds within 20%, the Wendland kernel 16), and
at 0.36-0.42 m/s their two inner rows pair ("The cubic spline on a stretched lattice").
"cubic_spline_tc", the spline with Thomas & Couchman's gradient, does not pair, and its slow
jets fall short as the Wendland kernel's do ("The cubic spline without pairing").
--relaxed-exit (suffix _rx) gives each measured jet's plug the speed x U and diameter d0 x^(-1/2)
to which the tube's fully developed (parabolic) exit profile relaxes, x from the momentum and
mass between the exit and the flat profile (relaxed_exit: 1.23 at 0.34 m/s, 1.29 at 0.58, 1.33
at 1.58), with d0/dx over the plug's diameter; the report gives the lengths over the tube's d0,
as measured, and the drops over the jet's own diameter. The paper's jets keep their plugs.

Each run is sized from a reference length L_ref (the measured L for mc, 13 sqrt(We_d)
(1 + 3 Oh_d) d0 for paper, at least 10 d0; with --size-c C, C sqrt(We_d) (1 + 3 Oh_d) d0
for every run, at least 10 d0, in a study directory of its own: runs sized for jets that
break well before the measured length, at a fraction of the cost): it runs to T = (1.5 + W) L_ref / U
(W = --window, 1 by default; another W has a study directory of its own, suffix _wW), the nozzle holds
the fluid of that time (length U T + 2 d0), and the box reaches 1.6 L_ref + 10 d0 below the
orifice and 2.5 d0 from the axis (--box-radius R: R d0, suffix _boxR; drops beyond leave the
run). The breakup length of a run is the mean of the jet's intact length (jet.csv L, the
paper's 1.5 h rule) over the samples with t >= 1.5 L_ref / U,
by when the start-up has gone (the first breakup comes at about L / U, and the unforced jets
of 0.78 and 1.57 m/s reach their steady lengths at 1.55 and 1.53 L_ref / U). A window sample
with the jet intact to within 1 d0 of the box's end means a jet longer than the box: no length.
Samples intact short of it (a drop touching the jet's end, or a neck held by a thread of axis
rings, at one check) are skipped and counted when they are at most 5% of the window; more,
and the run has no steady length. Its standard deviation over the
window is given beside it, the means over the first and the second half of the window's
samples (a length still drifting shows as two means apart), and the number of samples in the
window (fewer where a run stopped within it). With --own-window (needs --quiet-exit; suffix
_own) a run's window comes from its own length instead (own_window): from the first sample at
t >= t_q + 1.75 L / U to the first sample at or past W L / U later, L the mean length of the
broken samples of that window (at least 10 d0), so that a window is decided by its own samples
and the report is the same however the runs were staged; t_q is when the start-up's disturbance
left the orifice (quiet_since: the surface's wave amplitude 5 d0 below it has stopped falling and
is below 1e-3 a, or the jet drips short of there), and
a run whose orifice is not quiet by twice the time a jet as long as the box would have its
window (its start-up still fading) ends with no length ("start-up not cleared"); a run is
started to (1.75 + W) 10 d0 / U and, once finished, resumed with a later
end (`sphjet run --resume RUN --tmax T`) until its window is whole and flat (its trend within
10% of its mean, and each third of it within 10% of its mean; one that is not is made longer
from the same start by L / (4 U) at a time), or until a window that is not steady spans 2 L / U
(status "finished, unsteady window": a dripping jet's length wanders), so
that the short jets of the slow speeds cost their own lengths and the long ones get a window
past their own start-up. Drops
(equivalent sphere diameters, satellites are drops smaller than d0): the mean of the main drops
of the last sample of the window, and the median and the most frequent size (0.1 d0 bins) of the
main drops of every sample of the window, with the number of drop-samples it is taken over (a
drop counts once for each sample it is seen in). The particles that left the box (run.log; not
the sink's drops), in all and within the window (tools/left_the_box.py says where).

Groups, with the diameter: We_d = rho U^2 d0 / sigma, Oh_d = mu / sqrt(rho sigma d0),
x = sqrt(We_d) (1 + 3 Oh_d); theory L / d0 = ln(a / delta0) x (Weber 1931). The report fits
C in L / d0 = C x through the origin to the measurements and to the runs, and a line
L / d0 = C x + b with its R^2 to each, over every speed and over the convectively unstable
ones alone (We_d >= 2 pi: the speeds where a jet without gravity can stand). The paper's eq 37
is the same form with radius groups (We = We_d / 2, Oh = Oh_d sqrt 2) and C = 13.

`run` is resumable (tools/study_runs.py) and starts the costliest runs first (L_ref^2 / U), so
that runs made side by side (--parallel) end together. `report` reads what exists; missing runs are listed.
`report --brief` prints each run in a few lines instead of the table: its length beside the
measured one, eq 37 and Weber's law with the measurements' C, beside Weber's length with the
run's own disturbance at the orifice (delta0 and the growth fitted by tools/jet_noise.py over
the window), and beside where that fitted envelope reaches a (its own delta0 and growth); its
main drops beside Rayleigh's, and the particles that left the box, if any.
`report --keep-rows` keeps, for the runs not in the study directory, the rows that the report
already in --out gives them (a study made on several machines: runs/ stays on each), and says
which; their lengths enter the fits and the count within 20% as they were reported. The earlier
report must be of the same study (its study directory's name), else the report stops.
"""
import contextlib
import csv
import functools
import io
import math
import os
import re
import statistics
import sys
import tomllib

import jet_noise
from study_runs import (KERNELS, StudyError, add_numerics_arguments, add_run_arguments, add_set_argument, blew_up,
                        check_numerics, numerics_flags, numerics_sets, numerics_tag, dispatch, drops_at, first_breakup, fmt,
                        is_broken, md_table, open_report, read_csv, run_all, run_summary, select_runs, shown,
                        study_parser)

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BASE_CASE = os.path.join("cases", "round_jet", "round_jet.toml")
MC_CSV = os.path.join(REPO, "cases", "round_jet", "mansour_chigier_1994.csv")
# the same figure's jets from the tube's transitional flow (1.64-2.17 m/s): drawn, not run
MC_TRANSITIONAL_CSV = os.path.join(REPO, "cases", "round_jet", "mansour_chigier_1994_transitional.csv")

RHO, MU, SIGMA = 1000.0, 1.0e-3, 0.072       # the base case's water
D0_MC, D0_PAPER = 0.001194, 0.01
PAPER_U0S = (0.07, 0.17, 0.20, 0.25)
RAYLEIGH_DROP = 1.89                          # d / d0 of the drops of the fastest-growing wave
LENGTH_TOL = 0.20     # the breakup lengths' target: within 20% of the measured ones
WINDOW_T_FACTOR, WINDOW_LENGTH = 1.5, 1.0    # the window's start and (default) length, in L_ref / U
# --own-window: the window starts at the first sample t with t >= OWN_START L / U, L the mean
# length over the window itself (at least OWN_MIN_D0 d0): the study's jets reach their steady
# lengths at 1.5-1.8 of their own L / U (cases/round_jet/README.md); a run is sized for
# OWN_MIN_D0 d0 and made longer (resumed with a later end, at least OWN_GROWTH times the last)
# until its window is W L / U long. Breakup checks every L_ref / (OWN_CHECKS U), whatever the
# run's end.
OWN_START, OWN_MIN_D0, OWN_GROWTH, OWN_CHECKS = 1.75, 10.0, 1.25, 200
# A window whose least-squares line rises (or falls) by more than OWN_DRIFT of its mean over the
# window, and by more than twice that change's standard error, holds a jet still growing: the
# window is made longer by OWN_MORE L / U from the same start. A jet that grows slower than
# 0.57 U passes the start's test; over a window of 0.5 L / U one growing at 0.2 U or more
# changes by 10% or more, while the windows of finished runs (0.78 and 1.25 m/s at d0/dx 6,
# 1.25 m/s at d0/dx 10) changed by -5% to +7% (cases/round_jet/README.md, "Each run's window
# from its own length").
OWN_DRIFT, OWN_MORE = 0.10, 0.25
# A straight line does not see a jet that fell and grew back within the window (a fall and a
# regrowth cancel in it: a run whose jet a ring of start-up debris broke at 9 d0 and that grew back
# to 31 d0 had a window of std 32% of its mean with a change of +0.6%). So each third of the
# window (by time) must also hold its mean within OWN_DRIFT of the window's, or within twice that
# third's standard error, else the window is made longer by OWN_MORE L / U.
OWN_PARTS = 3
# A window that is still not steady once it spans OWN_LONGEST L / U from its start is not made
# longer: the jet's length wanders rather than settles (the dripping jets below We_d = 2 pi, whose
# windows' lines changed by 33-83% at c0 = 12 m/s). The run ends there and its length is reported as
# unsteady, with its drift. The convective runs' windows became whole within 0.54-1.09 of their
# own L / U from their start (the 0.78, 0.86, 0.88 and 0.96 m/s runs at c0 12 and 16 m/s).
OWN_LONGEST = 2.0
# The window's clock starts when the jet's start-up disturbance has left the orifice, not at t = 0.
# A slow falling jet clears it slowly: at 0.40 m/s the disturbance amplitude 5 d0 below the orifice
# fell by about 2 every 30 ms from 4e-2 a at 50 ms to 2e-6 a at 450 ms, while the jet broke at the
# end of its pocket of local absolute instability (13-15 d0 up to 260 ms) and then at 23-24 d0; at
# 0.49 m/s it reached its floor (7-12e-7 a) by 140 ms and the jet 30-32 d0 by 160 ms, from 16 d0 in
# the window that a clock from t = 0 gave (cases/round_jet/README.md, "A window after the
# start-up"). So: spans of OWN_MIN_D0 d0 / U from t = 0; the amplitude in a span is sqrt(2) times
# the rms about its median of the surface radius at OWN_QUIET_D0 d0 over the span's samples (as
# tools/jet_noise.py's envelope), where the intact jet reaches there in at least half of them. The
# orifice is quiet from the start of the first of OWN_QUIET_SPANS spans whose last amplitude is at
# least the first's over OWN_QUIET_FACTOR. Settled jets' amplitudes wander by up to a factor 2
# either way over 4 spans (0.49 m/s: 6.1e-7 a to 1.25e-6 a), so only a fall counts; the start-up's
# fell by a factor 6-14 over every 4 spans at 0.40 m/s up to 450 ms (over 2 spans of 25 ms, one
# fall there was only 0.51). 5 d0 is past the nozzle's lattice (2 d0 holds it at
# about 1e-6 a) and short of the breakup of every jet that does not drip. A dripping jet's
# amplitude there is that of its breakup (0.2-0.8 a at 0.34 and 0.36 m/s falling), with spans in
# most of whose samples it is shorter than 5 d0; such a span ends a quiet run as well (a jet that
# drips waits for nothing), so that its window is judged and found unsteady, as before. A run
# that has not gone quiet by own_cap ends there with no length (status "start-up not cleared").
# While the orifice is not quiet the cap is OWN_NOT_QUIET_CAPS times a quiet-from-t = 0 run's: the
# slowest jets' start-up outlasts one box's window (0.36 m/s falling from the tube's relaxed state
# went quiet at 0.411 s, its cap 0.393 s; 0.40 and 0.42 m/s falling with the plug at 0.446 and
# 0.395 s, their caps about 0.45 s), and once quiet each needs its window of a jet shorter than
# the box (0.36 m/s: whole at 0.600 s). A run quiet from t_q has the cap t_q plus one cap, so one
# that goes quiet just before twice the cap may run to about three; the quiet runs are not moved.
OWN_QUIET_D0, OWN_QUIET_SPANS, OWN_QUIET_FACTOR = 5.0, 4, 2.0
# A flat amplitude is not enough: the spans must also stay below OWN_QUIET_LEVEL (in a). At d0/dx 16
# the 0.36 m/s jet falling from the tube's relaxed state held 1.3-3.0e-2 a there over four spans from
# 24 ms, breaking at 12-21 d0 at the end of its pocket of local absolute instability, and was taken
# as quiet, its window at 0.087-0.149 s (13.9 tube d0, -60%); at d0/dx 10 the same jet went quiet at
# 0.41-0.46 s and was 25-26 tube d0 long from 0.53-0.58 s (two realizations). 1e-3 a at 5 d0 is an orifice disturbance of about
# e^-1 of it (Weber's growth over 5 d0), C = ln(a/delta0) near 8, below the floor of 10 that a quiet
# jet is held to and far below the quiet jets' 15-18; their spans there hold 1e-7 to 1e-6 a.
OWN_QUIET_LEVEL = 1e-3
OWN_NOT_QUIET_CAPS = 2.0
BOX_L_FACTOR = 1.6
# The box's reach from the axis in d0 (domain.lx): a drop thrown past it leaves the run. 2.5 d0 is
# five jet radii; 5 and 7.5 d0 were measured (cases/round_jet/README.md, "A plug at the tube's
# relaxed state": "A wider box").
BOX_RADIUS_D0 = 2.5
# A window sample with the jet intact short of the box's end is a drop touching the jet's end or
# a neck held by a thread of axis rings at one check; up to this fraction of such samples the
# length is the mean over the broken ones (more: no steady length). One reaching within
# BOX_END_D0 d0 of the box's end means a jet longer than the box: no length.
INTACT_SKIP_MAX, BOX_END_D0 = 0.05, 1.0
REFILL_NOZZLE = 3.0   # d0 of a refilling nozzle (--quiet-exit): the plug reaches far beyond 2h upstream
QUIET_BULK_VISCOSITY = 0.5   # --quiet-exit's numerics.bulk_viscosity (cases/round_jet/README.md)
# --gravity: g [m/s^2] along the jet, and the falling jets' numerics (cases/round_jet/README.md, "A plug
# that lets go at the orifice")
G_FALL = 9.81
FALLING_SETS = (f"gravity.gz={-G_FALL:g}", "domain.renormalise_ring_continuity=true", "nozzle.release=crossing")
# --fixed-step, --step-cap: the case's kernel width, Courant number and sound speed, which the
# step is scaled from where the study leaves them
with open(os.path.join(REPO, BASE_CASE), "rb") as _f:
    _CASE = tomllib.load(_f)
CASE_H_OVER_DX, CASE_CFL, CASE_C0 = (_CASE["resolution"]["h_over_dx"], _CASE["time"]["cfl"], _CASE["fluid"]["c0"])
CASE_KERNEL = _CASE["numerics"]["kernel"]
PAPER_C0 = 4.0   # the paper's jets' sound speed (their runs' fluid.c0)
# --quiet-jets: the options (attribute, value, flag) of the quiet round jets' numerics, as the
# quick start and the validation run them (cases/round_jet/README.md, "One evaluation per step")
QUIET_JETS = (("axis_pair", "rings_fit", "--axis-pair"), ("quiet_exit", True, "--quiet-exit"),
              ("artificial_alpha", 0.02, "--artificial-alpha"), ("reconstruct", True, "--reconstruct"),
              ("c0", 12.0, "--c0"), ("cfl", 0.25, "--cfl"), ("leapfrog", True, "--leapfrog"),
              ("sink", 15.0, "--sink"))


# ---------------------------------------------------------------- physics
def groups(u, d0, mu=MU):
    we_d = RHO * u * u * d0 / SIGMA
    oh_d = mu / math.sqrt(RHO * SIGMA * d0)
    x = math.sqrt(we_d) * (1.0 + 3.0 * oh_d)
    return {"We_d": we_d, "Oh_d": oh_d, "x": x,
            "eq37": 13.0 * math.sqrt(we_d / 2) * (1.0 + 3.0 * oh_d * math.sqrt(2)),
            "eq37_d": 13.0 * x}


def fit_origin(xs, ys):
    """C of y = C x (least squares) -> C, or None without points."""
    sxx = sum(x * x for x in xs)
    return sum(x * y for x, y in zip(xs, ys)) / sxx if sxx > 0 else None


def fit_line(xs, ys):
    """y = C x + b -> (C, b, R^2), or None with fewer than 3 points."""
    n = len(xs)
    if n < 3:
        return None
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    syy = sum((y - my) ** 2 for y in ys)
    if sxx == 0:
        return None
    c = sxy / sxx
    b = my - c * mx
    return c, b, (sxy * sxy / (sxx * syy) if syy > 0 else 1.0)


def one_c_band(cs, tol):
    """The interval of C in which C x is within the fraction tol of every measured L/d0 = c x,
    for c in cs: [max(cs) / (1 + tol), min(cs) / (1 - tol)] (empty when the first end is the
    larger), or None without values."""
    return (max(cs) / (1.0 + tol), min(cs) / (1.0 - tol)) if cs else None


def absolutely_unstable(we_d):
    """An inviscid jet without gravity is absolutely unstable (a disturbance grows at the orifice
    as well as downstream, so it drips rather than jets) for rho U^2 a / sigma < pi (Leib &
    Goldstein 1986), We_d < 2 pi; viscosity (Oh_d = 0.0034 here) moves that by little."""
    return we_d < 2.0 * math.pi


def relaxed_exit(u, d0):
    """--relaxed-exit: the flat plug to which the fully developed laminar (parabolic) exit profile
    of a tube of bore d0 and mean speed u relaxes -> (x = U_f / u, U_f, d_f = d0 x^(-1/2)).
    Momentum and mass between the exit (momentum flux 4/3 rho u^2 A0, the Laplace pressure on the
    cut and the surface tension on its rim) and the flat profile downstream give
    x - (2/We_d) x^(-1/2) = 4/3 - 2/We_d (cases/round_jet/README.md, "The tube's parabolic exit
    profile"); gravity and the viscous stresses over the relaxation are left out. The left side
    rises with x, is -1/3 at x = 1 and positive at 4/3: one root between, by bisection."""
    we = groups(u, d0)["We_d"]
    lo, hi = 1.0, 4.0 / 3.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if mid - (2.0 / we) / math.sqrt(mid) < 4.0 / 3.0 - 2.0 / we:
            lo = mid
        else:
            hi = mid
    x = 0.5 * (lo + hi)
    return x, u * x, d0 / math.sqrt(x)


def tube_scale(info):
    """A run's own d0 over the tube's (--relaxed-exit's "tube" in plan's info, or "plug" in the
    info as_tube gives); 1 without it."""
    if "tube" not in info:
        return 1.0
    own = info["plug"][1] if "plug" in info else info["d0"]
    return own / info["tube"][1]


def as_tube(info, r):
    """--relaxed-exit: a run's plan info and read_run summary r as the report gives them: U, d0 and
    the lengths (L, its std and halves, the first breakup's) the tube's, the plug's speed and
    diameter under "plug"; drops stay over the jet's own diameter (Rayleigh's 1.89 is of it).
    Without a relaxed plug, (info, r) as they are."""
    if "tube" not in info:
        return info, r
    (u, d0), scale = info["tube"], tube_scale(info)
    r = dict(r)
    for k in ("L", "L_std", "L_first"):
        if r.get(k) is not None:
            r[k] *= scale
    if r.get("L_halves") is not None:
        r["L_halves"] = tuple(scale * v for v in r["L_halves"])
    return dict(info, U=u, d0=d0, plug=(info["U"], info["d0"])), r


def length_text(info, l_d0, std=None):
    """'L/d0 = l_d0 (std std)' of a run (plan's info), a length over the run's own d0; with
    --relaxed-exit the same over the tube's d0 beside it, as the report's table gives it."""
    text = f"L/d0 = {l_d0:.1f}" + ("" if std is None else f" (std {std:.1f})")
    if "tube" in info:
        k = tube_scale(info)
        text += f", {k * l_d0:.1f}" + ("" if std is None else f" (std {k * std:.1f})") + " over the tube's d0"
    return text


def read_mc(path=MC_CSV):
    """-> list of (U, L/d0) of the measurements (comment lines start with #)."""
    try:
        with open(path) as f:
            rows = list(csv.DictReader(l for l in f if not l.startswith("#")))
        return [(float(r["U_m_per_s"]), float(r["L_over_d0"])) for r in rows]
    except (OSError, KeyError, ValueError) as e:
        raise StudyError(f"{path}: cannot read the measurements ({e})")


# ---------------------------------------------------------------- the plan
def u_tag(u):
    return f"u{u:g}"


def window_start(info):
    """The window's start [s] of a run of the plan (its info: U, L_ref)."""
    return WINDOW_T_FACTOR * info["L_ref"] / info["U"]


def measured_c():
    """C of L/d0 = C x through the origin over every measured jet (18.4)."""
    mc = read_mc()
    return fit_origin([groups(u, D0_MC)["x"] for u, _l in mc], [l for _u, l in mc])


@functools.lru_cache(maxsize=None)
def falling_jet(u, d0, one_frequency=False):
    """Weber's growth along a jet of speed u and diameter d0 falling at G_FALL
    (tools/jet_gravity_theory.py's Jet: the fastest local rate's, about half a second to build, or
    with one_frequency the frequency that has grown most's, 2-4 s; once per run)."""
    import jet_gravity_theory   # it imports this module: here, not at the top
    return jet_gravity_theory.Jet(u, 0.5 * d0, G_FALL, one_frequency=one_frequency)


def falling_c(info, l_d0, one_frequency=False):
    """--gravity: ln(a/delta0) that Weber's growth along the falling jet (followed at one frequency
    with one_frequency) reaches at the length l_d0 [d0] of a run of the plan (info: U, d0); None
    for no length."""
    u, d = info.get("plug", (info["U"], info["d0"]))   # as_tube's info: the jet leaves at the plug's
    return None if l_d0 is None else falling_jet(u, d, one_frequency).exponent(l_d0 * info["d0"])


def box_below(l_ref, d0):
    """The box's reach below the orifice [m] (drops beyond it leave the run)."""
    return BOX_L_FACTOR * l_ref + 10.0 * d0


def sizing(u, d0, l_ref, n, refill=False, window=WINDOW_LENGTH, own=False, radius=BOX_RADIUS_D0):
    """The overrides that size one run: nozzle length, box, orifice height, end time, sampling.
    refill: a nozzle of REFILL_NOZZLE d0 that refills (nozzle.refill) instead of one that holds
    the fluid of the whole run; window: the window's length in L_ref / U (the run ends at
    WINDOW_T_FACTOR + window of them); own: --own-window's first end and checks (own_window);
    radius: the box's reach from the axis in d0 (domain.lx)."""
    dx = d0 / n
    if own:
        t_end, every, refill = (OWN_START + window) * OWN_MIN_D0 * d0 / u, own_check_every(l_ref, u), True
    else:
        t_end = (WINDOW_T_FACTOR + window) * l_ref / u
        every = t_end / 400
    nozzle = REFILL_NOZZLE if refill else u * t_end / d0 + 2.0
    below = box_below(l_ref, d0)
    z0 = below
    lz = below + nozzle * d0 + 2.0 * dx
    return [f"resolution.dx={dx:.9g}", f"nozzle.d0={d0:g}", f"nozzle.u0={u:g}",
            f"nozzle.length_over_d0={nozzle:.6g}", f"nozzle.z0={z0:.9g}", f"domain.lz={lz:.9g}",
            f"domain.lx={radius * d0:.9g}", f"time.tmax={t_end:.6g}",
            f"breakup.check_every={every:.4g}", f"time.out={(20 * every if own else t_end / 20):.4g}"] + \
        (["nozzle.refill=true"] if refill else [])


def expected_cost(info):
    """-> a run's cost up to a factor (info as plan's): its particles grow with its length and its
    steps with its time, L_ref / U, so L_ref^2 / U. In the quiet study (--quiet-jets, c0 12 m/s)
    the twelve convective runs took 997-1821 s of one core, the eight absolutely unstable ones,
    shorter than measured, 85-1322 s (cases/round_jet/README.md); `run` starts the costliest
    first."""
    return info["L_ref"] ** 2 / info["U"]


def own_check_every(l_ref, u):
    """--own-window's interval between breakup checks [s]."""
    return l_ref / (OWN_CHECKS * u)


def quiet_span(u, d0):
    """--own-window: the span [s] over which quiet_spans takes each amplitude, OWN_MIN_D0 d0 / U."""
    return OWN_MIN_D0 * d0 / u


def quiet_spans(surface, u, d0):
    """A run's jet_surface.csv rows (time, s_over_d0, r_over_d0), for speed u and diameter d0 ->
    the wave amplitude [a] OWN_QUIET_D0 d0 below the orifice in each complete quiet_span from
    t = 0 (tools/jet_noise.py's envelope at that slice over the span's samples; OWN_QUIET_D0's
    comment), None for a span in more than half of whose samples the intact jet is shorter."""
    span = quiet_span(u, d0)
    times, at = {}, {}
    width = None
    for x in surface:
        s = float(x["s_over_d0"])
        if width is None:
            width = 2.0 * s   # the first slice's centre is half a slice from the orifice
        k = int(float(x["time"]) // span)
        times.setdefault(k, set()).add(x["time"])
        if abs(s - width * (math.floor(OWN_QUIET_D0 / width) + 0.5)) < 0.25 * width:
            at.setdefault(k, []).append(x)
    amps = []
    for k in range(max(times, default=0)):   # the last span may still be filling
        env = jet_noise.envelope(at.get(k, []), times[k], None) if k in times else []
        amps.append(env[0][1] if env else None)
    return amps


def first_quiet(amps):
    """quiet_spans' amplitudes -> the index of the span the orifice is quiet from (OWN_QUIET_D0's
    and OWN_QUIET_LEVEL's comments), None while the start-up's disturbance is still fading there
    or still loud. A span in most of whose samples the jet is shorter than OWN_QUIET_D0 (it
    drips, breaking at the orifice: no start-up to wait for there) ends a quiet run of spans as
    well."""
    for k in range(len(amps) + 1 - OWN_QUIET_SPANS):
        part = amps[k:k + OWN_QUIET_SPANS]
        if part[-1] is None or (all(a is not None for a in part) and part[0] > 0.0
                                and part[-1] >= part[0] / OWN_QUIET_FACTOR
                                and max(part) < OWN_QUIET_LEVEL):
            return k
    return None


def quiet_since(surface, u, d0):
    """--own-window: when the orifice went quiet [s] (first_quiet) from a run's jet_surface.csv
    rows for speed u and diameter d0; None while it has not."""
    k = first_quiet(quiet_spans(surface, u, d0))
    return None if k is None else k * quiet_span(u, d0)


def run_quiet(run_dir, info):
    """quiet_since of a run directory -> (quiet [s] or None, note or None): a run without
    jet_surface.csv (the breakup checks off) is taken as quiet from t = 0 and its note says so;
    one not quiet has a note of why (its last spans)."""
    try:
        surface = read_csv(os.path.join(run_dir, "jet_surface.csv"))
    except (OSError, ValueError):
        return 0.0, "no jet_surface.csv: its window's clock starts at t = 0, the orifice's quiet not judged"
    amps = quiet_spans(surface, info["U"], info["d0"])
    k = first_quiet(amps)
    if k is not None:
        return k * quiet_span(info["U"], info["d0"]), None
    last = [a for a in amps[-OWN_QUIET_SPANS:] if a is not None]
    if not last:
        return None, None
    loud = f", above {OWN_QUIET_LEVEL:g} a" if max(last) >= OWN_QUIET_LEVEL else ""
    return None, (f"the wave amplitude {OWN_QUIET_D0:g} d0 below the orifice went from {last[0]:.2g} a to "
                  f"{last[-1]:.2g} a over its last {OWN_QUIET_SPANS} spans of {OWN_MIN_D0:g} d0 / U{loud}: not quiet")


def own_window(rows, u, d0, window, quiet=0.0):
    """--own-window: a run's window from its jet.csv rows alone, the same however the run was
    staged (u, d0 its speed and diameter, window W, quiet the time the orifice went quiet,
    quiet_since, None while it has not). A broken sample at t_j is a candidate start; its window
    ends at the first row at or past t_j + W tau_j, tau_j = max(L_j, OWN_MIN_D0) d0 / U and L_j
    the mean length of the broken samples from t_j to that row, so that the window is decided by
    its own samples and none after it. The window starts at the first candidate with t_j >= quiet
    + OWN_START tau_j. If its trend is not flat (OWN_DRIFT) or one of its parts does not hold
    its mean (OWN_PARTS, parts_off), it ends instead at the first row past t_j + (W + m OWN_MORE)
    tau_j for m = 1, 2, ..., the first such window that is steady, up to max(OWN_LONGEST, W)
    tau_j, where a window still not steady is "unsteady". A candidate whose end the rows do not
    reach yet is undecided: the first candidate after it that passes the start's test on the
    rows so far (or, whose end is reached, on its own) is pending, and without one there is no
    start yet.
    -> dict start (t_j, None with no start yet), L (L_j in d0), tau (tau_j [s]), end (the
    window's last row's time, None while the rows do not reach it), steady (True, False
    (unsteady at the longest) or None while undecided), drift (the judged window's change along
    its least-squares line over its mean, or None), parts (parts_off's departure), need (the end
    [s] the rows are to reach next: the pending window's end; with no start yet, the end that a
    window of the recent length would need (each length at most the U t issued by then), at
    least OWN_GROWTH times the last sample's time), quiet (as given)."""
    times = [float(x["time"]) for x in rows]
    lengths = [float(x["L_over_d0"]) if is_broken(x) else None for x in rows]
    if quiet is not None:
        earliest = quiet + OWN_START * OWN_MIN_D0 * d0 / u   # tau_j is never less
        blocked = None   # the end [s] of the first candidate the rows do not decide yet
        for j, t in enumerate(times):
            if lengths[j] is None or t < earliest:
                continue
            got = window_from(times, lengths, j, u, d0, window)
            passes = t >= quiet + OWN_START * got["tau"]
            if got["end"] is None and not passes:
                blocked = got["need"] if blocked is None else blocked
                continue
            if not passes:
                continue
            out = {"start": t, "L": got["L"], "tau": got["tau"], "end": None, "steady": None,
                   "drift": None, "parts": None, "need": max(got["need"], blocked or 0.0),
                   "quiet": quiet}
            if got["end"] is None or blocked is not None:
                return out   # pending: the likely start, its end (or an earlier one's) not reached
            return dict(out, **judge_window(times, lengths, j, got, window))
    # a length counts up to the fluid issued since the start, U t: the rest of a longer jet is
    # the starting column's (--column), not the jet's own (a jet started at the orifice was at
    # most 0.92 U t long in the study's runs)
    broken = [(t, l) for t, l in zip(times, lengths) if l is not None]
    recent = [min(l, u * t / d0) for t, l in broken[-10:]]
    longest = max(sum(recent) / len(recent) if recent else 0.0, OWN_MIN_D0)
    t_last = times[-1] if times else 0.0
    return {"start": None, "L": None, "end": None, "steady": None, "drift": None, "quiet": quiet,
            "need": max(clock_end(longest * d0, u, window, quiet), OWN_GROWTH * t_last)}


def window_from(times, lengths, j, u, d0, window):
    """own_window's candidate window from row j (broken): -> dict L (the mean length [d0] of its
    broken rows), tau (max(L, OWN_MIN_D0) d0 / U [s]), end (the index of the first row at or
    past t_j + window tau, tau from the rows up to it; None when no row reaches it, L and tau
    then over every row from j) and need (t_j + window tau [s])."""
    total, n = 0.0, 0
    for k in range(j, len(times)):
        if lengths[k] is not None:
            total, n = total + lengths[k], n + 1
        tau = max(total / n, OWN_MIN_D0) * d0 / u
        if times[k] >= times[j] + window * tau:
            return {"L": total / n, "tau": tau, "end": k, "need": times[j] + window * tau}
    return {"L": total / n, "tau": tau, "end": None, "need": times[j] + window * tau}


def judge_window(times, lengths, j, got, window):
    """own_window's window from row j whose first end (window_from's got) the rows reach: its
    drift and parts, lengthened by OWN_MORE tau at a time while it is not steady (own_window).
    -> the keys end, steady, drift, parts and need of own_window's dict."""
    tau, e, extent = got["tau"], got["end"], window
    while True:
        win = [(times[k], lengths[k]) for k in range(j, e + 1) if lengths[k] is not None]
        out = {"end": times[e], "need": times[e], "steady": True, "drift": None, "parts": 0.0}
        if len(win) >= 3:
            mean = statistics.fmean(l for _t, l in win)
            change, error = trend(win)
            out["drift"], out["parts"] = change / mean, parts_off(win, mean)
            drifts = abs(change) > OWN_DRIFT * mean and abs(change) > 2.0 * error
            out["steady"] = not (drifts or out["parts"])
        if out["steady"] or extent >= max(OWN_LONGEST, window) - 1e-9:
            return out
        extent += OWN_MORE
        target = times[j] + extent * tau
        e = next((k for k in range(e, len(times)) if times[k] >= target), None)
        if e is None:
            return dict(out, end=None, steady=None, need=target)


def clock_end(length, u, window, quiet):
    """--own-window: the end [s] of a window of a jet length [m] long at speed u that starts as
    soon as the clock lets it, OWN_START length / u after quiet (after t = 0 while quiet is None),
    and is window length / u long (own_window's need before a start, own_cap)."""
    return (quiet or 0.0) + (OWN_START + window) * length / u


def parts_off(samples, mean):
    """(t, L) samples of a window and their mean -> the largest departure of the mean of one of
    its OWN_PARTS parts by time from the window's mean, over the window's mean, when it is more
    than OWN_DRIFT and more than twice that part's standard error (its samples taken as
    independent); else 0.0. Parts of fewer than 2 samples are not judged."""
    t0, t1 = samples[0][0], samples[-1][0]
    worst = 0.0
    for k in range(OWN_PARTS):
        lo, hi = t0 + (t1 - t0) * k / OWN_PARTS, t0 + (t1 - t0) * (k + 1) / OWN_PARTS
        part = [l for t, l in samples if lo <= t < hi or (k == OWN_PARTS - 1 and t == t1)]
        if len(part) < 2:
            continue
        m = sum(part) / len(part)
        se = statistics.stdev(part) / math.sqrt(len(part))
        off = abs(m - mean)
        if off > OWN_DRIFT * mean and off > 2.0 * se:
            worst = max(worst, off / mean)
    return worst


def trend(samples):
    """(t, L) samples (at least 3) -> (the change of L along their least-squares line (fit_line)
    from the first time to the last, its standard error from the residuals)."""
    fit = fit_line([t for t, _l in samples], [l for _t, l in samples])
    if fit is None or fit[0] == 0.0:
        return 0.0, 0.0
    slope, _b, r2 = fit   # the slope's variance: slope^2 (1/R^2 - 1) / (n - 2)
    span = samples[-1][0] - samples[0][0]
    return slope * span, abs(slope) * math.sqrt(max(1.0 / r2 - 1.0, 0.0) / (len(samples) - 2)) * span


def unsteady(ow):
    """-> how own_window's judged window ow departs from a steady one (its line's change, the
    third farthest off its mean), as a phrase to append; '' when it was not judged."""
    return (("" if ow["drift"] is None else f", changing by {100 * ow['drift']:+.0f}% along it")
            + (f", a third of it {100 * ow['parts']:.0f}% off its mean" if ow.get("parts") else ""))


def no_longer(ow, verdict, info, window):
    """--own-window: why a run whose own_verdict is "capped" or "unsteady" is made no longer, as
    `run` prints it beside "done" and `report` notes it."""
    if verdict == "capped":
        cap = own_cap(info, window, ow.get("quiet"))
        whose = ("a jet as long as the box" if ow.get("quiet") is not None else
                 f"{OWN_NOT_QUIET_CAPS:g} times a box-long jet's window from t = 0")
        return (f"made as long as --own-window goes (t = {cap:.4g} s, {whose}) without a whole window" + unsteady(ow)
                + ("" if ow.get("quiet") is not None else
                   f": the orifice not quiet ({OWN_QUIET_D0:g} d0 below it), no steady length"))
    return (f"its window not steady over {max(OWN_LONGEST, window):g} of its own L / U (from t = "
            f"{ow['start']:.4g} s, {length_text(info, ow['L'])})" + unsteady(ow) + ": the length wanders, made no longer")


def own_verdict(rows, info, window, quiet=0.0):
    """--own-window: what a run's jet.csv rows (at least one) say of its window, for `run` and
    `report` alike -> (own_window's dict, verdict, end): verdict "whole" (a steady window),
    "unsteady" (a window still not steady at max(OWN_LONGEST, W) of its own L / U: made no
    longer), "capped" (neither, but the rows reach own_cap within one check: made no longer) or
    "more", with the end [s] to resume it to (the need and one check more, at most own_cap).
    quiet: as own_window's."""
    every = own_check_every(info["L_ref"], info["U"])
    ow = own_window(rows, info["U"], info["d0"], window, quiet)
    if ow["steady"] is not None:
        return ow, "whole" if ow["steady"] else "unsteady", None
    cap = own_cap(info, window, quiet)
    if float(rows[-1]["time"]) >= cap - every:
        return ow, "capped", None
    return ow, "more", min(ow["need"] + every, cap)


def own_cap(info, window, quiet=0.0):
    """--own-window: the latest end [s] a run is made longer to (a window of a jet as long as
    the box, its clock from quiet as own_window's; while the orifice is not quiet (quiet None),
    OWN_NOT_QUIET_CAPS times that window's end from t = 0)."""
    if quiet is None:
        return OWN_NOT_QUIET_CAPS * clock_end(info["box"], info["U"], window, 0.0)
    return clock_end(info["box"], info["U"], window, quiet)


def plan(opts):
    """-> list of (set, name, overrides, info) with info = U, d0, L_ref, L_meas. opts: the parsed
    options of `run` or `report` (eps, d0_over_dx, size_c, remove_h, axis_pair, quiet_exit,
    artificial_alpha, reconstruct). eps: nozzle.disturbance of every run; d0_over_dx: the
    resolution; size_c: L_ref = size_c x d0 (at least 10 d0) for every run instead of the measured or eq 37
    length; axis_pair: domain.axis_pair of every run (None: the case's, the smoothed-radius
    pair), or "rings_own": the rings pair with surface_tension.rings_curvature = "own", or
    "rings_fit": the rings pair with the surface fit and the tensile correction; quiet_exit: the
    bulk viscosity and a refilling nozzle; artificial_alpha, reconstruct, c0, cfl: the damping,
    the measured jets' sound speed and the Courant number (study_runs.numerics_sets); column: the
    starting column's length in L_ref (None: none); gravity: the jets fall (FALLING_SETS);
    fixed_step, step_cap: F of a fixed or capped step F cfl h / c0 (step_sets), None for neither;
    landed: nozzle.release = "landed"; margin: domain.renormalise_margin_d0 (None: the key's 0);
    bound_xsph: domain.bound_ring_xsph; free_bodies: surface_tension.balance_free_bodies;
    thin_rings: surface_tension.thin_rings_normals; fit_points: surface_tension.fit_points_min
    (None: the key's 3); h_over_dx: resolution.h_over_dx (None: the case's); kernel:
    numerics.kernel (None: the case's); relaxed_exit: the mc runs' plugs at the tube's relaxed
    state (relaxed_exit), their info with "tube": (U, d0) the measured jet's (L_meas is over that
    d0; as_tube gives a run's lengths so)."""
    size_c, remove_h, axis_pair, quiet = opts.size_c, opts.remove_h, opts.axis_pair, opts.quiet_exit
    eps, n, window, own = opts.eps, opts.d0_over_dx, opts.window, opts.own_window
    radius = opts.box_radius
    runs = []
    for u, l_meas in read_mc():
        l_ref = max(l_meas if size_c is None else size_c * groups(u, D0_MC)["x"], 10.0) * D0_MC
        # --relaxed-exit: the run's plug at the tube's relaxed speed and diameter, d0/dx over that diameter
        u_run, d_run = relaxed_exit(u, D0_MC)[1:] if opts.relaxed_exit else (u, D0_MC)
        runs.append(("mc", f"mc_{u_tag(u)}", sizing(u_run, d_run, l_ref, n, quiet, window, own, radius),
                     {"U": u_run, "d0": d_run, "L_ref": l_ref, "L_meas": l_meas, "box": box_below(l_ref, d_run),
                      "own": own, "W": window} | ({"tube": (u, D0_MC)} if opts.relaxed_exit else {})))
    for u in PAPER_U0S:
        g = groups(u, D0_PAPER)
        l_ref = max(g["eq37_d"] if size_c is None else size_c * g["x"], 10.0) * D0_PAPER
        runs.append(("paper", f"paper_{u_tag(u)}", sizing(u, D0_PAPER, l_ref, n, quiet, window, own, radius) + [f"fluid.c0={PAPER_C0:g}"],
                     {"U": u, "d0": D0_PAPER, "L_ref": l_ref, "L_meas": None, "box": box_below(l_ref, D0_PAPER),
                      "own": own, "W": window}))
    if opts.column is not None:
        # the jet already out at the start, opts.column x its L_ref long (nozzle.column_over_d0)
        runs = [(st, name, sets + [f"nozzle.column_over_d0={opts.column * info['L_ref'] / info['d0']:.6g}"], info)
                for st, name, sets, info in runs]
    extra = [f"nozzle.disturbance={eps:g}"]
    if remove_h is not None:
        extra.append(f"breakup.remove_drops_below_h={remove_h:g}")
    if axis_pair == "rings_own":
        extra += ["domain.axis_pair=rings", "surface_tension.rings_curvature=own"]
    elif axis_pair == "rings_fit":
        extra += ["domain.axis_pair=rings", "surface_tension.curvature=surface_fit",
                  "numerics.tensile_correction=on"]
    elif axis_pair is not None:
        extra.append(f"domain.axis_pair={axis_pair}")
    if quiet:
        extra += [f"numerics.bulk_viscosity={QUIET_BULK_VISCOSITY:g}", "domain.split_axis_rings=true"]
    extra += numerics_sets(opts)
    if opts.gravity:   # --landed's release in place of the falling jets' crossing
        extra += [e for e in FALLING_SETS if not (opts.landed and e.startswith("nozzle.release="))]
    if opts.landed:
        extra.append("nozzle.release=landed")
    if opts.margin is not None:
        extra.append(f"domain.renormalise_margin_d0={opts.margin:g}")
    if opts.bound_xsph:
        extra.append("domain.bound_ring_xsph=true")
    if opts.free_bodies:
        extra.append("surface_tension.balance_free_bodies=true")
    if opts.thin_rings:
        extra.append("surface_tension.thin_rings_normals=true")
    if opts.fit_points is not None:
        extra.append(f"surface_tension.fit_points_min={opts.fit_points}")
    if opts.h_over_dx is not None:
        extra.append(f"resolution.h_over_dx={opts.h_over_dx:g}")
    if opts.kernel is not None:
        extra.append(f"numerics.kernel={opts.kernel}")
    if opts.sink is not None:
        extra.append(f"breakup.remove_drops_beyond_d0={opts.sink:g}")
    # --c0 is the measured jets' sound speed: the paper's jets keep their own 4 m/s
    return [(s, name, sets + [e for e in extra if s == "mc" or not e.startswith("fluid.c0=")]
             + step_sets(opts, info["d0"] / n, (opts.c0 or CASE_C0) if s == "mc" else PAPER_C0), info)
            for s, name, sets, info in runs]


def step_sets(opts, dx, c0):
    """--fixed-step F or --step-cap F: the overrides of a fixed step, or of the variable step's cap,
    F cfl h / c0 for a run of spacing dx and sound speed c0 (h = CASE_H_OVER_DX dx; cfl the
    study's, or the case's); [] with neither."""
    f = opts.fixed_step or opts.step_cap
    if f is None:
        return []
    dt = f"{f * (opts.cfl or CASE_CFL) * CASE_H_OVER_DX * dx / c0:.6g}"
    return ["time.variable_dt=false", f"time.dt={dt}"] if opts.fixed_step else [f"time.dt_max={dt}"]


SET_NAMES = ("mc", "paper")
# --axis-pair's choices, each a variant of the rings pair (domain.axis_pair = "rings")
RINGS_PAIRS = ("rings", "rings_own", "rings_fit")


def flag_text(flag, value):
    """-> a flag with its value as the command line gives it ('--leapfrog', '--c0 12')."""
    return flag if value is True else f"{flag} {value:g}" if isinstance(value, float) else f"{flag} {value}"


def is_quiet_jets(opts):
    """-> whether opts hold every option of QUIET_JETS at its value."""
    return all(getattr(opts, attr) == value for attr, value, _flag in QUIET_JETS)


def study_flags(opts):
    """-> the command-line flags that give opts' study (as study_dir names it); --quiet-jets for
    the options it stands for."""
    flags = (f" --eps {opts.eps:g} --d0-over-dx {opts.d0_over_dx:g}"
            + ("" if opts.size_c is None else f" --size-c {opts.size_c:g}")
            + ("" if opts.remove_h is None else f" --remove-drops-below-h {opts.remove_h:g}")
            + ("" if opts.axis_pair is None else f" --axis-pair {opts.axis_pair}")
            + (" --quiet-exit" if opts.quiet_exit else "") + numerics_flags(opts)
            + ("" if opts.sink is None else f" --sink {opts.sink:g}")
            + ("" if opts.window == WINDOW_LENGTH else f" --window {opts.window:g}")
            + (" --own-window" if opts.own_window else "")
            + ("" if opts.column is None else f" --column {opts.column:g}")
            + (" --gravity" if opts.gravity else "")
            + ("" if opts.fixed_step is None else f" --fixed-step {opts.fixed_step:g}")
            + ("" if opts.step_cap is None else f" --step-cap {opts.step_cap:g}")
            + (" --landed" if opts.landed else "")
            + ("" if opts.margin is None else f" --renormalise-margin {opts.margin:g}")
            + (" --bound-xsph" if opts.bound_xsph else "")
            + (" --free-bodies" if opts.free_bodies else "")
            + (" --thin-rings" if opts.thin_rings else "")
            + ("" if opts.fit_points is None else f" --fit-points {opts.fit_points}")
            + ("" if opts.h_over_dx is None else f" --h-over-dx {opts.h_over_dx:g}")
            + ("" if opts.kernel is None else f" --kernel {opts.kernel}")
            + (" --relaxed-exit" if opts.relaxed_exit else "")
            + ("" if opts.box_radius == BOX_RADIUS_D0 else f" --box-radius {opts.box_radius:g}"))
    if is_quiet_jets(opts):
        for _attr, value, flag in QUIET_JETS:
            flags = flags.replace(" " + flag_text(flag, value), "", 1)
        flags = flags.replace(f" --d0-over-dx {opts.d0_over_dx:g}", f" --d0-over-dx {opts.d0_over_dx:g} --quiet-jets", 1)
    return flags


def study_dir(opts):
    """opts.root/epsEPS_nN (opts.eps, opts.d0_over_dx) with a suffix for each option of opts (as
    plan's) that is not the default."""
    tail = (("" if opts.size_c is None else f"_c{opts.size_c:g}")
            + ("" if opts.remove_h is None else f"_rm{opts.remove_h:g}")
            + ("" if opts.axis_pair is None else f"_{opts.axis_pair}") + ("_quiet" if opts.quiet_exit else "")
            + numerics_tag(opts) + ("" if opts.sink is None else f"_sink{opts.sink:g}")
            + ("" if opts.window == WINDOW_LENGTH else f"_w{opts.window:g}")
            + ("_own" if opts.own_window else "") + ("" if opts.column is None else f"_col{opts.column:g}")
            + ("_g" if opts.gravity else "") + ("" if opts.fixed_step is None else f"_fix{opts.fixed_step:g}")
            + ("" if opts.step_cap is None else f"_cap{opts.step_cap:g}") + ("_land" if opts.landed else "")
            + ("" if opts.margin is None else f"_margin{opts.margin:g}")
            + ("_bx" if opts.bound_xsph else "") + ("_fb" if opts.free_bodies else "")
            + ("_tr" if opts.thin_rings else "")
            + ("" if opts.fit_points is None else f"_fp{opts.fit_points}")
            + ("" if opts.h_over_dx is None else f"_h{opts.h_over_dx:g}")
            + ("" if opts.kernel is None else f"_{opts.kernel}") + ("_rx" if opts.relaxed_exit else "")
            + ("" if opts.box_radius == BOX_RADIUS_D0 else f"_box{opts.box_radius:g}"))
    return os.path.join(opts.root, f"eps{opts.eps:g}_n{opts.d0_over_dx:g}{tail}")


def cmd_run(args):
    sdir = study_dir(args)
    case = os.path.join(REPO, BASE_CASE)
    names = args.set_name or list(SET_NAMES)
    todo = select_runs(plan(args), names, args.only, args.sphjet, args.dry_run)
    title = (f"round jet study: {len(todo)} run(s) in {sdir} (d0/dx = {args.d0_over_dx:g}, "
             f"disturbance {args.eps:g}, sets {', '.join(names)})")
    infos = {name: info for _s, name, _sets, info in todo}

    def more_time(name, run_dir):
        """--own-window: (the end a finished run is to go on to, why); (None, why) when it is made
        no longer with its window not whole (own_cap reached, or unsteady); None when its window
        is whole or it cannot have it (a blow-up, no rows)."""
        info = infos[name]
        try:
            rows = read_csv(os.path.join(run_dir, "jet.csv"))
        except (OSError, ValueError):
            return None
        if not rows or blew_up(run_dir):
            return None
        ow, verdict, end = own_verdict(rows, info, args.window, run_quiet(run_dir, info)[0])
        if verdict == "whole":
            return None
        if verdict != "more":
            return None, no_longer(ow, verdict, info, args.window)
        why = ("no window yet" + (", the orifice not yet quiet" if ow["quiet"] is None else "")
               if ow["start"] is None else
               f"its window from t = {ow['start']:.4g} s, {length_text(info, ow['L'])} so far"
               + unsteady(ow))
        return end, why

    # the costliest first, so that runs made side by side (--parallel) end together
    todo.sort(key=lambda r: -expected_cost(r[3]))
    return run_all([(name, sets) for _s, name, sets, _i in todo], sdir, case, args.sphjet,
                   args.threads, args.tmax, args.dry_run, "round_jet_study.py run", title, REPO, args.parallel,
                   more_time if args.own_window and args.tmax is None else None)


# ---------------------------------------------------------------- report
def drop_mode(diameters, width=0.1):
    """The most frequent of `diameters` (d/d0) in bins of `width` (the bin's centre; the smaller
    one of a tie), or None without any. The main drops of a window spread from 1 to 3.3 d0 (merged
    pairs at 2.4, triples at 2.7): their median moves between realizations of one jet (1.91 and
    2.39 at 0.78 m/s) where their most frequent size stays (1.9)."""
    if not diameters:
        return None
    bins = {}
    for d in diameters:
        k = round(d / width)
        bins[k] = bins.get(k, 0) + 1
    return round(min(bins, key=lambda k: (-bins[k], k)) * width, 9)


def split_window(window, box_d0):
    """The window's jet.csv rows -> (broken, intact, at_end): the samples with the jet broken, those
    with it intact, and of those the ones whose jet reaches within BOX_END_D0 of the box's end
    (box_d0 below the orifice, in d0), where the length is the box's and not the jet's."""
    broken = [x for x in window if is_broken(x)]
    intact = [x for x in window if not is_broken(x)]
    at_end = [x for x in intact if float(x["jet_tip_over_d0"]) >= box_d0 - BOX_END_D0]
    return broken, intact, at_end


def read_run(run_dir, info):
    r = {"status": "missing", "L": None, "L_std": None, "L_halves": None, "n_window": 0, "n_intact": 0,
         "t_first": None,
         "L_first": None, "drops_main": None, "drops_median": None, "drops_mode": None, "n_main_window": 0,
         "n_drops": None, "n_sat": None, "notes": [],
         "wall_s": None, "particles": None, "particle_steps_per_s": None, "finished": False,
         "unsteady": False, "quiet": None, "not_quiet": False}
    t0 = window_start(info)
    r["t0"] = t0
    own_short = []   # --own-window: the end the window still needs [s], when the run is short of it

    def first_and_window(rows):
        nonlocal t0
        if info.get("own") and rows:
            quiet, why = run_quiet(run_dir, info)
            if why:
                r["notes"].append(why)
            ow, verdict, _end = own_verdict(rows, info, info["W"], quiet)
            r["quiet"] = quiet
            if verdict == "more":
                own_short.append(ow["need"])
                return first_breakup(rows), []
            if verdict in ("capped", "unsteady"):
                r["notes"].append(no_longer(ow, verdict, info, info["W"]))
                r["unsteady"] = verdict == "unsteady"
                if quiet is None:   # no window: the start-up never cleared
                    r["not_quiet"] = True
                    t_end = float(rows[-1]["time"])
                    span = quiet_span(info["U"], info["d0"])
                    late = [float(x["L_over_d0"]) for x in rows
                            if is_broken(x) and float(x["time"]) >= t_end - span]
                    if late:
                        m, sd = statistics.fmean(late), statistics.pstdev(late)
                        r["notes"].append(f"over its last {OWN_MIN_D0:g} d0 / U ({t_end - span:.4g}-{t_end:.4g} s) "
                                          f"the jet broke at {length_text(info, m, sd)}, not a steady length")
                    return first_breakup(rows), []
            if ow["start"] is not None:
                t0 = r["t0"] = ow["start"]
            if ow["end"] is not None:   # the window's own end: the rows after it are not its
                return first_breakup(rows), [x for x in rows if t0 <= float(x["time"]) <= ow["end"]]
        return first_breakup(rows), [x for x in rows if float(x["time"]) >= t0]

    got = run_summary(run_dir, r, first_and_window)
    if got is None:
        return r
    first, window = got
    if own_short:
        r["notes"].append(f"its own window needs the run to reach t = {own_short[0]:.4g} s "
                          f"(`round_jet_study.py run ... --own-window` makes it longer)")
    if first is not None:
        r["t_first"], r["L_first"] = float(first["time"]), float(first["L_over_d0"])
    r["n_window"] = len(window)
    r["t1"] = float(window[-1]["time"]) if window else None
    broken, intact, at_end = split_window(window, info["box"] / info["d0"])
    r["n_intact"] = len(intact)
    if window and not at_end and len(intact) <= INTACT_SKIP_MAX * len(window):
        ls = [float(x["L_over_d0"]) for x in broken]
        r["L"] = sum(ls) / len(ls)
        r["L_std"] = math.sqrt(sum((v - r["L"]) ** 2 for v in ls) / len(ls))
        # the means over the window's first and second half of the samples: a length still
        # rising (or falling) shows as two means apart by more than the std allows
        if len(ls) >= 2:
            half = len(ls) // 2
            r["L_halves"] = (sum(ls[:half]) / half, sum(ls[half:]) / (len(ls) - half))
        if intact:
            times = ", ".join(f"{float(x['time']):.4g}" for x in intact)
            r["notes"].append(f"{len(intact)} of {len(window)} window samples intact short of the box's end "
                              f"(t = {times} s): skipped")
        step = window[-1]["step"]
        try:
            every = read_csv(os.path.join(run_dir, "drops.csv"))
            d = drops_at(every, step)
            main = [float(x["d_eq_over_d0"]) for x in d if x["satellite"] == "0"]
            r["n_drops"], r["n_sat"] = len(d), len(d) - len(main)
            r["drops_main"] = sum(main) / len(main) if main else None
            # the main drops of every sample of the window (a drop is counted in each sample
            # it is seen in, so the median weighs it by its time in the box): the last
            # sample's few drops, some merging or just pinched off, scatter more
            steps = {x["step"] for x in window}
            seen = [float(x["d_eq_over_d0"]) for x in every
                    if x["step"] in steps and x["satellite"] == "0"]
            r["n_main_window"] = len(seen)
            r["drops_median"] = statistics.median(seen) if seen else None
            r["drops_mode"] = drop_mode(seen)
        except (OSError, KeyError, ValueError) as e:
            r["notes"].append(f"drops.csv: {e}")
    elif at_end:
        r["notes"].append(f"{len(at_end)} of {len(window)} samples after t = {t0:.4g} s intact to the box's "
                          f"end: the jet is longer than the box, no breakup length")
    elif window:
        r["notes"].append(f"{len(intact)} of {len(window)} samples after t = {t0:.4g} s intact (more than "
                          f"{INTACT_SKIP_MAX:.0%}): no steady breakup length")
    # the particles that left the box within the window of a run with a length
    r["left_window"] = (None if r["L"] is None else
                        sum(1 for t in r["left_at"].values() if r["t0"] <= t <= r["t1"]))
    boom = blew_up(run_dir)
    if boom:
        r["status"] = "blew up"
        r["notes"].append(boom)
    elif r["finished"] and own_short:
        r["status"] = "unfinished (its own window not reached)"
    elif r["finished"] and r["not_quiet"]:
        r["status"] = "finished, start-up not cleared"
    elif r["finished"]:
        r["status"] = ("finished, no steady breakup" if r["L"] is None else
                       "finished, unsteady window" if r["unsteady"] else "finished")
    else:
        r["status"] = "unfinished"
    return r


def report(args):
    sdir = study_dir(args)
    open_report(sdir, args.out, "round_jet_study.py run" + study_flags(args))
    chosen = select_runs(plan(args), args.set_name or SET_NAMES, args.only, None, dry_run=True)   # no binary needed
    runs = [(s, name) + as_tube(info, read_run(os.path.join(sdir, name), info)) for s, name, _sets, info in chosen]
    earlier = (earlier_report(args.out, sdir, [name for _s, name, _i, r in runs if r["status"] == "missing"])
               if args.keep_rows else {})
    header = ["run", "U [m/s]", "We_d", "Oh_d", "x = sqrt(We_d)(1+3Oh_d)", "L/d0 measured",
              "L/d0 eq37 (radius)", "L/d0 13x (diameter)", "L/d0 SPH (std)", "L/d0 window halves",
              "window samples", "window from t [s] (its own L/U)",
              "err vs measured", "C = L/(d0 x) measured / SPH", "instability without gravity",
              "first breakup t [s], L/d0", "main drop d/d0",
              "main drops d/d0 window median (drop-samples)", "main drops d/d0 window mode",
              "drops (satellites)", "status",
              "particles", "particles left the box (in the window)", "wall [s]"]
    if args.own_window:
        at = header.index("window from t [s] (its own L/U)") + 1
        header[at:at] = ["window to t [s]", "orifice quiet from t [s]"]
    falling = falling_c if args.gravity else None
    if falling:
        header[header.index("instability without gravity"):header.index("instability without gravity")] = [
            "C = ln(a/delta0) falling, measured / SPH", "C falling at one frequency, measured / SPH"]
    rows, missing, notes = [], [], []
    pts_m, pts_s = [], []   # (x, L/d0, convectively unstable) of the measured jets and the runs
    for k, (s, name, info, r) in enumerate(runs):
        g = groups(info["U"], info["d0"])
        convective = not absolutely_unstable(g["We_d"])
        if name in earlier:   # its row as the earlier report gave it, under this report's header
            row, r = kept_row(earlier[name], header, name)
            runs[k] = (s, name, info, r)
        else:
            err = (None if r["L"] is None or info["L_meas"] is None
                   else 100.0 * (r["L"] - info["L_meas"]) / info["L_meas"])
            row = [name, f"{info['U']:g}", f"{g['We_d']:.3g}", f"{g['Oh_d']:.3g}", f"{g['x']:.3f}",
                   fmt(info["L_meas"]), fmt(g["eq37"]), fmt(g["eq37_d"]),
                   f"{fmt(r['L'])} ({fmt(r['L_std'])})",
                   "-" if r["L_halves"] is None else f"{fmt(r['L_halves'][0])} / {fmt(r['L_halves'][1])}",
                   f"{r['n_window']}" + (f" ({r['n_intact']} intact)" if r["n_intact"] else ""),
                   "-" if r["L"] is None else
                   f"{r['t0']:.4g} ({r['t0'] * info.get('plug', (info['U'],))[0] / (r['L'] * info['d0']):.2f})",
                   fmt(err, "+.0f") + ("%" if err is not None else ""),
                   f"{fmt(None if info['L_meas'] is None else info['L_meas'] / g['x'], '.1f')} / "
                   f"{fmt(None if r['L'] is None else r['L'] / g['x'], '.1f')}",
                   "convective" if convective else "absolute",
                   f"{fmt(r['t_first'], '.4f')}, {fmt(r['L_first'])}", fmt(r["drops_main"]),
                   f"{fmt(r['drops_median'])} ({r['n_main_window']})", fmt(r["drops_mode"], ".1f"),
                   f"{fmt(r['n_drops'], 'd')} ({fmt(r['n_sat'], 'd')})", r["status"],
                   fmt(r["particles"], "d"),
                   f"{fmt(r.get('left'), 'd')} ({fmt(r.get('left_window'), 'd')})",
                   fmt(r["wall_s"], ".0f")]
            if args.own_window:
                row[header.index("window to t [s]"):header.index("window to t [s]")] = [
                    "-" if r["L"] is None else f"{r['t1']:.4g}",
                    "-" if r["status"] == "missing" else fmt(r["quiet"], ".4g")]
            if falling:
                at = header.index("instability without gravity") - 2
                row[at:at] = [f"{fmt(falling(info, info['L_meas'], one), '.1f')} / "
                              f"{fmt(falling(info, r['L'], one), '.1f')}" for one in (False, True)]
        if r["status"] == "missing":
            missing.append(name)
        if info["L_meas"] is not None:
            pts_m.append((g["x"], info["L_meas"], convective))
        if r["notes"]:
            notes.append(f"{name}: " + "; ".join(r["notes"]))
        if s == "mc" and r["L"] is not None:
            pts_s.append((g["x"], r["L"], convective))
        rows.append(row)
    with open(os.path.join(args.out, "round_jets.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)
    def convective_only(pts):
        return [p for p in pts if p[2]]

    def origin_c(pts):
        return fit_origin([p[0] for p in pts], [p[1] for p in pts])

    def fit_row(label, pts, what):
        """A row of the fits table: C through the origin and the line over pts ((x, L/d0, _))."""
        line = fit_line([p[0] for p in pts], [p[1] for p in pts])
        return (f"| {label} ({len(pts)} {what}) | {fmt(origin_c(pts))} | "
                + ("-" if line is None else f"L/d0 = {line[0]:.2f} x {line[1]:+.1f}, R^2 = {line[2]:.3f}")
                + " |\n")

    cs_all = [y / x for x, y, _c in pts_m]   # the measured C = L / (d0 x)
    cs_conv = [y / x for x, y, _c in convective_only(pts_m)]

    def band_text(cs):
        band = one_c_band(cs, LENGTH_TOL)
        if band is None:
            return "-"
        return (f"C from {band[0]:.3f} to {band[1]:.3f}" if band[0] <= band[1]
                else f"none ({band[0]:.3f} > {band[1]:.3f})")

    text = (f"# Round jets (generated by tools/round_jet_study.py report)\n\n"
            f"Study {shown(sdir, REPO)}: d0/dx = "
            f"{args.d0_over_dx:g}, nozzle disturbance {args.eps:g} (plug speed u0 (1 + eps "
            f"sin(omega t)), k a = 0.697), the same for every run.\n\n"
            + md_table(header, rows) +
            "\nFits over the Mansour & Chigier speeds (x = sqrt(We_d)(1 + 3 Oh_d)):\n\n"
            "| | C of L/d0 = C x | line |\n|---|---|---|\n"
            + fit_row("measured", pts_m, "jets") + fit_row("SPH", pts_s, "runs")
            + fit_row("measured, We_d >= 2 pi", convective_only(pts_m), "jets")
            + fit_row("SPH, We_d >= 2 pi", convective_only(pts_s), "runs") + "\n"
            f"One C for every speed, with every length within {LENGTH_TOL:.0%} of the measured one "
            f"(max C / {1 + LENGTH_TOL:g} to min C / {1 - LENGTH_TOL:g} of the measured C = L/(d0 x)):\n"
            f"- the {len(cs_conv)} speeds with We_d >= 2 pi (convectively unstable): {band_text(cs_conv)};\n"
            f"- all {len(cs_all)} speeds: {band_text(cs_all)}.\n"
            f"Below We_d = 2 pi a jet without gravity is absolutely unstable (Leib & Goldstein 1986) "
            f"and breaks near the orifice: {len(cs_all) - len(cs_conv)} of the measured speeds"
            + (f"; here the jets fall (g = {G_FALL:g} m/s^2 along them), and the falling C is the ln(a/delta0) "
               f"that Weber's growth along the falling jet reaches at the length (tools/jet_gravity_theory.py, "
               f"absolute instability left out): at the fastest local rate, and followed at one frequency "
               f"(--one-frequency there: each wave carried down at its own frequency, the one grown most).\n\n"
               if falling else
               ", where this model (no gravity) cannot form the measured jet.\n\n")
            + f"Rayleigh's drop of the fastest-growing wave: {RAYLEIGH_DROP} d0.\n"
            f"Missing runs ({len(missing)}): {', '.join(missing) if missing else 'none'}.\n"
            + (f"Rows kept from the earlier report in {shown(args.out, REPO)} ({len(earlier)}; their runs "
               f"are not in this study directory): {', '.join(sorted(earlier))}.\n" if earlier else "")
            + left_text([r for _s, _n, _i, r in runs])
            + cost_text([r for _s, _n, _i, r in runs])
            + ("\nNotes:\n" + "".join(f"- {n}\n" for n in notes) if notes else ""))
    with open(os.path.join(args.out, "round_jets.md"), "w") as f:
        f.write(text)
    if not args.no_figures:
        figure(args.out, runs, origin_c(pts_m), origin_c(pts_s))
    if args.brief:
        c_all = measured_c()
        text = "\n\n".join(f"{name}: kept from the earlier report (its run is not in this study directory)"
                           if r.get("kept") else brief(sdir, args, name, info, r, c_all)
                           for _s, name, info, r in runs)
    print(text)
    return 0


def earlier_report(out, sdir, names):
    """The report already in `out` (round_jets.csv, and the notes of round_jets.md): {run: (its
    row as a dict of header -> cell, its notes)} for the runs in `names` it holds as made; {}
    without one. It must be a report of the study in sdir (its md names the study directory);
    a report of another study is an error, not a source of rows."""
    csv_path, md_path = os.path.join(out, "round_jets.csv"), os.path.join(out, "round_jets.md")
    if not names or not os.path.isfile(csv_path):
        return {}
    try:
        with open(md_path) as f:
            md = f.read()
    except OSError as e:
        raise StudyError(f"--keep-rows: {md_path}: {e}") from None
    study = re.search(r"^Study (\S+): ", md, re.M)
    if study is None or os.path.basename(study.group(1)) != os.path.basename(sdir):
        raise StudyError(f"--keep-rows: {md_path}: expected a report of the study "
                         f"{os.path.basename(sdir)}, found "
                         f"{'no study line' if study is None else os.path.basename(study.group(1))}")
    notes = {}
    for line in md.split("\nNotes:\n", 1)[1].splitlines() if "\nNotes:\n" in md else []:
        name, sep, note = line.removeprefix("- ").partition(": ")
        if sep:
            notes.setdefault(name, []).append(note)
    with open(csv_path, newline="") as f:
        made = {row["run"]: row for row in csv.DictReader(f) if row.get("status", "missing") != "missing"}
    return {name: (made[name], notes.get(name, [])) for name in names if name in made}


def kept_row(earlier, header, name):
    """An earlier report's row (earlier_report's (row, notes)) -> (this report's row, a summary in
    read_run's terms for the fits, the figure and the box's line). A column the earlier report
    lacks is '-'."""
    row, notes = earlier
    cells = [row.get(col, "-") for col in header]
    cells[0] = name

    def number(col, at=0):
        try:
            return float(row.get(col, "-").replace("(", " ").replace(")", " ").split()[at])
        except (ValueError, IndexError):
            return None

    left = number("particles left the box (in the window)")
    inside = number("particles left the box (in the window)", 1)
    r = {"kept": True, "status": row.get("status", "-"), "notes": notes,
         "L": number("L/d0 SPH (std)"), "L_std": number("L/d0 SPH (std)", 1),
         "left": None if left is None else int(left), "left_window": None if inside is None else int(inside),
         "wall_s": number("wall [s]"), "particle_steps": None}
    return cells, r


def left_text(summaries):
    """The report's line on the particles that left the box (its radial edge or its end; the
    sink's drops are not among them), from the read_run summaries: '' when none did."""
    made = [r for r in summaries if r["status"] != "missing"]
    left = [r.get("left") or 0 for r in made]
    if not any(left):
        return ""
    inside = [r["left_window"] for r in made if r.get("left_window")]
    n_left = sum(1 for n in left if n)
    return (f"Particles that left the box (through its side or its end; the drops the sink removed are "
            f"not counted): {sum(left)} in {n_left} of the {len(made)} runs made, "
            + (f"{sum(inside)} of them within the windows of {len(inside)} of the runs with a length.\n"
               if inside else "none within the window of a run with a length.\n"))


def cost_text(summaries):
    """The report's line on what the runs cost, from their read_run summaries (run.log's walls
    and particle-steps, summed over every part of every run): '' without a run.log."""
    here = [r for r in summaries if not r.get("kept")]
    walls = [r["wall_s"] for r in here if r.get("wall_s")]
    kept = [r["wall_s"] for r in summaries if r.get("kept") and r.get("wall_s")]
    if not walls and not kept:
        return ""
    steps = sum(r.get("particle_steps") or 0.0 for r in here)
    mantissa, exponent = f"{steps:.2e}".split("e")
    return ((f"Cost: {mantissa}e{int(exponent)} particle-steps; the runs' walls sum to {sum(walls):.0f} s "
             f"of one core ({sum(walls) / 7200:.2f} h on two cores if the runs pack, at the speed they "
             f"ran at)" if walls else "Cost: no run read here")
            + (f"; the {len(kept)} kept rows' walls sum to {sum(kept):.0f} s more" if kept else "") + ".\n")


def brief(sdir, args, name, info, r, c_all):
    """The run `name` of the study in sdir (its plan info, its read_run r) in a few lines: its
    length beside the measurement and the theory (c_all: measured_c()), its drops beside
    Rayleigh's."""
    g = groups(info["U"], info["d0"])
    t0 = r.get("t0", window_start(info))
    k = tube_scale(info)
    plug = (f", the plug at the tube's relaxed state: {info['plug'][0]:.4g} m/s, diameter {k:.3f} d0; lengths "
            f"over the tube's d0, drops over the jet's own diameter" if "plug" in info else "")
    lines = [f"{name}: U = {info['U']:g} m/s (We_d = {g['We_d']:.3g}, Oh_d = {g['Oh_d']:.2g}), "
             f"d0/dx = {args.d0_over_dx:g}{plug}, {r['status']}"]
    if r["L"] is None:
        return "\n".join(lines + [f"  no breakup length: {'; '.join(r['notes']) or 'no samples'}"])
    lines.append(f"  breakup length L/d0 = {r['L']:.1f} (std {r['L_std']:.1f}) over {r['n_window']} samples "
                 f"from t = {t0:.4g} s")
    if info["L_meas"] is not None:
        lines.append(f"  measured (Mansour & Chigier 1994): {info['L_meas']:.1f}, this run "
                     f"{100.0 * (r['L'] - info['L_meas']) / info['L_meas']:+.0f}%")
    try:
        with contextlib.redirect_stdout(io.StringIO()):
            noise = jet_noise.analyse(os.path.join(sdir, name), t0)["summary"]
    except jet_noise.NoiseError as e:
        noise = {"error": str(e)}
    if "L_weber_over_d0" in noise:
        lines.append(f"  theory: Weber's L = u0 ln(a/delta0) / omega_max = {k * noise['L_weber_over_d0']:.1f}, with "
                     f"this run's disturbance at the orifice, delta0 = {noise['delta0_over_a']:.2g} a "
                     f"(tools/jet_noise.py; its growth is {noise['omega_over_weber']:.2f} of Weber's)")
        lines.append(f"  with its own growth too: L = ln(a/delta0) / k_s = {k * noise['L_fit_over_d0']:.1f} (where the "
                     f"fitted envelope reaches a)")
    else:
        lines.append(f"  theory: no fit of the disturbance's growth ({noise.get('error', 'no growing stretch')})")
    lines.append(f"  the paper's eq 37: {g['eq37']:.1f}; Weber's law L/d0 = C sqrt(We_d)(1 + 3 Oh_d) with the "
                 f"measurements' C = {c_all:.1f}: {c_all * g['x']:.1f}")
    if args.gravity and info["L_meas"] is not None:
        lines.append(f"  falling (g = {G_FALL:g} m/s^2): Weber's growth along the jet reaches ln(a/delta0) = "
                     f"{falling_c(info, r['L']):.1f} at this length, {falling_c(info, info['L_meas']):.1f} at the "
                     f"measured one (tools/jet_gravity_theory.py); followed at one frequency, "
                     f"{falling_c(info, r['L'], True):.1f} and {falling_c(info, info['L_meas'], True):.1f}")
    lines.append(f"  main drops: {fmt(r['drops_median'])} d0 (median over the window, {r['n_main_window']} "
                 f"drop-samples), most frequent {fmt(r.get('drops_mode'), '.1f')} d0; Rayleigh's: {RAYLEIGH_DROP} d0")
    if r.get("left"):
        lines.append(f"  particles that left the box: {r['left']}, {fmt(r.get('left_window'), 'd')} of them in the window")
    return "\n".join(lines)


def figure(out, runs, c_m, c_s):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    mx = [groups(i["U"], i["d0"])["x"] for s, _n, i, _r in runs if s == "mc"]
    my = [i["L_meas"] for s, _n, i, _r in runs if s == "mc"]
    ax.plot(mx, my, "ko", mfc="none", label="Mansour & Chigier (1994), measured, laminar tube flow")
    if mx:
        tr = read_mc(MC_TRANSITIONAL_CSV)
        ax.plot([groups(u, D0_MC)["x"] for u, _l in tr], [l for _u, l in tr], "^", color="0.55", mfc="none",
                label="the same, the tube's flow transitional (not run)")
    sx = [groups(i["U"], i["d0"])["x"] for s, _n, i, r in runs if s == "mc" and r["L"] is not None]
    sy = [r["L"] for s, _n, i, r in runs if s == "mc" and r["L"] is not None]
    se = [r["L_std"] for s, _n, i, r in runs if s == "mc" and r["L"] is not None]
    if sx:
        ax.errorbar(sx, sy, yerr=se, fmt="s", color="C0", label="sphjet, axisymmetric (std over the window)")
    xs = [0, max(mx) * 1.1]
    ax.plot(xs, [13 * x for x in xs], "k:", label="13 x (diameter groups)")
    if c_m:
        ax.plot(xs, [c_m * x for x in xs], "k--", lw=0.8, label=f"fit to measured, C = {c_m:.1f}")
    if c_s:
        ax.plot(xs, [c_s * x for x in xs], "--", color="C0", lw=0.8, label=f"fit to sphjet, C = {c_s:.1f}")
    ax.set_xlabel("sqrt(We_d) (1 + 3 Oh_d)")
    ax.set_ylabel("breakup length L / d0")
    ax.set_title("Laminar round water jets, d0 = 1.194 mm")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "round_jets_L.png"), dpi=120)
    plt.close(fig)


def parse(argv=None):
    """The command line -> its checked options (what main dispatches on)."""
    ap, sub = study_parser(__doc__)
    root_default = os.path.join(REPO, "runs", "round_jet")
    for name in ("run", "report"):
        p = sub.add_parser(name, help="run what is missing (resumable)" if name == "run"
                           else "tables and the figure of the runs that exist")
        p.add_argument("--root", default=root_default, help="study root (default: REPO/runs/round_jet)")
        p.add_argument("--eps", type=float, default=0.01, help="nozzle disturbance amplitude (default 0.01)")
        p.add_argument("--d0-over-dx", type=float, default=10.0, help="particles across d0 (default 10)")
        p.add_argument("--remove-drops-below-h", dest="remove_h", type=float, default=None, metavar="D",
                       help="remove detached drops with d_eq < D h at the breakup checks (default: keep all)")
        p.add_argument("--axis-pair", choices=RINGS_PAIRS, default=None,
                       help="the rings pair (domain.axis_pair) in every run, rings_own with its surface "
                            "rows' own curvature, rings_fit with the surface fit and the tensile "
                            "correction (default: the smoothed-radius pair)")
        p.add_argument("--quiet-exit", action="store_true",
                       help=f"numerics.bulk_viscosity = {QUIET_BULK_VISCOSITY:g}, a {REFILL_NOZZLE:g} d0 nozzle "
                            "that refills (nozzle.refill) and domain.split_axis_rings in every run (needs a "
                            "rings --axis-pair)")
        add_numerics_arguments(p)
        p.add_argument("--quiet-jets", action="store_true",
                       help="the quiet round jets' numerics in one flag: "
                            + " ".join(flag_text(flag, value) for _a, value, flag in QUIET_JETS)
                            + " (the study directory is theirs)")
        p.add_argument("--sink", type=float, default=None, metavar="M",
                       help="remove the drops wholly farther than M d0 past the jet's end at the checks "
                            "(breakup.remove_drops_beyond_d0; default: none, the box's end is the only sink)")
        p.add_argument("--window", type=float, default=WINDOW_LENGTH, metavar="W",
                       help=f"the window's length in L_ref / U: every run ends at {WINDOW_T_FACTOR:g} + W of "
                            f"them (default {WINDOW_LENGTH:g}; suffix _wW)")
        p.add_argument("--own-window", action="store_true",
                       help=f"each run's window from its own length: from the first sample at t >= "
                            f"t_q + {OWN_START:g} L / U to the first at or past W L / U later (L the "
                            f"window's own mean, t_q when the start-up's disturbance left the "
                            f"orifice), whatever comes after it; runs are "
                            f"sized for {OWN_MIN_D0:g} d0 and made longer until they have it, an unsteady "
                            f"one for at most {OWN_LONGEST:g} L / U (needs "
                            f"--quiet-exit's refilling nozzle; suffix _own)")
        p.add_argument("--column", type=float, default=None, metavar="F",
                       help="start each run with its jet already out: a column of the nozzle's rings F x "
                            "its L_ref long past the orifice, moving at U (nozzle.column_over_d0; default: "
                            "none, the jet starts at the orifice; suffix _colF)")
        p.add_argument("--gravity", action="store_true",
                       help=f"the jets fall along their axis (gravity.gz = {-G_FALL:g}) with the falling jets' "
                            "numerics (domain.renormalise_ring_continuity, nozzle.release = \"crossing\"; needs a "
                            "rings --axis-pair; suffix _g); the report adds Weber's growth along the falling jet")
        p.add_argument("--fixed-step", type=float, default=None, metavar="F",
                       help="a fixed step in every run, F times the CFL step of its fluid at rest "
                            "(time.dt = F cfl h / c0, time.variable_dt = false; 0 < F < 1; default: the "
                            "variable step; suffix _fixF)")
        p.add_argument("--step-cap", type=float, default=None, metavar="F",
                       help="the variable step capped in every run at F times the CFL step of its fluid at "
                            "rest (time.dt_max = F cfl h / c0; 0 < F < 1; suffix _capF)")
        p.add_argument("--landed", action="store_true",
                       help="free the plug's rows exactly at the orifice line, the steps shortened where "
                            "needed so that they cross it at a step's end (nozzle.release = \"landed\"; "
                            "suffix _land)")
        p.add_argument("--renormalise-margin", dest="margin", type=float, default=None, metavar="M",
                       help="with --gravity: the renormalised continuity stops M d0 short of the jet's "
                            "intact end (domain.renormalise_margin_d0; default: at the end; suffix _marginM)")
        p.add_argument("--bound-xsph", action="store_true",
                       help="each ring's XSPH correction over its planar kernel sum where that exceeds 1 "
                            "(domain.bound_ring_xsph; a rings --axis-pair; suffix _bx)")
        p.add_argument("--free-bodies", action="store_true",
                       help="the surface tension's net axial force taken off each drop and fragment "
                            "(surface_tension.balance_free_bodies; suffix _fb)")
        p.add_argument("--thin-rings", action="store_true",
                       help="a free ring narrower than a tube of radius 1.5 h takes the normals' curvature "
                            "instead of the surface fit (surface_tension.thin_rings_normals; with the "
                            "surface fit: --axis-pair rings_fit or --quiet-jets; suffix _tr)")
        p.add_argument("--fit-points", type=int, default=None, metavar="N",
                       help="surface fits through fewer than N points refused, N > 3 "
                            "(surface_tension.fit_points_min; with the surface fit: --axis-pair rings_fit "
                            "or --quiet-jets; suffix _fpN)")
        p.add_argument("--h-over-dx", type=float, default=None, metavar="H",
                       help="the smoothing length H spacings (resolution.h_over_dx; the case's 2), the "
                            "step's cap or fixed step that of the case's h (suffix _hH)")
        p.add_argument("--kernel", choices=KERNELS + ("cubic_spline_tc",), default=None,
                       help=f"numerics.kernel in every run (the case's {CASE_KERNEL}, which is the default's "
                            "runs; suffix _K)")
        p.add_argument("--relaxed-exit", action="store_true",
                       help="the measured jets' plugs at the speed and diameter to which the tube's "
                            "parabolic exit profile relaxes (x = U_f / U from x - (2/We_d) x^(-1/2) = "
                            "4/3 - 2/We_d, d0 x^(-1/2)), d0/dx over that diameter; lengths reported over the "
                            "tube's d0 (suffix _rx)")
        p.add_argument("--box-radius", type=float, default=BOX_RADIUS_D0, metavar="R",
                       help=f"the box reaches R d0 from the axis (domain.lx = R d0; default {BOX_RADIUS_D0:g}): "
                            "a drop thrown farther leaves the run (suffix _boxR)")
        p.add_argument("--size-c", type=float, default=None, metavar="C",
                       help="size every run for L_ref = C sqrt(We_d)(1 + 3 Oh_d) d0 (default: the "
                            "measured length, eq 37 for the paper's jets)")
        if name == "run":
            add_run_arguments(p, SET_NAMES, REPO)
        else:
            p.add_argument("--out", default=os.path.join(REPO, "cases", "round_jet"))
            p.add_argument("--no-figures", action="store_true")
            add_set_argument(p, SET_NAMES)
            p.add_argument("--only", action="extend", nargs="+", metavar="RUN",
                           help="only these runs (default: every run of the plan)")
            p.add_argument("--brief", action="store_true",
                           help="print each run in a few lines (its length beside the measurement and "
                                "the theory, its drops beside Rayleigh's) instead of the table")
            p.add_argument("--keep-rows", action="store_true",
                           help="keep the rows of the report already in --out for the runs that are not "
                                "in this study directory (a study made on several machines); the fits and "
                                "the count within 20%% take them as they were reported")
    args = ap.parse_args(argv)
    if args.quiet_jets:
        for attr, value, flag in QUIET_JETS:
            given = getattr(args, attr)
            if given not in (None, False, 0.0, value):
                ap.error(f"--quiet-jets sets {flag_text(flag, value)}; found {flag_text(flag, given)}")
            setattr(args, attr, value)
    if not (0 <= args.eps < 1):
        ap.error(f"--eps {args.eps}: expected 0 <= eps < 1")
    if args.kernel == CASE_KERNEL:   # the case's own: the default's runs and study directory
        args.kernel = None
    if args.h_over_dx is not None and not 1.0 <= args.h_over_dx <= 4.0:
        ap.error(f"--h-over-dx {args.h_over_dx}: expected a smoothing length of 1 to 4 spacings "
                 "(resolution.h_over_dx; the case's is 2)")
    if not args.box_radius >= 1.0:
        ap.error(f"--box-radius {args.box_radius}: expected R >= 1 (in d0 from the axis; the jet's radius is 0.5 d0)")
    if args.remove_h is not None and not args.remove_h > 0:
        ap.error(f"--remove-drops-below-h {args.remove_h}: expected a positive number")
    if args.size_c is not None and not args.size_c > 0:
        ap.error(f"--size-c {args.size_c}: expected a positive number")
    if not args.window > 0:
        ap.error(f"--window {args.window}: expected a positive number of L_ref / U")
    if args.column is not None and not 0 < args.column < BOX_L_FACTOR:
        ap.error(f"--column {args.column}: expected 0 < F < {BOX_L_FACTOR:g} (the box reaches "
                 f"{BOX_L_FACTOR:g} L_ref + 10 d0 below the orifice)")
    for flag, f in (("--fixed-step", args.fixed_step), ("--step-cap", args.step_cap)):
        if f is not None and not 0 < f < 1:
            ap.error(f"{flag} {f}: expected 0 < F < 1 (a fraction of the CFL step of the fluid at rest)")
    if args.fixed_step is not None and args.step_cap is not None:
        ap.error("--fixed-step and --step-cap: give one (a fixed step, or the variable step capped)")
    if args.sink is not None and not args.sink > 0:
        ap.error(f"--sink {args.sink}: expected a positive number of d0")
    if args.own_window and not args.quiet_exit:
        ap.error("--own-window makes runs longer than they were started for: it needs --quiet-exit's "
                 "refilling nozzle")
    if args.quiet_exit and args.axis_pair not in RINGS_PAIRS:
        ap.error("--quiet-exit splits the rings of the rings pair: give --axis-pair rings, rings_own or rings_fit")
    if args.gravity and args.axis_pair not in RINGS_PAIRS:
        ap.error("--gravity renormalises the rings pair's continuity (domain.renormalise_ring_continuity): "
                 "give --axis-pair rings, rings_own or rings_fit")
    if args.margin is not None and not (args.gravity and args.margin > 0):
        ap.error(f"--renormalise-margin {args.margin:g}: expected a positive number of d0 with --gravity "
                 "(the margin of its renormalised continuity)")
    if args.bound_xsph and args.axis_pair not in RINGS_PAIRS:
        ap.error("--bound-xsph bounds the XSPH of the rings pair's rings (domain.bound_ring_xsph): "
                 "give --axis-pair rings, rings_own or rings_fit")
    if args.thin_rings and args.axis_pair != "rings_fit":
        ap.error("--thin-rings takes thin free rings off the surface fit (surface_tension.thin_rings_normals): "
                 "give --axis-pair rings_fit or --quiet-jets")
    if args.fit_points is not None and not (args.fit_points > 3 and args.axis_pair == "rings_fit"):
        ap.error(f"--fit-points {args.fit_points}: expected a number of points above 3 with the surface fit "
                 "(surface_tension.fit_points_min): give --axis-pair rings_fit or --quiet-jets")
    if args.leapfrog and not args.quiet_exit:
        ap.error("--leapfrog needs the bulk viscosity of --quiet-exit (numerics.integrator = \"leapfrog\" "
                 "is refused without numerics.bulk_viscosity > 0)")
    check_numerics(ap, args)
    if not args.d0_over_dx >= 4:
        ap.error(f"--d0-over-dx {args.d0_over_dx}: expected >= 4 (2 rings across the radius)")
    return args


def main(argv=None):
    return dispatch(parse(argv), cmd_run, report, "round_jet_study")


if __name__ == "__main__":
    sys.exit(main())
