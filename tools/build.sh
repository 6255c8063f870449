#!/usr/bin/env bash
# Configures and builds sphjet (Release, -O3 with link-time optimisation) into build/.
# A build/ already configured for Release is not configured again (cmake --build does that by
# itself when a CMakeLists.txt changes); one whose configuration stopped half-way (no build
# files, e.g. a package was missing) is configured again. Arguments: the targets to build, all by default (the
# tests too); `bash tools/build.sh sphjet` builds the driver alone.
set -euo pipefail
cd "$(dirname "$0")/.."
configured() {
  grep -qx "CMAKE_BUILD_TYPE:STRING=Release" build/CMakeCache.txt 2>/dev/null \
    && { [ -f build/Makefile ] || [ -f build/build.ninja ]; }
}
if ! configured; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
fi
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j "$(nproc)" "${targets[@]}"
