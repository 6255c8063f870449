#!/usr/bin/env bash
# The test job on a fresh machine: install, build, run the default test set (labels unit,
# interface, regression and fuzz; the long validation runs are excluded: ctest -L validation).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
bash tools/build.sh
cd build
ctest --output-on-failure -j "$(nproc)" -LE validation
