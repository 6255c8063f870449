#!/usr/bin/env bash
# The main job on a fresh machine: install, build, and run one of the laminar round water jets
# that Mansour & Chigier (1994) measured (d0 = 1.194 mm, U = 1.2545 m/s, no imposed
# disturbance) in the axisymmetric mode, with the round-jet study's quiet numerics (--quiet-jets:
# c0 = 12 m/s, cfl 0.25, the leapfrog and the rest; tools/round_jet_study.py run --help)
# at a coarse d0/dx = 6 and a short window (0.4 L/U from 1.5 L/U). The jet leaves as the plug
# that the tube's parabolic exit profile relaxes to (--relaxed-exit: 1.66 m/s, 0.869 d0 at this
# speed). It then prints the breakup length over the tube's d0 beside the measurement and the
# theory, and the main drops over the jet's own diameter beside Rayleigh's. About 1-2 minutes
# on two cores once built (the first build of the driver, about 2.5 minutes more). Output goes
# to runs/quickstart/.../mc_u1.2545/ (open sphjet.xmf in ParaView; jet.csv and drops.csv are
# the breakup record). The paper's planar jets are cases/jet/ and tools/jet_study.py.
# d0/dx 6 shows the method, not converged physics: a column at rest with three rings across its
# radius does not grow a small wave as the capillary instability does (tools/jet_column.py;
# cases/round_jet/README.md, "The jets' own capillary growth"), so the study's lengths are made
# at d0/dx 10 and checked at 20.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
bash tools/build.sh sphjet   # the driver alone (tools/test.sh builds the tests)
study=(--root runs/quickstart --eps 0 --quiet-jets --d0-over-dx 6 --window 0.4 --relaxed-exit)
/usr/bin/python3 tools/round_jet_study.py run "${study[@]}" --only mc_u1.2545
echo
/usr/bin/python3 tools/round_jet_study.py report "${study[@]}" --only mc_u1.2545 --brief \
    --out runs/quickstart/report
echo
echo "d0/dx 6 shows the method in a minute, not converged physics: at three rings across the"
echo "radius a small wave on the column does not grow as the capillary instability does"
echo "(tools/jet_column.py). The study's lengths are made at d0/dx 10 and checked at 20"
echo "(cases/round_jet/README.md)."
