#!/usr/bin/env bash
# Configures and builds sphjet (Release, -O3 with link-time optimisation) into build/.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)"
